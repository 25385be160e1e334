/* gls_play(): load, check everything, then render and write (player.h).
 * Every input is checked before the first pixel is drawn, so an error in
 * the last camera file leaves no output of the first camera behind.
 *
 * Over 500 lines because it is one job, the order of a run: check every
 * input, then for each camera (or each frame of a trajectory) render,
 * write and record progress, all through one session's state.  What has a
 * job of its own is elsewhere already (outputs.c, aa_render.c,
 * frame_files.c and frame_writer.c (encoding and writing, on a thread),
 * frame_record.c, progress.c, trajectory.c); splitting the camera and the
 * trajectory loops apart would cut through that shared state. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "aa_onepass.h"
#include "aa_render.h"
#include "atomic_write.h"
#include "calib_write.h"
#include "distort.h"
#include "distort_exposure.h"
#include "distort_render.h"
#include "frame_files.h"
#include "frame_plan.h"
#include "frames.h"
#include "frame_record.h"
#include "frame_writer.h"
#include "glctx.h"
#include "gt_boxes.h"
#include "gt_flow.h"
#include "gt_flow_rolling.h"
#include "lens_truth.h"
#include "gt_landmarks.h"
#include "gt_pass.h"
#include "gt_table.h"
#include "mkdirs.h"
#include "numfmt.h"
#include "motion.h"
#include "out_disparity.h"
#include "out_flow.h"
#include "outputs.h"
#include "player.h"
#include "progress.h"
#include "progress_json.h"
#include "shard.h"
#include "exposure.h"
#include "exposure_landmarks.h"
#include "subframe.h"
#include "suggest.h"
#include "trajectory.h"
#include "render.h"
#include "sensor_image.h"
#include "units.h"

#define MAXPATH 4096

int gls_output_path(char *buf, size_t len, const char *outdir, const char *name, const char *kind,
                    uint32_t frame, const char *ext)
{
    int k = snprintf(buf, len, "%s/%s/%s_%06u.%s", outdir, name, kind, frame, ext);
    return k < 0 || (size_t)k >= len ? -1 : 0;
}

/* Camera name: the file name without directory and without ".cam" (or
 * ".yml", ".yaml": an OpenCV camera file). */
static char *camera_name(const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t n = strlen(base);
    static const char *const ext[] = {".cam", ".yml", ".yaml"};
    for (size_t i = 0; i < 3; i++) {
        size_t e = strlen(ext[i]);
        if (n > e && strcmp(base + n - e, ext[i]) == 0) {
            n -= e;
            break;
        }
    }
    char *s = malloc(n + 1);
    if (s) {
        memcpy(s, base, n);
        s[n] = 0;
    }
    return s;
}


/* The file an output kind of one camera and frame goes to; -1 if too long. */
static int output_file(char *path, size_t len, const gls_play_opts *o, const char *name, size_t k, uint32_t frame)
{
    const char *ext = gls_output_kinds[k].ext;
    if (!ext || (gls_output_kinds[k].bit == GLS_OUT_IMAGE && o->image_format == GLS_IMG_PFM))
        ext = o->float_format == GLS_FLOAT_NPY ? "npy" : "pfm";
    return gls_output_path(path, len, o->outdir, name, gls_output_kinds[k].stem, frame, ext);
}

/* --motion: the named instances and their motion files. */
typedef struct {
    gls_scene *scene;
    size_t n;
    uint32_t *inst;
    gls_motion *m;
    int moving;      /* a trajectory or a motion: shutter and line_delay act */
    gls_motion rig;  /* the trajectory read whole for sub-frame poses (rig.n
                        = 0: not needed, subframe.h) */
    gls_traj_text traj; /* --trajectory's bytes, read once: every reader
                           parses them (data NULL: no trajectory) */
} motion_set;

/* Every camera whose exposure spans more than the frame time (shutter,
 * line_delay) needs poses at each time of the span: within the rows of
 * the trajectory and of every motion (interpolated, never extrapolated,
 * subframe.h).  0, or -1 after a message. */
static int exposure_check(const motion_set *ms, const gls_camera *cams, const char *const *names, size_t ncams,
                          uint64_t frame, FILE *errs)
{
    for (size_t c = 0; c < ncams; c++) {
        gls_exposure e = gls_exposure_of(&cams[c], ms->moving);
        if (!e.blur && !e.rolling)
            continue;
        double s0, s1;
        gls_exposure_span(&cams[c], &e, &s0, &s1);
        double x0 = (double)frame + s0, x1 = (double)frame + s1;
        for (size_t i = 0; i <= ms->n; i++) {
            const gls_motion *m = i < ms->n ? &ms->m[i] : &ms->rig;
            if (!m->n || (x0 >= (double)m->frame[0] && x1 <= (double)m->frame[m->n - 1]))
                continue;
            char a[40], b[40];
            gls_fmt_double(a, sizeof a, x0);
            gls_fmt_double(b, sizeof b, x1);
            fprintf(errs, "glsplay: error: camera %s, frame %llu: its exposure spans frames %s to %s, beyond the rows "
                          "of %s (frames %llu to %llu); sub-frame poses are interpolated between rows, never "
                          "extrapolated: render fewer --frames or extend the file\n",
                    names[c], (unsigned long long)frame, a, b, m->path, (unsigned long long)m->frame[0],
                    (unsigned long long)m->frame[m->n - 1]);
            return -1;
        }
    }
    return 0;
}

/* Every frame to be rendered must have a row in every motion file. */
static int motion_check(const motion_set *ms, uint64_t frame, FILE *errs)
{
    double R[9], T[3];
    for (size_t i = 0; i < ms->n; i++)
        if (gls_motion_pose(&ms->m[i], frame, R, T)) {
            fprintf(errs, "glsplay: error: %s: no row for frame %llu (the motion of instance %s)\n", ms->m[i].path,
                    (unsigned long long)frame, ms->scene->inst[ms->inst[i]].name);
            return -1;
        }
    return 0;
}

/* Pose the moving instances for frame (checked by motion_check). */
static void motion_apply(const motion_set *ms, uint64_t frame)
{
    double R[9], T[3];
    for (size_t i = 0; i < ms->n; i++)
        if (gls_motion_pose(&ms->m[i], frame, R, T) == 0)
            gls_scene_move(ms->scene, ms->inst[i], R, T);
    if (ms->n)
        gls_scene_update(ms->scene);
}

/* Read the --motion arguments against the scene's instance names.  0, or
 * 1 after a message. */
static int motion_load(const gls_play_opts *o, motion_set *ms, FILE *errs)
{
    char err[1024];
    ms->inst = calloc(o->nmotions ? o->nmotions : 1, sizeof *ms->inst);
    ms->m = calloc(o->nmotions ? o->nmotions : 1, sizeof *ms->m);
    if (!ms->inst || !ms->m) {
        fprintf(errs, "glsplay: error: out of memory\n");
        return 1;
    }
    for (size_t i = 0; i < o->nmotions; i++) {
        const char *arg = o->motions[i], *eq = strchr(arg, '=');
        char name[GLS_INSTANCE_NAME_MAX + 2];
        size_t len = (size_t)(eq - arg);
        snprintf(name, sizeof name, "%.*s", (int)(len < sizeof name - 1 ? len : sizeof name - 1), arg);
        uint32_t k = len <= GLS_INSTANCE_NAME_MAX ? gls_scene_find_instance(ms->scene, name) : GLS_NONE;
        if (k == GLS_NONE) {
            const char **names = calloc(ms->scene->ninst ? ms->scene->ninst : 1, sizeof *names);
            size_t nn = 0;
            for (uint32_t j = 0; names && j < ms->scene->ninst; j++)
                if (ms->scene->inst[j].name)
                    names[nn++] = ms->scene->inst[j].name;
            const char *s = names ? gls_suggest(arg, len, names, nn) : NULL;
            fprintf(errs, "glsplay: error: --motion %.*s: %s has no instance named '%.*s'%s%s%s\n", (int)len, arg,
                    o->bundle, (int)len, arg, s ? "; did you mean '" : nn ? "" : " (it names no instance)",
                    s ? s : "", s ? "'?" : "");
            free(names);
            return 1;
        }
        for (size_t j = 0; j < i; j++)
            if (ms->inst[j] == k) {
                fprintf(errs, "glsplay: error: --motion %s: instance %s is moved twice\n", arg, name);
                return 1;
            }
        ms->inst[i] = k;
        int got = gls_motion_read(eq + 1, errs, &ms->m[i], err, sizeof err);
        if (got) {
            /* the file itself (missing, a FIFO...): say which option named it */
            if (got == -2)
                fprintf(errs, "glsplay: error: --motion %s: %s\n", arg, err);
            else
                fprintf(errs, "%s\n", err);
            return 1;
        }
        ms->n = i + 1;
    }
    return 0;
}

