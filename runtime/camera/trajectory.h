/* Reading a glsroad trajectory file (spec/road.md, "Trajectory file"),
 * frame by frame, and composing a camera's rig-relative pose with the
 * rig's pose of a frame.  Self-contained (libc and libm only) so that the
 * player can use it as it is.
 *
 * A trajectory line:  FRAME TIME R00 R01 R02 R10 R11 R12 R20 R21 R22 T0 T1 T2
 * with P_rig = R * P_world + T (the camera-file convention).  KITTI (12
 * values: [Rw | c] row-major) and TUM (8: time c qx qy qz qw) lines are
 * read too, told apart by the first line's count: camera-to-world poses,
 * returned as R = Rw^T, T = -Rw^T c, frame = line number among lines with
 * values (spec/road.md, "KITTI and TUM trajectories").  A camera file
 * used with a trajectory gives that camera's pose relative to the rig:
 * P_cam = R_cam * P_rig + T_cam.  So in each frame
 *     R_cam_world = R_cam * R,   T_cam_world = R_cam * T + T_cam.
 *
 * A file is read once, whole (gls_traj_load), and parsed from memory as
 * often as needed (gls_traj_open_text): a pipe (--trajectory <(...),
 * /dev/stdin) works like a file, and every reader of a run sees the same
 * bytes.  The parse holds one line at a time.  Typical use:
 *
 *     gls_traj_text tx;
 *     if (gls_traj_load(path, &tx, err, sizeof err)) { ...say err... }
 *     gls_traj *t = gls_traj_open_text(&tx, stderr);   // NULL: out of memory
 *     gls_traj_pose p;
 *     int r;
 *     while ((r = gls_traj_next(t, &p, err, sizeof err)) == 1) {
 *         if (p.frame < first) continue;
 *         if (p.frame >= end) break;
 *         gls_traj_compose(cam.R, cam.T, p.R, p.T, R, T);  // per camera
 *         ... render frame p.frame with R, T ...
 *     }
 *     gls_traj_close(t);
 *     gls_traj_text_free(&tx);
 *     if (r < 0) { fprintf(stderr, "%s\n", err); exit 1; }
 */
#ifndef GLS_TRAJECTORY_H
#define GLS_TRAJECTORY_H
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct {
    uint64_t frame;    /* frame index: strictly increasing through the file */
    double time;       /* seconds, strictly increasing                      */
    double R[9];       /* world -> rig rotation, row-major, proper, orthonormal */
    double T[3];       /* world -> rig translation                         */
    unsigned line;     /* line of the file it came from                    */
} gls_traj_pose;

typedef struct gls_traj gls_traj;

/* The most bytes a trajectory file may hold (about 900,000 rows of
 * glsroad's, at full precision). */
#define GLS_TRAJ_MAX_FILE ((size_t)256 << 20)

/* A trajectory file's bytes, read once. */
typedef struct {
    char *path;  /* as given: the messages' file name */
    char *data;  /* len bytes and a NUL                */
    size_t len;
} gls_traj_text;

/* Read the file at path whole (a regular file, a pipe or a device): 0,
 * or -1 with "path: error: why" in err (cannot open, a directory, over
 * GLS_TRAJ_MAX_FILE) or "path:line: error: line longer than 4095 bytes",
 * said as soon as the line passes the limit. */
int gls_traj_load(const char *path, gls_traj_text *tx, char *err, size_t errlen);
void gls_traj_text_free(gls_traj_text *tx);

/* A reader of tx from its start (tx outlives it); NULL: out of memory.
 * Notes (an R re-orthonormalised, once per reader) go to notes; NULL
 * drops them. */
gls_traj *gls_traj_open_text(const gls_traj_text *tx, FILE *notes);

/* gls_traj_load and gls_traj_open_text in one, the reader owning the
 * text: NULL on error, with the message in err. */
gls_traj *gls_traj_open(const char *path, FILE *notes, char *err, size_t errlen);

/* The next frame: 1 (pose filled), 0 (end of file; an empty file -- no
 * frame at all -- is an error), or -1 with "path:line: error: message" in
 * err.  Checks every line: 14 finite numbers, FRAME a whole number,
 * frame and time strictly increasing, R a rotation (gls_rotation_check:
 * used as given within 1e-6, replaced by the nearest rotation within
 * 1e-4, refused beyond). */
int gls_traj_next(gls_traj *t, gls_traj_pose *p, char *err, size_t errlen);

void gls_traj_close(gls_traj *t);

/* Camera in the world for one frame: R = Rc * Rr, T = Rc * Tr + Tc, from
 * the camera's pose relative to the rig (Rc, Tc) and the rig's pose (Rr,
 * Tr).  The outputs may alias no input. */
void gls_traj_compose(const double Rc[9], const double Tc[3], const double Rr[9], const double Tr[3], double R[9],
                      double T[3]);

/* A frame range "A:B" (frames A..B-1), "A:" (A to the end), ":B", or "A"
 * (just A).  end = UINT64_MAX means no end.  0, or -1 with a message
 * ("--frames: ...") in err. */
int gls_traj_range(const char *s, uint64_t *first, uint64_t *end, char *err, size_t errlen);

/* The frames of a --frames range that have no row in the trajectory,
 * gathered as the rows are read in order, for one warning line: the
 * first GLS_TRAJ_GAPS_SHOWN runs of missing frames are named, the rest
 * counted. */
#define GLS_TRAJ_GAPS_SHOWN 4
typedef struct {
    uint64_t next;    /* the first frame asked for and not yet passed */
    uint64_t frames;  /* frames missing so far                        */
    uint64_t runs;    /* runs of them                                 */
    uint64_t a[GLS_TRAJ_GAPS_SHOWN], b[GLS_TRAJ_GAPS_SHOWN]; /* runs a..b */
} gls_traj_gaps;

/* Start at the range's first frame. */
void gls_traj_gaps_init(gls_traj_gaps *g, uint64_t first);
/* A row of the range (frames increasing). */
void gls_traj_gaps_row(gls_traj_gaps *g, uint64_t frame);
/* The range ends before end (UINT64_MAX: with the file, nothing after
 * its last row is missing). */
void gls_traj_gaps_end(gls_traj_gaps *g, uint64_t end);
/* "frames 3-4 asked for by --frames have no row in the trajectory PATH"
 * (without "glsplay: warning: "): 1, or 0 when none is missing. */
int gls_traj_gaps_message(const gls_traj_gaps *g, const char *path, char *buf, size_t len);

#endif
