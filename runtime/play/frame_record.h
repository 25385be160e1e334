/* The completion record of one camera's outputs of one frame, which
 * --resume trusts (spec/road.md "Resuming a sequence").
 *
 * Each output file is written atomically, but a frame is several files:
 * a re-render that fails part way would leave new and old files side by
 * side, each complete.  So the player removes the record before it
 * rewrites any file of that camera and frame, and writes the record
 * (atomically) after the last one.  The record says what it covers:
 * camera name and size, outputs, image and float formats and the settings
 * that change the files, so --resume with other outputs or settings does
 * not take it. */
#ifndef GLS_FRAME_RECORD_H
#define GLS_FRAME_RECORD_H

#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include "player.h"
#include "frame_plan.h"
#include "trajectory.h"

/* OUTDIR/NAME/.frame_F.done (hidden: it is bookkeeping, not an output).
 * 0, or -1 if it does not fit. */
int gls_frame_record_path(char *buf, size_t len, const char *outdir, const char *name, uint32_t frame);

/* The record's text for camera c (its name, size, intrinsics and lens)
 * and frame under o (outputs, image format, float format, depth16's
 * scale, anti-aliasing, anisotropy, background, the camera's effects),
 * ending with the inputs' digest (gls_frame_inputs_finish).  0, or -1 if it does
 * not fit in len. */
int gls_frame_record_text(char *buf, size_t len, const gls_play_opts *o, const gls_frame_plan *fp,
                          const gls_camera *c, const char *name, uint32_t frame, const char *inputs);

/* The digest of what the frames are made from, as the record's "inputs"
 * line shows it (16 hex digits): the bundle file, every camera file, the
 * trajectory (traj: its text as read once, NULL without one) and the
 * motion files (name and file), and --flatten; "-" when one of them
 * cannot be read again (every input is a regular file, readfile.h, but
 * one removed or replaced during the run has no digest, so a record made
 * then is never taken by --resume).
 *
 * In two steps, so that the files' part (the bundle and the
 * camera files, which come first: FNV-1a, one byte after another, takes
 * about 15 ms for a 9 MB bundle) runs on a thread of its own while the
 * run loads and checks its inputs on another core; the value is the
 * same.  start copies what it needs from o (the paths outlive the run)
 * and runs the part on the calling thread if no thread can be made;
 * finish waits for it and adds the rest (trajectory, motions, flatten);
 * join only waits (a run that ends before finish).  Each start is
 * followed by one finish or one join. */
typedef struct {
    const char *bundle;
    const char *const *cameras;
    size_t ncameras;
    uint64_t h;
    int ok, threaded;
    pthread_t th;
} gls_inputs_job;
void gls_frame_inputs_start(gls_inputs_job *j, const gls_play_opts *o);
void gls_frame_inputs_finish(gls_inputs_job *j, const gls_play_opts *o, const gls_traj_text *traj, char out[17]);
void gls_frame_inputs_join(gls_inputs_job *j);

/* 1 if the file at path holds exactly text (and is a regular file). */
int gls_frame_record_matches(const char *path, const char *text);

#endif
