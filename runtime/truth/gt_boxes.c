/* Object boxes from the ground truth (gt_boxes.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "gt_boxes.h"
#include "vec.h"

int gls_box_occlusion_level(double visible)
{
    return visible >= 0.9 ? 0 : visible >= 0.5 ? 1 : 2;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* The sorted distinct ids above 1 (instance 0 left out) in ids[0..n). */
static uint32_t *distinct_ids(const uint32_t *ids, size_t n, size_t *k)
{
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        m += ids[i] > 1;
    uint32_t *v = malloc(m ? m * sizeof *v : 1);
    if (!v)
        return NULL;
    m = 0;
    for (size_t i = 0; i < n; i++)
        if (ids[i] > 1)
            v[m++] = ids[i];
    qsort(v, m, sizeof *v, cmp_u32);
    size_t u = 0;
    for (size_t i = 0; i < m; i++)
        if (u == 0 || v[u - 1] != v[i])
            v[u++] = v[i];
    *k = u;
    return v;
}

/* The tight 2D boxes and pixel counts (ids sorted in v; mm: k rows of
 * scratch for the pixel bounds u0 v0 u1 v1). */
static void boxes_2d(const uint32_t *ids, uint32_t w, uint32_t h, const uint32_t *v, gls_box *b, size_t k,
                     uint32_t (*mm)[4])
{
    for (size_t j = 0; j < k; j++)
        mm[j][0] = mm[j][1] = UINT32_MAX, mm[j][2] = mm[j][3] = 0;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            uint32_t id = ids[(size_t)y * w + x];
            if (id <= 1)
                continue;
            const uint32_t *p = bsearch(&id, v, k, sizeof *v, cmp_u32);
            size_t j = (size_t)(p - v);
            b[j].pixels++;
            if (x < mm[j][0]) mm[j][0] = x;
            if (y < mm[j][1]) mm[j][1] = y;
            if (x > mm[j][2]) mm[j][2] = x;
            if (y > mm[j][3]) mm[j][3] = y;
        }
    /* pixel (x, y) spans x - 0.5 .. x + 0.5 (centres at whole numbers) */
    for (size_t j = 0; j < k; j++) {
        b[j].bbox[0] = mm[j][0] - 0.5, b[j].bbox[1] = mm[j][1] - 0.5;
        b[j].bbox[2] = mm[j][2] + 0.5, b[j].bbox[3] = mm[j][3] + 0.5;
    }
}

static rv3 to_cam(const gls_camera *c, rv3 p)
{
    rv3 q = rm_apply(c->R, p);
    return rv(q.x + c->T[0], q.y + c->T[1], q.z + c->T[2]);
}

double gls_box_truncation_of(const gls_camera *c, double u0, double v0, double u1, double v1)
{
    if (!(u1 >= u0 && v1 >= v0))
        return 1; /* wholly nearer than near */
    double area = (u1 - u0) * (v1 - v0);
    if (!(area > 0))
        return 0;
    double iu = fmin(u1, c->width - 0.5) - fmax(u0, -0.5), iv = fmin(v1, c->height - 0.5) - fmax(v0, -0.5);
    double in = iu > 0 && iv > 0 ? iu * iv : 0;
    return 1 - in / area;
}

/* Fraction of the 3D box's image outside the image: the bounding
 * rectangle of its corners' projections (the box clipped at the near
 * plane first) against the image's [-0.5, W - 0.5] x [-0.5, H - 0.5]. */
static double truncation(const gls_camera *c, const double k[8][3])
{
    double u0 = INFINITY, v0 = INFINITY, u1 = -INFINITY, v1 = -INFINITY;
    for (int a = 0; a < 8; a++)
        for (int bit = 0; bit < 4; bit++) {
            /* bit 3: the corner itself; else the edge to the corner with
             * that bit set, where it crosses the near plane */
            double p[3];
            if (bit == 3) {
                if (k[a][2] < c->near)
                    continue;
                memcpy(p, k[a], sizeof p);
            } else {
                int b = a | (1 << bit);
                if (b == a || (k[a][2] < c->near) == (k[b][2] < c->near))
                    continue;
                double t = (c->near - k[a][2]) / (k[b][2] - k[a][2]);
                for (int j = 0; j < 3; j++)
                    p[j] = k[a][j] + t * (k[b][j] - k[a][j]);
                p[2] = c->near;
            }
            double u = (c->fx * p[0] + c->skew * p[1]) / p[2] + c->cx, v = c->fy * p[1] / p[2] + c->cy;
            u0 = fmin(u0, u), u1 = fmax(u1, u), v0 = fmin(v0, v), v1 = fmax(v1, v);
        }
    return gls_box_truncation_of(c, u0, v0, u1, v1);
}

/* The angle in (-pi, pi]. */
static double wrap(double a)
{
    while (a > M_PI)
        a -= 2 * M_PI;
    while (a <= -M_PI)
        a += 2 * M_PI;
    return a;
}

