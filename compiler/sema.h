/* Shared by the semantic actions of the scene language, which the lemon
 * grammar calls as it reduces (parse.h declares them):
 *   statements.c   instruction names: lookup, "did you mean", and the checks
 *                  every instruction shares (placement, count, kinds)
 *   instructions.c each instruction's own checks and the code it emits
 *   blocks.c       primitive blocks: their names, vertex counts, PRIM
 *   fold.c         numbers, named constants, expression folding
 *   syntax.c       syntax errors, a missing ';', argument collection */
#ifndef GLS_SEMA_H
#define GLS_SEMA_H
#include "parse.h"

#define ERR(ctx, line, col, ...) gls_error_at((ctx)->d, gls_tok_loc((ctx), (line), (col)), __VA_ARGS__)

/* One instruction of the language (spec/language.md 7): its name, argument
 * count, the kind of each argument (one letter per position: n number,
 * s quoted name, w word), where it may appear, and its handler, called
 * once the shared checks passed. */
enum { WHERE_OUTSIDE, WHERE_PRIM };
typedef void (*sema_handler)(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n);
typedef struct {
    const char *name;
    unsigned min, max;
    const char *kinds;
    int where;
    sema_handler fn;
} sema_instr;

/* instructions.c */
extern const sema_instr sema_instrs[];
extern const size_t sema_ninstrs;
/* Append instruction in to the unit, attributed to line. */
void sema_emit(gls_parse *ctx, gls_insn *in, unsigned line);

/* statements.c */
/* every word with a meaning: instructions, primitives, "const" */
extern const char *const sema_words[];
extern const size_t sema_nwords;
/* names other languages use, for "did you mean" */
extern const gls_alias sema_aliases[];
extern const size_t sema_naliases;
int sema_tok_is(gls_tok t, const char *s);
/* the gls_primkind named by t, or -1 */
int sema_prim_kind(gls_tok t);
#endif