static void motion_free(motion_set *ms)
{
    for (size_t i = 0; ms->m && i < ms->n; i++)
        gls_motion_free(&ms->m[i]);
    gls_motion_free(&ms->rig);
    gls_traj_text_free(&ms->traj);
    free(ms->m);
    free(ms->inst);
}

/* What one run keeps across cameras and frames: the options, the
 * renderer, and the timing behind the progress line and the estimate. */
typedef struct {
    const gls_play_opts *o;
    const motion_set *ms;
    const gls_scene *scene;     /* its landmarks (--outputs landmarks)  */
    const gls_aa_plan *plan;
    gls_renderer *r;
    gls_writer *w;              /* where each camera frame's files go   */
    gls_progress_json *json;    /* --progress json: told of each written frame */
    FILE *errs;
    uint64_t views, views_done; /* camera frames to render, rendered    */
    double t0;                  /* when rendering began                 */
    int estimated;              /* the estimate was made (printed or not) */
    double baseline;            /* disparity: B of the rectified pair   */
    const gls_gt_table *gt;     /* instance and class ids, when asked   */
    /* flow (gt_flow.h): the next row of the trajectory (NULL: none, the
     * frame writes no flow), the camera's pose relative to the rig, and
     * the moving instances' transforms */
    const gls_traj_pose *next;
    const gls_camera *rel;
    gls_flow_moves *moves;
    const gls_box_names *box_names; /* boxes: the objects' names */
    /* sub-frame poses (exposure.h, subframe.h): the trajectory read whole
     * (NULL: none, or no camera needs it), the frame being rendered, the
     * camera's pose relative to the rig, whether anything moves */
    uint64_t frame_now;
    const gls_camera *rel_now;
    int moving;
    const char *name_now;       /* the camera being rendered            */
    const char *inputs;         /* the frame records' inputs digest     */
    gls_frame_counts *counts;   /* what the last camera frame did, counted
                                   (NULL: not counted; o->counts)      */
} session;

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

static void view_done(session *s)
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

/* Say why a camera frame failed.  An earlier frame's files may still be
 * in the writer: if one of them failed, a run without the writer thread
 * would have stopped there, so that message is said instead of this one
 * (the same message whatever the thread's timing). */
static void say_failure(session *s, const char *msg)
{
    char earlier[1024];
    fprintf(s->errs, "%s\n", gls_writer_finish(s->w, earlier, sizeof earlier) ? earlier : msg);
}

static int pose_at(void *ud, double t, gls_camera *cam);
static int flow_frame_rolling(session *s, const gls_camera *c, const gls_distort_frame *df, const char *name,
                              uint32_t frame, gls_bands bands, const uint32_t *inst, const float *z, float *z1, float *uv,
                              uint8_t *mask, char *msg, size_t msglen);

/* The flow of camera c from frame to the trajectory's next row (gt_flow.h),
 * from this frame's ground-truth pass (inst, z): the depth of the next
 * (its camera pose and motions; an extra centre pass), then the scene
 * posed back for this frame's other cameras.  0 with *uv and *mask, or -1
 * with the whole line in msg (empty: out of memory). */
static int flow_frame(session *s, const gls_camera *c, const gls_distort_frame *df, const char *name, uint32_t frame,
                      gls_bands bands,
                      const uint32_t *inst, const float *z, float **uv, uint8_t **mask, char *msg, size_t msglen)
{
    size_t n = (size_t)c->width * c->height;
    float *z1 = malloc(n * sizeof *z1);
    char err[512];
    int rc = -1;
    *uv = malloc(2 * n * sizeof **uv);
    *mask = malloc(n ? n : 1);
    if (!z1 || !*uv || !*mask)
        goto out;
    if (s->counts)
        s->counts->bytes[GLS_BUF_FLOW] += n * sizeof *z1 + 2 * n * sizeof **uv + n,
            s->counts->passes[GLS_PASS_I_FLOW_NEXT]++;
    if (bands.rows < c->height) {
        /* rolling shutter: both frames' rows at their own times (a lens,
         * df: their points projected by its model) */
        rc = flow_frame_rolling(s, c, df, name, frame, bands, inst, z, z1, *uv, *mask, msg, msglen);
        if (rc)
            goto out;
        goto check;
    }
    gls_camera c1 = *c;
    gls_traj_compose(s->rel->R, s->rel->T, s->next->R, s->next->T, c1.R, c1.T);
    gls_flow_moves_take(s->moves, s->ms->scene, 0);
    if (s->ms->n) {
        motion_apply(s->ms, s->next->frame);
        gls_flow_moves_take(s->moves, s->ms->scene, 1);
    }
    /* a lens (df): the next frame's depth through it, its points projected by its model */
    rc = df ? gls_lens_gt_render(s->r, df, &c1, NULL, NULL, z1, err, sizeof err)
            : gls_gt_render(s->r, &c1, NULL, NULL, z1, err, sizeof err);
    if (s->ms->n)
        motion_apply(s->ms, frame);
    if (rc) {
        snprintf(msg, msglen, "glsplay: error: camera %s: %s", name, err);
        goto out;
    }
    if (df)
        gls_flow_compute_lens(c, &c1, df, inst, z, z1, s->moves, *uv, *mask);
    else
        gls_flow_compute(c, &c1, inst, z, z1, s->moves, *uv, *mask);
check:;
    uint32_t x, y;
    float fu, fv;
    if ((s->o->outputs & GLS_OUT_FLOW) && gls_flow_kitti_check(*uv, *mask, c->width, c->height, &x, &y, &fu, &fv)) {
        int along_u = !(fabsf(fv) > fabsf(fu));
        snprintf(msg, msglen,
                 "glsplay: error: camera %s, frame %u: the flow at pixel (%u, %u) moves %.2f px along %c, beyond the "
                 "-512..512 px a KITTI flow PNG holds; leave out flow or move less between frames",
                 name, frame, x, y, along_u ? fu : fv, along_u ? 'u' : 'v');
        rc = -1;
    }
out:
    free(z1);
    if (rc) {
        free(*uv);
        free(*mask);
        *uv = NULL, *mask = NULL;
    }
    return rc;
}

/* flow_frame with a rolling shutter (gt_flow_rolling.h): the poses of
 * every row of this frame and the next, the next frame's rolling depth
 * (through df's lens when df).  0, or -1 with the whole line in msg
 * (empty: out of memory). */
static int flow_frame_rolling(session *s, const gls_camera *c, const gls_distort_frame *df, const char *name,
                              uint32_t frame, gls_bands bands, const uint32_t *inst, const float *z, float *z1, float *uv,
                              uint8_t *mask, char *msg, size_t msglen)
{
    double dt = (double)s->next->frame - (double)frame, bad = 0;
    char err[512];
    gls_flow_rows fr;
    int k = gls_flow_rows_fill(&fr, c, bands.rows, dt, s->moves, s->ms->scene, pose_at, s, &bad);
    if (k == 1) {
        char a[40];
        gls_fmt_double(a, sizeof a, (double)frame + bad);
        snprintf(msg, msglen, "glsplay: error: camera %s, frame %u: its flow needs the poses of the rolling readout "
                              "of frame %llu, at frame %s beyond the rows of the trajectory or a motion file; sub-frame "
                              "poses are interpolated between rows, never extrapolated: render fewer --frames or "
                              "extend the file", name, frame, (unsigned long long)s->next->frame, a);
        return -1;
    }
    if (k)
        return -1;
    if (gls_flow_rolling_depth(s->r, c, df, bands, dt, pose_at, s, z1, err, sizeof err)) {
        snprintf(msg, msglen, "glsplay: error: camera %s: %s", name, err);
        gls_flow_rows_free(&fr);
        return -1;
    }
    gls_flow_compute_rolling(c, df, &fr, s->moves, inst, z, z1, uv, mask);
    gls_flow_rows_free(&fr);
    return 0;
}

/* The scene and the camera s frame intervals after the frame time
 * (exposure.h): the moving instances and the rig interpolated between
 * their rows (subframe.h); checked to exist before rendering. */
