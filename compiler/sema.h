/* Shared by the semantic actions of the scene language.  The lemon grammar
 * calls the tree builders as it reduces (parse.h declares them); running a
 * statement calls the rest:
 *   tree.c         building the tree, and running statements as they are
 *                  parsed (outside loops)
 *   syntax.c       syntax errors, a missing ';'
 *   exec.c         running statements: instructions' arguments, blocks,
 *                  constants, parameters, repeat loops and their budget
 *   statements.c   instruction names: lookup, "did you mean", and the checks
 *                  every instruction shares (placement, count, kinds)
 *   instructions.c each instruction's own checks and the code it emits
 *   blocks.c       primitive blocks: their names, vertex counts, PRIM
 *   fold.c         numbers, names and their scopes, expression evaluation
 *   mathfn.c       the functions of expressions */
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

/* exec.c */
/* Run statement s (a block whole, a loop all its iterations). */
void sema_run(gls_parse *ctx, const gls_stmt *s);

/* blocks.c: a primitive block opened (its statements run next) and closed */
void sema_block_open(gls_parse *ctx, gls_tok name);
void sema_block_close(gls_parse *ctx);

/* fold.c */
/* The value of e now (constants, parameters and loop variables as they
 * are); errors are reported and give VAL_ERR. */
gls_val sema_eval(gls_parse *ctx, const gls_expr *e);
/* Report "unknown constant" for a word where a number is needed, "a
 * string ..." for a string; 1 if a is a number. */
int sema_need_number(gls_parse *ctx, const gls_val *a);
/* Define name (a NAME_* kind) as v in the current scope: 0, or -1 after
 * reporting why not (reserved name, already defined). */
int sema_define(gls_parse *ctx, int kind, gls_tok name, double v);
/* Give the name defined at index mark (sema_scope_mark before its
 * definition) the value v: a loop variable is defined once per loop and
 * takes each iteration's value this way, without the checks again. */
void sema_set_value(gls_parse *ctx, size_t mark, double v);
/* Scopes: a loop body's names are undefined when an iteration ends. */
size_t sema_scope_mark(const gls_parse *ctx);
void sema_scope_end(gls_parse *ctx, size_t mark);
void sema_names_free(gls_parse *ctx);
/* The number a NUMBER token stands for: 0 and *v, or -1 after reporting
 * a value that is not finite (1 for a malformed number, reported by the
 * lexer). */
int sema_parse_number(gls_parse *ctx, gls_tok t, double *v);

/* statements.c */
/* Instruction name with its arguments evaluated in ctx->args: checked and
 * compiled. */
void sema_stmt(gls_parse *ctx, gls_tok name, int parens);
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
