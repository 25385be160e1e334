/* The glscene bytecode instruction set, defined once.
 *
 * Every opcode is one row of GLS_OPCODES:
 *
 *     X(ENUM, "name", FLOW, O(KIND, NAME) O(KIND, NAME) ...)
 *
 * FLOW is what the instruction does to the walk of an object's code
 * (gls_flow); the O(...) list gives its operands in encoding order, each
 * with a kind (GLS_OPERAND_KINDS below: its width, its range and what it
 * refers to) and a name, which becomes the constant GLS_ARG_NAME, the
 * operand's position in gls_insn (so names carry their opcode's name).
 *
 * From these two lists come the enum, the name table, the encoder and the
 * decoder (insn.c), the validator (validate.c), the disassembler
 * (disasm.c), the feature flags (bundle_misc.c), the compiler's library
 * import and relocation (compiler/), and the GLS_ARG_ constants through
 * which the compiler and the player name operands.  Those files know
 * operand kinds, never an opcode's operand positions: an opcode whose
 * operands are of existing kinds is added here, plus the compiler's and
 * the player's code for what it means.  spec/bundle.md, section 9, is the
 * normative text of this table.
 *
 * Semantics (spec/bundle.md 9.2 has the full text):
 *   END        end of the object's code; must be the last instruction.
 *   COLOR      set the current colour (r, g, b, a), components in 0..1.
 *   TEXMODE    set texture mode: 0 colour only, 1 replace, 2 modulate.
 *   TEXTURE    select the current texture.
 *   NOTEXTURE  deselect the texture.
 *   TRANS      M = M * Translate(x, y, z)
 *   ROT        M = M * Rotate(angle in degrees, axis x, y, z)
 *   SCALE      M = M * Scale(sx, sy, sz)
 *   TRANSFORM  M = M * A, A given row-major: a00 a01 a02 a03 a10 ... a33
 *   PUSH/POP   save/restore the whole state (matrix, colour, mode, texture)
 *   CALL       render another object with a copy of the current state
 *   CALLN      CALL, naming the instance it draws (INSTANCE_NAMES): a
 *              player may move it (spec/bundle.md 9.2); drawn as CALL
 *   MARK       place the named landmark (MARK_NAMES) at M * (x, y, z, 1):
 *              draws nothing; a player reports where it is (glsplay
 *              --outputs landmarks, spec/outputs.md)
 *   CLASS      the object's class (a name of MARK_NAMES), at most one per
 *              object: draws nothing; ground truth names the object's
 *              instances with it instead of its package (spec/outputs.md)
 *   PRIM       draw a primitive: kind (0 poly, 1 qstrip, 2 tstrip, 3 tfan),
 *              vertex count, first position, first colour (or NONE: use the
 *              current colour), first texcoord (or NONE: texcoord 0,0).
 *   LIGHT      declare a light (kind 0 directional, 1 point, 2 ambient):
 *              directional: towards-the-light direction M * (x, y, z, 0);
 *              point: position M * (x, y, z, 1); ambient: x, y, z unused
 *              (0); colour r, g, b (>= 0, linear) and attenuation k (>= 0,
 *              point lights: 1 / (1 + k d^2); 0 otherwise).  Draws nothing;
 *              a bundle with one is lit (feature lights, spec/bundle.md)
 *   SPECULAR   set the specular colour (r, g, b in 0..1) and Phong
 *              exponent (>= 0) of the following primitives (state, like
 *              COLOR; initially 0 0 0 0: no highlight)
 *   PRIMN      PRIM with per-vertex normals: first normal (NORMALS), the
 *              other operands PRIM's, at the same positions
 *   SHADOWS    directional and point lights cast shadows, through maps of
 *              res x res texels (feature shadows; the largest res wins)
 */
#ifndef GLS_OPCODES_H
#define GLS_OPCODES_H

#include <stdint.h>

