/* Lossless transform for number streams before compression: each value is
 * XOR-ed with the previous value of the same component (neighbouring
 * vertices share sign, exponent and leading mantissa bits, which become
 * zeros), then the bytes are split into planes (all byte 0s, all byte 1s,
 * ...) so that those zeros form long runs zstd compresses well. */
#ifndef GLS_PLANES_H
#define GLS_PLANES_H
#include <stddef.h>
#include <stdint.h>

/* in: count records, stride bytes apart, each starting with ncomp words of
 * width bytes (4 or 8), native order.  out: count*ncomp*width bytes,
 * planar.  gls_planes_decode is its mirror: the words back into count
 * records stride bytes apart (the bytes between them untouched), so that
 * a reader decodes straight into its own array (bundle_read.c's
 * positions, four doubles a vertex from three stored) with no packed
 * copy in between. */
void gls_planes_encode(const void *in, size_t count, size_t stride, unsigned ncomp, unsigned width, uint8_t *out);
void gls_planes_decode(const uint8_t *in, size_t count, size_t stride, unsigned ncomp, unsigned width, void *out);
#endif
