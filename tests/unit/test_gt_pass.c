/* The ground-truth pass (runtime/render/gt_pass.h): instance ids against the
 * closed-form footprints of two boxes, normals against the box face each
 * pixel's ray enters first, depth bit for bit the colour pass's, and ids
 * cut exactly where an alpha-tested texture cuts the image; passes of some
 * rows only (a scissor) give those rows of the whole passes bit for bit and
 * leave the others alone.  The expected values come from a double-precision
 * camera model written here. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "gt_pass.h"
#include "player_scene.h"

static gls_glctx *ctx;

/* The unit cube -0.5..0.5 as six quads. */
static void tb_unit_cube(tb *t)
{
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2) {
            double q[4][3];
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            static const double uv[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
            for (int k = 0; k < 4; k++) {
                q[k][axis] = 0.5 * side;
                q[k][a] = uv[k][0];
                q[k][b] = uv[k][1];
            }
            tb_poly(t, 4, (const double(*)[3])q);
        }
}

/* A rotation about y by ay, then about x by ax (degrees), row-major. */
static void rot_yx(double ay, double ax, double R[9])
{
    double a = ay * M_PI / 180, b = ax * M_PI / 180;
    double Ry[9] = {cos(a), 0, sin(a), 0, 1, 0, -sin(a), 0, cos(a)};
    double Rx[9] = {1, 0, 0, 0, cos(b), -sin(b), 0, sin(b), cos(b)};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            R[3 * i + j] = 0;
            for (int k = 0; k < 3; k++)
                R[3 * i + j] += Rx[3 * i + k] * Ry[3 * k + j];
        }
}

static double project(const gls_camera *c, const double P[3], double *u, double *v)
{
    double X = c->R[0] * P[0] + c->R[1] * P[1] + c->R[2] * P[2] + c->T[0];
    double Y = c->R[3] * P[0] + c->R[4] * P[1] + c->R[5] * P[2] + c->T[1];
    double Z = c->R[6] * P[0] + c->R[7] * P[1] + c->R[8] * P[2] + c->T[2];
    *u = (c->fx * X + c->skew * Y) / Z + c->cx;
    *v = c->fy * Y / Z + c->cy;
    return Z;
}

/* Convex hull (counter-clockwise in u, v) of n points; returns its size. */
static int hull(int n, double (*p)[2], double (*h)[2])
{
    for (int i = 1; i < n; i++) /* sort by u, then v */
        for (int j = i; j > 0 && (p[j][0] < p[j - 1][0] || (p[j][0] == p[j - 1][0] && p[j][1] < p[j - 1][1])); j--) {
            double t0 = p[j][0], t1 = p[j][1];
            p[j][0] = p[j - 1][0], p[j][1] = p[j - 1][1];
            p[j - 1][0] = t0, p[j - 1][1] = t1;
        }
    int k = 0;
#define CROSS(o, a, b) (((a)[0] - (o)[0]) * ((b)[1] - (o)[1]) - ((a)[1] - (o)[1]) * ((b)[0] - (o)[0]))
    for (int i = 0; i < n; i++) {
        while (k >= 2 && CROSS(h[k - 2], h[k - 1], p[i]) <= 0)
            k--;
        h[k][0] = p[i][0], h[k][1] = p[i][1], k++;
    }
    for (int i = n - 2, lo = k + 1; i >= 0; i--) {
        while (k >= lo && CROSS(h[k - 2], h[k - 1], p[i]) <= 0)
            k--;
        h[k][0] = p[i][0], h[k][1] = p[i][1], k++;
    }
#undef CROSS
    return k - 1;
}

/* Signed distance of (u, v) inside the convex polygon h (positive
 * inside): the least distance to an edge line. */
static double inside(const double (*h)[2], int n, double u, double v)
{
    double d = INFINITY;
    for (int i = 0; i < n; i++) {
        const double *a = h[i], *b = h[(i + 1) % n];
        double ex = b[0] - a[0], ey = b[1] - a[1];
        double s = (ex * (v - a[1]) - ey * (u - a[0])) / hypot(ex, ey);
        d = fmin(d, s);
    }
    return d;
}

typedef struct {
    double c[3], e[3]; /* centre, half extents (world, axis-aligned) */
} box;