static int pose_at(void *ud, double t, gls_camera *cam)
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
static int render_plan(void *ud, const gls_camera *c, uint32_t v0, uint32_t v1, gls_accum *acc, char *msg,
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
        gls_aa_fine_opts fo = {o->aa_memory, 0, 0, o->progress == GLS_PROGRESS_BAR ? s->errs : NULL, name, estimate_from_tiles, s};
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
        gls_aa_run_opts ro = {o->aa_tiles, 0, o->progress == GLS_PROGRESS_BAR ? s->errs : NULL, name, estimate_from_passes, s};
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
static int centre_bands(session *s, const gls_camera *c, gls_bands bands, uint8_t *rgba, float *z, uint32_t *inst,
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
        pose_at(s, c->line_delay * (v0 + v1 - 1) / 2.0, &at);
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
        pose_at(s, 0, &at);
    }
    free(rb);
    free(zb);
    free(gb);
    free(nb);
    free(ib);
    return rc;
}

/* malloc for buffer k of the frame plan, its bytes counted when the run
 * is counted (gls_frame_counts: tests compare them with the plan). */
static void *frame_alloc(gls_frame_counts *cnt, int k, size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (p && cnt)
        cnt->bytes[k] += bytes;
    return p;
}

/* The centre and ground-truth passes just drawn, counted. */
static void count_passes(gls_frame_counts *cnt, int centre, int truth)
{
    if (!cnt)
        return;
    cnt->passes[GLS_PASS_I_CENTRE] += centre != 0;
    cnt->passes[GLS_PASS_I_TRUTH] += truth != 0;
}

/* What one camera frame holds while it is drawn: its plan, and the
 * buffers the plan asks for (NULL: not needed), freed together. */
typedef struct {
    gls_frame_plan fp;
    gls_distort_frame df;  /* a lens: the undistorted images (distort_render.h) */
    gls_bands bands;       /* rolling shutter: rows per band (exposure.h)      */
    uint8_t *rgba, *mask, *flowmask;
    float *z, *normal, *flow, *gt_z;
    uint32_t *gt_ids;      /* the ground-truth pass (gt_pass.h): ids for
                              instance, class, coco, flow, boxes             */
    gls_box *boxes;
    size_t nboxes;
    void *img;             /* the image in its file's format, when not rgba  */
    gls_accum acc;
} cam_frame;

static void cam_frame_free(cam_frame *cf)
{
    gls_accum_free(&cf->acc);
    gls_distort_frame_free(&cf->df);
    free(cf->rgba);
    free(cf->z);
    free(cf->img);
    free(cf->mask);
    free(cf->normal);
    free(cf->flow);
    free(cf->flowmask);
    free(cf->gt_ids);
    free(cf->gt_z);
    free(cf->boxes);
}

/* "glsplay: error: camera NAME: ERR" into msg; -1. */
static int camera_error(const session *s, const char *err, char *msg, size_t msglen)
{
    snprintf(msg, msglen, "glsplay: error: camera %s: %s", s->name_now, err);
    return -1;
}

/* The centre pass (colour and depth at the pixel centres) and the
 * ground-truth pass (ids, normals, the depth flow starts from), each
 * only when the plan reads it back: in bands of rows under a rolling
 * shutter, through the lens when there is one.  0, or -1 with msg
 * (empty: out of memory). */
static int frame_centre_truth(session *s, const gls_camera *c, cam_frame *cf, char *msg, size_t msglen)
{
    gls_renderer *r = s->r;
    char err[512];
    int centre = cf->rgba || cf->z, truth = cf->gt_ids || cf->normal;
    if (cf->bands.rows < c->height && cf->fp.lens) {
        /* flow starts from each band's ground-truth depth at the nearest
         * fine pixel; boxes take their 2D boxes from this instance image */
        if (gls_distort_truth_bands(r, c, &cf->df, cf->bands, pose_at, s, cf->rgba, cf->z, cf->gt_ids, cf->normal,
                                    cf->gt_z, err, sizeof err))
            return camera_error(s, err, msg, msglen);
        truth |= cf->gt_z != NULL;
    } else if (cf->bands.rows < c->height) {
        /* flow starts from each band's ground-truth depth; boxes take
         * their 2D boxes from this instance image */
        if (centre_bands(s, c, cf->bands, cf->rgba, cf->z, cf->gt_ids, cf->normal, cf->gt_z, msg, msglen))
            return -1;
        truth |= cf->gt_z != NULL;
    } else if (cf->fp.lens) {
        if (centre)
            gls_distort_frame_centre(&cf->df, c, cf->rgba, cf->z);
        /* through the lens: the ground-truth pass drawn by the plain fine
         * camera, read at each pixel centre's ray (lens_truth.h) */
        if (truth && gls_lens_gt_render(r, &cf->df, c, cf->gt_ids, cf->normal, cf->gt_z, err, sizeof err))
            return camera_error(s, err, msg, msglen);
    } else {
        if (centre) {
            gls_render_pass(r, c, 0.0, 0.0);
            if (cf->rgba)
                gls_render_read_rgba(r, cf->rgba);
            if (cf->z)
                gls_render_read_z(r, cf->z);
        }
        /* ground truth: the centre sample again, one pass for ids, normals
         * and the depth flow starts from (gt_pass.h), never blended
         * whatever --aa is */
        if (truth && gls_gt_render(r, c, cf->gt_ids, cf->normal, cf->gt_z, err, sizeof err))
            return camera_error(s, err, msg, msglen);
    }
    count_passes(s->counts, centre, truth);
    return 0;
}

/* The anti-aliased colour: the samples summed into the accumulator,
 * at each sub-frame time and lens point with exposure effects (exposure.h,
 * distort_exposure.h), through the lens's undistorted image with a lens.
 * 0, or -1 with msg (empty: out of memory). */
static int frame_colour(session *s, const gls_camera *c, cam_frame *cf, char *msg, size_t msglen)
{
    const gls_aa_plan *plan = s->plan;
    gls_frame_counts *cnt = s->counts;
    if (gls_accum_init(&cf->acc, c->width, c->height, cf->fp.weighted, (cf->fp.outputs & GLS_OUT_EDGE_MAPS) != 0))
        return -1;
    if (cnt) {
        cnt->bytes[GLS_BUF_ACCUM] += gls_accum_sums_bytes(&cf->acc);
        cnt->bytes[GLS_BUF_MIXED] += gls_accum_mask_bytes(&cf->acc);
        cnt->passes[cf->fp.effects ? GLS_PASS_I_EXPOSURE : GLS_PASS_I_SAMPLES]++;
    }
    int rc = 0;
    if (cf->fp.effects && cf->fp.lens)
        rc = gls_distort_exposure_render(s->r, c, &cf->fp.ex, plan, &cf->df, pose_at, s, cf->bands.rows,
                                         s->o->aa_memory, s->name_now, &cf->acc, msg, msglen);
    else if (cf->fp.effects) /* the plan at each sub-frame time and lens point */
        rc = gls_exposure_render(s->r, c, &cf->fp.ex, plan, pose_at, render_plan, s, &cf->acc, cf->bands, msg,
                                 msglen);
    else if (cf->fp.lens)
        rc = gls_distort_frame_accum(&cf->df, c, plan, &cf->acc) ? (msg[0] = 0, -1) : 0;
    else
        rc = render_plan(s, c, 0, c->height, &cf->acc, msg, msglen);
    if (cnt)
        cnt->accum_samples = cf->acc.samples;
    return rc;
}

/* The image in its file's format (through the sensor effects when the
 * camera asks for them: sensor.h, never on ground truth) and the edges
 * map.  0, or -1 when out of memory. */
