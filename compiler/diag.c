#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "bundle.h"
#include "diag.h"
#include "srcline.h"
#include "strmap.h"

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

static void print_at(gls_diag *d, gls_loc loc, const char *kind, const char *msg)
{
    if (loc.src)
        fprintf(d->out, "%s:%u:%u: %s: %s\n", loc.src->path, loc.line, loc.col, kind, msg);
    else
        fprintf(d->out, "glsc: %s: %s\n", kind, msg);
    if (loc.src && loc.line)
        print_line(d->out, &loc);
}

/* Print the diagnostic, unless dedupe is on and it was printed before:
 * 1 if printed. */
static int report(gls_diag *d, gls_loc loc, const char *kind, const char *fmt, va_list ap)
{
    char small[512], *msg = small;
    va_list aq;
    va_copy(aq, ap);
    int need = vsnprintf(small, sizeof small, fmt, ap);
    if (need >= (int)sizeof small && (msg = malloc((size_t)need + 1)))
        vsnprintf(msg, (size_t)need + 1, fmt, aq);
    va_end(aq);
    if (!msg)
        msg = small;
    int print = 1;
    if (d->dedupe) {
        gls_strmap *seen = d->seen ? d->seen : (d->seen = calloc(1, sizeof *seen));
        char head[64];
        snprintf(head, sizeof head, "%u:%u:%s:", loc.line, loc.col, kind);
        const char *path = loc.src ? loc.src->path : "";
        size_t n = strlen(path) + strlen(head) + strlen(msg) + 2;
        char *key = malloc(n);
        if (seen && key) {
            snprintf(key, n, "%s:%s%s", path, head, msg);
            if (gls_strmap_get(seen, key))
                print = 0;
            else if (gls_strmap_put(seen, key, key) == 0)
                key = NULL;
        }
        free(key);
    }
    if (print) {
        print_at(d, loc, kind, msg);
        if (d->making) {
            char note[GLS_MAX_NAME_BYTES + 64];
            snprintf(note, sizeof note, "while making %s for this call", d->making);
            print_at(d, d->making_at, "note", note);
        }
    }
    if (msg != small)
        free(msg);
    return print;
}

void gls_error_at(gls_diag *d, gls_loc loc, const char *fmt, ...)
{
    if (d->stopped)
        return;
    va_list ap;
    va_start(ap, fmt);
    int printed = report(d, loc, "error", fmt, ap);
    va_end(ap);
    d->errors++;
    if (printed && ++d->printed >= GLS_MAX_ERRORS) {
        fprintf(d->out, "glsc: too many errors (%u), stopping\n", d->printed);
        d->stopped = 1;
    }
}

void gls_warning_at(gls_diag *d, gls_loc loc, const char *fmt, ...)
{
    if (d->stopped)
        return;
    va_list ap;
    va_start(ap, fmt);
    if (report(d, loc, "warning", fmt, ap))
        d->warnings++;
    va_end(ap);
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

void gls_diag_free(gls_diag *d)
{
    gls_strmap *seen = d->seen;
    if (!seen)
        return;
    for (size_t i = 0; i < seen->cap; i++)
        free(seen->vals[i]); /* the key is the value */
    gls_strmap_free(seen);
    free(seen);
    d->seen = NULL;
}
