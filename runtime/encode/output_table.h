/* The output vocabulary (spec/outputs.md): one bit per file an output
 * makes, the words --outputs takes for them, and the formats of the image
 * and float files.  Below the writer and the player, so that every room
 * that names an output (the encoders, the writer, the plan, explain, the
 * library) takes it from here. */
#ifndef GLS_OUTPUT_TABLE_H
#define GLS_OUTPUT_TABLE_H

#include <stddef.h>

/* What an output needs of the frame (the frame plan, frame_plan.h, takes
 * its passes from these): the image's colour (anti-aliased or the centre
 * pass's), the mixed-pixel map, the centre pass's depth or colour, the
 * ground-truth pass's ids or normals, the next frame (flow), each visible
 * instance drawn alone (boxes). */
enum {
    GLS_NEED_COLOUR = 1,
    GLS_NEED_MIXED = 2,
    GLS_NEED_Z = 4,
    GLS_NEED_RGBA = 8,
    GLS_NEED_IDS = 16,
    GLS_NEED_NORMALS = 32,
    GLS_NEED_NEXT = 64,
    GLS_NEED_ALONE = 128,
    GLS_NEED_COVER = 256, /* exact coverage's areas per id (--aa exact) */
    GLS_NEED_SEGS = 512   /* exact coverage's edge segments (--aa exact) */
};

/* The outputs, one row per kind of file a camera frame writes, in the
 * order they are written (spec/outputs.md):
 *   X(ID, WORD, STEM, EXT, NEEDS, WITH, LISTED, WHAT, KEY)
 * ID: GLS_OUT_ID, the file's bit; WORD: the --outputs word that writes it
 * (a word with several files has a row each; NULL: written with the words
 * of WITH); STEM and EXT: the file OUTDIR/CAMERA/STEM_FRAME.EXT (EXT NULL:
 * the float format, .pfm or .npy); NEEDS: GLS_NEED_* bits; LISTED: --help
 * and messages list the word (mask, edges' old name, is taken for one
 * release but not listed); WHAT: what the file holds, as --explain's
 * "files:" line says it; KEY: the name the library's result gives the
 * file's array (glscene_result_array, include/glscene.h: the stem, or
 * the stem and what sets it apart where two files share one; flow is
 * the u v floats the .flo holds).  Everything else follows from the rows: the
 * bits, the words and what each writes, the groups below, the file names,
 * the frame record's outputs line, the plan's passes.  A new output is a
 * row here and its encoder (frame_files.c). */
#define GLS_OUTPUTS(X)                                                                                              \
    X(IMAGE, "image", "image", "png", GLS_NEED_COLOUR, 0, 1,                                                        \
      "the image", "image")                                                                                         \
    X(DEPTH, "depth", "depth", NULL, GLS_NEED_Z, 0, 1,                                                              \
      "Zc, float32", "depth")                                                                                       \
    X(POINTS, "points", "points", "ply", GLS_NEED_Z | GLS_NEED_RGBA, 0, 1,                                          \
      "the surface at each pixel centre, world frame, double", "points")                                            \
    X(EDGES, "edges", "edges", "png", GLS_NEED_COLOUR | GLS_NEED_MIXED, 0, 1,                                       \
      "255 where the samples of a pixel differ", "edges")                                                           \
    X(EDGES_AS_MASK, "mask", "mask", "png", GLS_NEED_COLOUR | GLS_NEED_MIXED, 0, 0,                                 \
      "edges under its old name", "mask")                                                                           \
    X(DISPARITY, "disparity", "disparity", NULL, GLS_NEED_Z, 0, 1,                                                  \
      "fx B / Zc, float32", "disparity")                                                                            \
    X(DISPARITY16, "disparity16", "disparity16", "png", GLS_NEED_Z, 0, 1,                                           \
      "KITTI disparity, d * 256", "disparity16")                                                                    \
    X(DEPTH16, "depth16", "depth16", "png", GLS_NEED_Z, 0, 1,                                                       \
      "Zc * the depth scale", "depth16")                                                                            \
    X(LANDMARKS, "landmarks", "landmarks", "csv", GLS_NEED_Z, 0, 1,                                                 \
      "the scene's marks projected, visible or not", "landmarks")                                                   \
    X(INSTANCE, "instance", "instance", "png", GLS_NEED_IDS, 0, 1,                                                  \
      "instance ids, 16-bit", "instance")                                                                           \
    X(CLASS, "class", "class", "png", GLS_NEED_IDS, 0, 1,                                                           \
      "class ids, 16-bit", "class")                                                                                 \
    X(INSTANCES_JSON, NULL, "instances", "json", GLS_NEED_IDS, GLS_OUT_INSTANCE | GLS_OUT_CLASS, 0,                 \
      "the table of instance and class ids", "instances")                                                           \
    X(COCO, "coco", "coco", "json", GLS_NEED_IDS, 0, 1,                                                             \
      "COCO annotations, run-length masks", "coco")                                                                 \
    X(NORMALS, "normals", "normals", NULL, GLS_NEED_NORMALS, 0, 1,                                                  \
      "world normals, 3 x float32", "normals")                                                                      \
    X(FLOW, "flow", "flow", "png", GLS_NEED_IDS | GLS_NEED_NEXT, 0, 1,                                              \
      "KITTI flow to the next frame", "flow_kitti")                                                                 \
    X(FLOW_FLO, "flow", "flow", "flo", GLS_NEED_IDS | GLS_NEED_NEXT, 0, 1,                                          \
      "Middlebury flow to the next frame", "flow")                                                                  \
    X(FLOW_MASK, "flow", "flowmask", "png", GLS_NEED_IDS | GLS_NEED_NEXT, 0, 1,                                     \
      "visible, occluded, out of view", "flowmask")                                                                 \
    X(BOXES, "boxes", "boxes", "txt", GLS_NEED_IDS | GLS_NEED_ALONE, 0, 1,                                          \
      "KITTI object labels", "boxes")                                                                               \
    X(BOXES_JSON, "boxes", "boxes", "json", GLS_NEED_IDS | GLS_NEED_ALONE, 0, 1,                                    \
      "the boxes as JSON", "boxes_json")                                                                            \
    X(COVERAGE, "coverage", "coverage", "csv", GLS_NEED_COVER, 0, 1,                                                \
      "each instance's exact visible area in each pixel (--aa exact)", "coverage")                                  \
    X(EDGE_SEGMENTS, "edge_segments", "edge_segments", "csv", GLS_NEED_SEGS, 0, 1,                                  \
      "the visible edges as exact sub-pixel segments, the instance on each side (--aa exact)", "edge_segments")

