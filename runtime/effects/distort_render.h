/* The image through a distorted lens (spec/camera.md "The distorted
 * image").  The scene is drawn through undistorted pinhole cameras (the
 * "fine" cameras) that cover the distorted field of view with a given
 * number of fine pixels per image pixel or more everywhere:
 *  - ground truth (depth, points' colours, the image without
 *    anti-aliasing): one plain pass at GLS_DISTORT_SCALE; each pixel takes
 *    the NEAREST fine pixel to its centre's undistorted ray, never
 *    blended;
 *  - the anti-aliased image: the fine image at GLS_DISTORT_AA_SCALE,
 *    itself anti-aliased (lattice, box, at least M / scale^2 samples per
 *    fine pixel, at least 4), then every anti-aliasing sample of every
 *    output pixel (the plan's positions, aa.h, in the distorted image)
 *    mapped through the inverse lens model and read there bilinearly,
 *    accumulated with the plan's weights.
 * Cameras without distortion never come here (play_frame.c). */
#ifndef GLS_DISTORT_RENDER_H
#define GLS_DISTORT_RENDER_H

#include <stdint.h>
#include <stdio.h>
#include "aa.h"
#include "camera.h"
#include "render.h"

/* Fine pixels per image pixel, at least, in every direction: of the
 * ground truth's plain fine image, and of the anti-aliased one. */
#define GLS_DISTORT_SCALE 4.0
#define GLS_DISTORT_AA_SCALE 2.0

typedef struct {
    gls_camera fine;   /* the undistorted camera drawn: c's pose, near and far */
    double margin;     /* image pixels covered beyond each border          */
    double mag;        /* least fine pixels per image pixel over the image  */
} gls_distort_layout;

/* The fine camera for camera c at scale fine pixels per image pixel and
 * an anti-aliasing plan p (its window sets the margin; NULL: the pixel
 * centres only, the ground truth's, whatever the plan), with maxdim the
 * largest framebuffer side (0: the camera limit).  -1 with a message when
 * the model has no ray at the margin or the fine image would exceed
 * maxdim. */
int gls_distort_layout_make(const gls_camera *c, const gls_aa_plan *p, double scale, uint32_t maxdim,
                            gls_distort_layout *lay, char *err, size_t errlen);

/* Samples per fine pixel of the anti-aliased fine image for a plan of M
 * samples per pixel: ceil(M / GLS_DISTORT_AA_SCALE^2), at least 4. */
uint64_t gls_distort_fine_samples(const gls_aa_plan *p);

typedef struct {
    gls_distort_layout lay;    /* the plain fine image (ground truth)     */
    gls_distort_layout lay_aa; /* the anti-aliased fine image             */
    uint8_t *rgba;     /* plain fine image, RGBA8, or NULL                */
    float *z;          /* plain fine depth Zc, or NULL                    */
    uint16_t *rgb16;   /* anti-aliased fine image, RGB16, or NULL         */
    double *ray;       /* per image pixel: its centre's ray x, y          */
    double *jinv;      /* per image pixel: d(x, y)/d(u, v) there, 2x2     */
} gls_distort_frame;

/* Draw what camera c's outputs need: the plain fine image (colour if
 * want_rgba, depth if want_z) and, if want_aa, the anti-aliased one
 * (one-pass lattice, aa_onepass.h, within aa_memory bytes, 0: default);
 * and the pixel centres' rays.  Leaves the renderer at another size.  -1
 * with a message (framebuffer, memory, layout). */
int gls_distort_frame_render(gls_distort_frame *f, gls_renderer *r, const gls_camera *c, const gls_aa_plan *p,
                             int want_rgba, int want_z, int want_aa, uint64_t aa_memory, char *err, size_t errlen);

/* Ground truth at the pixel centres (nearest fine pixel): colour into
 * rgba (W x H RGBA8) and/or depth into z; either may be NULL. */
void gls_distort_frame_centre(const gls_distort_frame *f, const gls_camera *c, uint8_t *rgba, float *z);
/* The same for image pixels i0 <= i < i1 only (rgba, z: whole images). */
void gls_distort_frame_centre_range(const gls_distort_frame *f, size_t i0, size_t i1, uint8_t *rgba, float *z);

/* The plain fine image's pixel nearest to image pixel i's centre ray
 * (index into lay.fine's pixels): the rule every ground truth through the
 * lens reads by. */
size_t gls_distort_frame_nearest(const gls_distort_frame *f, size_t i);
/* Image pixels i0 <= i < i1 of the ground-truth pass's fine images
 * (fine ids, normals and depth, as gt_pass.h draws them by lay.fine), each
 * read at its nearest fine pixel, into ids, normals, z (any may be NULL:
 * not wanted). */
/* The fine rows r0..r1 (inclusive) that image pixels i0 <= i < i1 read
 * by that rule, from the same rays: exactly the rows their ground truth
 * needs drawn (a rolling shutter's band, distort_exposure.c). */
void gls_distort_frame_nearest_rows(const gls_distort_frame *f, size_t i0, size_t i1, uint32_t *r0, uint32_t *r1);
void gls_distort_frame_read_truth(const gls_distort_frame *f, size_t i0, size_t i1, const uint32_t *fine_ids,
                                  const float *fine_normals, const float *fine_z, uint32_t *ids, float *normals,
                                  float *z);

/* The plan's samples through the lens, bilinear in the anti-aliased fine
 * image, into acc (initialised for c's size).  -1 when out of memory. */
int gls_distort_frame_accum(const gls_distort_frame *f, const gls_camera *c, const gls_aa_plan *p, gls_accum *acc);

/* The same for rows v0..v1-1 only (the other rows of acc get zero
 * samples: a band of a rolling shutter, distort_exposure.h). */
int gls_distort_frame_accum_rows(const gls_distort_frame *f, const gls_camera *c, const gls_aa_plan *p, uint32_t v0,
                                 uint32_t v1, gls_accum *acc);

/* The anti-aliased fine image of plan p through the undistorted camera f
 * (the one-pass lattice, gls_distort_fine_samples(p) a fine pixel, box)
 * into rgb16 (f's size, RGB16).  -1 with a message. */
int gls_distort_render_aa(gls_renderer *r, const gls_camera *f, const gls_aa_plan *p, uint64_t aa_memory,
                          uint16_t *rgb16, char *err, size_t errlen);

void gls_distort_frame_free(gls_distort_frame *f);

/* --explain: the camera's lens model and how its image is made (nothing
 * for a camera without distortion). */
void gls_distort_explain(FILE *out, const gls_camera *c, const gls_aa_plan *p);

#endif
