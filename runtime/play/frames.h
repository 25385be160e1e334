/* A run's frames (spec/road.md "--frames", "--shard", "--resume"): the
 * rows of the trajectory, those in --frames A:B, marked as this shard's
 * or not and, with --resume, as complete or not.  The one filter of
 * frames: the scan before rendering, the render, --explain's first frame
 * and --write-calib all read their frames through it. */
#ifndef GLS_FRAMES_H
#define GLS_FRAMES_H

#include <stdint.h>
#include <stdio.h>
#include "shard.h"
#include "trajectory.h"

typedef struct {
    gls_traj *t;
    uint64_t first, end;        /* --frames: frames first..end-1          */
    const gls_shard *shard;
    /* --resume: is frame f complete (1), given whether it has a next row;
     * NULL: nothing is complete */
    int (*complete)(void *ud, uint64_t frame);
    void *ud;
    int past;                   /* a row at or past end was read: *after */
    gls_traj_pose after;        /* the first row past the range          */
} gls_frames;

/* What gls_frames_next says of a frame in range. */
typedef struct {
    int mine;     /* this shard's                                        */
    int complete; /* --resume: complete already (only when mine)         */
} gls_frame_mark;

/* Read the frames of the trajectory text tx (read once: trajectory.h);
 * notes: where the reader's notes go (NULL: none).  0, or -1 when out of
 * memory. */
int gls_frames_open(gls_frames *f, const gls_traj_text *tx, FILE *notes, uint64_t first, uint64_t end,
                    const gls_shard *shard);
/* The next frame in range: 1 with its row and its mark, 0 when the range
 * is over (rows past it are left unread, but the first, in f->after when
 * f->past), -1 with the reader's message in err. */
int gls_frames_next(gls_frames *f, gls_traj_pose *p, gls_frame_mark *m, char *err, size_t errlen);
/* Read and check every row left, to the end of the file (a row out of
 * order after the range is as wrong as one in it); the first past the
 * range is in f->after when f->past.  0, or -1 with err. */
int gls_frames_rest(gls_frames *f, char *err, size_t errlen);
void gls_frames_close(gls_frames *f);

#endif