/* Operand kinds:  K(KIND, STORAGE, VALUES, NAMES, NOUN)
 *   STORAGE  F64 (8 bytes, IEEE binary64), U8 (1 byte) or U32 (4 bytes),
 *            little-endian, no padding;
 *   VALUES   for an enumeration, the number of values (0..VALUES-1), with
 *            NAMES their names (dump, compiler) and NOUN the word for one
 *            in messages ("mode 7 unknown"); 0, NULL, NULL otherwise.
 * What each kind means, and so what the validator checks:
 *   NUM        a number: coordinate, factor, axis or matrix element; finite
 *   ANGLE      an angle in degrees; finite
 *   COMPONENT  a colour component; in 0..1
 *   ALPHA      a colour's alpha; in 0..1, below 1 the content is translucent
 *   TEXMODE    a texture mode (gls_texmode)
 *   PRIMKIND   a primitive kind (gls_primkind); the dump prints it in place
 *              of the opcode's name
 *   NVERT      the number of vertices drawn: legal for the instruction's
 *              PRIMKIND (gls_prim_min_verts, gls_prim_needs_even), at most
 *              GLS_MAX_PRIM_VERTICES
 *   OBJECT     an object index (OBJECTS): the object is run, an edge of the
 *              call graph
 *   TEXTURE    a texture index (TEXTURES)
 *   FIRST_POS  the first of NVERT positions (POSITIONS)
 *   FIRST_COL  the first of NVERT colours (COLORS), or NONE
 *   FIRST_TC   the first of NVERT texture coordinates (TEXCOORDS), or NONE
 *   INSTNAME   an instance name (INSTANCE_NAMES)
 *   MARKNAME   a landmark name (MARK_NAMES); one object places each name
 *              at most once
 *   CLASSNAME  a class name, kept in the same table (MARK_NAMES)
 *   LIGHTKIND  a light kind (gls_lightkind)
 *   INTENSITY  a light's colour component, attenuation or Phong exponent;
 *              finite and >= 0
 *   FIRST_NRM  the first of NVERT unit normals (NORMALS)
 *   SHADOWRES  a shadow map's side in texels: a power of two in
 *              GLS_SHADOW_RES_MIN..GLS_SHADOW_RES_MAX
 */
#define GLS_OPERAND_KINDS(K)                                      \
    K(NUM,       F64, 0,              NULL,             NULL)     \
    K(ANGLE,     F64, 0,              NULL,             NULL)     \
    K(COMPONENT, F64, 0,              NULL,             NULL)     \
    K(ALPHA,     F64, 0,              NULL,             NULL)     \
    K(TEXMODE,   U8,  GLS_MODE_COUNT, gls_texmode_name, "mode")   \
    K(PRIMKIND,  U8,  GLS_PRIM_COUNT, gls_prim_name,    "kind")   \
    K(NVERT,     U32, 0,              NULL,             NULL)     \
    K(OBJECT,    U32, 0,              NULL,             NULL)     \
    K(TEXTURE,   U32, 0,              NULL,             NULL)     \
    K(FIRST_POS, U32, 0,              NULL,             NULL)     \
    K(FIRST_COL, U32, 0,              NULL,             NULL)     \
    K(FIRST_TC,  U32, 0,              NULL,             NULL)     \
    K(INSTNAME,  U32, 0,              NULL,             NULL)     \
    K(MARKNAME,  U32, 0,              NULL,             NULL)     \
    K(CLASSNAME, U32, 0,              NULL,             NULL)     \
    K(LIGHTKIND, U8,  GLS_LIGHT_COUNT, gls_light_name,  "light kind") \
    K(INTENSITY, F64, 0,              NULL,             NULL)     \
    K(FIRST_NRM, U32, 0,              NULL,             NULL)     \
    K(SHADOWRES, U32, 0,              NULL,             NULL)

/* How an instruction moves the walk of an object's code (validator):
 *   NEXT  on to the next instruction
 *   PUSH  saves the state: push depth + 1, at most GLS_MAX_PUSH_DEPTH
 *   POP   restores it: push depth - 1, never below 0
 *   END   the object's last instruction, with push depth 0 */
typedef enum { GLS_FLOW_NEXT, GLS_FLOW_PUSH, GLS_FLOW_POP, GLS_FLOW_END } gls_flow;

