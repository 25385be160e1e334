/* Object boxes of one camera frame (spec/outputs.md "Boxes"): for every
 * instance the instance image shows (instance 0, the top object's own
 * geometry, left out), its tight 2D box from the instance image, its 3D
 * box (its geometry's box in its own frame, under its pose of the frame,
 * in the camera frame) and the KITTI label's derived fields.
 *
 * Occlusion needs the pixels the instance would cover drawn alone: one
 * pass per box drawing only its items (gls_render_mapped) into the
 * renderer's framebuffer, whose depth is read back and counted. */
#ifndef GLS_GT_BOXES_H
#define GLS_GT_BOXES_H

#include <stddef.h>
#include <stdint.h>
#include "camera.h"
#include "render.h"
#include "scene.h"

typedef struct {
    uint32_t inst;          /* scene instance (its id in the image: + 1)   */
    uint64_t pixels;        /* pixels showing it                           */
    uint64_t alone;         /* pixels it covers drawn alone (in the image)  */
    double bbox[4];         /* left top right bottom, pixel edges          */
    double corners[8][3];   /* camera frame; corner k is the object-frame
                               box's (bit 0: x, bit 1: y, bit 2: z; 0 lo,
                               1 hi)                                        */
    int up, len, wid;       /* object-frame axes chosen as h, l, w         */
    double dims[3];         /* h w l                                        */
    double loc[3];          /* bottom centre, camera frame                  */
    double ry, alpha;       /* KITTI rotation_y and observation angle      */
    double truncated;       /* 0..1                                         */
    double visible;         /* pixels / alone (at most 1)                   */
    int occluded;           /* KITTI 0..2 from visible                      */
} gls_box;

/* The boxes of camera c (the renderer's framebuffer at the camera's
 * size; the scene posed for this frame), from the instance image ids
 * (instance + 1 a pixel, top row first; gt_pass.h).  Sorted by instance.
 * 0 with *boxes (malloc'ed, NULL when none) and *n, or -1 when out of
 * memory.  Leaves the renderer's framebuffer holding the last box's
 * pass. */
int gls_boxes_compute(gls_renderer *r, const gls_scene *s, const gls_camera *c, const uint32_t *ids,
                      gls_box **boxes, size_t *n);

/* What the boxes of camera c need of no pass (the lens or not): the 2D
 * boxes and pixel counts from ids and the 3D boxes and KITTI angles;
 * truncated, alone, visible and occluded left 0.  0 with *boxes, *n, or
 * -1 when out of memory. */
int gls_boxes_base(const gls_scene *s, const gls_camera *c, const uint32_t *ids, gls_box **boxes, size_t *n);
/* Set alone (at least pixels), visible and occluded from the pixels the
 * box's instance covers drawn alone. */
void gls_box_set_alone(gls_box *b, uint64_t alone);

/* 1 - area(R ∩ I) / area(R) for the rectangle R = [u0, u1] x [v0, v1]
 * of a box's image and I = [-0.5, W - 0.5] x [-0.5, H - 0.5]: 1 when R
 * is empty (u1 < u0: the box is wholly nearer than near), 0 when it has
 * no area. */
double gls_box_truncation_of(const gls_camera *c, double u0, double v0, double u1, double v1);

/* KITTI occlusion level of a visible fraction: 0 (at least 0.9 of the
 * instance's pixels visible), 1 (at least 0.5), 2 (less). */
int gls_box_occlusion_level(double visible);

#endif
