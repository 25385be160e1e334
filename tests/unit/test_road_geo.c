/* Road geometry and scene emission (roads/road_geo.c): chordal tolerance
 * of every edge, a band without cracks or overlaps, verges joined to the
 * road vertex for vertex, banking, fold detection, a 10 km road. */
#include <stdlib.h>
#include "check.h"
#include "road.h"
#include "road_load.h"


static const char *CURVY = "degree 3\n"
                           "point 0 0 0\npoint 0 0 60\npoint -10 0 110\npoint -45 2 160\npoint -60 3 220\n"
                           "point -30 2 280\npoint 20 0 310 2\npoint 60 0 360\npoint 60 0 430\n"
                           "lanes 2\nlane_width_at 0 3.5\nlane_width_at 200 3.0\nlane_width_at 300 3.75\n"
                           "shoulder 0.5\nverge 10\nbank_max 0.07\nbank_speed 20\ntolerance 0.001\n"
                           "speed_at distance 0 10\n";

/* Dense check: between consecutive stations, points of every edge at 63
   interior parameters lie within tol of the chord. */
static double worst_deviation(const road_geo *g, const road_edge *e, int ne, long *count)
{
    double *st;
    long n = road_stations(g, nurbs_umin(&g->c), nurbs_umax(&g->c), e, ne, &st);
    *count = n;
    double worst = 0;
    for (long k = 0; k + 1 < n; k++) {
        road_frame fa, fb, fm;
        road_frame_at(g, st[k], &fa);
        road_frame_at(g, st[k + 1], &fb);
        for (int i = 0; i < ne; i++) {
            rv3 A = road_edge_point(&fa, &e[i]), B = road_edge_point(&fb, &e[i]);
            for (int j = 1; j < 64; j++) {
                road_frame_at(g, st[k] + (st[k + 1] - st[k]) * j / 64, &fm);
                worst = fmax(worst, rv_seg_dist(road_edge_point(&fm, &e[i]), A, B));
            }
        }
    }
    free(st);
    return worst;
}

static void test_chordal_tolerance(void)
{
    road_desc d;
    road_geo g;
    if (load(CURVY, &d, &g))
        return check_failed_++, (void)0;
    road_edge e[4] = {{1, 0.5, 0, 10}, {1, 0.5, 0, 0}, {-1, -0.5, 0, 0}, {-1, -0.5, 0, -10}};
    long n1, n2;
    double w1 = worst_deviation(&g, e + 1, 2, &n1); /* the road band's edges */
    double w2 = worst_deviation(&g, e, 4, &n2);     /* with the verges' outer edges */
    CHECK_MSG(w1 <= d.tolerance, "road band: deviation %g > %g", w1, d.tolerance);
    CHECK_MSG(w2 <= d.tolerance, "with verges: deviation %g > %g", w2, d.tolerance);
    /* adaptive, not wasteful: the chord of a 1 mm deviation on these radii
       is metres long, so a few hundred stations */
    CHECK_MSG(n1 > 50 && n1 < 3000, "%ld stations", n1);
    CHECK(n2 >= n1);
    /* a coarser tolerance needs fewer stations, and still holds */
    d.tolerance = 0.05;
    long n3;
    double w3 = worst_deviation(&g, e + 1, 2, &n3);
    CHECK_MSG(w3 <= 0.05 && n3 < n1, "tol 0.05: deviation %g, %ld stations", w3, n3);
    road_geo_free(&g);
    road_desc_free(&d);
}

/* ---- the scene text, read back ------------------------------------------ */

typedef struct {
    char **v;    /* vertex texts, "x, y, z" */
    rv3 *p;      /* parsed */
    long n;
} strip;

/* The qstrip blocks after the comment line `section` and before the next
   comment line starting with "// " that is not a boundary marker. */
static int read_strips(const char *text, const char *section, strip *out, int max)
{
    const char *p = strstr(text, section);
    int ns = 0;
    if (!p)
        return 0;
    p += strlen(section);
    for (;;) {
        const char *q = strstr(p, "qstrip {");
        const char *c = strstr(p, "\n// ");
        if (!q || (c && c < q) || ns == max)
            break;
        const char *end = strstr(q, "}");
        strip *s = &out[ns++];
        s->n = 0;
        long cap = 1024;
        s->v = malloc(sizeof(char *) * cap);
        s->p = malloc(sizeof(rv3) * cap);
        for (const char *v = strstr(q, "vert("); v && v < end; v = strstr(v + 1, "vert(")) {
            const char *e = strchr(v, ')');
            if (s->n == cap) {
                cap *= 2;
                s->v = realloc(s->v, sizeof(char *) * cap);
                s->p = realloc(s->p, sizeof(rv3) * cap);
            }
            s->v[s->n] = strndup(v + 5, (size_t)(e - v - 5));
            char *r;
            s->p[s->n].x = strtod(v + 5, &r);
            s->p[s->n].y = strtod(r + 1, &r);
            s->p[s->n].z = strtod(r + 1, &r);
            s->n++;
        }
        p = end;
    }
    return ns;
}