static int frame_image(session *s, const gls_camera *c, const char *name, uint32_t frame, cam_frame *cf)
{
    const gls_play_opts *o = s->o;
    gls_frame_counts *cnt = s->counts;
    size_t n = (size_t)c->width * c->height;
    int aa = cf->fp.aa;
    if (cf->fp.image == GLS_IMAGE_SENSOR) {
        /* on the linear intensities before quantisation */
        cf->img = gls_sensor_image(c, name, frame, aa ? &cf->acc : NULL, cf->rgba, o->image_format);
        if (!cf->img)
            return -1;
        if (cnt) /* the linear intensities, then the image in its format (sensor_image.c's) */
            cnt->bytes[GLS_BUF_LINEAR] += 12 * (uint64_t)n, cnt->bytes[GLS_BUF_IMAGE] += cf->fp.bytes[GLS_BUF_IMAGE];
    } else if (cf->fp.image == GLS_IMAGE_CONVERTED) {
        size_t px = o->image_format == GLS_IMG_PNG16 ? 3 * sizeof(uint16_t)
                    : o->image_format == GLS_IMG_PFM ? 3 * sizeof(float) : 4;
        if (!(cf->img = frame_alloc(cnt, GLS_BUF_IMAGE, n * px)))
            return -1;
        if (o->image_format == GLS_IMG_PNG16 && aa)
            gls_accum_rgb16(&cf->acc, cf->img);
        else if (o->image_format == GLS_IMG_PNG16)
            gls_rgba8_to_rgb16(cf->rgba, n, cf->img);
        else if (o->image_format == GLS_IMG_PFM && aa)
            gls_accum_rgbf(&cf->acc, cf->img);
        else if (o->image_format == GLS_IMG_PFM)
            gls_rgba8_to_rgbf(cf->rgba, n, cf->img);
        else
            gls_accum_rgba8(&cf->acc, cf->img);
    }
    if (cf->fp.outputs & GLS_OUT_EDGE_MAPS) {
        /* one sample per pixel cannot straddle anything: all zero */
        if (!(cf->mask = calloc(n ? n : 1, 1)))
            return -1;
        if (cnt)
            cnt->bytes[GLS_BUF_EDGES] += n;
        for (size_t i = 0; aa && i < n; i++)
            cf->mask[i] = cf->acc.mixed[i] ? 255 : 0;
    }
    return 0;
}

/* Boxes and flow, from the ground-truth pass's ids.  0, or -1 with msg
 * (empty: out of memory). */
static int frame_boxes_flow(session *s, const gls_camera *c, uint32_t frame, cam_frame *cf, char *msg,
                            size_t msglen)
{
    char err[512];
    if (cf->fp.boxes && s->counts)
        s->counts->passes[GLS_PASS_I_BOXES_ALONE]++;
    if (cf->fp.boxes && cf->fp.lens) {
        if (gls_boxes_compute_lens(s->r, s->ms->scene, c, &cf->df, cf->gt_ids, &cf->boxes, &cf->nboxes, err,
                                   sizeof err))
            return camera_error(s, err, msg, msglen);
    } else if (cf->fp.boxes && gls_boxes_compute(s->r, s->ms->scene, c, cf->gt_ids, &cf->boxes, &cf->nboxes)) {
        return -1;
    }
    if (cf->fp.flow && flow_frame(s, c, cf->fp.lens ? &cf->df : NULL, s->name_now, frame, cf->bands, cf->gt_ids,
                                  cf->gt_z, &cf->flow, &cf->flowmask, msg, msglen))
        return -1;
    return 0;
}

/* The files go to the writer (frame_writer.h, frame_files.h), which
 * encodes and writes them, with its thread while the next frame renders,
 * and writes the frame record after the last one; the buffers it takes
 * are the writer's from here.  0, or -1 with msg (empty: out of memory). */
static int frame_submit(session *s, const gls_camera *c, const char *name, uint32_t frame, cam_frame *cf, char *msg,
                        size_t msglen)
{
    const gls_play_opts *o = s->o;
    uint32_t band = cf->bands.rows;
    gls_frame_files *f = gls_frame_files_new();
    if (!f)
        return -1;
    f->cam = *c;
    f->name = name;
    f->frame = frame;
    f->image_format = o->image_format;
    f->image_mosaic = c->sensor.bayer[0] != 0;
    f->float_format = o->float_format;
    f->fxB = c->fx * s->baseline;
    f->depth_scale = o->depth_scale > 0 ? o->depth_scale : GLS_DEPTH_SCALE_KITTI;
    f->buffer_bytes = cf->fp.total;
    f->json = s->json;
    int too_long = gls_frame_record_path(f->record, sizeof f->record, o->outdir, name, frame) ||
                   gls_frame_record_text(f->record_text, sizeof f->record_text, o, c, name, frame, s->inputs);
    /* one file a kind at most: files[] has room for every kind */
    for (size_t k = 0; k < GLS_OUT_KINDS && !too_long; k++)
        if (cf->fp.outputs & gls_output_kinds[k].bit) {
            f->files[f->nfiles].bit = gls_output_kinds[k].bit;
            too_long = output_file(f->files[f->nfiles++].path, GLS_FRAME_PATH, o, name, k, frame) != 0;
        }
    int rc = -1;
    if (too_long) {
        snprintf(msg, msglen, "glsplay: error: output path for camera %s is too long", name);
        goto fail;
    }
    /* where the landmarks are in this frame: motion moves them; under a
     * rolling shutter each at its band's time, as its rows */
    if ((cf->fp.outputs & GLS_OUT_LANDMARKS) && !(f->landmarks = gls_landmarks_take(s->scene)))
        goto fail;
    if (f->landmarks && band < c->height && gls_exposure_landmarks(s->scene, c, band, pose_at, s, f->landmarks))
        goto fail;
    /* rolling shutter: each row's points through the pose its depth was
     * drawn with (spec/outputs.md) */
    if ((cf->fp.outputs & GLS_OUT_POINTS) && band < c->height &&
        !(f->row_pose = gls_exposure_row_poses(c, band, pose_at, s)))
        goto fail;
    f->rgba = cf->rgba, f->z = cf->z, f->image = cf->img, f->mask = cf->mask;
    /* the writer needs the ids only for the id images and tables */
    int ids = (cf->fp.outputs & GLS_OUT_IDS) != 0;
    f->gt_inst = ids ? cf->gt_ids : NULL, f->normal = cf->normal, f->gt = s->gt;
    f->flow = cf->flow, f->flowmask = cf->flowmask;
    f->boxes = cf->boxes, f->nboxes = cf->nboxes, f->box_names = s->box_names;
    if (ids)
        cf->gt_ids = NULL;
    cf->rgba = cf->mask = cf->flowmask = NULL, cf->z = cf->flow = cf->normal = NULL, cf->img = NULL;
    cf->boxes = NULL;
    /* the writer's now, submitted or freed */
    return gls_writer_submit(s->w, &f->job, msg, msglen) ? -1 : 0;
fail:
    f->job.destroy(&f->job);
    return rc;
}

/* Render one camera and write what was asked for.
 *
 * Plain (N = 1): one pass at jitter (0, 0), no accumulator.
 * Anti-aliased (N > 1): the image (and mask) come from the accumulated
 * samples (one fine framebuffer for the lattice and grid, jittered passes
 * for stratified); depth and points come from one extra unjittered pass
 * (the geometry at each pixel centre, never averaged across an edge),
 * drawn only when they are asked for; the points' colours come from that
 * pass too, so each point has the colour of the surface it lies on.
 * Instance ids and normals come from one more unjittered pass
 * (gt_pass.h), drawn only when an output needs them. */
