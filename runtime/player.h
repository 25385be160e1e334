/* The player as a library: what glsplay does, callable from tests and,
 * later, from a Python binding or a trajectory driver. */
#ifndef GLS_PLAYER_H
#define GLS_PLAYER_H

#include <stdint.h>
#include <stdio.h>
#include "bundle.h"
#include "camera.h"
#include "scene.h"

enum { GLS_OUT_IMAGE = 1, GLS_OUT_DEPTH = 2, GLS_OUT_POINTS = 4 };

typedef struct {
    const char *bundle;          /* path of the .glsb                    */
    const char *const *cameras;  /* camera file paths                    */
    size_t ncameras;
    const char *outdir;          /* NULL: nothing is rendered            */
    unsigned outputs;            /* GLS_OUT_* bits                       */
    uint32_t width, height;      /* --size override, 0 = the camera's    */
    int explain;                 /* print the plan first                 */
    uint32_t frame;              /* frame number in the file names       */
} gls_play_opts;

/* Run the player.  Messages go to errs as "glsplay: error: ..." lines,
 * the plan to out.  Returns the exit status: 0 done, 1 input error. */
int gls_play(const gls_play_opts *o, FILE *out, FILE *errs);

/* Print the plan (explain.c): which GL effects are on and why, passes,
 * read-backs.  cams/names may be empty (n = 0). */
void gls_explain(FILE *out, const char *bundle_path, const gls_bundle *b, const gls_scene *s,
                 const gls_camera *cams, const char *const *names, size_t n, unsigned outputs);

/* Output file name: OUTDIR/NAME/KIND_%06u.EXT (frame numbers grow past
 * six digits without breaking).  Returns 0, -1 if it does not fit. */
int gls_output_path(char *buf, size_t len, const char *outdir, const char *name, const char *kind,
                    uint32_t frame, const char *ext);

#endif
