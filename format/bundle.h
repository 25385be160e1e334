/* The in-memory form of a glscene bundle, shared by the compiler (which
 * builds one and writes it) and the player (which reads and validates one).
 *
 * The file layout is in spec/bundle.md.  A gls_bundle that came out of
 * gls_bundle_read() has been validated completely: every index, count and
 * operand in it is in range, every number finite, push/pop balanced, the
 * call graph acyclic and within the depth limits.  Code that walks a read
 * bundle may rely on that and need not re-check.
 */
#ifndef GLS_BUNDLE_H
#define GLS_BUNDLE_H

#include <stddef.h>
#include <stdint.h>
#include "buf.h"
#include "opcodes.h"

#define GLS_FORMAT_VERSION 2u

/* Feature flags: which effects a bundle's content uses.  Computed from the
 * content by gls_bundle_features(), never set by hand, so they cannot lie. */
#define GLS_FEATURES(X)                                                     \
    X(TEXTURES,     0, "textures",      "the scene selects a texture")              \
    X(ALPHA_TEST,   1, "alpha-test",    "a selected texture has transparent texels") \
    X(VERTEX_COLOR, 2, "vertex-color",  "some primitive has per-vertex colours")  \
    X(TEXCOORDS,    3, "texcoords",     "some primitive has texture coordinates") \
    X(HOMOGENEOUS,  4, "homogeneous-w", "some vertex has w != 1")                 \
    X(MODULATE,     5, "modulate",      "texture mode modulate is used")          \
    X(REPLACE,      6, "replace",       "texture mode replace is used")           \
    X(TRANSLUCENT,  7, "translucent",   "some colour has alpha < 1 (recorded; drawn opaque)") \
    X(MARKS,        8, "marks",         "some object places a landmark (mark; draws nothing)") \
    X(LIGHTS,       9, "lights",        "some object declares a light (light, ambient): shaded per pixel") \
    X(SHADOWS,     10, "shadows",       "some object asks for shadows (shadows): directional and point lights cast them")

enum {
#define GLS_X_FEAT(e, bit, name, why) GLS_FEAT_##e = 1u << (bit),
    GLS_FEATURES(GLS_X_FEAT)
#undef GLS_X_FEAT
};
extern const char *const gls_feature_name[32];
extern const char *const gls_feature_why[32];

/* Limits enforced by the validator (and by the compiler, with its own
 * located messages).  See spec/bundle.md "Limits". */
#define GLS_MAX_FILE_BYTES        (1ull << 32)   /* 4 GiB bundle          */
/* decompressed sections, each and in total; a build may lower it
 * (-DGLS_MAX_SECTION_RAW=...: tests/unit/test_bundle_limit.c's reader,
 * whose sections can then add up past it without gigabytes) */
#ifndef GLS_MAX_SECTION_RAW
#define GLS_MAX_SECTION_RAW       (1ull << 32)
#endif
#define GLS_MAX_OBJECTS           (1u << 20)
#define GLS_MAX_TEXTURES          (1u << 16)
#define GLS_MAX_VERTICES          (1u << 28)     /* per bundle            */
#define GLS_MAX_PRIM_VERTICES     (1u << 24)     /* per primitive         */
#define GLS_MAX_TEXTURE_DIM       16384u         /* llvmpipe's GL limit   */
#define GLS_MAX_TEXELS            (1ull << 26)   /* per texture: 256 MiB  */
#define GLS_MAX_PUSH_DEPTH        64u            /* per object            */
#define GLS_MAX_CALL_DEPTH        256u           /* nested calls          */
#define GLS_MAX_NAME_BYTES        1024u
#define GLS_MAX_PARAMS            32u            /* per template          */
#define GLS_MAX_TEMPLATE_TEXT     (1u << 30)     /* source text, bytes    */
#define GLS_MAX_INSTANCE_NAME_BYTES 64u          /* an instance's name    */
#define GLS_MAX_MARK_NAME_BYTES   64u            /* a landmark's name     */
/* Vertices the top-level object draws once every call is unrolled: calls
 * share objects, so a small bundle can describe an exponentially large
 * scene (A calls B twice, B calls C twice, ...).  2^26 vertices is about
 * 1.5 GiB in the flattened form (glsplay --flatten), which refuses more;
 * bundles are bounded by their call paths instead. */
