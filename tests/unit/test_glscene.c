/* libglscene's C API (include/glscene.h, docs/api.md), through the
 * public header only: compile a small scene, render it, check depth
 * against the camera model, instance ids and their paths, a moved named
 * instance, anti-aliasing, and that errors come back as messages. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "check.h"
#include "glscene.h"

/* A wall at z = 10 and a 1 x 1 red tile "mover" at z = 5 in front of it;
 * the camera at the origin looks along +z (R = I: world = camera frame). */
static char dir[64], bundle[128];
enum { W = 64, H = 48 };
static const double FX = 50, CX = 31.5, CY = 23.5;

static void write_file(const char *rel, const char *text)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f)) {
        printf("FAIL test_glscene: cannot write %s\n", path);
        exit(1);
    }
}

static void make_scene(void)
{
    snprintf(dir, sizeof dir, "/tmp/test_glscene.XXXXXX");
    if (!mkdtemp(dir)) {
        printf("FAIL test_glscene: mkdtemp\n");
        exit(1);
    }
    char sub[128];
    snprintf(sub, sizeof sub, "%s/parts", dir);
    if (mkdir(sub, 0755)) {
        printf("FAIL test_glscene: mkdir %s\n", sub);
        exit(1);
    }
    write_file("Wall.scene", "color(0.5, 0.5, 0.5);\n"
                             "poly { vert(-100, -100, 10); vert(100, -100, 10); vert(100, 100, 10); "
                             "vert(-100, 100, 10); }\n"
                             "push; trans(0, 0, 5); call(\"parts.Tile\", \"mover\"); pop;\n");
    write_file("parts/Tile.scene", "color(1, 0, 0);\n"
                                   "poly { vert(-0.5, -0.5, 0); vert(0.5, -0.5, 0); vert(0.5, 0.5, 0); "
                                   "vert(-0.5, 0.5, 0); }\n");
    write_file("Bad.scene", "color(1, 0, 0;\n");
    snprintf(bundle, sizeof bundle, "%s/out/wall.glsb", dir);
}

static int camera(glscene_camera *c)
{
    glscene_error e;
    return glscene_camera_set(c, W, H, FX, FX, CX, CY, 0, NULL, NULL, 0.1, 100, &e);
}

/* The wall's player with the default options, and the camera. */
static glscene_player *open_wall(glscene_camera *c)
{
    glscene_error e;
    glscene_player *p = glscene_open(bundle, NULL, &e);
    CHECK_MSG(p != NULL, "%s", e.message);
    CHECK(camera(c) == 0);
    return p;
}

static void test_glscene_compile(void)
{
    glscene_error e;
    const char *roots[] = {dir};
    CHECK(glscene_compile("Wall", roots, 1, bundle, &e) == 0);
    CHECK(access(bundle, R_OK) == 0);
    char out2[160];
    snprintf(out2, sizeof out2, "%s/bad.glsb", dir);
    CHECK(glscene_compile("Bad", roots, 1, out2, &e) == -1);
    char want[512];
    snprintf(want, sizeof want, "%s/Bad.scene:1:", dir);
    CHECK_MSG(strncmp(e.message, want, strlen(want)) == 0 && strstr(e.message, ": error: "), "%s", e.message);
    CHECK(access(out2, F_OK) != 0);
    CHECK_STR(glscene_version(), GLSCENE_VERSION);
}

