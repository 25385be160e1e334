#include <string.h>
#include "srcline.h"

void gls_append_source_line(char *buf, size_t cap, const char *text, size_t len, unsigned line, unsigned col)
{
    size_t p = 0;
    for (unsigned l = 1; l < line && p < len; p++)
        if (text[p] == '\n')
            l++;
    size_t e = p;
    while (e < len && text[e] != '\n' && text[e] != '\r' && text[e] != 0)
        e++;
    if (e - p > 200)
        return; /* a very long line: the message alone says enough */
    size_t used = strlen(buf);
    if (used + (e - p) + col + 4 >= cap)
        return;
    buf[used++] = '\n';
    memcpy(buf + used, text + p, e - p);
    used += e - p;
    buf[used++] = '\n';
    for (unsigned c = 1; c < col && p + c - 1 < e; c++)
        buf[used++] = text[p + c - 1] == '\t' ? '\t' : ' ';
    buf[used++] = '^';
    buf[used] = 0;
}
