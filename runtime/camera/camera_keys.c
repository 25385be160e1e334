/* The checks of a camera's values that both camera file formats share
 * (camera_keys.h: the .cam parser in camera.c, OpenCV YAML in
 * camera_opencv.c): K's fixed entries, the size, the focal lengths, the
 * depth range (spec/camera.md "Depth range"), the declared pose against
 * its use, the rotation and the lens, each message located at the value
 * at fault. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "camera_keys.h"
#include "distort.h"
#include "numfmt.h"
#include "rotation.h"
#include "srcline.h"

typedef gls_camera_src src;
#define FAIL GLS_CAMERA_FAIL

int gls_camera_depth_range(double near, double far, double *near_min, double *near_max)
{
    const double L = GLS_DEPTH_MIN, M = FLT_MAX;
    /* a = n/(f-n) >= L  <=>  n >= L f/(1+L);  b = n f/(f-n) >= L  <=>  n >= L f/(f+L);
       b <= M  <=>  n <= M f/(f+M)  (spec/camera.md "Depth range") */
    *near_min = fmax(L * far / (1 + L), L * far / (far + L));
    *near_max = M * (far / (far + M));
    double a = near / (far - near), b = a * far;
    return a >= L && b >= L && b <= M ? 0 : -1;
}

/* v rounded to 3 significant digits, up (dir > 0) or down: a limit that
 * reads well in a message and is still on the right side of the exact one. */
static void fmt_limit(char *buf, size_t n, double v, int dir)
{
    snprintf(buf, n, "%.3g", v * (dir > 0 ? 1.01 : 0.99));
    if (dir > 0 ? strtod(buf, NULL) < v : strtod(buf, NULL) > v)
        gls_fmt_double(buf, n, v);
}

/* "fx" or, when K gave it, "fx (K[0][0])" */
static const char *label(char *buf, size_t n, const gls_camera_keys *k, const char *const *names, int key, int entry)
{
    if (!k->seen[K_K])
        return names[key];
    snprintf(buf, n, "%s (%s[%d][%d])", names[key], names[K_K], entry / 3, entry % 3);
    return buf;
}

/* The lens: distortion or fisheye, all zero meaning none (the pinhole
 * path, unchanged); checked over the image (distort.h). */
static int lens_from_keys(const gls_camera_keys *keys, const char *const *names, const char *text, size_t len,
                          const char *fname, gls_camera *cam, char *err, size_t errlen)
{
    int k = keys->seen[K_FISHEYE] ? K_FISHEYE : keys->seen[K_DIST] ? K_DIST : -1;
    if (k < 0)
        return 0;
    gls_distortion *d = &cam->dist;
    d->n = k == K_FISHEYE ? 4 : keys->ndist;
    int any = 0;
    for (unsigned i = 0; i < d->n; i++) {
        d->k[i] = keys->val[k][i];
        any |= d->k[i] != 0;
    }
    if (!any) {
        memset(d, 0, sizeof *d);
        return 0;
    }
    d->model = k == K_FISHEYE ? GLS_LENS_FISHEYE : GLS_LENS_BROWN;
    gls_distort_setup(d);
    char why[300];
    if (gls_distort_check(cam, 0, why, sizeof why)) {
        gls_text_error(err, errlen, text, len, fname, keys->eline[k][0], keys->ecol[k][0], "key '%s': %s", names[k],
                       why);
        return -1;
    }
    return 0;
}

/* K = [[fx, skew, cx], [0, fy, cy], [0, 0, 1]]: the intrinsics keys from
 * it, each located at its entry; the fixed entries checked first. */
static int intrinsics_from_K(const src *s, gls_camera_keys *keys, const char *const *names)
{
    double (*val)[9] = keys->val;
    static const int at[3][2] = {{1, 0}, {2, 0}, {2, 1}};
    for (int i = 0; i < 4; i++) {
        int e = i < 3 ? 3 * at[i][0] + at[i][1] : 8;
        double want = i < 3 ? 0 : 1;
        if (val[K_K][e] != want) {
            char num[40];
            gls_fmt_double(num, sizeof num, val[K_K][e]);
            return FAIL(s, keys->eline[K_K][e], keys->ecol[K_K][e],
                        "%s[%d][%d] is %s, must be %g: the camera matrix is [[fx, skew, cx], [0, fy, cy], "
                        "[0, 0, 1]]", names[K_K], e / 3, e % 3, num, want);
        }
    }
    static const int from[5][2] = {{K_FX, 0}, {K_FY, 4}, {K_CX, 2}, {K_CY, 5}, {K_SKEW, 1}};
    for (int i = 0; i < 5; i++) {
        int key = from[i][0], e = from[i][1];
        val[key][0] = val[K_K][e];
        keys->seen[key] = keys->eline[K_K][e];
        keys->vcol[key] = keys->ecol[K_K][e];
    }
    return 0;
}

/* R from a Rodrigues vector, located where the vector is. */
static void rotation_from_rvec(gls_camera_keys *keys)
{
    gls_rotation_rodrigues(keys->val[K_RVEC], keys->val[K_R]);
    keys->seen[K_R] = keys->seen[K_RVEC];
    keys->vcol[K_R] = keys->vcol[K_RVEC];
    keys->eline[K_R][0] = keys->eline[K_RVEC][0];
    keys->ecol[K_R][0] = keys->ecol[K_RVEC][0];
}

