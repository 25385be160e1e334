/* Names of specialised objects (specname.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"
#include "specname.h"

int gls_specname_write(gls_buf *b, const char *base, const char *const *names, const double *values, unsigned n)
{
    if (gls_buf_put(b, base, strlen(base)))
        return -1;
    for (unsigned i = 0; i < n; i++) {
        char num[40];
        gls_fmt_double(num, sizeof num, values[i]);
        if (gls_buf_put(b, i ? "," : "(", 1) || gls_buf_put(b, names[i], strlen(names[i])) ||
            gls_buf_put(b, "=", 1) || gls_buf_put(b, num, strlen(num)))
            return -1;
    }
    if ((n && gls_buf_put(b, ")", 1)) || gls_buf_reserve(b, 1))
        return -1;
    b->data[b->len] = 0;
    return 0;
}

static int ident_char(char c, int first)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || (!first && c >= '0' && c <= '9');
}

long gls_specname_parse(const char *s, gls_specarg *args, unsigned max, unsigned *n)
{
    *n = 0;
    const char *open = strchr(s, '(');
    if (!open)
        return (long)strlen(s);
    const char *p = open + 1;
    for (;;) {
        const char *name = p;
        while (ident_char(*p, p == name))
            p++;
        if (p == name || *p != '=' || *n >= max)
            return -1;
        size_t len = (size_t)(p - name);
        const char *num = ++p;
        while (*p && *p != ',' && *p != ')')
            p++;
        /* the value must be exactly its canonical spelling */
        char text[40], canon[40];
        size_t tl = (size_t)(p - num);
        if (tl == 0 || tl >= sizeof text)
            return -1;
        memcpy(text, num, tl);
        text[tl] = 0;
        char *end;
        double v = strtod(text, &end);
        gls_fmt_double(canon, sizeof canon, v);
        if (*end || !isfinite(v) || strcmp(canon, text) != 0)
            return -1;
        args[*n] = (gls_specarg){name, len, v};
        ++*n;
        if (*p == ')')
            return p[1] ? -1 : (long)(open - s);
        if (*p != ',')
            return -1;
        p++;
    }
}