static void test_glscene_render_depth_ids(void)
{
    glscene_error e;
    glscene_camera c;
    glscene_player *p = open_wall(&c);
    if (!p)
        return;
    static float z[W * H], nrm[W * H * 3];
    static uint32_t id[W * H];
    static uint8_t rgb[W * H * 3];
    glscene_buffers b = {rgb, NULL, z, id, nrm};
    CHECK_MSG(glscene_render(p, &c, &b, &e) == 0, "%s", e.message);
    /* the wall's Zc is 10 at every pixel it shows, to float precision */
    CHECK_NEAR(z[0], 10.0, 10.0 * 2e-7);
    CHECK_NEAR(z[W * H - 1], 10.0, 10.0 * 2e-7);
    /* the tile covers |u - cx|, |v - cy| < 5 px: Zc 5 at the centre */
    size_t mid = (size_t)24 * W + 32;
    CHECK_NEAR(z[mid], 5.0, 5.0 * 2e-7);
    CHECK(rgb[3 * mid] == 255 && rgb[3 * mid + 1] == 0 && rgb[3 * mid + 2] == 0);
    CHECK(rgb[0] == 128 && rgb[1] == 128 && rgb[2] == 128);
    /* ids: the wall (the top) and the tile, with their call paths */
    CHECK(glscene_instance_count(p) == 2);
    CHECK(id[0] != 0 && id[mid] != 0 && id[0] != id[mid]);
    CHECK_STR(glscene_instance_path(p, id[mid]), "Wall > parts.Tile#1");
    CHECK_STR(glscene_instance_path(p, id[0]), "Wall");
    CHECK(glscene_instance_path(p, 0) == NULL && glscene_instance_path(p, 3) == NULL);
    /* normals face the camera: 0 0 -1 */
    CHECK_NEAR(nrm[3 * mid + 2], -1.0, 1e-6);
    glscene_close(p);
}

static void test_glscene_move(void)
{
    glscene_error e;
    glscene_camera c;
    glscene_player *p = open_wall(&c);
    if (!p)
        return;
    static float z[W * H];
    glscene_buffers b = {NULL, NULL, z, NULL, NULL};
    size_t mid = (size_t)24 * W + 32;
    /* 3 further away: Zc 8, the tile 6.25 px wide: u 31.5 +- 3.125 */
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, T[3] = {0, 0, 3};
    CHECK_MSG(glscene_move_instance(p, "mover", I, T, &e) == 0, "%s", e.message);
    CHECK(glscene_render(p, &c, &b, &e) == 0);
    CHECK_NEAR(z[mid + 2], 8.0, 8.0 * 2e-7);
    CHECK_NEAR(z[mid + 4], 10.0, 10.0 * 2e-7);
    /* back to the identity */
    CHECK(glscene_move_instance(p, "mover", NULL, NULL, &e) == 0);
    CHECK(glscene_render(p, &c, &b, &e) == 0);
    CHECK_NEAR(z[mid + 4], 5.0, 5.0 * 2e-7);
    CHECK(glscene_move_instance(p, "mvoer", I, T, &e) == -1);
    CHECK_STR(e.message, "the scene has no instance named 'mvoer'");
    const double bad[9] = {1, 0, 0, 0, 2, 0, 0, 0, 1};
    CHECK(glscene_move_instance(p, "mover", bad, T, &e) == -1);
    CHECK_MSG(strncmp(e.message, "move mover: R: ", 15) == 0, "%s", e.message);
    glscene_close(p);
}

/* --aa 4: the image anti-aliased, depth still the centre sample's */
static void test_glscene_aa(void)
{
    glscene_error e;
    glscene_options o = {GLSCENE_BACKEND_AUTO, 4, GLSCENE_AA_LATTICE, 0, {0, 0, 0}};
    glscene_player *p = glscene_open(bundle, &o, &e), *q = glscene_open(bundle, NULL, &e);
    CHECK(p && q);
    if (!p || !q) {
        glscene_close(p);
        glscene_close(q);
        return;
    }
    /* cx off the half pixel: the tile's edges cross pixels */
    glscene_camera c;
    CHECK(glscene_camera_set(&c, W, H, FX, FX, CX - 0.3, CY - 0.3, 0, NULL, NULL, 0.1, 100, &e) == 0);
    static uint8_t a[W * H * 3], s[W * H * 3];
    static float za[W * H], zs[W * H], fa[W * H * 3];
    glscene_buffers ba = {a, fa, za, NULL, NULL}, bs = {s, NULL, zs, NULL, NULL};
    CHECK(glscene_render(p, &c, &ba, &e) == 0 && glscene_render(q, &c, &bs, &e) == 0);
    CHECK(memcmp(za, zs, sizeof za) == 0);
    /* inside the tile the same colour; at its edges mixed ones */
    size_t mid = (size_t)24 * W + 32;
    CHECK(memcmp(a + 3 * mid, s + 3 * mid, 3) == 0);
    int mixed = 0;
    for (size_t i = 0; i < (size_t)W * H * 3; i++)
        mixed += a[i] != s[i];
    CHECK(mixed > 0);
    CHECK_NEAR(fa[3 * mid], 1.0, 1e-6);
    glscene_close(p);
    glscene_close(q);
}

