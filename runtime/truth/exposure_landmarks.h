/* Landmarks under a rolling shutter (spec/camera.md "Exposure effects"):
 * each mark where it is at the time of the band of rows it projects
 * into.  The truth room's part of the exposure effects (effects/exposure.h
 * gives the poses). */
#ifndef GLS_EXPOSURE_LANDMARKS_H
#define GLS_EXPOSURE_LANDMARKS_H

#include "exposure.h"
#include "gt_landmarks.h"

/* Rolling shutter: landmark k of l (taken at the frame time) replaced by
 * where it is at the time of the band of `band` rows it projects into,
 * with that time's camera pose (l->pose); the scene left at s = 0.  0,
 * or -1 when out of memory. */
int gls_exposure_landmarks(const gls_scene *s, const gls_camera *c, uint32_t band, gls_pose_at_fn pose_at, void *ud,
                           gls_landmarks *l);

#endif
