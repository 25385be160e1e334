/* Exact coverage's edge segments (runtime/aa/exact.h, gls_exact_edges;
 * spec/outputs.md "Edge segments"): the segments against the outlines
 * known from the triangles, with the ids on the right sides.  A segment's
 * place is checked by both ends lying on an outline's side (within 1e-9
 * px) and the union by the lengths per side adding up to the side's
 * length. */
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include "check.h"
#include "exact.h"
#include "exact_int.h"

typedef struct {
    gls_exact_seg s[4096];
    size_t n;
} segs;

static void collect(void *user, const gls_exact_seg *s)
{
    segs *g = user;
    if (g->n < sizeof g->s / sizeof g->s[0])
        g->s[g->n++] = *s;
}

static gls_exact_tri tri(double x0, double y0, double x1, double y1, double x2, double y2, double iz, uint32_t id)
{
    return (gls_exact_tri){{x0, x1, x2}, {y0, y1, y2}, {iz, iz, iz}, id, {1, 1, 1, 1}, 0};
}

/* the square [x0, x1] x [y0, y1] as two triangles at depth iz */
static void square(gls_exact_tri *t, double x0, double y0, double x1, double y1, double iz, uint32_t id)
{
    t[0] = tri(x0, y0, x1, y0, x1, y1, iz, id);
    t[1] = tri(x0, y0, x1, y1, x0, y1, iz, id);
}

/* distance of point (x, y) from segment a-b */
static double dist_seg(double x, double y, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(x - ax - t * dx, y - ay - t * dy);
}

/* The outline of square [x0, x1] x [y0, y1] (id `in` inside, `out`
 * outside), as far as visible: sides[k] the visible length found on side
 * k (top, right, bottom, left); every segment on a side, ids right;
 * returns how many segments lie on no side */
static size_t on_outline(const segs *g, double x0, double y0, double x1, double y1, uint32_t in, uint32_t out,
                         double sides[4])
{
    const double c[5][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}};
    size_t off = 0;
    for (int k = 0; k < 4; k++)
        sides[k] = 0;
    for (size_t q = 0; q < g->n; q++) {
        const gls_exact_seg *s = &g->s[q];
        int found = -1;
        for (int k = 0; k < 4 && found < 0; k++)
            if (dist_seg(s->x0, s->y0, c[k][0], c[k][1], c[k + 1][0], c[k + 1][1]) <= 1e-9 &&
                dist_seg(s->x1, s->y1, c[k][0], c[k][1], c[k + 1][0], c[k + 1][1]) <= 1e-9)
                found = k;
        if (found < 0) {
            off++;
            continue;
        }
        sides[found] += hypot(s->x1 - s->x0, s->y1 - s->y0);
        /* the square's inside on the left of the walk: the left normal in
         * the image (y down) is (dy, -dx); the centre is on that side */
        double dx = s->x1 - s->x0, dy = s->y1 - s->y0;
        double side = (0.5 * (x0 + x1) - s->x0) * dy - (0.5 * (y0 + y1) - s->y0) * dx;
        uint32_t l = side > 0 ? in : out, r = side > 0 ? out : in;
        CHECK_MSG(s->left == l && s->right == r, "segment (%g,%g)-(%g,%g): ids %u|%u, want %u|%u", s->x0, s->y0,
                  s->x1, s->y1, s->left, s->right, l, r);
    }
    return off;
}

/* One square in front of the background: its outline, whole, ids 5 in
 * and 0 out; the diagonal the two triangles share is no edge. */
/* The walk hands the edges only the candidates with a visible part: 40
 * layers behind a nearer triangle, each crossing pixel (1, 1) (so no full
 * cover prunes them) but showing nowhere, are not handed out.  Before,
 * a pixel behind a terrain's silhouette had every layer as a candidate,
 * and the edges' per-pixel search over all of them took minutes on make
 * bench-aa's scene where the image takes a second. */
static int count_cands(void *user, const exact_prep *p, const exact_cand *c, size_t nc, int i, int j)
{
    (void)p, (void)c;
    if (i == 1 && j == 1)
        *(size_t *)user = nc;
    return 0;
}

