/* Motion along the road (roads/road_motion.c): speed profiles, distance
 * per frame by an independent arc length, the rig's pose against the demo
 * camera, quaternions, KITTI and TUM outputs, the body's pitch. */
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "road.h"
#include "road_load.h"
#include "trajectory.h"


static void test_profiles(void)
{
    road_profile p = {0};
    double xs[2] = {0, 100}, vs[2] = {10, 20};
    p.n = 2;
    p.x = xs;
    p.v = vs;
    /* by distance, v linear in x: the segment takes ln(2) / 0.1 s */
    double T = log(2) / 0.1, x, v, a;
    road_profile_motion(&p, T, &x, &v, &a);
    CHECK_NEAR(x, 100, 1e-9);
    CHECK_NEAR(v, 20, 1e-12);
    road_profile_motion(&p, T + 2, &x, &v, &a);
    CHECK_NEAR(x, 140, 1e-9);
    CHECK(a == 0);
    /* dx/dt = v and dv/dt = a, and v = 10 + 0.1 x, inside the segment */
    for (double t = 0.1; t < T; t += 0.37) {
        double x1, v1, a1, x2, v2, a2, h = 1e-5;
        road_profile_motion(&p, t, &x, &v, &a);
        road_profile_motion(&p, t - h, &x1, &v1, &a1);
        road_profile_motion(&p, t + h, &x2, &v2, &a2);
        CHECK_NEAR((x2 - x1) / (2 * h), v, 1e-6);
        CHECK_NEAR((v2 - v1) / (2 * h), a, 1e-6);
        CHECK_NEAR(v, 10 + 0.1 * x, 1e-12);
    }
    /* by time: 0 -> 20 m/s in 10 s, then constant */
    double ts[3] = {0, 10, 20}, vt[3] = {0, 20, 20};
    road_profile q = {1, 3, 3, ts, vt, 0};
    road_profile_motion(&q, 10, &x, &v, &a);
    CHECK_NEAR(x, 100, 1e-12);
    road_profile_motion(&q, 5, &x, &v, &a);
    CHECK_NEAR(x, 25, 1e-12);
    CHECK_NEAR(a, 2, 1e-15);
    road_profile_motion(&q, 25, &x, &v, &a);
    CHECK_NEAR(x, 400, 1e-12);
}

typedef struct {
    long n, cap;
    road_pose *p;
} poses;

static int collect(void *ctx, const road_pose *p)
{
    poses *ps = ctx;
    if (ps->n == ps->cap) {
        ps->cap = ps->cap ? 2 * ps->cap : 1024;
        ps->p = realloc(ps->p, sizeof(road_pose) * ps->cap);
    }
    ps->p[ps->n++] = *p;
    return 0;
}

/* Arc length between u0 and u1 by composite Simpson on |C'| (64
   intervals): independent of the library's Gauss-Legendre table and its
   Newton inversion. */
static double simpson_arc(const nurbs *c, double u0, double u1)
{
    int N = 64;
    double h = (u1 - u0) / N, s = 0;
    for (int i = 0; i <= N; i++) {
        rv3 D[2];
        nurbs_derivs(c, u0 + i * h, 1, D);
        s += (i == 0 || i == N ? 1 : i % 2 ? 4 : 2) * rv_len(D[1]);
    }
    return s * h / 3;
}

static const char *LONG_ROAD = "degree 3\n"
                               "point 0 0 0\npoint 0 0 1500\npoint -1200 10 3000\npoint -400 25 4500\n"
                               "point 900 40 6000\npoint 300 30 7500 5\npoint -500 20 8600 0.2\npoint 0 10 9800\n"
                               "verge 0\nfps 30\n";

/* Constant speed on a 10 km road: the distance between two frames is
   speed / fps to 1e-6 relative (measured: ~1e-12), at every frame. */