/* aa GLSCENE_AA_EXACT: the image is exact coverage (glsplay --aa exact):
 * the tile (x and y from -0.5 to 0.5 at z 5: 10 px a side) with the
 * principal point 0.3 px off, so its sides lie 0.3 px into their pixels;
 * each pixel's red share is the product of its two overlaps, the rest the
 * wall's grey; rgb8 is rgbf rounded.  Depth stays the centre pass's. */
static void test_glscene_exact(void)
{
    glscene_error e;
    glscene_options o = {GLSCENE_BACKEND_AUTO, GLSCENE_AA_EXACT, GLSCENE_AA_LATTICE, 0, {0, 0, 0}};
    glscene_player *p = glscene_open(bundle, &o, &e), *q = glscene_open(bundle, NULL, &e);
    CHECK_MSG(p && q, "%s", e.message);
    if (!p || !q) {
        glscene_close(p);
        glscene_close(q);
        return;
    }
    glscene_camera c;
    const double cx = CX - 0.3, cy = CY - 0.3;
    CHECK(glscene_camera_set(&c, W, H, FX, FX, cx, cy, 0, NULL, NULL, 0.1, 100, &e) == 0);
    static uint8_t a[W * H * 3];
    static float za[W * H], zs[W * H], fa[W * H * 3];
    glscene_buffers ba = {a, fa, za, NULL, NULL}, bs = {NULL, NULL, zs, NULL, NULL};
    CHECK(glscene_render(p, &c, &ba, &e) == 0 && glscene_render(q, &c, &bs, &e) == 0);
    CHECK(memcmp(za, zs, sizeof za) == 0);
    double worst = 0, half = 0.5 * FX / 5;
    int rounded = 1;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double ox = fmin(i + 0.5, cx + half) - fmax(i - 0.5, cx - half);
            double oy = fmin(j + 0.5, cy + half) - fmax(j - 0.5, cy - half);
            double red = (ox > 0 ? ox : 0) * (oy > 0 ? oy : 0);
            const float *f = fa + 3 * ((size_t)j * W + i);
            double g = 128 / 255.0; /* the wall's 0.5 as the scene stores it, 8 bits */
            double want[3] = {red + (1 - red) * g, (1 - red) * g, (1 - red) * g};
            for (int k = 0; k < 3; k++) {
                worst = fmax(worst, fabs(f[k] - want[k]));
                rounded &= a[3 * ((size_t)j * W + i) + k] == (uint8_t)floor(f[k] * 255 + 0.5);
            }
        }
    CHECK_MSG(worst < 1e-6, "worst %g", worst);
    CHECK(rounded);
    glscene_close(p);
    glscene_close(q);
    /* a lit, textured scene: the exact pass shades it on the CPU from the
     * bundle's textures, which the player keeps for it; within 0.02 of
     * 4,096 lattice samples (glsplay's own figure on such a scene is
     * 3.6e-3 against 65,536, spec/antialiasing.md) */
    static const unsigned char png[] = { /* 4x4 RGB, random colours */
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
        0x00, 0x04, 0x00, 0x00, 0x00, 0x04, 0x08, 0x02, 0x00, 0x00, 0x00, 0x26, 0x93, 0x09, 0x29, 0x00, 0x00, 0x00,
        0x3f, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x01, 0x34, 0x00, 0xcb, 0xff, 0x00, 0x79, 0x42, 0xbd, 0xf2, 0x21,
        0x06, 0xf0, 0x84, 0x77, 0x62, 0xf0, 0xf3, 0x00, 0xcb, 0x4d, 0x76, 0x4d, 0xc7, 0x07, 0x20, 0x51, 0x15, 0x9a,
        0x0f, 0x89, 0x00, 0xf2, 0xc6, 0xda, 0xca, 0xe3, 0x44, 0xbb, 0x31, 0x12, 0x45, 0xfd, 0x6f, 0x00, 0x84, 0xdf,
        0x9a, 0xd7, 0xc5, 0xb3, 0xd0, 0x76, 0xac, 0x0e, 0x8f, 0x53, 0x87, 0x8a, 0x19, 0x83, 0xec, 0x8e, 0x7b, 0x86,
        0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    char path[256];
    snprintf(path, sizeof path, "%s/tx", dir);
    CHECK(mkdir(path, 0755) == 0);
    snprintf(path, sizeof path, "%s/tx/Check.png", dir);
    FILE *f = fopen(path, "wb");
    CHECK(f && fwrite(png, 1, sizeof png, f) == sizeof png && fclose(f) == 0);
    const char *lit_tex = "ambient(0.2, 0.2, 0.2);\nlight(point, 0.3, -0.4, 3, 1, 1, 1, 0.02);\n"
                          "color(1, 0.8, 0.6);\ntexture(\"tx.Check\");\ntexmode(modulate);\n"
                          "poly { tex(0, 0); vert(-1.25, -0.5, 3.75); tex(2, 0); vert(0.75, -0.75, 5.75); "
                          "tex(2, 2); vert(1.0, 1.25, 6); tex(0, 2); vert(-1.0, 1.5, 4); }\n";
    write_file("LitTex.scene", lit_tex);
    const char *roots[] = {dir};
    char lit[160];
    snprintf(lit, sizeof lit, "%s/out/lit.glsb", dir);
    CHECK_MSG(glscene_compile("LitTex", roots, 1, lit, &e) == 0, "%s", e.message);
    glscene_options o64 = {GLSCENE_BACKEND_AUTO, 64, GLSCENE_AA_LATTICE, 0, {0, 0, 0}};
    p = glscene_open(lit, &o, &e);
    CHECK_MSG(p, "%s", e.message);
    q = glscene_open(lit, &o64, &e);
    CHECK_MSG(q, "%s", e.message);
    if (p && q) {
        static float fe[W * H * 3], fs[W * H * 3];
        glscene_buffers be = {NULL, fe, NULL, NULL, NULL}, bsm = {NULL, fs, NULL, NULL, NULL};
        CHECK_MSG(glscene_render(p, &c, &be, &e) == 0, "%s", e.message);
        CHECK_MSG(glscene_render(q, &c, &bsm, &e) == 0, "%s", e.message);
        double d = 0, lo = 1, hi = 0;
        for (size_t k = 0; k < sizeof fe / sizeof *fe; k++) {
            d = fmax(d, fabs(fe[k] - fs[k]));
            if (fe[k] > 0)
                lo = fmin(lo, fe[k]), hi = fmax(hi, fe[k]);
        }
        CHECK_MSG(d < 0.02, "exact against 4,096 samples: %g", d);
        CHECK_MSG(hi - lo > 0.2, "the texture and the light vary the colour: %g..%g", lo, hi);
    }
    glscene_close(p);
    glscene_close(q);
    /* shadows: refused at open, saying what to do */
    write_file("Shadow.scene", "shadows(256);\nlight(directional, 0, 0, -1, 1, 1, 1);\n"
                               "poly { vert(-1, -1, 5); vert(1, -1, 5); vert(0, 1, 5); }\n");
    char shadow[160];
    snprintf(shadow, sizeof shadow, "%s/out/shadow.glsb", dir);
    CHECK_MSG(glscene_compile("Shadow", roots, 1, shadow, &e) == 0, "%s", e.message);
    CHECK(glscene_open(shadow, &o, &e) == NULL);
    CHECK_MSG(strstr(e.message, "exact coverage (aa GLSCENE_AA_EXACT) does not draw shadows") &&
                  strstr(e.message, "ask for samples"),
              "%s", e.message);
    /* the default (aa 0, glsplay's --aa auto): exact coverage's image, the
     * same floats, for the square; one sample a pixel's for the scene with
     * shadows, which exact coverage cannot draw */
    glscene_options o1 = {GLSCENE_BACKEND_AUTO, 1, GLSCENE_AA_LATTICE, 0, {0, 0, 0}};
    const char *paths[2] = {bundle, shadow};
    for (int k = 0; k < 2; k++) {
        glscene_player *d = glscene_open(paths[k], NULL, &e);
        CHECK_MSG(d, "%s", e.message);
        p = glscene_open(paths[k], k == 0 ? &o : &o1, &e);
        CHECK_MSG(p, "%s", e.message);
        q = glscene_open(paths[k], k == 0 ? &o1 : &o, &e); /* the other: differs, or refused */
        if (d && p) {
            static float fd[W * H * 3], fp[W * H * 3], fq[W * H * 3];
            glscene_buffers bd = {NULL, fd, NULL, NULL, NULL}, bp = {NULL, fp, NULL, NULL, NULL},
                            bq = {NULL, fq, NULL, NULL, NULL};
            CHECK_MSG(glscene_render(d, &c, &bd, &e) == 0 && glscene_render(p, &c, &bp, &e) == 0, "%s", e.message);
            CHECK_MSG(memcmp(fd, fp, sizeof fd) == 0, "the default is not %s", k == 0 ? "exact" : "one sample");
            if (k == 0)
                CHECK(q && glscene_render(q, &c, &bq, &e) == 0 && memcmp(fd, fq, sizeof fd) != 0);
            else
                CHECK(q == NULL);
        }
        glscene_close(d);
        glscene_close(p);
        glscene_close(q);
    }
}

