/* One-pass anti-aliasing (spec/antialiasing.md "One pass"): the samples
 * of a lattice plan drawn as the pixels of one fine framebuffer (in tiles
 * that fit a memory budget, geometry culled per tile, K passes when M is
 * too large for one), gathered into the exact accumulator (aa.h). */
#ifndef GLS_AA_ONEPASS_H
#define GLS_AA_ONEPASS_H

#include <stdio.h>
#include "aa_fine.h"
#include "render.h"

/* Default memory for the fine framebuffer and its read-backs. */
#define GLS_AA_DEFAULT_MEMORY (256ull << 20)
/* Bytes per fine pixel: RGBA8 colour and float depth renderbuffers, the
 * renderer's float depth scratch, and two RGBA8 read-backs (one is
 * gathered while the next tile is drawn). */
#define GLS_AA_FINE_PIXEL_BYTES 20u

typedef struct {
    uint64_t memory;    /* bytes for tiles and read-backs; 0: the default  */
    uint32_t max_tile;  /* largest tile side (tests use tiny tiles); 0: auto */
    uint64_t max_l;     /* most samples per pixel and pass; 0: automatic  */
    FILE *progress;     /* progress lines, or NULL                          */
    const char *label;
    void (*on_pass)(void *ctx, uint64_t done, uint64_t total, double elapsed);
    void *ctx;
} gls_aa_fine_opts;

typedef struct {
    gls_aa_fine f;          /* K, L, A                                   */
    uint32_t tw, th;        /* tile size, fine pixels                    */
    int64_t x0, y0, fw, fh; /* fine bounding box of one pass             */
    uint64_t tiles;         /* tiles per pass (before skipping)          */
    uint64_t kernel;        /* gather entries per pixel and pass          */
    uint64_t bytes;         /* memory the tiles and read-backs take       */
} gls_aa_fine_layout;

typedef struct {
    gls_aa_fine_layout lay;
    uint64_t tiles_drawn, tiles_skipped, chunks_drawn, chunks_total;
    double draw_s, read_s, gather_s, total_s;
} gls_aa_fine_stats;

/* The layout for a W x H camera (maxdim: GL's largest framebuffer side,
 * 0 for the camera limit): passes, tile size, memory.  -1 with a message
 * if the plan is not a fine-framebuffer plan or nothing fits. */
int gls_aa_fine_plan(const gls_aa_plan *p, uint32_t w, uint32_t h, uint32_t maxdim, const gls_aa_fine_opts *fo,
                     gls_aa_fine_layout *lay, char *err, size_t errlen);

/* Render plan p through camera c into acc (initialised for the camera's
 * size; its wsum ends equal to the plan's).  Leaves the renderer at the
 * camera's size.  -1 with a message on failure. */
int gls_aa_render_fine(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_fine_opts *fo,
                       gls_accum *acc, gls_aa_fine_stats *st, char *err, size_t errlen);
/* The same for image rows v0..v1-1 only (a rolling shutter's band): the
 * same tiles at the same places, those no pixel of the rows needs
 * skipped, the others scissored to the samples of the rows, so those
 * rows' sums are the whole render's bit for bit; acc's other rows get
 * nothing (or part of their samples: not to be read). */
int gls_aa_render_fine_rows(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_fine_opts *fo,
                            uint32_t v0, uint32_t v1, gls_accum *acc, gls_aa_fine_stats *st, char *err, size_t errlen);

/* Add the sums of the R, G and B bytes of len RGBA8 pixels at q to s[0..2]
 * (the gather's inner loop; exposed for its unit test). */
void gls_aa_sum_run(const uint8_t *q, uint32_t len, uint32_t s[3]);

#endif
