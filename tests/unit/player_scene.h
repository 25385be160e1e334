/* Test helper: build small bundles in memory (no compiler needed) and
 * render them with the runtime library.  Header-only, for the player
 * tests.  Objects must be begun in strcmp order of their names (the
 * bundle's object table is sorted). */
#ifndef GLS_PLAYER_SCENE_H
#define GLS_PLAYER_SCENE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "atomic_write.h"
#include "bundle.h"
#include "camera.h"
#include "glctx.h"
#include "render.h"
#include "scene.h"

#define TB_MAXOBJ 16

typedef struct {
    gls_bundle *b;
    gls_buf code[TB_MAXOBJ];
    uint32_t ninsn[TB_MAXOBJ];
    uint32_t cur;
    uint32_t poscap, colcap, tccap;
} tb;

static inline void tb_die(const char *what)
{
    printf("FAIL player_scene: %s\n", what);
    exit(1);
}

static inline void tb_init(tb *t)
{
    memset(t, 0, sizeof *t);
    t->b = calloc(1, sizeof *t->b);
    if (!t->b)
        tb_die("out of memory");
    t->b->version = GLS_FORMAT_VERSION;
    t->b->objects = calloc(TB_MAXOBJ, sizeof(gls_object));
    t->b->top = GLS_NONE;
}

/* Start object `name`; top != 0 makes it the top-level object. */
static inline uint32_t tb_object(tb *t, const char *name, int top)
{
    uint32_t i = t->b->nobjects++;
    if (i >= TB_MAXOBJ)
        tb_die("too many objects");
    t->b->objects[i].name = strdup(name);
    t->cur = i;
    if (top)
        t->b->top = i;
    return i;
}

static inline void tb_insn(tb *t, gls_opcode op, const double *d, const uint32_t *u)
{
    gls_insn in;
    memset(&in, 0, sizeof in);
    in.op = op;
    /* d holds the numbers, u the integers, each in operand order */
    for (uint32_t i = 0, nd = 0, nu = 0; i < gls_op[op].noperands; i++) {
        if (gls_kind[gls_op[op].kind[i]].storage == GLS_STORE_F64)
            in.d[i] = d[nd++];
        else
            in.u[i] = u[nu++];
    }
    if (gls_insn_encode(&t->code[t->cur], &in))
        tb_die("out of memory");
    t->ninsn[t->cur]++;
}

static inline void tb_op0(tb *t, gls_opcode op) { tb_insn(t, op, NULL, NULL); }
static inline void tb_color(tb *t, double r, double g, double b, double a)
{
    double d[4] = {r, g, b, a};
    tb_insn(t, GLS_OP_COLOR, d, NULL);
}
static inline void tb_trans(tb *t, double x, double y, double z)
{
    double d[3] = {x, y, z};
    tb_insn(t, GLS_OP_TRANS, d, NULL);
}
static inline void tb_rot(tb *t, double deg, double x, double y, double z)
{
    double d[4] = {deg, x, y, z};
    tb_insn(t, GLS_OP_ROT, d, NULL);
}
static inline void tb_scale(tb *t, double x, double y, double z)
{
    double d[3] = {x, y, z};
    tb_insn(t, GLS_OP_SCALE, d, NULL);
}
static inline void tb_call(tb *t, uint32_t obj)
{
    uint32_t u[1] = {obj};
    tb_insn(t, GLS_OP_CALL, NULL, u);
}
static inline void tb_u1(tb *t, gls_opcode op, uint32_t v)
{
    uint32_t u[1] = {v};
    tb_insn(t, op, NULL, u);
}

/* *p grown to hold need elements of size elem, doubling *cap: a bundle of
 * many small primitives is not copied whole for each one (which, under
 * ASan, whose realloc always moves, made test_pack take 90 s for 0.2). */
static inline void *tb_grow(void *p, uint32_t *cap, uint64_t need, size_t elem)
{
    if (need <= *cap)
        return p;
    uint64_t c = *cap ? *cap : 256;
    while (c < need)
        c *= 2;
    if (c > UINT32_MAX || !(p = realloc(p, (size_t)c * elem)))
        tb_die("out of memory");
    *cap = (uint32_t)c;
    return p;
}

