/* One-pass anti-aliasing (aa_onepass.h, spec/antialiasing.md "One pass").
 *
 * Over 500 lines because its three parts work on one private pair of
 * types, the pass's kernel and the gather's context: the kernel (each
 * pass's fine offsets and weights, sorted into runs), the gather that
 * sums a read-back tile through it into the accumulator, and the tile
 * loop that decides from the kernel which tiles, pixels and chunks a pass
 * draws.  Apart, the kernel would need a header only these two files
 * read. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "aa_onepass.h"
#include "progress_line.h"
#include "units.h"

/* The largest tile the passes are planned for: a pass's L follows from
 * it (PASS_MAX_L below), so it fixes which samples share a pass. */
#define TILE_MAX_SIDE 2048u
/* The side tiles are drawn at, for speed: on llvmpipe a tile's colour and
 * depth buffers (8 bytes a fine pixel) are allocated, zeroed and read
 * back whole, and past about 768 x 768 (4.5 MiB) they fall out of cache.
 * Measured on 2026-11-29 (whole glsplay runs, best of 3, 640x480): 16
 * samples on 100k scattered triangles 0.67 s at 2048 against 0.49 s at
 * 768; 64 and 256 samples on the terrain 0.82 and 1.18 s against 0.56
 * and 0.77 s; 4096 samples 4.5 s at both (spec/antialiasing.md
 * "Tiles"). */
#define TILE_DRAW_SIDE 768u
/* A pass's pixel footprint (sqrt(L) fine pixels a side) stays under an
 * eighth of a tile side, and L under 2^16: K passes beyond. */
#define PASS_MAX_L 65536u

/* The gather kernel of one pass: fine offsets relative to the pixel's
 * base u A0 + v A1 and integer weights (1 for the box). */
typedef struct {
    uint64_t n;
    int64_t (*c)[2];
    uint64_t *w;
    int64_t lo[2], hi[2]; /* bounding box of c */
} kernel;

static void kernel_free(kernel *k)
{
    free(k->c);
    free(k->w);
    memset(k, 0, sizeof *k);
}

typedef struct {
    int64_t c[2];
    uint64_t w;
} entry;

static int cmp_entry(const void *a, const void *b)
{
    const entry *x = a, *y = b;
    if (x->c[1] != y->c[1])
        return x->c[1] < y->c[1] ? -1 : 1;
    return x->c[0] < y->c[0] ? -1 : x->c[0] > y->c[0];
}

static void sort_kernel(kernel *k)
{
    entry *e = malloc((k->n ? k->n : 1) * sizeof *e);
    if (!e)
        return; /* unsorted is correct, only slower */
    for (uint64_t i = 0; i < k->n; i++)
        e[i].c[0] = k->c[i][0], e[i].c[1] = k->c[i][1], e[i].w = k->w[i];
    qsort(e, k->n, sizeof *e, cmp_entry);
    for (uint64_t i = 0; i < k->n; i++)
        k->c[i][0] = e[i].c[0], k->c[i][1] = e[i].c[1], k->w[i] = e[i].w;
    free(e);
}

/* Kernel of pass r: the box's l samples, or the Gaussian's window points
 * with nonzero weight (cells -radius..radius around the pixel). */