/* The box's footprint through c; *zmin, *zmax its corners' depths. */
static int footprint(const gls_camera *c, const box *b, double (*h)[2], double *zmin, double *zmax)
{
    double p[8][2];
    *zmin = INFINITY, *zmax = -INFINITY;
    for (int k = 0; k < 8; k++) {
        double P[3] = {b->c[0] + (k & 1 ? 1 : -1) * b->e[0], b->c[1] + (k & 2 ? 1 : -1) * b->e[1],
                       b->c[2] + (k & 4 ? 1 : -1) * b->e[2]};
        double z = project(c, P, &p[k][0], &p[k][1]);
        *zmin = fmin(*zmin, z), *zmax = fmax(*zmax, z);
    }
    return hull(8, p, h);
}

/* The ray of pixel (u, v) against box b (slab method): the entry
 * distance and the world normal of the face entered; *margin is how
 * much sooner that face is entered than the next one (0: on an edge). */
static double ray_box(const gls_camera *c, double u, double v, const box *b, double n[3], double *margin)
{
    double y = (v - c->cy) / c->fy, x = (u - c->cx - c->skew * y) / c->fx, d[3], o[3];
    for (int i = 0; i < 3; i++) {
        d[i] = c->R[i] * x + c->R[3 + i] * y + c->R[6 + i]; /* R^T (x, y, 1) */
        o[i] = -(c->R[i] * c->T[0] + c->R[3 + i] * c->T[1] + c->R[6 + i] * c->T[2]);
    }
    double tin = -INFINITY, tout = INFINITY, second = -INFINITY;
    int ax = -1;
    for (int i = 0; i < 3; i++) {
        double t0 = (b->c[i] - b->e[i] - o[i]) / d[i], t1 = (b->c[i] + b->e[i] - o[i]) / d[i];
        double a = fmin(t0, t1), z = fmax(t0, t1);
        if (a > tin)
            second = tin, tin = a, ax = i;
        else if (a > second)
            second = a;
        tout = fmin(tout, z);
    }
    if (!(tin < tout) || ax < 0)
        return INFINITY;
    n[0] = n[1] = n[2] = 0;
    n[ax] = d[ax] > 0 ? -1 : 1;
    *margin = tin - second;
    return tin;
}

/* The colour pass's depth and the ground-truth pass of camera c. */
typedef struct {
    gls_renderer *r;
    size_t n;
    uint32_t *id;
    float *nrm, *z, *z0;
} gt_run;

static void gt_run_start(gt_run *g, const gls_bundle *b, const gls_scene *s, const gls_camera *c)
{
    char err[512];
    g->r = gls_renderer_create(ctx, b, s, err, sizeof err);
    if (!g->r || gls_renderer_set_size(g->r, c->width, c->height, err, sizeof err))
        tb_die(err);
    g->n = (size_t)c->width * c->height;
    g->id = malloc(g->n * sizeof *g->id);
    g->nrm = malloc(g->n * 3 * sizeof *g->nrm);
    g->z = malloc(g->n * sizeof *g->z);
    g->z0 = malloc(g->n * sizeof *g->z0);
    gls_render_pass(g->r, c, 0, 0);
    gls_render_read_z(g->r, g->z0);
    CHECK(gls_gt_render(g->r, c, g->id, g->nrm, g->z, err, sizeof err) == 0);
    /* depth: the colour pass's, bit for bit */
    long nd = 0;
    double md = 0;
    for (size_t i = 0; i < g->n; i++)
        if (memcmp(&g->z[i], &g->z0[i], sizeof *g->z)) {
            nd++;
            md = fmax(md, fabs(g->z[i] - g->z0[i]) / g->z0[i]);
        }
    printf("  depth: %ld pixels differ from the colour pass's, by up to %.3g relative\n", nd, md);
    CHECK(nd == 0);
}

static void gt_run_end(gt_run *g)
{
    gls_renderer_destroy(g->r);
    free(g->id), free(g->nrm), free(g->z), free(g->z0);
}

/* Passes of some rows only (gls_render_pass_rows, gls_gt_render_rows):
 * rows y0..y0+rows-1 bit for bit the whole pass's (rgba, z: the colour
 * pass's; id, nrm, gz: the ground-truth pass's), the other rows of the
 * framebuffers still what camera o drew there and of the host buffers
 * untouched. */