/* A primitive of n vertices (x, y, z, w), optional colours and texcoords. */
static inline void tb_prim4(tb *t, gls_primkind kind, uint32_t n, const gls_vec4 *p, const gls_rgba *c, const gls_st *st)
{
    gls_bundle *b = t->b;
    uint32_t u[5] = {(uint32_t)kind, n, b->npos, c ? b->ncol : GLS_NONE, st ? b->ntex : GLS_NONE};
    b->pos = tb_grow(b->pos, &t->poscap, (uint64_t)b->npos + n, sizeof *b->pos);
    memcpy(b->pos + b->npos, p, n * sizeof *p);
    b->npos += n;
    if (c) {
        b->col = tb_grow(b->col, &t->colcap, (uint64_t)b->ncol + n, sizeof *b->col);
        memcpy(b->col + b->ncol, c, n * sizeof *c);
        b->ncol += n;
    }
    if (st) {
        b->tc = tb_grow(b->tc, &t->tccap, (uint64_t)b->ntex + n, sizeof *b->tc);
        memcpy(b->tc + b->ntex, st, n * sizeof *st);
        b->ntex += n;
    }
    tb_insn(t, GLS_OP_PRIM, NULL, u);
}

/* A polygon from xyz triples (w = 1). */
static inline void tb_poly(tb *t, uint32_t n, const double (*xyz)[3])
{
    gls_vec4 p[64];
    if (n > 64)
        tb_die("polygon too large");
    for (uint32_t i = 0; i < n; i++)
        p[i] = (gls_vec4){xyz[i][0], xyz[i][1], xyz[i][2], 1.0};
    tb_prim4(t, GLS_PRIM_POLY, n, p, NULL, NULL);
}

/* Axis-aligned rectangle in the plane z = const: corners (x0,y0)-(x1,y1). */
static inline void tb_rect_z(tb *t, double x0, double y0, double x1, double y1, double z)
{
    double q[4][3] = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    tb_poly(t, 4, q);
}

/* Add a texture (names must be added in sorted order). */
static inline uint32_t tb_texture(tb *t, const char *name, uint32_t w, uint32_t h, const uint8_t *rgba)
{
    gls_bundle *b = t->b;
    b->textures = realloc(b->textures, (b->ntextures + 1) * sizeof *b->textures);
    gls_texture *tx = &b->textures[b->ntextures];
    tx->name = strdup(name);
    tx->width = w, tx->height = h;
    tx->rgba = malloc((size_t)w * h * 4);
    memcpy(tx->rgba, rgba, (size_t)w * h * 4);
    tx->flags = 0;
    for (size_t i = 0; i < (size_t)w * h; i++)
        if (rgba[4 * i + 3] == 0)
            tx->flags = GLS_TEX_ALPHA_HOLES;
    return b->ntextures++;
}

/* A GL context of backend B for the test NAME; none ends the test with
 * "FAIL NAME: no GL context: why" and exit status 1. */
static inline gls_glctx *tb_glctx(gls_backend b, const char *name)
{
    char err[256];
    gls_glctx *c = gls_glctx_create(b, err, sizeof err);
    if (!c) {
        printf("FAIL %s: no GL context: %s\n", name, err);
        exit(1);
    }
    return c;
}

/* Close every object with END and compute features; no validation
 * (for scenes beyond a validator limit that the player no longer needs). */
static inline gls_bundle *tb_finish_unchecked(tb *t)
{
    gls_bundle *b = t->b;
    for (uint32_t i = 0; i < b->nobjects; i++) {
        t->cur = i;
        tb_op0(t, GLS_OP_END);
        b->objects[i].code = t->code[i].data;
        b->objects[i].code_len = (uint32_t)t->code[i].len;
        b->objects[i].ninsn = t->ninsn[i];
    }
    b->features = gls_bundle_features(b);
    t->b = NULL;
    return b;
}

