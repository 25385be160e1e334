/* The OpenCV pinhole camera of glscene and its mapping onto OpenGL.
 *
 * spec/camera.md derives every formula in this file; the comments here
 * only name them.  All arithmetic is double precision: GL receives the
 * results as float only after the large terms have cancelled (the
 * modelview is camera-relative), see gls_camera_modelview().
 */
#ifndef GLS_CAMERA_H
#define GLS_CAMERA_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "sensor_params.h"

#define GLS_CAMERA_MAX_DIM 16384u
/* Camera files are a few hundred bytes; the cap keeps a wrong path (a
 * bundle, a device) from being read whole (spec/camera.md). */
#define GLS_CAMERA_MAX_FILE ((size_t)1 << 20)

/* The frame a camera file's R and T are given in (its 'pose' key):
 * undeclared, the world (P_cam = R P_world + T), or the rig of a
 * trajectory (P_cam = R P_rig + T).  As a use: how the caller applies R
 * and T; GLS_POSE_UNDECLARED then means "either, no check". */
typedef enum { GLS_POSE_UNDECLARED = 0, GLS_POSE_WORLD = 1, GLS_POSE_RIG = 2 } gls_pose;

/* Lens distortion (spec/camera.md "Lens distortion"; the model in
 * distort.h): none (an ideal pinhole, the default), OpenCV's
 * Brown-Conrady model of cv::projectPoints (k1 k2 p1 p2 [k3 [k4 k5 k6]])
 * or its fisheye model of cv::fisheye (k1 k2 k3 k4).  A camera whose
 * coefficients are all zero has model GLS_LENS_NONE: the pinhole path,
 * unchanged. */
typedef enum { GLS_LENS_NONE = 0, GLS_LENS_BROWN = 1, GLS_LENS_FISHEYE = 2 } gls_lens_model;
typedef struct {
    gls_lens_model model;
    unsigned n;            /* coefficients given: Brown 4, 5 or 8; fisheye 4 */
    double k[8];           /* Brown: k1 k2 p1 p2 k3 k4 k5 k6; fisheye: k1..k4 */
    double max_r2;         /* undistorted r^2 where the model folds back,
                              gls_distort_setup (distort.h)             */
} gls_distortion;

typedef struct {
    uint32_t width, height;
    double fx, fy, cx, cy, skew;
    double R[9];           /* world to camera, row-major                  */
    double T[3];           /* Pc = R * P + T                               */
    double near, far;      /* clipping distances along +Z, scene units    */
    gls_pose pose;         /* as the file declares it                     */
    gls_distortion dist;   /* lens distortion; model 0: none              */
    gls_sensor sensor;     /* sensor effects (sensor.h); on 0: none       */
    /* Effects (spec/camera.md "Motion blur, rolling shutter, depth of
     * field"), 0 = off: the exposure as a fraction of the frame interval,
     * centred on the frame time; the time between consecutive rows'
     * exposures, in frame intervals; the lens diameter and the focus
     * distance along the optical axis, scene units; the sub-frame renders
     * (time and lens samples) of blur and depth of field. */
    double shutter, line_delay, aperture, focus;
    uint32_t exposure_samples;
} gls_camera;

/* exposure_samples when the file does not give it */
#define GLS_EXPOSURE_SAMPLES_DEFAULT 16u
#define GLS_EXPOSURE_SAMPLES_MAX 4096u

/* Parse a camera file's text.  fname is used only in messages.  use is
 * how the caller applies R and T (GLS_POSE_WORLD for a single render,
 * GLS_POSE_RIG with a trajectory, GLS_POSE_UNDECLARED: no check); a file
 * declaring the other frame is an error at its 'pose' line.  On error
 * returns -1 and writes "fname:line:col: error: message", the source line
 * and a caret to err.  Notes about an accepted file go to notes, one line
 * each (R re-orthonormalised, runtime/camera/rotation.h; a rig use of a file
 * that does not declare its frame); NULL drops them. */
int gls_camera_parse(const char *text, size_t len, const char *fname, gls_pose use, FILE *notes, gls_camera *cam,
                     char *err, size_t errlen);

/* Read and parse a camera file ("fname: error: ..." if it cannot be read). */
int gls_camera_load(const char *path, gls_pose use, FILE *notes, gls_camera *cam, char *err, size_t errlen);

/* Reversed-Z float depth keeps float precision only while the mapping's
 * coefficients a = n/(f-n), b = n f/(f-n) are at least 2^-102 and b is at
 * most FLT_MAX (spec/camera.md "Depth range").  0 if near, far (far > near
 * > 0) qualify, else -1; either way *near_min and *near_max are the limits
 * on near for this far. */
#define GLS_DEPTH_MIN 0x1p-102
int gls_camera_depth_range(double near, double far, double *near_min, double *near_max);

/* Projection matrix, row-major, eye space -> clip space, for a principal
 * point shifted by (du, dv) pixels (0,0 for a plain render; sub-pixel
 * jitter for anti-aliasing passes).  Maps image (u, v) to GL window
 * (u + 0.5, v + 0.5) and Zc in [near, far] to depth [1, 0] (reversed Z,
 * glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)). */
void gls_camera_projection(const gls_camera *c, double du, double dv, double P[16]);

/* Projection for a 2D affine map of the image: image (u, v) goes to GL
 * window (m[0] u + m[1] v + m[2], m[3] u + m[4] v + m[5]) in a viewport
 * (0, 0, vw, vh); depth as above.  gls_camera_projection is the map
 * (1, 0, du + 1/2; 0, 1, dv + 1/2) with the camera's size (computed
 * there with its own rounding, which plain images keep).  The one-pass
 * anti-aliasing renders a fine framebuffer this way (aa_fine.h). */
void gls_camera_projection_map(const gls_camera *c, const double m[6], double vw, double vh, double P[16]);

/* Modelview, row-major, for geometry stored as offsets from anchor (world
 * coordinates): eye = diag(1,-1,-1) * (R * (anchor + off) + T).  The
 * translation R*anchor + T is formed in double, so it is small whenever the
 * anchor is near the camera, however far both are from the world origin. */
void gls_camera_modelview(const gls_camera *c, const double anchor[3], double MV[16]);

/* Depth buffer value -> camera Zc (reversed Z): Zc = n f / ((f - n) d + n).
 * d == 0 (the clear value: no surface) gives +inf. */
double gls_camera_depth_to_z(const gls_camera *c, double d);

/* Camera-frame point of pixel (u, v) at depth Zc (exact inverse of the
 * projection, skew included; through the inverse lens model, distort.h,
 * when the camera has distortion), and the same point in world
 * coordinates. */
void gls_camera_unproject(const gls_camera *c, double u, double v, double Zc, double Pc[3]);
void gls_camera_to_world(const gls_camera *c, const double Pc[3], double P[3]);

/* World point -> camera frame, and -> pixel (u, v); returns Zc. */
void gls_camera_to_cam(const gls_camera *c, const double P[3], double Pc[3]);
double gls_camera_project(const gls_camera *c, const double P[3], double *u, double *v);

/* Camera centre in world coordinates: C = -R^T T. */
void gls_camera_centre(const gls_camera *c, double C[3]);

#endif