static int play_camera(session *s, const gls_camera *c, const char *name, uint32_t frame)
{
    static const char lower_size[] = "lower --size (or the camera's width and height)";
    const gls_play_opts *o = s->o;
    gls_renderer *r = s->r;
    char err[512], msg[1024] = "";
    size_t n = (size_t)c->width * c->height;
    cam_frame cf;
    memset(&cf, 0, sizeof cf);
    /* everything this frame needs, decided once (frame_plan.h) */
    gls_plan_inputs pin = {o->outputs, o->image_format, s->plan, s->moving};
    gls_frame_plan_make(&cf.fp, &pin, c, s->next != NULL);
    const gls_frame_plan *fp = &cf.fp;
    gls_frame_counts *cnt = s->counts;
    if (cnt)
        memset(cnt, 0, sizeof *cnt), cnt->frames = 1;
    int rc = -1;
    s->name_now = name;
    if (gls_renderer_set_size(r, c->width, c->height, err, sizeof err)) {
        snprintf(msg, sizeof msg, "glsplay: error: camera %s: %s; %s", name, err, lower_size);
        goto out;
    }
    /* a lens: one undistorted fine image, read through the inverse model
       (distort_render.h); with the exposure's effects, one at each
       sub-frame time, lens point and band (distort_exposure.h) */
    if (fp->lens && gls_distort_frame_render(&cf.df, r, c, s->plan, fp->rgba, fp->z, fp->aa && !fp->effects,
                                             o->aa_memory, err, sizeof err)) {
        snprintf(msg, sizeof msg, "glsplay: error: camera %s: %s; %s", name, err, lower_size);
        goto out;
    }
    if (fp->lens && cnt)
        cnt->passes[GLS_PASS_I_LENS]++;
    /* rolling shutter: the ground truth of each band of rows at its time
     * (exposure.h), the bands chosen from this frame's motion; one band,
     * the whole image, otherwise.  Each band draws its own rows, or the
     * whole image when a test asks (gls_play_opts' bands_whole) */
    cf.bands.rows = fp->ex.rolling ? gls_exposure_band_rows(r, c, &fp->ex, pose_at, s) : c->height;
    cf.bands.whole = o->bands_whole != 0;
    if ((fp->rgba && !(cf.rgba = frame_alloc(cnt, GLS_BUF_RGBA, n * 4))) ||
        (fp->z && !(cf.z = frame_alloc(cnt, GLS_BUF_DEPTH, n * sizeof *cf.z))) ||
        (fp->ids && !(cf.gt_ids = frame_alloc(cnt, GLS_BUF_IDS, n * sizeof *cf.gt_ids))) ||
        (fp->normals && !(cf.normal = frame_alloc(cnt, GLS_BUF_NORMALS, n * 3 * sizeof *cf.normal))) ||
        (fp->truth_z && !(cf.gt_z = frame_alloc(cnt, GLS_BUF_TRUTH_DEPTH, n * sizeof *cf.gt_z))))
        goto out;
    if (frame_centre_truth(s, c, &cf, msg, sizeof msg) || (fp->aa && frame_colour(s, c, &cf, msg, sizeof msg)) ||
        frame_image(s, c, name, frame, &cf) || frame_boxes_flow(s, c, frame, &cf, msg, sizeof msg) ||
        frame_submit(s, c, name, frame, &cf, msg, sizeof msg))
        goto out;
    view_done(s);
    rc = 0;
out:
    if (rc && !msg[0])
        gls_frame_oom_message(msg, sizeof msg, name, c->width, c->height, fp->total);
    if (rc)
        say_failure(s, msg);
    cam_frame_free(&cf);
    return rc;
}

/* Is this frame complete: for every camera, a record that covers what o
 * asks for (written after the camera's last file, frame_record.h), and
 * every requested output file still there? */
static int frame_done(const gls_play_opts *o, const gls_camera *cams, const char *const *names, uint32_t frame,
                      int has_next, const char *inputs)
{
    if (strcmp(inputs, "-") == 0) /* an input that cannot be read again: never taken */
        return 0;
    char path[MAXPATH], text[1024];
    for (size_t i = 0; i < o->ncameras; i++) {
        if (gls_frame_record_path(path, sizeof path, o->outdir, names[i], frame) ||
            gls_frame_record_text(text, sizeof text, o, &cams[i], names[i], frame, inputs) ||
            !gls_frame_record_matches(path, text))
            return 0;
        unsigned want = gls_outputs_with(o->outputs);
        for (size_t k = 0; k < GLS_OUT_KINDS; k++) {
            if (!(want & gls_output_kinds[k].bit) || (!has_next && (gls_output_kinds[k].bit & GLS_OUT_FLOW_ALL)))
                continue;
            struct stat st;
            if (output_file(path, sizeof path, o, names[i], k, frame) ||
                stat(path, &st) != 0 || !S_ISREG(st.st_mode))
                return 0;
        }
    }
    return 1;
}

/* A reader of the trajectory's text, read once (ms->traj).  notes: where
 * the reader's notes go (a re-orthonormalised rotation); the text is
 * parsed several times (scan, then render), notes only once. */
static gls_traj *open_trajectory(const motion_set *ms, FILE *notes, FILE *errs)
{
    gls_traj *t = gls_traj_open_text(&ms->traj, notes);
    if (!t)
        fprintf(errs, "glsplay: error: out of memory\n");
    return t;
}

/* The frame of the trajectory's last row (the one frame with no flow
 * from it), or UINT64_MAX if it cannot be read (the scan says why). */
static uint64_t trajectory_last_frame(const motion_set *ms)
{
    char err[1024];
    gls_traj *t = gls_traj_open_text(&ms->traj, NULL);
    if (!t)
        return UINT64_MAX;
    gls_traj_pose p;
    uint64_t last = UINT64_MAX;
    int got;
    while ((got = gls_traj_next(t, &p, err, sizeof err)) == 1)
        last = p.frame;
    gls_traj_close(t);
    return got < 0 ? UINT64_MAX : last;
}

/* The trajectory parsed once before anything is rendered: every line of
 * the file is checked, whatever --frames asks for, the frames asked for
 * with no row said in a warning, the frames in the range counted,
 * those of this --shard (mine; all without one) and, with --resume, the
 * complete ones among them (last: the frame of the trajectory's last row,
 * which writes no flow).  With flow, the row after the range is read too,
 * and its motions checked: the last frame's flow goes to it.  0, or 1
 * after a message. */
/* --resume's question of the frames iterator (frames.h): is frame f
 * complete, for every camera? */
typedef struct {
    const gls_play_opts *o;
    const gls_camera *rel;
    const char *const *names;
    uint64_t last;       /* the trajectory's last frame: no flow from it */
    const char *inputs;
} resume_ctx;

static int resume_complete(void *ud, uint64_t frame)
{
    const resume_ctx *r = ud;
    return r->o->resume && frame_done(r->o, r->rel, r->names, (uint32_t)frame, frame != r->last, r->inputs);
}

/* The frames of the run (frames.h), --resume asking resume_ctx r. */
static int open_frames(gls_frames *f, const motion_set *ms, const gls_play_opts *o, FILE *notes, resume_ctx *r,
                       FILE *errs)
{
    if (gls_frames_open(f, &ms->traj, notes, o->frame_first, o->frame_end, &o->shard)) {
        fprintf(errs, "glsplay: error: out of memory\n");
        return 1;
    }
    if (r && o->resume)
        f->complete = resume_complete, f->ud = r;
    return 0;
}

static int scan_trajectory(const gls_play_opts *o, const motion_set *ms, const gls_camera *rel,
                           const char *const *names, const char *inputs, uint64_t last, FILE *errs,
                           uint64_t *inrange, uint64_t *mine, uint64_t *complete)
{
    char err[1024];
    resume_ctx rc_ = {o, rel, names, last, inputs};
    gls_frames f;
    if (open_frames(&f, ms, o, errs, &rc_, errs))
        return 1;
    gls_traj_pose p;
    gls_frame_mark m;
    int got, rc = 0;
    gls_traj_gaps gaps;
    gls_traj_gaps_init(&gaps, o->frame_first);
    *inrange = *mine = *complete = 0;
    while ((got = gls_frames_next(&f, &p, &m, err, sizeof err)) == 1) {
        gls_traj_gaps_row(&gaps, p.frame);
        if (p.frame > UINT32_MAX) {
            fprintf(errs, "%s:%u: error: frame %llu: frame numbers above %u are not supported\n", o->trajectory,
                    p.line, (unsigned long long)p.frame, UINT32_MAX);
            rc = 1;
            break;
        }
        if (motion_check(ms, p.frame, errs) || exposure_check(ms, rel, names, o->ncameras, p.frame, errs)) {
            rc = 1;
            break;
        }
        (*inrange)++;
        *mine += m.mine != 0;
        *complete += m.complete != 0;
    }
    /* the row after the range: the last frame's flow goes to it; then
     * every row to the end of the file, whatever the range */
    if (got == 0 && rc == 0 && f.past && (o->outputs & GLS_OUT_FLOW_ALL) && motion_check(ms, f.after.frame, errs))
        rc = 1;
    if (got == 0 && rc == 0)
        got = gls_frames_rest(&f, err, sizeof err);
    if (got < 0) {
        fprintf(errs, "%s\n", err);
        rc = 1;
    }
    gls_frames_close(&f);
    if (rc == 0 && *inrange == 0) {
        fprintf(errs, "glsplay: error: %s: no frame in the range given by --frames\n", o->trajectory);
        rc = 1;
    }
    /* frames --frames asks for (it was given: not 0 to the end) with no row */
    char msg[512];
    gls_traj_gaps_end(&gaps, o->frame_end);
    if (rc == 0 && (o->frame_first || o->frame_end != UINT64_MAX) &&
        gls_traj_gaps_message(&gaps, o->trajectory, msg, sizeof msg))
        fprintf(errs, "glsplay: warning: %s\n", msg);
    return rc;
}

/* --resume: how many frames it skips (one line, always). */
static void resume_note(FILE *errs, uint64_t complete, uint64_t total)
{
    fprintf(errs, "glsplay: note: --resume: %llu of %llu frame%s complete, skipped; %llu to render\n",
            (unsigned long long)complete, (unsigned long long)total, total == 1 ? "" : "s",
            (unsigned long long)(total - complete));
}

