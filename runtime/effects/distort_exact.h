/* Exact coverage through a lens (spec/antialiasing.md "Exact coverage in
 * glsplay"): exact in the undistorted image that the lens path resamples.
 * The undistorted fine image of the lens path's anti-aliased layout
 * (distort_render.h, GLS_DISTORT_AA_SCALE fine pixels per image pixel)
 * is drawn by exact coverage (exact_scene.h) instead of the lattice, and
 * resampled as the sampled path resamples it: each output pixel the mean
 * of GLS_DISTORT_EXACT_SAMPLES lattice positions, each mapped through the
 * inverse lens model and read bilinearly (8-bit per read).  The output is
 * thus a sampled box over a reconstruction of an exact image, not an
 * exact area in the distorted image. */
#ifndef GLS_DISTORT_EXACT_H
#define GLS_DISTORT_EXACT_H

#include "distort_render.h"
#include "exact_scene.h"

/* Lattice positions per output pixel of the resampling. */
#define GLS_DISTORT_EXACT_SAMPLES 64

/* The resampling's plan (a lattice of GLS_DISTORT_EXACT_SAMPLES).  0, or
 * -1 with a message. */
int gls_distort_exact_plan(gls_aa_plan *p, char *err, size_t errlen);

/* Camera c's image through its lens into rgba (c's width x height, RGBA
 * float), fr's rays already made (gls_distort_frame_render); scene s, its
 * bundle's textures, background bg; dense: gls_exact_render's.  Sets
 * fr's anti-aliased layout and fine image.  0, or -1 with a message. */
int gls_distort_exact(gls_distort_frame *fr, const gls_camera *c, const gls_scene *s, const gls_texture *textures,
                      const float bg[4], size_t dense, float *rgba, char *err, size_t errlen);

#endif
