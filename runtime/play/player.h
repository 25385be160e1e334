/* The player as a library: what glsplay does, callable from tests and,
 * later, from a Python binding or a trajectory driver. */
#ifndef GLS_PLAYER_H
#define GLS_PLAYER_H

#include <stdint.h>
#include <stdio.h>
#include "aa.h"
#include "frame_plan.h"
#include "output_table.h"
#include "bundle.h"
#include "camera.h"
#include "glctx.h"
#include "scene.h"
#include "shard.h"

/* --progress: nothing, the terminal line (progress.h), or one JSON
 * object a line per camera frame (progress_json.h) */
enum { GLS_PROGRESS_OFF = 0, GLS_PROGRESS_BAR = 1, GLS_PROGRESS_JSON = 2 };

typedef struct {
    const char *bundle;          /* path of the .glsb                    */
    const char *const *cameras;  /* camera file paths                    */
    size_t ncameras;
    const char *const *camera_texts; /* NULL; or per camera NULL (read the
                                    file) or the camera file's text, which
                                    cameras[i] then names (the library's
                                    cameras built from numbers)         */
    const char *outdir;          /* NULL: nothing is rendered            */
    unsigned outputs;            /* GLS_OUT_* bits                       */
    uint32_t width, height;      /* --size override, 0 = the camera's    */
    int explain;                 /* print the plan first                 */
    int times;                   /* --times: the run's time line on
                                    stderr at its end (play_times.c)    */
    uint32_t frame;              /* frame number in the file names, when
                                    there is no trajectory              */
    const char *trajectory;      /* NULL, or a trajectory file: render
                                    each of its frames (spec/road.md)   */
    uint64_t frame_first, frame_end; /* --frames A:B: frames A..B-1 of the
                                    trajectory; end UINT64_MAX = all    */
    int resume;                  /* skip complete frames (frame_record.h) */
    gls_shard shard;             /* --shard I/N: only frames f with
                                    (f - frame_first) mod N = I (shard.h) */
    float background[3];         /* clear colour, 0..1 (default black)   */
    gls_aa_opts aa;              /* anti-aliasing; n = 0 is taken as 1   */
    gls_image_format image_format;
    gls_float_format float_format; /* depth, disparity, a pfm image    */
    double depth_scale;          /* depth16: Zc * depth_scale, 0 = KITTI's */
    uint32_t aa_tiles;           /* samples per GL pass, 0 = automatic   */
    uint64_t aa_memory;          /* one-pass anti-aliasing: bytes for the
                                    fine framebuffer's tiles, 0 = default */
    int occlusion;               /* gls_occlusion_mode (occlusion.h):
                                    0 = auto, the default               */
    uint32_t anisotropy;         /* anisotropic texture filtering up to N x;
                                    0 or 1 = off (the fast default)     */
    int progress;                /* GLS_PROGRESS_*: what goes to errs     */
    gls_backend backend;         /* GL backend (glctx.h); 0 = auto       */
    int write_calib;             /* --write-calib: calibration files
                                    (calib_write.h)                     */
    int flatten;                 /* --flatten: the flattened reference path */
    const char *const *motions;  /* --motion NAME=FILE arguments         */
    size_t nmotions;
    unsigned writer_threads;     /* 1: encode and write each camera
                                    frame's files on a writer thread while
                                    the next renders (glsplay's default);
                                    0: on the rendering thread.  Same
                                    files either way (frame_writer.h)   */
    gls_frame_counts *counts;    /* NULL; or where the passes, buffers and
                                    samples of the last camera frame are
                                    counted as they run (frame_plan.h),
                                    for the tests that hold the run to
                                    its plan                            */
    struct gls_frame_sink *sink; /* NULL: files are written under outdir;
                                    else each camera frame's arrays go to
                                    it (frame_files.h) and nothing is
                                    written: no directory, record or
                                    calibration file (the library's
                                    glscene_play_render)                */
    int aa_auto;                 /* set by the player: aa.exact was
                                    GLS_AA_AUTO (the default), and the
                                    player chose (play_aa.c)            */
    char aa_auto_why[200];       /* set by the player: why --aa auto drew
                                    samples; "" when it chose exact     */
    int bands_whole;             /* 0; tests only (glsplay never sets it):
                                    each band of rows of a rolling
                                    shutter draws and reads back the
                                    whole image, the same bytes
                                    (gls_bands, exposure.h)             */
} gls_play_opts;

/* The refusals of the player that its options alone decide, without
 * reading any file, so that they are usage errors (exit status 2,
 * spec/exit_status.md): the anti-aliasing plan (a Gaussian sigma outside
 * 0.01..16), the output directory each camera file names (none, or two
 * cameras naming the same one), disparity's two cameras, an instance
 * given two --motion.  0, or -1 with the message (no "glsplay: error: ")
 * in msg. */
int gls_play_check_options(const gls_play_opts *o, char *msg, size_t msglen);