/* The 3D box of instance i seen by camera c, and its KITTI fields. */
static void box_3d(const gls_scene *s, const gls_camera *c, gls_box *b)
{
    const gls_instance *in = &s->inst[b->inst];
    const gls_proto *pr = &s->protos[in->proto];
    const double *W = in->world;
    for (int k = 0; k < 8; k++) {
        double o[3] = {k & 1 ? pr->hi[0] : pr->lo[0], k & 2 ? pr->hi[1] : pr->lo[1], k & 4 ? pr->hi[2] : pr->lo[2]};
        rv3 wp = rv(W[0] * o[0] + W[1] * o[1] + W[2] * o[2] + W[3], W[4] * o[0] + W[5] * o[1] + W[6] * o[2] + W[7],
                    W[8] * o[0] + W[9] * o[1] + W[10] * o[2] + W[11]);
        rv3 p = to_cam(c, wp);
        b->corners[k][0] = p.x, b->corners[k][1] = p.y, b->corners[k][2] = p.z;
    }
    /* the box's edges along each object axis, in the camera frame */
    rv3 e[3];
    double len[3], up_align[3];
    for (int a = 0; a < 3; a++) {
        int k = 1 << a;
        e[a] = rv(b->corners[k][0] - b->corners[0][0], b->corners[k][1] - b->corners[0][1],
                  b->corners[k][2] - b->corners[0][2]);
        len[a] = rv_len(e[a]);
        up_align[a] = len[a] > 0 ? fabs(e[a].y) / len[a] : 0;
    }
    /* up: the axis nearest the camera's vertical; length: the longer of
     * the other two (the lower axis on a tie, within 1e-9 relative) */
    b->up = 0;
    for (int a = 1; a < 3; a++)
        if (up_align[a] > up_align[b->up])
            b->up = a;
    int o1 = (b->up + 1) % 3, o2 = (b->up + 2) % 3;
    if (o2 < o1) {
        int t = o1;
        o1 = o2, o2 = t;
    }
    b->len = len[o2] > len[o1] * (1 + 1e-9) ? o2 : o1; /* equal up to rounding: a tie */
    b->wid = b->len == o1 ? o2 : o1;
    b->dims[0] = len[b->up], b->dims[1] = len[b->wid], b->dims[2] = len[b->len];
    /* bottom centre: the centre of the face across the up axis that is
     * lower in the camera (larger y) */
    rv3 cc = rv(0, 0, 0);
    for (int k = 0; k < 8; k++)
        cc = rv_add(cc, rv(b->corners[k][0], b->corners[k][1], b->corners[k][2]));
    cc = rv_mul(cc, 0.125);
    rv3 half = rv_mul(e[b->up], 0.5);
    rv3 bot = half.y >= 0 ? rv_add(cc, half) : rv_sub(cc, half);
    b->loc[0] = bot.x, b->loc[1] = bot.y, b->loc[2] = bot.z;
    rv3 d = e[b->len];
    /* + 0.0: no "-0" in the files */
    b->ry = (len[b->len] > 0 ? atan2(-d.z, d.x) : 0) + 0.0;
    b->alpha = wrap(b->ry - atan2(bot.x, bot.z)) + 0.0;
}

int gls_boxes_base(const gls_scene *s, const gls_camera *c, const uint32_t *ids, gls_box **boxes, size_t *n)
{
    uint32_t w = c->width, h = c->height;
    size_t np = (size_t)w * h, k = 0;
    *boxes = NULL, *n = 0;
    uint32_t *v = distinct_ids(ids, np, &k);
    gls_box *b = k ? calloc(k, sizeof *b) : NULL;
    uint32_t(*mm)[4] = k ? malloc(k * sizeof *mm) : NULL;
    if (!v || (k && (!b || !mm))) {
        free(v), free(b), free(mm);
        return -1;
    }
    for (size_t j = 0; j < k; j++)
        b[j].inst = v[j] - 1;
    boxes_2d(ids, w, h, v, b, k, mm);
    for (size_t j = 0; j < k; j++)
        box_3d(s, c, &b[j]);
    free(v), free(mm);
    *boxes = b, *n = k;
    return 0;
}

void gls_box_set_alone(gls_box *b, uint64_t alone)
{
    /* the same surfaces drawn alone: at least the pixels showing them,
     * but GL may round an edge pixel differently */
    b->alone = alone < b->pixels ? b->pixels : alone;
    b->visible = (double)b->pixels / (double)b->alone;
    b->occluded = gls_box_occlusion_level(b->visible);
}

int gls_boxes_compute(gls_renderer *r, const gls_scene *s, const gls_camera *c, const uint32_t *ids,
                      gls_box **boxes, size_t *n)
{
    uint32_t w = c->width, h = c->height;
    size_t np = (size_t)w * h, k = 0;
    gls_box *b = NULL;
    if (gls_boxes_base(s, c, ids, &b, &k))
        return -1;
    uint8_t *vis = k ? calloc(s->nitems ? s->nitems : 1, 1) : NULL;
    float *z = k ? malloc(np * sizeof *z) : NULL;
    if (k && (!vis || !z)) {
        free(b), free(vis), free(z);
        return -1;
    }
    gls_render_prepare(r, c);
    static const double m[6] = {1, 0, 0.5, 0, 1, 0.5}; /* image (u, v) -> window (u + 1/2, v + 1/2) */
    const uint32_t sc[4] = {0, 0, w, h};
    for (size_t j = 0; j < k; j++) {
        /* its items: the item list is sorted by draw key first, so an
         * instance's items are not one run */
        for (uint32_t i = 0; i < s->nitems; i++)
            vis[i] = s->items[i].inst == b[j].inst;
        b[j].truncated = truncation(c, (const double(*)[3])b[j].corners);
        gls_render_mapped(r, c, m, w, h, sc, vis);
        gls_render_read_z(r, z);
        uint64_t alone = 0;
        for (size_t i = 0; i < np; i++)
            alone += isfinite(z[i]) != 0;
        gls_box_set_alone(&b[j], alone);
    }
    if (k) {
        char err[256];
        gls_renderer_set_size(r, w, h, err, sizeof err); /* same size: its viewport and scissor back */
    }
    free(vis), free(z);
    *boxes = b, *n = k;
    return 0;
}
