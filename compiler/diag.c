#include <stdarg.h>
#include <stdlib.h>
#include "diag.h"
#include "srcline.h"

/* The source line and a caret under the column (base/srcline.h). */
static void print_line(FILE *out, const gls_loc *loc)
{
    gls_buf b = {0};
    if (gls_excerpt(&b, loc->src->text, loc->src->len, loc->line, loc->col, GLS_EXCERPT_WHOLE_LINE) == 0) {
        fwrite(b.data, 1, b.len, out);
        fputc('\n', out);
    }
    free(b.data);
}

static void report(gls_diag *d, gls_loc loc, const char *kind, const char *fmt, va_list ap)
{
    if (loc.src)
        fprintf(d->out, "%s:%u:%u: %s: ", loc.src->path, loc.line, loc.col, kind);
    else
        fprintf(d->out, "glsc: %s: ", kind);
    vfprintf(d->out, fmt, ap);
    fputc('\n', d->out);
    if (loc.src && loc.line)
        print_line(d->out, &loc);
}

void gls_error_at(gls_diag *d, gls_loc loc, const char *fmt, ...)
{
    if (d->stopped)
        return;
    va_list ap;
    va_start(ap, fmt);
    report(d, loc, "error", fmt, ap);
    va_end(ap);
    if (++d->errors >= GLS_MAX_ERRORS) {
        fprintf(d->out, "glsc: too many errors (%u), stopping\n", d->errors);
        d->stopped = 1;
    }
}

void gls_warning_at(gls_diag *d, gls_loc loc, const char *fmt, ...)
{
    if (d->stopped)
        return;
    va_list ap;
    va_start(ap, fmt);
    report(d, loc, "warning", fmt, ap);
    va_end(ap);
    d->warnings++;
}

void gls_note_at(gls_diag *d, gls_loc loc, const char *fmt, ...)
{
    if (d->stopped)
        return;
    va_list ap;
    va_start(ap, fmt);
    report(d, loc, "note", fmt, ap);
    va_end(ap);
}
