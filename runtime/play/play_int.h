/* Internal to the player's files: what gls_play (player.h) shares with
 * the rest of its family, and nothing outside runtime/play/play*.c may
 * include it (as SQLite's btreeInt.h is to btree.c).  The family:
 *   player.c        the order of a run: load and check the inputs, make
 *                   the directories, start the renderer and the writer,
 *                   render, free
 *   play_sequence.c the frames of a trajectory, --resume, --explain's
 *                   first frame
 *   play_frame.c    one camera frame: its plan's steps, to the writer
 *   play_passes.c   the passes that draw: poses within the exposure, the
 *                   anti-aliasing plan, rolling-shutter bands, estimates
 *   play_flow.c     a camera frame's flow to the next row
 *   play_motion.c   the --motion set: load, check, apply, free
 *   play_checks.c   the option and input checks before anything is drawn
 *   play_aa.c       exact coverage or samples: --aa auto's choice
 *   play_paths.c    camera names and output file paths */
#ifndef GLS_PLAY_INT_H
#define GLS_PLAY_INT_H

#include <stdint.h>
#include <stdio.h>
#include "distort_render.h"
#include "exposure.h"
#include "frame_writer.h"
#include "out_boxes.h"
#include "play_times.h"
#include "gt_flow.h"
#include "gt_table.h"
#include "motion.h"
#include "player.h"
#include "progress_json.h"
#include "render.h"
#include "trajectory.h"

#define MAXPATH 4096

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
    gls_play_times *times;      /* --times: the marks (NULL: not asked);
                                   the first frame marks plan and draw  */
    const gls_texture *textures; /* the bundle's, for the exact pass's
                                   shading (NULL: not kept)            */
} session;

/* What play_scan_trajectory found, before anything was created or written. */
typedef struct {
    uint64_t inrange, mine, complete, last;
} traj_scan;

/* play_paths.c */
char *play_camera_name(const char *path);
int play_output_file(char *path, size_t len, const gls_play_opts *o, const char *name, size_t k, uint32_t frame);

/* play_motion.c */
int play_motion_load(const gls_play_opts *o, motion_set *ms, FILE *errs);
int play_motion_check(const motion_set *ms, uint64_t frame, FILE *errs);
int play_exposure_check(const motion_set *ms, const gls_camera *cams, const char *const *names, size_t ncams,
                        uint64_t frame, FILE *errs);
void play_motion_apply(const motion_set *ms, uint64_t frame);
void play_motion_free(motion_set *ms);

/* play_aa.c: exact coverage or samples for the run (--aa auto resolved,
 * --aa exact's refusals): o->aa.exact and plan->o.exact become
 * GLS_AA_EXACT or GLS_AA_SAMPLED.  0, or 1 after a message. */
int play_aa_choose(gls_play_opts *o, gls_aa_plan *plan, const gls_scene *s, const gls_camera *cams,
                   const char *const *names, FILE *errs);

/* play_checks.c */
int play_rectified_check(const gls_play_opts *o, const gls_camera *cams, const char *const *names, double *B,
                         FILE *errs);
int play_lens_outputs_check(const gls_play_opts *o, const gls_camera *c, const char *path, FILE *errs);
int play_lens_check(const gls_camera *c, const char *path, const gls_aa_plan *plan, FILE *errs);
int play_exposure_setup(const gls_play_opts *o, motion_set *ms, const gls_camera *cams, const char *const *names,
                        const gls_aa_plan *plan, FILE *errs);

/* play_passes.c: play_pose_at is a gls_pose_at_fn, play_render_plan a
 * gls_render_plan_fn (exposure.h), both with a session as ud */
int play_pose_at(void *ud, double t, gls_camera *cam);
int play_render_plan(void *ud, const gls_camera *c, uint32_t v0, uint32_t v1, gls_accum *acc, char *msg,
                     size_t msglen);
int play_centre_bands(session *s, const gls_camera *c, gls_bands bands, uint8_t *rgba, float *z, uint32_t *inst,
                      float *normal, float *gt_z, char *msg, size_t msglen);
void play_view_done(session *s);

/* play_flow.c */
int play_flow_frame(session *s, const gls_camera *c, const gls_distort_frame *df, const char *name, uint32_t frame,
                    gls_bands bands,
                    const uint32_t *inst, const float *z, float **uv, uint8_t **mask, char *msg, size_t msglen);

/* play_frame.c */
int play_camera(session *s, const gls_camera *c, const char *name, uint32_t frame);

/* play_sequence.c */
int play_frame_done(const gls_play_opts *o, const gls_aa_plan *plan, int moving, const gls_camera *cams,
                    const char *const *names, uint32_t frame, int has_next, const char *inputs);
uint64_t play_trajectory_last_frame(const motion_set *ms);
int play_scan_trajectory(const gls_play_opts *o, const gls_aa_plan *plan, const motion_set *ms, const gls_camera *rel,
                         const char *const *names, const char *inputs, uint64_t last, FILE *errs,
                         uint64_t *inrange, uint64_t *mine, uint64_t *complete);
void play_resume_note(FILE *errs, uint64_t complete, uint64_t total);
int play_trajectory(session *s, const gls_camera *rel, const char *const *names, const traj_scan *sc);
int play_explain_first_frame(const gls_play_opts *o, const motion_set *ms, gls_camera *posed, uint64_t *inrange,
                             uint64_t *mine, FILE *errs);

#endif