#define GLS_OPCODES(X, O)                                                              \
    X(END,       "end",       END,  )                                                  \
    X(COLOR,     "color",     NEXT, O(COMPONENT, COLOR_R) O(COMPONENT, COLOR_G)        \
                                    O(COMPONENT, COLOR_B) O(ALPHA, COLOR_A))           \
    X(TEXMODE,   "texmode",   NEXT, O(TEXMODE, TEXMODE_MODE))                          \
    X(TEXTURE,   "texture",   NEXT, O(TEXTURE, TEXTURE_INDEX))                         \
    X(NOTEXTURE, "notexture", NEXT, )                                                  \
    X(TRANS,     "trans",     NEXT, O(NUM, TRANS_X) O(NUM, TRANS_Y) O(NUM, TRANS_Z))   \
    X(ROT,       "rot",       NEXT, O(ANGLE, ROT_ANGLE)                                \
                                    O(NUM, ROT_X) O(NUM, ROT_Y) O(NUM, ROT_Z))         \
    X(SCALE,     "scale",     NEXT, O(NUM, SCALE_X) O(NUM, SCALE_Y) O(NUM, SCALE_Z))   \
    X(TRANSFORM, "transform", NEXT,                                                    \
      O(NUM, TRANSFORM_A00) O(NUM, TRANSFORM_A01) O(NUM, TRANSFORM_A02) O(NUM, TRANSFORM_A03) \
      O(NUM, TRANSFORM_A10) O(NUM, TRANSFORM_A11) O(NUM, TRANSFORM_A12) O(NUM, TRANSFORM_A13) \
      O(NUM, TRANSFORM_A20) O(NUM, TRANSFORM_A21) O(NUM, TRANSFORM_A22) O(NUM, TRANSFORM_A23) \
      O(NUM, TRANSFORM_A30) O(NUM, TRANSFORM_A31) O(NUM, TRANSFORM_A32) O(NUM, TRANSFORM_A33)) \
    X(PUSH,      "push",      PUSH, )                                                  \
    X(POP,       "pop",       POP,  )                                                  \
    X(CALL,      "call",      NEXT, O(OBJECT, CALL_OBJECT))                            \
    X(PRIM,      "prim",      NEXT, O(PRIMKIND, PRIM_KIND) O(NVERT, PRIM_N)            \
                                    O(FIRST_POS, PRIM_POS) O(FIRST_COL, PRIM_COL)      \
                                    O(FIRST_TC, PRIM_TC))                              \
    X(CALLN,     "calln",     NEXT, O(OBJECT, CALLN_OBJECT) O(INSTNAME, CALLN_NAME))   \
    X(MARK,      "mark",      NEXT, O(MARKNAME, MARK_NAME)                              \
                                    O(NUM, MARK_X) O(NUM, MARK_Y) O(NUM, MARK_Z))      \
    X(CLASS,     "class",     NEXT, O(CLASSNAME, CLASS_NAME)) \
    X(LIGHT,     "light",     NEXT, O(LIGHTKIND, LIGHT_KIND)                           \
                                    O(NUM, LIGHT_X) O(NUM, LIGHT_Y) O(NUM, LIGHT_Z)    \
                                    O(INTENSITY, LIGHT_R) O(INTENSITY, LIGHT_G)        \
                                    O(INTENSITY, LIGHT_B) O(INTENSITY, LIGHT_ATTEN))   \
    X(SPECULAR,  "specular",  NEXT, O(COMPONENT, SPECULAR_R) O(COMPONENT, SPECULAR_G)  \
                                    O(COMPONENT, SPECULAR_B) O(INTENSITY, SPECULAR_EXP)) \
    X(PRIMN,     "primn",     NEXT, O(PRIMKIND, PRIMN_KIND) O(NVERT, PRIMN_N)          \
                                    O(FIRST_POS, PRIMN_POS) O(FIRST_COL, PRIMN_COL)    \
                                    O(FIRST_TC, PRIMN_TC) O(FIRST_NRM, PRIMN_NRM))     \
    X(SHADOWS,   "shadows",   NEXT, O(SHADOWRES, SHADOWS_RES))

typedef enum {
#define GLS_X_ENUM(e, name, flow, operands) GLS_OP_##e,
#define GLS_X_NONE(kind, name)
    GLS_OPCODES(GLS_X_ENUM, GLS_X_NONE)
#undef GLS_X_ENUM
#undef GLS_X_NONE
    GLS_OP_COUNT
} gls_opcode;

typedef enum {
#define GLS_X_KIND(kind, storage, values, names, noun) GLS_KIND_##kind,
    GLS_OPERAND_KINDS(GLS_X_KIND)
#undef GLS_X_KIND
    GLS_KIND_COUNT
} gls_operand_kind;