static void test_constant_speed_10km(void)
{
    char t[2048];
    snprintf(t, sizeof t, "%sspeed_at distance 0 27.5\n", LONG_ROAD);
    road_desc d;
    road_geo g;
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    poses ps = {0};
    char err[1024];
    long n = road_run_trajectory(&g, collect, &ps, err, sizeof err);
    CHECK_MSG(n == ps.n && n == (long)floor(g.c.length / 27.5 * 30) + 1, "%ld frames", n);
    double worst = 0;
    long worst_k = 0;
    double u_prev = nurbs_u_of_s(&g.c, ps.p[0].s);
    for (long k = 1; k < ps.n; k++) {
        double u = nurbs_u_of_s(&g.c, ps.p[k].s);
        double rel = fabs(simpson_arc(&g.c, u_prev, u) / (27.5 / 30) - 1);
        if (rel > worst)
            worst = rel, worst_k = k;
        u_prev = u;
    }
    CHECK_MSG(worst < 1e-6, "worst relative error %g at frame %ld", worst, worst_k);
    CHECK_MSG(worst < 1e-9, "worst relative error %g at frame %ld (expected ~1e-12)", worst, worst_k);
    free(ps.p);
    road_geo_free(&g);
    road_desc_free(&d);
}

/* Speed given by time: 5 -> 25 m/s over 20 s, then constant; the distance
   between frames is the integral of the profile over the frame interval. */
static void test_speed_by_time(void)
{
    char t[2048];
    snprintf(t, sizeof t, "%sspeed_at time 0 5\nspeed_at time 20 25\nduration 60\n", LONG_ROAD);
    road_desc d;
    road_geo g;
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    poses ps = {0};
    char err[1024];
    long n = road_run_trajectory(&g, collect, &ps, err, sizeof err);
    CHECK(n == 1800);
    double worst = 0;
    for (long k = 1; k < ps.n; k++) {
        double t0 = (k - 1) / 30.0, t1 = k / 30.0;
        /* x(t) = 5 t + t^2 / 2 up to 20 s, then 300 + 25 (t - 20) */
        double x0 = t0 <= 20 ? 5 * t0 + 0.5 * t0 * t0 : 300 + 25 * (t0 - 20);
        double x1 = t1 <= 20 ? 5 * t1 + 0.5 * t1 * t1 : 300 + 25 * (t1 - 20);
        double arc = simpson_arc(&g.c, nurbs_u_of_s(&g.c, ps.p[k - 1].s), nurbs_u_of_s(&g.c, ps.p[k].s));
        worst = fmax(worst, fabs(arc / (x1 - x0) - 1));
    }
    CHECK_MSG(worst < 1e-6, "worst relative error %g", worst);
    free(ps.p);
    road_geo_free(&g);
    road_desc_free(&d);
}

/* Straight road along +z from the origin, rig 1.5 m high pitched down 6
   degrees; composed with a camera 0.15 m to the rig's left this is exactly
   examples/demo/left.cam. */
