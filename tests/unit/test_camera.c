/* Camera files and the camera's matrices (runtime/camera/camera.c), CPU only. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "camera.h"
#include "check.h"
#include "rotation.h"
#include "textfile.h"

static const char good[] =
    "# a camera\n"
    "width 640\nheight 480\n"
    "fx 700.5   # pixels\nfy 650.25\ncx 301.3\ncy 257.8\nskew 3.7\n"
    "R 0.36 0.48 -0.8  -0.8 0.6 0  0.48 0.64 0.6\n"
    "T 0.2 -0.1 0.5\nnear 0.1\nfar 1000\n";

static int parse(const char *text, gls_camera *c, char *err)
{
    return gls_camera_parse(text, strlen(text), "x.cam", GLS_POSE_UNDECLARED, NULL, c, err, 512);
}

static void test_parse_good(void)
{
    gls_camera c;
    char err[256] = "";
    CHECK(parse(good, &c, err) == 0);
    CHECK(c.width == 640 && c.height == 480);
    CHECK(c.fx == 700.5 && c.fy == 650.25 && c.cx == 301.3 && c.cy == 257.8 && c.skew == 3.7);
    CHECK(c.R[2] == -0.8 && c.T[1] == -0.1 && c.near == 0.1 && c.far == 1000);
    /* skew is optional */
    char text[1024];
    strcpy(text, good);
    char *s = strstr(text, "skew 3.7\n");
    memmove(s, s + 9, strlen(s + 9) + 1);
    CHECK(parse(text, &c, err) == 0 && c.skew == 0);
}

/* Replace the first occurrence of `from` in good by `to`, parse, and
 * expect an error containing `msg`. */
static void expect_error(const char *from, const char *to, const char *msg)
{
    char text[2048], err[512] = "";
    const char *p = strstr(good, from);
    CHECK_MSG(p != NULL, "test setup: %s not in the good file", from);
    if (!p)
        return;
    size_t k = (size_t)(p - good);
    memcpy(text, good, k);
    strcpy(text + k, to);
    strcat(text, p + strlen(from));
    gls_camera c;
    CHECK_MSG(parse(text, &c, err) == -1, "accepted %s -> %s", from, to);
    CHECK_MSG(strstr(err, msg) != NULL, "message '%s' lacks '%s'", err, msg);
    CHECK_MSG(strncmp(err, "x.cam:", 6) == 0 && strstr(err, ": error: ") != NULL, "bad message form '%s'", err);
    /* three lines: the message, the offending source line, a caret under
       the column the message names */
    const char *nl1 = strchr(err, '\n'), *nl2 = nl1 ? strchr(nl1 + 1, '\n') : NULL;
    CHECK_MSG(nl1 && nl2 && !strchr(nl2 + 1, '\n'), "not message + source line + caret: '%s'", err);
    if (nl1 && nl2) {
        unsigned line = 0, col = 0;
        CHECK(sscanf(err, "x.cam:%u:%u:", &line, &col) == 2);
        const char *caret = strchr(nl2 + 1, '^');
        CHECK_MSG(caret && (unsigned)(caret - nl2) == col && caret[1] == 0, "caret not under column %u: '%s'", col, err);
    }
}