static void rows_check(gls_renderer *r, const gls_camera *c, const gls_camera *o, uint32_t y0, uint32_t rows,
                       const uint8_t *rgba, const float *z, const uint32_t *id, const float *nrm, const float *gz)
{
    char err[512];
    size_t w = c->width, n = w * c->height, a = w * y0, b = a + w * rows;
    uint8_t *rgba2 = malloc(4 * n), *orgba = malloc(4 * n);
    float *z2 = malloc(n * sizeof *z2), *nrm2 = malloc(3 * n * sizeof *nrm2), *gz2 = malloc(n * sizeof *gz2);
    uint32_t *id2 = malloc(n * sizeof *id2), *oid = malloc(n * sizeof *oid);
    /* camera o's whole passes first, then c's rows over them */
    gls_render_pass(r, o, 0, 0);
    gls_render_read_rgba(r, orgba);
    CHECK(gls_gt_render(r, o, oid, NULL, NULL, err, sizeof err) == 0);
    memset(rgba2, 0xab, 4 * n), memset(z2, 0xab, n * sizeof *z2);
    gls_render_pass_rows(r, c, y0, rows);
    gls_render_read_rgba_rows(r, y0, rows, rgba2);
    gls_render_read_z_rows(r, y0, rows, z2);
    CHECK(memcmp(rgba2 + 4 * a, rgba + 4 * a, 4 * (b - a)) == 0);
    CHECK(memcmp(z2 + a, z + a, (b - a) * sizeof *z) == 0);
    int untouched = 1;
    for (size_t i = 0; i < 4 * n; i++)
        untouched &= (i >= 4 * a && i < 4 * b) || rgba2[i] == 0xab;
    CHECK(untouched);
    memset(id2, 0xab, n * sizeof *id2), memset(nrm2, 0xab, 3 * n * sizeof *nrm2), memset(gz2, 0xab, n * sizeof *gz2);
    CHECK(gls_gt_render_rows(r, c, y0, rows, id2, nrm2, gz2, err, sizeof err) == 0);
    CHECK(memcmp(id2 + a, id + a, (b - a) * sizeof *id) == 0);
    CHECK(memcmp(nrm2 + 3 * a, nrm + 3 * a, 3 * (b - a) * sizeof *nrm) == 0);
    CHECK(memcmp(gz2 + a, gz + a, (b - a) * sizeof *gz) == 0);
    for (size_t i = 0; i < n; i++)
        untouched &= (i >= a && i < b) || id2[i] == 0xababababu;
    CHECK(untouched);
    /* the framebuffers' other rows: camera o's, neither cleared nor drawn */
    gls_render_read_rgba(r, rgba2);
    CHECK(gls_gt_render_rows(r, c, y0, rows, id2, NULL, NULL, err, sizeof err) == 0);
    int kept = 1, nkept = 0;
    for (size_t i = 0; i < n; i++)
        if (i < a || i >= b) {
            kept &= memcmp(rgba2 + 4 * i, orgba + 4 * i, 4) == 0;
            nkept += memcmp(rgba2 + 4 * i, rgba + 4 * i, 4) != 0;
        }
    CHECK(kept && nkept > 0);
    /* the scissor is off again: a whole pass is the whole image */
    gls_render_pass(r, c, 0, 0);
    gls_render_read_rgba(r, rgba2);
    CHECK(memcmp(rgba2, rgba, 4 * n) == 0);
    CHECK(gls_gt_render(r, c, id2, NULL, NULL, err, sizeof err) == 0);
    CHECK(memcmp(id2, id, n * sizeof *id) == 0);
    free(rgba2), free(orgba), free(z2), free(nrm2), free(gz2), free(id2), free(oid);
}

/* Box "cube" called twice (instances 1 and 2): A near, B behind it and
 * partly hidden by it, through a rotated camera. */
