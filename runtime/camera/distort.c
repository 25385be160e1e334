/* OpenCV's lens distortion models and their inverse (distort.h).  The
 * formulas are OpenCV's documented ones (calib3d "Detailed Description";
 * cv::fisheye "Definitions"), written out here and checked against
 * cv2.projectPoints and cv2.fisheye.projectPoints by
 * tests/py/check_distortion.py. */
#include <math.h>
#include <stdio.h>
#include "distort.h"

const char *gls_distort_model_name(const gls_distortion *d)
{
    switch (d->model) {
    case GLS_LENS_BROWN:
        return d->n == 8 ? "rational Brown-Conrady" : "Brown-Conrady";
    case GLS_LENS_FISHEYE:
        return "fisheye";
    default:
        return "none";
    }
}

/* Fisheye: theta_d = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 +
 * k4 theta^8) and its derivative in theta. */
static double fisheye_theta_d(const double *k, double t, double *dt)
{
    double t2 = t * t, t4 = t2 * t2, t6 = t4 * t2, t8 = t4 * t4;
    if (dt)
        *dt = 1 + 3 * k[0] * t2 + 5 * k[1] * t4 + 7 * k[2] * t6 + 9 * k[3] * t8;
    return t * (1 + k[0] * t2 + k[1] * t4 + k[2] * t6 + k[3] * t8);
}

/* Brown: the radial factor R(r2) = (1 + k1 r2 + k2 r2^2 + k3 r2^3) /
 * (1 + k4 r2 + k5 r2^2 + k6 r2^3) and dR/dr2; *den gets the denominator. */
static double brown_radial(const double *k, double r2, double *dr, double *den)
{
    double r4 = r2 * r2, r6 = r4 * r2;
    double a = 1 + k[0] * r2 + k[1] * r4 + k[4] * r6;
    double b = 1 + k[5] * r2 + k[6] * r4 + k[7] * r6;
    double da = k[0] + 2 * k[1] * r2 + 3 * k[4] * r4;
    double db = k[5] + 2 * k[6] * r2 + 3 * k[7] * r4;
    if (dr)
        *dr = (da * b - a * db) / (b * b);
    if (den)
        *den = b;
    return a / b;
}

void gls_distort_normalized(const gls_distortion *d, double x, double y, double *xd, double *yd, double j[4])
{
    const double *k = d->k;
    double r2 = x * x + y * y;
    if (d->model == GLS_LENS_BROWN) {
        double dR, R = brown_radial(k, r2, &dR, NULL);
        double p1 = k[2], p2 = k[3];
        *xd = x * R + 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
        *yd = y * R + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y;
        if (j) {
            j[0] = R + 2 * x * x * dR + 2 * p1 * y + 6 * p2 * x;
            j[1] = 2 * x * y * dR + 2 * p1 * x + 2 * p2 * y;
            j[2] = 2 * x * y * dR + 2 * p1 * x + 2 * p2 * y;
            j[3] = R + 2 * y * y * dR + 6 * p1 * y + 2 * p2 * x;
        }
    } else if (d->model == GLS_LENS_FISHEYE) {
        /* cv::fisheye: theta = atan(r), scale theta_d / r (1 at r = 0) */
        double r = sqrt(r2);
        if (r > 1e-8) {
            double th = atan(r), dtd, td = fisheye_theta_d(k, th, &dtd);
            double s = td / r;
            *xd = x * s;
            *yd = y * s;
            if (j) {
                /* s'(r) = (theta_d'(theta) / (1 + r^2) - s) / r */
                double ds = (dtd / (1 + r2) - s) / r;
                j[0] = s + x * x / r * ds;
                j[1] = x * y / r * ds;
                j[2] = j[1];
                j[3] = s + y * y / r * ds;
            }
        } else {
            *xd = x, *yd = y;
            if (j)
                j[0] = 1, j[1] = 0, j[2] = 0, j[3] = 1;
        }
    } else {
        *xd = x, *yd = y;
        if (j)
            j[0] = 1, j[1] = 0, j[2] = 0, j[3] = 1;
    }
}

void gls_distort_project(const gls_camera *c, const double Pc[3], double *u, double *v)
{
    double x = Pc[0] / Pc[2], y = Pc[1] / Pc[2];
    if (!gls_distort_on(c)) {
        *u = (c->fx * Pc[0] + c->skew * Pc[1]) / Pc[2] + c->cx;
        *v = c->fy * Pc[1] / Pc[2] + c->cy;
        return;
    }
    double xd, yd;
    gls_distort_normalized(&c->dist, x, y, &xd, &yd, NULL);
    *u = c->fx * xd + c->cx;
    *v = c->fy * yd + c->cy;
}

static double max_r2(const gls_distortion *d)
{
    /* scan the profile's derivative outward (fine steps near the axis,
       where lenses fold, geometric ones beyond), then bisect the first
       sign change */
    double prev = 0, t = 0;
    for (int i = 0;; i++) {
        t = i < 20000 ? i * 1e-4 : 2.0 * pow(1.0005, i - 20000);
        if (d->model == GLS_LENS_FISHEYE && t >= M_PI / 2)
            return INFINITY;
        if (d->model == GLS_LENS_BROWN && t > 1e4)
            return INFINITY;
        double g;
        if (d->model == GLS_LENS_FISHEYE) {
            fisheye_theta_d(d->k, t, &g);
        } else {
            double dR, den, R = brown_radial(d->k, t * t, &dR, &den);
            g = den <= 0 ? -1 : R + 2 * t * t * dR; /* d(r R(r^2))/dr */
        }
        if (!(g > 0))
            break;
        prev = t;
    }
    double lo = prev, hi = t;
    for (int i = 0; i < 60; i++) {
        double mid = 0.5 * (lo + hi), g;
        if (d->model == GLS_LENS_FISHEYE) {
            fisheye_theta_d(d->k, mid, &g);
        } else {
            double dR, den, R = brown_radial(d->k, mid * mid, &dR, &den);
            g = den <= 0 ? -1 : R + 2 * mid * mid * dR;
        }
        if (g > 0)
            lo = mid;
        else
            hi = mid;
    }
    if (d->model == GLS_LENS_FISHEYE)
        return tan(lo) * tan(lo);
    return lo * lo;
}

