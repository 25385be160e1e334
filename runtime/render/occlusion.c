/* Occlusion culling's plan (occlusion.h): GL-free, so the padding and the
 * near-plane rule are tested without a context. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "occlusion.h"
#include "scene_cull.h"

/* Relative margin of a tested box: its faces lie this fraction of (box
 * size + distance) outside the item's own box.  Float rounding of the
 * item's vertices and of the box's is about 2^-24 (6e-8) of the distance
 * a few times over; 1e-4 keeps the box's front faces nearer than anything
 * inside it, in depth as GL computes it, for rays up to 89 degrees off the
 * optical axis, and costs nothing measurable in what is culled. */
#define PAD 1e-4

/* Rows of the inverse of W's linear part (row-major 4x4, affine): 0, or
 * -1 when it is singular or not finite. */
static int inverse3(const double W[16], double Wi[9])
{
    double a = W[0], b = W[1], c = W[2], d = W[4], e = W[5], f = W[6], g = W[8], h = W[9], k = W[10];
    double A = e * k - f * h, B = f * g - d * k, Cc = d * h - e * g;
    double det = a * A + b * B + c * Cc;
    if (!isfinite(det) || fabs(det) < 1e-300)
        return -1;
    double m[9] = {A, c * h - b * k, b * f - c * e, B, a * k - c * g, c * d - a * f, Cc, b * g - a * h, a * e - b * d};
    for (int i = 0; i < 9; i++)
        Wi[i] = m[i] / det;
    return 0;
}

int gls_occlusion_box(const gls_camera *c, const double C[3], const double W[16], const double plo[3],
                      const double phi[3], const double wlo[3], const double whi[3], double corner[8][3])
{
    double size = 0, d2 = 0;
    for (int j = 0; j < 3; j++) {
        double m = 0.5 * (wlo[j] + whi[j]) - C[j];
        size = fmax(size, whi[j] - wlo[j]);
        d2 += m * m;
    }
    double pad = PAD * (size + sqrt(d2)), Wi[9];
    if (W && inverse3(W, Wi) == 0) {
        /* the proto box under W, each face moved out by pad in the world:
         * face j's normal is row j of W^-1 over its length, so a step of
         * pad along it is pad * |row j| in proto units */
        double p[3];
        for (int j = 0; j < 3; j++)
            p[j] = pad * sqrt(Wi[3 * j] * Wi[3 * j] + Wi[3 * j + 1] * Wi[3 * j + 1] + Wi[3 * j + 2] * Wi[3 * j + 2]);
        for (int k = 0; k < 8; k++) {
            double q[3];
            for (int j = 0; j < 3; j++)
                q[j] = k >> j & 1 ? phi[j] + p[j] : plo[j] - p[j];
            for (int i = 0; i < 3; i++)
                corner[k][i] = W[4 * i] * q[0] + W[4 * i + 1] * q[1] + W[4 * i + 2] * q[2] + W[4 * i + 3] - C[i];
        }
    } else {
        for (int k = 0; k < 8; k++)
            for (int j = 0; j < 3; j++)
                corner[k][j] = (k >> j & 1 ? whi[j] + pad : wlo[j] - pad) - C[j];
    }
    for (int k = 0; k < 8; k++) {
        /* camera z of the corner: R (P - C), T = -R C cancelling exactly */
        double z = c->R[6] * corner[k][0] + c->R[7] * corner[k][1] + c->R[8] * corner[k][2];
        if (!(z > c->near * (1 + 1e-6)) || !isfinite(z))
            return -1;
    }
    return 0;
}

static const double *sort_key;
static int by_key(const void *pa, const void *pb)
{
    uint32_t a = *(const uint32_t *)pa, b = *(const uint32_t *)pb;
    if (sort_key[a] != sort_key[b])
        return sort_key[a] < sort_key[b] ? -1 : 1;
    return a < b ? -1 : a > b; /* deterministic among equals */
}

/* Distance from C to the box lo..hi (0 inside). */
static double box_distance(const double C[3], const double lo[3], const double hi[3])
{
    double d2 = 0;
    for (int j = 0; j < 3; j++) {
        double e = C[j] < lo[j] ? lo[j] - C[j] : C[j] > hi[j] ? C[j] - hi[j] : 0;
        d2 += e * e;
    }
    return sqrt(d2);
}

