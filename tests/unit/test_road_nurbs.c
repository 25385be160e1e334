/* NURBS evaluation and arc length (roads/nurbs.c): against exact curves
 * (circles are rational quadratics), an independent Cox-de Boor
 * evaluation, finite differences, and independent quadrature. */
#include <stdlib.h>
#include "check.h"
#include "nurbs.h"

/* Independent evaluation: Cox-de Boor recursion over all basis functions,
   the rational point as sum N w P / sum N w.  Slow and simple. */
static double coxdeboor(int i, int p, double u, const double *U, int m, double umax)
{
    if (p == 0) {
        if (U[i] <= u && u < U[i + 1])
            return 1;
        /* the closed end: the last non-empty span owns u = umax */
        if (u == umax && U[i] < U[i + 1] && U[i + 1] == umax)
            return 1;
        return 0;
    }
    double a = 0, b = 0;
    if (U[i + p] > U[i])
        a = (u - U[i]) / (U[i + p] - U[i]) * coxdeboor(i, p - 1, u, U, m, umax);
    if (U[i + p + 1] > U[i + 1])
        b = (U[i + p + 1] - u) / (U[i + p + 1] - U[i + 1]) * coxdeboor(i + 1, p - 1, u, U, m, umax);
    return a + b;
}

static rv3 slow_point(int p, int npts, const double *P, const double *w, const double *U, double u)
{
    int m = npts + p;
    double X = 0, Y = 0, Z = 0, W = 0;
    for (int i = 0; i < npts; i++) {
        double N = coxdeboor(i, p, u, U, m, U[m]) * w[i];
        X += N * P[3 * i];
        Y += N * P[3 * i + 1];
        Z += N * P[3 * i + 2];
        W += N;
    }
    return rv(X / W, Y / W, Z / W);
}

static double dist(rv3 a, rv3 b) { return rv_len(rv_sub(a, b)); }

static void test_find_span(void)
{
    /* repeated interior knot 2 (multiplicity 2), degree 2, 7 points */
    double U[] = {0, 0, 0, 1, 2, 2, 3, 4, 4, 4};
    int n = 6, p = 2;
    CHECK(nurbs_find_span(n, p, 0, U) == 2);
    CHECK(nurbs_find_span(n, p, 0.5, U) == 2);
    CHECK(nurbs_find_span(n, p, 1, U) == 3);
    CHECK(nurbs_find_span(n, p, 1.999, U) == 3);
    CHECK(nurbs_find_span(n, p, 2, U) == 5); /* U[5] = 2 <= u < U[6] = 3 */
    CHECK(nurbs_find_span(n, p, 3.5, U) == 6);
    CHECK(nurbs_find_span(n, p, 4, U) == 6); /* the end belongs to the last span */
    /* every span found is non-empty and holds u */
    for (double u = 0; u < 4; u += 0.01) {
        int i = nurbs_find_span(n, p, u, U);
        CHECK(U[i] <= u && u < U[i + 1]);
    }
}

static void test_basis(void)
{
    double U[] = {0, 0, 0, 0, 0.3, 0.3, 0.5, 0.9, 1, 1, 1, 1};
    int p = 3, n = 7;
    double worst_sum = 0, worst_fd = 0;
    for (int k = 0; k <= 1000; k++) {
        double u = k / 1000.0;
        int i = nurbs_find_span(n, p, u, U);
        double N[4], D[4 * 4];
        nurbs_basis(i, u, p, U, N);
        nurbs_ders_basis(i, u, p, 3, U, D);
        double s = 0, ds = 0;
        for (int j = 0; j <= p; j++) {
            CHECK(N[j] >= -1e-15);
            CHECK_NEAR(N[j], D[j], 1e-14);
            /* against the recursion */
            CHECK_NEAR(N[j], coxdeboor(i - p + j, p, u, U, n + p + 1, 1), 1e-13);
            s += N[j];
            ds += D[4 + j];
        }
        worst_sum = fmax(worst_sum, fabs(s - 1));
        CHECK_NEAR(ds, 0, 1e-10); /* derivatives of a partition of unity sum to 0 */
        /* first derivative by central difference inside the span */
        double h = 1e-6;
        if (u - h >= U[i] && u + h < U[i + 1]) {
            double Np[4], Nm[4];
            nurbs_basis(i, u + h, p, U, Np);
            nurbs_basis(i, u - h, p, U, Nm);
            for (int j = 0; j <= p; j++)
                worst_fd = fmax(worst_fd, fabs((Np[j] - Nm[j]) / (2 * h) - D[4 + j]) / (1 + fabs(D[4 + j])));
        }
    }
    CHECK_NEAR(worst_sum, 0, 1e-14);
    CHECK_MSG(worst_fd < 1e-6, "basis derivative vs finite difference: %g", worst_fd);
}

