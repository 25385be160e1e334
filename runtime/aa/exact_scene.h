/* Exact coverage of a scene (spec/antialiasing.md "Exact coverage in
 * glsplay"): every triangle of every instance, in double from the
 * scene's exact positions and the instances' world transforms, cut at the
 * camera's near and far planes and projected through its pinhole
 * (exact.h), with what the region colour needs: the triangle's vertices
 * in camera space and their colours.  A region's colour is its
 * triangle's, interpolated as GL interpolates (perspective-correct), at
 * the region's centroid: exact for flat colour, sampled at the centroid
 * for vertex colours.  Lit and textured scenes are not drawn this way
 * (gls_exact_scene_unsupported says why). */
#ifndef GLS_EXACT_SCENE_H
#define GLS_EXACT_SCENE_H

#include <stddef.h>
#include "camera.h"
#include "exact.h"
#include "scene.h"

typedef struct {
    double P[3][3];     /* camera-space vertices of the whole triangle     */
    float rgba[3][4];   /* their colours, 0..1                             */
} gls_exact_vcol;

typedef struct {
    gls_exact_tri *t;   /* the image triangles                             */
    gls_exact_vcol *v;  /* per image triangle: its whole triangle's        */
    size_t n, cap;
    double fx, fy, cx, cy, skew;
} gls_exact_geom;

/* NULL when gls_exact_geom_make can draw s, else why not ("a lit scene",
 * "a textured object"). */
const char *gls_exact_scene_unsupported(const gls_scene *s);

/* The image triangles of s under c (ids: instance indices).  0, or -1
 * when out of memory. */
int gls_exact_geom_make(gls_exact_geom *g, const gls_scene *s, const gls_camera *c);
void gls_exact_geom_free(gls_exact_geom *g);

/* The shader of gls_exact_image for g (user = g). */
void gls_exact_geom_shade(void *user, const gls_exact_tri *t, size_t i, double x, double y, float rgba[4]);

/* The exact image (float RGBA) to the file formats: 8-bit RGBA and 16-bit
 * RGB rounded to nearest, float RGB as it is; values clamped to 0..1. */
void gls_exact_rgba8(const float *rgba, size_t n, uint8_t *out);
void gls_exact_rgb16(const float *rgba, size_t n, uint16_t *out);
void gls_exact_rgbf(const float *rgba, size_t n, float *out);

#endif
