/* Motion blur, rolling shutter and depth of field through a distorted
 * lens (spec/camera.md "Through a lens"): the exposure's sub-frame
 * samples and bands (exposure.h) with each band's image drawn as the lens
 * draws its image (distort_render.h):
 *  - the image: for each sample j (time s_j, lens point l_j) and each band
 *    of distorted rows v0..v1-1 (the whole image without a rolling
 *    shutter), the anti-aliased undistorted fine image at that band's
 *    time, its projection sheared for l_j as the pinhole's (the plane
 *    Zc = focus stays in place; the shear acts on the undistorted ray,
 *    before the lens model), cropped to the fine rows the band's pre-image
 *    under the model covers (a curved strip: the rows between its least
 *    and greatest fine row, found on its border); each anti-aliasing
 *    sample of the band's pixels mapped through the inverse model and read
 *    there bilinearly, accumulated exactly as the pinhole path;
 *  - with a rolling shutter, the ground truth of each band of rows (depth,
 *    colour of the points, ids, normals): the plain fine pass at the
 *    band's time, read at the band's pixel centres (nearest fine pixel).
 * Without a rolling shutter the ground truth is the lens's own (the frame
 * time, lens centre; play_frame.c). */
#ifndef GLS_DISTORT_EXPOSURE_H
#define GLS_DISTORT_EXPOSURE_H
#include <stdio.h>
#include "distort_render.h"
#include "exposure.h"

/* The image of lens camera c with its exposure e into acc (c's size),
 * its pixels' rays from df (gls_distort_frame_render: ray, jinv); band as
 * gls_exposure_render.  Leaves the scene at the frame time and the
 * renderer at another size.  0, or -1 with the whole message in msg. */
int gls_distort_exposure_render(gls_renderer *r, const gls_camera *c, const gls_exposure *e, const gls_aa_plan *p,
                                const gls_distort_frame *df, gls_pose_at_fn pose_at, void *ud, uint32_t band,
                                uint64_t aa_memory, const char *name, gls_accum *acc, char *msg, size_t msglen);

/* Rolling shutter through a lens: the ground truth of each band of
 * bands.rows rows at its middle row's time, through the plain fine camera of df
 * (df->lay, df->ray): colour (rgba) and depth (z) of the plain pass, ids
 * and normals of the ground-truth pass (gt_pass.h), and that pass's depth
 * (gt_z: where flow starts, as without a lens); NULL: not wanted.  Each
 * band draws and reads the fine rows its pixels read, or the whole fine
 * image when bands.whole (exposure.h).  Leaves the scene at the frame time (pose_at's time 0).  0, or -1 with a message (no
 * prefix) in err. */
int gls_distort_truth_bands(gls_renderer *r, const gls_camera *c, const gls_distort_frame *df, gls_bands bands,
                            gls_pose_at_fn pose_at, void *ud, uint8_t *rgba, float *z, uint32_t *inst, float *normal,
                            float *gt_z, char *err, size_t errlen);

/* --explain: what the exposure costs through a lens (nothing without a
 * lens or an exposure effect). */
void gls_distort_exposure_explain(FILE *out, const gls_camera *c, int moving, const gls_aa_plan *p);

#endif