/* A full circle of radius r from 9 points, degree 2, double interior knots
   (The NURBS Book, Ex. 7.2): exact, with repeated interior knots. */
static void circle(double r, double cx, double cz, double *P, double *w, double *U)
{
    static const double px[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, pz[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    for (int i = 0; i < 9; i++) {
        P[3 * i] = cx + r * px[i];
        P[3 * i + 1] = 0;
        P[3 * i + 2] = cz + r * pz[i];
        w[i] = i % 2 ? sqrt(0.5) : 1;
    }
    double K[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    memcpy(U, K, sizeof K);
}

static void test_circle(void)
{
    double P[27], w[9], U[12];
    const double r = 250, cx = 5000, cz = -7000;
    circle(r, cx, cz, P, w, U);
    nurbs c;
    char err[200];
    CHECK(nurbs_init(&c, 2, 9, P, w, U, err, sizeof err) == 0);
    double worst = 0, worst_t = 0, worst_k = 0;
    for (int k = 0; k <= 4000; k++) {
        double u = k / 4000.0;
        rv3 D[3];
        nurbs_derivs(&c, u, 2, D);
        rv3 rel = rv_sub(D[0], rv(cx, 0, cz));
        worst = fmax(worst, fabs(rv_len(rel) - r));
        worst_t = fmax(worst_t, fabs(rv_dot(rel, D[1])) / rv_len(D[1]) / r); /* tangent _|_ radius */
        /* curvature |C' x C''| / |C'|^3 = 1/r */
        double kap = rv_len(rv_cross(D[1], D[2])) / pow(rv_len(D[1]), 3);
        worst_k = fmax(worst_k, fabs(kap * r - 1));
    }
    CHECK_MSG(worst < 1e-9, "radius error %g", worst);
    CHECK_MSG(worst_t < 1e-12, "tangent error %g", worst_t);
    CHECK_MSG(worst_k < 1e-9, "curvature error %g", worst_k);
    CHECK_NEAR(c.length / (2 * M_PI * r), 1, 1e-13);
    /* quarter arcs: each double knot ends one */
    CHECK_NEAR(nurbs_s_of_u(&c, 0.25) / (0.5 * M_PI * r), 1, 1e-13);
    CHECK_NEAR(nurbs_s_of_u(&c, 0.75) / (1.5 * M_PI * r), 1, 1e-13);
    /* ends: C(0) = P0, C(1) = P8 exactly, and the end tangent */
    rv3 D[2];
    nurbs_derivs(&c, 1, 1, D);
    CHECK(D[0].x == P[24] && D[0].z == P[26]);
    CHECK(D[1].x == 0 && D[1].z > 0);
    /* s <-> u round trip, and the distance is the arc angle * r */
    for (int k = 0; k <= 100; k++) {
        double s = c.length * k / 100;
        double u = nurbs_u_of_s(&c, s);
        CHECK_NEAR(nurbs_s_of_u(&c, u), s, 1e-9);
        rv3 p = nurbs_point(&c, u);
        double ang = atan2(p.z - cz, p.x - cx);
        if (ang < -1e-9)
            ang += 2 * M_PI;
        if (k == 100)
            ang = 2 * M_PI;
        CHECK_NEAR(ang * r, s, 1e-7);
    }
    nurbs_free(&c);
}

/* Extreme weights: A4.2 against the independent evaluation and finite
   differences, on a curve with a triple interior knot (degree 3). */
static void test_weights(void)
{
    double P[7 * 3] = {0, 0, 0, 10, 5, 20, 30, -3, 25, 40, 0, 60, 70, 8, 70, 90, 0, 100, 100, 2, 130};
    double U[11] = {0, 0, 0, 0, 0.4, 0.4, 0.4, 1, 1, 1, 1};
    double wsets[3][7] = {{1, 1e3, 1e-3, 1e3, 1e-3, 1e3, 1},
                          {1e-3, 1, 1e3, 1, 1e3, 1, 1e-3},
                          {1e3, 1e3, 1e3, 1e3, 1e3, 1e3, 1e3}};
    for (int ws = 0; ws < 3; ws++) {
        nurbs c;
        char err[200];
        CHECK(nurbs_init(&c, 3, 7, P, wsets[ws], U, err, sizeof err) == 0);
        double worst_p = 0, worst_d1 = 0, worst_d2 = 0;
        for (int k = 0; k <= 500; k++) {
            double u = k / 500.0;
            rv3 D[3];
            nurbs_derivs(&c, u, 2, D);
            worst_p = fmax(worst_p, dist(D[0], slow_point(3, 7, P, wsets[ws], U, u)));
            /* one-sided differences that stay within one span */
            double h = 1e-7;
            int i = nurbs_find_span(c.n, c.p, u, c.U);
            double ua = u + h <= c.U[i + 1] ? u : u - h;
            if (u == 1)
                ua = u - h;
            rv3 A[2], Bd[2];
            nurbs_derivs(&c, ua, 1, A);
            nurbs_derivs(&c, ua + h, 1, Bd);
            rv3 fd1 = rv_mul(rv_sub(Bd[0], A[0]), 1 / h), fd2 = rv_mul(rv_sub(Bd[1], A[1]), 1 / h);
            rv3 D1[3];
            nurbs_derivs(&c, ua + 0.5 * h, 2, D1);
            worst_d1 = fmax(worst_d1, dist(fd1, D1[1]) / (1 + rv_len(D1[1])));
            worst_d2 = fmax(worst_d2, dist(fd2, D1[2]) / (1 + rv_len(D1[2])));
        }
        CHECK_MSG(worst_p < 1e-9, "weights set %d: point vs Cox-de Boor %g", ws, worst_p);
        CHECK_MSG(worst_d1 < 1e-5, "weights set %d: C' vs finite difference %g", ws, worst_d1);
        CHECK_MSG(worst_d2 < 1e-4, "weights set %d: C'' vs finite difference %g", ws, worst_d2);
        /* the ends interpolate the end points; the end tangent is
           p / (U[p+1] - U[1]) * w1 / w0 * (P1 - P0) */
        rv3 D[2];
        nurbs_derivs(&c, 0, 1, D);
        CHECK(dist(D[0], rv(0, 0, 0)) < 1e-12);
        rv3 t0 = rv_mul(rv(10, 5, 20), 3 / 0.4 * wsets[ws][1] / wsets[ws][0]);
        CHECK_MSG(dist(D[1], t0) < 1e-9 * rv_len(t0), "end tangent %g %g %g", D[1].x, D[1].y, D[1].z);
        nurbs_derivs(&c, 1, 0, D);
        CHECK(dist(D[0], rv(100, 2, 130)) < 1e-12);
        /* arc length against polylines through the independent points,
           2^17 and 2^18 chords per span, Richardson-extrapolated (the
           polyline's error falls as h^2) */
        double S = 0;
        double spans[3] = {0, 0.4, 1};
        for (int sp = 0; sp < 2; sp++) {
            double L[2];
            for (int lev = 0; lev < 2; lev++) {
                int N = 1 << (17 + lev);
                double a = spans[sp], b = spans[sp + 1], hh = (b - a) / N, acc = 0;
                rv3 prev = slow_point(3, 7, P, wsets[ws], U, a);
                for (int k = 1; k <= N; k++) {
                    rv3 q = slow_point(3, 7, P, wsets[ws], U, a + k * hh);
                    acc += dist(q, prev);
                    prev = q;
                }
                L[lev] = acc;
            }
            S += L[1] + (L[1] - L[0]) / 3;
        }
        CHECK_MSG(fabs(c.length - S) / S < 1e-9, "weights set %d: length %.12g vs polyline %.12g", ws, c.length, S);
        nurbs_free(&c);
    }
}

static void test_check(void)
{
    double w[4] = {1, 1, 1, 1}, wz[4] = {1, 0, 1, 1};
    double ok[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    double unclamped[8] = {0, 0, 0, 0.1, 1, 1, 1, 1};
    double dec[8] = {0, 0, 0, 0, 1, 1, 1, 0.5};
    CHECK(nurbs_check(3, 4, w, 8, ok) == NULL);
    CHECK(nurbs_check(3, 4, wz, 8, ok) != NULL);
    CHECK(nurbs_check(3, 4, w, 7, ok) != NULL);
    CHECK(nurbs_check(3, 4, w, 8, unclamped) != NULL);
    CHECK(nurbs_check(3, 4, w, 8, dec) != NULL);
    CHECK(nurbs_check(3, 3, w, 7, ok) != NULL);
    double w5[5] = {1, 1, 1, 1, 1}, split[] = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
    double w6[6] = {1, 1, 1, 1, 1, 1};
    CHECK(nurbs_check(2, 6, w6, 9, split) != NULL); /* interior multiplicity 3 > p = 2 */
    double dbl[] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    CHECK(nurbs_check(2, 5, w5, 8, dbl) == NULL);
    double U[8];
    nurbs_uniform_knots(3, 4, U);
    CHECK(nurbs_check(3, 4, w, 8, U) == NULL);
    double U7[11];
    nurbs_uniform_knots(3, 7, U7);
    CHECK(U7[4] == 0.25 && U7[5] == 0.5 && U7[6] == 0.75 && U7[7] == 1);
    /* coincident control points: no tangent at all */
    double P[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    nurbs c;
    char err[200];
    CHECK(nurbs_init(&c, 3, 4, P, w, ok, err, sizeof err) == -1);
}

int main(void)
{
    RUN(test_find_span);
    RUN(test_basis);
    RUN(test_circle);
    RUN(test_weights);
    RUN(test_check);
    CHECK_EXIT();
}
