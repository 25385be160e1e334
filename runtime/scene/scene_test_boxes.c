/* Each proto's test boxes (scene.h, gls_scene.tboxes): up to
 * GLS_PROTO_TEST_BOXES boxes in the proto's frame whose union holds all of
 * its triangles, hugging them more closely than the proto's one box.
 * Occlusion culling draws them in its queries (occlusion.c): with a box
 * around a tree's trunk and a few around its crown, a far tree seen
 * through the gaps under near crowns is no longer taken as visible just
 * because the one box around it all shows there.
 *
 * How they are chosen: greedily, like the top of a bounding volume
 * hierarchy.  Start from one leaf holding every triangle.  A leaf's best
 * split is the plane, on one of 3 axes and between SPLIT_BINS bins of its
 * triangles' centres, that most reduces the cost of the two halves' boxes
 * (each the union of its triangles' own boxes, so that every triangle
 * lies wholly in its leaf's box).  The leaf whose best split gains most
 * is split, until there are GLS_PROTO_TEST_BOXES leaves or no split gains
 * SPLIT_MIN_GAIN of the proto box's cost.  The cost of a box is its
 * volume, each side taken at least THICK of the proto box's longest side
 * (so that flat geometry, a sign or a wall, is split by area): empty
 * volume is what lets a box show where its geometry would not.  Measured
 * on the bench's forest (make bench-instances): the tree gets a trunk box
 * and 7 crown slabs; surface area as the cost never splits its crown
 * (two halves of a round crown have more area than the whole), and 16
 * boxes hide 0.2 % more than 8 for more queries' triangles.
 * Deterministic: the same triangles in the same order give the same
 * boxes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene.h"

#define SPLIT_BINS 16
/* A split is taken only when it removes at least this share of the
 * proto box's cost. */
#define SPLIT_MIN_GAIN 0.005
/* The least side of a box, for its cost: this share of the proto box's
 * longest side. */
#define THICK (1.0 / 64)

static void box_empty(gls_tbox *b)
{
    for (int j = 0; j < 3; j++)
        b->lo[j] = INFINITY, b->hi[j] = -INFINITY;
}

static void box_union(gls_tbox *b, const gls_tbox *o)
{
    for (int j = 0; j < 3; j++)
        b->lo[j] = fmin(b->lo[j], o->lo[j]), b->hi[j] = fmax(b->hi[j], o->hi[j]);
}

/* The box's volume, each side at least thick (0 for an empty box). */
static double box_cost(const gls_tbox *b, double thick)
{
    if (!(b->lo[0] <= b->hi[0]))
        return 0;
    double v = 1;
    for (int j = 0; j < 3; j++)
        v *= fmax(b->hi[j] - b->lo[j], thick);
    return v;
}

static void tri_box(const double *e, gls_tbox *b)
{
    for (int j = 0; j < 3; j++) {
        b->lo[j] = fmin(e[j], fmin(e[3 + j], e[6 + j]));
        b->hi[j] = fmax(e[j], fmax(e[3 + j], e[6 + j]));
    }
}

/* A leaf: triangles perm[a .. b), their box and the range of their
 * centres, and its best split (gain <= 0: none). */
typedef struct {
    uint32_t a, b;
    gls_tbox bx;
    double clo[3], chi[3];
    double gain;
    int axis, bin; /* triangles in bins 0..bin on axis go left */
} leaf;

static int bin_of(const leaf *l, int axis, double c)
{
    double w = l->chi[axis] - l->clo[axis];
    int k = (int)((c - l->clo[axis]) / w * SPLIT_BINS);
    return k < 0 ? 0 : k >= SPLIT_BINS ? SPLIT_BINS - 1 : k;
}

