/* Sub-pixel anti-aliasing by jittered multi-pass accumulation
 * (spec/antialiasing.md): the sample plan (offsets and integer weights of
 * an N x N window) and the software accumulation buffer.
 *
 * The plan and the accumulator know nothing of GL: the player renders
 * sample k with the principal point shifted by (-du, -dv) (so that pixel
 * (u, v) sees the scene at (u + du, v + dv)) and hands each read-back to
 * gls_accum_add() with the sample's weight.  Everything here is exact
 * integer arithmetic except the Gaussian itself, which is evaluated in
 * double and then quantised once to integer weights whose sum the plan
 * knows exactly. */
#ifndef GLS_AA_H
#define GLS_AA_H

#include <stddef.h>
#include <stdint.h>
#include "lattice.h"

#define GLS_AA_MAX_N 4096u
/* Gaussian support: the window spans +-GLS_AA_GAUSS_SPAN sigma per axis. */
#define GLS_AA_GAUSS_SPAN 3.0
#define GLS_AA_DEFAULT_SIGMA 0.5
/* Gaussian weights are quantised to units of 2^-52 of the total. */
#define GLS_AA_WEIGHT_BITS 52

typedef enum { GLS_AA_BOX = 0, GLS_AA_GAUSS = 1 } gls_aa_filter;
typedef enum { GLS_AA_GRID = 0, GLS_AA_STRATIFIED = 1, GLS_AA_LATTICE = 2 } gls_aa_pattern;
/* Most samples per pixel (M): 4096^2. */
#define GLS_AA_MAX_SAMPLES (4096ull * 4096ull)
/* Most samples a lattice Gaussian window may hold (M times its cells). */
#define GLS_AA_MAX_WINDOW (1ull << 28)

typedef struct {
    uint32_t n;             /* N: N x N samples per pixel, 1..4096 (when
                               samples is 0)                               */
    uint64_t samples;       /* M samples per pixel, 1..4096^2; 0: N * N.
                               grid and stratified need a square          */
    gls_aa_filter filter;
    double sigma;           /* Gaussian sigma in pixels (> 0)              */
    gls_aa_pattern pattern;
    uint64_t seed;          /* stratified jitter seed                      */
    int exact;              /* GLS_AA_EXACT: exact coverage instead of
                               samples (exact.h, spec/antialiasing.md
                               "Exact coverage"): the plan is then one
                               sample's, the frame plan runs the exact
                               pass.  GLS_AA_AUTO (glsplay's default): exact
                               where the run allows it, else samples;
                               the player chooses once, before anything is
                               drawn (play_aa.c), and the plan after that
                               holds GLS_AA_EXACT or GLS_AA_SAMPLED       */
    uint32_t dense;         /* exact coverage: 0, every pixel exact; or a
                               pixel where more triangles may show is
                               point-sampled (gls_exact_render's dense;
                               --aa auto's GLS_EXACT_AUTO_DENSE)          */
} gls_aa_opts;

/* gls_aa_opts.exact (spec/antialiasing.md "The default") */
enum { GLS_AA_SAMPLED = 0, GLS_AA_EXACT = 1, GLS_AA_AUTO = 2 };

typedef struct {
    gls_aa_opts o;          /* o.n is sqrt(M) for grid and stratified      */
    uint64_t m;             /* M: samples per pixel (lattice: per pixel
                               area, also for the Gaussian)                */
    uint64_t count;         /* samples of the plan: M, except the lattice
                               Gaussian: M * cells^2, the lattice points
                               of the cells around the pixel (those outside
                               the +-3 sigma window have weight 0)        */
    gls_lattice lat;        /* the lattice pattern (pattern lattice)        */
    uint32_t radius;        /* lattice Gaussian: cells -radius..radius      */
    double span;            /* window width in pixels: 1 (box), 6 sigma    */
    double gsum;            /* Gaussian: sum of the raw double weights     */
    uint64_t wsum;          /* exact sum of the integer weights            */
} gls_aa_plan;

/* Default options: N = 1, box, lattice, sigma 0.5, seed 0. */
gls_aa_opts gls_aa_defaults(void);

/* Window size for a requested accuracy a (pixels, 0 < a <= 1): the
 * smallest N whose grid step span / N is at most a (span 1 for the
 * lattice, whose samples are per pixel area whatever the filter).  0 if N
 * would exceed GLS_AA_MAX_N. */
uint32_t gls_aa_n_for_accuracy(gls_aa_filter f, gls_aa_pattern pat, double sigma, double a);

/* Pattern name ("grid", "stratified", "lattice"). */
const char *gls_aa_pattern_name(gls_aa_pattern p);

/* Check the options and prepare the plan (for the Gaussian this makes
 * one pass over all samples to get the normalisation).  -1 with a message
 * if the options are invalid. */
int gls_aa_plan_init(gls_aa_plan *p, const gls_aa_opts *o, char *err, size_t errlen);

/* Sample k (0 <= k < count): offset in pixels from the pixel centre and
 * integer weight (0: outside the window, not a sample of the pixel).
 * Deterministic: the same plan gives the same samples. */
void gls_aa_sample(const gls_aa_plan *p, uint64_t k, double *du, double *dv, uint64_t *w);

