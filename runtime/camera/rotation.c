/* Rotation checks and re-orthonormalisation (rotation.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rotation.h"
#include "vec.h"

#define STR_(x) #x
#define STR(x) STR_(x) /* "1e-4": the limits as they are written */

int gls_rotation_polar(const double R[9], double Q[9])
{
    memcpy(Q, R, 9 * sizeof *Q);
    for (int it = 0; it < 32; it++) {
        double d = rm_det(Q);
        if (!(fabs(d) > 1e-12))
            return -1;
        /* Q^-T = cofactor(Q) / det Q */
        double C[9] = {Q[4] * Q[8] - Q[5] * Q[7], Q[5] * Q[6] - Q[3] * Q[8], Q[3] * Q[7] - Q[4] * Q[6],
                       Q[2] * Q[7] - Q[1] * Q[8], Q[0] * Q[8] - Q[2] * Q[6], Q[1] * Q[6] - Q[0] * Q[7],
                       Q[1] * Q[5] - Q[2] * Q[4], Q[2] * Q[3] - Q[0] * Q[5], Q[0] * Q[4] - Q[1] * Q[3]};
        double change = 0;
        for (int i = 0; i < 9; i++) {
            double q = 0.5 * (Q[i] + C[i] / d);
            change = fmax(change, fabs(q - Q[i]));
            Q[i] = q;
        }
        if (change <= 1e-15)
            return 0;
    }
    return 0;
}

int gls_rotation_check(double R[9], char *why, size_t whylen)
{
    double Rt[9], RRt[9];
    rm_transpose(R, Rt);
    rm_mul(R, Rt, RRt);
    double worst = 0; /* largest |R R^T - I| entry */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = RRt[3 * i + j];
            double e = fabs(s - (i == j));
            if (!(e <= GLS_ROT_TOL)) {
                snprintf(why, whylen, "R is not orthonormal: (R R^T)[%d][%d] = %.9g, must be %d within %s", i, j, s,
                         i == j, STR(GLS_ROT_TOL));
                return -1;
            }
            worst = fmax(worst, e);
        }
    double det = rm_det(R);
    if (!(det > 0)) {
        snprintf(why, whylen, "R has determinant %.9g; a rotation needs +1 (a reflection swaps handedness)", det);
        return -1;
    }
    if (worst <= GLS_ROT_EXACT && fabs(det - 1) <= GLS_ROT_EXACT)
        return 0;
    double Q[9];
    if (gls_rotation_polar(R, Q)) { /* cannot happen with det near 1; refuse rather than guess */
        snprintf(why, whylen, "R is singular");
        return -1;
    }
    double moved = 0;
    for (int i = 0; i < 9; i++)
        moved = fmax(moved, fabs(Q[i] - R[i]));
    memcpy(R, Q, sizeof Q);
    snprintf(why, whylen,
             "R is orthonormal only within %.2g (used as given within %s): replaced by the nearest rotation, "
             "which moves no entry by more than %.2g",
             fmax(worst, fabs(det - 1)), STR(GLS_ROT_EXACT), moved);
    return 1;
}

void gls_rotation_rodrigues(const double r[3], double R[9])
{
    double t = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (t == 0) {
        static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        memcpy(R, I, sizeof I);
        return;
    }
    double k[3] = {r[0] / t, r[1] / t, r[2] / t}, c = cos(t), s = sin(t), c1 = 1 - c;
    /* [k]x = [[0, -kz, ky], [kz, 0, -kx], [-ky, kx, 0]] */
    const double kx[9] = {0, -k[2], k[1], k[2], 0, -k[0], -k[1], k[0], 0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[3 * i + j] = (i == j ? c : 0) + c1 * k[i] * k[j] + s * kx[3 * i + j];
}

int gls_rotation_quat(double x, double y, double z, double w, double R[9])
{
    double n = sqrt(x * x + y * y + z * z + w * w);
    if (!(fabs(n - 1) <= 1e-4))
        return -1;
    x /= n, y /= n, z /= n, w /= n;
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - z * w), R[2] = 2 * (x * z + y * w);
    R[3] = 2 * (x * y + z * w), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - x * w);
    R[6] = 2 * (x * z - y * w), R[7] = 2 * (y * z + x * w), R[8] = 1 - 2 * (x * x + y * y);
    return 0;
}