static int kernel_make(const gls_aa_fine *f, uint64_t r, kernel *k, int64_t shift[2])
{
    const gls_aa_plan *p = f->p;
    int gauss = gls_aa_weighted(p);
    int64_t R = gauss ? p->radius : 0, side = 2 * R + 1;
    uint64_t cap = f->l * (uint64_t)(side * side);
    int64_t(*pos)[2] = malloc(f->l * sizeof *pos), (*c)[2] = malloc(f->l * sizeof *c);
    k->c = malloc(cap * sizeof *k->c);
    k->w = malloc(cap * sizeof *k->w);
    if (!pos || !c || !k->c || !k->w) {
        free(pos), free(c);
        kernel_free(k);
        return -1;
    }
    gls_aa_fine_pass(f, r, shift, pos, c);
    k->n = 0;
    k->lo[0] = k->lo[1] = INT64_MAX;
    k->hi[0] = k->hi[1] = INT64_MIN;
    for (int64_t gy = -R; gy <= R; gy++)
        for (int64_t gx = -R; gx <= R; gx++)
            for (uint64_t j = 0; j < f->l; j++) {
                uint64_t w = 1;
                if (gauss) {
                    double du, dv;
                    gls_aa_lattice_sample(p, pos[j][0], pos[j][1], (int)gx, (int)gy, &du, &dv, &w);
                    if (!w)
                        continue;
                }
                int64_t x = c[j][0] + gx * f->a[0][0] + gy * f->a[0][1];
                int64_t y = c[j][1] + gx * f->a[1][0] + gy * f->a[1][1];
                k->c[k->n][0] = x, k->c[k->n][1] = y;
                k->w[k->n++] = w;
                k->lo[0] = x < k->lo[0] ? x : k->lo[0], k->hi[0] = x > k->hi[0] ? x : k->hi[0];
                k->lo[1] = y < k->lo[1] ? y : k->lo[1], k->hi[1] = y > k->hi[1] ? y : k->hi[1];
            }
    free(pos), free(c);
    /* in memory order (rows, then columns), so that a pixel's gather
     * walks its footprint row by row */
    for (uint64_t i = 1; i < k->n; i++)
        if (k->c[i][1] < k->c[i - 1][1] || (k->c[i][1] == k->c[i - 1][1] && k->c[i][0] < k->c[i - 1][0])) {
            sort_kernel(k);
            break;
        }
    return 0;
}

/* Fine bounding box of one pass for a w x h image with kernel bounds
 * lo..hi: bases u A0 + v A1 at the image's corner pixels. */
static void fine_box(const gls_aa_fine *f, uint32_t w, uint32_t h, const int64_t lo[2], const int64_t hi[2],
                     int64_t *x0, int64_t *y0, int64_t *x1, int64_t *y1)
{
    int64_t bx[4], by[4];
    for (int i = 0; i < 4; i++) {
        int64_t u = i & 1 ? (int64_t)w - 1 : 0, v = i & 2 ? (int64_t)h - 1 : 0;
        bx[i] = u * f->a[0][0] + v * f->a[0][1];
        by[i] = u * f->a[1][0] + v * f->a[1][1];
    }
    *x0 = *x1 = bx[0], *y0 = *y1 = by[0];
    for (int i = 1; i < 4; i++) {
        *x0 = bx[i] < *x0 ? bx[i] : *x0, *x1 = bx[i] > *x1 ? bx[i] : *x1;
        *y0 = by[i] < *y0 ? by[i] : *y0, *y1 = by[i] > *y1 ? by[i] : *y1;
    }
    *x0 += lo[0], *y0 += lo[1], *x1 += hi[0] + 1, *y1 += hi[1] + 1; /* half-open */
}

/* Kernel bounds of any pass: the samples lie in the pixel's square, so
 * c is within A [0, 1)^2 (plus the Gaussian's cells); pass 0's kernel is
 * built to measure, the others are assumed alike up to one pixel. */
