/* The passes of a camera frame that draw (play_int.h): the scene and
 * camera posed at a time within the exposure (play_pose_at), the
 * anti-aliasing plan drawn into the accumulator (play_render_plan), the
 * centre and ground-truth passes in bands of rows under a rolling shutter
 * (play_centre_bands), and the time estimate they report to. */
#include <stdlib.h>
#include <string.h>
#include "aa_onepass.h"
#include "aa_render.h"
#include "frame_files.h"
#include "gt_pass.h"
#include "play_int.h"
#include "progress.h"
#include "subframe.h"
#include "units.h"

/* The time estimate (spec/road.md "Progress and time estimate").  Made
 * once, from the earliest of: the anti-aliasing passes of the first camera
 * frame once they have run for ESTIMATE_AA_S (a long render learns its
 * fate within seconds, not after its first frame), or the camera frames
 * done once ESTIMATE_VIEWS_S have passed.  Both include the start-up
 * (shader compilation, first touches of memory), so they err long. */
#define ESTIMATE_AA_S 2.0
#define ESTIMATE_VIEWS_S 0.5

static void estimate_from_passes(void *ctx, uint64_t done, uint64_t total, double elapsed)
{
    session *s = ctx;
    if (s->estimated || s->views_done || done >= total || elapsed < ESTIMATE_AA_S)
        return;
    s->estimated = 1;
    gls_estimate_report(s->errs, elapsed, done, total, s->views);
}

/* The same for the one-pass renderer, whose steps are tiles. */
static void estimate_from_tiles(void *ctx, uint64_t done, uint64_t total, double elapsed)
{
    session *s = ctx;
    if (s->estimated || s->views_done || done >= total || elapsed < ESTIMATE_AA_S)
        return;
    s->estimated = 1;
    gls_estimate_report_units(s->errs, elapsed, done, total, s->views, "tiles");
}

void play_view_done(session *s)
{
    s->views_done++;
    if (s->estimated)
        return;
    double el = gls_now() - s->t0;
    if (s->views_done >= s->views || el >= ESTIMATE_VIEWS_S) {
        s->estimated = 1;
        if (s->views_done < s->views)
            gls_estimate_report(s->errs, el, s->views_done, 1, s->views);
    }
}

/* The scene and the camera s frame intervals after the frame time
 * (exposure.h): the moving instances and the rig interpolated between
 * their rows (subframe.h); checked to exist before rendering. */
int play_pose_at(void *ud, double t, gls_camera *cam)
{
    session *s = ud;
    const motion_set *ms = s->ms;
    double x = (double)s->frame_now + t, R[9], T[3];
    int rc = 0;
    for (size_t i = 0; i < ms->n; i++) {
        if (gls_motion_pose_at(&ms->m[i], x, 0, R, T) == 0)
            gls_scene_move(ms->scene, ms->inst[i], R, T);
        else
            rc = -1;
    }
    if (ms->n)
        gls_scene_update(ms->scene);
    if (ms->rig.n && s->rel_now) {
        if (gls_motion_pose_at(&ms->rig, x, 1, R, T) == 0)
            gls_traj_compose(s->rel_now->R, s->rel_now->T, R, T, cam->R, cam->T);
        else
            rc = -1;
    }
    return rc;
}

/* The anti-aliasing plan drawn through camera c into acc (aa.h): one
 * fine framebuffer for the lattice and grid, jittered passes for
 * stratified, one plain pass without anti-aliasing.  0, or -1 with the
 * message in msg.  Also the exposure's render of one sub-frame sample
 * (exposure.h), whence the signature. */
int play_render_plan(void *ud, const gls_camera *c, uint32_t v0, uint32_t v1, gls_accum *acc, char *msg,
                     size_t msglen)
{
    static const char lower_size[] = "lower --size (or the camera's width and height)";
    session *s = ud;
    const gls_play_opts *o = s->o;
    const gls_aa_plan *plan = s->plan;
    gls_renderer *r = s->r;
    const char *name = s->name_now;
    char err[512];
    if (plan->count == 1) {
        uint8_t *rgba = malloc((size_t)c->width * c->height * 4);
        if (!rgba) {
            gls_frame_oom_message(msg, msglen, name, c->width, c->height, (uint64_t)c->width * c->height * 4);
            return -1;
        }
        /* only rows v0..v1-1 drawn (scissored: the whole pass's bits),
         * read back and added; so do the fine framebuffer's tiles and the
         * jittered passes below */
        gls_render_pass_rows(r, c, v0, v1 - v0);
        gls_render_read_rgba_rows(r, v0, v1 - v0, rgba);
        gls_accum_add_rows(acc, v0, v1 - v0, rgba, (size_t)c->width * 4, 1);
        free(rgba);
        return 0;
    }
    if (gls_aa_fine_ok(plan)) {
        /* lattice and grid: the samples are the pixels of a fine
         * framebuffer drawn in tiles (aa_onepass.h), those of rows
         * v0..v1-1 only */
        /* the estimate only where there is somewhere to say it (not the
         * library's frames, gls_play_frame) */
        gls_aa_fine_opts fo = {o->aa_memory, 0, 0, o->progress == GLS_PROGRESS_BAR ? s->errs : NULL, name,
                               s->errs ? estimate_from_tiles : NULL, s};
        if (gls_aa_render_fine_rows(r, c, plan, &fo, v0, v1, acc, NULL, err, sizeof err)) {
            char mem[32];
            gls_fmt_bytes(mem, sizeof mem, o->aa_memory ? o->aa_memory : GLS_AA_DEFAULT_MEMORY);
            snprintf(msg, msglen, "glsplay: error: camera %s: %s; lower --aa-memory (%s now)", name, err,
                     mem);
            return -1;
        }
    } else {
        /* stratified, grid Gaussian: one jittered pass per sample,
         * several per GL pass (aa_render.h), rows v0..v1-1 only */
        gls_aa_run_opts ro = {o->aa_tiles, 0, o->progress == GLS_PROGRESS_BAR ? s->errs : NULL, name,
                              s->errs ? estimate_from_passes : NULL, s};
        if (gls_aa_render_rows(r, c, plan, &ro, v0, v1, acc, NULL, err, sizeof err)) {
            uint32_t kx, ky;
            gls_aa_mosaic_shape(r, c->width, c->height, plan->count, o->aa_tiles, &kx, &ky);
            if (kx * ky > 1)
                snprintf(msg, msglen, "glsplay: error: camera %s: %s; lower --aa-tiles (%u tiles a pass now)",
                         name, err, kx * ky);
            else
                snprintf(msg, msglen, "glsplay: error: camera %s: %s; %s", name, err, lower_size);
            return -1;
        }
    }
    return 0;
}

