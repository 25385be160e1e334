/* Packing the scene builder's triangles into chunks and draw items
 * (scene_pack.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene_pack.h"

static int key_cmp(const gls_drawkey *a, const gls_drawkey *b)
{
    if (a->texture != b->texture)
        return a->texture < b->texture ? -1 : 1;
    if (a->mode != b->mode)
        return a->mode < b->mode ? -1 : 1;
    return memcmp(a->rgba, b->rgba, 4);
}

/* Cell c's index among cells 2^level times as large: floor(c / 2^level)
 * (a right shift of a negative number is the implementation's choice). */
static int64_t coarse(int64_t c, unsigned level)
{
    return c >= 0 ? c >> level : -((-(c + 1)) >> level) - 1;
}

/* The drawing order: proto, key, cell of the chosen size (sort_level),
 * then the GLS_SCENE_CELL cell within it, Morton order in that, emission
 * order.  At level 0 the two cells are one. */
static unsigned sort_level;
static int tri_cmp(const void *pa, const void *pb)
{
    const gls_pack_tri *a = pa, *b = pb;
    if (a->proto != b->proto)
        return a->proto < b->proto ? -1 : 1;
    int k = key_cmp(&a->key, &b->key);
    if (k)
        return k;
    for (int j = 0; sort_level && j < 3; j++) {
        int64_t ca = coarse(a->cell[j], sort_level), cb = coarse(b->cell[j], sort_level);
        if (ca != cb)
            return ca < cb ? -1 : 1;
    }
    for (int j = 0; j < 3; j++)
        if (a->cell[j] != b->cell[j])
            return a->cell[j] < b->cell[j] ? -1 : 1;
    if (a->zorder != b->zorder)
        return a->zorder < b->zorder ? -1 : 1;
    return a->idx < b->idx ? -1 : a->idx > b->idx;
}

/* Items in drawing order: by key, then instance, then chunk. */
static const gls_scene *sort_scene;
static int item_cmp(const void *pa, const void *pb)
{
    const gls_item *a = pa, *b = pb;
    int k = key_cmp(&sort_scene->chunks[a->chunk].key, &sort_scene->chunks[b->chunk].key);
    if (k)
        return k;
    if (a->inst != b->inst)
        return a->inst < b->inst ? -1 : 1;
    return a->chunk < b->chunk ? -1 : a->chunk > b->chunk;
}

/* Area of the triangle of corners p[0..2], p[3..5], p[6..8]. */
static double tri_area(const double *p)
{
    double e1[3], e2[3];
    for (int j = 0; j < 3; j++)
        e1[j] = p[3 + j] - p[j], e2[j] = p[6 + j] - p[j];
    double x = e1[1] * e2[2] - e1[2] * e2[1], y = e1[2] * e2[0] - e1[0] * e2[2], z = e1[0] * e2[1] - e1[1] * e2[0];
    return 0.5 * sqrt(x * x + y * y + z * z);
}

/* Are a and b in one cell of level `level`? */
static int same_cell(const gls_pack_tri *a, const gls_pack_tri *b, unsigned level)
{
    for (int j = 0; j < 3; j++)
        if (coarse(a->cell[j], level) != coarse(b->cell[j], level))
            return 0;
    return 1;
}