static void test_parse_errors(void)
{
    expect_error("fx 700.5", "", "missing key 'fx'");
    expect_error("fy 650.25", "fy 650.25\nfy 3", "given twice");
    expect_error("fy 650.25", "fyy 650.25", "did you mean 'fy'");
    expect_error("near 0.1", "nera 0.1", "did you mean 'near'");
    expect_error("R 0.36", "r 0.36", "did you mean 'R'");
    expect_error("fx 700.5", "fx nan", "not a finite number");
    expect_error("fx 700.5", "fx inf", "not a finite number");
    expect_error("fx 700.5", "fx 1e999", "'1e999' is too large for a double (magnitudes up to 1.8e308)");
    expect_error("fx 700.5", "fx 1e-308", "'1e-308' is too close to zero for a double (nonzero magnitudes from 2.2e-308)");
    expect_error("fx 700.5", "fx 5e-324", "too close to zero");
    expect_error("fx 700.5", "fx 0x1p-1074", "too close to zero");
    /* commas: the caret on the comma (expect_error checks the column) */
    expect_error("T 0.2 -0.1 0.5", "T 0.2,-0.1,0.5",
                 "x.cam:10:6: error: key 'T': a comma in '0.2,-0.1,0.5': separate numbers with spaces");
    expect_error("T 0.2 -0.1 0.5", "T 0.2, -0.1, 0.5", "x.cam:10:6: error: key 'T': a comma in '0.2,'");
    expect_error("T 0.2 -0.1 0.5", "T 0.2 -0.1 , 0.5", "x.cam:10:12: error: key 'T': a comma in ','");
    expect_error("cx 301.3", "cx 301,3", "x.cam:6:7: error: key 'cx': a comma in '301,3'");
    expect_error("fx 700.5", "fx 7x", "not a finite number");
    expect_error("fx 700.5", "fx 0", "fx must be > 0");
    expect_error("fy 650.25", "fy -1", "fy must be > 0");
    expect_error("width 640", "width 0", "1..16384");
    expect_error("width 640", "width 16385", "1..16384");
    expect_error("height 480", "height 480.5", "whole number");
    expect_error("near 0.1", "near 0", "near must be > 0");
    expect_error("far 1000", "far 0.05", "greater than near");
    expect_error("T 0.2 -0.1 0.5", "T 0.2 -0.1", "takes 3 numbers");
    expect_error("R 0.36 0.48 -0.8", "R 0.36 0.48 -0.81", "not orthonormal");
    /* a reflection: orthonormal, determinant -1 */
    expect_error("R 0.36 0.48 -0.8  -0.8 0.6 0  0.48 0.64 0.6", "R 1 0 0 0 1 0 0 0 -1", "determinant");
    /* error line numbers point at the key */
    char err[256];
    gls_camera c;
    CHECK(parse("width 10\n\n# c\nbogus 1\n", &c, err) == -1 && strncmp(err, "x.cam:4:", 8) == 0);
}

/* Lines over 200 bytes get a window of the line around the column, with
   "..." at the cut ends, and the caret under the column; lines over
   GLS_TEXT_MAX_LINE bytes are refused at the byte where they overflow. */
static void test_long_lines(void)
{
    static char text[8192];
    char err[1024];
    gls_camera c;
    /* the error at column 4 of a 300-byte line: window from the start */
    snprintf(text, sizeof text, "%s", good);
    char *cy = strstr(text, "cy 257.8\n");
    memmove(cy + 300, cy + 8, strlen(cy + 8) + 1);
    memcpy(cy, "cy 2x7.8 #", 10);
    memset(cy + 10, 'c', 290);
    CHECK(parse(text, &c, err) == -1);
    const char *nl = strchr(err, '\n');
    CHECK_MSG(nl && strncmp(nl + 1, "cy 2x7.8 #ccc", 13) == 0 && strstr(nl + 1, "c...\n   ^") != NULL &&
                  strlen(strstr(nl + 1, "...\n")) == 8,
              "'%s'", err);
    /* the error at column 258 of a 400-byte line: a window around it */
    snprintf(text, sizeof text, "%s", good);
    char *t = strstr(text, "T 0.2 -0.1 0.5\n");
    memmove(t + 400, t + 14, strlen(t + 14) + 1);
    memset(t, ' ', 400);
    memcpy(t, "T 0 0", 5);
    memcpy(t + 257, "q  # end", 8);
    CHECK(parse(text, &c, err) == -1);
    CHECK_MSG(strstr(err, ":10:258: error: key 'T': 'q' is not a finite number\n...") != NULL, "'%s'", err);
    nl = strchr(err, '\n');
    const char *caret = nl ? strchr(nl + 1, '\n') : NULL;
    /* "..." then bytes 177.. of the line: q (byte 257) is at offset 83 */
    CHECK_MSG(caret && strncmp(nl + 1 + 3 + 80, "q  # end", 8) == 0 && strcmp(caret + 1 + 83, "^") == 0 &&
                  strspn(caret + 1, " ") == 83,
              "'%s'", err);
    /* a line over the limit (6000 bytes) */
    snprintf(text, sizeof text, "width 640\n# %0*d\n", 5998, 0);
    CHECK(parse(text, &c, err) == -1);
    CHECK_MSG(strncmp(err, "x.cam:2:4096: error: line longer than 4095 bytes\n...000", 55) == 0, "'%s'", err);
    nl = strchr(strchr(err, '\n') + 1, '\n');
    CHECK_MSG(nl && strspn(nl + 1, " ") == 83 && strcmp(nl + 1 + 83, "^") == 0 && strstr(err, "000...\n"), "'%s'", err);
    /* at the limit: a line of exactly GLS_TEXT_MAX_LINE bytes is read */
    snprintf(text, sizeof text, "%s# %0*d\n", good, (int)GLS_TEXT_MAX_LINE - 2, 0);
    CHECK_MSG(parse(text, &c, err) == 0, "'%s'", err);
}

