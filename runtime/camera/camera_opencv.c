/* A camera given as the YAML that cv::FileStorage writes (spec/camera.md
 * "OpenCV camera files"): top-level `key: scalar` lines and
 * `key: !!opencv-matrix` blocks (rows, cols, dt, data: [ ... ], the data
 * possibly over several lines).  Only that layout is read, not YAML at
 * large: it is what OpenCV writes and reads.  The values are checked by
 * the .cam parser's own code (gls_camera_from_keys, camera_keys.h), so
 * both formats refuse the same cameras with the same messages. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "camera_keys.h"
#include "numfmt.h"
#include "sensor_keys.h"
#include "srcline.h"
#include "textfile.h"

int gls_camera_is_opencv(const char *text, size_t len)
{
    return len >= 5 && memcmp(text, "%YAML", 5) == 0;
}

/* the keys read, and what glsplay's messages call them */
enum { Y_TVEC = K_COUNT, Y_DMODEL, Y_COUNT };
static const char *const yname[Y_COUNT] = {
    [K_WIDTH] = "image_width", [K_HEIGHT] = "image_height", [K_K] = "camera_matrix", [K_R] = "R",
    [K_RVEC] = "rvec",         [K_T] = "T",                 [K_NEAR] = "near",       [K_FAR] = "far",
    [K_POSE] = "pose",         [K_DIST] = "distortion_coefficients",                 [Y_TVEC] = "tvec",
    [Y_DMODEL] = "distortion_model",
    /* the effects, under the .cam file's names (spec/camera.md "OpenCV
     * camera files"); the sensor's keys are read apart (sensor_value) */
    [K_SHUTTER] = "shutter", [K_LINE_DELAY] = "line_delay", [K_APERTURE] = "aperture", [K_FOCUS] = "focus",
    [K_EXPOSURE_SAMPLES] = "exposure_samples",
    /* not keys of the file; named in messages about K's entries */
    [K_FX] = "fx", [K_FY] = "fy", [K_CX] = "cx", [K_CY] = "cy", [K_SKEW] = "skew"};
/* OpenCV's distortion coefficients, in its order */
static const char *const dist_name[14] = {"k1", "k2", "p1", "p2", "k3", "k4", "k5",
                                          "k6", "s1", "s2", "s3", "s4", "tx", "ty"};
#define MAXDATA 16

typedef gls_camera_src src;

