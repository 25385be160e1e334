#include <stdarg.h>
#include <string.h>
#include "diag.h"

static void print_line(FILE *out, const gls_loc *loc)
{
    const char *t = loc->src->text, *end = t + loc->src->len;
    unsigned line = 1;
    const char *p = t;
    while (p < end && line < loc->line) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        if (!nl)
            return;
        p = nl + 1;
        line++;
    }
    const char *e = p;
    while (e < end && *e != '\n' && *e != '\r')
        e++;
    fprintf(out, "%.*s\n", (int)(e - p), p);
    /* caret: keep tabs so it lines up with the source as the terminal shows it */
    for (unsigned c = 1; c < loc->col && p + c - 1 < e; c++)
        fputc(p[c - 1] == '\t' ? '\t' : ' ', out);
    fputs("^\n", out);
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