static void free_strip(strip *s)
{
    for (long i = 0; i < s->n; i++)
        free(s->v[i]);
    free(s->v);
    free(s->p);
}

static void test_band_no_cracks(void)
{
    road_desc d;
    road_geo g;
    if (load(CURVY, &d, &g))
        return check_failed_++, (void)0;
    road_buf sc, tr, car;
    char err[1024];
    CHECK(road_emit_scene(&g, &sc, &tr, &car, err, sizeof err) == 0);
    strip road[2], verge[3];
    CHECK(read_strips(sc.text, "// road surface", road, 2) == 1);
    CHECK(read_strips(sc.text, "// verges", verge, 3) == 2);
    strip *r = &road[0];
    CHECK(r->n % 2 == 0 && r->n >= 4);
    CHECK(verge[0].n == r->n && verge[1].n == r->n);
    long bad_share = 0, bad_width = 0, bad_order = 0, bad_convex = 0;
    for (long k = 0; k + 1 < r->n / 2 * 2 && 2 * k + 1 < r->n; k++) {
        /* the verges' inner edges are the road's edges, character for
           character: no gap can open between them */
        if (strcmp(verge[0].v[2 * k + 1], r->v[2 * k]) || strcmp(verge[1].v[2 * k], r->v[2 * k + 1]))
            bad_share++;
        /* the band is as wide as the lanes and shoulders */
        rv3 L = r->p[2 * k], R = r->p[2 * k + 1];
        road_frame f;
        (void)f;
        double w = rv_len(rv_sub(L, R));
        if (w < 2 * 3.0 + 1 - 1e-9 || w > 2 * 3.75 + 1 + 1e-9)
            bad_width++;
    }
    /* No overlaps: quad k = (L_k, R_k, R_k+1, L_k+1).  Seen along its
       normal, each quad is convex with the same orientation as the first,
       and the next quad lies entirely ahead of the shared edge. */
    long nq = r->n / 2 - 1;
    rv3 up = rv(0, 1, 0);
    for (long k = 0; k < nq; k++) {
        rv3 q[4] = {r->p[2 * k], r->p[2 * k + 1], r->p[2 * k + 3], r->p[2 * k + 2]};
        for (int i = 0; i < 4; i++) {
            rv3 a = rv_sub(q[(i + 1) % 4], q[i]), b = rv_sub(q[(i + 2) % 4], q[(i + 1) % 4]);
            if (rv_dot(rv_cross(a, b), up) <= 0)
                bad_convex++;
        }
        if (k + 1 < nq) {
            /* the shared edge R_k+1 -> L_k+1; the far vertices of quad k+1
               must be on the far side of it (in the plane, horizontal) */
            rv3 A = r->p[2 * k + 2], B = r->p[2 * k + 3];
            rv3 edge = rv_sub(A, B);
            rv3 ahead = rv_cross(edge, up); /* left x up = forward */
            rv3 back = rv_sub(r->p[2 * k], B);
            if (rv_dot(back, ahead) >= 0)
                bad_order++; /* the previous quad should be behind */
            for (int j = 4; j <= 5; j++)
                if (rv_dot(rv_sub(r->p[2 * k + j], B), ahead) <= 0)
                    bad_order++;
        }
    }
    CHECK_MSG(bad_share == 0, "%ld stations where a verge does not share the road's edge vertex", bad_share);
    CHECK_MSG(bad_width == 0, "%ld stations with a wrong width", bad_width);
    CHECK_MSG(bad_convex == 0, "%ld quad corners not convex / flipped", bad_convex);
    CHECK_MSG(bad_order == 0, "%ld quads overlapping their neighbour", bad_order);
    /* the markings are inside the road band, one strip per dash for the
       dashed centre line: about length / 12 m of them */
    strip m[400];
    int nm = read_strips(sc.text, "// boundary 1: dashed", m, 400);
    CHECK_MSG(nm > (int)(g.c.length / 12) - 1 && nm <= (int)(g.c.length / 12) + 1, "%d dashes", nm);
    for (int i = 0; i < nm; i++)
        free_strip(&m[i]);
    free_strip(&road[0]);
    free_strip(&verge[0]);
    free_strip(&verge[1]);
    free(sc.text);
    free(tr.text);
    free(car.text);
    road_geo_free(&g);
    road_desc_free(&d);
}

static void test_fold_detected(void)
{
    /* a hairpin of radius ~4 m under a road 8 m wide: its inner edge
       would run backwards */
    const char *t = "degree 2\npoint 0 0 0\npoint 0 0 10 \npoint -8 0 10 0.7071067811865476\npoint -8 0 0\n"
                    "knots 0 0 0 0.5 1 1 1\nverge 0\nspeed_at distance 0 10\n";
    road_desc d;
    road_geo g;
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    road_buf sc, tr, car;
    char err[1024] = "";
    CHECK(road_emit_scene(&g, &sc, &tr, &car, err, sizeof err) == -1);
    CHECK_MSG(strstr(err, "test.road: error: the road folds over itself") != NULL, "%s", err);
    road_geo_free(&g);
    road_desc_free(&d);
}

