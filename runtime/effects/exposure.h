/* Motion blur, rolling shutter and depth of field (spec/camera.md "Motion
 * blur, rolling shutter, depth of field"): an image accumulated over
 * sub-frame renders, each one the whole anti-aliasing plan drawn at its
 * own time and lens point.
 *
 * Sample j of K (the camera's exposure_samples) has
 *   time   s_j = S ((p(j) + 1/2) / K - 1/2) frame intervals from the frame
 *          time (the exposure [-S/2, S/2] is centred on it; p(j) = j a mod
 *          K, a coprime to K near K / golden ratio, decorrelates the time
 *          from the lens point; the midpoints of K equal sub-intervals:
 *          the box filter of the shutter by the midpoint rule);
 *   lens   (lx, ly) = A/2 sqrt((j + 1/2) / K) (cos j g, sin j g), g the
 *          golden angle (Vogel's spiral: a low-discrepancy set on the
 *          disk of diameter A), in the camera frame.
 * The camera for lens point l is moved by l in its own frame and its
 * principal point shifted by (fx lx + skew ly, fy ly) / F, so that the
 * plane Zc = F projects where it does without depth of field; a point at
 * depth Z moves by f l (1/F - 1/Z) pixels, its circle of confusion has
 * diameter c = f A |Z - F| / (Z F) pixels (f = fx across, fy down).
 * Rolling shutter: row v is exposed at s + v D (row 0 at the frame time);
 * rows are drawn in bands, each at its middle row's time, of at most h
 * rows where the image moves at most GLS_BAND_PX pixels within h D. */
#ifndef GLS_EXPOSURE_H
#define GLS_EXPOSURE_H
#include <stdio.h>
#include "aa.h"
#include "camera.h"
#include "render.h"

/* Most pixels the image may move within one band of rows. */
#define GLS_BAND_PX 0.125

/* Pose the scene (moving instances) at s frame intervals from the frame
 * time and set cam's R and T to the camera's pose then.  0, or -1. */
typedef int (*gls_pose_at_fn)(void *ud, double s, gls_camera *cam);

/* Render the plan through camera c into acc (initialised for c's size,
 * unweighted or weighted as the plan, tracking mixed pixels or not):
 * at least image rows v0..v1-1 (a band of a rolling shutter), which are
 * the same bits as in the whole image; the other rows may be left out.
 * 0, or -1 with a complete message in msg. */
typedef int (*gls_render_plan_fn)(void *ud, const gls_camera *c, uint32_t v0, uint32_t v1, gls_accum *acc, char *msg,
                                  size_t msglen);

typedef struct {
    int blur, rolling, dof;  /* which effects are on                      */
    uint32_t samples;        /* K: sub-frame renders (1: rolling only)    */
} gls_exposure;

/* The effects camera c turns on; moving: something moves (--trajectory
 * or --motion), without which shutter and line_delay do nothing. */
gls_exposure gls_exposure_of(const gls_camera *c, int moving);
static inline int gls_exposure_on(const gls_exposure *e) { return e->blur || e->rolling || e->dof; }

/* Time offsets (frame intervals) the exposure of c spans: [*s0, *s1]. */
void gls_exposure_span(const gls_camera *c, const gls_exposure *e, double *s0, double *s1);

/* Sample j: its time offset and lens point (see above). */
void gls_exposure_sample(const gls_camera *c, const gls_exposure *e, uint32_t j, double *s, double *lx, double *ly);

/* Camera c seen through lens point (lx, ly): moved and sheared. */
void gls_exposure_lens(const gls_camera *c, double lx, double ly, gls_camera *out);

/* Do K sub-frame renders of the plan fit the accumulator's exact range?
 * 0, or -1 with why. */
int gls_exposure_fits(const gls_exposure *e, const gls_aa_plan *p, char *why, size_t whylen);

/* The bands of rows a rolling shutter draws: rows each
 * (gls_exposure_band_rows; the height without a rolling shutter), each
 * band drawing and reading back only the rows it keeps.  whole, for a
 * test only (gls_play_opts' bands_whole, which glsplay never sets;
 * tests/e2e/rolling_bands.sh through tools/glsplay_bands_whole.c): every
 * band draws and reads back the whole image (the whole fine image through
 * a lens), as before the bands' rows were narrowed, so that the test can
 * compare the two byte for byte.  A parameter, not the environment: the
 * production path reads no switch of a test. */
typedef struct {
    uint32_t rows;
    int whole;
} gls_bands;

/* Rows per band for rolling shutter: at most GLS_BAND_PX pixels of image
 * motion within a band, from the projected corners of the scene's item
 * boxes at 8 times over the readout (an estimate: box corners, not the
 * surfaces).  Poses the scene (pose_at) and leaves it at s = 0. */
uint32_t gls_exposure_band_rows(const gls_renderer *r, const gls_camera *c, const gls_exposure *e,
                                gls_pose_at_fn pose_at, void *ud);

/* The image: every sample j, every band of bands.rows rows, rendered by
 * render_plan into a scratch accumulator whose band rows are added to
 * acc (render_plan asked for the band's rows, or the whole image when
 * bands.whole).  Leaves the scene at s = 0.  0, or -1 with msg. */
int gls_exposure_render(gls_renderer *r, const gls_camera *c, const gls_exposure *e, const gls_aa_plan *p,
                        gls_pose_at_fn pose_at, gls_render_plan_fn render_plan, void *ud, gls_accum *acc,
                        gls_bands bands, char *msg, size_t msglen);

/* One band of one sample: rows v0..v1-1 of the image through camera at
 * (posed at the band's time, not yet moved to the lens point (lx, ly))
 * drawn into tmp (cleared, c's size; only those rows are kept).  0, or -1
 * with msg. */
typedef int (*gls_render_band_fn)(void *ud, const gls_camera *at, double lx, double ly, uint32_t v0, uint32_t v1,
                                  gls_accum *tmp, char *msg, size_t msglen);

/* gls_exposure_render with the band drawn by render_band (a lens,
 * distort_exposure.h): the same samples, bands, times and sums. */
int gls_exposure_render_bands(const gls_camera *c, const gls_exposure *e, const gls_aa_plan *p,
                              gls_pose_at_fn pose_at, void *pose_ud, gls_render_band_fn render_band, void *band_ud,
                              gls_accum *acc, uint32_t band, char *msg, size_t msglen);

/* Rolling shutter: each row's camera pose (R row-major, then T), that of
 * its band of `band` rows (the middle row's time), the pose its depth was
 * drawn with; the scene left at s = 0.  A malloc'd H x 12 array, or NULL
 * when out of memory. */
double (*gls_exposure_row_poses(const gls_camera *c, uint32_t band, gls_pose_at_fn pose_at, void *ud))[12];

/* --explain: what the effects of camera c cost; image: an output is
 * drawn with them (the frame plan's decision, frame_plan.h). */
void gls_exposure_explain(FILE *out, const gls_camera *c, int moving, const gls_aa_plan *p, int image);

#endif