int gls_aa_fine_plan(const gls_aa_plan *p, uint32_t w, uint32_t h, uint32_t maxdim, const gls_aa_fine_opts *fo,
                     gls_aa_fine_layout *lay, char *err, size_t errlen)
{
    memset(lay, 0, sizeof *lay);
    uint64_t mem = fo && fo->memory ? fo->memory : GLS_AA_DEFAULT_MEMORY;
    uint64_t px = mem / GLS_AA_FINE_PIXEL_BYTES;
    uint32_t side = (uint32_t)sqrt((double)px);
    if (side > TILE_MAX_SIDE)
        side = TILE_MAX_SIDE;
    if (maxdim && side > maxdim)
        side = maxdim;
    if (side < 1) {
        snprintf(err, errlen, "anti-aliasing memory %llu bytes holds no tile", (unsigned long long)mem);
        return -1;
    }
    /* the split into passes follows from the memory, not from a test's
     * tiny tiles (max_tile), which must exercise pixels straddling tiles */
    uint64_t max_l = (uint64_t)side * side / 64;
    if (side > TILE_DRAW_SIDE)
        side = TILE_DRAW_SIDE;
    if (fo && fo->max_tile && side > fo->max_tile)
        side = fo->max_tile;
    if (max_l > PASS_MAX_L)
        max_l = PASS_MAX_L;
    if (fo && fo->max_l)
        max_l = fo->max_l;
    if (gls_aa_weighted(p)) { /* the Gaussian's kernel spans (2 radius + 1)^2 cells */
        uint64_t s = 2 * (uint64_t)p->radius + 1;
        max_l = max_l / (s * s) ? max_l / (s * s) : 1;
    }
    if (gls_aa_fine_init(&lay->f, p, max_l)) {
        snprintf(err, errlen, "the %s pattern with the %s filter is not drawn in one pass", gls_aa_pattern_name(p->o.pattern),
                 p->o.filter == GLS_AA_BOX ? "box" : "Gaussian");
        return -1;
    }
    /* kernel bounds: A [0, 1)^2 padded by the cells, from the matrix alone
     * (no kernel needed for --explain) */
    const gls_aa_fine *f = &lay->f;
    int64_t R = gls_aa_weighted(p) ? p->radius : 0, lo[2], hi[2];
    for (int row = 0; row < 2; row++) {
        int64_t a = f->a[row][0], b = f->a[row][1];
        lo[row] = (a < 0 ? a : 0) + (b < 0 ? b : 0) - R * (llabs(a) + llabs(b)) - 1;
        hi[row] = (a > 0 ? a : 0) + (b > 0 ? b : 0) + R * (llabs(a) + llabs(b)) + 1;
    }
    int64_t x1, y1;
    fine_box(f, w, h, lo, hi, &lay->x0, &lay->y0, &x1, &y1);
    lay->fw = x1 - lay->x0, lay->fh = y1 - lay->y0;
    lay->tw = (uint32_t)(lay->fw < side ? lay->fw : side);
    lay->th = (uint32_t)(lay->fh < side ? lay->fh : side);
    lay->tiles = (uint64_t)((lay->fw + lay->tw - 1) / lay->tw) * (uint64_t)((lay->fh + lay->th - 1) / lay->th);
    uint64_t s = gls_aa_weighted(p) ? 2 * (uint64_t)p->radius + 1 : 1;
    lay->kernel = f->l * s * s;
    lay->bytes = (uint64_t)lay->tw * lay->th * GLS_AA_FINE_PIXEL_BYTES;
    return 0;
}

/* ---- gather --------------------------------------------------------- */

typedef struct {
    const gls_aa_fine *f;
    const kernel *k;
    int64_t *off;       /* byte offsets of the kernel in the tile buffer */
    gls_accum *acc;
    uint8_t *seen;      /* mask: the pixel's first sample is recorded     */
    const int64_t *run_off; /* the kernel as runs of adjacent samples in  */
    const uint32_t *run_len; /* a fine row: byte offset, length; n_runs    */
    uint64_t n_runs;
} gather_ctx;

/* How many runs ahead the gather asks for cache lines (make bench-aa,
 * 4096 samples: 4, 8 and 16 about equal, none: grid 25 % slower) */
#define PREFETCH_RUNS 8

/* The kernel's entries (sorted by row, then column; byte offsets off) as
 * runs of samples next to each other in a fine row: about sqrt(L) runs
 * where the entries are L, so the common case of the gather sums whole
 * rows at a time.  Returns the number of runs. */
static uint64_t kernel_runs(const kernel *k, const int64_t *off, int64_t *run_off, uint32_t *run_len)
{
    uint64_t n = 0;
    for (uint64_t e = 0; e < k->n; e++)
        if (n && k->c[e][1] == k->c[e - 1][1] && k->c[e][0] == k->c[e - 1][0] + 1)
            run_len[n - 1]++;
        else
            run_off[n] = off[e], run_len[n++] = 1;
    return n;
}