void gls_distort_setup(gls_distortion *d)
{
    d->max_r2 = d->model == GLS_LENS_NONE ? INFINITY : max_r2(d);
}

int gls_distort_undistort(const gls_distortion *d, double xd, double yd, double x0, double y0, double *x, double *y)
{
    return gls_distort_undistort_tol(d, xd, yd, x0, y0, GLS_DISTORT_TOL, x, y);
}

int gls_distort_undistort_tol(const gls_distortion *d, double xd, double yd, double x0, double y0, double tol,
                              double *x, double *y)
{
    if (d->model == GLS_LENS_NONE) {
        *x = xd, *y = yd;
        return 0;
    }
    if (d->model == GLS_LENS_FISHEYE) {
        /* one dimension: theta from theta_d along the point's direction */
        double tdt = sqrt(xd * xd + yd * yd);
        if (tdt < 1e-300) {
            *x = xd, *y = yd;
            return 0;
        }
        double th = atan(sqrt(x0 * x0 + y0 * y0));
        int it;
        for (it = 0; it <= GLS_DISTORT_MAX_ITER; it++) {
            double dtd, td = fisheye_theta_d(d->k, th, &dtd);
            if (fabs(td - tdt) <= tol)
                break;
            if (!(dtd > 0) || it == GLS_DISTORT_MAX_ITER)
                return -1;
            double step = (td - tdt) / dtd, lim = atan(sqrt(d->max_r2));
            for (int h = 0; h < 60 && !(th - step >= 0 && th - step < lim); h++)
                step *= 0.5;
            th -= step;
        }
        double s = tan(th) / tdt;
        *x = xd * s, *y = yd * s;
        /* beyond the fold the same theta_d has a second solution */
        return *x * *x + *y * *y < d->max_r2 ? it : -1;
    }
    double px = x0, py = y0;
    int it;
    for (it = 0; it <= GLS_DISTORT_MAX_ITER; it++) {
        double fx, fy, j[4];
        gls_distort_normalized(d, px, py, &fx, &fy, j);
        double ex = fx - xd, ey = fy - yd;
        if (sqrt(ex * ex + ey * ey) <= tol * (1 + sqrt(xd * xd + yd * yd)))
            break;
        double det = j[0] * j[3] - j[1] * j[2];
        if (!(det > 0) || it == GLS_DISTORT_MAX_ITER)
            return -1;
        double sx = (j[3] * ex - j[1] * ey) / det, sy = (j[0] * ey - j[2] * ex) / det;
        /* a step past the fold is halved back: the solution wanted is
           the one on the one-to-one side */
        for (int h = 0; h < 60 && !((px - sx) * (px - sx) + (py - sy) * (py - sy) < d->max_r2); h++)
            sx *= 0.5, sy *= 0.5;
        px -= sx;
        py -= sy;
        if (!isfinite(px) || !isfinite(py))
            return -1;
    }
    if (!(px * px + py * py < d->max_r2))
        return -1; /* a second solution, past the fold */
    *x = px, *y = py;
    return it;
}

int gls_distort_pixel_ray(const gls_camera *c, double u, double v, double *x, double *y)
{
    double yd = (v - c->cy) / c->fy;
    double xd = ((u - c->cx) - c->skew * yd) / c->fx;
    if (!gls_distort_on(c)) {
        *x = xd, *y = yd;
        return 0;
    }
    return gls_distort_undistort(&c->dist, xd, yd, xd, yd, x, y);
}

int gls_distort_check(const gls_camera *c, double margin, char *why, size_t n)
{
    if (!gls_distort_on(c))
        return 0;
    if (c->skew != 0) {
        snprintf(why, n, "lens distortion needs skew 0 (cv::projectPoints ignores K[0][1]; cv::fisheye's alpha "
                         "is not modelled)");
        return -1;
    }
    double max_r2 = c->dist.max_r2;
    double W = c->width, H = c->height;
    double u0 = -0.5 - margin, u1 = W - 0.5 + margin, v0 = -0.5 - margin, v1 = H - 0.5 + margin;
    /* the border, every half pixel, and a grid inside: each must have a
       ray inside the fold, where the map is one-to-one */
    uint32_t nu = (uint32_t)(2 * (u1 - u0)) + 1, nv = (uint32_t)(2 * (v1 - v0)) + 1;
    for (uint32_t side = 0; side < 4; side++) {
        uint32_t cnt = side < 2 ? nu : nv;
        for (uint32_t i = 0; i <= cnt; i++) {
            double t = (double)i / cnt, u, v;
            if (side < 2)
                u = u0 + t * (u1 - u0), v = side ? v1 : v0;
            else
                u = side == 3 ? u1 : u0, v = v0 + t * (v1 - v0);
            double x, y;
            if (gls_distort_pixel_ray(c, u, v, &x, &y) < 0) {
                char fold[64] = "";
                if (isfinite(max_r2))
                    snprintf(fold, sizeof fold, " (it folds back at undistorted radius %.4g)", sqrt(max_r2));
                snprintf(why, n, "the %s model has no one-to-one undistorted ray at pixel (%.1f, %.1f)%s: the "
                                 "coefficients describe no lens over the whole image",
                         gls_distort_model_name(&c->dist), u, v, fold);
                return -1;
            }
        }
    }
    return 0;
}
