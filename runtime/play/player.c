/* gls_play(): load, check everything, then render and write (player.h).
 * Every input is checked before the first pixel is drawn, so an error in
 * the last camera file leaves no output of the first camera behind.
 *
 * This file is the order of a run: its state in one run struct, and its
 * steps (load the cameras, the scene, explain, make the directories,
 * start the renderer and the writer, render, free), grouped as begin,
 * frames, end so that a run can stay open across frames (player.h
 * gls_play_begin; the library's glscene_play_render).  The player's other
 * jobs are its family's, which share play_int.h: the frames of a
 * trajectory (play_sequence.c), one camera frame (play_frame.c), its
 * passes (play_passes.c) and flow (play_flow.c), the --motion set
 * (play_motion.c), the checks (play_checks.c) and the names
 * (play_paths.c). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "calib_write.h"
#include "frame_record.h"
#include "mkdirs.h"
#include "exact_scene.h"
#include "play_int.h"
#include "player.h"
#include "progress.h"

/* One run's state, loaded and checked before anything is drawn, freed
 * by run_free whatever happened.  A run stays open across frames
 * (gls_play_begin, player.h): what does not depend on the frame is here,
 * made once; the per-frame step sets the frame in its copy of the
 * options and renders through the session. */
struct gls_play_run {
    gls_play_opts opts;   /* o's copy: the frame step sets its frame, its
                             --frames range and its sink                */
    const gls_play_opts *o; /* &opts                                    */
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
    gls_glctx *ctx;       /* NULL when no frame needs GL (run_needs_gl)     */
    gls_renderer *r;      /* NULL with it                                  */
    gls_writer *wr;
    size_t *made;         /* per camera: what gls_mkdir_p_made made         */
    gls_progress_json json;
    int started;          /* rendering began: --progress json ends with a line */
    int rendering;        /* begun to render (an outdir or a sink): the
                             renderer, the writer and ses exist          */
    char inputs[17];      /* the frame records' inputs digest           */
    gls_inputs_job inputs_job; /* its files' part, on a thread meanwhile */
    int inputs_pending;   /* inputs_job started, not finished           */
    traj_scan scan;       /* the trajectory's frames o's range holds     */
    session ses;          /* what each frame renders with               */
    gls_play_times times; /* --times: the marks                        */
};
typedef struct gls_play_run run;

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
    u->times.load = gls_now();
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
        gls_pose use = o->trajectory ? GLS_POSE_RIG : GLS_POSE_WORLD;
        const char *text = o->camera_texts ? o->camera_texts[i] : NULL;
        if (text ? gls_camera_parse(text, strlen(text), o->cameras[i], use, errs, c, err, sizeof err)
                 : gls_camera_load(o->cameras[i], use, errs, c, err, sizeof err)) {
            fprintf(errs, "%s\n", err);
            return 1;
        }
        if (o->width)
            c->width = o->width, c->height = o->height;
        if (play_lens_outputs_check(o, c, o->cameras[i], errs))
            return 1;
        u->names[i] = play_camera_name(o->cameras[i]); /* usable: gls_play_check_options */
        if (!u->names[i])
            return oom(errs);
    }
    /* disparity: a rectified pair, checked before anything is drawn */
    return (o->outputs & GLS_OUT_DISPARITIES) &&
           play_rectified_check(o, u->cams, (const char *const *)u->names, &u->baseline, errs);
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
    u->times.build = gls_now(), u->times.pack = u->scene.pack_seconds;
    /* exact coverage or samples, once (play_aa.c), and each lens checked
     * for the anti-aliasing chosen */
    if (play_aa_choose(&u->opts, &u->plan, &u->scene, u->cams, names, errs))
        return 1;
    for (size_t i = 0; i < o->ncameras; i++)
        if (play_lens_check(&u->cams[i], o->cameras[i], &u->plan, errs))
            return 1;
    if (play_motion_load(o, &u->ms, errs) || (!o->trajectory && play_motion_check(&u->ms, o->frame, errs)))
        return 1;
    if (o->trajectory && gls_traj_load(o->trajectory, &u->ms.traj, err, sizeof err)) {
        fprintf(errs, "%s\n", err);
        return 1;
    }
    if (play_exposure_setup(o, &u->ms, u->cams, names, &u->plan, errs) ||
        (!o->trajectory && play_exposure_check(&u->ms, u->cams, names, o->ncameras, o->frame, errs)))
        return 1;
    if (o->outputs & (GLS_OUT_IDS | GLS_OUT_EXACT_ONLY)) {
        /* the ids of the whole run, from the bundle's object names (the
         * instance image's, coverage's and the edge segments') */
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
    if (posed && play_explain_first_frame(o, &u->ms, posed, &inrange, &mine, u->errs) == 0) {
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

/* Whether any camera's frames need GL (gls_frame_plan.gl): planned as
 * play_camera plans them, with a next row so that flow, when asked,
 * counts. */
static int run_needs_gl(const run *u)
{
    const gls_play_opts *o = u->o;
    gls_plan_inputs pin = {o->outputs, o->image_format, &u->plan, u->ms.moving};
    for (size_t i = 0; i < o->ncameras; i++) {
        gls_frame_plan fp;
        gls_frame_plan_make(&fp, &pin, &u->cams[i], 1);
        if (fp.gl)
            return 1;
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
    u->r = u->ctx ? gls_renderer_create(u->ctx, u->b, &u->scene, err, sizeof err) : NULL;
    if (u->ctx && !u->r) {
        fprintf(u->errs, "glsplay: error: %s\n", err);
        return 1;
    }
    if ((o->outputs & GLS_OUT_BOXES_ALL) && gls_box_names_init(&u->box_names, u->b, &u->scene))
        return oom(u->errs);
    /* the exact pass shades textures on the CPU: it keeps the bundle's */
    if (!u->plan.o.exact) {
        gls_bundle_free(u->b);
        u->b = NULL;
    }
    if (u->r) {
        gls_renderer_set_background(u->r, o->background);
        gls_renderer_set_occlusion(u->r, (gls_occlusion_mode)o->occlusion);
        if (o->anisotropy > 1 && gls_renderer_set_anisotropy(u->r, o->anisotropy, err, sizeof err)) {
            fprintf(u->errs, "glsplay: error: %s\n", err);
            return 1;
        }
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
    int skip = !mine || (o->resume && play_frame_done(o, &u->plan, u->ms.moving, u->cams, (const char *const *)u->names, o->frame, 0,
                                                   ses->inputs));
    if (o->resume && mine)
        play_resume_note(errs, skip, 1);
    u->json.total = skip ? 0 : o->ncameras;
    u->json.skipped = mine && skip;
    play_motion_apply(&u->ms, o->frame);
    for (size_t i = 0; !skip && i < o->ncameras; i++)
        if (play_camera(ses, &u->cams[i], u->names[i], o->frame))
            return 1;
    return 0;
}

static void run_free(run *u, int rc)
{
    const gls_play_opts *o = u->o;
    if (u->inputs_pending)
        gls_frame_inputs_join(&u->inputs_job);
    /* first: it waits for the files in flight, whose jobs name the
     * cameras */
    gls_writer_destroy(u->wr);
    /* after the writer, whose last jobs may still say their frames */
    if (u->started)
        gls_progress_json_end(&u->json, rc == 0, gls_now());
    /* the renderer frees GL objects: in its own context, which another
     * run or player of this thread may have made not current */
    if (u->ctx && u->r)
        gls_glctx_make_current(u->ctx);
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
    play_motion_free(&u->ms);
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

/* The order of a run up to its first frame: check the options, load and
 * check every input, explain, scan the trajectory, make the directories,
 * start the renderer and the writer.  0, or the exit status after the
 * message; u is freed by run_free either way. */
static int run_begin(run *u, const gls_play_opts *o, FILE *out, FILE *errs)
{
    char err[1024];
    u->times.start = gls_now();
    u->opts = *o;
    o = u->o = &u->opts;
    u->errs = errs, u->ms.scene = &u->scene;
    u->cams = calloc(o->ncameras ? o->ncameras : 1, sizeof *u->cams);
    u->names = calloc(o->ncameras ? o->ncameras : 1, sizeof *u->names);
    gls_aa_opts aao = o->aa;
    if (aao.n == 0)
        aao.n = 1;
    if (gls_play_check_options(o, err, sizeof err)) {
        fprintf(errs, "glsplay: error: %s\n", err);
        return 2;
    }
    if (gls_aa_plan_init(&u->plan, &aao, err, sizeof err)) { /* checked: cannot fail */
        fprintf(errs, "glsplay: error: %s\n", err);
        return 1;
    }
    if (!u->cams || !u->names)
        return oom(errs);
    /* the inputs' digest reads every input file again: on another core
     * while this one loads them (frame_record.h gls_frame_inputs_start) */
    if (o->outdir || o->sink) {
        gls_frame_inputs_start(&u->inputs_job, o);
        u->inputs_pending = 1;
    }
    if (run_load_cameras(u) || run_load_scene(u))
        return 1;
    /* the context before the plan, which reports it; none when no
     * camera's frames need GL (exact coverage alone: the CPU draws it),
     * unless --explain asks what GL there is */
    if (o->explain || run_needs_gl(u)) {
        u->ctx = gls_glctx_create(o->backend, err, sizeof err);
        if (!u->ctx) {
            fprintf(errs, "glsplay: error: %s\n", err);
            return 1;
        }
    }
    u->times.context = gls_now();
    if (o->explain)
        run_explain(u, out);
    if (!o->outdir && !o->sink)
        return 0;
    gls_frame_inputs_finish(&u->inputs_job, o, o->trajectory ? &u->ms.traj : NULL, u->inputs);
    u->inputs_pending = 0;
    /* The whole trajectory is read and checked (with --resume, the frames
     * already complete counted) before anything is created: a bad row
     * leaves no empty directory behind. */
    u->scan = (traj_scan){0, 0, 0, UINT64_MAX};
    if (o->trajectory) {
        if (o->outputs & GLS_OUT_FLOW_ALL)
            u->scan.last = play_trajectory_last_frame(&u->ms);
        if (play_scan_trajectory(o, &u->plan, &u->ms, u->cams, (const char *const *)u->names, u->inputs,
                                 u->scan.last, errs, &u->scan.inrange, &u->scan.mine, &u->scan.complete))
            return 1;
    }
    if ((!o->sink && run_make_dirs(u)) || run_start(u))
        return 1;
    u->times.upload = gls_now();
    u->json.f = o->progress == GLS_PROGRESS_JSON ? errs : NULL;
    u->json.cameras = o->ncameras;
    u->json.t0 = gls_now();
    session ses = {o,          &u->ms,  &u->scene,     &u->plan, u->r,  u->wr,    &u->json,    errs,
                   o->ncameras, 0,      u->json.t0,    0,        u->baseline, &u->gt, NULL,    NULL,
                   &u->moves,  &u->box_names, o->frame, NULL,    u->ms.moving, NULL, u->inputs, o->counts,
                   o->times ? &u->times : NULL, u->b ? u->b->textures : NULL};
    u->ses = ses;
    u->rendering = 1;
    return 0;
}

int gls_play_begin(const gls_play_opts *o, FILE *out, FILE *errs, gls_play_run **runp)
{
    run *u = calloc(1, sizeof *u);
    *runp = NULL;
    if (!u)
        return oom(errs);
    int rc = run_begin(u, o, out, errs);
    if (rc)
        return gls_play_end(u, rc);
    *runp = u;
    return 0;
}

int gls_play_render_frame(gls_play_run *u, uint64_t frame, struct gls_frame_sink *sink, FILE *errs)
{
    gls_play_opts *o = &u->opts;
    const char *const *names = (const char *const *)u->names;
    char err[1024];
    if (!u->rendering || !o->sink || !sink) { /* a caller's mistake: said all the same */
        fprintf(errs, "glsplay: error: the run was begun without a sink: it renders no frame into one\n");
        return 1;
    }
    u->errs = u->ses.errs = errs;
    o->sink = sink;
    /* this thread's current context may be another run's or player's */
    if (u->ctx && gls_glctx_make_current(u->ctx)) {
        fprintf(errs, "glsplay: error: cannot make the run's GL context current on this thread (a run renders "
                      "on the thread that began it)\n");
        return 1;
    }
    /* a fresh session's per-frame state, as a run of this frame alone */
    u->ses.views = o->ncameras, u->ses.views_done = 0, u->ses.estimated = 0;
    u->ses.t0 = gls_now();
    u->ses.next = NULL, u->ses.rel = NULL, u->ses.rel_now = NULL;
    int rc;
    if (o->trajectory) {
        /* the frame as --frames F:F+1, scanned as such (the begin's scan
         * covered the range it was begun with) */
        if (o->frame_first != frame || o->frame_end != frame + 1) {
            o->frame_first = frame, o->frame_end = frame + 1;
            if (play_scan_trajectory(o, &u->plan, &u->ms, u->cams, names, u->inputs, u->scan.last, errs,
                                     &u->scan.inrange, &u->scan.mine, &u->scan.complete))
                return 1;
        }
        rc = play_trajectory(&u->ses, u->cams, names, &u->scan);
    } else {
        if (frame > UINT32_MAX) {
            fprintf(errs, "glsplay: error: frame %llu is over the largest frame number, %u\n",
                    (unsigned long long)frame, UINT32_MAX);
            return 1;
        }
        /* the begin checked the motions and exposures at its frame */
        if (frame != o->frame &&
            (play_motion_check(&u->ms, frame, errs) ||
             play_exposure_check(&u->ms, u->cams, names, o->ncameras, frame, errs)))
            return 1;
        o->frame = (uint32_t)frame;
        u->ses.frame_now = frame;
        rc = run_single(u, &u->ses);
    }
    if (rc == 0 && gls_writer_finish(u->wr, err, sizeof err)) {
        fprintf(errs, "%s\n", err);
        rc = 1;
    }
    return rc;
}

int gls_play_end(gls_play_run *u, int rc)
{
    if (u) {
        run_free(u, rc);
        free(u);
    }
    return rc;
}

/* The order of a run: begin (check, load, explain, scan, make the
 * directories, start), then render and write each frame and camera, and
 * the calibration files last. */
int gls_play(const gls_play_opts *o, FILE *out, FILE *errs)
{
    char err[1024];
    run *u = NULL;
    int rc = gls_play_begin(o, out, errs, &u);
    if (rc || !u->rendering)
        return gls_play_end(u, rc);
    o = u->o;
    u->started = 1;
    rc = o->trajectory ? play_trajectory(&u->ses, u->cams, (const char *const *)u->names, &u->scan)
                       : run_single(u, &u->ses);
    if (rc == 0 && gls_writer_finish(u->wr, err, sizeof err)) {
        fprintf(errs, "%s\n", err);
        rc = 1;
    }
    u->times.write = gls_now();
    if (rc == 0 && o->times)
        gls_play_times_print(errs, &u->times);
    /* after the render and its files: every frame in the range was read
     * and checked */
    if (rc == 0 && o->write_calib && !o->sink)
        rc = gls_calib_write(o, o->trajectory ? &u->ms.traj : NULL, u->cams, (const char *const *)u->names, errs);
    return gls_play_end(u, rc);
}
