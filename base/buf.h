/* Growing memory: the one growth rule of every growing array in the tree
 * (capacity doubled until the need fits, sizes checked for overflow), and
 * a growing byte buffer built on it. */
#ifndef GLS_BUF_H
#define GLS_BUF_H
#include <stddef.h>
#include <stdint.h>

/* The capacity, in elements of elem bytes, that an array of capacity cap
 * grows to so that need elements fit: cap itself when they already do,
 * else cap doubled (from at least 16 elements and 256 bytes) until they
 * do.  0 when that many bytes would not fit in a size_t. */
size_t gls_grow_cap(size_t cap, size_t need, size_t elem);

/* realloc(p, n * elem) with the product checked for overflow: the new
 * block, or NULL (p is then left as it was). */
void *gls_resize(void *p, size_t n, size_t elem);

/* Make room for need elements of elem bytes in the array *arrp (arrp is
 * the address of the array pointer, T **) of capacity *cap, by the rule
 * of gls_grow_cap.  0, or -1 when out of memory (the array and *cap are
 * then left as they were). */
int gls_grow(void *arrp, size_t *cap, size_t need, size_t elem);

/* A growing byte buffer; {0} is an empty one, free(data) releases it. */
typedef struct {
    uint8_t *data;
    size_t len, cap;
} gls_buf;
/* Room for extra more bytes; 0, or -1 when out of memory. */
int gls_buf_reserve(gls_buf *b, size_t extra);
/* Append n bytes; 0, or -1 when out of memory. */
int gls_buf_put(gls_buf *b, const void *p, size_t n);
/* Append printf-formatted text (no terminating NUL counted in len; one is
 * left after it); 0, or -1 when out of memory or on a format error. */
int gls_buf_printf(gls_buf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
#endif