#define GLS_MAX_EXPANDED_VERTICES (1ull << 26)
/* Call paths from the top-level object (the top itself included): each
 * is at most one instance of the player's instanced form, which keeps
 * the objects' geometry once, so this, not the vertices once unrolled,
 * bounds a bundle.  2^22 instances are about 2.5 GiB in the player. */
#define GLS_MAX_CALL_PATHS (1u << 22)

typedef struct {
    double x, y, z, w;
} gls_vec4;

typedef struct {
    float r, g, b, a;
} gls_rgba;

typedef struct {
    float s, t;
} gls_st;

/* A unit normal (primn, section NORMALS). */
typedef struct {
    float x, y, z;
} gls_nrm;

/* Where an instruction came from: file is an index into sources[]. */
typedef struct {
    uint32_t file;
    uint32_t line;
} gls_srcloc;

typedef struct {
    char *name;            /* dotted name, e.g. "road.vegetation.Birch"   */
    uint8_t *code;         /* bytecode, ends with END                     */
    uint32_t code_len;
    uint32_t ninsn;        /* instructions in code (END included)         */
    gls_srcloc *src;       /* ninsn entries, or NULL when not recorded    */
} gls_object;

#define GLS_TEX_ALPHA_HOLES 1u   /* some texel has alpha 0                 */

typedef struct {
    char *name;            /* dotted name, e.g. "road.tex.asphalt"        */
    uint32_t width, height;
    uint32_t flags;        /* GLS_TEX_*                                   */
    uint8_t *rgba;         /* width*height*4 bytes, row 0 = top; alpha is
                              binary (0 or 255)                           */
} gls_texture;

/* A parameterised object's source (spec/bundle.md 7.7): what the compiler
 * needs to make it for parameter values no object of the bundle has. */
typedef struct {
    char *name;            /* the object's name, without parameter values */
    uint32_t source;       /* index into sources[]: the file of the text  */
    uint32_t nparams;      /* 1..GLS_MAX_PARAMS                           */
    char **params;         /* parameter names, in declaration order       */
    double *defaults;      /* their default values, finite                */
    char *text;            /* text_len bytes of source, no NUL inside; the
                              reader adds a NUL after them                */
    uint32_t text_len;
} gls_template;

typedef struct {
    uint32_t version;      /* format version the bundle was read as       */
    uint32_t features;     /* GLS_FEAT_* bits                              */
    uint32_t top;          /* index of the top-level object, or GLS_NONE
                              for a library bundle                        */
    uint32_t nobjects, ntextures, nsources;
    gls_object *objects;   /* sorted by name (strcmp), names unique       */
    gls_texture *textures; /* sorted by name                              */
    char **sources;        /* source file paths for gls_srcloc.file       */
    uint32_t ntemplates;
    gls_template *templates; /* sorted by name                            */
    uint32_t ninstnames;
    char **instnames;      /* instance names (calln), sorted, unique; each
                              on exactly one calln reached once from top  */
    uint32_t nmarknames;
    char **marknames;      /* landmark names (mark), sorted, unique; each
                              placed by some mark, at most once per object */

    uint32_t npos, ncol, ntex;
    gls_vec4 *pos;         /* vertex positions                             */
    gls_rgba *col;         /* per-vertex colours                          */
    gls_st *tc;            /* per-vertex texture coordinates              */
    uint32_t nnrm;
    gls_nrm *nrm;          /* per-vertex unit normals (primn); NULL if none */
} gls_bundle;

/* One decoded instruction.  Operand k (of gls_op[op].noperands) is d[k] if
 * its kind is stored as F64, else u[k]; GLS_ARG_ constants (opcodes.h)
 * name the positions: in.u[GLS_ARG_PRIM_N]. */
typedef struct {
    gls_opcode op;
    double d[GLS_MAX_OPERANDS];
    uint32_t u[GLS_MAX_OPERANDS];
} gls_insn;

/* The vertices an instruction draws, from its NVERT and FIRST_ operands:
 * n vertices from pos[first_pos], col[first_col] (or GLS_NONE: the current
 * colour), tc[first_tc] (or GLS_NONE: texture coordinates 0, 0). */