static int fail(const src *s, unsigned line, unsigned col, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static int fail(const src *s, unsigned line, unsigned col, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    gls_text_error(s->err, s->errlen, s->text, s->len, s->fname, line, col, "%s", msg);
    return -1;
}

/* One !!opencv-matrix block being read. */
typedef struct {
    int key;                 /* -1: none open                        */
    unsigned line, col;      /* of its key                           */
    int rows, cols, have_dt; /* rows, cols: -1 until given           */
    int in_data, data_done;  /* inside data's '[', after its ']'     */
    size_t n;                /* numbers read                         */
    double v[MAXDATA];
    unsigned vline[MAXDATA], vcol[MAXDATA];
} matrix;

/* Numbers of a data list from p on (column col0 of line), until ']'. */
static int data_numbers(const src *s, matrix *m, char *p, unsigned line, unsigned col0)
{
    char *start = p;
    for (;;) {
        p += strspn(p, " \t,");
        if (!*p || *p == '#')
            return 0;
        if (*p == ']') {
            m->in_data = 0;
            m->data_done = 1;
            p += 1 + strspn(p + 1, " \t");
            if (*p && *p != '#')
                return fail(s, line, col0 + (unsigned)(p - start), "key '%s': text after the data's ']'", yname[m->key]);
            return 0;
        }
        size_t k = strcspn(p, " \t,]#");
        char c = p[k], tok[64];
        unsigned col = col0 + (unsigned)(p - start);
        p[k] = 0;
        snprintf(tok, sizeof tok, "%s", p);
        double v;
        const char *why = gls_parse_double(p, &v);
        if (why)
            return fail(s, line, col, "key '%s': '%s' %s", yname[m->key], tok, why);
        if (m->n < MAXDATA) {
            m->v[m->n] = v;
            m->vline[m->n] = line;
            m->vcol[m->n] = col;
        }
        m->n++;
        p[k] = c;
        p += k;
    }
}

/* One "field: value" line inside a matrix block. */
static int matrix_field(const src *s, matrix *m, char *p, unsigned line, unsigned col0)
{
    char *start = p;
    if (m->in_data)
        return data_numbers(s, m, p, line, col0);
    const char *name = yname[m->key];
    char *colon = strchr(p, ':');
    if (!colon || m->data_done)
        return fail(s, line, col0, "key '%s': expected rows, cols, dt and data of an !!opencv-matrix", name);
    *colon = 0;
    char *v = colon + 1;
    v += strspn(v, " \t");
    unsigned vc = col0 + (unsigned)(v - start);
    if (strcmp(p, "rows") == 0 || strcmp(p, "cols") == 0) {
        int *dst = p[0] == 'r' ? &m->rows : &m->cols;
        char *e;
        long x = strtol(v, &e, 10);
        e += strspn(e, " \t");
        if (e == v || (*e && *e != '#') || x < 1 || x > 1000)
            return fail(s, line, vc, "key '%s': %s must be a whole number, 1 or more", name, p);
        *dst = (int)x;
        return 0;
    }
    if (strcmp(p, "dt") == 0) {
        /* OpenCV's element types; the numbers are read as doubles anyway */
        size_t k = strcspn(v, " \t#");
        if (k != 1 || !strchr("ucwsifd", v[0]))
            return fail(s, line, vc, "key '%s': dt must be one of u c w s i f d (an element type)", name);
        m->have_dt = 1;
        return 0;
    }
    if (strcmp(p, "data") == 0) {
        if (*v != '[')
            return fail(s, line, vc, "key '%s': data must be a list, [ ... ]", name);
        m->in_data = 1;
        return data_numbers(s, m, v + 1, line, vc + 1);
    }
    return fail(s, line, col0, "key '%s': unknown field '%s' of an !!opencv-matrix (rows, cols, dt, data)", name, p);
}

/* A matrix block is complete: check its shape and keep its values. */
static int matrix_end(const src *s, matrix *m, gls_camera_keys *keys)
{
    const char *name = yname[m->key];
    if (m->in_data)
        return fail(s, m->line, m->col, "key '%s': the data list has no closing ']'", name);
    if (m->rows < 0 || m->cols < 0 || !m->have_dt || !m->data_done)
        return fail(s, m->line, m->col, "key '%s': an !!opencv-matrix needs rows, cols, dt and data", name);
    if ((size_t)m->rows * (size_t)m->cols != m->n)
        return fail(s, m->line, m->col, "key '%s': %dx%d needs %d numbers, data has %zu", name, m->rows, m->cols,
                    m->rows * m->cols, m->n);
    int key = m->key;
    if (key == K_DIST) {
        size_t n = m->n;
        if ((m->rows != 1 && m->cols != 1) || (n != 4 && n != 5 && n != 8 && n != 12 && n != 14))
            return fail(s, m->line, m->col, "key '%s' must be a 1xN or Nx1 matrix, N = 4, 5, 8, 12 or 14 (OpenCV's "
                        "sizes), got %dx%d", name, m->rows, m->cols);
        /* thin prism and tilt: not modelled, so they must be 0 */
        for (size_t i = 8; i < n; i++)
            if (m->v[i] != 0) {
                char num[40];
                gls_fmt_double(num, sizeof num, m->v[i]);
                return fail(s, m->vline[i], m->vcol[i],
                            "key '%s': %s is %s: glsplay models k1 k2 p1 p2 k3 k4 k5 k6 (and cv::fisheye); the "
                            "thin-prism s1..s4 and tilt tx ty coefficients must be 0", name, dist_name[i], num);
            }
        keys->ndist = n < 8 ? (unsigned)n : 8;
        memcpy(keys->val[K_DIST], m->v, keys->ndist * sizeof *m->v);
        memcpy(keys->eline[K_DIST], m->vline, keys->ndist * sizeof *m->vline);
        memcpy(keys->ecol[K_DIST], m->vcol, keys->ndist * sizeof *m->vcol);
        keys->vcol[K_DIST] = m->col;
        return 0;
    }
    int square = key == K_K || key == K_R;
    if (square ? m->rows != 3 || m->cols != 3 : (m->rows != 1 && m->cols != 1) || m->n != 3)
        return fail(s, m->line, m->col, "key '%s' must be a %s matrix, got %dx%d%s", name, square ? "3x3" : "3x1",
                    m->rows, m->cols, key == K_R && m->n == 3 ? " (a Rodrigues vector is 'rvec')" : "");
    if (key == Y_TVEC)
        key = K_T;
    memcpy(keys->val[key], m->v, m->n * sizeof *m->v);
    memcpy(keys->eline[key], m->vline, m->n * sizeof *m->vline);
    memcpy(keys->ecol[key], m->vcol, m->n * sizeof *m->vcol);
    keys->vcol[key] = m->col;
    return 0;
}

/* A top-level scalar: one number, or (pose) one word, maybe quoted. */
static int scalar(const src *s, gls_camera_keys *keys, int k, char *v, unsigned line, unsigned vc)
{
    char *end;
    if (*v == '"' && (end = strchr(v + 1, '"')) != NULL) {
        v++, vc++;
        *end = 0;
    } else {
        end = v + strcspn(v, "#");
        while (end > v && (end[-1] == ' ' || end[-1] == '\t'))
            end--;
        *end = 0;
    }
    keys->vcol[k] = vc;
    if (k == K_POSE) {
        keys->pose = strcmp(v, "world") == 0 ? GLS_POSE_WORLD : strcmp(v, "rig") == 0 ? GLS_POSE_RIG
                                                                                      : GLS_POSE_UNDECLARED;
        if (!keys->pose)
            return fail(s, line, vc, "key 'pose': '%s' is neither world (R and T map the world into the camera) nor "
                        "rig (they map the rig, with a trajectory)", v);
        return 0;
    }
    const char *why = gls_parse_double(v, &keys->val[k][0]);
    return why ? fail(s, line, vc, "key '%s': '%s' %s", yname[k], v, why) : 0;
}

/* A sensor key's line (sensor_keys.h): its value, quoted or not, split
 * into words in place (the quotes blanked, so columns stay the line's)
 * and checked by the .cam file's own code, with its messages. */
#define SENSOR_MAX_WORDS 8
static int sensor_value(const src *s, gls_sensor_keys *sk, int key, char *buf, char *name, char *v, unsigned line)
{
    char *end = NULL;
    if (*v == '"' && (end = strchr(v + 1, '"')) != NULL) {
        *v = ' ', *end = 0;
    } else {
        v[strcspn(v, "#")] = 0;
    }
    char *tok[SENSOR_MAX_WORDS + 1];
    tok[0] = name;
    int nt = 1 + gls_text_split(v, "", " \t", tok + 1, SENSOR_MAX_WORDS);
    return gls_sensor_key_parse(sk, key, tok, nt, nt > SENSOR_MAX_WORDS, buf, line, s->text, s->len, s->fname,
                                s->err, s->errlen);
}

/* distortion_model: which model the coefficients are for (spec/camera.md
 * "OpenCV camera files"): plumb_bob or rational_polynomial (cv::projectPoints,
 * the default) or fisheye / equidistant (cv::fisheye); ROS's names. */
static int lens_model(const src *s, char *v, unsigned line, unsigned vc, int *fisheye)
{
    char *end = v + strcspn(v, " \t#");
    *end = 0;
    if (*v == '"' && end > v + 1 && end[-1] == '"')
        end[-1] = 0, v++, vc++;
    if (strcmp(v, "fisheye") == 0 || strcmp(v, "equidistant") == 0)
        *fisheye = 1;
    else if (strcmp(v, "plumb_bob") == 0 || strcmp(v, "rational_polynomial") == 0)
        *fisheye = 0;
    else
        return fail(s, line, vc, "key 'distortion_model': '%s' is none of plumb_bob, rational_polynomial "
                    "(cv::projectPoints), fisheye, equidistant (cv::fisheye)", v);
    return 0;
}

/* The reading of one file: what the lines so far gave. */
typedef struct {
    gls_camera_keys keys;
    unsigned seen[Y_COUNT], last; /* line of each key; of the last key */
    int fisheye;                  /* distortion_model: fisheye (or equidistant) */
    gls_sensor_keys sensor;       /* the sensor's keys, read apart (sensor_keys.h) */
    matrix m;                     /* the matrix block open, if any */
    int skipping;                 /* inside the value of a key glsplay does not read */
} reading;

/* A top-level line's key p (its column col) and value v (column vc):
 * which key, not given before, and its value read or its matrix opened. */
static int key_line(const src *s, reading *rd, char *buf, char *p, unsigned col, char *v, unsigned line)
{
    unsigned vc = (unsigned)(v - buf) + 1;
    int sk = gls_sensor_key(p);
    if (sk >= 0) {
        if (sensor_value(s, &rd->sensor, sk, buf, p, v, line))
            return -1;
        rd->last = line;
        return 0;
    }
    int k;
    for (k = 0; k < Y_COUNT; k++)
        if (yname[k] && k != K_FX && k != K_FY && k != K_CX && k != K_CY && k != K_SKEW && strcmp(p, yname[k]) == 0)
            break;
    if (k == Y_COUNT) {
        rd->skipping = 1; /* calibration metadata: per-view errors, times, ... */
        return 0;
    }
    unsigned *seen = rd->seen;
    if (seen[k])
        return fail(s, line, col, "key '%s' given twice (first on line %u)", p, seen[k]);
    static const int pairs[3][2] = {{K_R, K_RVEC}, {K_T, Y_TVEC}, {-1, -1}};
    for (int i = 0; pairs[i][0] >= 0; i++) {
        int other = k == pairs[i][0] ? pairs[i][1] : k == pairs[i][1] ? pairs[i][0] : -1;
        if (other >= 0 && seen[other])
            return fail(s, line, col, "key '%s' and key '%s' (line %u) both give the %s: give one", p, yname[other],
                        seen[other], i == 0 ? "rotation" : "translation");
    }
    seen[k] = line;
    rd->last = line;
    if (k != Y_DMODEL)
        rd->keys.seen[k == Y_TVEC ? K_T : k] = line;
    if (k == K_K || k == K_R || k == K_RVEC || k == K_T || k == K_DIST || k == Y_TVEC) {
        if (strncmp(v, "!!opencv-matrix", 15) != 0 || v[15 + strspn(v + 15, " \t")] != 0)
            return fail(s, line, vc, "key '%s' must be an !!opencv-matrix (as cv::FileStorage writes a cv::Mat)", p);
        rd->m = (matrix){.key = k, .line = line, .col = col, .rows = -1, .cols = -1};
        return 0;
    }
    if (k == Y_DMODEL)
        return lens_model(s, v, line, vc, &rd->fisheye);
    return scalar(s, &rd->keys, k, v, line, vc);
}

/* One line of the file (got, buf and n as gls_text_next_line gave them):
 * a matrix's field, a skipped key's, or a top-level key (which ends the
 * open matrix). */
static int read_line(const src *s, reading *rd, int got, char *buf, size_t n, unsigned line)
{
    if (got < 0)
        return fail(s, line, GLS_TEXT_MAX_LINE + 1, "line longer than %u bytes", GLS_TEXT_MAX_LINE);
    if (memchr(buf, 0, n))
        return fail(s, line, (unsigned)((char *)memchr(buf, 0, n) - buf) + 1,
                    "NUL byte in camera file (is it a text file?)");
    buf[strcspn(buf, "\r")] = 0;
    size_t ind = strspn(buf, " \t");
    char *p = buf + ind;
    unsigned col = (unsigned)ind + 1;
    if (!*p || *p == '#')
        return 0;
    if (ind > 0) {
        if (rd->m.key >= 0)
            return matrix_field(s, &rd->m, p, line, col);
        if (!rd->skipping)
            return fail(s, line, col, "an indented line outside a matrix (expected 'key: value')");
        return 0;
    }
    if (rd->m.key >= 0 && matrix_end(s, &rd->m, &rd->keys))
        return -1;
    rd->m.key = -1;
    rd->skipping = 0;
    if (*p == '%' || strcmp(p, "---") == 0 || strcmp(p, "...") == 0)
        return 0; /* directives, document markers */
    char *colon = strchr(p, ':');
    if (!colon)
        return fail(s, line, col, "expected 'key: value' (an OpenCV FileStorage YAML file)");
    *colon = 0;
    char *v = colon + 1;
    v += strspn(v, " \t");
    return key_line(s, rd, buf, p, col, v, line);
}

/* After the last line: the required keys, and the coefficients made
 * cv::fisheye's when distortion_model says fisheye. */
static int all_read(const src *s, reading *rd)
{
    const unsigned *seen = rd->seen;
    gls_camera_keys *keys = &rd->keys;
    static const int required[][2] = {{K_WIDTH, -1}, {K_HEIGHT, -1}, {K_K, -1}, {K_R, K_RVEC},
                                      {K_T, Y_TVEC}, {K_NEAR, -1},   {K_FAR, -1}};
    for (size_t i = 0; i < sizeof required / sizeof required[0]; i++) {
        int k = required[i][0], alt = required[i][1];
        if (!seen[k] && (alt < 0 || !seen[alt]))
            return fail(s, rd->last, 1, "missing key '%s' (required: image_width image_height camera_matrix R (or "
                        "rvec) T (or tvec) near far%s)", yname[k],
                        k == K_NEAR || k == K_FAR ? "; OpenCV files hold no clipping range: add near: and far:, "
                                                    "in scene units" : "");
    }
    if (!rd->fisheye)
        return 0;
    if (!seen[K_DIST])
        return fail(s, seen[Y_DMODEL], 1, "key 'distortion_model' is fisheye, but there is no "
                    "distortion_coefficients (k1 k2 k3 k4)");
    if (keys->ndist != 4)
        return fail(s, seen[K_DIST], 1, "key 'distortion_coefficients': the fisheye model (distortion_model, "
                    "line %u) takes 4 coefficients, k1 k2 k3 k4; got %u", seen[Y_DMODEL], keys->ndist);
    memcpy(keys->val[K_FISHEYE], keys->val[K_DIST], sizeof keys->val[K_DIST]);
    keys->seen[K_FISHEYE] = keys->seen[K_DIST];
    keys->vcol[K_FISHEYE] = keys->vcol[K_DIST];
    memcpy(keys->eline[K_FISHEYE], keys->eline[K_DIST], sizeof keys->eline[K_DIST]);
    memcpy(keys->ecol[K_FISHEYE], keys->ecol[K_DIST], sizeof keys->ecol[K_DIST]);
    keys->seen[K_DIST] = 0;
    return 0;
}

int gls_camera_parse_opencv(const char *text, size_t len, const char *fname, gls_pose use, FILE *notes,
                            gls_camera *cam, char *err, size_t errlen)
{
    src s = {text, fname, len, err, errlen};
    static reading zero;
    reading rd = zero;
    rd.last = 1;
    gls_sensor_keys_init(&rd.sensor);
    rd.m.key = -1;
    gls_text_lines it = {text, len, 0, 0};
    char buf[GLS_TEXT_MAX_LINE + 1];
    size_t n;
    int got;
    while ((got = gls_text_next_line(&it, buf, &n)) != 0)
        if (read_line(&s, &rd, got, buf, n, it.line))
            return -1;
    if ((rd.m.key >= 0 && matrix_end(&s, &rd.m, &rd.keys)) || all_read(&s, &rd))
        return -1;
    /* distortion_model: fisheye makes the coefficients cv::fisheye's */
    const char *names[K_COUNT];
    memcpy(names, yname, sizeof names);
    names[K_FISHEYE] = yname[K_DIST];
    if (rd.seen[Y_TVEC])
        names[K_T] = "tvec";
    if (gls_camera_from_keys(&rd.keys, names, text, len, fname, use, notes, cam, err, errlen))
        return -1;
    cam->sensor = rd.sensor.s;
    return 0;
}
