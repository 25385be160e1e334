/* The .npy encoder (out_npy.h).  Layout from numpy's format.py
 * (NEP 1): magic "\x93NUMPY", version 1 0, header length as little-endian
 * uint16, the header (a Python dict literal), then the raw array. */
#include <stdio.h>
#include <string.h>
#include "le.h"
#include "out_npy.h"

#define NPY_ALIGN 64

int gls_encode_npy(const float *v, uint32_t w, uint32_t h, unsigned channels, gls_buf *out)
{
    char dict[128], shape[64];
    if (channels == 1)
        snprintf(shape, sizeof shape, "(%u, %u)", h, w);
    else
        snprintf(shape, sizeof shape, "(%u, %u, %u)", h, w, channels);
    /* numpy's own spelling, key order and trailing ", " */
    int k = snprintf(dict, sizeof dict, "{'descr': '<f4', 'fortran_order': False, 'shape': %s, }", shape);
    size_t pre = 10; /* magic 6, version 2, header length 2 */
    size_t hlen = (size_t)k + 1;        /* the dict and its '\n' */
    hlen += (NPY_ALIGN - (pre + hlen) % NPY_ALIGN) % NPY_ALIGN;
    size_t values = (size_t)w * h * channels;
    if (gls_buf_reserve(out, pre + hlen + values * 4))
        return -1;
    uint8_t *p = out->data + out->len;
    memcpy(p, "\x93NUMPY\x01\x00", 8);
    p[8] = (uint8_t)(hlen & 0xff);
    p[9] = (uint8_t)(hlen >> 8);
    memcpy(p + pre, dict, (size_t)k);
    memset(p + pre + k, ' ', hlen - (size_t)k - 1);
    p[pre + hlen - 1] = '\n';
    p += pre + hlen;
    for (size_t i = 0; i < values; i++)
        gls_le_put_f32(p + 4 * i, v[i]);
    out->len += pre + hlen + values * 4;
    return 0;
}