static void test_rig_matches_demo_camera(void)
{
    const char *t = "degree 1\npoint 0 0 0\npoint 0 0 100\nrig_height 1.5\nrig_pitch 6\nframes 1\n"
                    "speed_at distance 0 10\n";
    road_desc d;
    road_geo g;
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    poses ps = {0};
    char err[1024];
    CHECK(road_run_trajectory(&g, collect, &ps, err, sizeof err) == 1);
    double Rc[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, Tc[3] = {0.15, 0, 0}, R[9], T[3];
    gls_traj_compose(Rc, Tc, ps.p[0].R, ps.p[0].T, R, T);
    double Rd[9] = {-1, 0, 0, 0, -0.99452189536827329, -0.10452846326765348, 0, -0.10452846326765348,
                    0.99452189536827329};
    double Td[3] = {0.14999999999999999, 1.4917828430524098, 0.15679269490148023};
    for (int i = 0; i < 9; i++)
        CHECK_NEAR(R[i], Rd[i], 1e-15);
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(T[i], Td[i], 1e-15);
    free(ps.p);
    road_geo_free(&g);
    road_desc_free(&d);
}

static void quat_to_R(const double q[4], double R[9])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double M[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                   2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                   2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    memcpy(R, M, sizeof M);
}

static void test_quaternion(void)
{
    unsigned seed = 12345;
    double worst = 0;
    for (int k = 0; k < 2000; k++) {
        double axis[3], ang;
        for (int i = 0; i < 3; i++) {
            seed = seed * 1103515245u + 12345u;
            axis[i] = (seed >> 8) / 8388608.0 - 1;
        }
        seed = seed * 1103515245u + 12345u;
        ang = (seed >> 8) / 16777216.0 * 2 * M_PI;
        if (k < 6) { /* the hard cases: 180 degrees about the axes and diagonals */
            axis[0] = k % 3 == 0 || k >= 3;
            axis[1] = k % 3 == 1 || k >= 4;
            axis[2] = k % 3 == 2 || k == 5;
            ang = M_PI;
        }
        double nrm = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        double x = axis[0] / nrm, y = axis[1] / nrm, z = axis[2] / nrm, c = cos(ang), s = sin(ang), C = 1 - c;
        /* Rodrigues' formula */
        double R[9] = {c + x * x * C, x * y * C - z * s, x * z * C + y * s,
                       y * x * C + z * s, c + y * y * C, y * z * C - x * s,
                       z * x * C - y * s, z * y * C + x * s, c + z * z * C};
        double q[4], R2[9];
        road_quat_from_R(R, q);
        CHECK(q[3] >= 0);
        CHECK_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1, 1e-15);
        quat_to_R(q, R2);
        for (int i = 0; i < 9; i++)
            worst = fmax(worst, fabs(R[i] - R2[i]));
        /* the vector part is the axis times sin(angle / 2) (up to the sign
           that makes w >= 0) */
        double sg = cos(ang / 2) < 0 ? -1 : 1;
        if (fabs(cos(ang / 2)) > 1e-9) {
            CHECK_NEAR(q[0], sg * x * sin(ang / 2), 1e-14);
            CHECK_NEAR(q[3], fabs(cos(ang / 2)), 1e-14);
        }
    }
    CHECK_MSG(worst < 1e-14, "R -> q -> R error %g", worst);
}

/* KITTI lines are [R|t] of frame i in frame 0's camera; TUM lines the
   camera-to-world position and quaternion. */