/* The leaf's box, centre range and best split. */
static void leaf_scan(leaf *l, const uint32_t *perm, const double *exact, double thick)
{
    gls_tbox bins[3][SPLIT_BINS];
    uint32_t cnt[3][SPLIT_BINS];
    box_empty(&l->bx);
    for (int j = 0; j < 3; j++)
        l->clo[j] = INFINITY, l->chi[j] = -INFINITY;
    for (uint32_t i = l->a; i < l->b; i++) {
        gls_tbox t;
        tri_box(exact + 9 * (size_t)perm[i], &t);
        box_union(&l->bx, &t);
        for (int j = 0; j < 3; j++) {
            double c = 0.5 * (t.lo[j] + t.hi[j]);
            l->clo[j] = fmin(l->clo[j], c), l->chi[j] = fmax(l->chi[j], c);
        }
    }
    l->gain = 0;
    if (l->b - l->a < 2)
        return;
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < SPLIT_BINS; k++)
            box_empty(&bins[j][k]), cnt[j][k] = 0;
    for (uint32_t i = l->a; i < l->b; i++) {
        gls_tbox t;
        tri_box(exact + 9 * (size_t)perm[i], &t);
        for (int j = 0; j < 3; j++) {
            if (!(l->chi[j] > l->clo[j]))
                continue;
            int k = bin_of(l, j, 0.5 * (t.lo[j] + t.hi[j]));
            box_union(&bins[j][k], &t), cnt[j][k]++;
        }
    }
    double whole = box_cost(&l->bx, thick);
    for (int j = 0; j < 3; j++) {
        if (!(l->chi[j] > l->clo[j]))
            continue;
        gls_tbox right[SPLIT_BINS];
        uint32_t rn[SPLIT_BINS];
        box_empty(&right[SPLIT_BINS - 1]), rn[SPLIT_BINS - 1] = 0;
        box_union(&right[SPLIT_BINS - 1], &bins[j][SPLIT_BINS - 1]), rn[SPLIT_BINS - 1] = cnt[j][SPLIT_BINS - 1];
        for (int k = SPLIT_BINS - 2; k >= 0; k--) {
            right[k] = right[k + 1], rn[k] = rn[k + 1] + cnt[j][k];
            box_union(&right[k], &bins[j][k]);
        }
        gls_tbox left;
        uint32_t ln = 0;
        box_empty(&left);
        for (int k = 0; k + 1 < SPLIT_BINS; k++) {
            box_union(&left, &bins[j][k]), ln += cnt[j][k];
            if (!ln || !rn[k + 1])
                continue;
            double g = whole - box_cost(&left, thick) - box_cost(&right[k + 1], thick);
            if (g > l->gain)
                l->gain = g, l->axis = j, l->bin = k;
        }
    }
}

int gls_scene_test_boxes(gls_scene *s)
{
    uint32_t most = 0;
    for (uint32_t p = 0; p < s->nprotos; p++)
        if (s->protos[p].ntris > most)
            most = s->protos[p].ntris;
    s->tboxes = malloc((s->nprotos ? s->nprotos : 1) * (size_t)GLS_PROTO_TEST_BOXES * sizeof *s->tboxes);
    uint32_t *perm = malloc((most ? most : 1) * sizeof *perm);
    if (!s->tboxes || !perm) {
        free(perm);
        return -1;
    }
    s->ntboxes = 0;
    for (uint32_t p = 0; p < s->nprotos; p++) {
        gls_proto *pr = &s->protos[p];
        pr->first_tbox = s->ntboxes, pr->ntboxes = 0;
        if (!pr->nchunks || !pr->ntris)
            continue;
        const double *exact = s->exact + 3 * (size_t)s->chunks[pr->first_chunk].first;
        for (uint32_t i = 0; i < pr->ntris; i++)
            perm[i] = i;
        leaf lv[GLS_PROTO_TEST_BOXES];
        uint32_t n = 1;
        lv[0].a = 0, lv[0].b = pr->ntris;
        double thick = 0;
        for (int j = 0; j < 3; j++)
            thick = fmax(thick, pr->hi[j] - pr->lo[j]);
        thick *= THICK;
        leaf_scan(&lv[0], perm, exact, thick);
        double floor = SPLIT_MIN_GAIN * box_cost(&lv[0].bx, thick);
        while (n < GLS_PROTO_TEST_BOXES) {
            uint32_t best = 0;
            for (uint32_t k = 1; k < n; k++)
                if (lv[k].gain > lv[best].gain)
                    best = k;
            leaf *l = &lv[best];
            if (!(l->gain > floor))
                break;
            /* partition perm[a..b): left bins first (in place; the order
             * within a side does not matter to the boxes) */
            uint32_t i = l->a, j = l->b;
            while (i < j) {
                gls_tbox t;
                tri_box(exact + 9 * (size_t)perm[i], &t);
                if (bin_of(l, l->axis, 0.5 * (t.lo[l->axis] + t.hi[l->axis])) <= l->bin) {
                    i++;
                } else {
                    uint32_t x = perm[i];
                    perm[i] = perm[--j], perm[j] = x;
                }
            }
            leaf *r = &lv[n++];
            r->a = i, r->b = l->b;
            l->b = i;
            leaf_scan(l, perm, exact, thick);
            leaf_scan(r, perm, exact, thick);
        }
        for (uint32_t k = 0; k < n; k++) {
            s->tboxes[s->ntboxes++] = lv[k].bx;
        }
        pr->ntboxes = n;
    }
    free(perm);
    gls_tbox *fit = realloc(s->tboxes, (s->ntboxes ? s->ntboxes : 1) * sizeof *fit);
    if (fit)
        s->tboxes = fit;
    return 0;
}