int gls_pack_chunks(const gls_pack_input *w, gls_scene *s)
{
    double cell = ldexp(GLS_SCENE_CELL, (int)s->cell_level);
    s->verts = malloc(w->ntri ? w->ntri * 3 * s->stride : 1);
    s->chunks = malloc((w->ntri ? w->ntri : 1) * sizeof *s->chunks);
    if (!s->verts || !s->chunks)
        return -1;
    for (int j = 0; j < 3; j++)
        s->lo[j] = INFINITY, s->hi[j] = -INFINITY;
    for (size_t p = 0; p < s->nprotos; p++)
        for (int j = 0; j < 3; j++)
            s->protos[p].lo[j] = INFINITY, s->protos[p].hi[j] = -INFINITY;
    gls_chunk *ch = NULL;
    for (size_t i = 0; i < w->ntri; i++) {
        const gls_pack_tri *t = &w->tris[i];
        gls_proto *pr = &s->protos[t->proto];
        int new_proto = i == 0 || w->tris[i - 1].proto != t->proto;
        if (!ch || new_proto || key_cmp(&ch->key, &t->key) || !same_cell(&w->tris[i - 1], t, s->cell_level)) {
            if (new_proto)
                pr->first_chunk = s->nchunks;
            pr->nchunks++;
            ch = &s->chunks[s->nchunks++];
            ch->key = t->key;
            ch->first = (uint32_t)(i * 3);
            ch->count = 0;
            ch->maxoff = 0;
            ch->area = 0;
            for (int j = 0; j < 3; j++) {
                ch->anchor[j] = ((double)coarse(t->cell[j], s->cell_level) + 0.5) * cell;
                ch->lo[j] = INFINITY, ch->hi[j] = -INFINITY;
            }
        }
        pr->ntris++;
        for (int k = 0; k < 3; k++) {
            uint8_t *v = s->verts + (i * 3 + (size_t)k) * s->stride;
            const double *p = w->wpos + 9 * (size_t)t->idx + 3 * k;
            float off[3];
            for (int j = 0; j < 3; j++) {
                off[j] = (float)(p[j] - ch->anchor[j]);
                double d = fabs(p[j] - ch->anchor[j]);
                if (d > ch->maxoff)
                    ch->maxoff = d;
                /* positions are finite (the walk drops the rest): plain
                 * comparisons, not fmin's calls; the protos' and the
                 * scene's boxes are the chunks', merged below */
                if (p[j] < ch->lo[j])
                    ch->lo[j] = p[j];
                if (p[j] > ch->hi[j])
                    ch->hi[j] = p[j];
            }
            memcpy(v, off, sizeof off);
            if (s->has_color)
                memcpy(v + s->color_offset, w->wcol + 12 * (size_t)t->idx + 4 * k, 4);
            if (s->has_texcoord)
                memcpy(v + s->texcoord_offset, w->wtc + 6 * (size_t)t->idx + 2 * k, 8);
            if (s->lit) {
                memcpy(v + s->normal_offset, w->wnrm + 9 * (size_t)t->idx + 3 * k, 12);
                memcpy(v + s->specular_offset, w->wspec + 4 * (size_t)t->idx, 16);
            }
        }
        ch->count += 3;
        ch->area += (float)tri_area(w->wpos + 9 * (size_t)t->idx);
    }
    for (size_t p = 0; p < s->nprotos; p++) {
        gls_proto *pr = &s->protos[p];
        for (uint32_t k = pr->first_chunk; k < pr->first_chunk + pr->nchunks; k++)
            for (int j = 0; j < 3; j++) {
                pr->lo[j] = fmin(pr->lo[j], s->chunks[k].lo[j]), pr->hi[j] = fmax(pr->hi[j], s->chunks[k].hi[j]);
                s->lo[j] = fmin(s->lo[j], s->chunks[k].lo[j]), s->hi[j] = fmax(s->hi[j], s->chunks[k].hi[j]);
            }
    }
    return 0;
}

int gls_pack_exact(double *wpos, const gls_pack_tri *t, size_t n)
{
    /* in place, cycle by cycle: position i takes triangle t[i].idx's
     * nine doubles; done[] marks the positions filled */
    uint8_t *done = calloc(n / 8 + 1, 1);
    if (!done)
        return -1;
    for (size_t i = 0; i < n; i++) {
        if (done[i / 8] >> (i % 8) & 1)
            continue;
        double first[9];
        memcpy(first, wpos + 9 * i, sizeof first);
        size_t j = i;
        for (;;) {
            done[j / 8] |= (uint8_t)(1u << (j % 8));
            size_t k = t[j].idx;
            if (k == i) {
                memcpy(wpos + 9 * j, first, sizeof first);
                break;
            }
            memcpy(wpos + 9 * j, wpos + 9 * k, sizeof first);
            j = k;
        }
    }
    free(done);
    return 0;
}

int gls_pack_items(gls_scene *s)
{
    size_t n = 0;
    for (uint32_t i = 0; i < s->ninst; i++) {
        gls_instance *in = &s->inst[i];
        if (in->proto != GLS_NONE && s->protos[in->proto].nchunks == 0)
            in->proto = GLS_NONE; /* an object that draws nothing itself */
        in->nitems = in->proto == GLS_NONE ? 0 : s->protos[in->proto].nchunks;
        n += in->nitems;
    }
    if (n > GLS_SCENE_MAX_ITEMS)
        return -2;
    s->items = malloc((n ? n : 1) * sizeof *s->items);
    if (!s->items)
        return -1;
    for (uint32_t i = 0; i < s->ninst; i++) {
        const gls_instance *in = &s->inst[i];
        for (uint32_t k = 0; k < in->nitems; k++) {
            gls_item *it = &s->items[s->nitems++];
            it->inst = i;
            it->chunk = s->protos[in->proto].first_chunk + k;
        }
    }
    sort_scene = s;
    if (s->nitems)
        qsort(s->items, s->nitems, sizeof *s->items, item_cmp);
    for (uint32_t i = 0; i < s->nitems; i++)
        if (i == 0 || key_cmp(&s->chunks[s->items[i - 1].chunk].key, &s->chunks[s->items[i].chunk].key))
            s->nbatches++;
    return 0;
}

