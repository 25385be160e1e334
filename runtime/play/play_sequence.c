/* The frames of a run (play_int.h): whether a frame is complete
 * (--resume), the trajectory scanned and checked before anything is
 * created, its frames rendered in order with the progress line, and the
 * first frame posed for --explain. */
#include <string.h>
#include <sys/stat.h>
#include "frame_record.h"
#include "frames.h"
#include "play_int.h"
#include "progress.h"

/* Is this frame complete: for every camera, a record that covers what o
 * asks for (written after the camera's last file, frame_record.h), and
 * every requested output file still there? */
int play_frame_done(const gls_play_opts *o, const gls_aa_plan *plan, int moving, const gls_camera *cams,
                    const char *const *names, uint32_t frame, int has_next, const char *inputs)
{
    gls_plan_inputs pin = {o->outputs, o->image_format, plan, moving};
    if (strcmp(inputs, "-") == 0) /* an input that cannot be read again: never taken */
        return 0;
    char path[MAXPATH], text[1024];
    for (size_t i = 0; i < o->ncameras; i++) {
        /* the record and the files of the frame's plan (frame_plan.h) */
        gls_frame_plan fp;
        gls_frame_plan_make(&fp, &pin, &cams[i], has_next);
        if (gls_frame_record_path(path, sizeof path, o->outdir, names[i], frame) ||
            gls_frame_record_text(text, sizeof text, o, &fp, &cams[i], names[i], frame, inputs) ||
            !gls_frame_record_matches(path, text))
            return 0;
        for (size_t k = 0; k < GLS_OUT_KINDS; k++) {
            if (!(fp.outputs & gls_output_kinds[k].bit))
                continue;
            struct stat st;
            if (play_output_file(path, sizeof path, o, names[i], k, frame) ||
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
uint64_t play_trajectory_last_frame(const motion_set *ms)
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

/* --resume's question of the frames iterator (frames.h): is frame f
 * complete, for every camera? */
typedef struct {
    const gls_play_opts *o;
    const gls_aa_plan *plan; /* with moving: the frames' plans            */
    int moving;
    const gls_camera *rel;
    const char *const *names;
    uint64_t last;       /* the trajectory's last frame: no flow from it */
    const char *inputs;
} resume_ctx;

static int resume_complete(void *ud, uint64_t frame)
{
    const resume_ctx *r = ud;
    return r->o->resume && play_frame_done(r->o, r->plan, r->moving, r->rel, r->names, (uint32_t)frame,
                                           frame != r->last, r->inputs);
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

/* The trajectory parsed once before anything is rendered: every line of
 * the file is checked, whatever --frames asks for, the frames asked for
 * with no row said in a warning, the frames in the range counted,
 * those of this --shard (mine; all without one) and, with --resume, the
 * complete ones among them (last: the frame of the trajectory's last row,
 * which writes no flow).  With flow, the row after the range is read too,
 * and its motions checked: the last frame's flow goes to it.  0, or 1
 * after a message. */
int play_scan_trajectory(const gls_play_opts *o, const gls_aa_plan *plan, const motion_set *ms, const gls_camera *rel,
                         const char *const *names, const char *inputs, uint64_t last, FILE *errs,
                         uint64_t *inrange, uint64_t *mine, uint64_t *complete)
{
    char err[1024];
    resume_ctx rc_ = {o, plan, ms->moving, rel, names, last, inputs};
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
        if (play_motion_check(ms, p.frame, errs) || play_exposure_check(ms, rel, names, o->ncameras, p.frame, errs)) {
            rc = 1;
            break;
        }
        (*inrange)++;
        *mine += m.mine != 0;
        *complete += m.complete != 0;
    }
    /* the row after the range: the last frame's flow goes to it; then
     * every row to the end of the file, whatever the range */
    if (got == 0 && rc == 0 && f.past && (o->outputs & GLS_OUT_FLOW_ALL) && play_motion_check(ms, f.after.frame, errs))
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
void play_resume_note(FILE *errs, uint64_t complete, uint64_t total)
{
    fprintf(errs, "glsplay: note: --resume: %llu of %llu frame%s complete, skipped; %llu to render\n",
            (unsigned long long)complete, (unsigned long long)total, total == 1 ? "" : "s",
            (unsigned long long)(total - complete));
}

/* Every frame of the trajectory in [frame_first, frame_end), parsed one
 * line at a time from its text (read once: memory stays flat beyond its
 * bytes however long the sequence), as scanned (sc).  Each camera file gives that camera's pose relative to the rig. */
int play_trajectory(session *s, const gls_camera *rel, const char *const *names, const traj_scan *sc)
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
        play_resume_note(errs, complete, mine);
    uint64_t todo = mine - complete, done = 0;
    s->views = todo * o->ncameras;
    s->json->total = s->views;
    s->json->skipped = complete;
    char err[1024];
    resume_ctx rctx = {o, s->plan, s->moving, rel, names, last, s->inputs};
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
        play_motion_apply(s->ms, p.frame);
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
int play_explain_first_frame(const gls_play_opts *o, const motion_set *ms, gls_camera *posed, uint64_t *inrange,
                             uint64_t *mine, FILE *errs)
{
    *inrange = 1;
    *mine = (uint64_t)gls_shard_has(&o->shard, o->frame, o->frame);
    if (!o->trajectory) {
        play_motion_apply(ms, o->frame);
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
    if (play_motion_check(ms, p.frame, errs) == 0)
        play_motion_apply(ms, p.frame);
    for (size_t i = 0; i < o->ncameras; i++) {
        gls_camera rel = posed[i];
        gls_traj_compose(rel.R, rel.T, p.R, p.T, posed[i].R, posed[i].T);
    }
    return 0;
}