/* The image size and the focal lengths. */
static int check_size_focal(const src *s, const gls_camera_keys *keys, const char *const *names)
{
    const double (*val)[9] = (const double (*)[9])keys->val;
    const unsigned *seen = keys->seen, *vcol = keys->vcol;
    char lab[64];
    static const int dims[2] = {K_WIDTH, K_HEIGHT};
    for (int i = 0; i < 2; i++) {
        double v = val[dims[i]][0];
        if (v != floor(v) || v < 1 || v > GLS_CAMERA_MAX_DIM) {
            char num[40];
            gls_fmt_double(num, sizeof num, v);
            return FAIL(s, seen[dims[i]], vcol[dims[i]], "%s %s must be a whole number in 1..%u", names[dims[i]],
                        num, GLS_CAMERA_MAX_DIM);
        }
    }
    if (!(val[K_FX][0] > 0))
        return FAIL(s, seen[K_FX], vcol[K_FX], "%s must be > 0 (focal length in pixels)",
                    label(lab, sizeof lab, keys, names, K_FX, 0));
    if (!(val[K_FY][0] > 0))
        return FAIL(s, seen[K_FY], vcol[K_FY], "%s must be > 0 (focal length in pixels)",
                    label(lab, sizeof lab, keys, names, K_FY, 4));
    return 0;
}

/* near and far, and the depth range the float depth buffer holds. */
static int check_depth(const src *s, const gls_camera_keys *keys, const char *const *names)
{
    double near = keys->val[K_NEAR][0], far = keys->val[K_FAR][0];
    const unsigned *seen = keys->seen, *vcol = keys->vcol;
    if (!(near > 0))
        return FAIL(s, seen[K_NEAR], vcol[K_NEAR], "%s must be > 0", names[K_NEAR]);
    if (!(far > near)) {
        char f[40], n[40];
        gls_fmt_double(f, sizeof f, far);
        gls_fmt_double(n, sizeof n, near);
        return FAIL(s, seen[K_FAR], vcol[K_FAR], "%s (%s) must be greater than %s (%s)", names[K_FAR], f,
                    names[K_NEAR], n);
    }
    double nmin, nmax;
    if (gls_camera_depth_range(near, far, &nmin, &nmax)) {
        char n[40], f[40], lim[40];
        gls_fmt_double(n, sizeof n, near);
        gls_fmt_double(f, sizeof f, far);
        int small = near < nmin;
        fmt_limit(lim, sizeof lim, small ? nmin : nmax, small ? 1 : -1);
        return FAIL(s, seen[K_NEAR], vcol[K_NEAR],
                    "near %s is too %s for far %s: the float depth buffer would lose precision; near must be %s %s "
                    "(spec/camera.md, Depth range)",
                    n, small ? "small" : "large", f, small ? "at least" : "at most", lim);
    }
    return 0;
}

/* The same file must not give different images: a declared frame is
 * checked against the use. */
static int check_pose_use(const src *s, const gls_camera_keys *keys, gls_pose use)
{
    gls_pose pose = keys->pose;
    if (pose && use && pose != use)
        return FAIL(s, keys->seen[K_POSE], keys->vcol[K_POSE],
                    pose == GLS_POSE_WORLD
                        ? "'pose world': R and T are declared the camera's pose in the world, but they are used "
                          "relative to the rig here (with a trajectory); use a camera file declared 'pose rig'"
                        : "'pose rig': R and T are declared relative to the rig, which needs a trajectory (glsplay "
                          "--trajectory, or glsroad --camera-at for one frame)");
    return 0;
}

/* The checked values into cam: its geometry, no lens, no effects. */
static void camera_of_keys(const gls_camera_keys *keys, gls_camera *cam)
{
    const double (*val)[9] = (const double (*)[9])keys->val;
    memset(cam, 0, sizeof *cam);
    cam->width = (uint32_t)val[K_WIDTH][0];
    cam->height = (uint32_t)val[K_HEIGHT][0];
    cam->fx = val[K_FX][0];
    cam->fy = val[K_FY][0];
    cam->cx = val[K_CX][0];
    cam->cy = val[K_CY][0];
    cam->skew = keys->seen[K_SKEW] ? val[K_SKEW][0] : 0.0;
    memcpy(cam->R, val[K_R], sizeof cam->R);
    memcpy(cam->T, val[K_T], sizeof cam->T);
    cam->near = val[K_NEAR][0];
    cam->far = val[K_FAR][0];
    cam->pose = keys->pose;
}

int gls_camera_from_keys(gls_camera_keys *keys, const char *const *names, const char *text, size_t len,
                         const char *fname, gls_pose use, FILE *notes, gls_camera *cam, char *err, size_t errlen)
{
    src s = {text, fname, len, err, errlen};
    if (keys->seen[K_K] && intrinsics_from_K(&s, keys, names))
        return -1;
    if (keys->seen[K_RVEC])
        rotation_from_rvec(keys);
    if (check_size_focal(&s, keys, names) || check_depth(&s, keys, names) || check_pose_use(&s, keys, use))
        return -1;
    char why[300];
    int rot = gls_rotation_check(keys->val[K_R], why, sizeof why);
    /* at R's first number: in OpenCV YAML that is on the data: line, not
       the R: line (seen[K_R]) */
    unsigned rline = keys->eline[K_R][0], rcol = keys->ecol[K_R][0];
    if (rot < 0)
        return FAIL(&s, rline, rcol, "%s", why);
    camera_of_keys(keys, cam);
    if (lens_from_keys(keys, names, text, len, fname, cam, err, errlen) ||
        gls_camera_exposure_keys(keys, names, text, len, fname, cam, err, errlen))
        return -1;
    cam->sensor = gls_sensor_none();
    /* notes only for a file that is accepted */
    if (rot > 0 && notes)
        fprintf(notes, "%s:%u:%u: note: %s\n", fname, rline, rcol, why);
    if (!keys->pose && use == GLS_POSE_RIG && notes)
        fprintf(notes, "%s: note: no 'pose' key: R and T are taken relative to the rig, as a trajectory needs; add "
                       "'pose rig' to say so\n", fname);
    return 0;
}
