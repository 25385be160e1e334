/* Sub-frame poses (runtime/camera/subframe.c) against closed forms: the slerp of
 * two rotations about one axis is the rotation by the interpolated angle;
 * a trajectory's centre moves on the straight line between its rows; the
 * rows themselves come back bit for bit; nothing beyond the ends. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "rotation.h"
#include "subframe.h"

static void axis_angle(const double k[3], double a, double R[9])
{
    double r[3] = {k[0] * a, k[1] * a, k[2] * a};
    gls_rotation_rodrigues(r, R);
}

static double max_diff(const double *A, const double *B, int n)
{
    double m = 0;
    for (int i = 0; i < n; i++)
        m = fmax(m, fabs(A[i] - B[i]));
    return m;
}

/* slerp about one axis: the angle interpolates linearly, every axis and
 * angle pair, the shorter arc when the quaternions' signs differ */
static void test_slerp_axis(void)
{
    const double axes[3][3] = {{0, 0, 1}, {0.6, 0, 0.8}, {1 / sqrt(3.0), -1 / sqrt(3.0), 1 / sqrt(3.0)}};
    const double pairs[3][2] = {{0.1, 0.9}, {-2.5, 2.9}, {3.0, -3.0}};
    for (int a = 0; a < 3; a++)
        for (int p = 0; p < 3; p++) {
            double a0 = pairs[p][0], a1 = pairs[p][1];
            /* the shorter way round */
            double d = a1 - a0;
            if (d > M_PI)
                d -= 2 * M_PI;
            if (d < -M_PI)
                d += 2 * M_PI;
            double R0[9], R1[9], T[3] = {0, 0, 0}, R[9], Tr[3], W[9];
            axis_angle(axes[a], a0, R0);
            axis_angle(axes[a], a1, R1);
            for (int k = 0; k <= 8; k++) {
                double u = k / 8.0;
                gls_pose_interp(R0, T, R1, T, u, 0, R, Tr);
                axis_angle(axes[a], a0 + u * d, W);
                CHECK_MSG(max_diff(R, W, 9) < 1e-12, "axis %d pair %d u %g: %g", a, p, u, max_diff(R, W, 9));
            }
        }
}

/* a motion row's T lerps; a trajectory's centre -R^T T lerps (not T) */
static void test_translation(void)
{
    const double z[3] = {0, 0, 1};
    double R0[9], R1[9], T0[3] = {1, 2, 3}, T1[3] = {5, -2, 7}, R[9], T[3];
    axis_angle(z, 0, R0);
    axis_angle(z, M_PI / 2, R1);
    gls_pose_interp(R0, T0, R1, T1, 0.25, 0, R, T);
    double want[3] = {2, 1, 4};
    CHECK(max_diff(T, want, 3) < 1e-15);
    gls_pose_interp(R0, T0, R1, T1, 0.25, 1, R, T);
    /* centres C = -R^T T */
    double C0[3] = {-1, -2, -3}, C1[3], C[3], Cw[3];
    C1[0] = -(R1[0] * T1[0] + R1[3] * T1[1] + R1[6] * T1[2]);
    C1[1] = -(R1[1] * T1[0] + R1[4] * T1[1] + R1[7] * T1[2]);
    C1[2] = -(R1[2] * T1[0] + R1[5] * T1[1] + R1[8] * T1[2]);
    for (int i = 0; i < 3; i++) {
        C[i] = -(R[i] * T[0] + R[3 + i] * T[1] + R[6 + i] * T[2]);
        Cw[i] = C0[i] + 0.25 * (C1[i] - C0[i]);
    }
    CHECK_MSG(max_diff(C, Cw, 3) < 1e-13, "centre off the line by %g", max_diff(C, Cw, 3));
}

/* rows bit for bit at their frames; between rows by frame number (frames
 * 0, 2, 3: x = 1 is halfway between the first two); none beyond */
static void test_motion_at(void)
{
    gls_motion m;
    memset(&m, 0, sizeof m);
    uint64_t frames[3] = {0, 2, 3};
    double RT[3][12];
    const double ax[3] = {0.36, 0.48, 0.8};
    for (int i = 0; i < 3; i++) {
        axis_angle(ax, 0.3 * i + 0.1, RT[i]);
        RT[i][9] = 0.1 * i + 1.0 / 3, RT[i][10] = -(double)i / 7, RT[i][11] = 2;
    }
    m.n = 3, m.frame = frames, m.RT = RT;
    double R[9], T[3];
    for (int i = 0; i < 3; i++) {
        CHECK(gls_motion_pose_at(&m, (double)frames[i], 0, R, T) == 0);
        CHECK(memcmp(R, RT[i], sizeof R) == 0 && memcmp(T, RT[i] + 9, sizeof T) == 0);
    }
    double W[9];
    CHECK(gls_motion_pose_at(&m, 1.0, 0, R, T) == 0);
    axis_angle(ax, 0.25, W);
    CHECK(max_diff(R, W, 9) < 1e-12);
    CHECK_NEAR(T[0], 1.0 / 3 + 0.05, 1e-15);
    CHECK(gls_motion_pose_at(&m, 2.5, 0, R, T) == 0);
    axis_angle(ax, 0.55, W);
    CHECK(max_diff(R, W, 9) < 1e-12);
    CHECK(gls_motion_pose_at(&m, -0.001, 0, R, T) == -1);
    CHECK(gls_motion_pose_at(&m, 3.0001, 0, R, T) == -1);
    CHECK(gls_motion_pose_at(&m, NAN, 0, R, T) == -1);
}

int main(void)
{
    RUN(test_slerp_axis);
    RUN(test_translation);
    RUN(test_motion_at);
    CHECK_EXIT();
}
