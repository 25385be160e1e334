/* Disparity of a rectified pair (spec/outputs.md "Disparity and 16-bit
 * depth"): the check that two cameras form one, and d = fx B / Zc. */
#ifndef GLS_OUT_DISPARITY_H
#define GLS_OUT_DISPARITY_H

#include <stddef.h>
#include <stdio.h>
#include "camera.h"

/* Is (l, r) a rectified pair, l the left camera: the same size, the same
 * fx, fy, cx, cy, skew (within 1e-9 of the larger value, or of fx), the
 * same rotation (1e-9 per entry), and r's centre at (B, 0, 0) in l's
 * frame with B > 0 (y and z within 1e-9 B)?  R and T are taken as given
 * (rig-relative with a trajectory: the rig moves the pair as a whole).
 * 0 with *B, or -1 with what is wrong, to follow "needs a rectified pair:
 * ", in err ("cameras left and right have different rotations"). */
int gls_rectified_pair(const gls_camera *l, const gls_camera *r, const char *lname, const char *rname, double *B,
                       char *err, size_t errlen);

/* d[i] = fxB / z[i] (fx B of the camera), +inf where z[i] is not finite
 * (no surface), as float. */
void gls_disparity_from_z(const float *z, size_t n, double fxB, float *d);

#endif
