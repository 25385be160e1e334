/* Camera files (spec/camera.md "File format") and the camera's matrices
 * (spec/camera.md "Projection", "Depth", "Back-projection"). */
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "camera.h"
#include "camera_keys.h"
#include "distort.h"
#include "numfmt.h"
#include "rotation.h"
#include "sensor_keys.h"
#include "srcline.h"
#include "suggest.h"
#include "textfile.h"
#include "vec.h"

static const char *const key_name[K_COUNT] = {"width", "height", "fx", "fy", "cx", "cy", "skew",
                                              "R", "T", "near", "far", "pose", "K", "rvec", "distortion",
                                              "fisheye", "shutter", "line_delay", "aperture", "focus",
                                              "exposure_samples"};
/* pose: a word; distortion: 4, 5 or 8 (checked apart) */
static const int key_arity[K_COUNT] = {1, 1, 1, 1, 1, 1, 1, 9, 3, 1, 1, 1, 9, 3, 8, 4, 1, 1, 1, 1, 1};

/* The key that gives the same thing as key k (K: fx fy cx cy skew; rvec:
 * R) and was seen already, or -1. */
static int given_already(int k, const unsigned *seen)
{
    if (k == K_K) {
        for (int j = K_FX; j <= K_SKEW; j++)
            if (seen[j])
                return j;
    } else if (k >= K_FX && k <= K_SKEW && seen[K_K]) {
        return K_K;
    } else if (k == K_RVEC && seen[K_R]) {
        return K_R;
    } else if (k == K_R && seen[K_RVEC]) {
        return K_RVEC;
    } else if (k == K_DIST && seen[K_FISHEYE]) {
        return K_FISHEYE;
    } else if (k == K_FISHEYE && seen[K_DIST]) {
        return K_DIST;
    }
    return -1;
}

static const char *suggest(const char *word)
{
    const char *s = gls_suggest(word, strlen(word), key_name, K_COUNT);
    return s ? s : gls_suggest(word, strlen(word), gls_sensor_key_names, GLS_SENSOR_NKEYS);
}

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

#define MAX_TOKENS 16