static void test_edges_hidden_not_handed(void)
{
    gls_exact_tri t[42];
    /* in front: everything left of x = 1.1; the layers: left of x = 0.7,
     * each farther than the last; at the back, a cover of the whole image */
    t[0] = tri(1.1, -50, 1.1, 50, -50, 0, 1, 1);
    for (int k = 0; k < 40; k++)
        t[1 + k] = tri(0.7, -50, 0.7, 50, -50, 0, 0.5 - 0.01 * k, 3);
    t[41] = tri(-50, -50, 50, -50, 0, 50, 0.01, 2);
    size_t nc = 0;
    CHECK(exact_visit_cands(t, 42, 3, 3, count_cands, &nc) == 0);
    CHECK_MSG(nc == 2, "pixel (1, 1) handed %zu candidates, want 2 (the front one and the back cover)", nc);
}

static void test_edges_square(void)
{
    static segs g;
    gls_exact_tri t[2];
    double x0 = 1.3, y0 = 1.2, x1 = 4.7, y1 = 3.6, sides[4];
    square(t, x0, y0, x1, y1, 1, 5);
    g.n = 0;
    CHECK(gls_exact_edges(t, 2, 8, 6, NULL, collect, &g) == 0);
    CHECK_MSG(on_outline(&g, x0, y0, x1, y1, 5, 0, sides) == 0, "segments off the outline");
    CHECK_NEAR(sides[0], x1 - x0, 1e-9);
    CHECK_NEAR(sides[2], x1 - x0, 1e-9);
    CHECK_NEAR(sides[1], y1 - y0, 1e-9);
    CHECK_NEAR(sides[3], y1 - y0, 1e-9);
    /* an id map: the square's id 5 -> 9 */
    uint16_t map[6] = {0, 0, 0, 0, 0, 9};
    g.n = 0;
    CHECK(gls_exact_edges(t, 2, 8, 6, map, collect, &g) == 0);
    CHECK(g.n > 0 && on_outline(&g, x0, y0, x1, y1, 9, 0, sides) == 0);
}

/* Two overlapping squares of different instances: the front one's
 * outline whole, the back one's only where not behind the front one. */
static void test_edges_occluded(void)
{
    static segs g, back;
    gls_exact_tri t[4];
    square(t, 1.3, 1.2, 4.7, 3.6, 2, 1);     /* front, id 1 */
    square(t + 2, 3.1, 2.4, 6.6, 5.3, 1, 2); /* back, id 2  */
    g.n = 0;
    CHECK(gls_exact_edges(t, 4, 8, 7, NULL, collect, &g) == 0);
    /* the back square's own segments: those with id 2 on one side */
    back.n = 0;
    double len = 0;
    for (size_t q = 0; q < g.n; q++) {
        const gls_exact_seg *s = &g.s[q];
        len += hypot(s->x1 - s->x0, s->y1 - s->y0);
        if (s->left == 2 || s->right == 2)
            back.s[back.n++] = *s;
        /* nothing of the back square's outline inside the front square */
        double mx = 0.5 * (s->x0 + s->x1), my = 0.5 * (s->y0 + s->y1);
        CHECK_MSG(!(mx > 1.3 + 1e-9 && mx < 4.7 - 1e-9 && my > 1.2 + 1e-9 && my < 3.6 - 1e-9),
                  "segment inside the front square at (%g, %g)", mx, my);
    }
    /* the visible outline: the front's 2 (3.4 + 2.4) plus the back's
     * right and bottom sides (2.9 + 3.5) and its top and left sides
     * beyond the front square (6.6 - 4.7 and 5.3 - 3.6) */
    CHECK_NEAR(len, 2 * (3.4 + 2.4) + 2.9 + 3.5 + 1.9 + 1.7, 1e-9);
    double sides[4];
    /* the back square's pieces: on its outline, 2 inside, 1 or 0 outside */
    for (size_t q = 0; q < back.n; q++) {
        const gls_exact_seg *s = &back.s[q];
        uint32_t o = s->left == 2 ? s->right : s->left;
        CHECK_MSG(o == 0 || o == 1, "back square's segment against id %u", o);
    }
    segs *b0 = &back;
    size_t n = 0;
    for (size_t q = 0; q < back.n; q++) /* those against the background */
        if (back.s[q].left == 0 || back.s[q].right == 0)
            b0->s[n++] = back.s[q];
    b0->n = n;
    CHECK(on_outline(b0, 3.1, 2.4, 6.6, 5.3, 2, 0, sides) == 0);
    CHECK_NEAR(sides[0], 6.6 - 4.7, 1e-9);
    CHECK_NEAR(sides[3], 5.3 - 3.6, 1e-9);
    CHECK_NEAR(sides[1], 5.3 - 2.4, 1e-9);
    CHECK_NEAR(sides[2], 6.6 - 3.1, 1e-9);
}

