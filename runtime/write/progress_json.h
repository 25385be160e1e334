/* glsplay --progress json: one JSON object a line on stderr for each
 * camera frame whose files are written, and one when the run ends, for
 * cluster logs, where a terminal line (progress.h) would be a mess of
 * carriage returns (spec/road.md "Progress and time estimate").
 *
 *   {"event": "frame", "frame": 12, "camera": "left", "done": 25, "total": 72,
 *    "elapsed_s": 8.314, "rate_fps": 3.007, "eta_s": 15.63}
 *   {"event": "end", "status": "ok", "done": 72, "total": 72, "frames": 36,
 *    "skipped": 0, "elapsed_s": 24.02, "rate_fps": 2.998}
 *
 * done, total and rate_fps count camera frames (a frame of every camera);
 * frames is the trajectory frames rendered, skipped those --resume
 * skipped.  Each line is written whole by one call, so other messages on
 * stderr (notes, errors) come as lines of their own between them. */
#ifndef GLS_PROGRESS_JSON_H
#define GLS_PROGRESS_JSON_H

#include <stdint.h>
#include <stdio.h>

typedef struct {
    FILE *f;         /* NULL: say nothing */
    uint64_t done;   /* camera frames written */
    uint64_t total;  /* camera frames to render (after --resume) */
    uint64_t cameras, skipped;
    double t0;       /* gls_now() when rendering began */
} gls_progress_json;

/* A camera frame's files are written (called by the thread that wrote
 * them), now = gls_now(). */
void gls_progress_json_frame(gls_progress_json *p, uint32_t frame, const char *camera, double now);

/* The closing line; ok: 0 when the run failed. */
void gls_progress_json_end(gls_progress_json *p, int ok, double now);

#endif
