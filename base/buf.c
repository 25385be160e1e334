/* Growing memory (buf.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"

size_t gls_grow_cap(size_t cap, size_t need, size_t elem)
{
    if (elem == 0 || need > SIZE_MAX / elem)
        return 0;
    if (need <= cap)
        return cap;
    size_t c = cap;
    if (c < 16)
        c = 16;
    if (c < 256 / elem)
        c = 256 / elem;
    while (c < need) {
        if (c > SIZE_MAX / 2 / elem)
            return need; /* doubling would overflow: exactly what is needed */
        c *= 2;
    }
    return c;
}

void *gls_resize(void *p, size_t n, size_t elem)
{
    if (elem && n > SIZE_MAX / elem)
        return NULL;
    size_t bytes = n * elem;
    return realloc(p, bytes ? bytes : 1); /* realloc(p, 0) may free p */
}

int gls_grow(void *arrp, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return 0;
    size_t c = gls_grow_cap(*cap, need, elem);
    void *old;
    memcpy(&old, arrp, sizeof old); /* arrp is a T **: read it as void * */
    void *p = c ? gls_resize(old, c, elem) : NULL;
    if (!p)
        return -1;
    memcpy(arrp, &p, sizeof p);
    *cap = c;
    return 0;
}

int gls_buf_reserve(gls_buf *b, size_t n)
{
    if (n > SIZE_MAX - b->len)
        return -1;
    return gls_grow(&b->data, &b->cap, b->len + n, 1);
}

int gls_buf_put(gls_buf *b, const void *p, size_t n)
{
    if (gls_buf_reserve(b, n))
        return -1;
    if (n)
        memcpy(b->data + b->len, p, n);
    b->len += n;
    return 0;
}

int gls_buf_printf(gls_buf *b, const char *fmt, ...)
{
    char small[256];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    if (n < 0)
        return -1;
    if ((size_t)n < sizeof small)
        return gls_buf_put(b, small, (size_t)n);
    if (gls_buf_reserve(b, (size_t)n + 1))
        return -1;
    va_start(ap, fmt);
    vsnprintf((char *)b->data + b->len, (size_t)n + 1, fmt, ap);
    va_end(ap);
    b->len += (size_t)n;
    return 0;
}
