/* Per-pixel lighting of a lit scene (the bundle's `lights` feature,
 * spec/camera.md "Lighting"): a GLSL program that replaces fixed-function
 * colouring in the colour passes, and the lights handed to it.
 *
 * Only a renderer of a lit scene has one (render.c creates it when the
 * scene's GLS_FEAT_LIGHTS is set), so an unlit scene draws through exactly
 * the fixed-function path it had before.
 *
 * The lights are composed on the CPU in double: each light's position or
 * direction in its instance's frame, by the instance's world transform
 * (motion included), then by the camera's R and T, and only then turned
 * into float, relative to the camera.  Shading happens in GL's eye frame
 * (F = diag(1, -1, -1) times OpenCV's camera frame), where the item's
 * modelview (formed camera-relative in double, render.c) puts the
 * vertices; normals go through gl_NormalMatrix of that modelview. */
#ifndef GLS_LIGHTING_H
#define GLS_LIGHTING_H

#include <stdio.h>
#include "camera.h"
#include "scene.h"

/* The lights of s for camera c, in GL's eye frame: n (at most
 * GLS_MAX_LIGHTS) directional and point lights, pos[4 i..] = unit
 * direction towards the light with w = 0, or position with w = 1;
 * col[4 i..] = colour r, g, b and attenuation k; ambient[3] the sum of
 * the ambient lights.  Returns n. */
uint32_t gls_lights_eye(const gls_scene *s, const gls_camera *c, double pos[4 * GLS_MAX_LIGHTS],
                        double col[4 * GLS_MAX_LIGHTS], double ambient[3]);

/* Light l's world position (point) or direction towards it (directional,
 * not normalised), through its instance's world transform (motion
 * included), in double. */
void gls_light_world(const gls_scene *s, const gls_light *l, double X[3]);

/* Directional and point lights of s (ambient ones not counted). */
uint32_t gls_lights_count(const gls_scene *s);

/* --explain: each light (kind, world position or direction in the first
 * frame, colour, the object that declares it) and the cost. */
void gls_lighting_explain(FILE *out, const gls_bundle *b, const gls_scene *s);

typedef struct gls_lighting gls_lighting;
struct gls_shadows;

/* The program, compiled in the context current now with the renderer's
 * GL entry points gl (glcalls.h; they must outlive it); NULL with a
 * message in err when GL lacks something or the scene has more than
 * GLS_MAX_LIGHTS directional and point lights. */
typedef struct gls_glext gls_glext;
gls_lighting *gls_lighting_create(const gls_glext *gl, const gls_scene *s, char *err, size_t errlen);
/* Before a colour pass's draws: the program on, the lights of camera c,
 * and the shadow maps sh drew for it (NULL: no shadows). */
void gls_lighting_begin(gls_lighting *l, const gls_scene *s, const gls_camera *c, const struct gls_shadows *sh);
/* When the draw key changes: how the surface colour comes from the
 * texture (none, replace, modulate), as the fixed-function path does. */
void gls_lighting_key(gls_lighting *l, const gls_drawkey *k);
/* After the pass: back to fixed function. */
void gls_lighting_end(gls_lighting *l);
void gls_lighting_destroy(gls_lighting *l);

#endif
