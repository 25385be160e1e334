/* Optical flow from a frame t of a trajectory to the next, t+1, from the
 * ground truth (spec/outputs.md "Optical flow"): for every pixel with a
 * surface at t, the camera point from the centre-sample depth, to the
 * world, to its instance's frame at t, back to the world with the
 * instance's pose at t+1, projected by the camera at t+1, all in double.
 *
 * Moving instances: those moved by --motion and their descendants (their
 * world transform changes with the motion of an ancestor); every other
 * instance has the same world transform in both frames, so it needs no
 * table.  gls_flow_moves holds the affected instances' world transforms
 * at t and t+1.
 */
#ifndef GLS_GT_FLOW_H
#define GLS_GT_FLOW_H

#include <stddef.h>
#include <stdint.h>
#include "camera.h"
#include "scene.h"

/* flowmask values (flowmask_F.png) */
enum { GLS_FLOW_NONE = 0, GLS_FLOW_VISIBLE = 1, GLS_FLOW_OCCLUDED = 2, GLS_FLOW_OUT = 3 };

/* The occlusion tolerance: occluded when the point's depth Zc' at t+1 is
 * farther than the t+1 depth at the nearest pixel by more than
 * GLS_FLOW_OCC_REL * Zc' plus, along u and along v, the larger change of
 * the t+1 depth to a neighbouring pixel times the point's offset from the
 * nearest pixel's centre (at most half a pixel), spec/outputs.md. */
#define GLS_FLOW_OCC_REL 1e-3

/* .flo's unknown value (Middlebury: anything above 1e9 is unknown). */
#define GLS_FLOW_UNKNOWN 1e10f

typedef struct {
    uint32_t n;          /* affected instances                         */
    uint32_t *slot;      /* per scene instance: its row, or GLS_NONE    */
    double (*inv0)[12];  /* per row: inverse of the world at t (3x4)    */
    double (*w1)[12];    /* per row: world at t+1 (3x4)                 */
} gls_flow_moves;

/* The instances that moved[0..nmoved-1] move (those and their
 * descendants; parents come first in the table).  0, or -1 when out of
 * memory.  nmoved = 0 gives an empty table (a static scene). */
int gls_flow_moves_init(gls_flow_moves *m, const gls_scene *s, const uint32_t *moved, size_t nmoved);
/* Record the affected instances' world transforms as they are now in s:
 * at t (which = 0: stored inverted) or at t+1 (which = 1). */
void gls_flow_moves_take(gls_flow_moves *m, const gls_scene *s, int which);
void gls_flow_moves_free(gls_flow_moves *m);

/* The flow of every pixel of camera c0 (frame t) into camera c1 (frame
 * t+1; same size): inst and z are the ground-truth pass of frame t
 * (instance + 1, Zc; gt_pass.h), z1 the depth of frame t+1 (instances
 * posed at t+1, camera c1).  uv: 2 floats a pixel, top row first (u'-u,
 * v'-v; GLS_FLOW_UNKNOWN where there is no surface or the point is behind
 * the camera at t+1); mask: GLS_FLOW_* a pixel. */
/* World point P of instance id (instance + 1) at t, moved to t+1 in place
 * (no change for an instance nothing moves). */
void gls_flow_move_point(const gls_flow_moves *m, uint32_t id, double P[3]);
/* The mask value of a point at depth Z in camera c1 (frame t+1) seen at
 * image position (u1, v1): GLS_FLOW_OUT outside the image or the near..far
 * range, GLS_FLOW_OCCLUDED behind z1 (the depth of frame t+1, c1's size)
 * by more than the tolerance above, else GLS_FLOW_VISIBLE.  spread (px)
 * is added to both offsets: how far z1[j] may have been read from pixel
 * j's centre (0 without a lens; through one, half a fine pixel). */
uint8_t gls_flow_visibility(const gls_camera *c1, const float *z1, double u1, double v1, double Z, double spread);

void gls_flow_compute(const gls_camera *c0, const gls_camera *c1, const uint32_t *inst, const float *z,
                      const float *z1, const gls_flow_moves *m, float *uv, uint8_t *mask);

#endif
