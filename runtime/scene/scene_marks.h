/* Landmarks while a bundle is walked into a scene (scene_build.c): the
 * call path being walked, each call numbered #k among its caller's calls
 * of the same object, and each mark placed with its instance, position
 * and path (scene.h gls_mark).  Off, and costing nothing, for a bundle
 * without marks. */
#ifndef GLS_SCENE_MARKS_H
#define GLS_SCENE_MARKS_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"
#include "scene.h"

typedef struct {
    const gls_bundle *b;
    int on;                 /* the bundle has marks: paths are kept        */
    gls_mark *marks;
    size_t n, cap;
    char *path;             /* "Top > a.B#2 > ...", NUL-terminated        */
    size_t len, pathcap;
    uint32_t **callk;       /* per object, lazily: each call's k, in code
                               order                                      */
    uint32_t *count;        /* per object, scratch: zero between uses     */
} gls_markwalk;

/* Start at b's top object.  0, or -1 when out of memory. */
int gls_markwalk_init(gls_markwalk *m, const gls_bundle *b);
/* The k (from 1) of each CALL/CALLN of object oi, in code order; NULL
 * when out of memory. */
const uint32_t *gls_markwalk_calls(gls_markwalk *m, uint32_t oi);
/* The walk enters a call of object callee, its k-th of that object:
 * *saved is what gls_markwalk_leave needs.  0, or -1 when out of memory. */
int gls_markwalk_enter(gls_markwalk *m, uint32_t callee, uint32_t k, size_t *saved);
void gls_markwalk_leave(gls_markwalk *m, size_t saved);
/* Most landmarks a scene places (all call paths): a bound on the memory
 * a hostile bundle can ask for. */
#define GLS_SCENE_MAX_MARKS (1u << 24)

/* A mark of landmark name at p (homogeneous, in instance inst's frame)
 * on the current path.  0, -1 when out of memory, -2 when there would be
 * more than GLS_SCENE_MAX_MARKS. */
int gls_markwalk_place(gls_markwalk *m, uint32_t inst, uint32_t name, const double p[4]);
/* Hand the marks and a copy of the names to s.  0, or -1 when out of
 * memory. */
int gls_markwalk_finish(gls_markwalk *m, gls_scene *s);
void gls_markwalk_free(gls_markwalk *m);

#endif
