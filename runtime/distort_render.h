/* The image through a distorted lens (spec/camera.md "The distorted
 * image"): the scene is drawn once through an undistorted pinhole camera
 * (the "fine" camera) that covers the distorted field of view at GLS_DISTORT_SCALE
 * fine pixels per image pixel or more everywhere; then
 *  - the image: every anti-aliasing sample of every output pixel (the
 *    plan's positions, aa.h, in the distorted image) is mapped through
 *    the inverse lens model into the fine image and read there
 *    bilinearly, and the samples are accumulated with the plan's weights
 *    (one sample at the centre, nearest, without anti-aliasing);
 *  - depth, points' colours and any other ground truth: the NEAREST fine
 *    pixel to the pixel centre's undistorted ray, never blended.
 * Cameras without distortion never come here (player.c). */
#ifndef GLS_DISTORT_RENDER_H
#define GLS_DISTORT_RENDER_H

#include <stdint.h>
#include <stdio.h>
#include "aa.h"
#include "camera.h"
#include "render.h"

/* Fine pixels per image pixel, at least, in every direction. */
#define GLS_DISTORT_SCALE 4.0

typedef struct {
    gls_camera fine;   /* the undistorted camera drawn: c's pose, near and far */
    double margin;     /* image pixels covered beyond each border          */
    double mag;        /* least fine pixels per image pixel over the image  */
} gls_distort_layout;

/* The fine camera for camera c and an anti-aliasing plan p (its window
 * sets the margin), with maxdim the largest framebuffer side (0: the
 * camera limit).  -1 with a message when the model has no ray at the
 * margin or the fine image would exceed maxdim. */
int gls_distort_layout_make(const gls_camera *c, const gls_aa_plan *p, uint32_t maxdim, gls_distort_layout *lay,
                            char *err, size_t errlen);

typedef struct {
    gls_distort_layout lay;
    uint8_t *rgba;     /* fine image, RGBA8, or NULL                      */
    float *z;          /* fine depth Zc, or NULL                          */
    double *ray;       /* per image pixel: its centre's ray x, y          */
    double *jinv;      /* per image pixel: d(x, y)/d(u, v) there, 2x2     */
} gls_distort_frame;

/* Draw the fine image of camera c (colour if want_rgba, depth if want_z)
 * and the pixel centres' rays.  Leaves the renderer at the fine size.  -1
 * with a message (framebuffer, memory, layout). */
int gls_distort_frame_render(gls_distort_frame *f, gls_renderer *r, const gls_camera *c, const gls_aa_plan *p,
                             int want_rgba, int want_z, char *err, size_t errlen);

/* Ground truth at the pixel centres (nearest fine pixel): colour into
 * rgba (W x H RGBA8) and/or depth into z; either may be NULL. */
void gls_distort_frame_centre(const gls_distort_frame *f, const gls_camera *c, uint8_t *rgba, float *z);

/* The plan's samples through the lens, bilinear in the fine image, into
 * acc (initialised for c's size).  -1 when out of memory. */
int gls_distort_frame_accum(const gls_distort_frame *f, const gls_camera *c, const gls_aa_plan *p, gls_accum *acc);

void gls_distort_frame_free(gls_distort_frame *f);

/* --explain: the camera's lens model and how its image is made (nothing
 * for a camera without distortion). */
void gls_distort_explain(FILE *out, const gls_camera *c, const gls_aa_plan *p);

#endif
