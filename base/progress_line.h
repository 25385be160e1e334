/* The monotonic clock, and the progress line of a long job inside one
 * camera frame (anti-aliasing samples or tiles).  In base/ because the
 * rooms that run such jobs (aa/) sit below the player, which owns the
 * frame-level progress (runtime/play/progress.h). */
#ifndef GLS_PROGRESS_LINE_H
#define GLS_PROGRESS_LINE_H

#include <stdint.h>
#include <stdio.h>

/* Monotonic clock, seconds. */
double gls_now(void);

/* An anti-aliased camera frame's progress line, at most every 0.5 s
 * (*last: when it was last printed; final: always, with a newline):
 * "\rglsplay: NAME: 12/256 samples (5%), 3 s left   " (units "samples",
 * or "tiles" for the one-pass renderer).  Nothing if f is NULL. */
void gls_progress_steps(FILE *f, const char *label, const char *units, uint64_t done, uint64_t total, double t0,
                        double *last, int final);

#endif
