/* Occlusion culling (runtime/occlusion.h): the padded box contains its
 * geometry with the documented margin, in the oriented and the world-box
 * form; boxes reaching the near plane are never tested; and a scene built
 * to hide most of its instances behind a wall with alpha-tested holes
 * renders byte-identical colour and depth with occlusion culling on and
 * off (plain pass and a mosaic of jittered passes), while the culling
 * really skips items. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "occlusion.h"
#include "player.h"
#include "player_scene.h"

static gls_glctx *ctx;

/* Signed distance of X from the plane through a, b, c, positive on the
 * side of `inside`. */
static double plane_dist(const double a[3], const double b[3], const double c[3], const double inside[3],
                         const double X[3])
{
    double u[3], v[3], n[3];
    for (int i = 0; i < 3; i++)
        u[i] = b[i] - a[i], v[i] = c[i] - a[i];
    n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2], n[2] = u[0] * v[1] - u[1] * v[0];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), d = 0, s = 0;
    for (int i = 0; i < 3; i++)
        d += n[i] * (X[i] - a[i]) / len, s += n[i] * (inside[i] - a[i]);
    return s > 0 ? d : -d;
}

/* Smallest distance of X inside the box of 8 corners (bit order of
 * occlusion.h), negative when outside. */
static double inside_margin(double corner[8][3], const double X[3])
{
    double mid[3] = {0, 0, 0}, m = INFINITY;
    for (int k = 0; k < 8; k++)
        for (int i = 0; i < 3; i++)
            mid[i] += corner[k][i] / 8;
    for (int j = 0; j < 3; j++)
        for (int side = 0; side < 2; side++) {
            int f[4], n = 0;
            for (int k = 0; k < 8 && n < 4; k++)
                if ((k >> j & 1) == side)
                    f[n++] = k;
            m = fmin(m, plane_dist(corner[f[0]], corner[f[1]], corner[f[2]], mid, X));
        }
    return m;
}

static void test_box_margin(void)
{
    static const double I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double T0[3] = {0, 0, 0};
    gls_camera c = tb_camera(320, 240, 200, 200, 159.5, 119.5, 0, I3, T0, 0.5, 1000);
    double C[3] = {0, 0, 0};
    /* an instance turned, scaled unevenly and sheared, 40 units ahead */
    double a = 0.7, W[16] = {cos(a) * 2.0, 0.8, sin(a) * 0.5, 3, 0, 0.3, 0, -1, -sin(a) * 2.0, 0.1, cos(a) * 0.5, 40,
                             0, 0, 0, 1};
    double plo[3] = {-1, 0, -2}, phi[3] = {1, 4, 2}, wlo[3], whi[3], corner[8][3];
    for (int i = 0; i < 3; i++) { /* world box of the proto box's corners */
        wlo[i] = INFINITY, whi[i] = -INFINITY;
        for (int k = 0; k < 8; k++) {
            double q[3] = {k & 1 ? phi[0] : plo[0], k & 2 ? phi[1] : plo[1], k & 4 ? phi[2] : plo[2]};
            double x = W[4 * i] * q[0] + W[4 * i + 1] * q[1] + W[4 * i + 2] * q[2] + W[4 * i + 3];
            wlo[i] = fmin(wlo[i], x), whi[i] = fmax(whi[i], x);
        }
    }
    double size = 0, d2 = 0;
    for (int i = 0; i < 3; i++) {
        size = fmax(size, whi[i] - wlo[i]);
        d2 += pow(0.5 * (wlo[i] + whi[i]), 2);
    }
    double pad = 1e-4 * (size + sqrt(d2)); /* the documented margin */
    for (int form = 0; form < 2; form++) {
        CHECK(gls_occlusion_box(&c, C, form ? NULL : W, plo, phi, wlo, whi, corner) == 0);
        double worst = INFINITY;
        for (int k = 0; k < 8; k++) { /* the geometry's extreme points: the proto box's corners */
            double q[3] = {k & 1 ? phi[0] : plo[0], k & 2 ? phi[1] : plo[1], k & 4 ? phi[2] : plo[2]}, X[3];
            for (int i = 0; i < 3; i++)
                X[i] = W[4 * i] * q[0] + W[4 * i + 1] * q[1] + W[4 * i + 2] * q[2] + W[4 * i + 3];
            worst = fmin(worst, inside_margin(corner, X));
        }
        printf("  %s box: geometry at least %.3g inside (margin %.3g)\n", form ? "world" : "oriented", worst, pad);
        CHECK(worst >= 0.999 * pad);
        if (!form) { /* the oriented box is tighter: its volume is the proto box's under W */
            double e[3][3];
            for (int j = 0; j < 3; j++)
                for (int i = 0; i < 3; i++)
                    e[j][i] = corner[1 << j][i] - corner[0][i];
            double vol = fabs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                              e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                              e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]));
            double wvol = (whi[0] - wlo[0]) * (whi[1] - wlo[1]) * (whi[2] - wlo[2]);
            CHECK(vol < 0.5 * wvol);
        }
    }
    /* reaching the near plane (z 0.5): never tested */
    double nlo[3] = {-1, -1, 0.4}, nhi[3] = {1, 1, 3};
    CHECK(gls_occlusion_box(&c, C, NULL, nlo, nhi, nlo, nhi, corner) == -1);
    double blo[3] = {-1, -1, -5}, bhi[3] = {1, 1, -3}; /* behind the camera */
    CHECK(gls_occlusion_box(&c, C, NULL, blo, bhi, blo, bhi, corner) == -1);
    double flo[3] = {-1, -1, 0.6}, fhi[3] = {1, 1, 3}; /* in front, within the margin of near? no: 0.6 - pad */
    CHECK(gls_occlusion_box(&c, C, NULL, flo, fhi, flo, fhi, corner) == 0);
}

