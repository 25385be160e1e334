/* A bundle flattened for drawing: every primitive of the top object's
 * call tree, triangulated, transformed to world coordinates in double
 * precision, and stored as float offsets from a per-chunk double anchor.
 *
 * Why chunks: GL works in float.  A vertex 1e7 units from the origin has a
 * float spacing of 1 unit, so world coordinates cannot go to GL as they
 * are.  Each chunk holds the triangles of one GLS_SCENE_CELL-sized cube of
 * space; its anchor is the cube's centre, so offsets stay below about one
 * cell (float error <= 2^-24 * offset).  Per frame the renderer forms the
 * chunk's modelview in double, camera-relative (camera.h), and only then
 * converts it to float.  A float offset errs by up to 2^-24 of its size,
 * which matters only for geometry much closer to the camera than the
 * chunk's size: the renderer re-anchors such chunks at the camera centre
 * each frame (render.c), so the error stays ~2^-24 of the distance.
 * Anchors are multiples of the cell size plus half a
 * cell, so translating a whole scene (and its camera) by a multiple of the
 * cell size changes no float that GL sees: the output is byte-identical.
 */
#ifndef GLS_SCENE_H
#define GLS_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"

/* Edge of a chunk cell in scene units: a power of two, so anchors and
 * cell indices are exact in binary floating point. */
#define GLS_SCENE_CELL 64.0

/* Farthest a vertex may be from the world origin, after its transforms
 * (2^50, about 1e15 units; the double spacing there is 1/8 unit).
 * Vertices beyond it are dropped with their triangles. */
#define GLS_SCENE_MAX_COORD 1125899906842624.0

/* Drawing state shared by all triangles of a batch. */
typedef struct {
    uint32_t texture;      /* texture index, or GLS_NONE (texturing off)  */
    uint8_t mode;          /* GLS_MODE_*; GLS_MODE_COLOR iff no texture   */
    uint8_t rgba[4];       /* colour, when vertices carry none            */
} gls_drawkey;

typedef struct {
    double anchor[3];      /* world position the offsets are relative to  */
    double lo[3], hi[3];   /* bounding box of the chunk's vertices        */
    double maxoff;         /* largest |vertex - anchor| (any axis)        */
    gls_drawkey key;
    uint32_t first, count; /* vertex range in gls_scene.verts             */
} gls_chunk;

typedef struct {
    uint32_t features;     /* the bundle's GLS_FEAT_* bits                */
    int has_color;         /* vertices carry RGBA8 colours                */
    int has_texcoord;      /* vertices carry float s, t                   */
    size_t stride;         /* bytes per vertex: 12 [+4 colour] [+8 st]    */
    size_t color_offset, texcoord_offset;
    uint8_t *verts;        /* nverts * stride bytes, GL_TRIANGLES order   */
    double *world;         /* nverts * 3: exact world positions, for
                              re-anchoring chunks near the camera         */
    uint32_t nverts;
    gls_chunk *chunks;     /* sorted by key, then cell                    */
    uint32_t nchunks;
    uint32_t nbatches;     /* runs of chunks with equal keys              */
    uint64_t dropped;      /* triangles with a vertex at infinity (w = 0) */
    double lo[3], hi[3];   /* world bounding box of the vertices          */
} gls_scene;

/* Flatten b (which must be validated and have a top object).  Returns 0,
 * or -1 with a message in err (out of memory, too many vertices). */
int gls_scene_flatten(const gls_bundle *b, gls_scene *s, char *err, size_t errlen);
void gls_scene_free(gls_scene *s);

#endif
