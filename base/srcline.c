#include <string.h>
#include "srcline.h"

/* Lines longer than this are shown as a window of SRCLINE_WINDOW bytes
 * around the column, with "..." where the line goes on. */
#define SRCLINE_MAX 200
#define SRCLINE_WINDOW 160

void gls_append_source_line(char *buf, size_t cap, const char *text, size_t len, unsigned line, unsigned col)
{
    size_t p = 0;
    for (unsigned l = 1; l < line && p < len; p++)
        if (text[p] == '\n')
            l++;
    size_t e = p;
    while (e < len && text[e] != '\n' && text[e] != '\r' && text[e] != 0)
        e++;
    size_t c0 = col ? col - 1 : 0; /* the caret's offset in the line */
    size_t from = 0, to = e - p;
    if (to > SRCLINE_MAX) {
        size_t n = to;
        from = c0 > SRCLINE_WINDOW / 2 ? c0 - SRCLINE_WINDOW / 2 : 0;
        if (from > n - SRCLINE_WINDOW)
            from = n - SRCLINE_WINDOW;
        to = from + SRCLINE_WINDOW;
    }
    int dots_before = from > 0, dots_after = p + to < e;
    size_t used = strlen(buf);
    size_t caret_at = c0 < from ? 0 : c0 - from;
    if (used + (to - from) + 6 + caret_at + 3 + 4 >= cap)
        return;
    buf[used++] = '\n';
    if (dots_before)
        memcpy(buf + used, "...", 3), used += 3;
    memcpy(buf + used, text + p + from, to - from);
    used += to - from;
    if (dots_after)
        memcpy(buf + used, "...", 3), used += 3;
    buf[used++] = '\n';
    if (dots_before)
        memcpy(buf + used, "   ", 3), used += 3;
    for (size_t c = from; c < c0 && p + c < e; c++)
        buf[used++] = text[p + c] == '\t' ? '\t' : ' ';
    buf[used++] = '^';
    buf[used] = 0;
}