/* What keeps exact coverage from drawing with these anti-aliasing options
 * (a Gaussian filter), this scene (shadows; s may be NULL) and these n
 * cameras (exposure or sensor effects; moving: a trajectory or a motion,
 * with which shutter and line_delay act): NULL when nothing does, else a
 * phrase that follows "exact coverage does not draw", and *cam the
 * camera's index, or SIZE_MAX when it is the options' or the scene's.
 * The one rule behind --aa auto and --aa exact's refusals (play_aa.c),
 * and the library's (glscene_open). */
const char *gls_play_exact_blocker(const gls_aa_opts *aa, const gls_scene *s, const gls_camera *cams, size_t n,
                                   int moving, size_t *cam);
/* --aa auto resolved, given the blocker's answer why (NULL: none) and the
 * run's outputs: aa->exact GLS_AA_EXACT or GLS_AA_SAMPLED, and aa->dense,
 * the default's bound on a pixel's cost (exact.h GLS_EXACT_AUTO_DENSE; 0
 * when coverage or edge segments need every area).  glsplay's and the
 * library's one rule (play_aa.c, glscene_open). */
void gls_play_aa_auto(gls_aa_opts *aa, const char *why, unsigned outputs);

/* One camera frame drawn by the player's own steps into buffers the
 * caller takes (libglscene's glscene_render): the frame plan for
 * outputs (GLS_OUT_IMAGE, DEPTH, INSTANCE, NORMALS: what a library
 * caller can ask), its centre and ground-truth passes and, when the plan
 * accumulates, its colour; no files, no writer.  The renderer has the
 * camera's size set.  0 with *res (free it with gls_play_frame_free), or
 * -1 with msg (empty: out of memory). */
typedef struct {
    gls_frame_plan fp;  /* what ran                                     */
    uint8_t *rgba;      /* the centre pass's colour (fp.rgba), or NULL  */
    float *z;           /* its depth (fp.z), or NULL                    */
    uint32_t *ids;      /* the truth pass's ids, scene instance + 1     */
    float *normals;     /* its normals, 3 a pixel                        */
    gls_accum acc;      /* the accumulated samples (fp.aa)              */
    float *exact;       /* exact coverage's image, RGBA float (fp.exact) */
} gls_play_frame_result;
/* background and textures: the exact pass's (plan->o.exact; the GL
 * passes take the renderer's); textures is the bundle's, NULL for an
 * untextured scene */
int gls_play_frame(gls_renderer *r, const gls_scene *scene, const gls_aa_plan *plan, const gls_camera *c,
                   unsigned outputs, const float background[3], const gls_texture *textures,
                   gls_play_frame_result *res, char *msg, size_t msglen);
void gls_play_frame_free(gls_play_frame_result *res);

/* Run the player.  Messages go to errs as "glsplay: error: ..." lines,
 * the plan to out.  Returns the exit status: 0 done, 1 input error, 2 a
 * usage error of gls_play_check_options (which it runs first). */
int gls_play(const gls_play_opts *o, FILE *out, FILE *errs);

/* gls_play in three steps, so that a run stays open across frames (the
 * library's glscene_play_render): gls_play is begin, its frames, end.
 *
 * gls_play_begin does everything that does not depend on the frame: the
 * checks, the bundle, the cameras, the scene, the motions and the
 * trajectory (read once), the GL context (made current on this thread),
 * --explain, the scan of o's range of the trajectory, the directories
 * (without a sink), the renderer with the scene uploaded, the writer.  0
 * with *run (o is copied; its strings must outlive the run), or the exit
 * status after the message with *run NULL.  A run begun with neither
 * outdir nor sink renders nothing (--explain alone).
 *
 * gls_play_render_frame renders frame F of a run begun with a sink into
 * sink (which replaces o's): the trajectory's row F as --frames F:F+1
 * would (its flow to the next row, its motions and sub-frame poses), or
 * the single frame numbered F; messages to errs.  It makes the run's GL
 * context current first: call it from the thread that began the run.  0,
 * or 1 after the message; after a failure, end the run (the writer keeps
 * its first failure).
 *
 * gls_play_end frees the run (NULL is fine), its context last; returns
 * rc. */
typedef struct gls_play_run gls_play_run;
int gls_play_begin(const gls_play_opts *o, FILE *out, FILE *errs, gls_play_run **run);
int gls_play_render_frame(gls_play_run *run, uint64_t frame, struct gls_frame_sink *sink, FILE *errs);
int gls_play_end(gls_play_run *run, int rc);

/* Print the plan (explain.c): the GL backend and context, which GL
 * effects are on and why, passes, anti-aliasing, read-backs.  cams/names
 * may be empty (n = 0); o gives the outputs, the anti-aliasing, the image
 * format and the backend asked for; ctx is the context made for it. */
void gls_explain(FILE *out, const char *bundle_path, const gls_bundle *b, const gls_scene *s,
                 const gls_camera *cams, const char *const *names, size_t n, const gls_play_opts *o,
                 const gls_glctx *ctx);

/* Output file name: OUTDIR/NAME/KIND_%06u.EXT (frame numbers grow past
 * six digits without breaking).  Returns 0, -1 if it does not fit. */
int gls_output_path(char *buf, size_t len, const char *outdir, const char *name, const char *kind,
                    uint32_t frame, const char *ext);

#endif
