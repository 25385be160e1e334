/* Ground truth through a lens that needs more than the one pass of the
 * frame (spec/outputs.md "Through a lens"): the ground-truth pass of any
 * pose of the camera read at the pixel centres' rays (the next frame's
 * depth, for flow), flow whose points are projected by the lens model,
 * and the boxes' pixels-drawn-alone and truncation through it.  Every
 * read of a fine image takes the nearest fine pixel to the pixel centre's
 * ray (gls_distort_frame_nearest), as depth and ids do. */
#ifndef GLS_LENS_TRUTH_H
#define GLS_LENS_TRUTH_H

#include <stddef.h>
#include <stdint.h>
#include "camera.h"
#include "distort_render.h"
#include "gt_boxes.h"
#include "gt_flow.h"
#include "render.h"
#include "scene.h"

/* The ground-truth pass (gt_pass.h) of camera c (f's lens, any pose)
 * through the plain fine camera of f posed as c, read at c's pixel
 * centres: ids, normals (W x H x 3) and depth Zc, any of them NULL; with
 * z, leaves the renderer at the fine camera's size.  0, or -1 with a
 * message (out of memory, framebuffer, the pass's own). */
int gls_lens_gt_render(gls_renderer *r, const gls_distort_frame *f, const gls_camera *c, uint32_t *ids,
                       float *normals, float *z, char *err, size_t errlen);

/* gls_flow_compute for a camera with lens distortion (f: its frame):
 * pixel i's point at t is z[i] times its centre's ray (f->ray), moved as
 * without a lens, and projected by c1's distortion model at t+1
 * (gls_distort_project).  A point behind the camera or at or beyond the
 * model's fold (undistorted r^2 >= max_r2: no image position) gets
 * GLS_FLOW_UNKNOWN and GLS_FLOW_OUT; visibility as gls_flow_visibility
 * with z1 the depth of t+1 through the lens and a spread of one fine
 * pixel (1 / f->lay.mag image pixels): z and z1 are each read up to half
 * a fine pixel from the pixel centre. */
void gls_flow_compute_lens(const gls_camera *c0, const gls_camera *c1, const gls_distort_frame *f,
                           const uint32_t *inst, const float *z, const float *z1, const gls_flow_moves *m, float *uv,
                           uint8_t *mask);

/* Edge samples of a 3D box's outline for its truncation through a lens:
 * each of the 12 edges, clipped to Zc >= near, at this many equal steps. */
#define GLS_LENS_BOX_EDGE_STEPS 64

/* The truncation of a box with camera-frame corners k (gt_boxes.h's
 * order) through c's lens: 1 - the fraction of the bounding rectangle of
 * its edge samples' images (gls_distort_project; a sample at or beyond
 * the fold is taken at the fold along its direction) inside the image's
 * [-0.5, W - 0.5] x [-0.5, H - 0.5]; 1 when the box is wholly nearer
 * than near. */
double gls_lens_box_truncation(const gls_camera *c, const double k[8][3]);

/* gls_boxes_compute through f's lens: 2D boxes from the (distorted)
 * instance image ids, 3D boxes as without a lens, truncation by
 * gls_lens_box_truncation, and the pixels each instance covers drawn
 * alone through the plain fine camera, read at the pixel centres.  Leaves
 * the renderer at the fine camera's size.  0, or -1 when out of memory or
 * the framebuffer fails (err). */
int gls_boxes_compute_lens(gls_renderer *r, const gls_scene *s, const gls_camera *c, const gls_distort_frame *f,
                           const uint32_t *ids, gls_box **boxes, size_t *n, char *err, size_t errlen);

#endif