static void test_two_boxes(void)
{
    static const box bx[2] = {{{-0.3, 0.1, 6}, {0.6, 0.5, 0.4}}, {{0.9, -0.2, 9}, {1.0, 0.8, 0.7}}};
    tb t;
    tb_init(&t);
    uint32_t cube = tb_object(&t, "cube", 0);
    tb_color(&t, 0.8, 0.6, 0.2, 1);
    tb_unit_cube(&t);
    tb_object(&t, "top", 1);
    for (int k = 0; k < 2; k++) {
        tb_op0(&t, GLS_OP_PUSH);
        tb_trans(&t, bx[k].c[0], bx[k].c[1], bx[k].c[2]);
        tb_scale(&t, 2 * bx[k].e[0], 2 * bx[k].e[1], 2 * bx[k].e[2]);
        tb_call(&t, cube);
        tb_op0(&t, GLS_OP_POP);
    }
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[512];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    CHECK(s.ninst == 3 && s.inst[1].parent == 0 && s.inst[2].parent == 0);
    double R[9], T[3] = {0.2, -0.1, 0.5};
    rot_yx(8, -6, R);
    gls_camera c = tb_camera(240, 180, 260, 255, 119.5, 89.5, 0.5, R, T, 0.1, 100);
    gt_run g;
    gt_run_start(&g, b, &s, &c);
    gls_renderer *r = g.r;
    size_t n = g.n;
    uint32_t *id = g.id;
    float *nrm = g.nrm, *z = g.z, *z0 = g.z0;
    /* the colour pass still works after it, and gives the same depth */
    gls_render_pass(r, &c, 0, 0);
    gls_render_read_z(r, z0);
    CHECK(memcmp(z, z0, n * sizeof *z) == 0);

    double h[2][16][2], zmin[2], zmax[2];
    int nh[2];
    for (int k = 0; k < 2; k++)
        nh[k] = footprint(&c, &bx[k], h[k], &zmin[k], &zmax[k]);
    CHECK(zmax[0] < zmin[1]); /* A wholly in front of B */
    long bad = 0, band = 0, count[3] = {0, 0, 0}, nbad = 0, nchecked = 0;
    double worst = 0;
    for (uint32_t v = 0; v < c.height; v++)
        for (uint32_t u = 0; u < c.width; u++) {
            size_t i = (size_t)v * c.width + u;
            double dA = inside((const double(*)[2])h[0], nh[0], u, v);
            double dB = inside((const double(*)[2])h[1], nh[1], u, v);
            /* exact up to the float rounding of the vertices */
            if (fabs(dA) < 1e-3 || fabs(dB) < 1e-3) {
                band++;
                continue;
            }
            uint32_t want = dA > 0 ? 1 + 1 : dB > 0 ? 2 + 1 : 0;
            count[want ? want - 1 : 0]++;
            if (id[i] != want) {
                if (bad++ < 5)
                    printf("  pixel (%u, %u): id %u, footprint says %u\n", u, v, id[i], want);
            }
            CHECK((id[i] == 0) == isinf(z[i]));
            /* normal: the face the ray enters first, in camera axes */
            if (!want)
                continue;
            double nw[3], margin;
            double tin = ray_box(&c, u, v, &bx[want - 2], nw, &margin);
            if (!isfinite(tin) || margin < 1e-4 * tin)
                continue;
            for (int j = 0; j < 3; j++) {
                double nc = c.R[3 * j] * nw[0] + c.R[3 * j + 1] * nw[1] + c.R[3 * j + 2] * nw[2];
                double e = fabs(nrm[3 * i + j] - nc);
                worst = fmax(worst, e);
                if (e > 1e-5 && nbad++ < 5)
                    printf("  pixel (%u, %u): normal[%d] %.8f, face %.8f\n", u, v, j, nrm[3 * i + j], nc);
            }
            nchecked++;
        }
    printf("  ids: %ld background, %ld box A, %ld box B pixels; %ld within 1e-3 px of an edge; %ld wrong\n",
           count[0], count[1], count[2], band, bad);
    printf("  normals: %ld pixels, largest error %.3g\n", nchecked, worst);
    CHECK(bad == 0);
    CHECK(count[1] > 1500 && count[2] > 1500 && count[0] > 10000 && band < 50);
    CHECK(nbad == 0 && nchecked > 4000);
    /* no surface: normal 0 0 0 */
    CHECK(id[0] == 0 && nrm[0] == 0 && nrm[1] == 0 && nrm[2] == 0);
    /* again, after a colour pass: the same ids, normals and depth, and
     * the colour pass's image untouched by it; any argument may be NULL */
    uint8_t *rgba = malloc(n * 4), *rgba2 = malloc(n * 4);
    uint32_t *id2 = malloc(n * sizeof *id2);
    float *nrm2 = malloc(n * 3 * sizeof *nrm2);
    gls_render_pass(r, &c, 0, 0);
    gls_render_read_rgba(r, rgba);
    CHECK(gls_gt_render(r, &c, id2, nrm2, NULL, err, sizeof err) == 0);
    CHECK(gls_gt_render(r, &c, NULL, NULL, z0, err, sizeof err) == 0);
    gls_render_read_rgba(r, rgba2);
    CHECK(memcmp(z, z0, n * sizeof *z) == 0);
    CHECK(memcmp(id, id2, n * sizeof *id) == 0);
    CHECK(memcmp(nrm, nrm2, n * 3 * sizeof *nrm) == 0);
    CHECK(memcmp(rgba, rgba2, n * 4) == 0);
    /* some rows only: the top, a middle band through both boxes, the
     * bottom, one row; another camera (moved) drew the rest */
    gls_camera o = c;
    o.T[0] += 0.4;
    static const uint32_t rr[4][2] = {{0, 20}, {70, 41}, {150, 30}, {95, 1}};
    for (int k = 0; k < 4; k++)
        rows_check(r, &c, &o, rr[k][0], rr[k][1], rgba, z0, id, nrm, z);
    free(rgba), free(rgba2), free(id2), free(nrm2);
    gt_run_end(&g);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

/* A textured quad whose texture has holes (alpha 0) and soft alpha
 * edges, in REPLACE and MODULATE: ids exactly where the image shows
 * the quad, for both anti-aliasing's centre pass and a plain one. */
static void test_alpha_holes(void)
{
    enum { TW = 16 };
    uint8_t tex[TW * TW * 4];
    for (int y = 0; y < TW; y++)
        for (int x = 0; x < TW; x++) {
            uint8_t *p = tex + 4 * (TW * y + x);
            p[0] = 200, p[1] = (uint8_t)(40 + 10 * x), p[2] = (uint8_t)(60 + 8 * y);
            /* a round hole and a diagonal slot */
            double dx = x - 5.5, dy = y - 9.5;
            p[3] = dx * dx + dy * dy < 12 || abs(x - y) < 2 ? 0 : 255;
        }
    tb t;
    tb_init(&t);
    uint32_t ti = tb_texture(&t, "holes", TW, TW, tex);
    tb_object(&t, "scene", 1);
    tb_u1(&t, GLS_OP_TEXTURE, ti);
    gls_vec4 p[4] = {{-1, -1, 5, 1}, {1, -1, 5.5, 1}, {1, 1, 5.2, 1}, {-1, 1, 4.7, 1}};
    gls_st st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    tb_u1(&t, GLS_OP_TEXMODE, GLS_MODE_REPLACE);
    tb_prim4(&t, GLS_PRIM_POLY, 4, p, NULL, st);
    tb_color(&t, 0.6, 0.7, 0.8, 0.9);
    tb_u1(&t, GLS_OP_TEXMODE, GLS_MODE_MODULATE);
    tb_trans(&t, 2.2, 0, 0);
    tb_prim4(&t, GLS_PRIM_POLY, 4, p, NULL, st);
    gls_bundle *b = tb_finish(&t);
    CHECK(b->features & GLS_FEAT_ALPHA_TEST);
    gls_scene s;
    char err[512];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    static const double I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double T[3] = {-1.1, 0, 0};
    gls_camera c = tb_camera(300, 140, 140, 140, 149.5, 69.5, 0, I3, T, 0.1, 100);
    gls_renderer *r = gls_renderer_create(ctx, b, &s, err, sizeof err);
    CHECK(r && gls_renderer_set_size(r, c.width, c.height, err, sizeof err) == 0);
    size_t n = (size_t)c.width * c.height;
    uint32_t *id = malloc(n * sizeof *id);
    uint8_t *rgba = malloc(n * 4);
    gls_render_pass(r, &c, 0, 0);
    gls_render_read_rgba(r, rgba);
    CHECK(gls_gt_render(r, &c, id, NULL, NULL, err, sizeof err) == 0);
    /* the quads' footprints, to count the pixels of their holes */
    double h[2][8][2];
    int nh[2];
    for (int q = 0; q < 2; q++) {
        double pp[4][2];
        for (int k = 0; k < 4; k++) {
            double P[3] = {p[k].x + 2.2 * q, p[k].y, p[k].z};
            project(&c, P, &pp[k][0], &pp[k][1]);
        }
        nh[q] = hull(4, pp, h[q]);
    }
    long mism = 0, shown = 0, holes = 0;
    for (size_t i = 0; i < n; i++) {
        int img = rgba[4 * i] || rgba[4 * i + 1] || rgba[4 * i + 2]; /* background black, texels never */
        shown += img;
        mism += img != (id[i] != 0);
        double u = (double)(i % c.width), v = (double)(i / c.width);
        holes += !img && (inside((const double(*)[2])h[0], nh[0], u, v) > 1 ||
                          inside((const double(*)[2])h[1], nh[1], u, v) > 1);
    }
    printf("  %ld pixels show the quads, %ld pixels of their holes, %ld differ from the ids\n", shown, holes,
           mism);
    CHECK(mism == 0 && shown > 3500 && holes > 1000);
    gls_renderer_destroy(r);
    free(id), free(rgba);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

/* A valley of two huge planes under the camera, reaching behind it: items
 * re-anchored at the camera and triangles clipped by the near plane keep
 * their normals (the triangle index survives clipping) and their depth. */
static void test_near_valley(void)
{
    tb t;
    tb_init(&t);
    tb_object(&t, "top", 1);
    tb_color(&t, 0.3, 0.6, 0.3, 1);
    /* left: y = 1 - 0.05 x for x <= 0; right: y = 1 + 0.05 x for x >= 0 */
    double L[4][3] = {{-100, 6, -100}, {0, 1, -100}, {0, 1, 100}, {-100, 6, 100}};
    double Rt[4][3] = {{0, 1, -100}, {100, 6, -100}, {100, 6, 100}, {0, 1, 100}};
    tb_poly(&t, 4, (const double(*)[3])L);
    tb_poly(&t, 4, (const double(*)[3])Rt);
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[512];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    double R[9], T[3] = {0.3, 0, 0};
    rot_yx(5, -12, R); /* looking a little down */
    gls_camera c = tb_camera(200, 150, 180, 180, 99.5, 74.5, 0, R, T, 0.05, 500);
    gt_run g;
    gt_run_start(&g, b, &s, &c);
    uint32_t *id = g.id;
    float *nrm = g.nrm;
    long checked = 0, bad = 0;
    double worst = 0;
    for (uint32_t v = 0; v < c.height; v++)
        for (uint32_t u = 0; u < c.width; u++) {
            size_t i = (size_t)v * c.width + u;
            /* the ray in the world, from C = -R^T T */
            double y = (v - c.cy) / c.fy, x = (u - c.cx) / c.fx, d[3], o[3];
            for (int j = 0; j < 3; j++) {
                d[j] = c.R[j] * x + c.R[3 + j] * y + c.R[6 + j];
                o[j] = -(c.R[j] * T[0] + c.R[3 + j] * T[1] + c.R[6 + j] * T[2]);
            }
            /* the plane y = 1 + s 0.05 x with the hit on its side */
            double nw[3] = {0, 0, 0};
            int hit = 0;
            for (int sd = -1; sd <= 1; sd += 2) {
                double tt = (1 - o[1] + sd * 0.05 * o[0]) / (d[1] - sd * 0.05 * d[0]);
                double hx = o[0] + tt * d[0], hz = o[2] + tt * d[2];
                if (tt > 0 && sd * hx > 1e-3 * tt && sd * hx < 100 && fabs(hz) < 100) {
                    nw[0] = -sd * 0.05, nw[1] = 1; /* (then facing the camera: above the planes) */
                    hit++;
                }
            }
            if (hit != 1)
                continue;
            double l = hypot(nw[0], nw[1]);
            CHECK(id[i] == 1);
            for (int j = 0; j < 3; j++) {
                /* facing the camera (above the valley): -n */
                double nc = -(c.R[3 * j] * nw[0] + c.R[3 * j + 1] * nw[1] + c.R[3 * j + 2] * nw[2]) / l;
                double e = fabs(nrm[3 * i + j] - nc);
                worst = fmax(worst, e);
                bad += e > 1e-5;
            }
            checked++;
        }
    printf("  %ld pixels of the valley, largest normal error %.3g\n", checked, worst);
    CHECK(bad == 0 && checked > 5000);
    gt_run_end(&g);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

int main(void)
{
    ctx = tb_glctx(GLS_BACKEND_AUTO, "test_gt_pass");
    RUN(test_two_boxes);
    RUN(test_alpha_holes);
    RUN(test_near_valley);
    gls_glctx_destroy(ctx);
    CHECK_EXIT();
}
