/* The one check of a rotation matrix read from a text file (camera files,
 * trajectories): R must be a proper rotation.  Files print R with a few
 * decimals, so R is accepted within a tolerance and then replaced by the
 * nearest rotation; see spec/camera.md "File format". */
#ifndef GLS_ROTATION_H
#define GLS_ROTATION_H
#include <stddef.h>

/* Within GLS_ROT_EXACT (every entry of R R^T from I, and det R from 1) R is
 * used exactly as given: files written with full precision render as they
 * always did.  Within GLS_ROT_TOL it is re-orthonormalised.  Beyond, it is
 * refused.  Five printed decimals (rounding of 5e-6 per entry) are within
 * GLS_ROT_TOL with room to spare. */
#define GLS_ROT_EXACT 1e-6
#define GLS_ROT_TOL 1e-4

/* Check the row-major R:
 *   0: a rotation within GLS_ROT_EXACT; R unchanged.
 *   1: orthonormal within GLS_ROT_TOL with det > 0: R is replaced by the
 *      nearest rotation (the orthogonal factor of its polar decomposition)
 *      and why says so (one line, for a note).
 *  -1: not a rotation; why says why (for an error). */
int gls_rotation_check(double R[9], char *why, size_t whylen);

/* The orthogonal factor of the polar decomposition R = Q S (S symmetric
 * positive definite): the rotation nearest to R in the Frobenius norm when
 * det R > 0.  Newton's iteration Q <- (Q + Q^-T) / 2, quadratic from
 * matrices near orthonormal.  Returns 0, or -1 if R is singular. */
int gls_rotation_polar(const double R[9], double Q[9]);
/* The rotation of a Rodrigues vector r (OpenCV's cv::Rodrigues, the
 * `rvec` of camera files): angle |r| radians about r / |r|,
 *     R = cos t I + (1 - cos t) k k^T + sin t [k]x,  t = |r|, k = r / t,
 * row-major; I for r = 0. */
void gls_rotation_rodrigues(const double r[3], double R[9]);
/* The rotation of a quaternion (x, y, z, w), w last as TUM writes it:
 * row-major R.  Returns -1 if its length is off 1 by more than 1e-4
 * (more than printed decimals explain), else 0 (normalised first). */
int gls_rotation_quat(double x, double y, double z, double w, double R[9]);
#endif
