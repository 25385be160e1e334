/* A small string-keyed hash map (open addressing) of pointers. */
#ifndef GLS_STRMAP_H
#define GLS_STRMAP_H
#include <stddef.h>

typedef struct {
    const char **keys;   /* borrowed: the value owns its key            */
    void **vals;
    size_t cap, n;
} gls_strmap;

void *gls_strmap_get(const gls_strmap *m, const char *key);
int gls_strmap_put(gls_strmap *m, const char *key, void *val);   /* 0 or -1 */
void gls_strmap_free(gls_strmap *m);
#endif
