/* A bundle prepared for drawing: each object's own geometry once
 * (a "proto", in the object's frame), and an instance table with one
 * entry per call path (an object and a double-precision transform).
 *
 * Instances: the top object is instance 0 (identity); every `call` whose
 * transform is affine adds an instance of the callee, child of the
 * caller's instance.  A proto is an object entered with one drawing state
 * (colour, texture, mode): a tree called 10,000 times with the same state
 * is one proto and 10,000 instances.  A call whose matrix is projective
 * (a TRANSFORM with a bottom row other than 0 0 0 1) is inlined into the
 * caller's proto instead: its vertices are divided by w after the whole
 * transform, which a per-instance matrix in GL cannot reproduce exactly.
 * gls_scene_flatten() inlines every call (the reference path: one proto,
 * one instance, the world-space triangles of the previous player).
 *
 * Why chunks: GL works in float.  A vertex 1e7 units from the origin has a
 * float spacing of 1 unit, so coordinates cannot go to GL as they are.
 * Each chunk holds the triangles of one GLS_SCENE_CELL-sized cube of its
 * proto's space (a cube 2^cell_level times as large when the triangles
 * are so scattered that more than GLS_SCENE_CHUNK_BUDGET chunks would
 * draw them); its anchor is the cube's centre, so offsets stay below
 * about one cell (float error <= 2^-24 * offset).  Per frame the renderer
 * forms each drawn (instance, chunk) item's modelview in double,
 * camera-relative (camera.h: R * (W * anchor) + T, the large terms
 * cancelling in double), and only then converts it to float.  Items much
 * closer to the camera than their size are re-anchored at the camera
 * centre each frame (render.c).  Anchors are multiples of the cell size
 * plus half a cell, so translating a whole scene (and its camera) by a
 * multiple of the cell size (GLS_SCENE_CELL * 2^cell_level) changes no
 * float that GL sees.
 */
#ifndef GLS_SCENE_H
#define GLS_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"

/* Edge of a chunk cell in scene units: a power of two, so anchors and
 * cell indices are exact in binary floating point. */
#define GLS_SCENE_CELL 64.0
/* Chunks a scene's protos make at most, where their protos and drawing
 * states allow (scene_pack.h gls_pack_sort): past it, cells grow by
 * powers of two.  A scene drawn as one instance draws at most this many
 * items a frame; instances multiply their protos' chunks, and are culled
 * whole first (scene_cull.c).  4,096: issue 30's budget of a few thousand
 * draws a frame. */
#define GLS_SCENE_CHUNK_BUDGET 4096u
/* Sub-cells per axis of a cell, for the drawing order within it
 * (scene_build.c cell_zorder): 10 bits per axis, a 30-bit Morton code. */
#define GLS_SCENE_SUBCELLS 1024.0

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
    float area;            /* its triangles' area, summed, in the proto's
                              frame: occlusion culling's model of how much
                              of the image the chunk covers (occlusion.c);
                              a float, in the struct's padding            */
} gls_chunk;

/* A box in a proto's frame (scene_test_boxes.c). */
typedef struct {
    double lo[3], hi[3];
} gls_tbox;
/* Test boxes a proto has at most (scene_test_boxes.c). */
#define GLS_PROTO_TEST_BOXES 8
/* Geometry of one object entered with one drawing state. */
typedef struct {
    uint32_t object;       /* bundle object index                          */
    uint32_t first_chunk, nchunks; /* its chunks, sorted by key then cell */
    uint32_t ntris;
    double lo[3], hi[3];   /* bounding box in the proto's frame (double)   */
    uint32_t first_tbox, ntboxes; /* its test boxes in gls_scene.tboxes:
                              their union holds its triangles, more
                              tightly than lo..hi (scene_test_boxes.c)         */
    /* build only: the drawing state it was entered with (texture and
     * mode as they were, not normalised: an object that selects a
     * texture itself draws it in the mode it inherits), next proto of
     * the same object */
    uint8_t rgba[4];
    double spec[4];        /* the specular state (lit scenes)             */
    uint32_t texture, mode, next;
} gls_proto;

