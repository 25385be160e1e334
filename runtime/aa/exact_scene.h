/* Exact coverage of a scene (spec/antialiasing.md "Exact coverage in
 * glsplay"): every triangle of every instance, in double from the
 * scene's exact positions and the instances' world transforms, cut at the
 * camera's near and far planes and projected through its pinhole
 * (exact.h), with what the region colour needs: the triangle's vertices
 * in camera space, their colours, and where the scene keeps their texture
 * coordinates, normals and specular colours.  A region's colour is its
 * triangle's shaded as GL shades it (perspective-correct interpolation;
 * the texture's base level bilinear with GL_REPEAT, as 8-bit texels /
 * 255, replace or modulate; lighting.c's per-pixel Lambert and Phong in
 * double; the result clamped to 0..1 as the 8-bit framebuffer clamps each
 * sample): at the region's centroid for flat and vertex colours (exact
 * for flat colour), the mean over the pixel's GLS_EXACT_SHADE_M lattice
 * points in the region for textured and lit triangles (exact.h); a
 * triangle whose texture has transparent texels (the scene's alpha test)
 * is point-sampled at those points (GLS_EXACT_HOLES).  Shadows are not
 * drawn this way (gls_exact_scene_unsupported says why). */
#ifndef GLS_EXACT_SCENE_H
#define GLS_EXACT_SCENE_H

#include <stddef.h>
#include "camera.h"
#include "exact.h"
#include "bundle.h"
#include "scene.h"

typedef struct {
    double P[3][3];     /* camera-space vertices of the whole triangle     */
    double C[3][3];     /* P[k+1] x P[k+2]: a ray d meets the triangle's
                           plane at barycentric weights d.C[k] / sum      */
    float rgba[3][4];   /* their colours, 0..1                             */
    uint32_t v;         /* its first vertex in the scene                   */
    uint32_t inst;      /* its instance                                    */
    uint32_t chunk;     /* its chunk (texture and mode)                    */
} gls_exact_vcol;

typedef struct {
    gls_exact_tri *t;   /* the image triangles                             */
    gls_exact_vcol *v;  /* per image triangle: its whole triangle's        */
    size_t n, cap;
    double fx, fy, cx, cy, skew;
    const gls_scene *s;
    const gls_texture *tex; /* the bundle's textures                      */
    double *nm;         /* lit: per instance, the 3x3 normal matrix to GL's
                           eye frame (row-major)                           */
    uint32_t nl;        /* lit: lights as lighting.c's uniforms            */
    double lpos[4 * GLS_MAX_LIGHTS], lcol[4 * GLS_MAX_LIGHTS], amb[3];
} gls_exact_geom;

/* The camera's view as six half-spaces of camera space, n . X + d >= 0:
 * the image's columns -1.5..width + 0.5 and rows -1.5..height + 0.5
 * (a pixel's margin around its pixel squares), between the near and the
 * far plane.  A box whose eight corners all miss one of them is outside
 * the view (the view is their intersection, and a half-space holds a box
 * when it holds its corners), and no triangle in it can touch a pixel:
 * such an instance's triangles are not projected at all.  Without it a
 * scene of many instances mostly out of view, which the GL passes cull,
 * had every triangle of every instance projected and held (2^27 of them
 * in tests/e2e/load_limits.sh, more memory than the machine had). */
typedef struct {
    double n[6][3], d[6];
} gls_exact_view;

void gls_exact_view_make(const gls_exact_pinhole *cam, uint32_t w, uint32_t h, gls_exact_view *v);
/* Instance i's chunks that may meet the view, in order: the first
 * (GLS_NONE: none, or the instance draws nothing or is out of view) and
 * the one after ch. */
uint32_t gls_exact_view_first(const gls_exact_view *v, const gls_exact_pinhole *cam, const gls_scene *s, uint32_t i);
uint32_t gls_exact_view_next(const gls_exact_view *v, const gls_exact_pinhole *cam, const gls_scene *s, uint32_t i,
                             uint32_t ch);

/* NULL when gls_exact_geom_make can draw s, else why not ("shadows
 * ..."). */
const char *gls_exact_scene_unsupported(const gls_scene *s);

/* The image triangles of s under c (ids: instance indices); textures: the
 * bundle's (needed when s is textured).  0, or -1 when out of memory or
 * a textured scene comes without its textures. */
int gls_exact_geom_make(gls_exact_geom *g, const gls_scene *s, const gls_texture *textures, const gls_camera *c);
void gls_exact_geom_free(gls_exact_geom *g);

/* The shader of gls_exact_image for g (user = g). */
void gls_exact_geom_shade(void *user, const gls_exact_tri *t, size_t i, const double *x, const double *y, size_t n,
                          float (*rgba)[4]);

/* The exact image (float RGBA) to the file formats: 8-bit RGBA and 16-bit
 * RGB rounded to nearest, float RGB as it is; values clamped to 0..1. */
void gls_exact_rgba8(const float *rgba, size_t n, uint8_t *out);
void gls_exact_rgb16(const float *rgba, size_t n, uint16_t *out);
void gls_exact_rgbf(const float *rgba, size_t n, float *out);

#endif
