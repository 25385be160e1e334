/* Sample plan and accumulation buffer (aa.h, spec/antialiasing.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "aa.h"

gls_aa_opts gls_aa_defaults(void)
{
    gls_aa_opts o;
    memset(&o, 0, sizeof o);
    o.n = 1;
    o.filter = GLS_AA_BOX;
    o.sigma = GLS_AA_DEFAULT_SIGMA;
    o.pattern = GLS_AA_LATTICE;
    return o;
}

const char *gls_aa_pattern_name(gls_aa_pattern p)
{
    return p == GLS_AA_GRID ? "grid" : p == GLS_AA_STRATIFIED ? "stratified" : "lattice";
}

/* Width of the square the plan's N x N offsets spread over: the pixel
 * (box), the +-3 sigma window (Gaussian, grid and stratified).  The
 * lattice's points are per pixel area whatever the filter. */
static double span_of(gls_aa_filter f, gls_aa_pattern pat, double sigma)
{
    return f == GLS_AA_GAUSS && pat != GLS_AA_LATTICE ? 2 * GLS_AA_GAUSS_SPAN * sigma : 1.0;
}

uint32_t gls_aa_n_for_accuracy(gls_aa_filter f, gls_aa_pattern pat, double sigma, double a)
{
    if (!(a > 0) || !(sigma > 0))
        return 0;
    double span = span_of(f, pat, sigma), n = ceil(span / a);
    /* ceil of a quotient that is an integer up to rounding (1 / (1/256))
     * must not round up to the next N */
    if (n > 1 && span / (n - 1) <= a * (1 + 1e-12))
        n -= 1;
    return n >= 1 && n <= GLS_AA_MAX_N ? (uint32_t)n : 0;
}

/* splitmix64: a tiny, well-mixed, seedable generator.  Sample k's jitter
 * is a pure function of (seed, k), so samples can be generated in any
 * order (mosaic tiles) and two runs give identical images. */