static void test_glscene_errors(void)
{
    glscene_error e;
    glscene_camera c;
    CHECK(glscene_camera_set(&c, W, H, 0, FX, CX, CY, 0, NULL, NULL, 0.1, 100, &e) == -1);
    CHECK_STR(e.message, "camera: fx must be > 0 (focal length in pixels)");
    CHECK(glscene_camera_set(&c, 0, H, FX, FX, CX, CY, 0, NULL, NULL, 0.1, 100, &e) == -1);
    CHECK_STR(e.message, "camera: width 0 must be a whole number in 1..16384");
    CHECK(glscene_camera_set(&c, W, H, FX, FX, CX, CY, 0, NULL, NULL, 1, 0.5, &e) == -1);
    CHECK_STR(e.message, "camera: far (0.5) must be greater than near (1)");
    const double R[9] = {0, 1, 0, 1, 0, 0, 0, 0, 1}; /* a reflection */
    CHECK(glscene_camera_set(&c, W, H, FX, FX, CX, CY, 0, R, NULL, 0.1, 100, &e) == -1);
    CHECK_MSG(strncmp(e.message, "camera: R: ", 11) == 0, "%s", e.message);
    CHECK(glscene_open("/nonexistent/x.glsb", NULL, &e) == NULL);
    CHECK_MSG(strstr(e.message, "/nonexistent/x.glsb") != NULL, "%s", e.message);
    CHECK(glscene_camera_from_file("/nonexistent/x.cam", &c, &e) == -1);
    CHECK_MSG(strncmp(e.message, "/nonexistent/x.cam: error: ", 27) == 0, "%s", e.message);
    char cam[160];
    snprintf(cam, sizeof cam, "%s/c.cam", dir);
    write_file("c.cam", "width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\n"
                        "far 100\n");
    glscene_camera f, n;
    CHECK(glscene_camera_from_file(cam, &f, &e) == 0 && camera(&n) == 0);
    CHECK(memcmp(&f, &n, sizeof f) == 0);
    write_file("c.cam", "width 64\nheight 48\nfx -50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\n"
                        "near 0.1\nfar 100\n");
    CHECK(glscene_camera_from_file(cam, &f, &e) == -1);
    char want[512];
    snprintf(want, sizeof want, "%s:3:4: error: fx must be > 0 (focal length in pixels)\n", cam);
    CHECK_MSG(strncmp(e.message, want, strlen(want)) == 0, "%s", e.message);
    /* a lens is refused, not dropped: the API's camera is a pinhole */
    write_file("c.cam", "width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\n"
                        "far 100\ndistortion -0.2 0.01 0 0\n");
    CHECK(glscene_camera_from_file(cam, &f, &e) == -1);
    snprintf(want, sizeof want, "%s: lens distortion ('distortion' or 'fisheye') is not in the library's camera yet; "
                                "glsplay renders it", cam);
    CHECK_STR(e.message, want);
    /* options outside the enums */
    glscene_error e2;
    CHECK(glscene_open(bundle, &(glscene_options){.pattern = 7}, &e2) == NULL);
    CHECK_STR(e2.message, "glscene_open: options: backend 0 or pattern 7 is not one of the enum's values");
}

