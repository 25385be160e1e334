/* Motion files (glsplay --motion NAME=FILE; spec/bundle.md section 9.3):
 * per frame, the pose of a named instance relative to its parent at the
 * call site, object-to-parent: world at frame k = W_call * [R_k T_k; 0 1].
 *
 * Formats, told apart like trajectory files:
 *   "# glsroad motion 1" as the first line, then rows
 *       FRAME TIME R00 R01 R02 R10 R11 R12 R20 R21 R22 TX TY TZ
 *   KITTI: 12 numbers a row, row-major [R | T]; row k is frame k
 *   TUM:   t tx ty tz qx qy qz qw; row k is frame k
 * '#' starts a comment; blank lines are skipped.  The file is read whole
 * (a motion is a few hundred bytes a frame) so that every frame to be
 * rendered is checked before the first is drawn. */
#ifndef GLS_MOTION_H
#define GLS_MOTION_H
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct {
    char *path;
    uint64_t n;        /* rows */
    uint64_t *frame;   /* increasing */
    double (*RT)[12];  /* R row-major, then T */
} gls_motion;

/* Read path.  0; -1 with "path:line: error: ..." in err (or "path:
 * error: out of memory"); or -2 when the file cannot be opened or read
 * (readfile.h's rule: a regular file), with only the reason in err
 * ("cannot open: No such file or directory"), for the caller to say which
 * option named the file.  Notes (an R re-orthonormalised, once) go to
 * notes. */
int gls_motion_read(const char *path, FILE *notes, gls_motion *m, char *err, size_t errlen);
/* The pose of frame k: 0, or -1 when the file has no row for it. */
int gls_motion_pose(const gls_motion *m, uint64_t k, double R[9], double T[3]);
void gls_motion_free(gls_motion *m);

#endif