/* R printed with 5 decimals: accepted with a note, re-orthonormalised;
   with 3 decimals: refused.  A full-precision R is used as given. */
static void test_rotation_tolerance(void)
{
    char text[2048], err[512] = "", *notes = NULL;
    size_t nlen = 0;
    gls_camera c;
    /* a rotation about (1, 1, 1) by 0.5 rad, rounded to 5 decimals */
    snprintf(text, sizeof text, "%s", good);
    char *r = strstr(text, "R 0.36");
    const char *R5 = "R 0.91839 -0.23599 0.3176  0.3176 0.91839 -0.23599  -0.23599 0.3176 0.91839";
    memmove(r + strlen(R5), strchr(r, '\n'), strlen(strchr(r, '\n')) + 1);
    memcpy(r, R5, strlen(R5));
    FILE *nf = open_memstream(&notes, &nlen);
    CHECK_MSG(gls_camera_parse(text, strlen(text), "x.cam", GLS_POSE_UNDECLARED, nf, &c, err, sizeof err) == 0, "%s", err);
    fclose(nf);
    CHECK_MSG(notes && strncmp(notes, "x.cam:9:3: note: R is orthonormal only within ", 46) == 0 &&
                  strstr(notes, "replaced by the nearest rotation, which moves no entry by more than") && strchr(notes, '\n') == notes + nlen - 1,
              "'%s'", notes ? notes : "");
    free(notes);
    double worst = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            worst = fmax(worst, fabs(c.R[3 * i] * c.R[3 * j] + c.R[3 * i + 1] * c.R[3 * j + 1] +
                                     c.R[3 * i + 2] * c.R[3 * j + 2] - (i == j)));
    CHECK_MSG(worst < 1e-15, "R R^T - I up to %g", worst);
    CHECK_NEAR(c.R[0], 0.91838837, 1e-5);
    /* the same with 3 decimals */
    expect_error("R 0.36 0.48 -0.8  -0.8 0.6 0  0.48 0.64 0.6", "R 0.918 -0.236 0.318  0.318 0.918 -0.236  -0.236 0.318 0.918",
                 "must be 1 within 1e-4");
    /* full precision: as given, no note */
    notes = NULL;
    nf = open_memstream(&notes, &nlen);
    CHECK(gls_camera_parse(good, strlen(good), "x.cam", GLS_POSE_UNDECLARED, nf, &c, err, sizeof err) == 0);
    fclose(nf);
    CHECK(nlen == 0 && c.R[0] == 0.36 && c.R[8] == 0.6);
    free(notes);
}

