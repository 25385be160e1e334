/* The glscene bytecode instruction set, defined once.
 *
 * Every opcode is one X-macro row:  X(ENUM, "name", "operand schema")
 * From this single list come the enum, the name table used by the
 * disassembler, the operand schema used by the encoder, the decoder, the
 * validator and the relocator (library linking).  Nothing else in the tree
 * may know how many operands an opcode has.
 *
 * Operand schema characters (all little-endian, fixed width):
 *   d  float64 number, must be finite
 *   b  uint8 enumeration (meaning depends on the opcode, checked by the
 *      validator against the opcode's range)
 *   n  uint32 vertex count
 *   o  uint32 object index            (into the bundle's object table)
 *   t  uint32 texture index           (into the bundle's texture table)
 *   p  uint32 first position          (into the position stream)
 *   c  uint32 first colour or NONE    (into the colour stream)
 *   x  uint32 first texcoord or NONE  (into the texcoord stream)
 *
 * Semantics (spec/bundle.md has the full text):
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
 *   PRIM       draw a primitive: kind (0 poly, 1 qstrip, 2 tstrip, 3 tfan),
 *              vertex count, first position, first colour (or NONE: use the
 *              current colour), first texcoord (or NONE: texcoord 0,0).
 */
#ifndef GLS_OPCODES_H
#define GLS_OPCODES_H

#include <stdint.h>

#define GLS_OPCODES(X)                  \
    X(END,       "end",       "")       \
    X(COLOR,     "color",     "dddd")   \
    X(TEXMODE,   "texmode",   "b")      \
    X(TEXTURE,   "texture",   "t")      \
    X(NOTEXTURE, "notexture", "")       \
    X(TRANS,     "trans",     "ddd")    \
    X(ROT,       "rot",       "dddd")   \
    X(SCALE,     "scale",     "ddd")    \
    X(TRANSFORM, "transform", "dddddddddddddddd") \
    X(PUSH,      "push",      "")       \
    X(POP,       "pop",       "")       \
    X(CALL,      "call",      "o")      \
    X(PRIM,      "prim",      "bnpcx")

typedef enum {
#define GLS_X_ENUM(e, name, schema) GLS_OP_##e,
    GLS_OPCODES(GLS_X_ENUM)
#undef GLS_X_ENUM
    GLS_OP_COUNT
} gls_opcode;

/* Longest operand list of any opcode (TRANSFORM). */
#define GLS_MAX_OPERANDS 16

/* Index value meaning "absent" for the c and x operands. */
#define GLS_NONE 0xFFFFFFFFu

typedef enum { GLS_MODE_COLOR = 0, GLS_MODE_REPLACE = 1, GLS_MODE_MODULATE = 2, GLS_MODE_COUNT } gls_texmode;
typedef enum { GLS_PRIM_POLY = 0, GLS_PRIM_QSTRIP = 1, GLS_PRIM_TSTRIP = 2, GLS_PRIM_TFAN = 3, GLS_PRIM_COUNT } gls_primkind;

extern const char *const gls_op_name[GLS_OP_COUNT];
extern const char *const gls_op_schema[GLS_OP_COUNT];
extern const char *const gls_texmode_name[GLS_MODE_COUNT];
extern const char *const gls_prim_name[GLS_PRIM_COUNT];

/* Smallest legal vertex count of each primitive kind, and whether the count
 * must be even (qstrip). */
unsigned gls_prim_min_verts(gls_primkind k);
int gls_prim_needs_even(gls_primkind k);

#endif