/* Rolling shutter: the centre pass (colour, depth) and the ground-truth
 * pass (ids, normals) of each band of `band` rows drawn at its middle
 * row's time, scissored to the band's rows (the whole pass's viewport and
 * projection, so the same bits) and read back straight into their place;
 * the scene left at the frame time.  The buffers not asked for are NULL.
 * With the test's choice (gls_bands' whole, exposure.h) each band draws
 * and reads the whole image into scratch buffers and copies its rows out,
 * as before the rows were narrowed.  0, or -1 with msg. */
int play_centre_bands(session *s, const gls_camera *c, gls_bands bands, uint8_t *rgba, float *z, uint32_t *inst,
                      float *normal, float *gt_z, char *msg, size_t msglen)
{
    size_t n = (size_t)c->width * c->height, W = c->width;
    uint32_t band = bands.rows;
    int whole = bands.whole;
    uint8_t *rb = whole && rgba ? malloc(n * 4) : NULL;
    float *zb = whole && z ? malloc(n * sizeof *zb) : NULL, *gb = whole && gt_z ? malloc(n * sizeof *gb) : NULL;
    float *nb = whole && normal ? malloc(n * 3 * sizeof *nb) : NULL;
    uint32_t *ib = whole && inst ? malloc(n * sizeof *ib) : NULL;
    char err[512];
    int rc = -1;
    if (whole && ((rgba && !rb) || (z && !zb) || (gt_z && !gb) || (normal && !nb) || (inst && !ib))) {
        gls_frame_oom_message(msg, msglen, s->name_now, c->width, c->height, 32 * (uint64_t)n);
        goto out;
    }
    for (uint32_t v0 = 0; v0 < c->height; v0 += band) {
        uint32_t v1 = v0 + band < c->height ? v0 + band : c->height;
        size_t a = W * v0, len = W * (v1 - v0);
        /* the rows drawn and read, and where they are read into */
        uint32_t y0 = whole ? 0 : v0, rows = whole ? c->height : v1 - v0;
        gls_camera at = *c;
        play_pose_at(s, c->line_delay * (v0 + v1 - 1) / 2.0, &at);
        if (rgba || z) {
            gls_render_pass_rows(s->r, &at, y0, rows);
            if (rgba)
                gls_render_read_rgba_rows(s->r, y0, rows, whole ? rb : rgba);
            if (z)
                gls_render_read_z_rows(s->r, y0, rows, whole ? zb : z);
        }
        /* flow starts from the ground-truth pass's depth */
        if ((inst || normal || gt_z) && gls_gt_render_rows(s->r, &at, y0, rows, whole ? ib : inst,
                                                           whole ? nb : normal, whole ? gb : gt_z, err, sizeof err)) {
            snprintf(msg, msglen, "glsplay: error: camera %s: %s", s->name_now, err);
            goto out;
        }
        if (whole) { /* the band's rows of the whole images */
            if (rgba)
                memcpy(rgba + 4 * a, rb + 4 * a, 4 * len);
            if (z)
                memcpy(z + a, zb + a, len * sizeof *z);
            if (inst)
                memcpy(inst + a, ib + a, len * sizeof *inst);
            if (normal)
                memcpy(normal + 3 * a, nb + 3 * a, 3 * len * sizeof *normal);
            if (gt_z)
                memcpy(gt_z + a, gb + a, len * sizeof *gt_z);
        }
    }
    rc = 0;
out:
    {
        gls_camera at = *c;
        play_pose_at(s, 0, &at);
    }
    free(rb);
    free(zb);
    free(gb);
    free(nb);
    free(ib);
    return rc;
}