/* A circular arc of radius 200 m (rational quadratic): banking to
   min(v^2 / (g R), bank_max), the left side low in a left curve. */
static void test_bank(void)
{
    char t[1024];
    double R = 200, w = sqrt(0.5);
    for (int pass = 0; pass < 2; pass++) {
        double bank_max = pass ? 0.02 : 0.1, v = 20;
        /* a quarter circle from the origin heading +z, turning left (+x)
           about the centre (R, 0, 0) */
        snprintf(t, sizeof t,
                 "degree 2\npoint 0 0 0\npoint 0 0 %.17g %.17g\npoint %.17g 0 %.17g\n"
                 "bank_max %g\nbank_speed %g\nspeed_at distance 0 10\n",
                 R, w, R, R, bank_max, v);
        road_desc d;
        road_geo g;
        if (load(t, &d, &g))
            return check_failed_++, (void)0;
        double e_want = fmin(v * v / (9.81 * R), bank_max);
        road_frame f;
        road_frame_at(&g, 0.3, &f);
        CHECK_NEAR(f.kappa, 1 / R, 1e-12);
        CHECK_NEAR(g.c.length, M_PI / 2 * R, 1e-9);
        CHECK_NEAR(f.e, e_want, 1e-12);
        road_edge L = {1, 0.5, 0, 0}, Rr = {-1, -0.5, 0, 0};
        rv3 PL = road_edge_point(&f, &L), PR = road_edge_point(&f, &Rr);
        double dy = PL.y - PR.y, dh = hypot(PL.x - PR.x, PL.z - PR.z);
        CHECK_NEAR(dy / dh, -e_want, 1e-12); /* left side lower */
        CHECK_NEAR(rv_dot(f.n, f.t), 0, 1e-15);
        CHECK_NEAR(rv_dot(f.n, f.l), 0, 1e-15);
        CHECK_NEAR(rv_len(f.n), 1, 1e-15);
        CHECK(f.n.y > 0);
        road_geo_free(&g);
        road_desc_free(&d);
    }
}

/* 10 km of road whose end is 10 km from the origin: the tessellation holds
   the tolerance there, and the printed vertices are the computed doubles
   exactly (shortest round-trip printing). */
static void test_10km(void)
{
    const char *t = "degree 3\n"
                    "point 0 0 0\npoint 0 0 1500\npoint -1200 10 3000\npoint -400 25 4500\n"
                    "point 900 40 6000\npoint 300 30 7500\npoint -500 20 8600\npoint 0 10 9800\n"
                    "verge 0\nspeed_at distance 0 30\n";
    road_desc d;
    road_geo g;
    if (load(t, &d, &g))
        return check_failed_++, (void)0;
    CHECK_MSG(g.c.length > 10000 && g.c.length < 12000, "length %g", g.c.length);
    rv3 end = nurbs_point(&g.c, 1);
    CHECK(rv_len(end) > 9000);
    road_buf sc, tr, car;
    char err[1024];
    CHECK(road_emit_scene(&g, &sc, &tr, &car, err, sizeof err) == 0);
    strip r[2];
    CHECK(read_strips(sc.text, "// road surface", r, 2) == 1);
    road_edge e[2] = {{1, 0.5, 0, 0}, {-1, -0.5, 0, 0}};
    double *st;
    long n = road_stations(&g, 0, 1, e, 2, &st);
    CHECK(n * 2 == r[0].n);
    long mism = 0;
    for (long k = 0; k < n && 2 * k + 1 < r[0].n; k++) {
        road_frame f;
        road_frame_at(&g, st[k], &f);
        rv3 L = road_edge_point(&f, &e[0]), R = road_edge_point(&f, &e[1]);
        if (L.x != r[0].p[2 * k].x || L.y != r[0].p[2 * k].y || L.z != r[0].p[2 * k].z ||
            R.x != r[0].p[2 * k + 1].x || R.y != r[0].p[2 * k + 1].y || R.z != r[0].p[2 * k + 1].z)
            mism++;
    }
    CHECK_MSG(mism == 0, "%ld stations print differently from their doubles", mism);
    /* the tolerance holds over the whole 10 km */
    long cnt;
    double wd = worst_deviation(&g, e, 2, &cnt);
    CHECK_MSG(wd <= d.tolerance, "deviation %g", wd);
    free(st);
    free_strip(&r[0]);
    free(sc.text);
    free(tr.text);
    free(car.text);
    road_geo_free(&g);
    road_desc_free(&d);
}

int main(void)
{
    RUN(test_chordal_tolerance);
    RUN(test_band_no_cracks);
    RUN(test_fold_detected);
    RUN(test_bank);
    RUN(test_10km);
    CHECK_EXIT();
}