static unsigned bit_length(uint64_t v)
{
    unsigned b = 0;
    while (v)
        b++, v >>= 1;
    return b;
}

/* tri_cmp's order by one 64-bit key a triangle, where the triangles allow
 * it: one proto and key, in emission order (idx rising: a stable sort
 * keeps ties as tri_cmp's last rule does), and their cells' span small
 * enough that the coarse cell, the GLS_SCENE_CELL cell within it and the
 * Morton code fit 64 bits (a scattered scene over kilometres: about 50).
 * Then a stable radix sort of (key, index) pairs and a permutation in
 * place, not qsort's comparisons (tri_cmp was 5 % of issue 30's
 * one-camera run).  0, or -1 when it does not apply or memory is short
 * (t unchanged: qsort then). */
static int sort_by_keys(gls_pack_tri *t, size_t n, unsigned level)
{
    if (n < 2 || n > UINT32_MAX)
        return -1;
    int64_t lo[3], hi[3];
    for (int j = 0; j < 3; j++)
        lo[j] = hi[j] = coarse(t[0].cell[j], level);
    for (size_t i = 1; i < n; i++) {
        if (t[i].proto != t[0].proto || key_cmp(&t[i].key, &t[0].key) || t[i].idx <= t[i - 1].idx ||
            t[i].zorder >> 30 || t[0].zorder >> 30)
            return -1;
        for (int j = 0; j < 3; j++) {
            int64_t c = coarse(t[i].cell[j], level);
            lo[j] = c < lo[j] ? c : lo[j], hi[j] = c > hi[j] ? c : hi[j];
        }
    }
    unsigned bits[3], total = 3 * level + 30; /* the fine cells, the Morton code */
    for (int j = 0; j < 3; j++)
        total += bits[j] = bit_length((uint64_t)(hi[j] - lo[j]));
    if (total > 64)
        return -1;
    uint64_t *pair = malloc(4 * n * sizeof *pair); /* key, index; twice, for the passes */
    uint8_t *done = calloc(n / 8 + 1, 1);
    if (!pair || !done) {
        free(pair), free(done);
        return -1;
    }
    uint64_t *a = pair, *b = pair + 2 * n;
    for (size_t i = 0; i < n; i++) {
        uint64_t k = 0, fine = 0;
        for (int j = 0; j < 3; j++) {
            int64_t c = coarse(t[i].cell[j], level);
            k = k << bits[j] | (uint64_t)(c - lo[j]);
            /* the GLS_SCENE_CELL cell within the coarse one: 0 .. 2^level - 1 */
            fine = fine << level | (uint64_t)(t[i].cell[j] - c * ((int64_t)1 << level));
        }
        k = (k << (3 * level) | fine) << 30 | t[i].zorder;
        a[2 * i] = k, a[2 * i + 1] = i;
    }
    /* least significant byte first, each pass stable */
    for (unsigned shift = 0; shift < total; shift += 8) {
        size_t count[257] = {0};
        for (size_t i = 0; i < n; i++)
            count[(a[2 * i] >> shift & 0xff) + 1]++;
        for (int d = 0; d < 256; d++)
            count[d + 1] += count[d];
        for (size_t i = 0; i < n; i++) {
            size_t at = count[a[2 * i] >> shift & 0xff]++;
            b[2 * at] = a[2 * i], b[2 * at + 1] = a[2 * i + 1];
        }
        uint64_t *x = a;
        a = b, b = x;
    }
    /* t[i] = the old t[a[2 i + 1]], cycle by cycle */
    for (size_t i = 0; i < n; i++) {
        if (done[i / 8] >> (i % 8) & 1)
            continue;
        gls_pack_tri first = t[i];
        size_t j = i;
        for (;;) {
            done[j / 8] |= (uint8_t)(1u << (j % 8));
            size_t k = (size_t)a[2 * j + 1];
            if (k == i) {
                t[j] = first;
                break;
            }
            t[j] = t[k];
            j = k;
        }
    }
    free(pair), free(done);
    return 0;
}

