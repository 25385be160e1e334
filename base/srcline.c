/* The source excerpt under a diagnostic (srcline.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "srcline.h"

/* Lines longer than this are shown as a window of SRCLINE_WINDOW bytes
 * around the column, with "..." where the line goes on. */
#define SRCLINE_MAX 200
#define SRCLINE_WINDOW 160

/* Where the excerpt of a line comes from. */
typedef struct {
    const char *p;        /* the line's first byte                         */
    size_t end;           /* its length: the caret goes no further          */
    size_t from, to;      /* the part shown, p[from..to)                    */
    size_t caret;         /* the caret's offset in the line (column - 1)    */
    int cut_before, cut_after;
} excerpt;

static int find(const char *text, size_t len, unsigned line, unsigned col, gls_excerpt_style style, excerpt *x)
{
    size_t p = 0;
    for (unsigned l = 1; l < line; l++) {
        const char *nl = memchr(text + p, '\n', len - p);
        if (!nl)
            return -1;
        p = (size_t)(nl - text) + 1;
    }
    size_t e = p;
    while (e < len && text[e] != '\n' && text[e] != '\r' && (style == GLS_EXCERPT_WHOLE_LINE || text[e] != 0))
        e++;
    x->p = text + p;
    x->end = e - p;
    x->caret = col ? col - 1 : 0;
    x->from = 0;
    x->to = x->end;
    if (style == GLS_EXCERPT_WINDOW && x->end > SRCLINE_MAX) {
        x->from = x->caret > SRCLINE_WINDOW / 2 ? x->caret - SRCLINE_WINDOW / 2 : 0;
        if (x->from > x->end - SRCLINE_WINDOW)
            x->from = x->end - SRCLINE_WINDOW;
        x->to = x->from + SRCLINE_WINDOW;
    }
    x->cut_before = x->from > 0;
    x->cut_after = x->to < x->end;
    return 0;
}

static int put(gls_buf *b, const excerpt *x)
{
    /* the text shown stops at a NUL byte (GLS_EXCERPT_WHOLE_LINE) */
    const char *nul = memchr(x->p + x->from, 0, x->to - x->from);
    size_t shown = nul ? (size_t)(nul - (x->p + x->from)) : x->to - x->from;
    if (gls_buf_reserve(b, 3 + shown + 3 + 1 + 3 + (x->caret > x->from ? x->caret - x->from : 0) + 1))
        return -1;
    char *o = (char *)b->data + b->len;
    if (x->cut_before)
        memcpy(o, "...", 3), o += 3;
    memcpy(o, x->p + x->from, shown), o += shown;
    if (x->cut_after)
        memcpy(o, "...", 3), o += 3;
    *o++ = '\n';
    if (x->cut_before)
        memcpy(o, "   ", 3), o += 3;
    for (size_t c = x->from; c < x->caret && c < x->end; c++)
        *o++ = x->p[c] == '\t' ? '\t' : ' ';
    *o++ = '^';
    b->len = (size_t)(o - (char *)b->data);
    return 0;
}

int gls_excerpt(gls_buf *b, const char *text, size_t len, unsigned line, unsigned col, gls_excerpt_style style)
{
    excerpt x;
    return find(text, len, line, col, style, &x) ? -1 : put(b, &x);
}

void gls_append_source_line(char *buf, size_t cap, const char *text, size_t len, unsigned line, unsigned col)
{
    excerpt x;
    if (find(text, len, line, col, GLS_EXCERPT_WINDOW, &x))
        return;
    size_t used = strlen(buf);
    size_t caret_at = x.caret < x.from ? 0 : x.caret - x.from;
    if (used + (x.to - x.from) + 6 + caret_at + 3 + 4 >= cap)
        return;
    gls_buf b = {0};
    if (put(&b, &x) == 0 && used + 1 + b.len < cap) {
        buf[used] = '\n';
        memcpy(buf + used + 1, b.data, b.len);
        buf[used + 1 + b.len] = 0;
    }
    free(b.data);
}

void gls_text_error(char *err, size_t errlen, const char *text, size_t len, const char *file, unsigned line,
                    unsigned col, const char *fmt, ...)
{
    int k = snprintf(err, errlen, "%s:%u:%u: error: ", file, line, col);
    if (k < 0 || (size_t)k >= errlen)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + k, errlen - (size_t)k, fmt, ap);
    va_end(ap);
    gls_append_source_line(err, errlen, text, len, line, col);
}
