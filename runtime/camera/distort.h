/* OpenCV's lens distortion models (spec/camera.md "Lens distortion"), in
 * double precision: the forward map of cv::projectPoints (Brown-Conrady,
 * rational) and of cv::fisheye::projectPoints, and its inverse by Newton's
 * method with a convergence check.  The image through such a lens is
 * drawn by distort_render.h. */
#ifndef GLS_DISTORT_H
#define GLS_DISTORT_H

#include <stddef.h>
#include "camera.h"

/* Newton's method stops when the distorted point it reaches is within
 * this distance (normalised image units, Euclidean) of the target: about
 * 1e-11 px at a focal length of 1000 px. */
#define GLS_DISTORT_TOL 1e-14
#define GLS_DISTORT_MAX_ITER 50

/* Does camera c have lens distortion (model other than none)? */
static inline int gls_distort_on(const gls_camera *c) { return c->dist.model != GLS_LENS_NONE; }

/* "Brown-Conrady", "rational Brown-Conrady", "fisheye", "none". */
const char *gls_distort_model_name(const gls_distortion *d);

/* Normalised undistorted (x, y) = (Xc/Zc, Yc/Zc) -> normalised distorted
 * (xd, yd), as cv::projectPoints (Brown) or cv::fisheye::projectPoints
 * compute it; j (may be NULL) gets the Jacobian d(xd, yd)/d(x, y),
 * row-major 2x2. */
void gls_distort_normalized(const gls_distortion *d, double x, double y, double *xd, double *yd, double j[4]);

/* Camera-frame point -> pixel: (u, v) = (fx xd + cx, fy yd + cy) with
 * (xd, yd) distorted from (Xc/Zc, Yc/Zc); the pinhole projection (skew
 * included) when the camera has no distortion.  Zc must be > 0. */
void gls_distort_project(const gls_camera *c, const double Pc[3], double *u, double *v);

/* The inverse: normalised distorted (xd, yd) -> undistorted (x, y), by
 * Newton's method from (x0, y0) (the caller's guess; (xd, yd) will do).
 * Returns the iterations taken (0 if the guess already fits), or -1 when
 * the residual did not fall below GLS_DISTORT_TOL in GLS_DISTORT_MAX_ITER
 * steps, the Jacobian vanished, or the point found lies beyond the
 * model's fold (max_r2 below). */
int gls_distort_undistort(const gls_distortion *d, double xd, double yd, double x0, double y0, double *x, double *y);
/* The same to a residual of tol (normalised units) instead of
 * GLS_DISTORT_TOL: the image's anti-aliasing samples (distort_render.c)
 * need their positions to 1e-7 px, not 1e-11. */
int gls_distort_undistort_tol(const gls_distortion *d, double xd, double yd, double x0, double y0, double tol,
                              double *x, double *y);

/* Pixel (u, v) of camera c -> the normalised undistorted ray (x, y, 1);
 * -1 as gls_distort_undistort. */
int gls_distort_pixel_ray(const gls_camera *c, double u, double v, double *x, double *y);

/* Set d->max_r2, where the model stops being one-to-one: the radial
 * profile (Brown: r (1 + k1 r^2 + ...) / (1 + k4 r^2 + ...); fisheye:
 * theta_d(theta) for theta < pi/2) first stops increasing at undistorted
 * r^2 = max_r2 (fisheye: r = tan theta); +inf if it never does.  Beyond
 * it OpenCV's formula folds back and describes no lens.  Call after
 * filling model, n and k (the camera parsers do). */
void gls_distort_setup(gls_distortion *d);

/* Check that camera c's distortion is usable over its image grown by
 * margin pixels on each side: skew 0, every border point has an
 * undistorted ray inside the one-to-one part of the model (fisheye: less
 * than 90 degrees off axis).  0, or -1 with a message (no location) in
 * why. */
int gls_distort_check(const gls_camera *c, double margin, char *why, size_t n);

#endif
