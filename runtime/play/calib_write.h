/* glsplay --write-calib: the cameras of a run in the calibration formats
 * vision tools read (spec/outputs.md "Calibration files"): OpenCV
 * FileStorage YAML and a JSON per frame, KITTI calib.txt and ROS
 * CameraInfo YAML for the rig.  Every file is written whole through a
 * temporary file and a rename. */
#ifndef GLS_CALIB_WRITE_H
#define GLS_CALIB_WRITE_H
#include <stdio.h>
#include "buf.h"
#include "camera.h"
#include "player.h"
#include "trajectory.h"

/* Write the calibration files of a run whose frames were rendered: for
 * the single render (frame o->frame) or for every frame of the
 * trajectory traj (o->trajectory's text as the run read it once; NULL
 * without one) in [o->frame_first, o->frame_end).  cams are the cameras
 * as loaded (with a trajectory: relative to the rig), names their output
 * names, in the order of --camera (camera 0 is the first).  0, or 1 after
 * a "glsplay: error: ..." line on errs. */
int gls_calib_write(const gls_play_opts *o, const gls_traj_text *traj, const gls_camera *cams,
                    const char *const *names, FILE *errs);

/* The pose of camera i relative to camera 0, x0 -> xi: R = Ri R0^T,
 * t = Ti - R T0 (R = I and t = Ti - T0 exactly when Ri == R0). */
void gls_calib_relative(const gls_camera *c0, const gls_camera *ci, double R[9], double t[3]);

/* The file texts, appended to b (0, or -1 when out of memory).
 * OpenCV FileStorage YAML of one camera with its world pose (R, T). */
int gls_calib_opencv_yaml(gls_buf *b, const gls_camera *c, const char *name, uint32_t frame);
/* KITTI calib.txt: "Pi:" and K_i [R_i0 | t_i0] for each camera. */
int gls_calib_kitti(gls_buf *b, const gls_camera *cams, size_t n);
/* ROS CameraInfo YAML of camera i of the rig (cams[0] is camera 0). */
int gls_calib_ros_yaml(gls_buf *b, const gls_camera *cams, const char *const *names, size_t i);

#endif
