/* The CPU side of lighting and shadows (lighting.h, shadows.h), against
 * numbers formed here: lights in GL's eye frame through their instance's
 * world transform and the camera; the shadow map's fit and the matrix
 * from the camera's eye frame to the map, composed in double; a point
 * light's cube faces against GL's cube-map sampling rule. */
#include <stdlib.h>
#include "check.h"
#include "lighting.h"
#include "shadows.h"
#include "shadows_cube.h"

/* A scene of one instance (world = translate(10, 0, 0)) with a point
 * light, a directional one and two ambient ones, and one item (a box). */
static void make_scene(gls_scene *s, gls_instance *inst, gls_light *l, gls_item *it)
{
    memset(s, 0, sizeof *s);
    memset(inst, 0, sizeof *inst);
    static const double W[16] = {1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    memcpy(inst->world, W, sizeof W);
    l[0] = (gls_light){.kind = GLS_LIGHT_POINT, .p = {0, 2, 0, 1}, .rgb = {1, 0.5, 0.25}, .atten = 0.5};
    l[1] = (gls_light){.kind = GLS_LIGHT_DIRECTIONAL, .p = {0, 3, 3, 0}, .rgb = {2, 2, 2}};
    l[2] = (gls_light){.kind = GLS_LIGHT_AMBIENT, .rgb = {0.1, 0.2, 0.3}};
    l[3] = (gls_light){.kind = GLS_LIGHT_AMBIENT, .rgb = {0.1, 0.1, 0.1}};
    *it = (gls_item){.lo = {-1, 0, -1}, .hi = {1, 2, 1}};
    s->inst = inst, s->ninst = 1;
    s->lights = l, s->nlights = 4;
    s->items = it, s->nitems = 1;
}

static void test_lights_eye(void)
{
    gls_scene s;
    gls_instance inst;
    gls_light l[4];
    gls_item it;
    make_scene(&s, &inst, l, &it);
    /* the camera: rotated 90 degrees about y, centre (0, 0, -5) */
    gls_camera c = {.R = {0, 0, -1, 0, 1, 0, 1, 0, 0}, .T = {-5, 0, 0}};
    double pos[4 * GLS_MAX_LIGHTS], col[4 * GLS_MAX_LIGHTS], amb[3];
    CHECK(gls_lights_count(&s) == 2);
    CHECK(gls_lights_eye(&s, &c, pos, col, amb) == 2);
    /* point: world (10, 2, 0); camera R X + T = (0 - 5, 2, 10); eye (x, -y, -z) */
    CHECK_NEAR(pos[0], -5, 1e-15);
    CHECK_NEAR(pos[1], -2, 1e-15);
    CHECK_NEAR(pos[2], -10, 1e-15);
    CHECK(pos[3] == 1 && col[0] == 1 && col[1] == 0.5 && col[2] == 0.25 && col[3] == 0.5);
    /* directional: world (0, 3, 3) -> camera (-3, 3, 0), unit, no translation */
    CHECK_NEAR(pos[4], -sqrt(0.5), 1e-15);
    CHECK_NEAR(pos[5], -sqrt(0.5), 1e-15);
    CHECK_NEAR(pos[6], 0, 1e-15);
    CHECK(pos[7] == 0 && col[4] == 2 && col[7] == 0);
    CHECK_NEAR(amb[0], 0.2, 1e-15);
    CHECK_NEAR(amb[1], 0.3, 1e-15);
    CHECK_NEAR(amb[2], 0.4, 1e-15);
}

/* A point's map coordinates through S from the camera's eye frame equal
 * those through the light's own frame and projection, to 1e-9 texture
 * units, 1e6 units from the origin too; the box's corners land inside
 * 0..1 (the fit) with depth 1 nearest the light. */
static void test_shadow_matrix(void)
{
    gls_scene s;
    gls_instance inst;
    gls_light l[4];
    gls_item it;
    make_scene(&s, &inst, l, &it);
    for (int far = 0; far < 2; far++) {
        double D = far ? 1048576.0 : 0.0;
        for (int j = 0; j < 3; j++)
            it.lo[j] += j == 0 ? D : 0, it.hi[j] += j == 0 ? D : 0;
        const double L[3] = {0.6, 0.8, 0};
        gls_shadow_view v;
        CHECK(gls_shadow_fit(&s, L, NULL, 1024, &v) == 0);
        double P[16], S[16];
        gls_shadow_projection(&v, P);
        gls_camera c = {.R = {1, 0, 0, 0, -1, 0, 0, 0, -1}, .T = {-D, 0, 10}};
        gls_shadow_matrix(&v, &c, S);
        double worst = 0, lo_depth = 2, hi_depth = -1;
        for (int k = 0; k < 8; k++) {
            double X[3] = {k & 1 ? it.hi[0] : it.lo[0], k & 2 ? it.hi[1] : it.lo[1], k & 4 ? it.hi[2] : it.lo[2]};
            double e[4], le[4], clip[4], got[4];
            for (int i = 0; i < 3; i++) { /* GL eye of the camera and of the light */
                double sg = i ? -1 : 1;
                e[i] = sg * (c.R[3 * i] * X[0] + c.R[3 * i + 1] * X[1] + c.R[3 * i + 2] * X[2] + c.T[i]);
                le[i] = sg * (v.R[3 * i] * X[0] + v.R[3 * i + 1] * X[1] + v.R[3 * i + 2] * X[2] + v.T[i]);
            }
            e[3] = le[3] = 1;
            for (int i = 0; i < 4; i++) {
                clip[i] = P[4 * i] * le[0] + P[4 * i + 1] * le[1] + P[4 * i + 2] * le[2] + P[4 * i + 3];
                got[i] = S[4 * i] * e[0] + S[4 * i + 1] * e[1] + S[4 * i + 2] * e[2] + S[4 * i + 3];
            }
            double want[3] = {0.5 * clip[0] + 0.5, 0.5 * clip[1] + 0.5, clip[2]};
            for (int i = 0; i < 3; i++)
                worst = fmax(worst, fabs(got[i] - want[i]));
            CHECK(want[0] > 0 && want[0] < 1 && want[1] > 0 && want[1] < 1 && want[2] > 0 && want[2] < 1);
            lo_depth = fmin(lo_depth, want[2]), hi_depth = fmax(hi_depth, want[2]);
        }
        CHECK_MSG(worst < 1e-9, "S differs from the light's own projection by %g (far %d)", worst, far);
        /* the top-right corner (1, 2, *) faces the light: the greatest depth */
        CHECK(hi_depth > 0.98 && lo_depth < 0.02);
        CHECK_NEAR(v.texel, fmax(v.x1 - v.x0, v.y1 - v.y0) / 1024, 1e-15);
    }
}

/* A point light's cube faces against the GL specification's table 8.19:
 * for a direction d from the light, the face of its major axis draws the
 * point at d where a lookup with d samples it (NDC x = s_c / |m_a|, y =
 * t_c / |m_a|), with depth near / |m_a|; every face's R is a rotation; a
 * light 1e6 units away composes the same. */
static void test_cube_faces(void)
{
    /* (axis, sign) of each face and its s_c, t_c as +-(x, y, z) indices */
    static const int axis[6] = {0, 0, 1, 1, 2, 2}, sc_i[6] = {2, 2, 0, 0, 0, 0}, tc_i[6] = {1, 1, 2, 2, 1, 1};
    static const double sign[6] = {1, -1, 1, -1, 1, -1}, sc_s[6] = {-1, 1, 1, 1, 1, -1},
                        tc_s[6] = {-1, -1, 1, -1, -1, -1};
    double P[16], worst = 0;
    const double near = 0.001;
    gls_cube_projection(near, P);
    srand(7);
    for (int shift = 0; shift < 2; shift++) {
        double X[3] = {shift ? 1048576.0 : 0.5, -2, shift ? -524288.0 : 3};
        for (int k = 0; k < 2000; k++) {
            double d[3];
            for (int j = 0; j < 3; j++)
                d[j] = 4.0 * rand() / RAND_MAX - 2.0;
            int a = fabs(d[0]) >= fabs(d[1]) && fabs(d[0]) >= fabs(d[2]) ? 0 : fabs(d[1]) >= fabs(d[2]) ? 1 : 2;
            int f = 2 * a + (d[a] < 0);
            CHECK(axis[f] == a && sign[f] * d[a] > 0);
            double ma = fabs(d[a]), want[3] = {sc_s[f] * d[sc_i[f]] / ma, tc_s[f] * d[tc_i[f]] / ma, near / ma};
            gls_camera c;
            gls_cube_face_camera(X, f, near, &c);
            double pc[3], e[4], clip[4];
            for (int i = 0; i < 3; i++) /* R (X + d) + T, then GL's eye */
                pc[i] = c.R[3 * i] * (X[0] + d[0]) + c.R[3 * i + 1] * (X[1] + d[1]) + c.R[3 * i + 2] * (X[2] + d[2]) +
                        c.T[i];
            e[0] = pc[0], e[1] = -pc[1], e[2] = -pc[2], e[3] = 1;
            for (int i = 0; i < 4; i++)
                clip[i] = P[4 * i] * e[0] + P[4 * i + 1] * e[1] + P[4 * i + 2] * e[2] + P[4 * i + 3] * e[3];
            for (int i = 0; i < 3; i++)
                worst = fmax(worst, fabs(clip[i] / clip[3] - want[i]));
        }
    }
    CHECK_MSG(worst < 1e-9, "a cube face draws %g away from where GL samples it", worst);
    for (int f = 0; f < 6; f++) { /* rotations: R R^T = I, det 1 */
        gls_camera c;
        double X[3] = {0, 0, 0}, det;
        gls_cube_face_camera(X, f, near, &c);
        const double *R = c.R;
        det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) + R[2] * (R[3] * R[7] - R[4] * R[6]);
        CHECK_NEAR(det, 1.0, 1e-15);
    }
}

/* The near distance: 1e-4 of the farthest corner of the items' boxes;
 * the maps' memory. */
static void test_cube_near(void)
{
    gls_scene s;
    gls_instance inst;
    gls_light l[4];
    gls_item it;
    make_scene(&s, &inst, l, &it);
    double X[3] = {0, 0, 0}, far2 = 0;
    for (int k = 0; k < 8; k++) {
        double d2 = 0;
        for (int j = 0; j < 3; j++) {
            double v = (k >> j) & 1 ? it.hi[j] : it.lo[j];
            d2 += v * v;
        }
        far2 = fmax(far2, d2);
    }
    CHECK_NEAR(gls_cube_near(&s, X), 1e-4 * sqrt(far2), 1e-18);
    /* one point light (a cube map of six faces), one directional (a map) */
    s.shadow_res = 1024;
    CHECK(gls_shadows_points(&s) == 1);
    CHECK(gls_shadows_bytes(&s) == 7ull * 1024 * 1024 * 4);
}

int main(void)
{
    RUN(test_lights_eye);
    RUN(test_shadow_matrix);
    RUN(test_cube_faces);
    RUN(test_cube_near);
    CHECK_EXIT();
}
