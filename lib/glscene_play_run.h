/* What glscene_play.c (a run: its life, its checks, the run itself) and
 * glscene_play_args.c (glsplay's options, one table) share: the run's
 * state and its failure and string keeping.  Not installed. */
#ifndef GLSCENE_PLAY_RUN_H
#define GLSCENE_PLAY_RUN_H
#include "glscene.h"
#include "player.h"

struct glscene_play {
    gls_play_opts o;     /* what gls_play runs; its strings are copies  */
    char **strs;         /* the copies, freed with the run              */
    size_t nstrs, strs_cap;
    const char **cams, **mots; /* o.cameras, o.motions                  */
    size_t cams_cap, mots_cap;
    const char **texts;  /* o.camera_texts: one a camera, NULL for a file */
    size_t texts_cap;
    int frames;          /* --frames given (needs --trajectory)         */
    double subpixel;     /* --subpixel A, 0: not given                  */
    int have_aa, have_samples;
    int checked;         /* glscene_play_check passed since the last arg */
    int rendering;       /* checked for glscene_play_render: no -o needed */
    char *msg;           /* the last failure's whole message            */
    /* glscene_play_render's open run (player.h gls_play_begin): kept
     * while the settings stay the same, so the frames after the first
     * reuse its bundle, context and uploaded scene; closed by a change
     * of setting (gls_play_close_run), a failed render, or the free */
    gls_play_run *run;
};

/* End the open run, if any: the next glscene_play_render begins again. */
void gls_play_close_run(glscene_play *r);

/* Keep the whole message in r->msg (glscene_play_message) and as much as
 * fits in e; returns rc. */
__attribute__((format(printf, 4, 5))) int gls_play_fail(glscene_play *r, glscene_error *e, int rc, const char *fmt,
                                                          ...);
/* Add a camera: a file's path (text NULL), or a name and a camera file's
 * text.  0, or -1 with e (out of memory). */
int gls_play_add_camera(glscene_play *r, glscene_error *e, const char *path, const char *text);
/* A copy of s that lives as long as r; NULL (with e) when out of memory. */
char *gls_play_keep(glscene_play *r, glscene_error *e, const char *s);
#endif
