/* Shadow maps of directional lights (the bundle's `shadows` feature,
 * spec/camera.md "Shadows").
 *
 * Each directional light gets an orthographic depth map, drawn from the
 * light before each colour pass: its x, y extent fitted to the world boxes
 * of the draw items the camera sees (the receivers that can show a
 * shadow), its depth range to every item (so that a caster outside the
 * view still casts into it).  The lighting program (lighting.c) looks each
 * lit fragment up in the maps with a slope-scaled depth bias and 2x2
 * bilinear percentage-closer filtering.  Each point light gets a cube map
 * (shadows_cube.h: six 90-degree depth passes from the light), looked up
 * by the direction from the light with the same bias, scaled by the
 * texel's size at the point's depth. */
#ifndef GLS_SHADOWS_H
#define GLS_SHADOWS_H

#include <stdio.h>
#include "camera.h"
#include "scene.h"

/* The bias, in units of a map texel's world size t, added to the depth of
 * the lit point before it is compared with the map: t * (SHADOW_BIAS_CONST
 * + SHADOW_BIAS_SLOPE * min(tan(theta), SHADOW_BIAS_TAN_MAX)), theta the
 * angle between the normal and the light (spec/camera.md "Shadows" says
 * why, and what it costs at contacts). */
#define GLS_SHADOW_BIAS_CONST 1.0
#define GLS_SHADOW_BIAS_SLOPE 2.0
#define GLS_SHADOW_BIAS_TAN_MAX 10.0

/* One light's view: a camera-like frame (R, T, world to light; the light
 * looks along +Z, down the light's direction) and the box of its map in
 * that frame. */
typedef struct {
    double R[9], T[3];
    double x0, x1, y0, y1, z0, z1;
    double texel;          /* world size of one texel (the larger side)   */
} gls_shadow_view;

/* Fit the view of the light arriving from direction L (world, unit,
 * towards the light) for the items vis marks (NULL: all) as receivers and
 * every item as a caster, with res x res texels.  0, or -1 when the scene
 * has no items. */
int gls_shadow_fit(const gls_scene *s, const double L[3], const uint8_t *vis, uint32_t res, gls_shadow_view *v);
/* The view as a gls_camera (R, T; intrinsics unused), for the draw. */
void gls_shadow_camera(const gls_shadow_view *v, gls_camera *c);
/* Its orthographic projection from GL eye coordinates, reversed depth
 * (near 1, far 0, like the colour pass: spec/camera.md "Depth"). */
void gls_shadow_projection(const gls_shadow_view *v, double P[16]);
/* S: camera c's GL eye coordinates to the map's (s, t, depth), composed in
 * double (row-major). */
void gls_shadow_matrix(const gls_shadow_view *v, const gls_camera *c, double S[16]);

typedef struct gls_shadows gls_shadows;
struct gls_renderer;

/* The maps of s's directional and point lights, res = s->shadow_res,
 * made with the renderer's GL entry points gl (glcalls.h; they must
 * outlive them); NULL with a message when there is too little memory or
 * GL lacks something. */
typedef struct gls_glext gls_glext;
gls_shadows *gls_shadows_create(const gls_glext *gl, const gls_scene *s, char *err, size_t errlen);
/* Draw every map for camera c, whose draw items vis marks (NULL: all);
 * restores the framebuffer, viewport and scissor it found. */
void gls_shadows_render(gls_shadows *sh, struct gls_renderer *r, const gls_scene *s, const gls_camera *c,
                        const uint8_t *vis);
/* For the lighting program, after gls_shadows_render: the number of maps
 * (one per directional or point light, in gls_lights_eye's order), each's
 * S (column-major floats, 16 each) and bias per texel in depth units (0
 * for a cube map); whether each is a cube map, its near distance, and a
 * face texel's size at depth 1 (2 / res); the
 * directional maps bound to texture units 1..n, the cube maps to units
 * 9..8+n (unit 0 active again after). */
uint32_t gls_shadows_uniforms(const gls_shadows *sh, float *S, float *bias);
uint32_t gls_shadows_cube_uniforms(const gls_shadows *sh, int *cube, float *near, float *texel);
/* The point lights among the (at most 8) shaded lights: their cube maps. */
uint32_t gls_shadows_points(const gls_scene *s);
void gls_shadows_bind(const gls_shadows *sh);
uint64_t gls_shadows_bytes(const gls_scene *s);
/* --explain: the maps, their memory and cost, the bias. */
void gls_shadows_explain(FILE *out, const gls_scene *s);
void gls_shadows_destroy(gls_shadows *sh);

#endif