int gls_camera_parse(const char *text, size_t len, const char *fname, gls_pose use, FILE *notes, gls_camera *cam,
                     char *err, size_t errlen)
{
    if (gls_camera_is_opencv(text, len))
        return gls_camera_parse_opencv(text, len, fname, use, notes, cam, err, errlen);
    static gls_camera_keys zero;
    gls_camera_keys keys = zero;
    gls_sensor_keys sensor; /* the sensor's keys, read apart (sensor_keys.h) */
    gls_sensor_keys_init(&sensor);
    double (*val)[9] = keys.val;
    unsigned *seen = keys.seen; /* line where each key was given, 0 = absent */
    unsigned *vcol = keys.vcol; /* column of its first value              */
    unsigned last = 0;          /* last line holding a key               */
    gls_text_lines it = {text, len, 0, 0};
    size_t n;
    int got;
    char buf[GLS_TEXT_MAX_LINE + 1];
    while ((got = gls_text_next_line(&it, buf, &n)) != 0) {
        unsigned line = it.line;
        if (got < 0) {
            gls_text_error(err, errlen, text, len, fname, line, GLS_TEXT_MAX_LINE + 1, "line longer than %u bytes",
                 GLS_TEXT_MAX_LINE);
            return -1;
        }
        const char *nul = memchr(buf, 0, n);
        if (nul) {
            gls_text_error(err, errlen, text, len, fname, line, (unsigned)(nul - buf) + 1,
                           "NUL byte in camera file (is it a text file?)");
            return -1;
        }
#define COL(t) ((unsigned)((t) - buf) + 1)
        /* a '#' or a CR ends the line */
        char *tok[MAX_TOKENS + 1];
        int nt = gls_text_split(buf, "#\r", " \t\f\v", tok, MAX_TOKENS + 1);
        if (nt == 0)
            continue;
        int k;
        for (k = 0; k < K_COUNT; k++)
            if (strcmp(tok[0], key_name[k]) == 0)
                break;
        int sk = k == K_COUNT ? gls_sensor_key(tok[0]) : -1;
        if (sk >= 0) {
            if (gls_sensor_key_parse(&sensor, sk, tok, nt, nt > MAX_TOKENS, buf, line, text, len, fname, err, errlen))
                return -1;
            last = line;
            continue;
        }
        if (k == K_COUNT) {
            const char *s = suggest(tok[0]);
            if (s)
                gls_text_error(err, errlen, text, len, fname, line, COL(tok[0]), "unknown key '%s' (did you mean '%s'?)", tok[0], s);
            else
                gls_text_error(err, errlen, text, len, fname, line, COL(tok[0]),
                     "unknown key '%s' (keys: width height fx fy cx cy skew K R rvec T near far pose distortion "
                     "fisheye gain read_noise shot_noise noise_seed vignetting bayer shutter line_delay aperture "
                     "focus exposure_samples)", tok[0]);
            return -1;
        }
        if (seen[k]) {
            gls_text_error(err, errlen, text, len, fname, line, COL(tok[0]), "key '%s' given twice (first on line %u)", key_name[k],
                 seen[k]);
            return -1;
        }
        int other = given_already(k, seen);
        if (other >= 0) {
            int rot = k == K_R || k == K_RVEC, lens = k == K_DIST || k == K_FISHEYE;
            gls_text_error(err, errlen, text, len, fname, line, COL(tok[0]),
                           "key '%s' and key '%s' (line %u) both give the %s: give %s", key_name[k], key_name[other],
                           seen[other], rot ? "rotation" : lens ? "lens distortion" : "intrinsics",
                           rot    ? "R or rvec, not both"
                           : lens ? "distortion (OpenCV's Brown-Conrady model) or fisheye (cv::fisheye), not both"
                                  : "K, or fx fy cx cy and optionally skew, not both");
            return -1;
        }
        if (k == K_POSE) {
            if (nt != 2) {
                gls_text_error(err, errlen, text, len, fname, line, COL(tok[0]), "key 'pose' takes one word, world or rig, got %s%d",
                     nt > MAX_TOKENS ? "more than " : "", nt - 1);
                return -1;
            }
            gls_pose pose = strcmp(tok[1], "world") == 0 ? GLS_POSE_WORLD : strcmp(tok[1], "rig") == 0 ? GLS_POSE_RIG
                                                                                            : GLS_POSE_UNDECLARED;
            if (!pose) {
                gls_text_error(err, errlen, text, len, fname, line, COL(tok[1]),
                     "key 'pose': '%s' is neither world (R and T map the world into the camera) nor rig (they map the "
                     "rig, with a trajectory)", tok[1]);
                return -1;
            }
            keys.pose = pose;
            seen[k] = line;
            vcol[k] = COL(tok[1]);
            last = line;
            continue;
        }
        /* "T 0,0,0" or "cx 319,5": point at the comma, not at the count */
        for (int j = 1; j < nt; j++) {
            char *comma = strchr(tok[j], ',');
            if (comma) {
                gls_text_error(err, errlen, text, len, fname, line, COL(comma),
                     "key '%s': a comma in '%s': separate numbers with spaces and write decimals with '.'", key_name[k],
                     tok[j]);
                return -1;
            }
        }
        if (k == K_DIST && nt - 1 != 4 && nt - 1 != 5 && nt - 1 != 8) {
            gls_text_error(err, errlen, text, len, fname, line, COL(tok[0]),
                           "key 'distortion' takes 4, 5 or 8 numbers (k1 k2 p1 p2 [k3 [k4 k5 k6]], OpenCV's order), "
                           "got %s%d", nt > MAX_TOKENS ? "more than " : "", nt - 1);
            return -1;
        }
        if (k == K_DIST)
            keys.ndist = (unsigned)(nt - 1);
        else if (nt - 1 != key_arity[k]) {
            gls_text_error(err, errlen, text, len, fname, line, COL(tok[0]), "key '%s' takes %d number%s, got %s%d", key_name[k],
                 key_arity[k], key_arity[k] == 1 ? "" : "s", nt > MAX_TOKENS ? "more than " : "", nt - 1);
            return -1;
        }
        for (int j = 0; j < (k == K_DIST ? (int)keys.ndist : key_arity[k]); j++) {
            keys.eline[k][j] = line;
            keys.ecol[k][j] = COL(tok[1 + j]);
            const char *why = gls_parse_double(tok[1 + j], &val[k][j]);
            if (why) {
                gls_text_error(err, errlen, text, len, fname, line, COL(tok[1 + j]), "key '%s': '%s' %s", key_name[k],
                     tok[1 + j], why);
                return -1;
            }
        }
        seen[k] = line;
        vcol[k] = COL(tok[1]);
        last = line;
#undef COL
    }
    for (int k = 0; k < K_COUNT; k++) {
        /* optional: skew, pose; K and rvec stand for what they give */
        int optional = k == K_SKEW || k == K_POSE || k == K_K || k == K_RVEC || k == K_DIST || k == K_FISHEYE ||
                       k >= K_SHUTTER ||
                       (k >= K_FX && k <= K_CY && seen[K_K]) || (k == K_R && seen[K_RVEC]);
        if (!seen[k] && !optional) {
            gls_text_error(err, errlen, text, len, fname, last ? last : 1, 1,
                 "missing key '%s' (required: width height fx fy cx cy (or K) R (or rvec) T near far)", key_name[k]);
            return -1;
        }
    }
    if (gls_camera_from_keys(&keys, key_name, text, len, fname, use, notes, cam, err, errlen))
        return -1;
    cam->sensor = sensor.s;
    return 0;
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

int gls_camera_from_keys(gls_camera_keys *keys, const char *const *names, const char *text, size_t len,
                         const char *fname, gls_pose use, FILE *notes, gls_camera *cam, char *err, size_t errlen)
{
    double (*val)[9] = keys->val;
    unsigned *seen = keys->seen, *vcol = keys->vcol;
    gls_pose pose = keys->pose;
    char lab[64];
    /* K = [[fx, skew, cx], [0, fy, cy], [0, 0, 1]]: the intrinsics keys
       from it, each located at its entry */
    if (seen[K_K]) {
        static const int at[3][2] = {{1, 0}, {2, 0}, {2, 1}};
        for (int i = 0; i < 4; i++) {
            int e = i < 3 ? 3 * at[i][0] + at[i][1] : 8;
            double want = i < 3 ? 0 : 1;
            if (val[K_K][e] != want) {
                char num[40];
                gls_fmt_double(num, sizeof num, val[K_K][e]);
                gls_text_error(err, errlen, text, len, fname, keys->eline[K_K][e], keys->ecol[K_K][e],
                               "%s[%d][%d] is %s, must be %g: the camera matrix is [[fx, skew, cx], [0, fy, cy], "
                               "[0, 0, 1]]", names[K_K], e / 3, e % 3, num, want);
                return -1;
            }
        }
        static const int from[5][2] = {{K_FX, 0}, {K_FY, 4}, {K_CX, 2}, {K_CY, 5}, {K_SKEW, 1}};
        for (int i = 0; i < 5; i++) {
            int key = from[i][0], e = from[i][1];
            val[key][0] = val[K_K][e];
            seen[key] = keys->eline[K_K][e];
            vcol[key] = keys->ecol[K_K][e];
        }
    }
    if (seen[K_RVEC]) {
        gls_rotation_rodrigues(val[K_RVEC], val[K_R]);
        seen[K_R] = seen[K_RVEC];
        vcol[K_R] = vcol[K_RVEC];
        keys->eline[K_R][0] = keys->eline[K_RVEC][0];
        keys->ecol[K_R][0] = keys->ecol[K_RVEC][0];
    }
    static const int dims[2] = {K_WIDTH, K_HEIGHT};
    for (int i = 0; i < 2; i++) {
        double v = val[dims[i]][0];
        if (v != floor(v) || v < 1 || v > GLS_CAMERA_MAX_DIM) {
            char num[40];
            gls_fmt_double(num, sizeof num, v);
            gls_text_error(err, errlen, text, len, fname, seen[dims[i]], vcol[dims[i]], "%s %s must be a whole number in 1..%u",
                 names[dims[i]], num, GLS_CAMERA_MAX_DIM);
            return -1;
        }
    }
    if (!(val[K_FX][0] > 0)) {
        gls_text_error(err, errlen, text, len, fname, seen[K_FX], vcol[K_FX], "%s must be > 0 (focal length in pixels)",
                       label(lab, sizeof lab, keys, names, K_FX, 0));
        return -1;
    }
    if (!(val[K_FY][0] > 0)) {
        gls_text_error(err, errlen, text, len, fname, seen[K_FY], vcol[K_FY], "%s must be > 0 (focal length in pixels)",
                       label(lab, sizeof lab, keys, names, K_FY, 4));
        return -1;
    }
    if (!(val[K_NEAR][0] > 0)) {
        gls_text_error(err, errlen, text, len, fname, seen[K_NEAR], vcol[K_NEAR], "%s must be > 0", names[K_NEAR]);
        return -1;
    }
    if (!(val[K_FAR][0] > val[K_NEAR][0])) {
        char f[40], n[40];
        gls_fmt_double(f, sizeof f, val[K_FAR][0]);
        gls_fmt_double(n, sizeof n, val[K_NEAR][0]);
        gls_text_error(err, errlen, text, len, fname, seen[K_FAR], vcol[K_FAR], "%s (%s) must be greater than %s (%s)", names[K_FAR], f, names[K_NEAR], n);
        return -1;
    }
    double nmin, nmax;
    if (gls_camera_depth_range(val[K_NEAR][0], val[K_FAR][0], &nmin, &nmax)) {
        char n[40], f[40], lim[40];
        gls_fmt_double(n, sizeof n, val[K_NEAR][0]);
        gls_fmt_double(f, sizeof f, val[K_FAR][0]);
        int small = val[K_NEAR][0] < nmin;
        fmt_limit(lim, sizeof lim, small ? nmin : nmax, small ? 1 : -1);
        gls_text_error(err, errlen, text, len, fname, seen[K_NEAR], vcol[K_NEAR],
             "near %s is too %s for far %s: the float depth buffer would lose precision; near must be %s %s "
             "(spec/camera.md, Depth range)",
             n, small ? "small" : "large", f, small ? "at least" : "at most", lim);
        return -1;
    }
    /* the same file must not give different images: a declared frame is
       checked against the use */
    if (pose && use && pose != use) {
        gls_text_error(err, errlen, text, len, fname, seen[K_POSE], vcol[K_POSE],
             pose == GLS_POSE_WORLD
                 ? "'pose world': R and T are declared the camera's pose in the world, but they are used relative to "
                   "the rig here (with a trajectory); use a camera file declared 'pose rig'"
                 : "'pose rig': R and T are declared relative to the rig, which needs a trajectory (glsplay "
                   "--trajectory, or glsroad --camera-at for one frame)");
        return -1;
    }
    char why[300];
    int rot = gls_rotation_check(val[K_R], why, sizeof why);
    /* at R's first number: in OpenCV YAML that is on the data: line, not
       the R: line (seen[K_R]) */
    unsigned rline = keys->eline[K_R][0], rcol = keys->ecol[K_R][0];
    if (rot < 0) {
        gls_text_error(err, errlen, text, len, fname, rline, rcol, "%s", why);
        return -1;
    }
    memset(cam, 0, sizeof *cam);
    cam->width = (uint32_t)val[K_WIDTH][0];
    cam->height = (uint32_t)val[K_HEIGHT][0];
    cam->fx = val[K_FX][0];
    cam->fy = val[K_FY][0];
    cam->cx = val[K_CX][0];
    cam->cy = val[K_CY][0];
    cam->skew = seen[K_SKEW] ? val[K_SKEW][0] : 0.0;
    memcpy(cam->R, val[K_R], sizeof cam->R);
    memcpy(cam->T, val[K_T], sizeof cam->T);
    cam->near = val[K_NEAR][0];
    cam->far = val[K_FAR][0];
    cam->pose = pose;
    if (lens_from_keys(keys, names, text, len, fname, cam, err, errlen) ||
        gls_camera_exposure_keys(keys, names, text, len, fname, cam, err, errlen))
        return -1;
    cam->sensor = gls_sensor_none();
    /* notes only for a file that is accepted */
    if (rot > 0 && notes)
        fprintf(notes, "%s:%u:%u: note: %s\n", fname, rline, rcol, why);
    if (!pose && use == GLS_POSE_RIG && notes)
        fprintf(notes, "%s: note: no 'pose' key: R and T are taken relative to the rig, as a trajectory needs; add "
                       "'pose rig' to say so\n", fname);
    return 0;
}

int gls_camera_load(const char *path, gls_pose use, FILE *notes, gls_camera *cam, char *err, size_t errlen)
{
    size_t n;
    char *text = gls_text_read(path, GLS_CAMERA_MAX_FILE, "camera file", &n, err, errlen);
    if (!text)
        return -1;
    int r = gls_camera_parse(text, n, path, use, notes, cam, err, errlen);
    free(text);
    return r;
}

void gls_camera_projection(const gls_camera *c, double du, double dv, double P[16])
{
    /* spec/camera.md "Projection": eye = (x, -y, -z) of the camera frame;
     * x_w = u + 0.5, y_w = v + 0.5 with viewport (0, 0, W, H). */
    double W = c->width, H = c->height, n = c->near, f = c->far;
    double cx = c->cx + du, cy = c->cy + dv;
    memset(P, 0, 16 * sizeof *P);
    P[0] = 2 * c->fx / W;
    P[1] = -2 * c->skew / W;
    P[2] = 1 - 2 * (cx + 0.5) / W;
    P[5] = -2 * c->fy / H;
    P[6] = 1 - 2 * (cy + 0.5) / H;
    P[10] = n / (f - n);
    P[11] = n * f / (f - n);
    P[14] = -1;
}

void gls_camera_projection_map(const gls_camera *c, const double m[6], double vw, double vh, double P[16])
{
    /* with Zc = -ze: u Zc = fx xe - skew ye - cx ze, v Zc = -fy ye - cy ze;
     * x_clip = (2 / vw) (m0 u Zc + m1 v Zc + m2 Zc) - Zc, and y alike */
    double n = c->near, f = c->far;
    memset(P, 0, 16 * sizeof *P);
    const double size[2] = {vw, vh};
    for (int row = 0; row < 2; row++) {
        const double *r = m + 3 * row;
        double s = 2 / size[row];
        P[4 * row + 0] = s * r[0] * c->fx;
        P[4 * row + 1] = s * (-r[0] * c->skew - r[1] * c->fy);
        P[4 * row + 2] = s * (-r[0] * c->cx - r[1] * c->cy - r[2]) + 1;
    }
    P[10] = n / (f - n);
    P[11] = n * f / (f - n);
    P[14] = -1;
}

void gls_camera_modelview(const gls_camera *c, const double a[3], double MV[16])
{
    const double *R = c->R;
    /* R*a + T: the large parts cancel here, in double */
    rv3 r = rm_apply(R, rv(a[0], a[1], a[2]));
    const double Ra[3] = {r.x, r.y, r.z};
    memset(MV, 0, 16 * sizeof *MV);
    for (int i = 0; i < 3; i++) {
        double s = i == 0 ? 1.0 : -1.0; /* the flip diag(1, -1, -1) */
        for (int j = 0; j < 3; j++)
            MV[4 * i + j] = s * R[3 * i + j];
        MV[4 * i + 3] = s * (Ra[i] + c->T[i]);
    }
    MV[15] = 1;
}

double gls_camera_depth_to_z(const gls_camera *c, double d)
{
    if (d <= 0)
        return INFINITY;
    double n = c->near, f = c->far;
    return n * f / ((f - n) * d + n);
}

void gls_camera_unproject(const gls_camera *c, double u, double v, double Zc, double Pc[3])
{
    double y = (v - c->cy) / c->fy;                  /* Yc / Zc */
    double x = ((u - c->cx) - c->skew * y) / c->fx;  /* Xc / Zc */
    if (gls_distort_on(c) && gls_distort_pixel_ray(c, u, v, &x, &y) < 0)
        x = y = NAN; /* not for a pixel of a checked camera's image */
    Pc[0] = x * Zc;
    Pc[1] = y * Zc;
    Pc[2] = Zc;
}

void gls_camera_to_world(const gls_camera *c, const double Pc[3], double P[3])
{
    rv3 p = rm_apply_t(c->R, rv(Pc[0] - c->T[0], Pc[1] - c->T[1], Pc[2] - c->T[2]));
    P[0] = p.x, P[1] = p.y, P[2] = p.z;
}

void gls_camera_to_cam(const gls_camera *c, const double P[3], double Pc[3])
{
    rv3 p = rm_apply(c->R, rv(P[0], P[1], P[2]));
    Pc[0] = p.x + c->T[0], Pc[1] = p.y + c->T[1], Pc[2] = p.z + c->T[2];
}

double gls_camera_project(const gls_camera *c, const double P[3], double *u, double *v)
{
    double Pc[3];
    gls_camera_to_cam(c, P, Pc);
    *u = (c->fx * Pc[0] + c->skew * Pc[1]) / Pc[2] + c->cx;
    *v = c->fy * Pc[1] / Pc[2] + c->cy;
    return Pc[2];
}

void gls_camera_centre(const gls_camera *c, double C[3])
{
    double z[3] = {0, 0, 0};
    gls_camera_to_world(c, z, C);
}
