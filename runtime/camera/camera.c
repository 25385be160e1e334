/* Camera files (spec/camera.md "File format"; their values checked in
 * camera_keys.c, as OpenCV YAML's are) and the camera's matrices
 * (spec/camera.md "Projection", "Depth", "Back-projection"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "camera.h"
#include "camera_keys.h"
#include "distort.h"
#include "numfmt.h"
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

#define MAX_TOKENS 16

typedef gls_camera_src src;
#define FAIL GLS_CAMERA_FAIL

/* The column of t, a pointer into the line buf */
#define COL(t) ((unsigned)((t) - buf) + 1)

/* A first word that is no key (line's buf, word w). */
static int unknown_key(const src *s, const char *buf, unsigned line, const char *w)
{
    const char *sug = suggest(w);
    if (sug)
        return FAIL(s, line, COL(w), "unknown key '%s' (did you mean '%s'?)", w, sug);
    return FAIL(s, line, COL(w),
                "unknown key '%s' (keys: width height fx fy cx cy skew K R rvec T near far pose distortion "
                "fisheye gain read_noise shot_noise noise_seed vignetting bayer shutter line_delay aperture "
                "focus exposure_samples)", w);
}

/* Key k at word w: refused when it, or a key giving the same thing, was
 * given before. */
static int given_before(const src *s, const gls_camera_keys *keys, int k, const char *buf, unsigned line,
                        const char *w)
{
    const unsigned *seen = keys->seen;
    if (seen[k])
        return FAIL(s, line, COL(w), "key '%s' given twice (first on line %u)", key_name[k], seen[k]);
    int other = given_already(k, seen);
    if (other < 0)
        return 0;
    int rot = k == K_R || k == K_RVEC, lens = k == K_DIST || k == K_FISHEYE;
    return FAIL(s, line, COL(w), "key '%s' and key '%s' (line %u) both give the %s: give %s", key_name[k],
                key_name[other], seen[other], rot ? "rotation" : lens ? "lens distortion" : "intrinsics",
                rot    ? "R or rvec, not both"
                : lens ? "distortion (OpenCV's Brown-Conrady model) or fisheye (cv::fisheye), not both"
                       : "K, or fx fy cx cy and optionally skew, not both");
}

/* The value of key 'pose': one word, world or rig. */
static int pose_value(const src *s, gls_camera_keys *keys, char *const *tok, int nt, const char *buf, unsigned line)
{
    if (nt != 2)
        return FAIL(s, line, COL(tok[0]), "key 'pose' takes one word, world or rig, got %s%d",
                    nt > MAX_TOKENS ? "more than " : "", nt - 1);
    gls_pose pose = strcmp(tok[1], "world") == 0 ? GLS_POSE_WORLD
                    : strcmp(tok[1], "rig") == 0 ? GLS_POSE_RIG
                                                 : GLS_POSE_UNDECLARED;
    if (!pose)
        return FAIL(s, line, COL(tok[1]),
                    "key 'pose': '%s' is neither world (R and T map the world into the camera) nor rig (they map the "
                    "rig, with a trajectory)", tok[1]);
    keys->pose = pose;
    return 0;
}

/* The numbers of key k: tok[1..nt), as many as the key takes. */
static int numbers_value(const src *s, gls_camera_keys *keys, int k, char *const *tok, int nt, const char *buf,
                         unsigned line)
{
    /* "T 0,0,0" or "cx 319,5": point at the comma, not at the count */
    for (int j = 1; j < nt; j++) {
        char *comma = strchr(tok[j], ',');
        if (comma)
            return FAIL(s, line, COL(comma),
                        "key '%s': a comma in '%s': separate numbers with spaces and write decimals with '.'",
                        key_name[k], tok[j]);
    }
    if (k == K_DIST && nt - 1 != 4 && nt - 1 != 5 && nt - 1 != 8)
        return FAIL(s, line, COL(tok[0]),
                    "key 'distortion' takes 4, 5 or 8 numbers (k1 k2 p1 p2 [k3 [k4 k5 k6]], OpenCV's order), "
                    "got %s%d", nt > MAX_TOKENS ? "more than " : "", nt - 1);
    if (k == K_DIST)
        keys->ndist = (unsigned)(nt - 1);
    else if (nt - 1 != key_arity[k])
        return FAIL(s, line, COL(tok[0]), "key '%s' takes %d number%s, got %s%d", key_name[k], key_arity[k],
                    key_arity[k] == 1 ? "" : "s", nt > MAX_TOKENS ? "more than " : "", nt - 1);
    for (int j = 0; j < (k == K_DIST ? (int)keys->ndist : key_arity[k]); j++) {
        keys->eline[k][j] = line;
        keys->ecol[k][j] = COL(tok[1 + j]);
        const char *why = gls_parse_double(tok[1 + j], &keys->val[k][j]);
        if (why)
            return FAIL(s, line, COL(tok[1 + j]), "key '%s': '%s' %s", key_name[k], tok[1 + j], why);
    }
    return 0;
}