/* The 12 triangles of a box by its corners (occlusion.h bit order). */
static const uint8_t box_tris[GLS_OCCLUSION_BOX_VERTS] = {
    0, 2, 1, 1, 2, 3, /* z low  */ 4, 5, 6, 5, 7, 6, /* z high */
    0, 1, 4, 1, 5, 4, /* y low  */ 2, 6, 3, 3, 6, 7, /* y high */
    0, 4, 2, 2, 4, 6, /* x low  */ 1, 3, 5, 3, 7, 5, /* x high */
};

/* Units: runs of consecutive items of one instance in the drawing order
 * o->items[0 .. nitems_in) (an instance's items share its distance, so
 * they follow each other), tested as one (the union of their boxes): one
 * query for a tree in four cells rather than four. */
static void make_units(gls_occlusion *o, const gls_scene *s)
{
    o->nunits = 0;
    for (uint32_t k = 0; k < o->nitems_in; k++) {
        const gls_item *it = &s->items[o->items[k]];
        const gls_chunk *ch = &s->chunks[it->chunk];
        uint32_t u = o->nunits;
        if (u && s->items[o->items[k - 1]].inst == it->inst && o->unit_n[u - 1] < GLS_OCCLUSION_UNIT_ITEMS) {
            u--;
            o->unit_n[u]++;
            for (int j = 0; j < 3; j++) {
                o->lo[3 * u + j] = fmin(o->lo[3 * u + j], it->lo[j]);
                o->hi[3 * u + j] = fmax(o->hi[3 * u + j], it->hi[j]);
                o->plo[3 * u + j] = fmin(o->plo[3 * u + j], ch->lo[j]);
                o->phi[3 * u + j] = fmax(o->phi[3 * u + j], ch->hi[j]);
            }
        } else {
            o->unit_first[u] = k, o->unit_n[u] = 1, o->unit_verts[u] = 0, o->unit_area[u] = 0;
            memcpy(o->lo + 3 * u, it->lo, sizeof it->lo);
            memcpy(o->hi + 3 * u, it->hi, sizeof it->hi);
            memcpy(o->plo + 3 * u, ch->lo, sizeof ch->lo);
            memcpy(o->phi + 3 * u, ch->hi, sizeof ch->hi);
            o->nunits++;
        }
        o->unit_verts[u] += ch->count;
        double sc = s->inst[it->inst].scale;
        o->unit_area[u] += (double)ch->area * sc * sc;
    }
}

/* The units' boxes' projected areas (bounding rectangles within the
 * image) over the image's (o->overdraw): an upper bound on how often a
 * pixel is drawn over, and so on what occlusion can save.  And the
 * model of the geometry's own depth complexity (o->depth): each unit's
 * triangles' area (under its instance's scale, squared) seen at the
 * camera depth of its box's centre, facing the camera at a random
 * angle (half the area on average), at most its box's projected area;
 * summed over the image's.  Boxes that are mostly empty (scattered
 * triangles, sparse ribs) cover the image many times over while the
 * geometry covers it about once: then the first units drawn hide
 * nothing, whatever the boxes' overlap (occlusion.h). */
static void overdraw(gls_occlusion *o, const gls_camera *c)
{
    double area = 0, geo = 0, W = c->width, H = c->height;
    for (uint32_t u = 0; u < o->nunits; u++) {
        double b[4];
        gls_box_image_bounds(c, o->lo + 3 * u, o->hi + 3 * u, b);
        double w = fmin(b[2], W) - fmax(b[0], 0), h = fmin(b[3], H) - fmax(b[1], 0);
        if (!(w > 0 && h > 0))
            continue;
        area += w * h;
        double m[3], z = c->T[2];
        for (int j = 0; j < 3; j++)
            m[j] = 0.5 * (o->lo[3 * u + j] + o->hi[3 * u + j]);
        for (int j = 0; j < 3; j++)
            z += c->R[6 + j] * m[j];
        double g = z > c->near ? 0.5 * o->unit_area[u] * c->fx * c->fy / (z * z) : INFINITY;
        geo += fmin(g, w * h);
    }
    o->overdraw = area / (W * H);
    o->depth = geo / (W * H);
}

