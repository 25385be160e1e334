/* Encoders of the flow files (spec/outputs.md "Optical flow"), into
 * memory like outputs.h's: Middlebury .flo and KITTI's 16-bit flow PNG.
 * The flow is 2 floats a pixel (u, v), top row first; the mask holds
 * gt_flow.h's GLS_FLOW_* values. */
#ifndef GLS_OUT_FLOW_H
#define GLS_OUT_FLOW_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"

/* Middlebury .flo: the float 202021.25 ("PIEH" in little-endian bytes),
 * int32 width and height, then u v as float32 per pixel, rows top first,
 * all little-endian. */
int gls_encode_flo(const float *uv, uint32_t w, uint32_t h, gls_buf *out);

/* KITTI's flow PNG holds flow * 64 + 2^15 in 16 bits, so a flow must lie
 * in [-512, 512 - 1/128) px to be stored.  0 if every visible pixel's
 * does, else -1 with the first that does not (x, y) and its flow. */
int gls_flow_kitti_check(const float *uv, const uint8_t *mask, uint32_t w, uint32_t h, uint32_t *x, uint32_t *y,
                         float *u, float *v);

/* The PNG's samples, 3 a pixel, n pixels (the library's flow_kitti array). */
void gls_flow_kitti_codes(const float *uv, const uint8_t *mask, size_t n, uint16_t *rgb);
/* KITTI flow PNG (16-bit RGB, as the devkit's flow_read reads it): R =
 * u * 64 + 2^15, G = v * 64 + 2^15 rounded to the nearest, B = 1 on
 * visible pixels (mask GLS_FLOW_VISIBLE), 0 0 0 on every other pixel.
 * Checked with gls_flow_kitti_check first. */
int gls_encode_flow_kitti(const float *uv, const uint8_t *mask, uint32_t w, uint32_t h, gls_buf *out);

#endif