static uint64_t mix64(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/* Uniform in [0, 1) with 53 random bits. */
static double unit(uint64_t x) { return (double)(x >> 11) * 0x1.0p-53; }

/* Offset of sample k, in pixels from the pixel centre.  Grid: the centres
 * of an N x N subdivision of the window; stratified: one uniformly
 * jittered point in each of those cells. */
static void offset(const gls_aa_plan *p, uint64_t k, double *du, double *dv)
{
    uint64_t n = p->o.n, i = k % n, j = k / n;
    double fx = 0.5, fy = 0.5;
    if (p->o.pattern == GLS_AA_STRATIFIED && n > 1) {
        uint64_t h = mix64(p->o.seed ^ mix64(k));
        fx = unit(h);
        fy = unit(mix64(h));
    }
    /* (i + f) / n - 1/2 in [-1/2, 1/2), times the window width */
    *du = p->span * (((double)i + fx) / (double)n - 0.5);
    *dv = p->span * (((double)j + fy) / (double)n - 0.5);
}

static double gauss_raw(const gls_aa_plan *p, double du, double dv);
static int in_window(const gls_aa_plan *p, double du, double dv);
static void lattice_offset(const gls_aa_plan *p, uint64_t k, double *du, double *dv, double *raw);

/* Offset and raw Gaussian weight of sample k, any pattern. */
static void raw_sample(const gls_aa_plan *p, uint64_t k, double *du, double *dv, double *g)
{
    if (p->o.pattern == GLS_AA_LATTICE) {
        lattice_offset(p, k, du, dv, g);
        return;
    }
    offset(p, k, du, dv);
    *g = gauss_raw(p, *du, *dv);
}

static double gauss_raw(const gls_aa_plan *p, double du, double dv)
{
    double s = p->o.sigma;
    return exp(-(du * du + dv * dv) / (2 * s * s));
}

/* Lattice Gaussian: inside the window [-3 sigma, 3 sigma) per axis (the
 * half-open square the grid's offsets fill). */
static int in_window(const gls_aa_plan *p, double du, double dv)
{
    double h = GLS_AA_GAUSS_SPAN * p->o.sigma;
    return du >= -h && du < h && dv >= -h && dv < h;
}

/* Integer weight of a sample with raw Gaussian weight g: floor of its
 * share of 2^52.  Flooring (not rounding) keeps every weight and the sum
 * below 2^52; the sum is counted exactly in gls_aa_plan_init, so the
 * normalisation divides by exactly the weight that was added. */
static uint64_t quantise(const gls_aa_plan *p, double g)
{
    return (uint64_t)floor(g / p->gsum * 0x1.0p52);
}

void gls_aa_lattice_sample(const gls_aa_plan *p, int64_t x, int64_t y, int cx, int cy, double *du, double *dv,
                           uint64_t *w)
{
    double q = (double)p->lat.q;
    *du = (double)cx + (double)x / q - 0.5;
    *dv = (double)cy + (double)y / q - 0.5;
    if (p->o.filter == GLS_AA_BOX || p->m == 1)
        *w = 1;
    else
        *w = in_window(p, *du, *dv) ? (uint64_t)floor(gauss_raw(p, *du, *dv) / p->gsum * 0x1.0p52) : 0;
}

/* Sample k of a lattice plan: point k % M of cell k / M.  raw: the
 * Gaussian's double weight (0 outside the window). */
static void lattice_offset(const gls_aa_plan *p, uint64_t k, double *du, double *dv, double *raw)
{
    uint64_t i = k % p->m, cell = k / p->m, side = 2 * (uint64_t)p->radius + 1;
    int cx = (int)(cell % side) - (int)p->radius, cy = (int)(cell / side) - (int)p->radius;
    int64_t x, y;
    gls_lattice_point(&p->lat, i, &x, &y);
    double q = (double)p->lat.q;
    *du = (double)cx + (double)x / q - 0.5;
    *dv = (double)cy + (double)y / q - 0.5;
    *raw = in_window(p, *du, *dv) ? gauss_raw(p, *du, *dv) : 0;
}

int gls_aa_plan_init(gls_aa_plan *p, const gls_aa_opts *o, char *err, size_t errlen)
{
    memset(p, 0, sizeof *p);
    uint64_t m = o->samples ? o->samples : (uint64_t)o->n * o->n;
    if (!o->samples && (o->n < 1 || o->n > GLS_AA_MAX_N)) {
        snprintf(err, errlen, "anti-aliasing window %u is outside 1..%u", o->n, GLS_AA_MAX_N);
        return -1;
    }
    if (m < 1 || m > GLS_AA_MAX_SAMPLES) {
        snprintf(err, errlen, "%llu samples per pixel is outside 1..%llu", (unsigned long long)m,
                 (unsigned long long)GLS_AA_MAX_SAMPLES);
        return -1;
    }
    uint64_t n = (uint64_t)sqrt((double)m);
    while (n * n > m)
        n--;
    while ((n + 1) * (n + 1) <= m)
        n++;
    if (o->pattern != GLS_AA_LATTICE && n * n != m) {
        snprintf(err, errlen, "the %s pattern needs a square number of samples (N x N), not %llu; "
                 "the lattice takes any number", gls_aa_pattern_name(o->pattern), (unsigned long long)m);
        return -1;
    }
    if (o->filter == GLS_AA_GAUSS && !(o->sigma >= 0.01 && o->sigma <= 16)) {
        snprintf(err, errlen, "Gaussian sigma %g is outside 0.01..16 pixels", o->sigma);
        return -1;
    }
    p->o = *o;
    p->o.n = (uint32_t)(n * n == m ? n : 0);
    p->m = m;
    p->count = m;
    p->span = span_of(o->filter, o->pattern, o->sigma);
    if (o->pattern == GLS_AA_LATTICE) {
        if (gls_lattice_choose(m, &p->lat)) {
            snprintf(err, errlen, "no lattice for %llu samples", (unsigned long long)m);
            return -1;
        }
        if (o->filter == GLS_AA_GAUSS && m > 1) {
            /* the cells whose points can fall in [-3 sigma, 3 sigma) */
            p->radius = (uint32_t)ceil(GLS_AA_GAUSS_SPAN * o->sigma + 0.5);
            uint64_t side = 2 * (uint64_t)p->radius + 1;
            if (m > GLS_AA_MAX_WINDOW / (side * side)) {
                snprintf(err, errlen, "a Gaussian of sigma %g over %llu samples per pixel needs %llu samples "
                         "(more than %llu); lower --samples or sigma", o->sigma, (unsigned long long)m,
                         (unsigned long long)(m * side * side), (unsigned long long)GLS_AA_MAX_WINDOW);
                return -1;
            }
            p->count = m * side * side;
        }
    }
    if (o->filter == GLS_AA_BOX || m == 1) {
        /* box, and any filter at N = 1: equal weights, one unit each */
        p->wsum = p->count;
        p->gsum = (double)p->count;
        return 0;
    }
    /* Gaussian: normalise by the sum of the weights actually used, so the
     * window's weights sum to one whatever N, pattern and truncation.
     * Kahan summation: 16M terms of similar size would otherwise lose
     * ~log2(16M) = 24 bits of the 53. */
    double s = 0, c = 0;
    for (uint64_t k = 0; k < p->count; k++) {
        double du, dv, g;
        raw_sample(p, k, &du, &dv, &g);
        double y = g - c, t = s + y;
        c = (t - s) - y;
        s = t;
    }
    p->gsum = s;
    uint64_t w = 0;
    for (uint64_t k = 0; k < p->count; k++) {
        double du, dv, g;
        raw_sample(p, k, &du, &dv, &g);
        w += quantise(p, g);
    }
    p->wsum = w;
    return 0;
}

void gls_aa_sample(const gls_aa_plan *p, uint64_t k, double *du, double *dv, uint64_t *w)
{
    double g;
    raw_sample(p, k, du, dv, &g);
    if (p->m == 1)
        *du = *dv = 0; /* one sample: the pixel centre, whatever the filter */
    *w = p->o.filter == GLS_AA_BOX || p->m == 1 ? 1 : quantise(p, g);
}

double gls_aa_weight_exact(const gls_aa_plan *p, uint64_t k)
{
    double du, dv, g;
    raw_sample(p, k, &du, &dv, &g);
    if (p->o.filter == GLS_AA_BOX || p->m == 1)
        return 1.0 / (double)p->count;
    return g / p->gsum;
}

/* ---- accumulator ---------------------------------------------------- */

int gls_aa_weighted(const gls_aa_plan *p) { return p->o.filter != GLS_AA_BOX && p->m > 1; }

int gls_accum_init(gls_accum *a, uint32_t width, uint32_t height, int weighted, int track_mixed)
{
    memset(a, 0, sizeof *a);
    size_t n = (size_t)width * height;
    a->width = width;
    a->height = height;
    a->weighted = weighted;
    if (weighted) {
        a->sum64 = calloc(n * 4, sizeof *a->sum64);
        a->row = malloc((size_t)width * 4 * sizeof(uint64_t));
    } else {
        a->sum32 = calloc(n * 4, sizeof *a->sum32);
        a->row = malloc((size_t)width * 4 * sizeof(uint16_t));
    }
    if (track_mixed) {
        a->first = calloc(n, sizeof *a->first);
        a->mixed = calloc(n, 1);
    }
    if ((!a->sum32 && !a->sum64) || !a->row || (track_mixed && (!a->first || !a->mixed))) {
        gls_accum_free(a);
        return -1;
    }
    return 0;
}

uint64_t gls_accum_sums_bytes(const gls_accum *a)
{
    uint64_t n = (uint64_t)a->width * a->height;
    return a->weighted ? (n * 4 + (uint64_t)a->width * 4) * sizeof(uint64_t)
                       : n * 4 * sizeof(uint32_t) + (uint64_t)a->width * 4 * sizeof(uint16_t);
}

uint64_t gls_accum_mask_bytes(const gls_accum *a)
{
    uint64_t n = (uint64_t)a->width * a->height;
    return a->mixed ? n * (sizeof *a->first + 1) : 0;
}

void gls_accum_free(gls_accum *a)
{
    free(a->sum32);
    free(a->sum64);
    free(a->row);
    free(a->first);
    free(a->mixed);
    memset(a, 0, sizeof *a);
}

/* Mixed pixels of one sample row: compare RGB (alpha ignored) with the
 * first sample's. */
static void track_mixed(gls_accum *a, uint32_t y, const uint8_t *src, int first)
{
    uint32_t *f = a->first + (size_t)a->width * y;
    uint8_t *m = a->mixed + (size_t)a->width * y;
    for (uint32_t x = 0; x < a->width; x++) {
        uint32_t c;
        memcpy(&c, src + 4 * x, 4);
        c &= 0x00FFFFFFu; /* bytes R, G, B on little-endian; alpha ignored */
        if (first)
            f[x] = c;
        else
            m[x] |= f[x] != c;
    }
}

void gls_accum_add_tiles(gls_accum *a, const uint8_t *const *tile, size_t stride, uint32_t n, const uint64_t *w)
{
    size_t rowlen = (size_t)a->width * 4;
    if (n > GLS_ACCUM_MAX_TILES)
        n = GLS_ACCUM_MAX_TILES; /* callers stay within; never overflow a partial sum */
    for (uint32_t y = 0; y < a->height; y++) {
        size_t off = stride * y;
        if (!a->weighted) {
            /* uint16 partial sums of n <= 256 samples (<= 65280), then one
             * pass over the uint32 sums: plain loops the compiler turns
             * into SIMD widening adds */
            uint16_t *r = a->row;
            const uint8_t *src = tile[0] + off;
            for (size_t i = 0; i < rowlen; i++)
                r[i] = src[i];
            for (uint32_t t = 1; t < n; t++) {
                src = tile[t] + off;
                for (size_t i = 0; i < rowlen; i++)
                    r[i] = (uint16_t)(r[i] + src[i]);
            }
            uint32_t *s = a->sum32 + rowlen * y;
            for (size_t i = 0; i < rowlen; i++)
                s[i] += r[i];
        } else {
            uint64_t *r = a->row;
            memset(r, 0, rowlen * sizeof *r);
            for (uint32_t t = 0; t < n; t++) {
                const uint8_t *src = tile[t] + off;
                uint64_t wt = w[t];
                for (size_t i = 0; i < rowlen; i++)
                    r[i] += wt * src[i];
            }
            uint64_t *s = a->sum64 + rowlen * y;
            for (size_t i = 0; i < rowlen; i++)
                s[i] += r[i];
        }
        if (a->mixed)
            for (uint32_t t = 0; t < n; t++)
                track_mixed(a, y, tile[t] + off, a->samples == 0 && t == 0);
    }
    for (uint32_t t = 0; t < n; t++)
        a->wsum += a->weighted ? w[t] : 1;
    a->samples += n;
}

void gls_accum_add(gls_accum *a, const uint8_t *rgba, size_t stride, uint64_t w)
{
    gls_accum_add_tiles(a, &rgba, stride, 1, &w);
}

void gls_accum_add_rows(gls_accum *a, uint32_t y0, uint32_t rows, const uint8_t *rgba, size_t stride, uint64_t w)
{
    gls_accum_add_tiles_rows(a, y0, rows, &rgba, stride, 1, &w);
}

void gls_accum_add_tiles_rows(gls_accum *a, uint32_t y0, uint32_t rows, const uint8_t *const *tile, size_t stride,
                              uint32_t n, const uint64_t *w)
{
    /* the accumulator of those rows alone: the same sums, row buffer and
     * counts, seen from row y0 */
    size_t at = (size_t)a->width * y0;
    gls_accum v = *a;
    v.height = rows;
    if (v.sum32)
        v.sum32 += 4 * at;
    if (v.sum64)
        v.sum64 += 4 * at;
    if (v.first)
        v.first += at;
    if (v.mixed)
        v.mixed += at;
    const uint8_t *top[GLS_ACCUM_MAX_TILES];
    if (n > GLS_ACCUM_MAX_TILES)
        n = GLS_ACCUM_MAX_TILES;
    for (uint32_t t = 0; t < n; t++)
        top[t] = tile[t] + stride * y0;
    gls_accum_add_tiles(&v, top, stride, n, w);
    a->samples = v.samples;
    a->wsum = v.wsum;
}

static inline uint64_t sum_at(const gls_accum *a, size_t i)
{
    return a->weighted ? a->sum64[i] : a->sum32[i];
}

void gls_accum_rgba8(const gls_accum *a, uint8_t *rgba)
{
    size_t n = (size_t)a->width * a->height;
    uint64_t W = a->wsum ? a->wsum : 1;
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++)
            rgba[4 * i + c] = (uint8_t)((sum_at(a, 4 * i + c) * 2 + W) / (2 * W));
        rgba[4 * i + 3] = 255;
    }
}