/* What scan_trajectory found, before anything was created or written. */
typedef struct {
    uint64_t inrange, mine, complete, last;
} traj_scan;

/* Every frame of the trajectory in [frame_first, frame_end), parsed one
 * line at a time from its text (read once: memory stays flat beyond its
 * bytes however long the sequence), as scanned (sc).  Each camera file gives that camera's pose relative to the rig. */
static int play_trajectory(session *s, const gls_camera *rel, const char *const *names, const traj_scan *sc)
{
    const gls_play_opts *o = s->o;
    FILE *errs = s->errs;
    uint64_t inrange = sc->inrange, mine = sc->mine, complete = sc->complete, last = sc->last;
    int flow = (o->outputs & GLS_OUT_FLOW_ALL) != 0;
    /* more shards than frames: this one has none, which is no error */
    if (mine == 0) {
        fprintf(errs, "glsplay: note: --shard %llu/%llu: none of the %llu frame%s in range is this shard's; "
                      "nothing to render\n", (unsigned long long)o->shard.index, (unsigned long long)o->shard.count,
                (unsigned long long)inrange, inrange == 1 ? "" : "s");
        return 0;
    }
    if (o->resume)
        resume_note(errs, complete, mine);
    uint64_t todo = mine - complete, done = 0;
    s->views = todo * o->ncameras;
    s->json->total = s->views;
    s->json->skipped = complete;
    char err[1024];
    resume_ctx rctx = {o, rel, names, last, s->inputs};
    gls_frames f;
    if (open_frames(&f, s->ms, o, NULL, &rctx, errs))
        return 1;
    /* flow: a second reader one row ahead gives each frame's next row */
    gls_traj *ahead = flow ? open_trajectory(s->ms, NULL, errs) : NULL;
    if (flow && !ahead) {
        gls_frames_close(&f);
        return 1;
    }
    gls_traj_pose p, pn;
    gls_frame_mark m;
    int got = 0, rc = 0, have = ahead ? gls_traj_next(ahead, &pn, err, sizeof err) : 0, noted = 0;
    double shown = 0;
    s->t0 = s->json->t0 = gls_now();
    while (done < todo && (got = gls_frames_next(&f, &p, &m, err, sizeof err)) == 1) {
        if (p.frame > UINT32_MAX) /* refused by the scan */
            break;
        if (!m.mine || m.complete)
            continue;
        while (have == 1 && pn.frame <= p.frame)
            have = gls_traj_next(ahead, &pn, err, sizeof err);
        if (have < 0) { /* the scan read the same rows: never */
            got = have;
            break;
        }
        s->next = have == 1 ? &pn : NULL;
        if (flow && !s->next && !noted++)
            fprintf(errs, "glsplay: note: frame %llu is the last of %s: no flow from it (flow goes from a frame to "
                          "the next)\n", (unsigned long long)p.frame, o->trajectory);
        motion_apply(s->ms, p.frame);
        for (size_t i = 0; i < o->ncameras && rc == 0; i++) {
            gls_camera c = rel[i];
            gls_traj_compose(rel[i].R, rel[i].T, p.R, p.T, c.R, c.T);
            s->rel = &rel[i];
            s->frame_now = p.frame, s->rel_now = &rel[i];
            if (play_camera(s, &c, names[i], (uint32_t)p.frame))
                rc = 1;
        }
        if (rc)
            break;
        done++;
        /* the last frame's files are written before the closing progress
         * line, whose time includes them */
        if (done == todo && gls_writer_finish(s->w, err, sizeof err)) {
            fprintf(errs, "%s\n", err);
            rc = 1;
            break;
        }
        double now = gls_now();
        if (o->progress == GLS_PROGRESS_BAR && (done == todo || now - shown >= 0.5)) {
            shown = now;
            gls_progress_frames(errs, done, todo, now - s->t0, done == todo);
        }
    }
    if (got < 0) {
        fprintf(errs, "%s\n", err);
        rc = 1;
    }
    gls_frames_close(&f);
    if (ahead)
        gls_traj_close(ahead);
    return rc;
}

/* --explain counts culling in the first frame: with a trajectory, the
 * cameras and motions are posed for its first frame in range (of the
 * --shard, if one is given; the cameras in place, they are posed again
 * per frame when rendering).  With --shard, the frames in range and the
 * shard's are counted (*inrange, *mine).  0, or 1 after a message. */
static int explain_first_frame(const gls_play_opts *o, const motion_set *ms, gls_camera *posed, uint64_t *inrange,
                               uint64_t *mine, FILE *errs)
{
    *inrange = 1;
    *mine = (uint64_t)gls_shard_has(&o->shard, o->frame, o->frame);
    if (!o->trajectory) {
        motion_apply(ms, o->frame);
        return 0;
    }
    char err[1024];
    gls_frames f;
    if (open_frames(&f, ms, o, NULL, NULL, errs))
        return 1;
    gls_traj_pose p, first;
    gls_frame_mark m;
    int have = 0;
    *inrange = *mine = 0;
    while (gls_frames_next(&f, &p, &m, err, sizeof err) == 1) {
        (*inrange)++;
        if (!m.mine)
            continue;
        (*mine)++;
        if (!have)
            first = p, have = 1;
        if (!o->shard.count)
            break; /* nothing to count: the first frame is all it needs */
    }
    gls_frames_close(&f);
    if (!have)
        return 0; /* the scan before rendering says what is wrong */
    p = first;
    if (motion_check(ms, p.frame, errs) == 0)
        motion_apply(ms, p.frame);
    for (size_t i = 0; i < o->ncameras; i++) {
        gls_camera rel = posed[i];
        gls_traj_compose(rel.R, rel.T, p.R, p.T, posed[i].R, posed[i].T);
    }
    return 0;
}

static const char *disparity_word(const gls_play_opts *o)
{
    return o->outputs & GLS_OUT_DISPARITY ? "disparity" : "disparity16";
}

int gls_play_check_options(const gls_play_opts *o, char *msg, size_t msglen)
{
    gls_aa_plan plan;
    gls_aa_opts aao = o->aa;
    if (aao.n == 0)
        aao.n = 1;
    if (gls_aa_plan_init(&plan, &aao, msg, msglen))
        return -1;
    /* OUTDIR/NAME, NAME the camera file's name without its extension */
    for (size_t i = 0; i < o->ncameras; i++) {
        char *name = camera_name(o->cameras[i]);
        if (!name) {
            snprintf(msg, msglen, "out of memory");
            return -1;
        }
        int bad = !name[0] || strcmp(name, ".") == 0 || strcmp(name, "..") == 0;
        size_t j = 0;
        for (; !bad && j < i; j++) {
            char *other = camera_name(o->cameras[j]);
            int same = !other || strcmp(name, other) == 0;
            free(other);
            if (same)
                break;
        }
        if (bad)
            snprintf(msg, msglen, "%s: cannot name an output directory after this camera file", o->cameras[i]);
        else if (j < i)
            snprintf(msg, msglen, "cameras %s and %s would both write to %s/%s/", o->cameras[j], o->cameras[i],
                     o->outdir ? o->outdir : "OUTDIR", name);
        free(name);
        if (bad || j < i)
            return -1;
    }
    if ((o->outputs & GLS_OUT_DISPARITIES) && o->ncameras != 2) {
        snprintf(msg, msglen, "--outputs %s needs a rectified pair: exactly two cameras, the left one first; %zu given",
                 disparity_word(o), o->ncameras);
        return -1;
    }
    /* the same NAME twice: decided here; two names of one instance
       (motion_load) only once the bundle is read */
    for (size_t i = 0; i < o->nmotions; i++)
        for (size_t j = 0; j < i; j++) {
            size_t n = strcspn(o->motions[i], "=");
            if (n == strcspn(o->motions[j], "=") && strncmp(o->motions[i], o->motions[j], n) == 0) {
                snprintf(msg, msglen, "--motion %s: instance %.*s is moved twice", o->motions[i], (int)n,
                         o->motions[i]);
                return -1;
            }
        }
    return 0;
}

/* --outputs disparity: the two cameras (gls_play_check_options) are a
 * rectified pair with the left one first (out_disparity.h).  0 with *B,
 * or 1 after a message. */