static void test_kitti_tum(void)
{
    char t[2048];
    snprintf(t, sizeof t, "%sspeed_at distance 0 20\nframes 300\nrig_pitch 5\nrig_yaw 3\nrig_roll -2\n", LONG_ROAD);
    road_desc d;
    road_geo g;
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    road_buf tr, ki, tu, ve;
    char err[1024];
    CHECK(road_emit_motion(&g, &tr, &ki, &tu, &ve, NULL, err, sizeof err) == 0);
    poses ps = {0};
    road_run_trajectory(&g, collect, &ps, err, sizeof err);
    const char *pk = ki.text, *pt = tu.text;
    while (*pt == '#')
        pt = strchr(pt, '\n') + 1;
    double worst_k = 0, worst_t = 0, q_prev[4] = {0, 0, 0, 0};
    for (long k = 0; k < ps.n; k++) {
        double m[12], u[8];
        char *e;
        for (int i = 0; i < 12; i++)
            m[i] = strtod(pk, &e), pk = e;
        for (int i = 0; i < 8; i++)
            u[i] = strtod(pt, &e), pt = e;
        const double *R0 = ps.p[0].R, *T0 = ps.p[0].T, *R = ps.p[k].R, *T = ps.p[k].T;
        /* a point in camera k's frame -> world -> camera 0's frame equals
           the KITTI matrix applied to it */
        double pc[3] = {1.5, -0.7, 12.0}, pw[3], p0[3];
        for (int i = 0; i < 3; i++) /* world = R^T (pc - T) */
            pw[i] = R[i] * (pc[0] - T[0]) + R[3 + i] * (pc[1] - T[1]) + R[6 + i] * (pc[2] - T[2]);
        for (int i = 0; i < 3; i++)
            p0[i] = R0[3 * i] * pw[0] + R0[3 * i + 1] * pw[1] + R0[3 * i + 2] * pw[2] + T0[i];
        for (int i = 0; i < 3; i++)
            worst_k = fmax(worst_k, fabs(m[4 * i] * pc[0] + m[4 * i + 1] * pc[1] + m[4 * i + 2] * pc[2] + m[4 * i + 3] - p0[i]));
        if (k == 0) /* relative to the first frame: exactly the identity */
            CHECK(strncmp(ki.text, "1 0 0 0 0 1 0 0 0 0 1 0\n", 24) == 0);
        /* continuous quaternions: never the far sign of the same rotation */
        if (k > 0)
            CHECK(u[4] * q_prev[0] + u[5] * q_prev[1] + u[6] * q_prev[2] + u[7] * q_prev[3] >= 0);
        memcpy(q_prev, u + 4, sizeof q_prev);
        /* TUM: timestamp, then q maps camera to world: pw = q pc q* + t */
        CHECK_NEAR(u[0], k / 30.0, 1e-12);
        double Rq[9];
        quat_to_R(u + 4, Rq);
        for (int i = 0; i < 3; i++)
            worst_t = fmax(worst_t, fabs(Rq[3 * i] * pc[0] + Rq[3 * i + 1] * pc[1] + Rq[3 * i + 2] * pc[2] + u[1 + i] - pw[i]));
    }
    CHECK_MSG(worst_k < 1e-9, "KITTI error %g m", worst_k);
    CHECK_MSG(worst_t < 1e-9, "TUM error %g m", worst_t);
    free(ps.p);
    free(tr.text);
    free(ki.text);
    free(tu.text);
    free(ve.text);
    road_geo_free(&g);
    road_desc_free(&d);
}

/* Pitch from acceleration: accelerating at 2 m/s^2 with accel_pitch 1
   deg per m/s^2 settles at 2 degrees nose up; after the acceleration ends
   the pitch rings down at the damped frequency.  No inputs: exactly 0. */
static void test_body_pitch(void)
{
    char t[2048];
    road_desc d;
    road_geo g;
    char err[1024];
    snprintf(t, sizeof t, "%sspeed_at time 0 5\nspeed_at time 10 25\nduration 16\n"
                          "accel_pitch 1\nbody_freq 1.5\nbody_damping 0.2\n", LONG_ROAD);
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    poses ps = {0};
    road_run_trajectory(&g, collect, &ps, err, sizeof err);
    CHECK_NEAR(ps.p[0].pitch, -2 * M_PI / 180, 1e-12); /* starts at equilibrium */
    CHECK_NEAR(ps.p[270].pitch, -2 * M_PI / 180, 1e-6); /* t = 9 s: settled */
    /* after t = 10 s: overshoot past 0 (nose down) within half a period,
       then decaying */
    double mx = 0;
    for (long k = 301; k < 330; k++)
        mx = fmax(mx, ps.p[k].pitch);
    double zeta = 0.2, overshoot = exp(-zeta * M_PI / sqrt(1 - zeta * zeta)) * 2 * M_PI / 180;
    CHECK_MSG(fabs(mx - overshoot) < 0.05 * overshoot, "overshoot %g, expected %g", mx, overshoot);
    CHECK(fabs(ps.p[479].pitch) < 0.2 * overshoot);
    free(ps.p);
    road_geo_free(&g);
    road_desc_free(&d);
    /* roughness: deterministic per seed */
    double rms[3];
    for (int run = 0; run < 3; run++) {
        snprintf(t, sizeof t, "%sspeed_at distance 0 20\nduration 10\nroughness 0.005\nseed %d\n", LONG_ROAD,
                 run == 2 ? 8 : 7);
        if (load(t, &d, &g))
            return check_failed_++, (void)0;
        poses q = {0};
        road_run_trajectory(&g, collect, &q, err, sizeof err);
        double s = 0;
        for (long k = 0; k < q.n; k++)
            s += q.p[k].pitch * q.p[k].pitch;
        rms[run] = sqrt(s / q.n);
        free(q.p);
        road_geo_free(&g);
        road_desc_free(&d);
    }
    CHECK(rms[0] > 1e-5 && rms[0] < 0.05);
    CHECK(rms[0] == rms[1]);
    CHECK(rms[0] != rms[2]);
}

