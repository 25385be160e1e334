/* The exact area of {a x + b y + c > 0} in the pixel square
 * [-0.5, 0.5]^2, in closed form: the square's area on one side of a line
 * is a box spline, a sum of quadratic ramps at the four corner offsets.
 * The independent reference of exact coverage, shared by its unit test
 * (tests/unit/test_exact.c) and make bench-aa's sweep (bench/aa_exact.c). */
#ifndef GLS_HALFPLANE_AREA_H
#define GLS_HALFPLANE_AREA_H
#include <math.h>

static inline double gls_ramp2(double t) { return t > 0 ? t * t : 0; }

static inline double gls_halfplane_area(double a, double b, double c)
{
    double aa = fabs(a), ab = fabs(b);
    /* nearly axis-aligned: the line crosses two opposite sides (or a
     * corner region 1e-6 wide), where the area is linear in c exactly */
    if (ab < 1e-6 * aa)
        return fmin(1, fmax(0, c / aa + 0.5));
    if (aa < 1e-6 * ab)
        return fmin(1, fmax(0, c / ab + 0.5));
    double p = 0.5 * (aa + ab), m = 0.5 * (aa - ab);
    if (c >= p || c <= -p) /* the line misses the square */
        return c > 0;
    return (gls_ramp2(c + p) - gls_ramp2(c + m) - gls_ramp2(c - m) + gls_ramp2(c - p)) / (2 * aa * ab);
}
#endif
