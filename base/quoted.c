/* Double-quoted YAML and JSON strings (quoted.h). */
#include <stdio.h>
#include "quoted.h"

int gls_buf_quoted(gls_buf *b, const char *s, int json)
{
    if (gls_buf_put(b, "\"", 1))
        return -1;
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        char e[8];
        int n;
        if (c == '"' || c == '\\')
            n = snprintf(e, sizeof e, "\\%c", c);
        else if (c < 0x20 || c == 0x7f)
            n = snprintf(e, sizeof e, json ? "\\u%04x" : "\\x%02x", c);
        else
            e[0] = (char)c, n = 1;
        if (gls_buf_put(b, e, (size_t)n))
            return -1;
    }
    return gls_buf_put(b, "\"", 1);
}