/* glsplay's full options (glscene_play_*): arguments taken one at a time
 * with glsplay's words, the checks between them, and a run that writes
 * files and says what went wrong on the stream it is given. */
static void test_glscene_play(void)
{
    glscene_error e;
    glscene_play *r = glscene_play_new();
    CHECK(r != NULL);
    if (!r)
        return;
    CHECK(glscene_play_check(r, &e) == -1);
    CHECK_STR(e.message, "no bundle given");
    CHECK(glscene_play_arg(r, "--aa", "4", &e) == 2);
    CHECK(glscene_play_arg(r, "--explain", "--aa", &e) == 1);
    CHECK(glscene_play_arg(r, "--progress", "json", &e) == 2);
    CHECK(glscene_play_arg(r, "--progress", "x.glsb", &e) == 1);
    /* --progress last takes itself alone; --progress=WORD never takes the
       next argument, even one that is the same string as WORD */
    CHECK(glscene_play_arg(r, "--progress", NULL, &e) == 1);
    static const char progress_bar[] = "--progress=bar";
    CHECK(glscene_play_arg(r, progress_bar, progress_bar + 11, &e) == 1);
    CHECK(glscene_play_arg(r, "--aa", "0", &e) == -1);
    CHECK_STR(e.message, "--aa needs N in 1..4096, exact or auto, got '0'");
    CHECK(glscene_play_arg(r, "--camera", NULL, &e) == -1);
    CHECK_STR(e.message, "--camera needs a camera file");
    CHECK(glscene_play_arg(r, "--bogus", NULL, &e) == -1);
    CHECK_STR(e.message, "unknown option '--bogus'");
    CHECK(glscene_play_arg(r, NULL, NULL, &e) == -2);
    /* the whole message, however long the value echoed; e has what fits */
    static char big[3000];
    memset(big, '9', sizeof big - 1);
    CHECK(glscene_play_arg(r, "--aa", big, &e) == -1);
    CHECK(strlen(glscene_play_message(r)) == strlen("--aa needs N in 1..4096, exact or auto, got ''") + sizeof big - 1);
    CHECK(strlen(e.message) == sizeof e.message - 1 && strncmp(e.message, glscene_play_message(r), 1023) == 0);
    glscene_play_free(r);

    /* a run: the depth file is written; a missing camera is an input error */
    char cam[160], out[160], depth[200], missing[160];
    snprintf(cam, sizeof cam, "%s/p.cam", dir);
    snprintf(out, sizeof out, "%s/play", dir);
    snprintf(depth, sizeof depth, "%s/play/p/depth_000000.pfm", dir);
    snprintf(missing, sizeof missing, "%s/none.cam", dir);
    write_file("p.cam", "width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\n"
                        "far 100\n");
    for (int k = 0; k < 2; k++) {
        const char *args[] = {bundle, "--camera", k ? missing : cam, "-o", out, "--outputs", "depth"};
        r = glscene_play_new();
        int rc = 0;
        for (int i = 0, n = 0; i < 7 && rc == 0; i += n)
            if ((n = glscene_play_arg(r, args[i], i + 1 < 7 ? args[i + 1] : NULL, &e)) < 0)
                rc = -1;
        CHECK_MSG(rc == 0 && glscene_play_check(r, &e) == 0, "%s", e.message);
        FILE *o = tmpfile(), *errs = tmpfile();
        char msg[512] = "";
        CHECK(o && errs);
        if (o && errs) {
            rc = glscene_play_run(r, o, errs);
            rewind(errs);
            if (!fgets(msg, sizeof msg, errs))
                msg[0] = 0;
        }
        if (k == 0) {
            CHECK_MSG(rc == 0 && msg[0] == 0, "%d %s", rc, msg);
            CHECK(access(depth, R_OK) == 0);
        } else {
            char want[300];
            snprintf(want, sizeof want, "%s: error: cannot open: ", missing);
            CHECK_MSG(rc == 1 && strncmp(msg, want, strlen(want)) == 0, "%d %s", rc, msg);
        }
        if (o)
            fclose(o);
        if (errs)
            fclose(errs);
        glscene_play_free(r);
    }
}