/* Lattice: offset from the pixel centre of the point at (x, y) (units of
 * 1/lat.q px, in the pixel's square) in the cell (cx, cy) pixels away,
 * and its integer weight (0 outside the Gaussian window).  Sample k of
 * the plan is point k % M in cell k / M (row-major from -radius). */
void gls_aa_lattice_sample(const gls_aa_plan *p, int64_t x, int64_t y, int cx, int cy, double *du, double *dv,
                           uint64_t *w);

/* Normalised double weight of sample k (w / wsum before quantisation),
 * for tests. */
double gls_aa_weight_exact(const gls_aa_plan *p, uint64_t k);

/* The accumulation buffer: per pixel four sums (R, G, B and alpha, so
 * that the add loops run over contiguous RGBA bytes, alpha unused).
 *  unweighted (box, or N = 1): uint32 sums of the 8-bit samples; at most
 *    4096^2 = 2^24 samples of at most 255 sum to < 2^32: exact.
 *  weighted (Gaussian): uint64 sums of weight * sample; with weights
 *    summing to wsum <= 2^52, every sum stays below 255 * 2^52 < 2^60.
 * No rounding anywhere, whatever N.  Optionally tracks which pixels see
 * more than one colour (mixed pixels). */
typedef struct {
    uint32_t width, height;
    int weighted;
    uint32_t *sum32;        /* unweighted sums, width * height * 4          */
    uint64_t *sum64;        /* weighted sums, width * height * 4            */
    void *row;              /* one row of per-pass partial sums             */
    uint32_t *first;        /* mask: colour of the first sample, or NULL    */
    uint8_t *mixed;         /* mask: 1 where a sample differed, or NULL     */
    uint64_t samples;       /* samples added                               */
    uint64_t wsum;          /* weights added                               */
} gls_accum;

/* Most samples one gls_accum_add_tiles() call takes (the unweighted row
 * partial sums are uint16: 257 * 255 = 65535). */
#define GLS_ACCUM_MAX_TILES 256u
/* Most samples an unweighted accumulator takes exactly. */
#define GLS_ACCUM_MAX_SAMPLES (GLS_AA_MAX_N * GLS_AA_MAX_N)

/* weighted: 1 for plans whose weights are not all 1 (gls_aa_weighted). */
int gls_accum_init(gls_accum *a, uint32_t width, uint32_t height, int weighted, int track_mixed);
void gls_accum_free(gls_accum *a);
/* The bytes a's sums (and its row of partial sums) take, and those of its
 * mixed-pixel mask (0 when it tracks none): what gls_accum_init took. */
uint64_t gls_accum_sums_bytes(const gls_accum *a);
uint64_t gls_accum_mask_bytes(const gls_accum *a);
int gls_aa_weighted(const gls_aa_plan *p);
/* Add n <= GLS_ACCUM_MAX_TILES samples: tile[t] is the top-left pixel of
 * sample t's RGBA8 image, stride the bytes between its rows (4 * width
 * for a plain image, more for a mosaic), w[t] its weight (1 if the
 * accumulator is unweighted).  Each row of the n samples is summed in a
 * small buffer that stays in cache before it is added to the sums, so the
 * sums are read and written once per call, not once per sample. */
void gls_accum_add_tiles(gls_accum *a, const uint8_t *const *tile, size_t stride, uint32_t n, const uint64_t *w);
void gls_accum_add(gls_accum *a, const uint8_t *rgba, size_t stride, uint64_t w);
/* gls_accum_add for rows y0..y0+rows-1 only: rgba is the whole image
 * (those rows at their place), the other rows' sums untouched; samples
 * and wsum counted as by gls_accum_add. */
void gls_accum_add_rows(gls_accum *a, uint32_t y0, uint32_t rows, const uint8_t *rgba, size_t stride, uint64_t w);
/* gls_accum_add_tiles for rows y0..y0+rows-1 only, likewise: tile[t] is
 * sample t's whole image (its top-left pixel). */
void gls_accum_add_tiles_rows(gls_accum *a, uint32_t y0, uint32_t rows, const uint8_t *const *tile, size_t stride,
                              uint32_t n, const uint64_t *w);

/* Results (call when wsum equals the plan's wsum).  Each rounds the
 * exact quotient sum / wsum once:
 *   rgba8: round(sum / wsum), alpha 255           (8-bit PNG, PLY colours)
 *   rgb16: round(sum * 257 / wsum)                (16-bit PNG)
 *   rgbf:  sum / wsum / 255 as float              (PFM), exact for constants
 * A pixel all of whose samples have colour c gets c exactly in every form. */
void gls_accum_rgba8(const gls_accum *a, uint8_t *rgba);
void gls_accum_rgb16(const gls_accum *a, uint16_t *rgb);
void gls_accum_rgbf(const gls_accum *a, float *rgb);

/* Conversions of a single 8-bit image (N = 1, no accumulator). */
void gls_rgba8_to_rgb16(const uint8_t *rgba, size_t n, uint16_t *rgb);
void gls_rgba8_to_rgbf(const uint8_t *rgba, size_t n, float *rgb);

#endif
