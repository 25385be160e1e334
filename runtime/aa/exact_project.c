/* Exact coverage: a world triangle to image triangles under a pinhole
 * (exact.h, gls_exact_project).  The part behind the near plane is cut
 * away in camera space, before the division by Zc, where the cut is a
 * plane and 1/Zc of what is left stays affine in the image; projecting
 * first would send a vertex behind the camera through infinity.  All in
 * double, the camera centre subtracted first. */
#include <string.h>
#include "exact_int.h"

static void to_camera(const gls_exact_pinhole *c, const double p[3], double q[3])
{
    double d[3] = {p[0] - c->C[0], p[1] - c->C[1], p[2] - c->C[2]};
    for (int r = 0; r < 3; r++)
        q[r] = c->R[3 * r] * d[0] + c->R[3 * r + 1] * d[1] + c->R[3 * r + 2] * d[2];
}

static void project(const gls_exact_pinhole *c, const double q[3], double *u, double *v, double *iz)
{
    *iz = 1 / q[2];
    *u = (c->fx * q[0] + c->skew * q[1]) / q[2] + c->cx;
    *v = c->fy * q[1] / q[2] + c->cy;
}

/* Sutherland-Hodgman of polygon in[0..n) against side * (Zc - z) >= 0 */
static int clip_z(const double in[][3], int n, double z, double side, double out[][3])
{
    int m = 0;
    for (int k = 0; k < n; k++) {
        const double *a = in[k], *b = in[(k + 1) % n];
        int ina = side * (a[2] - z) >= 0, inb = side * (b[2] - z) >= 0;
        if (ina)
            memcpy(out[m++], a, 3 * sizeof *a);
        if (ina != inb) {
            double s = (z - a[2]) / (b[2] - a[2]);
            for (int r = 0; r < 3; r++)
                out[m][r] = a[r] + s * (b[r] - a[r]);
            out[m++][2] = z;
        }
    }
    return m;
}

int gls_exact_project(const gls_exact_pinhole *cam, const double p[3][3], const gls_exact_tri *proto,
                      gls_exact_tri out[3])
{
    double q[3][3], poly[4][3], poly2[5][3];
    for (int k = 0; k < 3; k++)
        to_camera(cam, p[k], q[k]);
    int n = clip_z((const double(*)[3])q, 3, cam->znear, 1, poly);
    const double(*v)[3] = (const double(*)[3])poly;
    if (n >= 3 && cam->zfar > cam->znear) {
        n = clip_z(v, n, cam->zfar, -1, poly2);
        v = (const double(*)[3])poly2;
    }
    if (n < 3)
        return 0;
    for (int t = 0; t < n - 2; t++) {
        out[t] = *proto;
        int idx[3] = {0, t + 1, t + 2};
        for (int k = 0; k < 3; k++)
            project(cam, v[idx[k]], &out[t].x[k], &out[t].y[k], &out[t].iz[k]);
    }
    return n - 2;
}