/* Close every object with END, compute features, validate. */
static inline gls_bundle *tb_finish(tb *t)
{
    gls_bundle *b = tb_finish_unchecked(t);
    gls_error err;
    if (gls_bundle_validate(b, &err)) {
        printf("FAIL player_scene: built bundle does not validate: %s\n", err.msg);
        exit(1);
    }
    return b;
}

static inline int tb_write(const gls_bundle *b, const char *path)
{
    uint8_t *data;
    size_t len;
    gls_error err;
    if (gls_bundle_write(b, &data, &len, &err))
        return -1;
    int r = gls_write_file_atomic(path, data, len);
    free(data);
    return r;
}

/* Render a bundle through a camera in-process; rgba/z may be NULL. */
typedef struct {
    gls_glctx *ctx;
} tb_gl;

static inline int tb_render(gls_glctx *ctx, const gls_bundle *b, const gls_camera *c, double du, double dv,
                     uint8_t *rgba, float *z)
{
    char err[512];
    gls_scene s;
    if (gls_scene_load(b, &s, err, sizeof err)) {
        printf("  scene: %s\n", err);
        return -1;
    }
    gls_renderer *r = gls_renderer_create(ctx, b, &s, err, sizeof err);
    if (!r || gls_renderer_set_size(r, c->width, c->height, err, sizeof err)) {
        printf("  renderer: %s\n", err);
        gls_renderer_destroy(r);
        gls_scene_free(&s);
        return -1;
    }
    gls_render_pass(r, c, du, dv);
    if (rgba)
        gls_render_read_rgba(r, rgba);
    if (z)
        gls_render_read_z(r, z);
    gls_renderer_destroy(r);
    gls_scene_free(&s);
    return 0;
}

/* Camera from parts (R row-major). */
static inline gls_camera tb_camera(uint32_t w, uint32_t h, double fx, double fy, double cx, double cy, double skew,
                            const double R[9], const double T[3], double n, double f)
{
    gls_camera c;
    memset(&c, 0, sizeof c);
    c.width = w, c.height = h, c.fx = fx, c.fy = fy, c.cx = cx, c.cy = cy, c.skew = skew;
    memcpy(c.R, R, sizeof c.R);
    memcpy(c.T, T, sizeof c.T);
    c.near = n, c.far = f;
    return c;
}

/* The anti-aliasing tests' view (test_aa.c, test_aa_lattice.c): at the
 * origin looking along +z (R = I, T = 0), f = 100 px, the principal point
 * at the image's centre, near 0.5, far 100. */
static inline gls_camera tb_front_camera(uint32_t w, uint32_t h)
{
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, T[3] = {0, 0, 0};
    return tb_camera(w, h, 100, 100, (w - 1) / 2.0, (h - 1) / 2.0, 0, R, T, 0.5, 100);
}

/* A wall of one colour, (77, 154, 231) / 255, at depth 5 filling any view
 * of tb_front_camera: every pixel, sample and filter must give exactly
 * that colour. */
static inline gls_bundle *tb_wall(void)
{
    tb t;
    tb_init(&t);
    tb_object(&t, "wall", 1);
    tb_color(&t, 77 / 255.0, 154 / 255.0, 231 / 255.0, 1);
    tb_rect_z(&t, -100, -100, 100, 100, 5);
    return tb_finish(&t);
}

/* Write a camera file in the documented format. */
static inline int tb_write_camera(const gls_camera *c, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "# written by the player tests\nwidth %u\nheight %u\nfx %.17g\nfy %.17g\ncx %.17g\ncy %.17g\n"
               "skew %.17g\nR",
            c->width, c->height, c->fx, c->fy, c->cx, c->cy, c->skew);
    for (int i = 0; i < 9; i++)
        fprintf(f, " %.17g", c->R[i]);
    fprintf(f, "\nT %.17g %.17g %.17g\nnear %.17g\nfar %.17g\n", c->T[0], c->T[1], c->T[2], c->near, c->far);
    return fclose(f);
}

#endif