/* spec/camera.md "Depth range": near is refused where the float
   coefficients a = n/(f-n), b = n f/(f-n) fall below 2^-102 or b exceeds
   FLT_MAX; at the limit every point closer than far by more than one float
   step (2^-24 relative) still gets a normal (not subnormal) float depth. */
static void test_depth_range(void)
{
    double lo, hi;
    CHECK(gls_camera_depth_range(0.1, 1000, &lo, &hi) == 0);
    CHECK(gls_camera_depth_range(1e-37, 1000, &lo, &hi) == -1);
    CHECK_NEAR(lo, 0x1p-102 * 1000, 1e-40);
    CHECK(gls_camera_depth_range(lo * (1 + 1e-9), 1000, &lo, &hi) == 0);
    CHECK(gls_camera_depth_range(lo * (1 - 1e-9), 1000, &lo, &hi) == -1);
    CHECK(gls_camera_depth_range(1, 1e31, &lo, &hi) == -1);      /* far/near > 2^102 */
    CHECK(gls_camera_depth_range(1e-31, 1e-30, &lo, &hi) == -1); /* b < 2^-102 */
    CHECK(gls_camera_depth_range(1e30, 1e38, &lo, &hi) == 0);
    CHECK(gls_camera_depth_range(1e39, 2e39, &lo, &hi) == -1);   /* b > FLT_MAX */
    CHECK(hi < 3.4e38 && gls_camera_depth_range(hi * (1 - 1e-9), 2e39, &lo, &hi) == 0);
    /* the derivation: clip-space z = b - a Zc = a (f - Zc) and depth
       d = z / Zc, with a as the float GL gets, at Zc one float step before
       far, are normal floats at the limit; below it one of them is
       subnormal (z ~ a f 2^-24 = b 2^-24 tests b, d ~ a 2^-24 tests a) */
    static const double fars[] = {1e-20, 1, 1000, 1e20};
    for (int k = 0; k < 4; k++) {
        double f = fars[k];
        gls_camera_depth_range(1, f, &lo, &hi);
        for (int below = 0; below < 2; below++) {
            double n = below ? lo / 4 : lo * 1.000001;
            float a = (float)(n / (f - n));
            double Zc = f * (1 - 0x1p-24);
            double z = (double)a * (f - Zc), d = fmin(z, z / Zc);
            CHECK_MSG(below ? d < FLT_MIN : d >= FLT_MIN, "far %g near %g: z or depth %g one step before far", f, n, d);
        }
    }
    expect_error("near 0.1", "near 1e-37",
                 "x.cam:11:6: error: near 1e-37 is too small for far 1000: the float depth buffer would lose precision; "
                 "near must be at least 1.99e-28 (spec/camera.md, Depth range)");
}

/* 'pose world' / 'pose rig': recorded, checked against the use; an
   undeclared file used relative to the rig gets a note. */
