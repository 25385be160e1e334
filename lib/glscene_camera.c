/* Cameras of the library (include/glscene.h): from a camera file through
 * the runtime's parser, or from numbers checked with the same limits and
 * the same rotation check, so that numbers a camera file would refuse are
 * refused here too, with the file's words. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "distort.h"
#include "glscene_internal.h"
#include "numfmt.h"
#include "rotation.h"

int gls_api_fail(glscene_error *e, const char *fmt, ...)
{
    if (e) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->message, sizeof e->message, fmt, ap);
        va_end(ap);
    }
    return -1;
}

int glscene_camera_from_file(const char *path, glscene_camera *out, glscene_error *e)
{
    gls_camera c;
    char err[sizeof e->message];
    /* notes (a re-orthonormalised R) are dropped: the library never prints */
    if (!path || gls_camera_load(path, GLS_POSE_WORLD, NULL, &c, err, sizeof err))
        return gls_api_fail(e, "%s", path ? err : "glscene_camera_from_file: no path");
    /* the API's camera is a pinhole: a lens would be dropped silently */
    if (gls_distort_on(&c))
        return gls_api_fail(e, "%s: lens distortion ('distortion' or 'fisheye') is not in the library's camera yet; "
                               "glsplay renders it", path);
    /* checked already; the file's values pass the same checks */
    return glscene_camera_set(out, c.width, c.height, c.fx, c.fy, c.cx, c.cy, c.skew, c.R, c.T, c.near, c.far, e);
}

/* The checks of runtime/camera/camera.c's gls_camera_from_keys, on numbers. */
static int check(glscene_camera *c, glscene_error *e)
{
    const double *num[] = {&c->fx, &c->fy, &c->cx, &c->cy, &c->skew, &c->near, &c->far};
    static const char *const name[] = {"fx", "fy", "cx", "cy", "skew", "near", "far"};
    for (size_t i = 0; i < sizeof num / sizeof num[0]; i++)
        if (!isfinite(*num[i]))
            return gls_api_fail(e, "camera: %s is not a finite number", name[i]);
    for (int i = 0; i < 12; i++)
        if (!isfinite(i < 9 ? c->R[i] : c->T[i - 9]))
            return gls_api_fail(e, "camera: %s[%d] is not a finite number", i < 9 ? "R" : "T", i < 9 ? i : i - 9);
    if (c->width < 1 || c->width > GLS_CAMERA_MAX_DIM || c->height < 1 || c->height > GLS_CAMERA_MAX_DIM)
        return gls_api_fail(e, "camera: %s %u must be a whole number in 1..%u",
                            c->width < 1 || c->width > GLS_CAMERA_MAX_DIM ? "width" : "height",
                            c->width < 1 || c->width > GLS_CAMERA_MAX_DIM ? c->width : c->height,
                            GLS_CAMERA_MAX_DIM);
    if (!(c->fx > 0))
        return gls_api_fail(e, "camera: fx must be > 0 (focal length in pixels)");
    if (!(c->fy > 0))
        return gls_api_fail(e, "camera: fy must be > 0 (focal length in pixels)");
    if (!(c->near > 0))
        return gls_api_fail(e, "camera: near must be > 0");
    char a[40], b[40];
    gls_fmt_double(a, sizeof a, c->far);
    gls_fmt_double(b, sizeof b, c->near);
    if (!(c->far > c->near))
        return gls_api_fail(e, "camera: far (%s) must be greater than near (%s)", a, b);
    double nmin, nmax;
    if (gls_camera_depth_range(c->near, c->far, &nmin, &nmax)) {
        int small = c->near < nmin;
        char lim[40];
        gls_fmt_double(lim, sizeof lim, small ? nmin : nmax);
        return gls_api_fail(e,
                            "camera: near %s is too %s for far %s: the float depth buffer would lose precision; "
                            "near must be %s %s (spec/camera.md, Depth range)",
                            b, small ? "small" : "large", a, small ? "at least" : "at most", lim);
    }
    char why[300];
    if (gls_rotation_check(c->R, why, sizeof why) < 0)
        return gls_api_fail(e, "camera: R: %s", why);
    return 0;
}

int glscene_camera_set(glscene_camera *out, uint32_t width, uint32_t height, double fx, double fy, double cx,
                       double cy, double skew, const double R[9], const double T[3], double near, double far,
                       glscene_error *e)
{
    static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, O[3] = {0, 0, 0};
    glscene_camera c = {width, height, fx, fy, cx, cy, skew, {0}, {0}, near, far};
    memcpy(c.R, R ? R : I, sizeof c.R);
    memcpy(c.T, T ? T : O, sizeof c.T);
    if (check(&c, e))
        return -1;
    *out = c;
    return 0;
}

int gls_api_camera(const glscene_camera *c, gls_camera *out, glscene_error *e)
{
    glscene_camera k = *c;
    if (check(&k, e))
        return -1;
    memset(out, 0, sizeof *out);
    out->width = k.width, out->height = k.height;
    out->fx = k.fx, out->fy = k.fy, out->cx = k.cx, out->cy = k.cy, out->skew = k.skew;
    memcpy(out->R, k.R, sizeof out->R);
    memcpy(out->T, k.T, sizeof out->T);
    out->near = k.near, out->far = k.far;
    out->pose = GLS_POSE_WORLD;
    return 0;
}
