/* The shared rotation check and re-orthonormalisation (runtime/camera/rotation.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "rotation.h"

/* Rotation by angle a about the unit axis (x, y, z) (Rodrigues). */
static void axis_angle(double x, double y, double z, double a, double R[9])
{
    double n = sqrt(x * x + y * y + z * z), c = cos(a), s = sin(a), t = 1 - c;
    x /= n, y /= n, z /= n;
    double M[9] = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
                   t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
                   t * x * z - s * y, t * y * z + s * x, t * z * z + c};
    memcpy(R, M, sizeof M);
}

static void mul(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

static double max_diff(const double A[9], const double B[9])
{
    double m = 0;
    for (int i = 0; i < 9; i++)
        m = fmax(m, fabs(A[i] - B[i]));
    return m;
}

/* largest |R R^T - I| entry */
static double orth_err(const double R[9])
{
    double m = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m = fmax(m, fabs(R[3 * i] * R[3 * j] + R[3 * i + 1] * R[3 * j + 1] + R[3 * i + 2] * R[3 * j + 2] - (i == j)));
    return m;
}

static double frob(const double A[9], const double B[9])
{
    double s = 0;
    for (int i = 0; i < 9; i++)
        s += (A[i] - B[i]) * (A[i] - B[i]);
    return sqrt(s);
}

/* M = R (I + S) with S symmetric and small is a polar decomposition
   already (I + S is symmetric positive definite), so its orthogonal factor
   is exactly R: the decomposition must return R to rounding. */
static void test_polar_accuracy(void)
{
    srand(11);
    double worst = 0, worst_orth = 0;
    for (int k = 0; k < 1000; k++) {
        double R[9], S[9], IS[9], M[9], Q[9];
        axis_angle(rand() / (double)RAND_MAX - 0.5, rand() / (double)RAND_MAX - 0.5,
                   rand() / (double)RAND_MAX - 0.5 + 1e-3, 6.0 * rand() / RAND_MAX, R);
        for (int i = 0; i < 3; i++)
            for (int j = i; j < 3; j++)
                S[3 * i + j] = S[3 * j + i] = 6e-5 * (rand() / (double)RAND_MAX - 0.5);
        for (int i = 0; i < 9; i++)
            IS[i] = S[i] + (i % 4 == 0);
        mul(R, IS, M);
        CHECK(gls_rotation_polar(M, Q) == 0);
        worst = fmax(worst, max_diff(Q, R));
        worst_orth = fmax(worst_orth, orth_err(Q));
    }
    CHECK_MSG(worst < 1e-15, "polar factor differs from R by %g", worst);
    CHECK_MSG(worst_orth < 1e-15, "polar factor orthonormal only to %g", worst_orth);
    printf("  polar decomposition: worst |Q - R| %.2g, worst |Q Q^T - I| %.2g over 1000 matrices\n", worst, worst_orth);
}

/* The orthogonal factor is the nearest rotation: no rotation near it is
   closer to M (Frobenius norm). */
static void test_polar_is_nearest(void)
{
    double R[9], M[9], Q[9];
    axis_angle(1, 2, 3, 0.7, R);
    for (int i = 0; i < 9; i++)
        M[i] = R[i] + 4e-5 * sin(7.0 * i + 1); /* a general perturbation */
    CHECK(gls_rotation_polar(M, Q) == 0);
    double dq = frob(M, Q);
    int closer = 0;
    for (int a = 0; a < 3; a++)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double E[9], Q2[9];
            axis_angle(a == 0, a == 1, a == 2, sgn * 1e-6, E);
            mul(E, Q, Q2);
            closer += frob(M, Q2) < dq;
        }
    CHECK_MSG(closer == 0, "%d nearby rotations are closer to M than its polar factor", closer);
}

static void test_check_tiers(void)
{
    char why[300];
    double R[9], A[9];
    /* exact: unchanged, bit for bit */
    axis_angle(0.3, -1, 0.2, 2.1, R);
    memcpy(A, R, sizeof A);
    CHECK(gls_rotation_check(A, why, sizeof why) == 0 && memcmp(A, R, sizeof A) == 0);
    /* printed with 5 decimals: accepted, re-orthonormalised, near R */
    for (int i = 0; i < 9; i++)
        A[i] = round(R[i] * 1e5) / 1e5;
    CHECK(orth_err(A) > 1e-6);
    CHECK_MSG(gls_rotation_check(A, why, sizeof why) == 1, "%s", why);
    CHECK_MSG(orth_err(A) < 1e-15, "%g", orth_err(A));
    CHECK_MSG(max_diff(A, R) < 1e-5, "%g", max_diff(A, R));
    CHECK_MSG(strncmp(why, "R is orthonormal only within ", 29) == 0 && strstr(why, "replaced by the nearest rotation"), "%s", why);
    /* scaled by 1 + 4e-5: the nearest rotation is R itself */
    for (int i = 0; i < 9; i++)
        A[i] = R[i] * (1 + 4e-5);
    CHECK(gls_rotation_check(A, why, sizeof why) == 1);
    CHECK_MSG(max_diff(A, R) < 1e-15, "%g", max_diff(A, R));
    /* printed with 3 decimals: beyond the tolerance */
    for (int i = 0; i < 9; i++)
        A[i] = round(R[i] * 1e3) / 1e3;
    CHECK(gls_rotation_check(A, why, sizeof why) == -1);
    CHECK_MSG(strncmp(why, "R is not orthonormal: (R R^T)[", 30) == 0 && strstr(why, "within 1e-4"), "%s", why);
    /* a reflection */
    double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, -1};
    CHECK(gls_rotation_check(F, why, sizeof why) == -1);
    CHECK_STR(why, "R has determinant -1; a rotation needs +1 (a reflection swaps handedness)");
}

int main(void)
{
    RUN(test_polar_accuracy);
    RUN(test_polar_is_nearest);
    RUN(test_check_tiers);
    CHECK_EXIT();
}