static int rectified_check(const gls_play_opts *o, const gls_camera *cams, const char *const *names, double *B,
                           FILE *errs)
{
    char why[512];
    const char *word = disparity_word(o);
    if (gls_rectified_pair(&cams[0], &cams[1], names[0], names[1], B, why, sizeof why) == 0)
        return 0;
    fprintf(errs, "glsplay: error: --outputs %s needs a rectified pair: %s\n", word, why);
    return 1;
}

/* The outputs not made through a lens: disparity (a rectified pair has no
 * distortion: rectify first).  0, or -1 after a message. */
static int lens_outputs_check(const gls_play_opts *o, const gls_camera *c, const char *path, FILE *errs)
{
    static const struct {
        unsigned bits;
        const char *word, *why;
    } no[] = {{GLS_OUT_DISPARITY, "disparity", "a rectified pair has no lens distortion"},
              {GLS_OUT_DISPARITY16, "disparity16", "a rectified pair has no lens distortion"}};
    if (!gls_distort_on(c))
        return 0;
    for (size_t i = 0; i < sizeof no / sizeof no[0]; i++)
        if (o->outputs & no[i].bits) {
            fprintf(errs, "glsplay: error: %s: --outputs %s needs a camera without lens distortion: %s\n", path,
                    no[i].word, no[i].why);
            return -1;
        }
    return 0;
}

/* A camera with lens distortion: the model must be one-to-one over the
 * image as --size makes it (the file was checked at its own size) and the
 * anti-aliasing window beyond it, before anything is drawn.  0, or -1
 * after a message. */
static int lens_check(const gls_camera *c, const char *path, const gls_aa_plan *plan, FILE *errs)
{
    gls_distort_layout lay;
    char why[600];
    if (gls_distort_on(c) && (gls_distort_layout_make(c, NULL, GLS_DISTORT_SCALE, 0, &lay, why, sizeof why) ||
                              gls_distort_layout_make(c, plan, GLS_DISTORT_AA_SCALE, 0, &lay, why, sizeof why))) {
        fprintf(errs, "glsplay: error: %s: %s\n", path, why);
        return -1;
    }
    return 0;
}

/* The effects of every camera, before anything is drawn: a note for a
 * shutter or line_delay with nothing moving (no effect), the
 * accumulator's range, and the trajectory read whole when a camera needs
 * sub-frame poses of the rig.  0, or 1 after a message. */
static int exposure_setup(const gls_play_opts *o, motion_set *ms, const gls_camera *cams, const char *const *names,
                          const gls_aa_plan *plan, FILE *errs)
{
    int need_rig = 0;
    ms->moving = o->trajectory || o->nmotions;
    for (size_t i = 0; i < o->ncameras; i++) {
        const gls_camera *c = &cams[i];
        if (!ms->moving && (c->shutter > 0 || c->line_delay > 0))
            fprintf(errs, "glsplay: note: camera %s: %s no effect: nothing moves (no --trajectory, no --motion)\n",
                    names[i], c->shutter > 0 && c->line_delay > 0 ? "shutter and line_delay have"
                              : c->shutter > 0                    ? "shutter has"
                                                                  : "line_delay has");
        gls_exposure e = gls_exposure_of(c, ms->moving);
        char why[300];
        if (gls_exposure_on(&e) && (o->outputs & (GLS_OUT_IMAGE | GLS_OUT_EDGE_MAPS)) &&
            gls_exposure_fits(&e, plan, why, sizeof why)) {
            fprintf(errs, "glsplay: error: camera %s: %s\n", names[i], why);
            return 1;
        }
        need_rig |= e.blur || e.rolling;
    }
    char err[1024];
    if (need_rig && o->trajectory && gls_traj_read_all(&ms->traj, NULL, &ms->rig, err, sizeof err)) {
        fprintf(errs, "%s\n", err);
        return 1;
    }
    return 0;
}

/* One run's state, loaded and checked before anything is drawn, freed
 * by run_free whatever happened. */
typedef struct {
    const gls_play_opts *o;
    FILE *errs;
    gls_camera *cams;
    char **names;
    gls_bundle *b;
    gls_aa_plan plan;
    gls_scene scene;
    motion_set ms;
    gls_flow_moves moves;
    gls_box_names box_names;
    gls_gt_table gt;
    double baseline;      /* disparity: B of the rectified pair            */
    gls_glctx *ctx;
    gls_renderer *r;
    gls_writer *wr;
    size_t *made;         /* per camera: what gls_mkdir_p_made made         */
    gls_progress_json json;
    int started;          /* rendering began: --progress json ends with a line */
} run;

/* "glsplay: error: out of memory"; 1. */
static int oom(FILE *errs)
{
    fprintf(errs, "glsplay: error: out of memory\n");
    return 1;
}

/* The bundle and the cameras, each checked; disparity's pair.  0, or 1
 * after the message. */
static int run_load_cameras(run *u)
{
    const gls_play_opts *o = u->o;
    FILE *errs = u->errs;
    char err[1024];
    gls_error gerr;
    u->b = gls_bundle_read_file(o->bundle, &gerr);
    if (!u->b) {
        fprintf(errs, "glsplay: error: %s\n", gerr.msg); /* the message names the file */
        return 1;
    }
    if (u->b->top == GLS_NONE) {
        fprintf(errs, "glsplay: error: %s: a library bundle (no top-level object) cannot be played; "
                      "compile a scene with a top-level object\n", o->bundle);
        return 1;
    }
    for (size_t i = 0; i < o->ncameras; i++) {
        gls_camera *c = &u->cams[i];
        if (gls_camera_load(o->cameras[i], o->trajectory ? GLS_POSE_RIG : GLS_POSE_WORLD, errs, c, err, sizeof err)) {
            fprintf(errs, "%s\n", err);
            return 1;
        }
        if (o->width)
            c->width = o->width, c->height = o->height;
        if (lens_check(c, o->cameras[i], &u->plan, errs) || lens_outputs_check(o, c, o->cameras[i], errs))
            return 1;
        u->names[i] = camera_name(o->cameras[i]); /* usable: gls_play_check_options */
        if (!u->names[i])
            return oom(errs);
    }
    /* disparity: a rectified pair, checked before anything is drawn */
    return (o->outputs & GLS_OUT_DISPARITIES) &&
           rectified_check(o, u->cams, (const char *const *)u->names, &u->baseline, errs);
}

/* The scene, the motions, the trajectory (read once, whole: a pipe gives
 * its bytes only once, and the scan, the render, the digest and the
 * calibration must all see the same rows), the exposure's checks, the
 * instance ids and the moving instances of flow.  0, or 1. */
static int run_load_scene(run *u)
{
    const gls_play_opts *o = u->o;
    FILE *errs = u->errs;
    const char *const *names = (const char *const *)u->names;
    char err[1024];
    if ((o->flatten ? gls_scene_flatten : gls_scene_load)(u->b, &u->scene, err, sizeof err)) {
        fprintf(errs, "glsplay: error: %s: %s\n", o->bundle, err);
        return 1;
    }
    if (motion_load(o, &u->ms, errs) || (!o->trajectory && motion_check(&u->ms, o->frame, errs)))
        return 1;
    if (o->trajectory && gls_traj_load(o->trajectory, &u->ms.traj, err, sizeof err)) {
        fprintf(errs, "%s\n", err);
        return 1;
    }
    if (exposure_setup(o, &u->ms, u->cams, names, &u->plan, errs) ||
        (!o->trajectory && exposure_check(&u->ms, u->cams, names, o->ncameras, o->frame, errs)))
        return 1;
    if (o->outputs & GLS_OUT_IDS) {
        /* the ids of the whole run, from the bundle's object names */
        uint32_t count;
        int k = gls_gt_table_build(&u->gt, u->b, &u->scene, &count);
        if (k == 1) {
            fprintf(errs, "glsplay: error: %s: %u instances draw something, more than the %u ids of the 16-bit "
                          "instance image (--outputs instance, class, coco)\n", o->bundle, count, GLS_GT_MAX_IDS);
            return 1;
        }
        if (k)
            return oom(errs);
    }
    if ((o->outputs & GLS_OUT_FLOW_ALL) && gls_flow_moves_init(&u->moves, &u->scene, u->ms.inst, u->ms.n))
        return oom(errs);
    return 0;
}