/* Two triangles of one instance sharing an edge: no segment on it; of two
 * instances: one segment run there, ids on the right sides. */
static void test_edges_shared(void)
{
    static segs g;
    gls_exact_tri t[2];
    t[0] = tri(1.2, 1.1, 5.3, 1.4, 2.1, 4.6, 1, 3);
    t[1] = tri(5.3, 1.4, 2.1, 4.6, 5.9, 4.2, 1, 3);
    g.n = 0;
    CHECK(gls_exact_edges(t, 2, 7, 6, NULL, collect, &g) == 0);
    double on = 0, all = 0;
    for (size_t q = 0; q < g.n; q++) {
        const gls_exact_seg *s = &g.s[q];
        double l = hypot(s->x1 - s->x0, s->y1 - s->y0);
        all += l;
        if (dist_seg(s->x0, s->y0, 5.3, 1.4, 2.1, 4.6) <= 1e-9 && dist_seg(s->x1, s->y1, 5.3, 1.4, 2.1, 4.6) <= 1e-9)
            on += l;
    }
    CHECK_NEAR(on, 0, 0);
    double outline = hypot(4.1, 0.3) + hypot(0.9, 3.5) + hypot(0.6, 2.8) + hypot(3.8, 0.4);
    CHECK_NEAR(all, outline, 1e-9);
    t[1].id = 4;
    g.n = 0;
    CHECK(gls_exact_edges(t, 2, 7, 6, NULL, collect, &g) == 0);
    on = 0;
    for (size_t q = 0; q < g.n; q++) {
        const gls_exact_seg *s = &g.s[q];
        if (!(dist_seg(s->x0, s->y0, 5.3, 1.4, 2.1, 4.6) <= 1e-9 && dist_seg(s->x1, s->y1, 5.3, 1.4, 2.1, 4.6) <= 1e-9))
            continue;
        on += hypot(s->x1 - s->x0, s->y1 - s->y0);
        /* walking lexicographically (2.1, 4.6) -> (5.3, 1.4): triangle 0
         * (towards (1.2, 1.1)) is on the left as seen in the image */
        CHECK_MSG(s->x0 < s->x1 && s->left == 3 && s->right == 4, "ids %u|%u", s->left, s->right);
    }
    CHECK_NEAR(on, hypot(3.2, 3.2), 1e-9);
}

/* Two squares passing through each other: their equal-depth line is an
 * edge where one shows on each side. */
static void test_edges_interpenetrating(void)
{
    static segs g;
    gls_exact_tri t[4];
    /* id 1 tilted in x (nearer to the right), id 2 flat: equal at x = 3.4 */
    square(t, 1.2, 1.3, 5.6, 4.7, 1, 1);
    for (int k = 0; k < 2; k++)
        for (int v = 0; v < 3; v++)
            t[k].iz[v] = 1 + 0.1 * (t[k].x[v] - 3.4);
    square(t + 2, 1.2, 1.3, 5.6, 4.7, 1, 2);
    g.n = 0;
    CHECK(gls_exact_edges(t, 4, 7, 6, NULL, collect, &g) == 0);
    double on = 0;
    for (size_t q = 0; q < g.n; q++) {
        const gls_exact_seg *s = &g.s[q];
        if (fabs(s->x0 - 3.4) > 1e-9 || fabs(s->x1 - 3.4) > 1e-9)
            continue;
        on += fabs(s->y1 - s->y0);
        /* walking down (y grows): left in the image is +x, id 1 */
        CHECK_MSG(s->y1 > s->y0 && s->left == 1 && s->right == 2, "ids %u|%u", s->left, s->right);
    }
    CHECK_NEAR(on, 4.7 - 1.3, 1e-9);
}

static uint64_t rng = 88172645463325252ull;
static double urand(void) /* [0, 1) */
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* the id in front at (x, y), by brute force over all triangles: each's
 * 1/Zc by barycentric interpolation, the larger nearer, ties the lower
 * index; 0 where none covers */