static int grow(gls_occlusion *o, uint32_t n)
{
    if (o->cap >= n)
        return 0;
    free(o->occluder), free(o->tested), free(o->key), free(o->items);
    free(o->unit_first), free(o->unit_n), free(o->unit_verts), free(o->unit_area), free(o->lo), free(o->hi);
    free(o->plo), free(o->phi), free(o->box_first), free(o->box_n), free(o->utested);
    o->occluder = malloc(n);
    o->unit_area = malloc(n * sizeof *o->unit_area);
    o->utested = malloc(n);
    o->box_first = malloc(n * sizeof *o->box_first);
    o->box_n = malloc(n * sizeof *o->box_n);
    o->tested = malloc(n * sizeof *o->tested);
    o->key = malloc(n * sizeof *o->key);
    o->items = malloc(n * sizeof *o->items);
    o->unit_first = malloc(n * sizeof *o->unit_first);
    o->unit_n = malloc(n * sizeof *o->unit_n);
    o->unit_verts = malloc(n * sizeof *o->unit_verts);
    o->lo = malloc(3 * n * sizeof *o->lo);
    o->hi = malloc(3 * n * sizeof *o->hi);
    o->plo = malloc(3 * n * sizeof *o->plo);
    o->phi = malloc(3 * n * sizeof *o->phi);
    o->cap = n;
    if (!o->occluder || !o->tested || !o->key || !o->items || !o->unit_first || !o->unit_n ||
        !o->unit_verts || !o->unit_area || !o->lo || !o->hi || !o->plo || !o->phi || !o->box_first || !o->box_n || !o->utested) {
        o->cap = 0;
        return -1;
    }
    return 0;
}

int gls_occlusion_faces(const double corner[8][3], uint8_t front[6])
{
    double mid[3] = {0, 0, 0};
    for (int k = 0; k < 8; k++)
        for (int j = 0; j < 3; j++)
            mid[j] += corner[k][j] / 8;
    int n = 0;
    for (int f = 0; f < 6; f++) {
        const uint8_t *q = box_tris + 6 * f;
        /* the face's centre (the mean of its two triangles' six corners:
         * each diagonal of the parallelogram has its middle there) and a
         * normal; the camera, at the origin, sees the face when it is on
         * the face's outer side: (centre - origin) . outward normal < 0 */
        double fc[3] = {0, 0, 0}, e1[3], e2[3], nrm[3];
        for (int j = 0; j < 3; j++) {
            for (int t = 0; t < 6; t++)
                fc[j] += corner[q[t]][j] / 6;
            e1[j] = corner[q[1]][j] - corner[q[0]][j], e2[j] = corner[q[2]][j] - corner[q[0]][j];
        }
        nrm[0] = e1[1] * e2[2] - e1[2] * e2[1];
        nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
        nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double out = 0, seen = 0;
        for (int j = 0; j < 3; j++)
            out += nrm[j] * (fc[j] - mid[j]), seen += nrm[j] * fc[j];
        front[f] = (out < 0 ? -seen : seen) < 0;
        n += front[f];
    }
    return n;
}

/* The faces of the box (corners relative to the camera centre) that face
 * the camera, as triangles: vertices of s's layout written at v; how
 * many. */
static uint32_t front_faces(const double corner[8][3], uint8_t *v, const gls_scene *s)
{
    uint8_t front[6];
    gls_occlusion_faces(corner, front);
    uint32_t n = 0;
    for (int f = 0; f < 6; f++) {
        if (!front[f])
            continue;
        for (int t = 0; t < 6; t++, v += s->stride, n++) {
            float p[3];
            for (int j = 0; j < 3; j++)
                p[j] = (float)corner[box_tris[6 * f + t]][j];
            memset(v, 0, s->stride);
            memcpy(v, p, sizeof p);
            if (s->has_color)
                memset(v + s->color_offset, 255, 4);
        }
    }
    return n;
}

/* Mark unit u's items in m. */
static void mark_unit(const gls_occlusion *o, uint32_t u, uint8_t *m)
{
    for (uint32_t k = 0; k < o->unit_n[u]; k++)
        m[o->items[o->unit_first[u] + k]] = 1;
}

