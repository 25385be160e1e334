#include <string.h>
#include "planes.h"

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the plane transform stores native words: glscene supports little-endian hosts only"
#endif

static uint64_t load_word(const uint8_t *p, unsigned width)
{
    if (width == 8) { uint64_t v; memcpy(&v, p, 8); return v; }
    uint32_t v; memcpy(&v, p, 4); return v;
}

static void store_word(uint8_t *p, unsigned width, uint64_t v)
{
    if (width == 8) { memcpy(p, &v, 8); return; }
    uint32_t w = (uint32_t)v; memcpy(p, &w, 4);
}

/* Plane (c, b) holds byte b (little-endian significance) of component c. */
void gls_planes_encode(const void *in, size_t count, size_t stride, unsigned ncomp, unsigned width, uint8_t *out)
{
    const uint8_t *src = in;
    for (unsigned c = 0; c < ncomp; c++) {
        uint64_t prev = 0;
        uint8_t *plane = out + (size_t)c * width * count;
        for (size_t i = 0; i < count; i++) {
            uint64_t v = load_word(src + i * stride + c * width, width);
            uint64_t x = v ^ prev;
            prev = v;
            for (unsigned b = 0; b < width; b++)
                plane[b * count + i] = (uint8_t)(x >> (8 * b));
        }
    }
}

/* One component's planes back into words, width a constant in each
 * caller below so that the byte loop unrolls. */
static inline void decode_comp(const uint8_t *plane, size_t count, unsigned width, uint8_t *dst, size_t stride)
{
    uint64_t prev = 0;
    for (size_t i = 0; i < count; i++) {
        uint64_t x = 0;
        for (unsigned b = 0; b < width; b++)
            x |= (uint64_t)plane[b * count + i] << (8 * b);
        prev ^= x;
        store_word(dst + i * stride, width, prev);
    }
}

void gls_planes_decode(const uint8_t *in, size_t count, size_t stride, unsigned ncomp, unsigned width, void *out)
{
    uint8_t *dst = out;
    for (unsigned c = 0; c < ncomp; c++) {
        const uint8_t *plane = in + (size_t)c * width * count;
        if (width == 8)
            decode_comp(plane, count, 8, dst + c * 8, stride);
        else
            decode_comp(plane, count, 4, dst + c * 4, stride);
    }
}