/* Sum of the R, G and B bytes of len RGBA8 pixels at q into s.  Two
 * pixels a 64-bit load: R and B in one word's 16-bit lanes, G (and A) in
 * another's, at most 128 values of 255 a lane before the lanes are
 * emptied (every 256 pixels); the same integers as adding byte by byte. */
void gls_aa_sum_run(const uint8_t *q, uint32_t len, uint32_t s[3])
{
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    const uint64_t mask = 0x00FF00FF00FF00FFull;
    while (len) {
        uint32_t n = len < 256 ? len : 256, i = 0;
        uint64_t rb = 0, ga = 0;
        for (; i + 2 <= n; i += 2) {
            uint64_t w;
            memcpy(&w, q + 4 * i, 8);
            rb += w & mask, ga += (w >> 8) & mask;
        }
        if (i < n) {
            uint32_t w;
            memcpy(&w, q + 4 * i, 4);
            rb += w & 0x00FF00FFu, ga += (w >> 8) & 0x00FF00FFu;
        }
        s[0] += (uint32_t)(rb & 0xFFFF) + (uint32_t)(rb >> 32 & 0xFFFF);
        s[1] += (uint32_t)(ga & 0xFFFF) + (uint32_t)(ga >> 32 & 0xFFFF);
        s[2] += (uint32_t)(rb >> 16 & 0xFFFF) + (uint32_t)(rb >> 48);
        q += 4 * (size_t)n, len -= n;
    }
#else
    for (uint32_t i = 0; i < len; i++)
        s[0] += q[4 * i], s[1] += q[4 * i + 1], s[2] += q[4 * i + 2];
#endif
}

/* Add the samples of every pixel whose kernel meets the tile at fine
 * (X0, Y0), tw x th, from its read-back buf. */
static void gather(gather_ctx *g, const uint8_t *buf, int64_t X0, int64_t Y0, uint32_t tw, uint32_t th,
                   int64_t u0, int64_t u1, int64_t v0, int64_t v1)
{
    const gls_aa_fine *f = g->f;
    const kernel *k = g->k;
    gls_accum *acc = g->acc;
    size_t stride = (size_t)tw * 4;
    for (int64_t v = v0; v <= v1; v++)
        for (int64_t u = u0; u <= u1; u++) {
            int64_t bx = u * f->a[0][0] + v * f->a[0][1] - X0, by = u * f->a[1][0] + v * f->a[1][1] - Y0;
            if (bx + k->hi[0] < 0 || bx + k->lo[0] >= (int64_t)tw || by + k->hi[1] < 0 || by + k->lo[1] >= (int64_t)th)
                continue;
            int full = bx + k->lo[0] >= 0 && bx + k->hi[0] < (int64_t)tw && by + k->lo[1] >= 0 &&
                       by + k->hi[1] < (int64_t)th;
            size_t pix = (size_t)v * acc->width + (size_t)u;
            const uint8_t *base = buf + (int64_t)by * (int64_t)stride + bx * 4;
            uint64_t s[3] = {0, 0, 0};
            uint32_t first = 0;
            int have = acc->mixed && g->seen[pix], mixed = 0;
            if (have)
                first = acc->first[pix];
            if (full && !acc->weighted && !acc->mixed) {
                /* the common case: box, whole kernel in this tile, no
                 * mask, summed a run at a time; at most 2^24 samples of
                 * 255 fit in 32 bits */
                uint32_t t[3] = {0, 0, 0};
                for (uint64_t j = 0; j < g->n_runs; j++) {
                    /* request a later run's cache lines now: each run
                     * ends in a mispredicted branch, which would otherwise
                     * hold the next fine row's misses back until then */
                    if (j + PREFETCH_RUNS < g->n_runs) {
                        const uint8_t *nq = base + g->run_off[j + PREFETCH_RUNS];
                        for (uint32_t o = 0; o < 4 * g->run_len[j + PREFETCH_RUNS]; o += 64)
                            __builtin_prefetch(nq + o);
                    }
                    gls_aa_sum_run(base + g->run_off[j], g->run_len[j], t);
                }
                s[0] = t[0], s[1] = t[1], s[2] = t[2];
            } else
                for (uint64_t e = 0; e < k->n; e++) {
                    if (!full) {
                        int64_t x = bx + k->c[e][0], y = by + k->c[e][1];
                        if (x < 0 || y < 0 || x >= (int64_t)tw || y >= (int64_t)th)
                            continue;
                    }
                    const uint8_t *q = base + g->off[e];
                    if (acc->weighted) {
                        uint64_t w = k->w[e];
                        s[0] += w * q[0], s[1] += w * q[1], s[2] += w * q[2];
                    } else {
                        s[0] += q[0], s[1] += q[1], s[2] += q[2];
                    }
                    if (acc->mixed) {
                        uint32_t col = (uint32_t)q[0] | (uint32_t)q[1] << 8 | (uint32_t)q[2] << 16;
                        if (!have)
                            first = col, have = 1;
                        else
                            mixed |= col != first;
                    }
                }
            if (acc->weighted)
                for (int ch = 0; ch < 3; ch++)
                    acc->sum64[4 * pix + ch] += s[ch];
            else
                for (int ch = 0; ch < 3; ch++)
                    acc->sum32[4 * pix + ch] += (uint32_t)s[ch];
            if (acc->mixed && have) {
                acc->first[pix] = first;
                g->seen[pix] = 1;
                acc->mixed[pix] |= (uint8_t)mixed;
            }
        }
}