static uint32_t id_at(const gls_exact_tri *t, size_t n, double x, double y)
{
    double best = -1;
    uint32_t id = 0;
    for (size_t k = 0; k < n; k++) {
        const double *X = t[k].x, *Y = t[k].y;
        double d = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
        double b1 = ((x - X[0]) * (Y[2] - Y[0]) - (y - Y[0]) * (X[2] - X[0])) / d;
        double b2 = ((X[1] - X[0]) * (y - Y[0]) - (Y[1] - Y[0]) * (x - X[0])) / d;
        double b0 = 1 - b1 - b2;
        if (b0 < 0 || b1 < 0 || b2 < 0)
            continue;
        double z = b0 * t[k].iz[0] + b1 * t[k].iz[1] + b2 * t[k].iz[2];
        if (z > best)
            best = z, id = t[k].id;
    }
    return id;
}

/* Random tilted triangles of five ids passing through each other: every
 * segment's ids are what a brute-force point query finds just beside its
 * middle (1e-7 px off), and no segment has one id on both sides. */
static void test_edges_random(void)
{
    static segs g;
    gls_exact_tri t[40];
    for (int k = 0; k < 40; k++) {
        double cx = 2 + 12 * urand(), cy = 2 + 8 * urand();
        for (int v = 0; v < 3; v++)
            t[k].x[v] = cx + 6 * (urand() - 0.5), t[k].y[v] = cy + 6 * (urand() - 0.5), t[k].iz[v] = 1 + urand();
        t[k].id = 1 + (uint32_t)(k % 5);
    }
    g.n = 0;
    CHECK(gls_exact_edges(t, 40, 16, 12, NULL, collect, &g) == 0);
    CHECK(g.n > 100 && g.n < sizeof g.s / sizeof g.s[0]);
    size_t bad = 0, checked = 0;
    for (size_t q = 0; q < g.n; q++) {
        const gls_exact_seg *s = &g.s[q];
        double dx = s->x1 - s->x0, dy = s->y1 - s->y0, l = hypot(dx, dy);
        bad += s->left == s->right;
        if (l < 1e-4)
            continue;
        double mx = 0.5 * (s->x0 + s->x1), my = 0.5 * (s->y0 + s->y1), nx = dy / l * 1e-7, ny = -dx / l * 1e-7;
        uint32_t a = id_at(t, 40, mx + nx, my + ny), b = id_at(t, 40, mx - nx, my - ny);
        checked++;
        if (a != s->left || b != s->right) {
            if (bad < 5)
                printf("  segment (%.9g,%.9g)-(%.9g,%.9g): ids %u|%u, brute force %u|%u\n", s->x0, s->y0, s->x1, s->y1,
                       s->left, s->right, a, b);
            bad++;
        }
    }
    CHECK_MSG(bad == 0, "%zu of %zu segments wrong", bad, checked);
    /* and none missing: along random rows, every change of the brute-force
     * id (bisected to 1e-11 px) lies on a segment */
    size_t changes = 0, missing = 0;
    for (int r = 0; r < 40; r++) {
        double y = -0.4 + 11.8 * urand(), x = -0.45;
        uint32_t prev = id_at(t, 40, x, y);
        for (; x + 0.01 < 15.5; x += 0.01) {
            uint32_t next = id_at(t, 40, x + 0.01, y);
            if (next == prev)
                continue;
            double lo = x, hi = x + 0.01;
            while (hi - lo > 1e-11) {
                double m = 0.5 * (lo + hi);
                if (id_at(t, 40, m, y) == prev)
                    lo = m;
                else
                    hi = m;
            }
            int found = 0;
            for (size_t q = 0; q < g.n && !found; q++)
                found = dist_seg(lo, y, g.s[q].x0, g.s[q].y0, g.s[q].x1, g.s[q].y1) <= 1e-8;
            changes++, missing += !found;
            prev = next;
        }
    }
    CHECK_MSG(changes > 50 && missing == 0, "%zu of %zu changes of id on no segment", missing, changes);
}

int main(void)
{
    RUN(test_edges_square);
    RUN(test_edges_occluded);
    RUN(test_edges_shared);
    RUN(test_edges_interpenetrating);
    RUN(test_edges_random);
    RUN(test_edges_hidden_not_handed);
    CHECK_EXIT();
}