typedef struct {
    uint32_t n, first_pos, first_col, first_tc, first_nrm; /* first_nrm: GLS_NONE without normals */
} gls_vertex_span;
/* Fills *v and returns 1 if in draws vertices; 0 otherwise. */
int gls_insn_vertices(const gls_insn *in, gls_vertex_span *v);

/* Decode the instruction at code[*pos]; advance *pos.  Returns 0 on success,
 * -1 if the bytes are not a complete instruction (unknown opcode or
 * truncated operands).  Checks nothing else: use on validated code. */
int gls_insn_decode(const uint8_t *code, size_t len, size_t *pos, gls_insn *out);

/* Append the encoding of in to a growing buffer (base/buf.h).  Returns 0,
 * or -1 on allocation failure. */
int gls_insn_encode(gls_buf *b, const gls_insn *in);

/* Error reporting for read/validate: one message, the first failure. */
typedef struct {
    char msg[512];
    int check_line;        /* line of the check in format/ that failed */
} gls_error;

/* Read and validate a bundle from memory / from a file.  On success returns
 * a bundle owning all its memory; on failure NULL with err filled in. */
gls_bundle *gls_bundle_read(const uint8_t *data, size_t len, gls_error *err);
gls_bundle *gls_bundle_read_file(const char *path, gls_error *err);

/* Validate an in-memory bundle (the compiler calls this on what it built
 * before writing it; gls_bundle_read calls it on everything it reads). */
int gls_bundle_validate(const gls_bundle *b, gls_error *err);

/* Serialise to bytes (malloc'd).  Deterministic. Returns 0 or -1. */
int gls_bundle_write(const gls_bundle *b, uint8_t **out, size_t *outlen, gls_error *err);

/* Vertices object oi draws with its calls unrolled, saturated at
 * GLS_MAX_EXPANDED_VERTICES + 1.  The bundle must be validated (acyclic). */
uint64_t gls_bundle_expanded_vertices(const gls_bundle *b, uint32_t oi);

/* How many times each object is drawn when object top is: the number of
 * call paths from top to it (1 for top, 0 for an object it does not
 * reach), saturated at UINT64_MAX; nobjects entries, malloc'd (free it),
 * or NULL when out of memory.  The bundle must be acyclic (validated). */
uint64_t *gls_bundle_paths(const gls_bundle *b, uint32_t top);
/* The number of call paths from top (1 for top alone, the sum of
 * gls_bundle_paths), saturated at UINT64_MAX, in *n: 0, or -1 when out of
 * memory.  The bundle must be acyclic (validated). */
int gls_bundle_count_paths(const gls_bundle *b, uint32_t top, uint64_t *n);

/* The same with a chosen section codec (layout.h GLS_CODEC_*): uncompressed
 * bundles are for fuzzing seeds and for looking at with a hex editor. */
int gls_bundle_write_codec(const gls_bundle *b, int codec, uint8_t **out, size_t *outlen, gls_error *err);

/* Compute the feature flags from the content (used by the writer). */
uint32_t gls_bundle_features(const gls_bundle *b);

/* Find an object or texture by name (binary search); GLS_NONE if absent. */
uint32_t gls_bundle_find_object(const gls_bundle *b, const char *name);
uint32_t gls_bundle_find_texture(const gls_bundle *b, const char *name);
uint32_t gls_bundle_find_template(const gls_bundle *b, const char *name);

void gls_bundle_free(gls_bundle *b);

/* Is s[0..n) a valid instance name: [A-Za-z_][A-Za-z0-9_.-]*, at most
 * GLS_MAX_INSTANCE_NAME_BYTES long? */
int gls_valid_instance_name(const char *s, size_t n);

/* Is s[0..n) a valid landmark name: 1..GLS_MAX_MARK_NAME_BYTES bytes of
 * [A-Za-z0-9_.-]? */
int gls_valid_mark_name(const char *s, size_t n);

/* The class object oi declares with `class` (its CLASS instruction's
 * name), or NULL when it declares none.  b is validated. */
const char *gls_object_class(const gls_bundle *b, uint32_t oi);

/* Is s[0..n) a valid dotted name: identifiers ([A-Za-z_][A-Za-z0-9_]*)
 * joined by single dots, at most GLS_MAX_NAME_BYTES long? */
int gls_valid_name(const char *s, size_t n);

#endif
