/* View-frustum culling of a scene's instances and draw items (scene.h). */
#ifndef GLS_SCENE_CULL_H
#define GLS_SCENE_CULL_H
#include <stdint.h>
#include "camera.h"
#include "scene.h"

/* Image-space bounds {u0, v0, u1, v1} of the world box lo..hi through
 * camera c: the bounding box of its projected corners plus a pixel;
 * {-inf, -inf, inf, inf} when the box reaches nearer than the near plane
 * (it may be anywhere), {inf, inf, -inf, -inf} when it is wholly nearer
 * than near or beyond far (nowhere). */
void gls_box_image_bounds(const gls_camera *c, const double lo[3], const double hi[3], double b[4]);

typedef struct {
    uint32_t drawn, culled;  /* instances with geometry */
    uint32_t items_drawn;
} gls_cull_stats;

/* Which instances (ivis, s->ninst) and items (vis, s->nitems) camera c
 * can see: an instance whose box cannot reach the image is skipped, and
 * so is each item (chunk) of a visible instance whose own box cannot. */
void gls_scene_cull(const gls_scene *s, const gls_camera *c, uint8_t *ivis, uint8_t *vis, gls_cull_stats *st);

#endif