/* One frame into a result (glscene_play_render): a camera given as
 * text, every array glsplay's files would hold, the names and types, and
 * the errors (a camera's text located by its name, no such array, the
 * checks of a run without -o). */
static void test_glscene_play_render(void)
{
    glscene_error e;
    glscene_play *r = glscene_play_new();
    if (!r)
        return;
    CHECK(glscene_play_arg(r, bundle, NULL, &e) == 1);
    CHECK(glscene_play_arg(r, "--outputs", "depth,disparity16,instance,boxes", &e) == 2);
    CHECK(glscene_play_render(r, 0, &e) == NULL);
    CHECK_STR(e.message, "no camera given (--camera CAM)");
    static const char cam[] = "width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\n"
                              "near 0.1\nfar 100\n";
    CHECK(glscene_play_camera_text(r, "p", cam, &e) == 0);
    /* disparity needs the rectified pair: a second camera 0.5 to the right */
    CHECK(glscene_play_render(r, 0, &e) == NULL);
    CHECK_MSG(strstr(e.message, "two cameras") != NULL, "%s", e.message);
    CHECK(glscene_play_camera_text(r, "q", "width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\n"
                                   "R 1 0 0 0 1 0 0 0 1\nT -0.5 0 0\nnear 0.1\nfar 100\n", &e) == 0);
    glscene_result *res = glscene_play_render(r, 0, &e);
    CHECK_MSG(res != NULL, "%s", e.message);
    if (res) {
        CHECK(glscene_result_cameras(res) == 2);
        CHECK_STR(glscene_result_camera(res, 0), "p");
        CHECK_STR(glscene_result_camera(res, 1), "q");
        CHECK(glscene_result_camera(res, 2) == NULL);
        /* the table's order: depth, disparity16, instance, instances, boxes, boxes_json */
        static const char *const names[] = {"depth", "disparity16", "instance", "instances", "boxes", "boxes_json"};
        CHECK(glscene_result_count(res, 0) == 6);
        for (size_t k = 0; k < 6; k++)
            CHECK_STR(glscene_result_name(res, 0, k), names[k]);
        CHECK(glscene_result_name(res, 0, 6) == NULL);
        glscene_array a;
        CHECK_MSG(glscene_result_array(res, 0, "depth", &a, &e) == 0, "%s", e.message);
        CHECK(a.dtype == GLSCENE_F32 && a.ndim == 2 && a.dims[0] == H && a.dims[1] == W && a.bytes == W * H * 4);
        size_t mid = (size_t)24 * W + 32;
        CHECK_NEAR(((const float *)a.data)[mid], 5.0, 5.0 * 2e-7);
        /* KITTI's disparity of the tile: fx B / Z * 256 = 50 * 0.5 / 5 * 256 */
        CHECK(glscene_result_array(res, 0, "disparity16", &a, &e) == 0);
        CHECK(a.dtype == GLSCENE_U16 && ((const uint16_t *)a.data)[mid] == 1280);
        CHECK(glscene_result_array(res, 0, "instance", &a, &e) == 0);
        CHECK(a.dtype == GLSCENE_U16 && ((const uint16_t *)a.data)[0] != ((const uint16_t *)a.data)[mid]);
        CHECK(glscene_result_array(res, 0, "boxes", &a, &e) == 0);
        CHECK(a.dtype == GLSCENE_TEXT && a.ndim == 1 && a.dims[0] == a.bytes && strlen(a.data) == a.bytes);
        CHECK(glscene_result_array(res, 0, "normals", &a, &e) == -1);
        CHECK_STR(e.message, "camera p has no array 'normals' (it has: depth, disparity16, instance, instances, "
                             "boxes, boxes_json)");
        CHECK(glscene_result_array(res, 2, "depth", &a, &e) == -1);
        CHECK_STR(e.message, "the result has 2 cameras; there is no camera 2");
        glscene_result_free(res);
    }
    glscene_play_free(r);
    /* a camera's text with a mistake: located by its name */
    r = glscene_play_new();
    CHECK(glscene_play_arg(r, bundle, NULL, &e) == 1);
    CHECK(glscene_play_camera_text(r, "bad", "width 64\nheight 48\nfx -1\n", &e) == 0);
    CHECK(glscene_play_render(r, 0, &e) == NULL);
    CHECK_MSG(strncmp(e.message, "bad:3:", 6) == 0 && strstr(e.message, "error: "), "%s", e.message);
    CHECK(glscene_play_trajectory_frames(r, NULL, 0, &e) == -1);
    CHECK_STR(e.message, "the run has no --trajectory");
    glscene_play_free(r);
    glscene_result_free(NULL);
}