void gls_accum_rgb16(const gls_accum *a, uint16_t *rgb)
{
    size_t n = (size_t)a->width * a->height;
    unsigned __int128 W = a->wsum ? a->wsum : 1;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            /* sum * 257 reaches 2^68 for Gaussian weights: 128-bit */
            unsigned __int128 s = (unsigned __int128)sum_at(a, 4 * i + c) * 257;
            rgb[3 * i + c] = (uint16_t)((2 * s + W) / (2 * W));
        }
}

void gls_accum_rgbf(const gls_accum *a, float *rgb)
{
    size_t n = (size_t)a->width * a->height;
    uint64_t W = a->wsum ? a->wsum : 1;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            /* integer part exactly, fraction in double: a constant pixel
             * (remainder 0) comes out as exactly c / 255 */
            uint64_t s = sum_at(a, 4 * i + c), q = s / W, r = s % W;
            rgb[3 * i + c] = (float)(((double)q + (double)r / (double)W) / 255.0);
        }
}

void gls_rgba8_to_rgb16(const uint8_t *rgba, size_t n, uint16_t *rgb)
{
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + c] = (uint16_t)(rgba[4 * i + c] * 257u);
}

void gls_rgba8_to_rgbf(const uint8_t *rgba, size_t n, float *rgb)
{
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + c] = (float)(rgba[4 * i + c] / 255.0);
}
