/* Scaled 16-bit PNGs of float images (spec/outputs.md "Disparity and
 * 16-bit depth"): KITTI's disparity (d * 256) and depth (Zc * scale,
 * --depth-scale), 0 where there is no surface.  A value that does not fit
 * is refused, never clamped: the caller says which pixel. */
#ifndef GLS_OUT_PNG16_H
#define GLS_OUT_PNG16_H

#include <stddef.h>
#include <stdint.h>
#include "buf.h"

/* Results of gls_encode_scaled16 besides 0 (done) and -1 (out of memory). */
enum { GLS_SCALED16_OVER = 1, GLS_SCALED16_ZERO = 2 };

/* v (top row first) as a 16-bit greyscale PNG of floor(v * scale + 0.5)
 * (v * scale rounded half up, in double), 0 where v is not finite.
 * GLS_SCALED16_OVER when a value's code is over 65535, GLS_SCALED16_ZERO
 * when a finite value's code is 0 (it would read as "no surface"), with
 * *bad the index of the first such pixel (row by row from the top); no
 * bytes are added then. */
int gls_encode_scaled16(const float *v, uint32_t w, uint32_t h, double scale, gls_buf *out, size_t *bad);

/* The codes themselves, the PNG's samples (the library's depth16 and
 * disparity16 arrays): for values gls_scaled16_check passed. */
void gls_scaled16_codes(const float *v, size_t n, double scale, uint16_t *code);
/* The same verdict without encoding: 0, GLS_SCALED16_OVER or
 * GLS_SCALED16_ZERO with *bad (the player checks before it writes any
 * file of the frame). */
int gls_scaled16_check(const float *v, size_t n, double scale, size_t *bad);

#endif
