/* The chunk budget (scene_pack.h gls_pack_sort, issue 30): whatever the
 * triangles' distribution (scattered, clustered, in one cell), packing
 * makes at most the budget's chunks where the protos and keys allow, by
 * the smallest cell size that does; within the budget nothing changes
 * (cells of GLS_SCENE_CELL).  And the whole load: a scattered scene's
 * draw items within GLS_SCENE_CHUNK_BUDGET, its vertices where they were. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "player_scene.h"
#include "scene_pack.h"

static uint64_t rng = 88172645463325252ull;
static uint32_t rnd(uint32_t n)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (uint32_t)(rng % n);
}

static int64_t floordiv(int64_t c, unsigned level)
{
    int64_t d = (int64_t)1 << level, q = c / d;
    return q * d > c ? q - 1 : q;
}

/* Distinct (proto, key, cell of `level`) among t, by my own count. */
static gls_pack_tri *cmp_base;
static unsigned cmp_level;
static int by_cell(const void *pa, const void *pb)
{
    const gls_pack_tri *a = pa, *b = pb;
    if (a->proto != b->proto)
        return a->proto < b->proto ? -1 : 1;
    if (a->key.texture != b->key.texture)
        return a->key.texture < b->key.texture ? -1 : 1;
    for (int j = 0; j < 3; j++) {
        int64_t x = floordiv(a->cell[j], cmp_level), y = floordiv(b->cell[j], cmp_level);
        if (x != y)
            return x < y ? -1 : 1;
    }
    return 0;
}
static size_t distinct(const gls_pack_tri *t, size_t n, unsigned level)
{
    gls_pack_tri *c = malloc(n * sizeof *c);
    memcpy(c, t, n * sizeof *c);
    cmp_level = level, cmp_base = c;
    qsort(c, n, sizeof *c, by_cell);
    size_t d = 0;
    for (size_t i = 0; i < n; i++)
        d += i == 0 || by_cell(&c[i - 1], &c[i]) != 0;
    free(c);
    return d;
}

static void tri_at(gls_pack_tri *t, size_t i, uint32_t key, int64_t x, int64_t y, int64_t z)
{
    memset(t, 0, sizeof *t);
    t->key.texture = key, t->key.mode = GLS_MODE_COLOR;
    t->cell[0] = x, t->cell[1] = y, t->cell[2] = z;
    t->idx = (uint32_t)i;
}

/* The level gls_pack_sort chose is the smallest within the budget, and
 * the triangles are in order of that level's cells. */
static void check_level(gls_pack_tri *t, size_t n, size_t budget, unsigned level)
{
    size_t at = distinct(t, n, level);
    CHECK_MSG(at <= budget, "%zu chunks at level %u, budget %zu", at, level, budget);
    if (level)
        CHECK_MSG(distinct(t, n, level - 1) > budget, "level %u is not the smallest", level);
    cmp_level = level;
    size_t runs = 0;
    for (size_t i = 0; i < n; i++)
        runs += i == 0 || by_cell(&t[i - 1], &t[i]) != 0;
    CHECK_MSG(runs == at, "%zu runs for %zu cells: not sorted by them", runs, at);
}

/* 100,000 triangles scattered over a cube of 85 cells a side, as the
 * issue's random scene: nearly one cell each. */
static void test_pack_budget_scattered(void)
{
    size_t n = 100000;
    gls_pack_tri *t = malloc(n * sizeof *t);
    for (size_t i = 0; i < n; i++)
        tri_at(&t[i], i, GLS_NONE, (int64_t)rnd(85) - 42, (int64_t)rnd(85) - 42, rnd(85));
    CHECK(distinct(t, n, 0) > 80000);
    unsigned level = gls_pack_sort(t, n, 4096);
    CHECK(level > 0);
    check_level(t, n, 4096, level);
    free(t);
}

/* 6,000 clusters of 8 triangles, each cluster in a cell of its own, the
 * clusters far apart (up to 2^30 cells): the cells must grow a lot. */
static void test_pack_budget_clustered(void)
{
    size_t n = 48000;
    gls_pack_tri *t = malloc(n * sizeof *t);
    for (size_t k = 0; k < n / 8; k++) {
        int64_t x = (int64_t)rnd(1u << 30) - (1 << 29), y = rnd(1000), z = (int64_t)rnd(1u << 20) * 7;
        for (size_t i = 0; i < 8; i++)
            tri_at(&t[8 * k + i], 8 * k + i, GLS_NONE, x, y, z);
    }
    CHECK(distinct(t, n, 0) == n / 8);
    unsigned level = gls_pack_sort(t, n, 4096);
    check_level(t, n, 4096, level);
    /* and the cluster's triangles stay together, in emission order */
    int together = 1;
    for (size_t i = 1; i < n; i++)
        if (t[i].cell[0] == t[i - 1].cell[0] && t[i].cell[2] == t[i - 1].cell[2] && t[i].idx < t[i - 1].idx)
            together = 0;
    CHECK(together);
    free(t);
}

