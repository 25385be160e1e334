/* Shared state of the lexer (lexer.re), the grammar (grammar.y) and the
 * semantic actions (sema.h) while one .scene file is compiled. */
#ifndef GLS_PARSE_H
#define GLS_PARSE_H
#include "lexer.h"
#include "texuse.h"
#include "unit.h"

#define GLS_MAX_ARGS 16
#define GLS_MAX_CONSTS_BUCKETS 256

enum { VAL_NUM, VAL_WORD, VAL_STR, VAL_ERR };

/* The value of an expression or argument, folded at parse time. */
typedef struct {
    int kind;
    double num;
    const char *s;   /* VAL_WORD / VAL_STR: points into the source */
    uint32_t len;
    unsigned line, col;
} gls_val;

typedef struct gls_const {
    const char *name;
    uint32_t len;
    double value;
    struct gls_const *next;
} gls_const;

typedef struct {
    gls_unit *u;
    gls_diag *d;
    /* arguments of the statement being parsed */
    gls_val args[GLS_MAX_ARGS];
    unsigned nargs;
    int too_many_args;
    /* the open primitive block, if any */
    int in_prim;
    int prim_kind;          /* gls_primkind, or -1 for an unknown block name */
    gls_tok prim_tok;
    uint32_t prim_pos0, prim_col0, prim_tc0, prim_nvert;
    int prim_has_col, prim_has_tc;
    gls_rgba cur_col;
    gls_st cur_tc;
    /* push nesting, to point at an unbalanced push */
    gls_tok push_tok[GLS_MAX_PUSH_DEPTH + 1];
    unsigned depth;
    unsigned depth_overflow; /* pushes refused as too deep, not yet popped */
    /* which texture(...) statements texture anything (texuse.h) */
    gls_texuse texuse;
    /* named constants */
    gls_const *consts[GLS_MAX_CONSTS_BUCKETS];
    /* parser health */
    int stop;               /* stack overflow or error limit: stop feeding */
    unsigned errors_at_start;   /* diag error count when this file began   */
    unsigned errors_at_block;   /* ... when the open primitive block began */
    int syntax_errors;          /* statements were dropped by recovery     */
    int cur_major;              /* code of the token being parsed           */
    gls_tok last;               /* last token read, for stack overflow     */
    gls_tok prev;               /* the token before it: where a missing ';'
                                   belongs                                  */
    int lex_eof_error;          /* an unterminated string or comment was
                                   reported: the parser's end-of-file error
                                   would only repeat it                    */
} gls_parse;

static inline gls_loc gls_tok_loc(const gls_parse *ctx, unsigned line, unsigned col)
{
    gls_loc l = {&ctx->u->src, line, col};
    return l;
}

/* The semantic actions, called from the grammar (sema.h lists their files) */
void sema_stmt(gls_parse *ctx, gls_tok name, int parens);
void sema_block_open(gls_parse *ctx, gls_tok name);
void sema_block_close(gls_parse *ctx, gls_tok rbrace);
void sema_const(gls_parse *ctx, gls_tok name, gls_val v);
void sema_stmt_without_semi(gls_parse *ctx, gls_tok name, int parens);
void sema_const_without_semi(gls_parse *ctx, gls_tok name, gls_val v);
void sema_arg(gls_parse *ctx, gls_val v);
void sema_recover(gls_parse *ctx);
void sema_syntax_error(gls_parse *ctx, int major, gls_tok tok);
gls_val sema_number(gls_parse *ctx, gls_tok t);
gls_val sema_string(gls_parse *ctx, gls_tok t);
gls_val sema_ident(gls_parse *ctx, gls_tok t);
gls_val sema_unary(gls_parse *ctx, char op, gls_val a, gls_tok optok);
gls_val sema_binary(gls_parse *ctx, char op, gls_val a, gls_val b, gls_tok optok);

/* grammar.y (lemon) */
void *glsParseAlloc(void *(*mallocProc)(size_t), gls_parse *ctx);
void glsParse(void *p, int major, gls_tok minor);
void glsParseFree(void *p, void (*freeProc)(void *));
#endif
