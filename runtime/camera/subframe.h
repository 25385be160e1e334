/* Poses at a fractional frame time (spec/camera.md "Sub-frame poses"):
 * what motion blur and rolling shutter render.  A time is a frame number
 * plus a fraction, x = k + s: one frame interval is one frame number.
 * Between the rows at frames a <= x <= b (consecutive rows of a motion
 * file, or of a trajectory read whole) the pose is interpolated with
 * u = (x - a) / (b - a), in double:
 *   rotation: slerp of the rows' unit quaternions (the shorter arc);
 *   translation: lerp.  For a motion file's object-to-parent [R | T] that
 *     is T, the object's origin in its parent.  For a trajectory's
 *     world-to-rig pose it is the rig's centre C = -R^T T (the camera
 *     moves on the straight line between its centres), T = -R C after.
 * At a row's own frame the row is returned unchanged, bit for bit, so a
 * sub-frame render at s = 0 is the plain render.  Outside the rows
 * (before the first, after the last) there is no pose: refused, never
 * clamped (a clamped pose would blur less than asked, silently). */
#ifndef GLS_SUBFRAME_H
#define GLS_SUBFRAME_H
#include <stdio.h>
#include "motion.h"
#include "trajectory.h"

/* Interpolate rotation R0 -> R1 (slerp) and translation T0 -> T1 (lerp)
 * at u in [0, 1]; u = 0 and u = 1 give the ends exactly.  centre: T is a
 * world-to-frame translation and the lerp is of the centres -R^T T. */
void gls_pose_interp(const double R0[9], const double T0[3], const double R1[9], const double T1[3], double u,
                     int centre, double R[9], double T[3]);

/* The pose of m at time x (frame number + fraction): 0, or -1 when x is
 * before m's first row or after its last.  centre as above. */
int gls_motion_pose_at(const gls_motion *m, double x, int centre, double R[9], double T[3]);

/* A trajectory's text parsed whole into m (frame numbers and world-to-rig
 * poses, gls_traj_next's checks), for sub-frame poses.  0, or -1 with
 * "path:line: error: ..." in err.  Notes go to notes. */
int gls_traj_read_all(const gls_traj_text *tx, FILE *notes, gls_motion *m, char *err, size_t errlen);

#endif