/* The depth array of frame f of r (a result freed here); NULL on failure. */
static float *render_depth(glscene_play *r, uint64_t f)
{
    glscene_error e;
    glscene_result *res = glscene_play_render(r, f, &e);
    CHECK_MSG(res != NULL, "frame %llu: %s", (unsigned long long)f, e.message);
    glscene_array a;
    float *z = NULL;
    if (res && glscene_result_array(res, 0, "depth", &a, &e) == 0 && (z = malloc(a.bytes)))
        memcpy(z, a.data, a.bytes);
    glscene_result_free(res);
    return z;
}

static glscene_play *depth_run(void)
{
    glscene_error e;
    glscene_play *r = glscene_play_new();
    if (r) {
        CHECK(glscene_play_arg(r, bundle, NULL, &e) == 1);
        CHECK(glscene_play_arg(r, "--outputs", "depth", &e) == 2);
        CHECK(glscene_play_camera_text(r, "p", "width 64\nheight 48\nfx 50\nfy 50\ncx 31.5\ncy 23.5\n"
                                       "R 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n", &e) == 0);
    }
    return r;
}

/* glscene_play_render keeps its run open across frames: the bundle is
 * read once, when the run begins, so frames 1 and 2 render with the
 * bundle gone (a run reopened per frame would fail to read it), the same
 * arrays as fresh runs; a setting changed after a render begins the run
 * again, which reads the bundle again. */
