/* Shared state of the lexer (lexer.re), the grammar (grammar.y), the tree
 * it builds (ast.h) and the semantic actions (sema.h) while one .scene
 * file is parsed and run: the parse side (open blocks and loops, the
 * arena), and the run side (the unit being filled, the open primitive,
 * push nesting, constants and their scopes, the loop budget). */
#ifndef GLS_PARSE_H
#define GLS_PARSE_H
#include "ast.h"
#include "lexer.h"
#include "texuse.h"
#include "unit.h"

/* Arguments recorded per statement: 1 + GLS_MAX_PARAMS for call. */
#define GLS_MAX_ARGS 33
#define GLS_MAX_CONSTS_BUCKETS 256
/* Blocks and loops open at once while parsing (the parser's stack of 200
 * entries allows fewer). */
#define GLS_MAX_OPEN 128
/* Statements one object may run inside repeat loops, iterations counted
 * too, and all the objects of a compile together (spec/language.md 9). */
#ifndef GLS_MAX_UNROLLED
#define GLS_MAX_UNROLLED (1u << 22)
#endif
#ifndef GLS_MAX_UNROLLED_TOTAL
#define GLS_MAX_UNROLLED_TOTAL (1ull << 26)
#endif

enum { VAL_NUM, VAL_WORD, VAL_STR, VAL_ERR };

/* The value of an expression or argument, evaluated when its statement
 * runs.  A named argument (NAME = value, call's parameter values) also
 * has its name. */
typedef struct {
    int kind;
    double num;
    const char *s;   /* VAL_WORD / VAL_STR: points into the source */
    uint32_t len;
    unsigned line, col;
    const gls_tok *pname; /* a named argument's name (in its node), or NULL */
} gls_val;

/* What a name stands for while a file runs. */
enum { NAME_CONST, NAME_PARAM, NAME_LOOP };
typedef struct gls_const {
    const char *name;
    uint32_t len;
    double value;
    int kind;               /* NAME_* */
    struct gls_const *next; /* in its hash bucket */
} gls_const;

/* A block or loop being parsed. */
typedef struct {
    gls_stmt *node;
    int repeat;
    gls_arena_mark mark; /* what was allocated after its node */
} gls_open;

