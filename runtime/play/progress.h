/* A sequence's frame-level progress line, and the one-line estimate of a
 * long render's time (spec/road.md "Progress and time estimate").
 * Both write to a FILE* given by the caller, so they are unit-tested
 * without a terminal; the player passes stderr only when it is one
 * (progress) or always (the estimate, printed once and only when the
 * render will take long). */
#ifndef GLS_PROGRESS_H
#define GLS_PROGRESS_H

#include <stdint.h>
#include <stdio.h>
#include "progress_line.h"

/* Renders projected to take longer than this get the estimate line. */
#define GLS_ESTIMATE_THRESHOLD_S 60.0

/* "\rglsplay: frame 12/500 (2%), 3.10 frames/s, 2 min 37 s left   "
 * after `done` of `total` frames in `elapsed` seconds; with final set,
 * "\rglsplay: 500 frames in 2 min 41 s, 3.10 frames/s" and a newline. */
void gls_progress_frames(FILE *f, uint64_t done, uint64_t total, double elapsed, int final);

/* The projected time of a whole render from a measurement: `elapsed`
 * seconds for the first `done` units (anti-aliasing passes, or whole
 * camera frames), `per_view` units in each camera frame, `views` camera
 * frames (cameras x frames) to render in all. */
double gls_estimate_total(double elapsed, uint64_t done, uint64_t per_view, uint64_t views);

/* Print the estimate line to f if the projection exceeds
 * GLS_ESTIMATE_THRESHOLD_S; 1 if printed.
 * per_view > 1: the units are anti-aliasing passes; 1: whole camera frames. */
int gls_estimate_report(FILE *f, double elapsed, uint64_t done, uint64_t per_view, uint64_t views);
/* The same with the anti-aliasing steps named: "passes" (jittered GL
 * passes), "tiles" (tiles of the one-pass fine framebuffer). */
int gls_estimate_report_units(FILE *f, double elapsed, uint64_t done, uint64_t per_view, uint64_t views,
                              const char *units);

#endif