/* Sort t into the drawing order of level `level`. */
static void sort_level_order(gls_pack_tri *t, size_t n, unsigned level)
{
    sort_level = level;
    if (n && sort_by_keys(t, n, level)) /* qsort(NULL, 0) is undefined */
        qsort(t, n, sizeof *t, tri_cmp);
}

/* Do a and b fall in one chunk at level `level`? */
static int same_chunk(const gls_pack_tri *a, const gls_pack_tri *b, unsigned level)
{
    return a->proto == b->proto && !key_cmp(&a->key, &b->key) && same_cell(a, b, level);
}

static uint64_t mix(uint64_t h, uint64_t v)
{
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return h * 0xff51afd7ed558ccdull;
}

/* How many chunks t (in any order) makes at level `level`, counted up to
 * cap + 1 (a count above cap is cap + 1): its distinct (proto, key, cell)
 * triples, in a hash table of slots (UINT32_MAX: empty) rather than by
 * sorting, so that trying a level costs one pass, and only as large as
 * the count it can reach (a scene of millions of triangles within the
 * budget needs a table of twice the budget, not of its triangles).  -1
 * when out of memory. */
static long long count_level(const gls_pack_tri *t, size_t n, unsigned level, size_t cap)
{
    if (cap > n)
        cap = n; /* there are at most n */
    size_t nslots = 2;
    while (nslots < 2 * (cap + 1))
        nslots *= 2;
    uint32_t *slot = malloc(nslots * sizeof *slot);
    if (!slot)
        return -1;
    memset(slot, 0xff, nslots * sizeof *slot);
    size_t distinct = 0;
    for (size_t i = 0; i < n && distinct <= cap; i++) {
        const gls_pack_tri *a = &t[i];
        uint64_t h = mix(mix(a->proto, a->key.texture), (uint64_t)a->key.mode << 32 | (uint64_t)a->key.rgba[0] << 24 |
                                                          (uint64_t)a->key.rgba[1] << 16 | (uint64_t)a->key.rgba[2] << 8 |
                                                          a->key.rgba[3]);
        for (int j = 0; j < 3; j++)
            h = mix(h, (uint64_t)coarse(a->cell[j], level));
        size_t k = (size_t)(h >> 20) & (nslots - 1);
        while (slot[k] != UINT32_MAX && !same_chunk(&t[slot[k]], a, level))
            k = (k + 1) & (nslots - 1);
        if (slot[k] == UINT32_MAX)
            slot[k] = (uint32_t)i, distinct++;
    }
    free(slot);
    return (long long)distinct;
}

unsigned gls_pack_sort(gls_pack_tri *t, size_t n, size_t budget)
{
    /* the common case: within the budget at GLS_SCENE_CELL, one sort (a
     * pass counting at most budget + 1 chunks decides it; n <= budget
     * needs none).  n is below 2^28 (GLS_SCENE_MAX_VERTS / 3): indices
     * fit 32 bits */
    long long at0 = n <= budget ? 0 : count_level(t, n, 0, budget);
    if (at0 < 0 || (size_t)at0 <= budget) { /* out of memory: as sorted */
        sort_level_order(t, n, 0);
        return 0;
    }
    /* The count falls (or stays) as the level rises, each cell the union
     * of eight of the level below; at the top level the box of every
     * vertex (GLS_SCENE_MAX_COORD) spans two cells an axis, so its count
     * is the least there is: at most eight a proto and key.  Aim for the
     * budget, or that least count where the protos and keys alone exceed
     * it; the smallest level that reaches the aim, by bisection, each try
     * a pass; then one sort, in that level's order.  Out of memory: cells
     * of GLS_SCENE_CELL. */
    long long least = count_level(t, n, GLS_PACK_MAX_LEVEL, budget);
    if (least > (long long)budget)
        least = count_level(t, n, GLS_PACK_MAX_LEVEL, n);
    unsigned lo = 0, hi = GLS_PACK_MAX_LEVEL; /* count(lo) > aim >= count(hi) */
    size_t aim = least > (long long)budget ? (size_t)least : budget;
    if (least > (long long)budget) { /* level 0 may reach that aim */
        long long c = count_level(t, n, 0, aim);
        if (c >= 0 && (size_t)c <= aim)
            least = -1; /* then level 0: no bisection */
    }
    while (least >= 0 && hi - lo > 1) { /* least < 0: level 0 */
        unsigned mid = (lo + hi) / 2;
        long long c = count_level(t, n, mid, aim);
        if (c < 0)
            least = -1;
        else if ((size_t)c <= aim)
            hi = mid;
        else
            lo = mid;
    }
    if (least < 0)
        hi = 0;
    sort_level_order(t, n, hi);
    return hi;
}