/* Pixels whose kernel can meet the fine rectangle [X0, X1) x [Y0, Y1):
 * bases in [X0 - hi, X1 - lo) x ..., pulled back through A^-1 =
 * adj(A) / L; a bounding box clipped to the image.  0 if none. */
static int pixel_range(const gls_aa_fine *f, const kernel *k, int64_t X0, int64_t Y0, int64_t X1, int64_t Y1,
                       uint32_t w, uint32_t h, int64_t r[4])
{
    double bx[2] = {(double)(X0 - k->hi[0]), (double)(X1 - 1 - k->lo[0])};
    double by[2] = {(double)(Y0 - k->hi[1]), (double)(Y1 - 1 - k->lo[1])};
    double L = (double)f->l, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 4; i++) {
        double x = bx[i & 1], y = by[i >> 1];
        double u = ((double)f->a[1][1] * x - (double)f->a[0][1] * y) / L;
        double v = (-(double)f->a[1][0] * x + (double)f->a[0][0] * y) / L;
        lo[0] = fmin(lo[0], u), hi[0] = fmax(hi[0], u);
        lo[1] = fmin(lo[1], v), hi[1] = fmax(hi[1], v);
    }
    r[0] = (int64_t)floor(lo[0]) - 1, r[1] = (int64_t)ceil(hi[0]) + 1;
    r[2] = (int64_t)floor(lo[1]) - 1, r[3] = (int64_t)ceil(hi[1]) + 1;
    r[0] = r[0] < 0 ? 0 : r[0], r[2] = r[2] < 0 ? 0 : r[2];
    r[1] = r[1] > (int64_t)w - 1 ? (int64_t)w - 1 : r[1];
    r[3] = r[3] > (int64_t)h - 1 ? (int64_t)h - 1 : r[3];
    return r[0] <= r[1] && r[2] <= r[3];
}

/* The part of tile [X0, X0 + tw) x [Y0, Y0 + th) that samples of image
 * rows v0..v1-1 can fall in: the parallelogram A [-g, W + g] x
 * [v0 - g, v1 + g] (g: the Gaussian's cells and a pixel of margin; the
 * whole image: v0 = 0, v1 = H) clipped to the tile; its bounding box,
 * tile-relative, as a scissor {x, y, w, h}.  0 if empty. */