/* Everything in one cell: level 0, one chunk, the order of cells of
 * GLS_SCENE_CELL (Morton order, then emission order). */
static void test_pack_budget_single_cell(void)
{
    size_t n = 50000;
    gls_pack_tri *t = malloc(n * sizeof *t);
    for (size_t i = 0; i < n; i++) {
        tri_at(&t[i], i, GLS_NONE, -5, 7, 1000000);
        t[i].zorder = rnd(1u << 30);
    }
    CHECK(gls_pack_sort(t, n, 4096) == 0);
    CHECK(distinct(t, n, 0) == 1);
    int sorted = 1;
    for (size_t i = 1; i < n; i++)
        if (t[i].zorder < t[i - 1].zorder || (t[i].zorder == t[i - 1].zorder && t[i].idx < t[i - 1].idx))
            sorted = 0;
    CHECK(sorted);
    free(t);
}

/* Within the budget nothing changes: 4,096 triangles in 4,096 cells are
 * 4,096 chunks; one more cell and the level rises. */
static void test_pack_budget_edge(void)
{
    size_t n = 4097;
    gls_pack_tri *t = malloc(n * sizeof *t);
    for (size_t i = 0; i < n; i++)
        tri_at(&t[i], i, GLS_NONE, (int64_t)(i % 16) * 3, (int64_t)(i / 16 % 16) * 3, (int64_t)(i / 256) * 3);
    CHECK(gls_pack_sort(t, n - 1, 4096) == 0);
    CHECK(gls_pack_sort(t, n, 4096) > 0);
    free(t);
}

/* More keys than the budget, each scattered: no level brings them within
 * it, so the cells grow only until each key is one chunk (as few as the
 * top level makes), not to the top. */
static void test_pack_budget_keys(void)
{
    size_t n = 20000;
    gls_pack_tri *t = malloc(n * sizeof *t);
    for (size_t i = 0; i < n; i++)
        tri_at(&t[i], i, (uint32_t)(i % 5000), (int64_t)rnd(64), rnd(64), rnd(64));
    unsigned level = gls_pack_sort(t, n, 4096);
    size_t least = distinct(t, n, GLS_PACK_MAX_LEVEL);
    CHECK(least == 5000);
    CHECK(level < GLS_PACK_MAX_LEVEL);
    CHECK(distinct(t, n, level) == least);
    CHECK(level > 0 && distinct(t, n, level - 1) > least);
    free(t);
}

/* The whole load: 20,000 small triangles scattered over 8 km draw as at
 * most GLS_SCENE_CHUNK_BUDGET items, each vertex's float offset from its
 * chunk's anchor within float rounding of its exact position; a scene
 * within the budget keeps its cells of GLS_SCENE_CELL. */
static void test_pack_budget_scene(void)
{
    tb t;
    tb_init(&t);
    tb_object(&t, "cloud", 1);
    tb_color(&t, 0, 1, 0, 1);
    for (int k = 0; k < 20000; k++) {
        double x = rnd(8000) - 4000.0, y = rnd(8000) - 4000.0, z = rnd(8000) + 0.25;
        double tri[3][3] = {{x, y, z}, {x + 1.5, y, z}, {x, y + 1.5, z + 0.5}};
        tb_poly(&t, 3, tri);
    }
    gls_bundle *b = tb_finish(&t);
    gls_scene s;
    char err[256];
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    printf("  20,000 scattered triangles: %u chunks, %u items, cells of %g units\n", s.nchunks, s.nitems,
           ldexp(GLS_SCENE_CELL, (int)s.cell_level));
    CHECK(s.nitems <= GLS_SCENE_CHUNK_BUDGET && s.nchunks <= GLS_SCENE_CHUNK_BUDGET);
    CHECK(s.cell_level > 0);
    double worst = 0;
    for (uint32_t c = 0; c < s.nchunks; c++) {
        const gls_chunk *ch = &s.chunks[c];
        CHECK(ch->maxoff <= ldexp(GLS_SCENE_CELL, (int)s.cell_level));
        for (uint32_t v = ch->first; v < ch->first + ch->count; v++) {
            float off[3];
            memcpy(off, s.verts + (size_t)v * s.stride, sizeof off);
            for (int j = 0; j < 3; j++) {
                double e = fabs(ch->anchor[j] + off[j] - s.exact[3 * (size_t)v + j]);
                worst = fmax(worst, e / fmax(ch->maxoff, 1e-30));
            }
        }
    }
    CHECK_MSG(worst <= ldexp(1, -24), "offset error %g of maxoff", worst);
    gls_scene_free(&s);
    gls_bundle_free(b);
    /* within the budget: cells of GLS_SCENE_CELL */
    tb_init(&t);
    tb_object(&t, "few", 1);
    for (int k = 0; k < 100; k++) {
        double x = 100.0 * k, tri[3][3] = {{x, 0, 10}, {x + 1, 0, 10}, {x, 1, 10}};
        tb_poly(&t, 3, tri);
    }
    b = tb_finish(&t);
    CHECK(gls_scene_load(b, &s, err, sizeof err) == 0);
    CHECK(s.cell_level == 0 && s.nchunks == 100);
    gls_scene_free(&s);
    gls_bundle_free(b);
}