int gls_occlusion_plan(gls_occlusion *o, gls_occlusion_mode mode, const gls_scene *s, const gls_camera *c,
                       const double C[3], const uint8_t *vis)
{
    o->ntested = 0, o->nunits = 0, o->nitems_in = 0, o->overdraw = 0, o->depth = 0, o->total_verts = 0;
    if (grow(o, s->nitems ? s->nitems : 1))
        return -1;
    /* the drawing order: the kept items by the distance from C to their
     * instance's world box, then by index (scene.h: by key, instance and
     * cell) */
    for (uint32_t i = 0; i < s->nitems; i++) {
        if (vis && !vis[i])
            continue;
        const gls_instance *in = &s->inst[s->items[i].inst];
        o->key[i] = box_distance(C, in->lo, in->hi);
        o->items[o->nitems_in++] = i;
    }
    sort_key = o->key;
    if (o->nitems_in > 1)
        qsort(o->items, o->nitems_in, sizeof *o->items, by_key);
    make_units(o, s);
    memset(o->occluder, 0, s->nitems);
    memset(o->utested, 0, o->nunits);
    uint64_t total = 0;
    uint32_t n = o->nunits;
    for (uint32_t u = 0; u < n; u++)
        total += o->unit_verts[u];
    o->total_verts = total;
    if (mode == GLS_OCCLUSION_OFF || n < 2)
        return 0;
    overdraw(o, c);
    if (mode == GLS_OCCLUSION_AUTO &&
        (total < GLS_OCCLUSION_MIN_VERTS || n < GLS_OCCLUSION_MIN_UNITS || o->overdraw < GLS_OCCLUSION_MIN_OVERDRAW ||
         o->depth < GLS_OCCLUSION_MIN_DEPTH))
        return 0;
    /* the nearest units, at least one, up to the share of the vertices:
     * drawn untested, first */
    uint64_t occ = 0;
    uint32_t k = 0;
    do {
        mark_unit(o, k, o->occluder);
        occ += o->unit_verts[k++];
    } while (k < n && (double)(occ + o->unit_verts[k]) <= GLS_OCCLUSION_OCCLUDER_SHARE * (double)total);
    size_t need = (size_t)(n - k) * GLS_PROTO_TEST_BOXES * GLS_OCCLUSION_FRONT_VERTS * s->stride;
    if (need > o->box_cap) {
        uint8_t *nb = realloc(o->boxes, need);
        if (!nb)
            return -1;
        o->boxes = nb, o->box_cap = need;
    }
    uint32_t nv = 0;
    for (uint32_t u = k; u < n; u++) {
        const gls_instance *in = &s->inst[s->items[o->items[o->unit_first[u]]].inst];
        const gls_proto *pr = &s->protos[in->proto];
        double corner[GLS_PROTO_TEST_BOXES][8][3];
        uint32_t nb = 0;
        int near = 0;
        for (uint32_t b = 0; b < pr->ntboxes && !near; b++) {
            /* the proto's test box clipped to the box of the unit's
             * chunks: each of the unit's triangles lies in both */
            const gls_tbox *t = &s->tboxes[pr->first_tbox + b];
            double lo[3], hi[3];
            int empty = 0;
            for (int j = 0; j < 3; j++) {
                lo[j] = fmax(t->lo[j], o->plo[3 * u + j]), hi[j] = fmin(t->hi[j], o->phi[3 * u + j]);
                empty |= !(lo[j] <= hi[j]);
            }
            if (empty)
                continue;
            near = gls_occlusion_box(c, C, in->world, lo, hi, o->lo + 3 * u, o->hi + 3 * u, corner[nb]) != 0;
            nb++;
        }
        if (near || !nb)
            continue; /* reaches the near plane: drawn untested, in its turn */
        o->box_first[u] = nv;
        for (uint32_t b = 0; b < nb; b++)
            nv += front_faces(corner[b], o->boxes + (size_t)nv * s->stride, s);
        o->box_n[u] = nv - o->box_first[u];
        o->utested[u] = 1;
        o->tested[o->ntested++] = u;
    }
    o->box_verts = nv;
    return o->ntested > 0;
}

void gls_occlusion_free(gls_occlusion *o)
{
    free(o->occluder), free(o->tested), free(o->key), free(o->boxes), free(o->items);
    free(o->unit_first), free(o->unit_n), free(o->unit_verts), free(o->unit_area), free(o->lo), free(o->hi);
    free(o->plo), free(o->phi), free(o->box_first), free(o->box_n), free(o->utested);
    memset(o, 0, sizeof *o);
}