/* One line of the file (got, buf and n as gls_text_next_line gave them):
 * nothing, a sensor key's, or a key and its value; *last: the line, when
 * it holds a key. */
static int read_line(const src *s, gls_camera_keys *keys, gls_sensor_keys *sensor, int got, char *buf, size_t n,
                     unsigned line, unsigned *last)
{
    if (got < 0)
        return FAIL(s, line, GLS_TEXT_MAX_LINE + 1, "line longer than %u bytes", GLS_TEXT_MAX_LINE);
    const char *nul = memchr(buf, 0, n);
    if (nul)
        return FAIL(s, line, COL(nul), "NUL byte in camera file (is it a text file?)");
    /* a '#' or a CR ends the line */
    char *tok[MAX_TOKENS + 1];
    int nt = gls_text_split(buf, "#\r", " \t\f\v", tok, MAX_TOKENS + 1);
    if (nt == 0)
        return 0;
    int k;
    for (k = 0; k < K_COUNT; k++)
        if (strcmp(tok[0], key_name[k]) == 0)
            break;
    int sk = k == K_COUNT ? gls_sensor_key(tok[0]) : -1;
    if (sk >= 0) {
        if (gls_sensor_key_parse(sensor, sk, tok, nt, nt > MAX_TOKENS, buf, line, s->text, s->len, s->fname, s->err,
                                 s->errlen))
            return -1;
        *last = line;
        return 0;
    }
    if (k == K_COUNT)
        return unknown_key(s, buf, line, tok[0]);
    if (given_before(s, keys, k, buf, line, tok[0]) ||
        (k == K_POSE ? pose_value(s, keys, tok, nt, buf, line) : numbers_value(s, keys, k, tok, nt, buf, line)))
        return -1;
    keys->seen[k] = line;
    keys->vcol[k] = COL(tok[1]);
    *last = line;
    return 0;
}

/* Every required key given (K and rvec stand for what they give); the
 * message points at the last line holding a key. */
static int all_required(const src *s, const unsigned *seen, unsigned last)
{
    for (int k = 0; k < K_COUNT; k++) {
        /* optional: skew, pose; K and rvec stand for what they give */
        int optional = k == K_SKEW || k == K_POSE || k == K_K || k == K_RVEC || k == K_DIST || k == K_FISHEYE ||
                       k >= K_SHUTTER ||
                       (k >= K_FX && k <= K_CY && seen[K_K]) || (k == K_R && seen[K_RVEC]);
        if (!seen[k] && !optional)
            return FAIL(s, last ? last : 1, 1,
                        "missing key '%s' (required: width height fx fy cx cy (or K) R (or rvec) T near far)",
                        key_name[k]);
    }
    return 0;
}

int gls_camera_parse(const char *text, size_t len, const char *fname, gls_pose use, FILE *notes, gls_camera *cam,
                     char *err, size_t errlen)
{
    if (gls_camera_is_opencv(text, len))
        return gls_camera_parse_opencv(text, len, fname, use, notes, cam, err, errlen);
    src s = {text, fname, len, err, errlen};
    static gls_camera_keys zero;
    gls_camera_keys keys = zero;
    gls_sensor_keys sensor; /* the sensor's keys, read apart (sensor_keys.h) */
    gls_sensor_keys_init(&sensor);
    unsigned last = 0; /* last line holding a key */
    gls_text_lines it = {text, len, 0, 0};
    size_t n;
    int got;
    char buf[GLS_TEXT_MAX_LINE + 1];
    while ((got = gls_text_next_line(&it, buf, &n)) != 0)
        if (read_line(&s, &keys, &sensor, got, buf, n, it.line, &last))
            return -1;
    if (all_required(&s, keys.seen, last) ||
        gls_camera_from_keys(&keys, key_name, text, len, fname, use, notes, cam, err, errlen))
        return -1;
    cam->sensor = sensor.s;
    return 0;
}
#undef COL

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