/* More keys than the budget, each in one cell already: level 0 makes
 * as few chunks as any level, so the cells stay at GLS_SCENE_CELL. */
static void test_pack_budget_keys_one_cell(void)
{
    size_t n = 20000;
    gls_pack_tri *t = malloc(n * sizeof *t);
    for (size_t i = 0; i < n; i++) {
        uint32_t k = (uint32_t)(i % 5000);
        tri_at(&t[i], i, k, (int64_t)(k % 17) * 1000, (int64_t)(k / 17) * 1000, 0);
    }
    CHECK(distinct(t, n, 0) == 5000);
    CHECK(gls_pack_sort(t, n, 4096) == 0);
    free(t);
}

/* The documented drawing order (scene_pack.h gls_pack_sort), for
 * test_pack_order: proto, key, cell of the level, GLS_SCENE_CELL cell,
 * Morton code, emission order. */
static int by_order(const void *pa, const void *pb)
{
    const gls_pack_tri *a = pa, *b = pb;
    int c = by_cell(pa, pb); /* proto, key, cell of the level */
    if (c)
        return c;
    for (int j = 0; j < 3; j++)
        if (a->cell[j] != b->cell[j])
            return a->cell[j] < b->cell[j] ? -1 : 1;
    if (a->zorder != b->zorder)
        return a->zorder < b->zorder ? -1 : 1;
    return a->idx < b->idx ? -1 : a->idx > b->idx;
}

/* gls_pack_sort's order is the documented one, whichever way it sorts:
 * one proto and key (by 64-bit keys), several keys (by comparisons),
 * cells around the origin and far from it, Morton codes with ties, at
 * the levels the budgets choose. */
static void test_pack_order(void)
{
    size_t n = 30000;
    gls_pack_tri *t = malloc(n * sizeof *t), *r = malloc(n * sizeof *r);
    const int64_t far[3] = {0, -(1ll << 40), 123456789};
    const size_t budgets[4] = {1000000, 4096, 300, 9};
    for (int c = 0; c < 24; c++) {
        int64_t span = c % 2 ? 90 : 7;
        for (size_t i = 0; i < n; i++) {
            tri_at(&t[i], i, c % 3 == 2 ? rnd(3) : 5, far[c % 3 == 1] + (int64_t)rnd((uint32_t)span) - span / 2,
                   (int64_t)rnd((uint32_t)span) - 3, far[(c / 2) % 3] + (int64_t)rnd((uint32_t)span));
            t[i].zorder = rnd(c % 4 < 2 ? 50 : 1u << 30);
        }
        memcpy(r, t, n * sizeof *t);
        unsigned level = gls_pack_sort(t, n, budgets[c % 4]);
        cmp_level = level;
        qsort(r, n, sizeof *r, by_order);
        size_t bad = 0;
        for (size_t i = 0; i < n; i++)
            bad += memcmp(&t[i], &r[i], sizeof *t) != 0;
        CHECK_MSG(bad == 0, "case %d (level %u): %zu triangles out of the documented order", c, level, bad);
    }
    free(t);
    free(r);
}

int main(void)
{
    RUN(test_pack_order);
    RUN(test_pack_budget_scattered);
    RUN(test_pack_budget_clustered);
    RUN(test_pack_budget_single_cell);
    RUN(test_pack_budget_edge);
    RUN(test_pack_budget_keys);
    RUN(test_pack_budget_keys_one_cell);
    RUN(test_pack_budget_scene);
    CHECK_EXIT();
}
