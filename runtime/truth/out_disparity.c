/* Rectified-pair check and disparity (out_disparity.h). */
#include <math.h>
#include <stdio.h>
#include "numfmt.h"
#include "out_disparity.h"

#define RECT_TOL 1e-9

static int differs(double a, double b, double scale)
{
    double m = fmax(fmax(fabs(a), fabs(b)), scale);
    return fabs(a - b) > RECT_TOL * m;
}

int gls_rectified_pair(const gls_camera *l, const gls_camera *r, const char *lname, const char *rname, double *B,
                       char *err, size_t errlen)
{
    if (l->width != r->width || l->height != r->height) {
        snprintf(err, errlen, "cameras %s and %s have different sizes (%ux%u and %ux%u)", lname, rname, l->width,
                 l->height, r->width, r->height);
        return -1;
    }
    static const char *const iname[] = {"fx", "fy", "cx", "cy", "skew"};
    const double li[5] = {l->fx, l->fy, l->cx, l->cy, l->skew}, ri[5] = {r->fx, r->fy, r->cx, r->cy, r->skew};
    for (int i = 0; i < 5; i++)
        if (differs(li[i], ri[i], fabs(l->fx))) {
            char a[32], b[32];
            gls_fmt_double(a, sizeof a, li[i]);
            gls_fmt_double(b, sizeof b, ri[i]);
            snprintf(err, errlen, "cameras %s and %s have different %s (%s and %s)", lname, rname, iname[i], a, b);
            return -1;
        }
    for (int i = 0; i < 9; i++)
        if (fabs(l->R[i] - r->R[i]) > RECT_TOL) {
            snprintf(err, errlen, "cameras %s and %s have different rotations", lname, rname);
            return -1;
        }
    /* r's centre C_r = -R_r^T T_r, in l's frame: R_l C_r + T_l */
    double C[3], p[3];
    gls_camera_centre(r, C);
    gls_camera_to_cam(l, C, p);
    if (fabs(p[1]) > RECT_TOL * fabs(p[0]) || fabs(p[2]) > RECT_TOL * fabs(p[0])) {
        char x[3][32];
        for (int i = 0; i < 3; i++)
            gls_fmt_double(x[i], sizeof x[i], p[i]);
        snprintf(err, errlen, "the baseline is not along x: camera %s's centre is at (%s, %s, %s) in camera %s's frame",
                 rname, x[0], x[1], x[2], lname);
        return -1;
    }
    if (!(p[0] > 0)) {
        char x[32];
        gls_fmt_double(x, sizeof x, p[0]);
        snprintf(err, errlen,
                 "camera %s is not to the right of camera %s (its centre is at x = %s in %s's frame); give the left "
                 "camera first",
                 rname, lname, x, lname);
        return -1;
    }
    *B = p[0];
    return 0;
}

void gls_disparity_from_z(const float *z, size_t n, double fxB, float *d)
{
    for (size_t i = 0; i < n; i++)
        d[i] = isfinite(z[i]) ? (float)(fxB / z[i]) : INFINITY;
}