/* Longest instance name (spec/language.md: at most 64 bytes). */
#define GLS_INSTANCE_NAME_MAX 64

/* One call path.  world = parent's world * local * motion (motion: the
 * identity unless --motion moves a named instance, gls_scene_move). */
typedef struct {
    uint32_t proto;        /* its geometry, GLS_NONE if it draws nothing   */
    uint32_t object;       /* the bundle object called (the top's: top)    */
    uint32_t parent;       /* GLS_NONE for the top (instance 0)            */
    double local[16];      /* call-site transform in the parent's frame    */
    double motion[16];     /* per frame, object-to-parent (--motion)       */
    double world[16];      /* composed, row-major, affine                  */
    double lo[3], hi[3];   /* world box of its geometry (from the proto's) */
    double scale;          /* max row sum |W[i][0..2]|: float error growth */
    char *name;            /* NULL, or its name (gls_scene_name_instance)  */
    uint32_t first_item, nitems; /* its draw items, by key then cell      */
} gls_instance;

/* A landmark (a bundle's mark) as placed by one call path: its name (an
 * index into gls_scene.marknames), the instance whose frame it is in, its
 * position in that frame (the mark's matrix applied, homogeneous), and its
 * call path, "Top > a.B#2 > c.D#1": each call as the callee's name and
 * #k, the k-th call of that object in its caller's code, from 1
 * (spec/outputs.md "Landmarks"). */
typedef struct {
    uint32_t name, inst;
    double p[4];
    char *path;
} gls_mark;

/* A light (a bundle's light instruction, spec/bundle.md 9.2) as placed
 * by one call path: its kind, the instance whose frame it is in, and
 * M (x, y, z, w) in that frame, w = 0 for a direction (towards the
 * light), 1 for a point light's position; unused for ambient. */
typedef struct {
    uint32_t kind, inst;   /* gls_lightkind; instance index               */
    double p[4];
    double rgb[3], atten;  /* linear colour; point lights: 1/(1 + k d^2)  */
} gls_light;

/* Lights shaded at once (GLSL uniform arrays); ambient lights are summed
 * and do not count.  A scene with more is refused at load. */
#define GLS_MAX_LIGHTS 8

/* What the renderer draws: a chunk of an instance's proto. */
typedef struct {
    uint32_t inst, chunk;
    double lo[3], hi[3];   /* world box of the chunk under the instance   */
} gls_item;

/* Limits of the instanced form (spec/bundle.md section 10), checked as
 * the bundle is walked, so that load time and memory follow unique
 * geometry and the instance table:
 * - instances: call paths, each ~600 bytes with its draw items; the
 *   validator's bound on a top's call paths (GLS_MAX_CALL_PATHS);
 * - unique vertices: about 140 bytes each at the peak of a load (180 in
 *   a lit scene), so 2^28 of them is up to about 36 GiB (48 GiB lit);
 * - instructions decoded (each object once per drawing state it is
 *   entered with, every later entry replayed from a record, scene_build.c;
 *   an inlined call's callee once per call): 2^28 of them take 3 s
 *   (colours) to 17 s (rotations) on the 2-core reference machine;
 * - lights on all call paths (each shaded light is one of the 8 of
 *   GLS_MAX_LIGHTS, ambient ones are summed);
 * - draw items (each instance times its proto's chunks, 56 bytes each,
 *   culled every frame): 2^26 of them are 3.5 GiB. */
#define GLS_SCENE_MAX_INSTANCES GLS_MAX_CALL_PATHS
#define GLS_SCENE_MAX_VERTS (1u << 28)
#define GLS_SCENE_MAX_WALK (1u << 28)
#define GLS_SCENE_MAX_PLACED_LIGHTS (1u << 16)
#define GLS_SCENE_MAX_ITEMS (1u << 26)