typedef struct {
    gls_unit *u;            /* the unit being filled                        */
    const gls_source *src;  /* the text, for locations                      */
    gls_diag *d;

    /* ---- parsing ---- */
    gls_arena *arena;       /* the tree's nodes                              */
    gls_open open[GLS_MAX_OPEN];
    unsigned nopen;
    unsigned open_repeats;  /* loops among the open: their statements are
                               kept, and run when the outermost loop ends   */
    gls_stmt file;          /* the top-level statements, when kept          */
    gls_arena_mark file_mark; /* the arena before any statement             */
    int keep_tree;          /* the file declares parameters: its tree is
                               run again for other values (template.c)     */
    int no_run;             /* parse only (a template from a bundle)        */
    int leading_params;     /* only parameters so far at the top level      */
    int stop;               /* stack overflow or error limit: stop feeding */
    int syntax_errors;      /* statements were dropped by recovery          */
    int cur_major;          /* code of the token being parsed               */
    gls_tok last;           /* last token read, for stack overflow          */
    gls_tok prev;           /* the token before it: where a missing ';'
                               belongs                                      */
    int lex_eof_error;      /* an unterminated string or comment was
                               reported: the parser's end-of-file error
                               would only repeat it                         */
    struct {                /* the statement just built lacks its ';':
                               reported once it has run                     */
        int form;           /* 0 none, else syntax.c's FORM_ + 1            */
        gls_tok name, end;
    } missing_semi;

    /* ---- running ---- */
    /* arguments of the statement being run */
    gls_val args[GLS_MAX_ARGS];
    unsigned nargs;
    int too_many_args;
    /* the open primitive block, if any */
    int in_prim;
    int prim_kind;          /* gls_primkind, or -1 for an unknown block name */
    gls_tok prim_tok;
    uint32_t prim_pos0, prim_col0, prim_tc0, prim_nrm0, prim_nvert;
    int prim_has_col, prim_has_tc, prim_has_nrm;
    gls_rgba cur_col;
    gls_st cur_tc;
    gls_nrm cur_nrm;
    /* push nesting, to point at an unbalanced push */
    gls_tok push_tok[GLS_MAX_PUSH_DEPTH + 1];
    unsigned depth;
    unsigned depth_overflow; /* pushes refused as too deep, not yet popped */
    /* which texture(...) statements texture anything (texuse.h) */
    gls_texuse texuse;
    /* constants, parameters and loop variables; defined[] in definition
       order, so a loop body's scope ends by undefining its tail */
    gls_const *consts[GLS_MAX_CONSTS_BUCKETS];
    gls_const **defined;
    size_t ndefined, defined_cap;
    /* parameter values to run with (NULL: the defaults), and the
       parameters declared so far with their values */
    const gls_named *binding;
    unsigned nbinding;
    unsigned nparams;
    gls_tok pnames[GLS_MAX_PARAMS];
    double pvalues[GLS_MAX_PARAMS];
    int in_default;         /* evaluating a parameter's default: no names  */
    int other_stmt_run;     /* a statement other than param has run         */
    /* loops */
    unsigned loops;            /* repeat loops running now                 */
    gls_tok loop_tok;          /* the outermost one's keyword              */
    uint64_t unrolled;         /* statements run inside loops (GLS_MAX_UNROLLED) */
    uint64_t *total_unrolled;  /* the compile's count, or NULL              */
    int unroll_over;           /* the limit was reported: loops stop        */
    unsigned errors_at_start;   /* diag error count when this file began   */
    unsigned errors_at_block;   /* ... when the open primitive block began */
} gls_parse;

static inline gls_loc gls_tok_loc(const gls_parse *ctx, unsigned line, unsigned col)
{
    gls_loc l = {ctx->src, line, col};
    return l;
}

/* ---- the grammar's actions: build the tree (syntax.c) ---- */
gls_stmt *sema_instr_stmt(gls_parse *ctx, gls_tok name, int parens, gls_elist args);
gls_stmt *sema_instr_without_semi(gls_parse *ctx, gls_tok name, int parens, gls_elist args);
gls_stmt *sema_const(gls_parse *ctx, gls_tok kw, gls_tok name, gls_expr *value, int is_param);
gls_stmt *sema_const_without_semi(gls_parse *ctx, gls_tok kw, gls_tok name, gls_expr *value, int is_param);
gls_stmt *sema_block_begin(gls_parse *ctx, gls_tok name);
gls_stmt *sema_repeat_begin(gls_parse *ctx, gls_tok kw, gls_tok var, gls_elist bounds);
gls_stmt *sema_open_end(gls_parse *ctx, gls_stmt *open, gls_tok rbrace);
void sema_stmt_done(gls_parse *ctx, gls_stmt *s);
void sema_report_missing_semi(gls_parse *ctx);
void sema_syntax_error(gls_parse *ctx, int major, gls_tok tok);
gls_expr *sema_number(gls_parse *ctx, gls_tok t);
gls_expr *sema_leaf(gls_parse *ctx, gls_expr_kind kind, gls_tok t);
gls_expr *sema_op(gls_parse *ctx, char op, gls_tok optok, gls_expr *a, gls_expr *b);
gls_expr *sema_fn(gls_parse *ctx, gls_tok name, gls_elist args);
gls_expr *sema_named(gls_parse *ctx, gls_tok name, gls_expr *value);
gls_elist sema_list(gls_parse *ctx, gls_elist l, gls_expr *e);

/* grammar.y (lemon) */
void *glsParseAlloc(void *(*mallocProc)(size_t), gls_parse *ctx);
void glsParse(void *p, int major, gls_tok minor);
void glsParseFree(void *p, void (*freeProc)(void *));
#endif
