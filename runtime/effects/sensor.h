/* Sensor effects of a camera (spec/camera.md "Sensor effects"): what the
 * camera file asks for (vignetting, exposure gain, shot and read noise,
 * a Bayer mosaic) and the post-process that applies it to the image's
 * linear intensities before they are quantised.  All off by default: a
 * camera that asks for none has on == 0 and the player's image path is
 * the one it had before (no call into sensor.c).
 *
 * The keys are read by camera.c through sensor_keys.c; the noise comes
 * from a counter-based generator (sensor_rng.h) keyed by the seed, the
 * camera's name, the frame and the pixel, so it depends on nothing else
 * (not on the order pixels are done in, nor on threads). */
#ifndef GLS_SENSOR_H
#define GLS_SENSOR_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "sensor_params.h"

/* Vignetting factor of pixel (u, v) of an image whose principal point is
 * (cx, cy) and whose pixel (u, v) looks along the camera-frame ray
 * (x, y, 1): cos4 gives cos^4 of the ray's angle to the optical axis,
 * 1 / (1 + x^2 + y^2)^2; poly gives 1 + a1 r^2 + a2 r^4 + a3 r^6 with
 * r = |(u - cx, v - cy)| / fx; never below 0. */
double gls_sensor_vignetting(const gls_sensor *s, double u, double v, double cx, double cy, double fx, double x,
                             double y);

/* Apply vignetting, gain, shot noise and read noise in place to rgb
 * (3 floats a pixel, linear intensities, top row first, w x h), then clip
 * to [0, 1].  ray(ctx, u, v, &x, &y) gives the camera-frame ray of pixel
 * (u, v) (only called for vignetting cos4).  The noise of pixel i,
 * channel c is drawn from the streams of (seed, camera, frame, i, c):
 * camera is a hash of the camera's name (gls_sensor_camera_key).  The
 * rows are done in bands, each on a thread of its own: threads of them
 * (at most GLS_SENSOR_MAX_THREADS and h), or with threads 0 (the
 * player's) one per GLS_SENSOR_BAND_PIXELS pixels up to the processors
 * online.  The image is the same bits whatever their number (tests:
 * test_sensor's threads_same_image). */
void gls_sensor_apply(const gls_sensor *s, float *rgb, uint32_t w, uint32_t h, double cx, double cy, double fx,
                      void (*ray)(void *ctx, double u, double v, double *x, double *y), void *ctx,
                      uint64_t camera, uint32_t frame, unsigned threads);

/* gls_sensor_apply's bands: at least this many pixels each when it
 * chooses their number, and at most this many. */
#define GLS_SENSOR_BAND_PIXELS 65536
#define GLS_SENSOR_MAX_THREADS 16

/* The camera's part of the noise key: FNV-1a of its name. */
uint64_t gls_sensor_camera_key(const char *name);

/* The channel (0 R, 1 G, 2 B) pixel (x, y) of the Bayer pattern keeps:
 * the pattern names the 2x2 block at the top-left corner row by row. */
int gls_sensor_bayer_channel(const char *pattern, uint32_t x, uint32_t y);

/* Quantise clipped intensities (3 floats a pixel) into an image file's
 * samples: bits 8 (round(255 x), as RGBA with alpha 255, the layout the
 * 8-bit PNG encoder takes), 16 (round(65535 x), RGB) or 32 (the float
 * itself, RGB).  Returns a malloc'd buffer or NULL when out of memory. */
void *gls_sensor_quantise(const float *rgb, uint32_t w, uint32_t h, int bits);

/* The Bayer mosaic of an image of per samples a pixel (R, G, B first),
 * each size bytes: one sample a pixel, the channel
 * gls_sensor_bayer_channel names.  A malloc'd buffer, or NULL. */
void *gls_sensor_mosaic(const char *pattern, const void *px, size_t per, size_t size, uint32_t w, uint32_t h);

/* Text for --explain and the frame record. */
/* The effects, in the order they are applied, one line each under
 * "  sensor:" with the key that asks for each and its cost over npixels. */
void gls_sensor_explain(FILE *out, const gls_sensor *s, uint64_t npixels, int image);
/* One line, "sensor vignetting cos4 gain 2 ..." (no newline), or "" when
 * nothing is on; 0, or -1 if it does not fit. */
int gls_sensor_describe(char *buf, size_t len, const gls_sensor *s);

#endif