static int tile_scissor(const gls_aa_fine *f, uint32_t W, uint32_t v0, uint32_t v1, double g, int64_t X0, int64_t Y0,
                        uint32_t tw, uint32_t th, uint32_t sc[4])
{
    double poly[16][2], tmp[16][2];
    int n = 4;
    for (int i = 0; i < 4; i++) {
        double u = (i == 1 || i == 2) ? W + g : -g, v = i >= 2 ? v1 + g : v0 - g;
        poly[i][0] = (double)f->a[0][0] * u + (double)f->a[0][1] * v - (double)X0;
        poly[i][1] = (double)f->a[1][0] * u + (double)f->a[1][1] * v - (double)Y0;
    }
    /* clip to 0 <= x <= tw, 0 <= y <= th (Sutherland-Hodgman) */
    for (int e = 0; e < 4 && n; e++) {
        int axis = e & 1;
        double lim = e < 2 ? 0 : (axis ? th : tw), sgn = e < 2 ? -1 : 1;
        int m = 0;
        for (int i = 0; i < n; i++) {
            const double *a = poly[i], *b = poly[(i + 1) % n];
            double da = sgn * (a[axis] - lim), db = sgn * (b[axis] - lim);
            if (da <= 0)
                tmp[m][0] = a[0], tmp[m][1] = a[1], m++;
            if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
                double t = da / (da - db);
                tmp[m][0] = a[0] + t * (b[0] - a[0]);
                tmp[m][1] = a[1] + t * (b[1] - a[1]);
                m++;
            }
        }
        n = m;
        memcpy(poly, tmp, sizeof(double) * 2 * (size_t)m);
    }
    if (n < 3)
        return 0;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 2; k++)
            lo[k] = fmin(lo[k], poly[i][k]), hi[k] = fmax(hi[k], poly[i][k]);
    int64_t x0 = (int64_t)floor(lo[0]) - 1, y0 = (int64_t)floor(lo[1]) - 1;
    int64_t x1 = (int64_t)ceil(hi[0]) + 1, y1 = (int64_t)ceil(hi[1]) + 1;
    x0 = x0 < 0 ? 0 : x0, y0 = y0 < 0 ? 0 : y0;
    x1 = x1 > (int64_t)tw ? tw : x1, y1 = y1 > (int64_t)th ? th : y1;
    if (x0 >= x1 || y0 >= y1)
        return 0;
    sc[0] = (uint32_t)x0, sc[1] = (uint32_t)y0, sc[2] = (uint32_t)(x1 - x0), sc[3] = (uint32_t)(y1 - y0);
    return 1;
}


int gls_aa_render_fine(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_fine_opts *fo,
                       gls_accum *acc, gls_aa_fine_stats *st, char *err, size_t errlen)
{
    return gls_aa_render_fine_rows(r, c, p, fo, 0, c->height, acc, st, err, errlen);
}

/* What the passes of one render share: the camera, the plan and the
 * layout, the rows asked for, the tile buffers (two: a tile is read back
 * into one while the previous tile, in the other, is gathered), the
 * chunks' bounds and which are drawn, the pass's kernel and its gather
 * offsets, and the stats and progress. */
typedef struct {
    gls_renderer *r;
    const gls_camera *c;
    const gls_aa_plan *p;
    const gls_aa_fine_opts *fo;
    const gls_aa_fine *f;
    uint32_t W, H, tw, th, v0, v1, nch;
    gls_accum *acc;
    double (*cb)[4];
    uint8_t *vis, *buf[2], *seen;
    kernel k;
    int64_t *off, *run_off;
    uint32_t *run_len;
    gls_aa_fine_stats s;
    uint64_t total, done; /* tiles, for the progress line */
    double t0, last;
} fine_run;

/* Pass `pass`'s kernel (and its shift) and the gather's offsets of it,
 * replacing the previous pass's. */