static void test_end_of_road(void)
{
    const char *t = "degree 1\npoint 0 0 0\npoint 0 0 100\nframes 300\nspeed_at distance 0 10\n";
    road_desc d;
    road_geo g;
    char err[1024] = "";
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    CHECK(road_run_trajectory(&g, NULL, NULL, err, sizeof err) == -1);
    CHECK_MSG(strstr(err, "test.road:4:1: error: the vehicle passes the end of the road") != NULL, "%s", err);
    road_geo_free(&g);
    road_desc_free(&d);
    /* without frames: up to the end, 100 m at 10 m/s and 25 fps */
    t = "degree 1\npoint 0 0 0\npoint 0 0 100\nspeed_at distance 0 10\n";
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    CHECK(road_run_trajectory(&g, NULL, NULL, err, sizeof err) == 251);
    road_geo_free(&g);
    road_desc_free(&d);
}

/* Arc length from the start of the curve to u, span by span, by
   composite Simpson on 2048 intervals a span (|C'| is smooth within a
   span, not across a knot): independent of the library's table. */
static double arc_to(const nurbs *c, double u)
{
    double s = 0;
    for (int j = c->p; j <= c->n && c->U[j] < u; j++) {
        double a = c->U[j], b = fmin(c->U[j + 1], u), h = (b - a) / 2048, sum = 0;
        for (int i = 0; b > a && i <= 2048; i++) {
            rv3 D[2];
            nurbs_derivs(c, a + i * h, 1, D);
            sum += (i == 0 || i == 2048 ? 1 : i % 2 ? 4 : 2) * rv_len(D[1]);
        }
        s += sum * h / 3;
    }
    return s;
}

/* The parameter at distance s: Newton on arc_to, started from the middle. */
static double u_at(const nurbs *c, double s)
{
    double u = 0.5 * (nurbs_umin(c) + nurbs_umax(c));
    for (int i = 0; i < 60; i++) {
        rv3 D[2];
        nurbs_derivs(c, u, 1, D);
        double du = (arc_to(c, u) - s) / rv_len(D[1]);
        u = fmin(fmax(u - du, nurbs_umin(c)), nurbs_umax(c));
        if (fabs(du) < 1e-15)
            break;
    }
    return u;
}

static const char *TRAFFIC = "degree 3\n"
                             "point 0 0 0\npoint 0 0 60\npoint -10 0 110\npoint -45 0 160\npoint -60 0 220\n"
                             "verge 0\nfps 25\nduration 12\nspeed_at distance 0 10\n"
                             "vehicle car lateral -1.75 start 30\n"
                             "vehicle_speed car distance 0 12\nvehicle_speed car distance 100 20\n"
                             "vehicle van lateral 1.75 start 150 oncoming object road.vehicles.Van\n"
                             "vehicle_speed van time 0 14\n";

/* Other vehicles' motion files (spec/road.md, "Other vehicles"): the row
   of frame k is the pose at the distance the speed profile gives at k /
   fps, found on the curve by an independent arc length, the heading the
   curve's tangent, the origin `lateral` to the left of the centre line;
   beyond an end, on along that end's tangent.  Within 1e-9 m; the same
   bytes every run. */