typedef struct {
    uint32_t features;     /* the bundle's GLS_FEAT_* bits                */
    int has_color;         /* vertices carry RGBA8 colours                */
    int has_texcoord;      /* vertices carry float s, t                   */
    size_t stride;         /* bytes per vertex: 12 [+4 colour] [+8 st]
                              [+12 normal +16 specular, lit scenes]       */
    size_t color_offset, texcoord_offset;
    int lit;               /* the bundle has GLS_FEAT_LIGHTS: vertices carry
                              a normal (float x 3: unit for a given one,
                              length 2 for a flat one, which the shader
                              turns to face the camera) and the specular
                              colour and exponent (float x 4)             */
    size_t normal_offset, specular_offset;
    gls_light *lights;     /* every light on every call path, walk order  */
    uint32_t nlights;
    uint32_t shadow_res;   /* shadow map side (the largest shadows(...)
                              the walk met), 0: no shadows; used only when
                              lit                                         */
    uint8_t *verts;        /* nverts * stride bytes, GL_TRIANGLES order   */
    double *exact;         /* nverts * 3: exact positions in the proto's
                              frame, for re-anchoring near the camera     */
    uint32_t nverts;
    gls_chunk *chunks;     /* per proto, sorted by key, then cell        */
    unsigned cell_level;   /* the chunks' cells are GLS_SCENE_CELL *
                              2^cell_level units (scene_pack.h)           */
    uint32_t nchunks;
    uint32_t nbatches;     /* distinct draw keys                          */
    gls_proto *protos;
    uint32_t nprotos;
    gls_tbox *tboxes;      /* the protos' test boxes (occlusion culling)  */
    uint32_t ntboxes;
    gls_instance *inst;
    uint32_t ninst;
    gls_item *items;       /* all instances' items, in drawing order:
                              by key, then instance, then cell            */
    uint32_t nitems;
    gls_mark *marks;       /* landmarks, in the order the walk placed them */
    uint32_t nmarks;
    char **marknames;      /* the bundle's landmark names                 */
    uint32_t nmarknames;
    int moving;            /* some instance has a motion (gls_scene_move)  */
    uint64_t dropped;      /* triangles with a vertex at infinity (w = 0) */
    double pack_seconds;   /* the packing's time (scene_pack.h: sort,
                              chunks, test boxes, items), for glsplay
                              --times; never in an output              */
    int no_cull;           /* 1: gls_scene_cull marks everything visible:
                              only for measuring what culling saves
                              (bench/instances_bench --no-cull); 0 after
                              load */
    double lo[3], hi[3];   /* bounding box of the unique vertices        */
} gls_scene;

/* Build the instanced scene of b (validated, with a top object): what
 * the player draws.  Vertices always carry a colour, so that colour
 * changes do not split draws; keys are texture and mode only.  0, or -1
 * with a message in err (out of memory, a limit above). */
int gls_scene_load(const gls_bundle *b, gls_scene *s, char *err, size_t errlen);
/* The same with every call inlined into one proto drawn once (the
 * flattened reference path; colours in keys when vertices carry none). */
int gls_scene_flatten(const gls_bundle *b, gls_scene *s, char *err, size_t errlen);
void gls_scene_free(gls_scene *s);

/* Give instance i a name (the seam for named calls: the bundle's CALLN
 * names one call site, which is exactly one instance).  0, or -1 if i is
 * out of range, the name is invalid or another instance has it. */
int gls_scene_name_instance(gls_scene *s, uint32_t i, const char *name);
/* The instance named name, or GLS_NONE. */
uint32_t gls_scene_find_instance(const gls_scene *s, const char *name);
/* Set instance i's motion (object-to-parent, row-major R and T) for the
 * next frames; R = NULL resets it to the identity.  Then
 * gls_scene_update() recomputes world transforms and boxes. */
void gls_scene_move(gls_scene *s, uint32_t i, const double R[9], const double T[3]);
void gls_scene_update(gls_scene *s);

/* World position of landmark k in the current frame: its instance's
 * world transform (motion included) applied, divided by w, in double. */
void gls_scene_mark_world(const gls_scene *s, uint32_t k, double X[3]);

/* The protos' test boxes (scene_test_boxes.c), once chunks are packed.  0,
 * or -1 when out of memory. */
int gls_scene_test_boxes(gls_scene *s);
/* Memory: unique geometry (vertices, exact positions, chunks, protos) and
 * the instance table (instances, items, names). */
void gls_scene_memory(const gls_scene *s, uint64_t *geometry, uint64_t *table);

#endif
