/* Anti-aliased rendering: the sample plan (aa.h) drawn through the
 * renderer (render.h) into the accumulator, several samples per GL pass
 * (a mosaic of tiles, one read-back each) with the accumulation of one
 * read-back overlapping the rasterisation of the next.
 * spec/antialiasing.md describes the method and its exactness. */
#ifndef GLS_AA_RENDER_H
#define GLS_AA_RENDER_H

#include <stdio.h>
#include "aa.h"
#include "render.h"

typedef struct {
    uint32_t tiles;     /* samples per GL pass (mosaic tiles); 0: automatic */
    int serial;         /* 1: no overlap, glFinish after drawing, so that the
                           times below separate draw, read-back and
                           accumulation (for the benchmark) */
    FILE *progress;     /* progress lines ("\r...") go here; NULL: none */
    const char *label;  /* name in the progress line */
    /* called after every pass with the passes done, the passes of this
     * render and the seconds since it began (the player's time estimate);
     * NULL: none */
    void (*on_pass)(void *ctx, uint64_t done, uint64_t total, double elapsed);
    void *ctx;
} gls_aa_run_opts;

typedef struct {
    uint64_t samples, passes;
    uint32_t kx, ky;            /* the mosaic used                        */
    double draw_s, read_s, accum_s, total_s;
} gls_aa_stats;

/* Tiles per pass the automatic choice gives for a width x height image:
 * mosaics up to about 0.5 Mpixel (see spec/antialiasing.md, measured with
 * make bench-aa), never more than the plan has samples. */
void gls_aa_mosaic_shape(const gls_renderer *r, uint32_t width, uint32_t height, uint64_t samples,
                         uint32_t tiles, uint32_t *kx, uint32_t *ky);

/* Render every sample of plan p through camera c into acc (initialised
 * for the camera's size).  Leaves the renderer with a 1 x 1 mosaic.
 * -1 with a message on failure (framebuffer, memory). */
int gls_aa_render(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_run_opts *ro,
                  gls_accum *acc, gls_aa_stats *st, char *err, size_t errlen);
/* gls_aa_render of image rows v0..v1-1 only (0 <= v0 < v1 <= height):
 * each pass draws (scissored, its whole viewport and projection) and reads
 * back those rows, and only their sums change.  A sample of pixel (u, v)
 * is drawn in row v of its pass whatever the filter (the jitter moves the
 * projection, not the pixel), so those rows are the whole render's bit
 * for bit.  For the bands of a rolling shutter (exposure.h). */
int gls_aa_render_rows(gls_renderer *r, const gls_camera *c, const gls_aa_plan *p, const gls_aa_run_opts *ro,
                       uint32_t v0, uint32_t v1, gls_accum *acc, gls_aa_stats *st, char *err, size_t errlen);

#endif
