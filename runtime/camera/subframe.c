/* Sub-frame poses (subframe.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "rotation.h"
#include "subframe.h"
#include "trajectory.h"
#include "vec.h"

/* Unit quaternion (x, y, z, w) of a rotation matrix (Shepperd's method:
 * divide by the largest of the four candidates, never by a small one). */
static void quat_of(const double R[9], double q[4])
{
    double tr = R[0] + R[4] + R[8];
    if (tr >= R[0] && tr >= R[4] && tr >= R[8]) {
        double s = 2 * sqrt(1 + tr);
        q[3] = s / 4, q[0] = (R[7] - R[5]) / s, q[1] = (R[2] - R[6]) / s, q[2] = (R[3] - R[1]) / s;
    } else if (R[0] >= R[4] && R[0] >= R[8]) {
        double s = 2 * sqrt(1 + R[0] - R[4] - R[8]);
        q[0] = s / 4, q[3] = (R[7] - R[5]) / s, q[1] = (R[1] + R[3]) / s, q[2] = (R[2] + R[6]) / s;
    } else if (R[4] >= R[8]) {
        double s = 2 * sqrt(1 + R[4] - R[0] - R[8]);
        q[1] = s / 4, q[3] = (R[2] - R[6]) / s, q[0] = (R[1] + R[3]) / s, q[2] = (R[5] + R[7]) / s;
    } else {
        double s = 2 * sqrt(1 + R[8] - R[0] - R[4]);
        q[2] = s / 4, q[3] = (R[3] - R[1]) / s, q[0] = (R[2] + R[6]) / s, q[1] = (R[5] + R[7]) / s;
    }
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int i = 0; i < 4; i++)
        q[i] /= n;
}

static void slerp(const double R0[9], const double R1[9], double u, double R[9])
{
    double a[4], b[4], q[4];
    quat_of(R0, a);
    quat_of(R1, b);
    double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    if (d < 0) { /* q and -q are one rotation: take the shorter arc */
        for (int i = 0; i < 4; i++)
            b[i] = -b[i];
        d = -d;
    }
    double wa, wb;
    if (d > 1 - 1e-12) { /* (nearly) the same rotation: lerp is exact to rounding */
        wa = 1 - u, wb = u;
    } else {
        double th = acos(d), s = sin(th);
        wa = sin((1 - u) * th) / s, wb = sin(u * th) / s;
    }
    for (int i = 0; i < 4; i++)
        q[i] = wa * a[i] + wb * b[i];
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    gls_rotation_quat(q[0] / n, q[1] / n, q[2] / n, q[3] / n, R);
}

void gls_pose_interp(const double R0[9], const double T0[3], const double R1[9], const double T1[3], double u,
                     int centre, double R[9], double T[3])
{
    if (u <= 0 || u >= 1) {
        memcpy(R, u <= 0 ? R0 : R1, 9 * sizeof *R);
        memcpy(T, u <= 0 ? T0 : T1, 3 * sizeof *T);
        return;
    }
    slerp(R0, R1, u, R);
    if (!centre) {
        for (int i = 0; i < 3; i++)
            T[i] = T0[i] + u * (T1[i] - T0[i]);
        return;
    }
    rv3 c0 = rm_apply_t(R0, rv(T0[0], T0[1], T0[2])), c1 = rm_apply_t(R1, rv(T1[0], T1[1], T1[2]));
    rv3 c = rv_add(c0, rv_mul(rv_sub(c1, c0), u)); /* -C, lerped */
    rv3 t = rm_apply(R, c);
    T[0] = t.x, T[1] = t.y, T[2] = t.z;
}

int gls_motion_pose_at(const gls_motion *m, double x, int centre, double R[9], double T[3])
{
    if (!(m->n > 0) || !(x >= (double)m->frame[0]) || !(x <= (double)m->frame[m->n - 1]))
        return -1;
    uint64_t lo = 0, hi = m->n - 1; /* the last row with frame <= x */
    while (lo < hi) {
        uint64_t mid = lo + (hi - lo + 1) / 2;
        if ((double)m->frame[mid] <= x)
            lo = mid;
        else
            hi = mid - 1;
    }
    const double *a = m->RT[lo];
    if ((double)m->frame[lo] == x || lo + 1 >= m->n) {
        memcpy(R, a, 9 * sizeof *R);
        memcpy(T, a + 9, 3 * sizeof *T);
        return 0;
    }
    const double *b = m->RT[lo + 1];
    double u = (x - (double)m->frame[lo]) / (double)(m->frame[lo + 1] - m->frame[lo]);
    gls_pose_interp(a, a + 9, b, b + 9, u, centre, R, T);
    return 0;
}

int gls_traj_read_all(const gls_traj_text *tx, FILE *notes, gls_motion *m, char *err, size_t errlen)
{
    const char *path = tx->path;
    memset(m, 0, sizeof *m);
    gls_traj *t = gls_traj_open_text(tx, notes);
    if (!t) {
        snprintf(err, errlen, "%s: error: out of memory", path);
        return -1;
    }
    size_t cap = 0, fcap = 0;
    gls_traj_pose p;
    int got;
    while ((got = gls_traj_next(t, &p, err, errlen)) == 1) {
        if (gls_grow(&m->RT, &cap, m->n + 1, sizeof *m->RT) || gls_grow(&m->frame, &fcap, m->n + 1, sizeof *m->frame)) {
            snprintf(err, errlen, "%s: error: out of memory", path);
            got = -1;
            break;
        }
        memcpy(m->RT[m->n], p.R, sizeof p.R);
        memcpy(m->RT[m->n] + 9, p.T, sizeof p.T);
        m->frame[m->n++] = p.frame;
    }
    gls_traj_close(t);
    if (got < 0) {
        gls_motion_free(m);
        return -1;
    }
    m->path = strdup(path);
    return 0;
}