static void test_vehicle_motion_files(void)
{
    road_desc d;
    road_geo g;
    if (load(TRAFFIC, &d, &g))
        return check_failed_++, (void)0;
    road_buf tr, ki, tu, ve, mo[2], again[2];
    char err[1024];
    CHECK(road_emit_motion(&g, &tr, &ki, &tu, &ve, mo, err, sizeof err) == 0);
    free(tr.text), free(ki.text), free(tu.text), free(ve.text);
    CHECK(road_emit_motion(&g, &tr, &ki, &tu, &ve, again, err, sizeof err) == 0);
    free(tr.text), free(ki.text), free(tu.text), free(ve.text);
    const double L = g.c.length, b = (20.0 - 12.0) / 100, T = log(20.0 / 12.0) / b;
    for (int v = 0; v < 2; v++) {
        CHECK(mo[v].len == again[v].len && memcmp(mo[v].text, again[v].text, mo[v].len) == 0);
        CHECK(strncmp(mo[v].text, "# glsroad motion 1\n", 19) == 0);
        double worst_p = 0, worst_r = 0;
        long rows = 0, off_road = 0;
        for (char *line = mo[v].text; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
            if (*line == '#')
                continue;
            double x[14];
            char *q = line;
            for (int i = 0; i < 14; i++)
                x[i] = strtod(q, &q);
            long k = (long)x[0];
            CHECK(k == rows && x[1] == k / 25.0);
            double t = k / 25.0, dist;
            if (v == 0) /* v linear in distance: x(t) = v0 (e^(b t) - 1) / b, then 20 m/s */
                dist = t < T ? 12 * (exp(b * t) - 1) / b : 100 + 20 * (t - T);
            else
                dist = 14 * t;
            double s = v == 0 ? 30 + dist : 150 - dist, sc = fmin(fmax(s, 0), L);
            off_road += s != sc;
            rv3 D[2];
            nurbs_derivs(&g.c, u_at(&g.c, sc), 1, D);
            rv3 tan = rv_unit(D[1]), up = {0, 1, 0}, left = rv_unit(rv_cross(up, tan));
            rv3 P = rv_madd(rv_madd(D[0], tan, s - sc), left, v == 0 ? -1.75 : 1.75);
            rv3 fwd = v == 0 ? tan : rv_mul(tan, -1), lft = v == 0 ? left : rv_mul(left, -1);
            double want[9] = {lft.x, up.x, fwd.x, lft.y, up.y, fwd.y, lft.z, up.z, fwd.z};
            for (int i = 0; i < 9; i++)
                worst_r = fmax(worst_r, fabs(x[2 + i] - want[i]));
            worst_p = fmax(worst_p, rv_len(rv_sub(rv(x[11], x[12], x[13]), P)));
            rows++;
        }
        CHECK_MSG(rows == 300, "vehicle %d: %ld rows", v, rows);
        CHECK_MSG(off_road > 10 && off_road < rows - 10, "vehicle %d: %ld frames off the road", v, off_road);
        printf("  vehicle %d: %ld frames (%ld off the road), worst position error %.2g m, rotation %.2g\n", v, rows,
               off_road, worst_p, worst_r);
        CHECK_MSG(worst_p < 1e-9, "vehicle %d: position off by %g m", v, worst_p);
        CHECK_MSG(worst_r < 1e-9, "vehicle %d: rotation off by %g", v, worst_r);
        free(mo[v].text), free(again[v].text);
    }
    road_geo_free(&g);
    road_desc_free(&d);
}

int main(void)
{
    RUN(test_profiles);
    RUN(test_constant_speed_10km);
    RUN(test_speed_by_time);
    RUN(test_rig_matches_demo_camera);
    RUN(test_quaternion);
    RUN(test_kitti_tum);
    RUN(test_body_pitch);
    RUN(test_end_of_road);
    RUN(test_vehicle_motion_files);
    CHECK_EXIT();
}