static void test_pose_frame(void)
{
    static const struct {
        const char *line;
        gls_pose use;
        int ok;
        gls_pose pose;
        const char *msg;
    } cases[] = {
        {"", GLS_POSE_WORLD, 1, GLS_POSE_UNDECLARED, ""},
        {"", GLS_POSE_RIG, 1, GLS_POSE_UNDECLARED, "x.cam: note: no 'pose' key: R and T are taken relative to the rig"},
        {"pose world\n", GLS_POSE_WORLD, 1, GLS_POSE_WORLD, ""},
        {"pose rig  # rig\n", GLS_POSE_RIG, 1, GLS_POSE_RIG, ""},
        {"pose world\n", GLS_POSE_UNDECLARED, 1, GLS_POSE_WORLD, ""},
        {"pose world\n", GLS_POSE_RIG, 0, 0, "x.cam:13:6: error: 'pose world': R and T are declared the camera's pose"},
        {"  pose rig\n", GLS_POSE_WORLD, 0, 0, "x.cam:13:8: error: 'pose rig': R and T are declared relative to the rig"},
        {"pose Rig\n", GLS_POSE_RIG, 0, 0, "x.cam:13:6: error: key 'pose': 'Rig' is neither world"},
        {"pose\n", GLS_POSE_RIG, 0, 0, "x.cam:13:1: error: key 'pose' takes one word, world or rig, got 0"},
        {"pose rig\npose rig\n", GLS_POSE_RIG, 0, 0, "x.cam:14:1: error: key 'pose' given twice (first on line 13)"},
        {"poes rig\n", GLS_POSE_RIG, 0, 0, "x.cam:13:1: error: unknown key 'poes' (did you mean 'pose'?)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[2048], err[512] = "", *notes = NULL;
        size_t nlen = 0;
        snprintf(text, sizeof text, "%s%s", good, cases[i].line);
        FILE *nf = open_memstream(&notes, &nlen);
        gls_camera c;
        int r = gls_camera_parse(text, strlen(text), "x.cam", cases[i].use, nf, &c, err, sizeof err);
        fclose(nf);
        const char *got = cases[i].ok ? notes : err;
        CHECK_MSG(r == (cases[i].ok ? 0 : -1) && strncmp(got, cases[i].msg, strlen(cases[i].msg)) == 0 &&
                      (cases[i].msg[0] || !got[0]) && (!cases[i].ok || c.pose == cases[i].pose),
                  "case %zu: r %d, '%s'", i, r, got);
        free(notes);
    }
}

static void test_load_missing_file(void)
{
    gls_camera c;
    char err[256];
    CHECK(gls_camera_load("/nonexistent/dir/a.cam", GLS_POSE_UNDECLARED, NULL, &c, err, sizeof err) == -1);
    CHECK(strstr(err, "/nonexistent/dir/a.cam: error: cannot open") == err);
}

/* P * MV applied to a world point, then GL's viewport transform in double:
 * window x, y must be u + 0.5, v + 0.5 and depth must invert to Zc. */
static void test_matrices_map_to_pixels(void)
{
    gls_camera c;
    char err[256];
    CHECK(parse(good, &c, err) == 0);
    const double pts[3][3] = {{0.3, -0.2, 6}, {-2, 1, 40}, {5, 3, 900}};
    for (int k = 0; k < 3; k++) {
        double anchor[3] = {pts[k][0] - 0.25, pts[k][1] + 0.5, pts[k][2] - 1}; /* any anchor */
        double off[4] = {pts[k][0] - anchor[0], pts[k][1] - anchor[1], pts[k][2] - anchor[2], 1};
        double MV[16], P[16], e[4], cl[4];
        gls_camera_modelview(&c, anchor, MV);
        gls_camera_projection(&c, 0, 0, P);
        for (int i = 0; i < 4; i++)
            e[i] = MV[4 * i] * off[0] + MV[4 * i + 1] * off[1] + MV[4 * i + 2] * off[2] + MV[4 * i + 3] * off[3];
        for (int i = 0; i < 4; i++)
            cl[i] = P[4 * i] * e[0] + P[4 * i + 1] * e[1] + P[4 * i + 2] * e[2] + P[4 * i + 3] * e[3];
        double xw = (cl[0] / cl[3] + 1) * c.width / 2, yw = (cl[1] / cl[3] + 1) * c.height / 2, d = cl[2] / cl[3];
        /* reference projection, written out here */
        double X = c.R[0] * pts[k][0] + c.R[1] * pts[k][1] + c.R[2] * pts[k][2] + c.T[0];
        double Y = c.R[3] * pts[k][0] + c.R[4] * pts[k][1] + c.R[5] * pts[k][2] + c.T[1];
        double Z = c.R[6] * pts[k][0] + c.R[7] * pts[k][1] + c.R[8] * pts[k][2] + c.T[2];
        double u = (c.fx * X + c.skew * Y) / Z + c.cx, v = c.fy * Y / Z + c.cy;
        CHECK_NEAR(xw, u + 0.5, 1e-9);
        CHECK_NEAR(yw, v + 0.5, 1e-9);
        CHECK(d > 0 && d < 1);
        CHECK_NEAR(gls_camera_depth_to_z(&c, d) / Z, 1, 1e-12);
        /* unproject(project) is the identity */
        double uu, vv, Pc[3], W[3];
        double Zc = gls_camera_project(&c, pts[k], &uu, &vv);
        CHECK_NEAR(uu, u, 1e-9);
        CHECK_NEAR(vv, v, 1e-9);
        gls_camera_unproject(&c, uu, vv, Zc, Pc);
        gls_camera_to_world(&c, Pc, W);
        for (int j = 0; j < 3; j++)
            CHECK_NEAR(W[j], pts[k][j], 1e-9 * (1 + fabs(pts[k][j])));
    }
    /* near -> depth 1, far -> depth 0 */
    CHECK_NEAR(gls_camera_depth_to_z(&c, 1.0), c.near, 1e-15);
    CHECK_NEAR(gls_camera_depth_to_z(&c, 0.0 + 1e-300), c.far, 1e-6);
    CHECK(isinf(gls_camera_depth_to_z(&c, 0.0)));
    /* a jitter shifts the principal point: window x grows by du */
    double P0[16], P1[16];
    gls_camera_projection(&c, 0, 0, P0);
    gls_camera_projection(&c, 0.25, -0.5, P1);
    /* x_ndc = P[0]x + P[1]y + P[2]z over -z: dP[2] = -2 du / W */
    CHECK_NEAR(P1[2] - P0[2], -2 * 0.25 / c.width, 1e-15);
    CHECK_NEAR(P1[6] - P0[6], 2 * 0.5 / c.height, 1e-15);
}

/* The K and rvec keys (spec/camera.md "File format") and the OpenCV YAML
 * form ("OpenCV camera files") give the same camera as fx..skew and R. */
static void test_k_rvec_yaml(void)
{
    gls_camera a, b, y;
    char err[512] = "";
    CHECK(parse(good, &a, err) == 0);
    static const char kfile[] = "width 640\nheight 480\nK 700.5 3.7 301.3  0 650.25 257.8  0 0 1\n"
                                "R 0.36 0.48 -0.8  -0.8 0.6 0  0.48 0.64 0.6\nT 0.2 -0.1 0.5\nnear 0.1\nfar 1000\n";
    CHECK_MSG(parse(kfile, &b, err) == 0, "%s", err);
    CHECK(memcmp(&a, &b, sizeof a) == 0);
    static const char yfile[] =
        "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n"
        "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
        "   data: [ 7.0050000000000000e+02, 3.7000000000000002e+00, 301.3, 0.,\n       650.25, 257.8, 0., 0., 1. ]\n"
        "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n   data: [ 0., 0., 0., 0., 0. ]\n"
        "R: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ 0.36, 0.48, -0.8, -0.8, 0.6, 0., 0.48, 0.64, 0.6 ]\n"
        "T: !!opencv-matrix\n   rows: 3\n   cols: 1\n   dt: d\n   data: [ 0.2, -0.1, 0.5 ]\nnear: 0.1\nfar: 1000.\n";
    CHECK_MSG(parse(yfile, &y, err) == 0, "%s", err);
    CHECK(memcmp(&a, &y, sizeof a) == 0);
    /* rvec: a quarter turn about z, and the zero vector */
    static const char rfile[] = "width 640\nheight 480\nK 700 0 320  0 700 240  0 0 1\n"
                                "rvec 0 0 1.5707963267948966\nT 0 0 0\nnear 0.1\nfar 1000\n";
    CHECK_MSG(parse(rfile, &b, err) == 0, "%s", err);
    const double Rz[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    for (int i = 0; i < 9; i++)
        CHECK_NEAR(b.R[i], Rz[i], 1e-16);
    double R0[9], r0[3] = {0, 0, 0};
    gls_rotation_rodrigues(r0, R0);
    CHECK(R0[0] == 1 && R0[4] == 1 && R0[8] == 1 && R0[1] == 0 && R0[5] == 0);
}

/* distortion and fisheye keys, .cam and OpenCV YAML (spec/camera.md
 * "Lens distortion"); zero coefficients are no distortion at all */
static void test_lens_keys(void)
{
    static const char base[] = "width 640\nheight 480\nfx 500\nfy 500\ncx 319.5\ncy 239.5\n"
                               "R 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n";
    char text[1024], err[512] = "";
    gls_camera pin, c;
    CHECK_MSG(parse(base, &pin, err) == 0, "%s", err);
    CHECK(pin.dist.model == GLS_LENS_NONE);
    snprintf(text, sizeof text, "%sdistortion -0.3 0.08 0.0012 -0.0008\n", base);
    CHECK_MSG(parse(text, &c, err) == 0, "%s", err);
    CHECK(c.dist.model == GLS_LENS_BROWN && c.dist.n == 4 && c.dist.k[0] == -0.3 && c.dist.k[3] == -0.0008 &&
          c.dist.k[4] == 0);
    snprintf(text, sizeof text, "%sdistortion 0.1 0 0 0 0 0.2 0 0.01\n", base);
    CHECK_MSG(parse(text, &c, err) == 0, "%s", err);
    CHECK(c.dist.model == GLS_LENS_BROWN && c.dist.n == 8 && c.dist.k[5] == 0.2 && c.dist.k[7] == 0.01);
    snprintf(text, sizeof text, "%sfisheye 0.05 -0.01 0.002 -0.0004\n", base);
    CHECK_MSG(parse(text, &c, err) == 0, "%s", err);
    CHECK(c.dist.model == GLS_LENS_FISHEYE && c.dist.n == 4 && c.dist.k[2] == 0.002);
    snprintf(text, sizeof text, "%sdistortion 0 0 0 0 0\n", base);
    CHECK_MSG(parse(text, &c, err) == 0, "%s", err);
    CHECK(memcmp(&c, &pin, sizeof c) == 0);
    static const char yfile[] =
        "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n"
        "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
        "   data: [ 500., 0., 319.5, 0., 500., 239.5, 0., 0., 1. ]\n"
        "distortion_coefficients: !!opencv-matrix\n   rows: 4\n   cols: 1\n   dt: d\n"
        "   data: [ 0.05, -0.01, 0.002, -0.0004 ]\n"
        "R: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ 1., 0., 0., 0., 1., 0., 0., 0., 1. ]\n"
        "T: !!opencv-matrix\n   rows: 3\n   cols: 1\n   dt: d\n   data: [ 0., 0., 0. ]\nnear: 0.1\nfar: 100.\n"
        "distortion_model: fisheye\n";
    gls_camera y;
    CHECK_MSG(parse(yfile, &y, err) == 0, "%s", err);
    CHECK(memcmp(&c, &y, sizeof c) != 0 && y.dist.model == GLS_LENS_FISHEYE);
    snprintf(text, sizeof text, "%sfisheye 0.05 -0.01 0.002 -0.0004\n", base);
    CHECK(parse(text, &c, err) == 0 && memcmp(&c, &y, sizeof c) == 0);
}

int main(void)
{
    RUN(test_lens_keys);
    RUN(test_k_rvec_yaml);
    RUN(test_parse_good);
    RUN(test_parse_errors);
    RUN(test_long_lines);
    RUN(test_rotation_tolerance);
    RUN(test_depth_range);
    RUN(test_pose_frame);
    RUN(test_load_missing_file);
    RUN(test_matrices_map_to_pixels);
    CHECK_EXIT();
}
