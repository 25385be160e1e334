/* The player's 8-bit PNG encoder before issue 14, for comparisons
 * (tests/unit/test_outputs.c, bench/png_bench.c): the alpha dropped, then
 * stb_image_write's PNG writer (Debian's libstb) into a gls_buf. */
#ifndef GLS_STB_PNG_H
#define GLS_STB_PNG_H
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <stb/stb_image_write.h>
#include "buf.h"

typedef struct {
    gls_buf *out;
    int failed;
} stb_png_sink;

static inline void stb_png_put(void *ctx, void *data, int size)
{
    stb_png_sink *s = ctx;
    if (size > 0 && gls_buf_put(s->out, data, (size_t)size))
        s->failed = 1;
}

/* 0, or -1 when out of memory */
static inline int stb_png_encode(const uint8_t *rgba, int w, int h, gls_buf *out)
{
    size_t n = (size_t)w * (size_t)h;
    uint8_t *rgb = malloc(n ? n * 3 : 1);
    if (!rgb)
        return -1;
    for (size_t i = 0; i < n; i++)
        memcpy(rgb + 3 * i, rgba + 4 * i, 3);
    stb_png_sink s = {out, 0};
    int ok = stbi_write_png_to_func(stb_png_put, &s, w, h, 3, rgb, w * 3);
    free(rgb);
    return ok && !s.failed ? 0 : -1;
}
#endif
