/* Instanced replay: named instances moved per frame (--motion), motion
 * files, and a scene beyond the flattened form's 2^26-vertex limit.  The
 * projections are checked against an independent double-precision camera
 * model written here.  A list of independent tests, one function each,
 * over the scene builder of player_scene.h: long on purpose. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check.h"
#include "exact_scene.h"
#include "motion.h"
#include "player.h"
#include "player_scene.h"
#include "vec.h"

static gls_glctx *ctx;
static const double I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

/* u, v of world point P through c (P_cam = R P + T, pinhole, skew). */
static double ref_project(const gls_camera *c, const double P[3], double *u, double *v)
{
    double X = c->R[0] * P[0] + c->R[1] * P[1] + c->R[2] * P[2] + c->T[0];
    double Y = c->R[3] * P[0] + c->R[4] * P[1] + c->R[5] * P[2] + c->T[1];
    double Z = c->R[6] * P[0] + c->R[7] * P[1] + c->R[8] * P[2] + c->T[2];
    *u = (c->fx * X + c->skew * Y) / Z + c->cx;
    *v = c->fy * Y / Z + c->cy;
    return Z;
}

/* Centroid of the pixels of colour rgb; the count of them. */
static long centroid(const uint8_t *rgba, uint32_t W, uint32_t H, const uint8_t rgb[3], double *cu, double *cv)
{
    long n = 0;
    double su = 0, sv = 0;
    for (uint32_t v = 0; v < H; v++)
        for (uint32_t u = 0; u < W; u++) {
            const uint8_t *p = rgba + 4 * ((size_t)v * W + u);
            if (p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2])
                n++, su += u, sv += v;
        }
    *cu = n ? su / n : 1e9, *cv = n ? sv / n : 1e9;
    return n;
}

static int render_scene(gls_scene *s, const gls_bundle *b, const gls_camera *c, uint8_t *rgba)
{
    char err[256];
    gls_renderer *r = gls_renderer_create(ctx, b, s, err, sizeof err);
    if (!r || gls_renderer_set_size(r, c->width, c->height, err, sizeof err)) {
        printf("  renderer: %s\n", err);
        gls_renderer_destroy(r);
        return -1;
    }
    gls_render_pass(r, c, 0, 0);
    gls_render_read_rgba(r, rgba);
    gls_renderer_destroy(r);
    return 0;
}

/* A red unit square (x, y in -0.5..0.5, z = 0) called at (1, 0, 8) and
 * named "car1", moved by a rotation of 30 degrees about z and (0.5,
 * -0.25, 0.75): its corners must land where the model puts
 * W_call * (R q + T). */