/* A unit cube at the origin (x, z -0.5..0.5, y -1..0). */
static void cube(tb *t)
{
    static const int f[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (int k = 0; k < 6; k++) {
        double q[4][3];
        for (int v = 0; v < 4; v++) {
            int c = f[k][v];
            q[v][0] = c & 1 ? 0.5 : -0.5, q[v][1] = c & 2 ? 0 : -1, q[v][2] = c & 4 ? 0.5 : -0.5;
        }
        tb_poly(t, 4, q);
    }
}

/* The scene: a wall 3 units ahead with a checker of alpha holes (the
 * occluders must keep its holes), 24 x 24 cubes behind it, turned,
 * scaled and some sheared, and two cubes reaching the near plane. */
static gls_bundle *hidden_scene(void)
{
    tb t;
    tb_init(&t);
    uint8_t tex[16 * 16 * 4];
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            uint8_t *p = tex + 4 * (16 * y + x);
            p[0] = (uint8_t)(16 * x), p[1] = 200, p[2] = (uint8_t)(16 * y);
            p[3] = (x / 4 + y / 4) % 2 && x % 4 && y % 4 ? 0 : 255; /* holes inside every other cell */
        }
    uint32_t tx = tb_texture(&t, "wall.png", 16, 16, tex);
    uint32_t cb = tb_object(&t, "cube", 0); /* objects in name order */
    cube(&t);
    tb_object(&t, "top", 1);
    tb_u1(&t, GLS_OP_TEXMODE, GLS_MODE_REPLACE);
    tb_u1(&t, GLS_OP_TEXTURE, tx);
    gls_vec4 p[4] = {{-6, -4, 3, 1}, {6, -4, 3, 1}, {6, 4, 3, 1}, {-6, 4, 3, 1}};
    gls_st st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    tb_prim4(&t, GLS_PRIM_POLY, 4, p, NULL, st);
    tb_op0(&t, GLS_OP_NOTEXTURE);
    for (int i = 0; i < 24; i++)
        for (int j = 0; j < 24; j++) {
            tb_color(&t, (i % 5) / 4.0, (j % 7) / 6.0, ((i + j) % 3) / 2.0, 1);
            tb_op0(&t, GLS_OP_PUSH);
            tb_trans(&t, 1.5 * (i - 12), 1.0, 8 + 2.0 * j);
            tb_rot(&t, (i * 37 + j * 11) % 90, 0, 1, 0);
            if ((i + j) % 5 == 0)
                tb_scale(&t, 1.3, 0.7, 1.1);
            if ((i * j) % 7 == 3) {
                double sh[16] = {1, 0.4, 0, 0, 0, 1, 0, 0, 0.3, 0, 1, 0, 0, 0, 0, 1};
                tb_insn(&t, GLS_OP_TRANSFORM, sh, NULL);
            }
            tb_call(&t, cb);
            tb_op0(&t, GLS_OP_POP);
        }
    for (int k = 0; k < 2; k++) { /* reach the near plane (0.5): drawn untested */
        tb_op0(&t, GLS_OP_PUSH);
        tb_trans(&t, k ? 2.5 : -2.5, 2.5, 0.6);
        tb_call(&t, cb);
        tb_op0(&t, GLS_OP_POP);
    }
    return tb_finish(&t);
}