static int pass_kernel(fine_run *u, uint64_t pass, int64_t shift[2], char *err, size_t errlen)
{
    kernel_free(&u->k);
    free(u->off), free(u->run_off), free(u->run_len);
    u->off = u->run_off = NULL, u->run_len = NULL;
    kernel *k = &u->k;
    if (kernel_make(u->f, pass, k, shift) || !(u->off = malloc((k->n ? k->n : 1) * sizeof *u->off)) ||
        !(u->run_off = malloc((k->n ? k->n : 1) * sizeof *u->run_off)) ||
        !(u->run_len = malloc((k->n ? k->n : 1) * sizeof *u->run_len))) {
        snprintf(err, errlen, "out of memory for the gather of %llu samples", (unsigned long long)u->f->l);
        return -1;
    }
    for (uint64_t e = 0; e < k->n; e++)
        u->off[e] = (k->c[e][1] * (int64_t)u->tw + k->c[e][0]) * 4;
    return 0;
}

/* One pass's tiles: each drawn with the chunks that can reach its pixels'
 * samples and read back, while the tile before it is gathered.  The loop
 * stays whole because that pipeline (the buffer drawn into, the one
 * pending with its pixel range and origin) is carried from one tile to
 * the next. */
static void run_pass(fine_run *u, const int64_t shift[2])
{
    const gls_aa_fine *f = u->f;
    const kernel *k = &u->k;
    gls_aa_fine_stats *s = &u->s;
    uint32_t W = u->W, H = u->H, tw = u->tw, th = u->th, v0 = u->v0, v1 = u->v1;
    gather_ctx g = {f, k, u->off, u->acc, u->seen, u->run_off, u->run_len,
                    kernel_runs(k, u->off, u->run_off, u->run_len)};
    /* the tiles cover this pass's own fine bounding box (the layout's
     * is an estimate for --explain and the progress line) */
    int64_t x0, y0, x1, y1;
    fine_box(f, W, H, k->lo, k->hi, &x0, &y0, &x1, &y1);
    uint64_t tx = (uint64_t)((x1 - x0 + tw - 1) / tw), ty = (uint64_t)((y1 - y0 + th - 1) / th);
    if (u->done + tx * ty > u->total)
        u->total = u->done + tx * ty;
    int pending = 0;
    int64_t pr[4] = {0, 0, 0, 0}, pX = 0, pY = 0;
    int cur = 0;
    for (uint64_t t = 0; t < tx * ty; t++) {
        int64_t X0 = x0 + (int64_t)(t % tx) * tw, Y0 = y0 + (int64_t)(t / tx) * th;
        int64_t rng[4];
        u->done++;
        /* the pixels of rows v0..v1-1 whose samples the tile holds */
        if (!pixel_range(f, k, X0, Y0, X0 + tw, Y0 + th, W, H, rng) || rng[3] < (int64_t)v0 ||
            rng[2] > (int64_t)v1 - 1) {
            s->tiles_skipped++;
            continue;
        }
        rng[2] = rng[2] < (int64_t)v0 ? (int64_t)v0 : rng[2];
        rng[3] = rng[3] > (int64_t)v1 - 1 ? (int64_t)v1 - 1 : rng[3];
        /* geometry that can reach the samples of those pixels: their
         * squares, the Gaussian's cells, a pixel of margin */
        double R = (double)(gls_aa_weighted(u->p) ? u->p->radius : 0) + 1.5;
        double iu0 = (double)rng[0] - R, iu1 = (double)rng[1] + R, iv0 = (double)rng[2] - R, iv1 = (double)rng[3] + R;
        for (uint32_t i = 0; i < u->nch; i++) {
            double *cb = u->cb[i];
            u->vis[i] = !(cb[2] < iu0 || cb[0] > iu1 || cb[3] < iv0 || cb[1] > iv1);
            s->chunks_drawn += u->vis[i];
        }
        double m[6];
        uint32_t sc[4];
        if (!tile_scissor(f, W, v0, v1, R + 1, X0, Y0, tw, th, sc)) {
            s->tiles_skipped++;
            continue;
        }
        gls_aa_fine_map(f, shift, X0, Y0, m);
        double ta = gls_now();
        gls_render_mapped(u->r, u->c, m, tw, th, sc, u->vis);
        gls_render_flush(u->r);
        double tb = gls_now();
        s->draw_s += tb - ta;
        if (pending)
            gather(&g, u->buf[cur ^ 1], pX, pY, tw, th, pr[0], pr[1], pr[2], pr[3]);
        double tc = gls_now();
        s->gather_s += tc - tb;
        gls_render_read_rect(u->r, tw, sc, u->buf[cur]);
        s->read_s += gls_now() - tc;
        memcpy(pr, rng, sizeof pr);
        pX = X0, pY = Y0;
        pending = 1;
        cur ^= 1;
        s->tiles_drawn++;
        gls_progress_steps(u->fo->progress, u->fo->label, "tiles", u->done, u->total, u->t0, &u->last, 0);
        if (u->fo->on_pass)
            u->fo->on_pass(u->fo->ctx, u->done, u->total, gls_now() - u->t0);
    }
    if (pending) {
        double tc = gls_now();
        gather(&g, u->buf[cur ^ 1], pX, pY, tw, th, pr[0], pr[1], pr[2], pr[3]);
        s->gather_s += gls_now() - tc;
    }
}