static void test_motion_moves_named_instance(void)
{
    tb t;
    tb_init(&t);
    uint32_t sq = tb_object(&t, "square", 0);
    tb_color(&t, 1, 0, 0, 1);
    tb_rect_z(&t, -0.5, -0.5, 0.5, 0.5, 0);
    tb_object(&t, "top", 1);
    tb_op0(&t, GLS_OP_PUSH);
    tb_trans(&t, 1, 0, 8);
    tb_call(&t, sq);
    tb_op0(&t, GLS_OP_POP);
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    CHECK(s.ninst == 2 && s.inst[1].parent == 0);
    CHECK(gls_scene_name_instance(&s, 1, "car1") == 0);
    CHECK(gls_scene_name_instance(&s, 0, "car1") == -1);   /* taken */
    CHECK(gls_scene_name_instance(&s, 0, "1car") == -1);   /* charset */
    CHECK(gls_scene_name_instance(&s, 9, "x") == -1);      /* no such instance */
    CHECK(gls_scene_find_instance(&s, "car1") == 1);
    double a = 30 * 3.14159265358979323846 / 180;
    double R[9] = {cos(a), -sin(a), 0, sin(a), cos(a), 0, 0, 0, 1}, T[3] = {0.5, -0.25, 0.75};
    gls_scene_move(&s, 1, R, T);
    gls_scene_update(&s);
    double Tc[3] = {0, 0, 0};
    gls_camera c = tb_camera(320, 240, 300, 300, 159.5, 119.5, 0, I3, Tc, 0.1, 100);
    uint8_t *rgba = malloc((size_t)320 * 240 * 4);
    CHECK(render_scene(&s, b, &c, rgba) == 0);
    /* the model: corner q -> R q + T -> + (1, 0, 8); the projected
     * square's centroid is the mean of its corners' projections to first
     * order (the square is small and nearly fronto-parallel) */
    static const double q[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    double mu = 0, mv = 0;
    for (int k = 0; k < 4; k++) {
        double P[3], u, v;
        for (int i = 0; i < 3; i++)
            P[i] = R[3 * i] * q[k][0] + R[3 * i + 1] * q[k][1] + T[i] + (i == 0 ? 1 : i == 2 ? 8 : 0);
        ref_project(&c, P, &u, &v);
        mu += u / 4, mv += v / 4;
    }
    static const uint8_t red[3] = {255, 0, 0};
    double cu, cv;
    long n = centroid(rgba, 320, 240, red, &cu, &cv);
    printf("  moved square: %ld pixels, centroid (%.3f, %.3f), model (%.3f, %.3f)\n", n, cu, cv, mu, mv);
    /* area: the square at depth 8.75 is 300/8.75 = 34.3 px on a side */
    CHECK(n > 1000 && n < 1350);
    CHECK(fabs(cu - mu) < 0.05 && fabs(cv - mv) < 0.05);
    /* without the motion it is back at its placement */
    gls_scene_move(&s, 1, NULL, NULL);
    gls_scene_update(&s);
    CHECK(render_scene(&s, b, &c, rgba) == 0);
    centroid(rgba, 320, 240, red, &cu, &cv);
    double P0[3] = {1, 0, 8}, u0, v0;
    ref_project(&c, P0, &u0, &v0);
    CHECK(fabs(cu - u0) < 0.05 && fabs(cv - v0) < 0.05);
    free(rgba);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

/* A named instance without motion renders byte-identically to the
 * unnamed one. */
static void test_named_without_motion_identical(void)
{
    tb t;
    tb_init(&t);
    uint32_t sq = tb_object(&t, "square", 0);
    tb_color(&t, 0, 1, 0, 1);
    tb_rect_z(&t, -0.5, -0.3, 0.4, 0.5, 0);
    tb_object(&t, "top", 1);
    tb_trans(&t, 0.3, 0.1, 5);
    tb_rot(&t, 20, 0, 1, 0);
    tb_call(&t, sq);
    gls_bundle *b = tb_finish(&t);
    gls_scene s0, s1;
    char err[256];
    CHECK(gls_scene_load(b, &s0, err, sizeof err) == 0 && gls_scene_load(b, &s1, err, sizeof err) == 0);
    CHECK(gls_scene_name_instance(&s1, 1, "car1") == 0);
    double Tc[3] = {0, 0, 0};
    gls_camera c = tb_camera(160, 120, 150, 150, 79.5, 59.5, 0, I3, Tc, 0.1, 100);
    size_t n = (size_t)160 * 120 * 4;
    uint8_t *a = malloc(n), *a1 = malloc(n);
    CHECK(render_scene(&s0, b, &c, a) == 0 && render_scene(&s1, b, &c, a1) == 0);
    CHECK(memcmp(a, a1, n) == 0);
    free(a), free(a1);
    gls_scene_free(&s0);
    gls_scene_free(&s1);
    gls_bundle_free(b);
}

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(text, f);
    return fclose(f);
}

/* The three formats give the same pose; errors verbatim. */
static void test_motion_files(void)
{
    char dir[] = "/tmp/gls_motion_XXXXXX", path[512], err[512];
    CHECK(mkdtemp(dir) != NULL);
    /* 90 degrees about z, T = (1, 2, 3); quaternion (0, 0, s, s), s = sqrt(1/2) */
    static const char *files[3] = {
        "# glsroad motion 1\n0 0 1 0 0 0 1 0 0 0 1 0 0 0\n4 0.1 0 -1 0 1 0 0 0 0 1 1 2 3\n",
        "1 0 0 0 0 1 0 0 0 0 1 0\n# a comment\n1 0 0 0 0 1 0 0 0 0 1 0\n\n"
        "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 0\n0 -1 0 1 1 0 0 2 0 0 1 3\n",
        "0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n3 0 0 0 0 0 0 1\n"
        "4 1 2 3 0 0 0.70710678118654752 0.70710678118654752\n"};
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/m%d.txt", dir, k);
        CHECK(write_text(path, files[k]) == 0);
        gls_motion m;
        double R[9], T[3];
        CHECK(gls_motion_read(path, NULL, &m, err, sizeof err) == 0);
        CHECK(gls_motion_pose(&m, 4, R, T) == 0);
        CHECK_MSG(fabs(R[1] + 1) < 1e-12 && fabs(R[3] - 1) < 1e-12 && fabs(R[0]) < 1e-12 && T[0] == 1 && T[1] == 2 &&
                      T[2] == 3, "format %d", k);
        CHECK(gls_motion_pose(&m, 5, R, T) == -1); /* no row: the player's load-time error */
        if (k == 0)
            CHECK(gls_motion_pose(&m, 2, R, T) == -1);
        gls_motion_free(&m);
    }
    static const struct {
        const char *text, *want;
    } bad[] = {
        {"1 2 3\n", "PATH:1: error: 3 values: not a motion row (\"# glsroad motion 1\" then 14 values, KITTI's 12 or TUM's 8)"},
        {"1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n", "PATH:2: error: expected 12 values like the first row, got 11"},
        {"0 0 0 0 0 0 0 2\n", "PATH:1: error: quaternion (0 0 0 2) is not of unit length"},
        {"# glsroad motion 1\n3 0 1 0 0 0 1 0 0 0 1 0 0 0\n3 0 1 0 0 0 1 0 0 0 1 0 0 0\n",
         "PATH:3: error: frame 3 does not follow frame 3: frames must increase"},
        {"# glsroad motion 1\n", "PATH:1: error: no frames in the motion file"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        snprintf(path, sizeof path, "%s/bad.txt", dir);
        CHECK(write_text(path, bad[k].text) == 0);
        gls_motion m;
        CHECK(gls_motion_read(path, NULL, &m, err, sizeof err) == -1);
        char want[600];
        const char *at = strstr(bad[k].want, "PATH");
        snprintf(want, sizeof want, "%s%s", path, at + 4);
        CHECK_MSG(strcmp(err, want) == 0, "got '%s', want '%s'", err, want);
        unlink(path);
    }
    for (int k = 0; k < 3; k++) {
        snprintf(path, sizeof path, "%s/m%d.txt", dir, k);
        unlink(path);
    }
    rmdir(dir);
}

/* --motion with a name the bundle lacks: an input error, exit 1. */
static void test_motion_unknown_name(void)
{
    char dir[] = "/tmp/gls_motion_XXXXXX", bpath[512], cpath[512], out[512];
    CHECK(mkdtemp(dir) != NULL);
    tb t;
    tb_init(&t);
    tb_object(&t, "top", 1);
    tb_rect_z(&t, 0, 0, 1, 1, 5);
    gls_bundle *b = tb_finish(&t);
    snprintf(bpath, sizeof bpath, "%s/s.glsb", dir);
    snprintf(cpath, sizeof cpath, "%s/c.cam", dir);
    snprintf(out, sizeof out, "%s/out", dir);
    double Tc[3] = {0, 0, 0};
    gls_camera c = tb_camera(32, 24, 30, 30, 15.5, 11.5, 0, I3, Tc, 0.1, 100);
    CHECK(tb_write(b, bpath) == 0 && tb_write_camera(&c, cpath) == 0);
    const char *cams[1] = {cpath}, *mot[1] = {"car1=/nonexistent"};
    gls_play_opts o;
    memset(&o, 0, sizeof o);
    o.bundle = bpath, o.cameras = cams, o.ncameras = 1, o.outdir = out, o.outputs = GLS_OUT_IMAGE;
    o.motions = mot, o.nmotions = 1;
    o.aa = gls_aa_defaults();
    o.frame_end = UINT64_MAX;
    FILE *errs = tmpfile(), *outs = tmpfile();
    CHECK(gls_play(&o, outs, errs) == 1);
    char msg[600] = "", want[600];
    rewind(errs);
    if (!fgets(msg, sizeof msg, errs))
        msg[0] = 0;
    snprintf(want, sizeof want, "glsplay: error: --motion car1: %s has no instance named 'car1' (it names no instance)\n",
             bpath);
    CHECK_MSG(strcmp(msg, want) == 0, "got '%s'", msg);
    CHECK(access(out, F_OK) != 0); /* nothing written */
    fclose(errs), fclose(outs);
    unlink(bpath), unlink(cpath), rmdir(dir);
    gls_bundle_free(b);
}

/* 2^11 instances of a 65,536-vertex fan: 2^27 vertices flattened, twice
 * the flattened form's limit, and about 13 GB as flattened triangles;
 * instanced, one fan and a table.  The validator accepts it (4095 call
 * paths), gls_scene_flatten refuses it before building anything.  Only
 * the first fan is in view: the others are culled. */
static void test_beyond_flattened_limit(void)
{
    enum { NV = 65536, LEVELS = 11 };
    tb t;
    tb_init(&t);
    uint32_t leaf = tb_object(&t, "fan", 0);
    gls_vec4 *p = malloc(NV * sizeof *p);
    for (int k = 0; k < NV; k++) {
        double a = 2 * 3.14159265358979323846 * k / NV;
        p[k] = k == 0 ? (gls_vec4){0, 0, 0, 1} : (gls_vec4){0.5 * cos(a), 0.5 * sin(a), 0, 1};
    }
    tb_color(&t, 0, 0, 1, 1);
    tb_prim4(&t, GLS_PRIM_TFAN, NV, p, NULL, NULL);
    free(p);
    uint32_t prev = leaf;
    for (int l = 0; l < LEVELS; l++) { /* level l: two calls of level l-1, 2^l * 3 units apart */
        char name[16];
        snprintf(name, sizeof name, "level%02d", l);
        uint32_t o = tb_object(&t, name, l == LEVELS - 1);
        tb_call(&t, prev);
        tb_trans(&t, 3.0 * (1 << l), 0, 0);
        tb_call(&t, prev);
        prev = o;
    }
    gls_bundle *b = tb_finish(&t); /* validated */
    CHECK(gls_bundle_expanded_vertices(b, b->top) > GLS_MAX_EXPANDED_VERTICES);
    gls_scene s;
    char err[256];
    CHECK(gls_scene_flatten(b, &s, err, sizeof err) != 0);
    CHECK_STR(err, "level10 draws more than 67108864 vertices once its calls are unrolled: too large to flatten (drop "
                   "--flatten to draw it instanced)");
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    CHECK(s.nverts == 3 * (NV - 2) && s.nprotos >= 1);
    uint32_t leaves = 0;
    for (uint32_t i = 0; i < s.ninst; i++)
        leaves += s.inst[i].nitems > 0;
    CHECK(leaves == 1u << LEVELS);
    uint64_t geo, table;
    gls_scene_memory(&s, &geo, &table);
    printf("  %u instances of a %u-triangle fan: geometry %.1f MiB, table %.1f MiB\n", leaves, NV - 2, geo / 1048576.0,
           table / 1048576.0);
    double Tc[3] = {0, 0, 4};
    gls_camera c = tb_camera(32, 32, 40, 40, 15.5, 15.5, 0, I3, Tc, 0.1, 100);
    uint8_t *rgba = malloc((size_t)32 * 32 * 4);
    CHECK(render_scene(&s, b, &c, rgba) == 0);
    static const uint8_t blue[3] = {0, 0, 255};
    double cu, cv;
    long n = centroid(rgba, 32, 32, blue, &cu, &cv);
    /* the fan at the origin, radius 0.5 at depth 4: 5 px, area ~ 78 px
     * (the next one, 3 units along x, projects 30 px away: not in view) */
    printf("  %ld pixels, centroid (%.3f, %.3f)\n", n, cu, cv);
    CHECK(n > 60 && n < 100 && fabs(cu - 15.5) < 0.3 && fabs(cv - 15.5) < 0.3);
    free(rgba);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

/* An object entered on many call paths is walked once per drawing state
 * and replayed from a record on the other paths (scene_build.c): its
 * landmarks (one behind an inlined projective call, so the record keeps
 * the path through it), lights and instances must come out exactly as a
 * full walk of every path places them, the flattened walk (which inlines
 * everything): same order, names, paths and world positions.  b.Lamp is
 * entered three times with one drawing state and once more with the same
 * proto but another raw texture mode (a second record). */
static void test_replay_matches_flatten(void)
{
    tb t;
    tb_init(&t);
    uint32_t top = tb_object(&t, "a.Top", 1);
    uint32_t lamp = tb_object(&t, "b.Lamp", 0);
    uint32_t post = tb_object(&t, "c.Post", 0);
    uint32_t tip = tb_object(&t, "d.Tip", 0);
    double tri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    t.cur = top;
    for (int i = 0; i < 4; i++) {
        tb_op0(&t, GLS_OP_PUSH);
        tb_trans(&t, 10.0 * i, 0, 5);
        tb_rot(&t, 30.0 * i, 0, 1, 0);
        if (i == 3)
            tb_u1(&t, GLS_OP_TEXMODE, GLS_MODE_MODULATE); /* no texture, but a proto of its own (and its posts') */
        tb_call(&t, lamp);
        tb_op0(&t, GLS_OP_POP);
    }
    t.cur = lamp;
    tb_poly(&t, 3, tri);
    for (int i = 0; i < 2; i++) {
        tb_trans(&t, 0, 2, 0);
        tb_call(&t, post);
    }
    t.cur = post;
    tb_poly(&t, 3, tri);
    uint32_t mk_base[1] = {0}, mk_tip[1] = {1}, lk[1] = {GLS_LIGHT_POINT};
    tb_insn(&t, GLS_OP_LIGHT, (double[]){0, 3, 0, 1, 1, 1, 0}, lk);
    tb_op0(&t, GLS_OP_PUSH);
    /* projective: the call is inlined into c.Post's instance */
    tb_insn(&t, GLS_OP_TRANSFORM, (double[]){1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 0, 0, 0, 0.125, 1}, NULL);
    tb_call(&t, tip);
    tb_op0(&t, GLS_OP_POP);
    tb_insn(&t, GLS_OP_MARK, (double[]){0.5, 0.25, 0}, mk_base); /* its path: back out of d.Tip */
    t.cur = tip;
    tb_insn(&t, GLS_OP_MARK, (double[]){0, 1, 2}, mk_tip);
    t.b->nmarknames = 2;
    t.b->marknames = malloc(2 * sizeof *t.b->marknames);
    t.b->marknames[0] = strdup("base");
    t.b->marknames[1] = strdup("tip");
    gls_bundle *b = tb_finish(&t);
    gls_scene s, f;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    CHECK(gls_scene_flatten(b, &f, err, sizeof err) == 0);
    /* 1 top, 4 lamps, 8 posts: each post with its own mark and the tip's */
    CHECK(s.ninst == 13 && s.nmarks == 16 && f.nmarks == 16 && s.nlights == 8 && f.nlights == 8);
    CHECK(s.nprotos == 5); /* top; lamp and post, each as entered with and without the texmode */
    for (uint32_t k = 0; k < s.nmarks && k < f.nmarks; k++) {
        double a[3], c[3];
        gls_scene_mark_world(&s, k, a);
        gls_scene_mark_world(&f, k, c);
        CHECK_MSG(s.marks[k].name == f.marks[k].name && strcmp(s.marks[k].path, f.marks[k].path) == 0,
                  "mark %u: %s vs %s", k, s.marks[k].path, f.marks[k].path);
        for (int j = 0; j < 3; j++)
            CHECK_NEAR(a[j], c[j], 1e-9 * (1 + fabs(c[j])));
    }
    CHECK_STR(s.marks[14].path, "a.Top > b.Lamp#4 > c.Post#2 > d.Tip#1");
    CHECK_STR(s.marks[15].path, "a.Top > b.Lamp#4 > c.Post#2");
    for (uint32_t k = 0; k < s.nlights && k < f.nlights; k++) {
        double a[4];
        m4_apply(s.inst[s.lights[k].inst].world, s.lights[k].p[0], s.lights[k].p[1], s.lights[k].p[2],
                 s.lights[k].p[3], a);
        CHECK(s.lights[k].kind == GLS_LIGHT_POINT && f.lights[k].inst == 0);
        for (int j = 0; j < 3; j++)
            CHECK_NEAR(a[j], f.lights[k].p[j], 1e-9 * (1 + fabs(f.lights[k].p[j])));
    }
    /* instances in walk order: each lamp followed by its two posts */
    for (uint32_t i = 1; i < s.ninst; i++)
        CHECK(s.inst[i].object == ((i - 1) % 3 == 0 ? lamp : post) &&
              s.inst[i].parent == ((i - 1) % 3 == 0 ? 0 : i - (i - 1) % 3));
    gls_scene_free(&s);
    gls_scene_free(&f);
    gls_bundle_free(b);
}

/* Chris Ericson's/Timothy Chan's comparison of Morton order without
 * interleaving: the axis whose coordinates differ in the highest bit
 * decides; at the same bit, x before y before z (scene_build.c puts x
 * highest within each bit). */
static int msb_less(uint32_t a, uint32_t b) { return a < b && a < (a ^ b); }
static int zorder_before(const uint32_t p[3], const uint32_t q[3])
{
    int axis = 0;
    uint32_t best = 0;
    for (int j = 0; j < 3; j++) {
        uint32_t x = p[j] ^ q[j];
        if (msb_less(best, x))
            axis = j, best = x;
    }
    return p[axis] < q[axis];
}

/* Within a chunk, triangles are drawn in the Morton order of their first
 * vertex on a 1/16-unit grid, whatever order the object emits them in
 * (spec/bundle.md 9.3). */
static void test_draw_order_within_cell(void)
{
    enum { N = 12 };
    tb t;
    tb_init(&t);
    tb_object(&t, "grid", 1);
    tb_color(&t, 0, 1, 0, 1);
    /* N x N small triangles in one cell, emitted in a scrambled order
     * (k * 37 mod N^2 visits every k once: 37 is prime to 144) */
    for (int k = 0; k < N * N; k++) {
        int m = (k * 37) % (N * N), i = m % N, j = m / N;
        double x = 1 + 3.3 * i, y = 2 + 2.7 * j;
        double tri[3][3] = {{x, y, 20}, {x + 1, y, 20}, {x, y + 1, 20}};
        tb_poly(&t, 3, tri);
    }
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    CHECK(s.nverts == 3 * N * N && s.nchunks == 1);
    int inorder = 1;
    uint32_t prev[3] = {0, 0, 0};
    for (uint32_t k = 0; k < s.nverts / 3; k++) {
        const double *v = s.exact + 9 * (size_t)k; /* first vertex, world, double */
        uint32_t q[3];
        for (int j = 0; j < 3; j++)
            q[j] = (uint32_t)floor(v[j] * 16);
        if (k && zorder_before(q, prev))
            inorder = 0;
        memcpy(prev, q, sizeof q);
    }
    CHECK(inorder);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

/* An object that selects a texture itself but inherits the texture mode,
 * called twice with no texture: once after texmode(modulate), once after
 * texmode(replace).  Its prims draw in the inherited mode, so the two
 * calls must not share one proto (their normalised state, no texture, is
 * the same): the instanced image equals the flattened one. */
static void test_inherited_texmode(void)
{
    tb t;
    tb_init(&t);
    uint8_t tex[4 * 4 * 4];
    for (int i = 0; i < 16; i++) /* a green texture, opaque */
        tex[4 * i] = 0, tex[4 * i + 1] = 200, tex[4 * i + 2] = 0, tex[4 * i + 3] = 255;
    uint32_t tx = tb_texture(&t, "green.png", 4, 4, tex);
    uint32_t sq = tb_object(&t, "square", 0);
    tb_u1(&t, GLS_OP_TEXTURE, tx);
    gls_vec4 p[4] = {{-0.5, -0.5, 0, 1}, {0.5, -0.5, 0, 1}, {0.5, 0.5, 0, 1}, {-0.5, 0.5, 0, 1}};
    gls_st st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    tb_prim4(&t, GLS_PRIM_POLY, 4, p, NULL, st);
    tb_object(&t, "top", 1);
    tb_color(&t, 1, 0, 0, 1); /* modulate: green x red = black; replace: green */
    for (int k = 0; k < 2; k++) {
        tb_u1(&t, GLS_OP_TEXMODE, k ? GLS_MODE_REPLACE : GLS_MODE_MODULATE);
        tb_op0(&t, GLS_OP_PUSH);
        tb_trans(&t, k ? 0.75 : -0.75, 0, 4);
        tb_call(&t, sq);
        tb_op0(&t, GLS_OP_POP);
    }
    gls_bundle *b = tb_finish(&t);
    double T0[3] = {0, 0, 0};
    gls_camera c = tb_camera(64, 32, 40, 40, 31.5, 15.5, 0, I3, T0, 0.1, 100);
    uint8_t inst[64 * 32 * 4], flat[64 * 32 * 4];
    gls_scene s, f;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0 && gls_scene_flatten(b, &f, err, sizeof err) == 0);
    CHECK(render_scene(&s, b, &c, inst) == 0 && render_scene(&f, b, &c, flat) == 0);
    size_t green = 0, diff = 0;
    for (size_t i = 0; i < sizeof inst; i += 4) {
        green += flat[i + 1] > 150 && flat[i] < 50;
        diff += memcmp(inst + i, flat + i, 4) != 0;
    }
    printf("  flattened: %zu green (replace) pixels; instanced differs in %zu pixels\n", green, diff);
    CHECK(green > 50);
    CHECK(diff == 0);
    gls_scene_free(&s), gls_scene_free(&f);
    gls_bundle_free(b);
}

/* Exact coverage projects only what may meet the view (exact_view.c): a
 * square in view and one across the image's right edge keep their
 * triangles; one far to the side, one behind the camera and one beyond
 * the far plane have none, until a motion brings one into view.  The
 * triangles kept are checked against the independent model: each kept
 * instance's, and only those, have a corner within a pixel's margin of
 * the image. */
static void test_exact_view_culls(void)
{
    tb t;
    tb_init(&t);
    uint32_t sq = tb_object(&t, "square", 0);
    tb_color(&t, 1, 0, 0, 1);
    tb_rect_z(&t, -0.5, -0.5, 0.5, 0.5, 0);
    tb_object(&t, "top", 1);
    /* instances 1..5: in view, across the right edge (u 57.5..77.5 of 64), far
     * right, behind, beyond far */
    static const double at[5][3] = {{0, 0, 5}, {1.8, 0, 5}, {50, 0, 5}, {0, 0, -5}, {0, 0, 200}};
    for (int k = 0; k < 5; k++) {
        tb_op0(&t, GLS_OP_PUSH);
        tb_trans(&t, at[k][0], at[k][1], at[k][2]);
        tb_call(&t, sq);
        tb_op0(&t, GLS_OP_POP);
    }
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    CHECK(s.ninst == 6);
    double Tc[3] = {0, 0, 0};
    gls_camera c = tb_camera(64, 48, 100, 100, 31.5, 23.5, 0, I3, Tc, 0.5, 100);
    for (int moved = 0; moved < 2; moved++) {
        if (moved) { /* the far-right square moved into view: the culling sees motion */
            double T[3] = {-50, 0, 0};
            gls_scene_move(&s, 3, I3, T);
            gls_scene_update(&s);
        }
        gls_exact_geom g;
        CHECK(gls_exact_geom_make(&g, &s, NULL, &c) == 0);
        int tris[6] = {0};
        for (size_t k = 0; k < g.n; k++)
            if (g.v[k].inst < 6)
                tris[g.v[k].inst]++;
        int want[6] = {0, 1, 1, moved, 0, 0};
        for (int i = 1; i < 6; i++) {
            /* the model: does a corner of the moved square land in view? */
            int seen = 0;
            for (int q = 0; q < 4; q++) {
                double P[3] = {at[i - 1][0] + (q & 1 ? 0.5 : -0.5) + (moved && i == 3 ? -50 : 0),
                               at[i - 1][1] + (q & 2 ? 0.5 : -0.5), at[i - 1][2]}, u, v;
                double Z = ref_project(&c, P, &u, &v);
                seen |= Z > 0.5 && Z < 100 && u > -1.5 && u < 64.5 && v > -1.5 && v < 48.5;
            }
            CHECK(seen == want[i]);
            CHECK((tris[i] > 0) == want[i]);
            if (want[i])
                CHECK(tris[i] == 2);
        }
        gls_exact_geom_free(&g);
    }
    gls_scene_free(&s);
    gls_bundle_free(b);
}

int main(void)
{
    ctx = tb_glctx(GLS_BACKEND_AUTO, "test_instances");
    RUN(test_motion_moves_named_instance);
    RUN(test_named_without_motion_identical);
    RUN(test_motion_files);
    RUN(test_motion_unknown_name);
    RUN(test_beyond_flattened_limit);
    RUN(test_replay_matches_flatten);
    RUN(test_draw_order_within_cell);
    RUN(test_inherited_texmode);
    RUN(test_exact_view_culls);
    gls_glctx_destroy(ctx);
    CHECK_EXIT();
}