static void test_same_image(void)
{
    static const double I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double T0[3] = {0, 0, 0};
    gls_camera c = tb_camera(320, 240, 200, 200, 159.5, 119.5, 0, I3, T0, 0.5, 1000);
    gls_bundle *b = hidden_scene();
    gls_scene s;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    gls_renderer *r = gls_renderer_create(ctx, b, &s, err, sizeof err);
    CHECK(r != NULL);
    if (!r)
        return;
    size_t n = (size_t)320 * 240;
    uint8_t *rgba[2] = {malloc(4 * n), malloc(4 * n)};
    float *z[2] = {malloc(4 * n), malloc(4 * n)};
    uint32_t occluded[2];
    CHECK(gls_renderer_set_size(r, 320, 240, err, sizeof err) == 0);
    for (int on = 0; on < 2; on++) {
        gls_renderer_set_occlusion(r, on ? GLS_OCCLUSION_ON : GLS_OCCLUSION_OFF);
        gls_render_pass(r, &c, 0, 0);
        occluded[on] = gls_render_occluded(r);
        gls_render_read_rgba(r, rgba[on]);
        gls_render_read_z(r, z[on]);
    }
    size_t diff = 0, holes = 0;
    for (size_t i = 0; i < 4 * n; i++)
        diff += rgba[0][i] != rgba[1][i];
    for (size_t i = 0; i < n; i++)
        holes += z[0][i] > 7.5 && z[0][i] < 1e30; /* cubes seen through the wall's holes or beside it */
    printf("  plain pass: %u of %u items occluded; %zu bytes differ; %zu pixels show cubes\n", occluded[1], s.nitems,
           diff, holes);
    CHECK(occluded[0] == 0 && occluded[1] > s.nitems / 4);
    CHECK(holes > 1000);
    CHECK(diff == 0 && memcmp(z[0], z[1], 4 * n) == 0);

    /* a 2 x 2 mosaic of jittered passes: each tile culls for itself */
    double du[4] = {-0.25, 0.25, -0.25, 0.25}, dv[4] = {-0.25, -0.25, 0.25, 0.25};
    uint8_t *m[2] = {malloc(16 * n), malloc(16 * n)};
    CHECK(gls_renderer_set_mosaic(r, 320, 240, 2, 2, err, sizeof err) == 0);
    for (int on = 0; on < 2; on++) {
        gls_renderer_set_occlusion(r, on ? GLS_OCCLUSION_ON : GLS_OCCLUSION_OFF);
        gls_render_tiles(r, &c, 4, du, dv);
        occluded[on] = gls_render_occluded(r);
        gls_render_read_mosaic(r, 2, m[on]);
    }
    printf("  mosaic: last tile %u items occluded\n", occluded[1]);
    CHECK(occluded[1] > s.nitems / 4);
    CHECK(memcmp(m[0], m[1], 16 * n) == 0);
    free(m[0]), free(m[1]);
    free(rgba[0]), free(rgba[1]), free(z[0]), free(z[1]);
    gls_renderer_destroy(r);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

int main(void)
{
    RUN(test_box_margin);
    ctx = tb_glctx(GLS_BACKEND_AUTO, "occlusion");
    RUN(test_same_image);
    gls_glctx_destroy(ctx);
    CHECK_EXIT();
}
