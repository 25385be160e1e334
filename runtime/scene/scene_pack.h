/* The last stage of building a gls_scene (scene_build.c): the walk's
 * triangles, sorted into drawing order, packed into chunks of one proto,
 * draw key and 64-unit cell (float offsets from the cell's anchor, exact
 * positions kept beside them), and the instances' draw items sorted by
 * key, instance and chunk.  Private to the scene builder. */
#ifndef GLS_SCENE_PACK_H
#define GLS_SCENE_PACK_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"

/* One triangle before chunking: its proto, draw key, cell and the
 * walk's index of its vertices. */
typedef struct {
    uint32_t proto;
    gls_drawkey key;
    int64_t cell[3];
    uint32_t zorder; /* the first vertex's place in its cell, Morton order */
    uint32_t idx; /* emission order: the final tie-break, for determinism */
} gls_pack_tri;

/* The walk's triangles and their vertices' data, by emission index:
 * positions (9 doubles a triangle, in the proto's frame), colours (12
 * bytes), texture coordinates (6 floats), and for lit scenes normals (9
 * floats) and the specular state (4 floats). */
typedef struct {
    const gls_pack_tri *tris;
    size_t ntri;
    const double *wpos;
    const uint8_t *wcol;
    const float *wtc, *wnrm, *wspec;
} gls_pack_input;

/* The largest cell level: cells of GLS_SCENE_CELL * 2^45 = 2^51 units,
 * so that every vertex within GLS_SCENE_MAX_COORD (2^50) of the origin is
 * in one of the two cells of each axis around it. */
#define GLS_PACK_MAX_LEVEL 45u

/* Sort triangles into drawing order and choose the size of the chunks'
 * cells: GLS_SCENE_CELL * 2^level, the smallest such that the triangles
 * make at most `budget` chunks (runs of one proto, key and cell), or, when
 * their protos and keys alone make more, as few as any level makes.  The
 * order: proto, key, cell of that size, the GLS_SCENE_CELL cell within it,
 * Morton order in that, emission order.  Returns the level: 0 whenever the
 * GLS_SCENE_CELL cells are within the budget (then one sort, and the
 * order and chunks are those of cells of GLS_SCENE_CELL).  Why a count:
 * scattered triangles (a particle field, a terrain over kilometres, the
 * random bench scene) fill one cell each, a draw each; the budget bounds
 * the draws, whatever the distribution. */
unsigned gls_pack_sort(gls_pack_tri *t, size_t n, size_t budget);
/* Chunks, vertices and the protos' and scene's boxes from the sorted
 * triangles (s's layout, protos and instances set, s->cell_level the level
 * gls_pack_sort chose).  0, or -1 when out of memory. */
int gls_pack_chunks(const gls_pack_input *w, gls_scene *s);
/* The scene's exact positions (gls_scene.exact: 9 doubles a triangle, in
 * drawing order) from the walk's (wpos, 9 doubles a triangle in emission
 * order) in place, t sorted: wpos becomes them, with no second array of
 * them (7 MB a 100,000-triangle scene, issue 30's fresh pages).  After
 * gls_pack_chunks, which reads wpos in emission order.  0, or -1 when out
 * of memory (wpos then unchanged). */
int gls_pack_exact(double *wpos, const gls_pack_tri *t, size_t n);
/* Items of every instance with geometry, sorted into drawing order.  0,
 * -1 when out of memory, -2 when there would be more than
 * GLS_SCENE_MAX_ITEMS. */
int gls_pack_items(gls_scene *s);

#endif