static void test_glscene_play_render_keeps_run(void)
{
    char moved[160];
    snprintf(moved, sizeof moved, "%s.away", bundle);
    glscene_error e;
    glscene_play *r = depth_run();
    if (!r)
        return;
    float *kept[3] = {render_depth(r, 0), NULL, NULL};
    CHECK(rename(bundle, moved) == 0);
    kept[1] = render_depth(r, 1);
    kept[2] = render_depth(r, 2);
    /* a setting: the next render begins again, and the bundle is gone */
    CHECK(glscene_play_arg(r, "--background", "0,0,1", &e) == 2);
    CHECK(glscene_play_render(r, 3, &e) == NULL);
    CHECK_MSG(strstr(e.message, "wall.glsb") != NULL, "%s", e.message);
    CHECK(rename(moved, bundle) == 0);
    /* a failed render closed nothing it needs: the next begins and renders */
    float *again = render_depth(r, 3);
    CHECK(again != NULL);
    free(again);
    glscene_play_free(r);
    for (int f = 0; f < 3; f++) {
        glscene_play *fresh = depth_run();
        float *z = fresh ? render_depth(fresh, (uint64_t)f) : NULL;
        CHECK_MSG(z && kept[f] && memcmp(z, kept[f], (size_t)W * H * sizeof *z) == 0, "frame %d", f);
        free(z);
        free(kept[f]);
        glscene_play_free(fresh);
    }
}

int main(void)
{
    make_scene();
    RUN(test_glscene_compile);
    RUN(test_glscene_render_depth_ids);
    RUN(test_glscene_move);
    RUN(test_glscene_aa);
    RUN(test_glscene_exact);
    RUN(test_glscene_errors);
    RUN(test_glscene_play);
    RUN(test_glscene_play_render);
    RUN(test_glscene_play_render_keeps_run);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd)) {
    }
    CHECK_EXIT();
}
