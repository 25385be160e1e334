/* Clamped NURBS curves in 3-D and their arc length.
 *
 * Evaluation follows Piegl & Tiller, The NURBS Book (2nd ed.):
 * A2.1 FindSpan, A2.2 BasisFuns, A2.3 DersBasisFuns, A3.2 CurveDerivs on
 * the homogeneous control points, A4.2 RatCurveDerivs.  The arc length is
 * integrated per knot span by adaptive Gauss-Legendre quadrature into a
 * table; s -> u is solved by safeguarded Newton iteration inside one table
 * interval, so positions at a given distance are exact to ~1e-12 relative.
 */
#ifndef GLS_NURBS_H
#define GLS_NURBS_H
#include <stddef.h>
#include "vec.h"

#define NURBS_MAX_DEGREE 9
#define NURBS_MAX_DERIV 3

typedef struct {
    int p;          /* degree, 1..NURBS_MAX_DEGREE                        */
    int n;          /* index of the last control point (n + 1 points)     */
    double *Pw;     /* homogeneous control points: 4 * (n + 1): wx wy wz w */
    double *U;      /* knots, m + 1 = n + p + 2 of them                    */
    /* arc-length table: ntab + 1 breakpoints (u_i, s_i), s_0 = 0 */
    int ntab;
    double *tu, *ts;
    double length;  /* total arc length                                   */
} nurbs;

/* Check a curve definition: degree, point count, weights > 0 and finite,
 * knots non-decreasing, clamped (first and last p + 1 equal), interior
 * multiplicity <= p, and the right number of knots.  Returns NULL if it is
 * valid, else a static message. */
const char *nurbs_check(int p, int npts, const double *w, int nknots, const double *U);

/* Clamped uniform knots on [0, 1] for npts points of degree p: p + 1
 * zeros, npts - p - 1 evenly spaced interior knots, p + 1 ones.  U must
 * have room for npts + p + 1 values. */
void nurbs_uniform_knots(int p, int npts, double *U);

/* Build a curve (copies the data; pts is x y z per point) and its
 * arc-length table.  Returns 0, or -1 (message in err) on invalid input
 * or a curve with a zero-length tangent somewhere (a cusp). */
int nurbs_init(nurbs *c, int p, int npts, const double *pts, const double *w, const double *U, char *err,
               size_t errlen);
void nurbs_free(nurbs *c);

/* A2.1: the knot span index i with U[i] <= u < U[i+1]; u = U[m] gives n. */
int nurbs_find_span(int n, int p, double u, const double *U);
/* A2.2: the p + 1 non-vanishing basis functions at u in span i. */
void nurbs_basis(int i, double u, int p, const double *U, double *N);
/* A2.3: ders[k * (p + 1) + j] = k-th derivative of N_{i-p+j,p}, k <= nd. */
void nurbs_ders_basis(int i, double u, int p, int nd, const double *U, double *ders);

/* A4.2: CK[k] = k-th derivative of C at u, k = 0..d (d <= NURBS_MAX_DERIV).
 * u is clamped to the knot range. */
void nurbs_derivs(const nurbs *c, double u, int d, rv3 *CK);
rv3 nurbs_point(const nurbs *c, double u);

double nurbs_umin(const nurbs *c);
double nurbs_umax(const nurbs *c);

/* Arc length from the curve's start to u. */
double nurbs_s_of_u(const nurbs *c, double u);
/* The parameter at arc length s (clamped to [0, length]). */
double nurbs_u_of_s(const nurbs *c, double s);
/* Arc length between u0 and u1 by the same quadrature (u0 <= u1, any). */
double nurbs_arc(const nurbs *c, double u0, double u1);
#endif
