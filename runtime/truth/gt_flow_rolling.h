/* Optical flow with a rolling shutter (spec/outputs.md "Optical flow",
 * "With a rolling shutter"): both frames are rolling images.  Pixel (u, v)
 * of frame t shows its surface at its row's time (its band's, as its
 * depth and instance were drawn, exposure.h); its point goes to where the
 * rolling image of frame t+1 shows it: the row v' whose time t1 + v' D
 * sees the point at row v', the fixed point of
 *     v' = y(v'),   y(v') = the row the point projects to with the camera
 *                   and its instance posed at t1 + v' D,
 * solved by iteration from the projection at t1 (row 0's time).  The
 * poses are taken at every row's time t1 + r D, and y, u and Zc are
 * linear between consecutive rows.  The iteration contracts when the
 * point moves less than 1/D rows a frame interval; a point whose iterate
 * does not settle within GLS_FLOW_RS_TOL px in GLS_FLOW_RS_ITER steps has
 * no flow (unknown, mask out of view).  Visibility: as gt_flow.h, against
 * the depth of frame t+1's rolling image (its bands at their times). */
#ifndef GLS_GT_FLOW_ROLLING_H
#define GLS_GT_FLOW_ROLLING_H

#include <stdint.h>
#include "distort_render.h"
#include "exposure.h"
#include "gt_flow.h"

#define GLS_FLOW_RS_TOL 1e-6
#define GLS_FLOW_RS_ITER 50

typedef struct {
    uint32_t H, n;      /* rows; moving instances (gls_flow_moves' n)       */
    double (*cam0)[12]; /* per row of frame t: the camera pose its depth was drawn with */
    double (*inv0)[12]; /* per row x n: the instances' inverse worlds then   */
    double (*cam1)[12]; /* per row r: the camera pose at t1 + r D            */
    double (*w1)[12];   /* per row x n: the instances' worlds then           */
} gls_flow_rows;

/* Fill fr for camera c (line_delay D, bands of `band` rows) from the
 * scene posed by pose_at (relative to frame t; frame t+1 is next_dt
 * later), recording m's instances.  Leaves the scene at frame t.  0; 1
 * when a pose is beyond the rows of the trajectory or a motion file (*bad:
 * the time, frame intervals after frame t); -1 when out of memory. */
int gls_flow_rows_fill(gls_flow_rows *fr, const gls_camera *c, uint32_t band, double next_dt, gls_flow_moves *m,
                       const gls_scene *s, gls_pose_at_fn pose_at, void *ud, double *bad);
void gls_flow_rows_free(gls_flow_rows *fr);

/* Frame t+1's rolling depth (bands of bands.rows rows at t1's row times)
 * into z1 (c's size; the renderer at c's size); through f's lens (NULL:
 * none) each band's ground-truth depth read at the nearest fine pixel
 * (gls_distort_truth_bands; the renderer left at another size).  Each
 * band draws and reads its own rows, or the whole image when bands.whole
 * (exposure.h).  Leaves the scene at frame t.  0, or -1 with a message
 * (no prefix) in err. */
int gls_flow_rolling_depth(gls_renderer *r, const gls_camera *c, const gls_distort_frame *f, gls_bands bands,
                           double next_dt, gls_pose_at_fn pose_at, void *ud, float *z1, char *err, size_t errlen);

/* The flow of every pixel of camera c (its size, intrinsics, near and
 * far) from the rolling ground truth of frame t (inst, z) into frame
 * t+1's rolling image (depth z1), as gls_flow_compute's uv and mask.
 * Through a lens (f: c's frame, its pixel centres' rays; NULL: none, a
 * pinhole): pixel i's point is z[i] times its centre's exact ray, y and u
 * are the lens model's projection (gls_distort_project) at each row's
 * pose, a row where the point lies behind the camera or at or beyond the
 * model's fold ends the iteration (no flow, as one that does not settle),
 * and the visibility has the lens's spread of one fine pixel
 * (gls_flow_compute_lens). */
void gls_flow_compute_rolling(const gls_camera *c, const gls_distort_frame *f, const gls_flow_rows *fr,
                              const gls_flow_moves *m, const uint32_t *inst, const float *z, const float *z1,
                              float *uv, uint8_t *mask);

#endif
