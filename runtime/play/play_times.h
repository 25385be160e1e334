/* glsplay --times: the run's time line (load, build, pack, context,
 * upload, plan, first draw, write), printed on stderr when the run ends
 * and only when asked, so that no output, --explain's included, depends
 * on a clock. */
#ifndef GLS_PLAY_TIMES_H
#define GLS_PLAY_TIMES_H
#include <stdio.h>

/* The marks of a run, in gls_now() seconds: each stage ends at its mark
 * (0: it did not happen); pack is a duration within build (scene.h
 * pack_seconds). */
typedef struct {
    double start, load, build, pack, context, upload, plan, draw, write;
} gls_play_times;

/* "glsplay: times: load 0.012 s, build ..." on out: each stage's time
 * from the mark before it. */
void gls_play_times_print(FILE *out, const gls_play_times *t);

#endif
