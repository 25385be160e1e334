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

void gls_note_at(gls_diag *d, gls_loc loc, const char *fmt, ...)
{
    if (d->stopped)
        return;
    va_list ap;
    va_start(ap, fmt);
    report(d, loc, "note", fmt, ap);
    va_end(ap);
}

/* Optimal-string-alignment distance: insertions, deletions, substitutions
 * and swaps of two neighbouring letters each cost 1 ("trnas" is 1 from
 * "trans"). */
unsigned gls_edit_distance(const char *a, size_t alen, const char *b)
{
    size_t blen = strlen(b);
    if (alen > 64 || blen > 64)
        return 1000;
    unsigned d[65][65];
    for (size_t i = 0; i <= alen; i++)
        d[i][0] = (unsigned)i;
    for (size_t j = 0; j <= blen; j++)
        d[0][j] = (unsigned)j;
    for (size_t i = 1; i <= alen; i++)
        for (size_t j = 1; j <= blen; j++) {
            unsigned best = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[alen][blen];
}

const char *gls_suggest(const char *word, size_t len, const char *const *cands, size_t n)
{
    const char *best = NULL;
    unsigned bestd = 1000;
    for (size_t i = 0; i < n; i++) {
        unsigned dd = gls_edit_distance(word, len, cands[i]);
        if (dd < bestd) {
            bestd = dd;
            best = cands[i];
        }
    }
    /* close enough: at most a third of the word, and at least one edit allowed */
    unsigned limit = len >= 6 ? (unsigned)len / 3 : 1;
    if (len <= 2)
        limit = 1;
    return bestd <= limit ? best : NULL;
}