/* --explain: the plan of the first frame, its cameras posed for it. */
static void run_explain(run *u, FILE *out)
{
    const gls_play_opts *o = u->o;
    gls_camera *posed = malloc((o->ncameras ? o->ncameras : 1) * sizeof *posed);
    if (posed)
        memcpy(posed, u->cams, o->ncameras * sizeof *posed);
    uint64_t inrange, mine;
    if (posed && explain_first_frame(o, &u->ms, posed, &inrange, &mine, u->errs) == 0) {
        gls_explain(out, o->bundle, u->b, &u->scene, posed, (const char *const *)u->names, o->ncameras, o, u->ctx);
        gls_shard_explain(out, &o->shard, o->trajectory != NULL, o->frame_first, mine, inrange);
    }
    free(posed);
}

/* All directories before any rendering: an unwritable output fails
 * before anything is written.  Those this run makes are removed at the
 * end if they are still empty (made[], run_free): a run that fails or
 * has nothing to render leaves no empty directory behind.  0, or 1. */
static int run_make_dirs(run *u)
{
    const gls_play_opts *o = u->o;
    u->made = calloc(o->ncameras ? o->ncameras : 1, sizeof *u->made);
    if (!u->made)
        return oom(u->errs);
    for (size_t i = 0; i < o->ncameras; i++) {
        char dir[MAXPATH];
        int k = snprintf(dir, sizeof dir, "%s/%s", o->outdir, u->names[i]);
        if (k < 0 || (size_t)k >= sizeof dir || gls_mkdir_p_made(dir, &u->made[i])) {
            fprintf(u->errs, "glsplay: error: cannot create output directory %s: %s\n", dir,
                    k < 0 || (size_t)k >= sizeof dir ? "path too long" : strerror(errno));
            return 1;
        }
    }
    return 0;
}

/* The renderer and the writer.  The bundle's texels and code are on the
 * GPU side or in the scene once the renderer exists: it is freed before
 * the per-camera buffers are allocated.  0, or 1. */
static int run_start(run *u)
{
    const gls_play_opts *o = u->o;
    char err[1024];
    u->r = gls_renderer_create(u->ctx, u->b, &u->scene, err, sizeof err);
    if (!u->r) {
        fprintf(u->errs, "glsplay: error: %s\n", err);
        return 1;
    }
    if ((o->outputs & GLS_OUT_BOXES_ALL) && gls_box_names_init(&u->box_names, u->b, &u->scene))
        return oom(u->errs);
    gls_bundle_free(u->b);
    u->b = NULL;
    gls_renderer_set_background(u->r, o->background);
    gls_renderer_set_occlusion(u->r, (gls_occlusion_mode)o->occlusion);
    if (o->anisotropy > 1 && gls_renderer_set_anisotropy(u->r, o->anisotropy, err, sizeof err)) {
        fprintf(u->errs, "glsplay: error: %s\n", err);
        return 1;
    }
    u->wr = gls_writer_create(o->writer_threads, err, sizeof err);
    if (!u->wr) {
        fprintf(u->errs, "glsplay: error: %s\n", err);
        return 1;
    }
    return 0;
}

/* A single frame (no trajectory): shard 0's (shard.h), skipped when
 * --resume finds it complete.  0, or 1. */
static int run_single(run *u, session *ses)
{
    const gls_play_opts *o = u->o;
    FILE *errs = u->errs;
    int mine = gls_shard_has(&o->shard, o->frame, o->frame);
    if (!mine)
        fprintf(errs, "glsplay: note: --shard %llu/%llu: a single render (no --trajectory) is shard 0's; "
                      "nothing to render\n", (unsigned long long)o->shard.index, (unsigned long long)o->shard.count);
    int skip = !mine || (o->resume && frame_done(o, u->cams, (const char *const *)u->names, o->frame, 0, ses->inputs));
    if (o->resume && mine)
        resume_note(errs, skip, 1);
    u->json.total = skip ? 0 : o->ncameras;
    u->json.skipped = mine && skip;
    motion_apply(&u->ms, o->frame);
    for (size_t i = 0; !skip && i < o->ncameras; i++)
        if (play_camera(ses, &u->cams[i], u->names[i], o->frame))
            return 1;
    return 0;
}

static void run_free(run *u, int rc)
{
    const gls_play_opts *o = u->o;
    /* first: it waits for the files in flight, whose jobs name the
     * cameras */
    gls_writer_destroy(u->wr);
    /* after the writer, whose last jobs may still say their frames */
    if (u->started)
        gls_progress_json_end(&u->json, rc == 0, gls_now());
    gls_renderer_destroy(u->r);
    gls_glctx_destroy(u->ctx);
    /* after the writer's last file: the directories made, last camera
     * first (the first camera's may hold the others') */
    for (size_t i = o->ncameras; u->made && i-- > 0;) {
        char dir[MAXPATH];
        snprintf(dir, sizeof dir, "%s/%s", o->outdir, u->names[i]);
        gls_rmdir_made(dir, u->made[i]);
    }
    free(u->made);
    motion_free(&u->ms);
    gls_gt_table_free(&u->gt);
    gls_flow_moves_free(&u->moves);
    gls_box_names_free(&u->box_names);
    gls_scene_free(&u->scene);
    gls_bundle_free(u->b);
    for (size_t i = 0; u->names && i < o->ncameras; i++)
        free(u->names[i]);
    free(u->names);
    free(u->cams);
}

/* The order of a run: check the options, load and check every input,
 * explain, scan the trajectory, make the directories, then render and
 * write each frame and camera, and the calibration files last. */
int gls_play(const gls_play_opts *o, FILE *out, FILE *errs)
{
    char err[1024];
    int rc = 1;
    run u;
    memset(&u, 0, sizeof u);
    u.o = o, u.errs = errs, u.ms.scene = &u.scene;
    u.cams = calloc(o->ncameras ? o->ncameras : 1, sizeof *u.cams);
    u.names = calloc(o->ncameras ? o->ncameras : 1, sizeof *u.names);
    gls_aa_opts aao = o->aa;
    if (aao.n == 0)
        aao.n = 1;
    if (gls_play_check_options(o, err, sizeof err)) {
        fprintf(errs, "glsplay: error: %s\n", err);
        rc = 2;
        goto out;
    }
    if (gls_aa_plan_init(&u.plan, &aao, err, sizeof err)) { /* checked: cannot fail */
        fprintf(errs, "glsplay: error: %s\n", err);
        goto out;
    }
    if (!u.cams || !u.names) {
        oom(errs);
        goto out;
    }
    if (run_load_cameras(&u) || run_load_scene(&u))
        goto out;
    /* the context before the plan, which reports it */
    u.ctx = gls_glctx_create(o->backend, err, sizeof err);
    if (!u.ctx) {
        fprintf(errs, "glsplay: error: %s\n", err);
        goto out;
    }
    if (o->explain)
        run_explain(&u, out);
    if (!o->outdir) {
        rc = 0;
        goto out;
    }
    char inputs[17];
    gls_frame_inputs(o, o->trajectory ? &u.ms.traj : NULL, inputs);
    /* The whole trajectory is read and checked (with --resume, the frames
     * already complete counted) before anything is created: a bad row
     * leaves no empty directory behind. */
    traj_scan scan = {0, 0, 0, UINT64_MAX};
    if (o->trajectory) {
        if (o->outputs & GLS_OUT_FLOW_ALL)
            scan.last = trajectory_last_frame(&u.ms);
        if (scan_trajectory(o, &u.ms, u.cams, (const char *const *)u.names, inputs, scan.last, errs, &scan.inrange,
                            &scan.mine, &scan.complete))
            goto out;
    }
    if (run_make_dirs(&u) || run_start(&u))
        goto out;
    u.json.f = o->progress == GLS_PROGRESS_JSON ? errs : NULL;
    u.json.cameras = o->ncameras;
    u.json.t0 = gls_now();
    session ses = {o,          &u.ms,   &u.scene,       &u.plan, u.r,  u.wr,    &u.json,     errs,
                   o->ncameras, 0,      u.json.t0,      0,       u.baseline, &u.gt, NULL,     NULL,
                   &u.moves,   &u.box_names, o->frame,  NULL,    u.ms.moving, NULL, inputs,   o->counts};
    u.started = 1;
    rc = o->trajectory ? play_trajectory(&ses, u.cams, (const char *const *)u.names, &scan) : run_single(&u, &ses);
    if (rc == 0 && gls_writer_finish(u.wr, err, sizeof err)) {
        fprintf(errs, "%s\n", err);
        rc = 1;
    }
    /* after the render and its files: every frame in the range was read
     * and checked */
    if (rc == 0 && o->write_calib)
        rc = gls_calib_write(o, o->trajectory ? &u.ms.traj : NULL, u.cams, (const char *const *)u.names, errs);
out:
    run_free(&u, rc);
    return rc;
}