/* Operand positions: GLS_ARG_PRIM_N is the position of prim's vertex
 * count, an index into gls_insn.u; GLS_NARGS_PRIM is prim's number of
 * operands.  One enum per opcode, each counting from 0. */
#define GLS_X_ARGS(e, name, flow, operands) enum { operands GLS_NARGS_##e };
#define GLS_X_ARG(kind, name) GLS_ARG_##name,
GLS_OPCODES(GLS_X_ARGS, GLS_X_ARG)
#undef GLS_X_ARGS
#undef GLS_X_ARG

/* PRIMN is PRIM plus its normals: the player and the dump read both
 * through PRIM's operand positions. */
_Static_assert((int)GLS_ARG_PRIMN_KIND == (int)GLS_ARG_PRIM_KIND && (int)GLS_ARG_PRIMN_N == (int)GLS_ARG_PRIM_N &&
                   (int)GLS_ARG_PRIMN_POS == (int)GLS_ARG_PRIM_POS && (int)GLS_ARG_PRIMN_COL == (int)GLS_ARG_PRIM_COL &&
                   (int)GLS_ARG_PRIMN_TC == (int)GLS_ARG_PRIM_TC,
               "primn's operands are prim's, then the first normal");

/* Longest operand list of any opcode (TRANSFORM). */
#define GLS_MAX_OPERANDS 16
#define GLS_X_FITS(e, name, flow, operands) \
    _Static_assert(GLS_NARGS_##e <= GLS_MAX_OPERANDS, "opcode " name " has more than GLS_MAX_OPERANDS operands");
#define GLS_X_NONE(kind, name)
GLS_OPCODES(GLS_X_FITS, GLS_X_NONE)
#undef GLS_X_FITS
#undef GLS_X_NONE

/* Shadow map sides (SHADOWRES): powers of two in this range. */
#define GLS_SHADOW_RES_MIN 256u
#define GLS_SHADOW_RES_MAX 8192u

/* Index value meaning "absent" for the FIRST_COL and FIRST_TC operands. */
#define GLS_NONE 0xFFFFFFFFu

typedef enum { GLS_MODE_COLOR = 0, GLS_MODE_REPLACE = 1, GLS_MODE_MODULATE = 2, GLS_MODE_COUNT } gls_texmode;
typedef enum { GLS_LIGHT_DIRECTIONAL = 0, GLS_LIGHT_POINT = 1, GLS_LIGHT_AMBIENT = 2, GLS_LIGHT_COUNT } gls_lightkind;
typedef enum { GLS_PRIM_POLY = 0, GLS_PRIM_QSTRIP = 1, GLS_PRIM_TSTRIP = 2, GLS_PRIM_TFAN = 3, GLS_PRIM_COUNT } gls_primkind;

typedef enum { GLS_STORE_F64, GLS_STORE_U8, GLS_STORE_U32 } gls_storage;

/* One operand kind (GLS_OPERAND_KINDS). */
typedef struct {
    gls_storage storage;
    unsigned bytes;                  /* 8, 1 or 4                          */
    uint32_t values;                 /* enumerations: 0..values-1; else 0  */
    const char *const *value_names;  /* enumerations: values names         */
    const char *noun;                /* enumerations: "mode", "kind"       */
} gls_kind_info;

/* One opcode (GLS_OPCODES). */
typedef struct {
    const char *name;
    gls_flow flow;
    uint32_t noperands;
    /* the gls_operand_kind of each operand, then GLS_KIND_COUNT (an
       initializer list that is never empty, even for END's) */
    uint8_t kind[GLS_MAX_OPERANDS + 1];
} gls_op_info;

extern const gls_kind_info gls_kind[GLS_KIND_COUNT];
extern const gls_op_info gls_op[GLS_OP_COUNT];
extern const char *const gls_texmode_name[GLS_MODE_COUNT];
extern const char *const gls_prim_name[GLS_PRIM_COUNT];
extern const char *const gls_light_name[GLS_LIGHT_COUNT];

/* Position of opcode op's first operand of kind k, or -1 if it has none. */
int gls_op_find(gls_opcode op, gls_operand_kind k);

/* Smallest legal vertex count of each primitive kind, and whether the count
 * must be even (qstrip). */
unsigned gls_prim_min_verts(gls_primkind k);
int gls_prim_needs_even(gls_primkind k);

#endif
