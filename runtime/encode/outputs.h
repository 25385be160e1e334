/* Encoders of the player's output files, into memory; the caller writes
 * the bytes with gls_write_file_atomic() so no partial file is ever seen.
 * All encoders are deterministic: same pixels, same bytes. */
#ifndef GLS_OUTPUTS_H
#define GLS_OUTPUTS_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"
#include "camera.h"

/* Every PNG is encoded by libspng at zlib level 1 with the "sub" filter on
 * every row (outputs.c), chosen by measurement (make bench-encode,
 * docs/benchmarks.md): 4 to 6 times faster than stb_image_write's encoder,
 * which the player used before, with files of about the same size or
 * smaller and the same pixels. */

/* 8-bit RGB PNG of an RGBA image (alpha dropped), top row first. */
int gls_encode_png(const uint8_t *rgba, uint32_t w, uint32_t h, gls_buf *out);

/* 16-bit RGB PNG, rgb top row first, 3 samples per pixel. */
int gls_encode_png16(const uint16_t *rgb, uint32_t w, uint32_t h, gls_buf *out);

/* 8-bit greyscale PNG of one byte per pixel. */
int gls_encode_png_gray(const uint8_t *g, uint32_t w, uint32_t h, gls_buf *out);

/* 16-bit greyscale PNG, one host-order sample per pixel, top row first. */
int gls_encode_png16_gray(const uint16_t *g, uint32_t w, uint32_t h, gls_buf *out);

/* How PNGs are encoded, in words, for --explain. */
const char *gls_png_encoding(void);

/* Any of the above with other settings, for the bench: channels 1 or 3,
 * depth 8 or 16 (host-order samples), rgba: 8-bit pixels given as RGBA
 * (alpha dropped), level 0..9, filters SPNG_FILTER_CHOICE_* bits. */
int gls_encode_png_with(const void *px, uint32_t w, uint32_t h, int channels, int depth, int rgba, int level,
                        int filters, gls_buf *out);

/* Colour PFM ("PF", 3 channels float32, scale -1.0 = little-endian),
 * rows bottom to top; rgb is top row first. */
int gls_encode_pfm_rgb(const float *rgb, uint32_t w, uint32_t h, gls_buf *out);

/* PFM ("Pf", one channel float32, scale -1.0 = little-endian), rows
 * bottom to top as the format (Middlebury) requires; z is top row first. */
int gls_encode_pfm(const float *z, uint32_t w, uint32_t h, gls_buf *out);

/* Binary little-endian PLY of every pixel with a surface (finite z):
 * world coordinates as double x y z (float would lose millimetres 1e5
 * units from the origin) and uchar red green blue.  Points are in pixel
 * order, row by row from the top.  *npoints receives the count. */
int gls_encode_ply(const gls_camera *c, const float *z, const uint8_t *rgba, gls_buf *out, uint64_t *npoints);
/* The same with row v unprojected through the camera pose row_pose[v]
 * (R row-major, then T; a rolling shutter's rows, exposure.h), or c's
 * for every row when row_pose is NULL. */
int gls_encode_ply_rows(const gls_camera *c, const double (*row_pose)[12], const float *z, const uint8_t *rgba,
                        gls_buf *out, uint64_t *npoints);

#endif