static void run_free(fine_run *u)
{
    kernel_free(&u->k);
    free(u->off), free(u->run_off), free(u->run_len);
    free(u->cb);
    free(u->vis);
    free(u->buf[0]);
    free(u->buf[1]);
    free(u->seen);
}

int gls_aa_render_fine_rows(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_fine_opts *fo_in,
                            uint32_t v0, uint32_t v1, gls_accum *acc, gls_aa_fine_stats *st, char *err, size_t errlen)
{
    gls_aa_fine_opts fo0;
    memset(&fo0, 0, sizeof fo0);
    fine_run u;
    memset(&u, 0, sizeof u);
    u.r = r, u.c = c, u.p = p, u.fo = fo_in ? fo_in : &fo0, u.acc = acc;
    u.W = c->width, u.H = c->height, u.v0 = v0, u.v1 = v1;
    gls_aa_fine_stats *s = &u.s;
    u.t0 = u.last = gls_now();
    if (gls_aa_fine_plan(p, u.W, u.H, gls_renderer_max_dim(r), u.fo, &s->lay, err, errlen))
        return -1;
    u.f = &s->lay.f;
    uint32_t tw = u.tw = s->lay.tw, th = u.th = s->lay.th;
    int rc = -1;
    uint32_t nch = u.nch = gls_renderer_nchunks(r);
    u.cb = malloc((nch ? nch : 1) * sizeof *u.cb);
    u.vis = malloc(nch ? nch : 1);
    u.buf[0] = malloc((size_t)tw * th * 4), u.buf[1] = malloc((size_t)tw * th * 4);
    u.seen = acc->mixed ? calloc((size_t)u.W * u.H, 1) : NULL;
    if (!u.cb || !u.vis || !u.buf[0] || !u.buf[1] || (acc->mixed && !u.seen)) {
        char need[32];
        gls_fmt_bytes(need, sizeof need, s->lay.bytes);
        snprintf(err, errlen, "out of memory for %ux%u anti-aliasing tiles (%s; lower --aa-memory)", tw, th, need);
        goto out;
    }
    if (gls_renderer_set_size(r, tw, th, err, errlen))
        goto out;
    gls_render_chunk_bounds(r, c, u.cb);
    gls_render_prepare(r, c);
    s->chunks_total = (uint64_t)nch * s->lay.tiles * u.f->k;
    u.total = s->lay.tiles * u.f->k;
    for (uint64_t pass = 0; pass < u.f->k; pass++) {
        int64_t shift[2];
        if (pass_kernel(&u, pass, shift, err, errlen))
            goto out;
        run_pass(&u, shift);
    }
    acc->wsum = p->wsum;
    acc->samples = p->count;
    s->total_s = gls_now() - u.t0;
    if (s->total_s > 2)
        gls_progress_steps(u.fo->progress, u.fo->label, "tiles", u.total, u.total, u.t0, &u.last, 1);
    rc = gls_renderer_set_size(r, u.W, u.H, err, errlen);
out:
    run_free(&u);
    if (st)
        *st = *s;
    return rc;
}