enum {
#define X(id, word, stem, ext, needs, with, listed, what, key) GLS_OUT_I_##id,
    GLS_OUTPUTS(X)
#undef X
        GLS_OUT_KINDS
};
enum {
#define X(id, word, stem, ext, needs, with, listed, what, key) GLS_OUT_##id = 1u << GLS_OUT_I_##id,
    GLS_OUTPUTS(X)
#undef X
};
_Static_assert(GLS_OUT_KINDS <= 32, "one bit an output kind in an unsigned");

/* the outputs made from the mixed-pixel map, from the centre pass's depth,
 * from the ground-truth pass's instance ids (flow and boxes too: they are
 * ids as well), the files of flow and of boxes */
#define GLS_OUT_EDGE_MAPS (GLS_OUT_EDGES | GLS_OUT_EDGES_AS_MASK)
#define GLS_OUT_DISPARITIES (GLS_OUT_DISPARITY | GLS_OUT_DISPARITY16)
#define GLS_OUT_IF_Z_(id, word, stem, ext, needs, with, listed, what, key) | (((needs) & GLS_NEED_Z) ? GLS_OUT_##id : 0u)
#define GLS_OUT_FROM_Z (0u GLS_OUTPUTS(GLS_OUT_IF_Z_))
#define GLS_OUT_IDS (GLS_OUT_INSTANCE | GLS_OUT_CLASS | GLS_OUT_INSTANCES_JSON | GLS_OUT_COCO)
#define GLS_OUT_FLOW_ALL (GLS_OUT_FLOW | GLS_OUT_FLOW_FLO | GLS_OUT_FLOW_MASK)
#define GLS_OUT_BOXES_ALL (GLS_OUT_BOXES | GLS_OUT_BOXES_JSON)
/* the outputs only exact coverage makes (refused without --aa exact), and
 * the word a refusal names: the first of them asked */
#define GLS_OUT_EXACT_ONLY (GLS_OUT_COVERAGE | GLS_OUT_EDGE_SEGMENTS)
#define GLS_OUT_EXACT_WORD(outputs) ((outputs) & GLS_OUT_COVERAGE ? "coverage" : "edge_segments")

/* One row of the table, as data. */
typedef struct {
    unsigned bit;      /* GLS_OUT_*                                     */
    const char *word;  /* --outputs word, NULL: written with `with`    */
    const char *stem;  /* file name: STEM_FRAME.EXT                     */
    const char *ext;   /* NULL: the float format                        */
    unsigned needs;    /* GLS_NEED_*                                    */
    unsigned with;     /* written when any of these is asked            */
    int listed;        /* --help and messages list the word             */
    const char *what;  /* what the file holds (--explain)               */
    const char *key;   /* its array's name in the library's result      */
} gls_output_kind;
extern const gls_output_kind gls_output_kinds[GLS_OUT_KINDS];

/* The bits of every row a --outputs word writes (0: no such word), with
 * the rows written with them (the instances' JSON table). */
unsigned gls_output_word_bits(const char *word, size_t len);
/* bits and the rows written with them (the instances' JSON table with
 * instance or class): what a set of outputs asked for writes. */
unsigned gls_outputs_with(unsigned bits);
/* The listed words, once each, in the table's order: words[0..n), n
 * returned (at most cap); with unlisted, the unlisted after them. */
size_t gls_output_words(const char **words, size_t cap, int unlisted);

/* depth16's scale by default: KITTI's metres * 256 (TUM's is 5000) */
#define GLS_DEPTH_SCALE_KITTI 256.0
#define GLS_DEPTH_SCALE_TUM 5000.0

/* Format of the float outputs (depth, disparity, normals, the image with
 * --image-format pfm): PFM, or NumPy .npy (out_npy.h). */
typedef enum { GLS_FLOAT_PFM = 0, GLS_FLOAT_NPY = 1 } gls_float_format;
/* Image file format: 8-bit PNG, 16-bit PNG, float32 PFM ("PF", RGB). */
typedef enum { GLS_IMG_PNG8 = 0, GLS_IMG_PNG16 = 1, GLS_IMG_PFM = 2 } gls_image_format;

#endif
