/* The syntax tree of a .scene file (spec/language.md 4), as the grammar
 * builds it, and the arena its nodes live in.
 *
 * Most statements are run as soon as they are parsed (exec.c), so a flat
 * file of a million vertices never holds more than one statement's nodes.
 * The tree is kept where a statement must run again or later: the body of
 * a repeat loop runs once per iteration, and a file that declares
 * parameters is run again for every set of values it is called with
 * (template.c).  Nodes are never freed one by one: the arena is released
 * to a mark (the statements after it are done with) or freed whole. */
#ifndef GLS_AST_H
#define GLS_AST_H
#include <stddef.h>
#include "lexer.h"

/* ---- arena ---------------------------------------------------------------- */

typedef struct gls_chunk gls_chunk;
typedef struct {
    gls_chunk *cur; /* the newest chunk; older ones hang off it */
} gls_arena;

/* Everything allocated after a mark is released with it. */
typedef struct {
    gls_chunk *chunk;
    size_t used;
} gls_arena_mark;

/* n zeroed bytes, aligned for any type; NULL when out of memory. */
void *gls_arena_alloc(gls_arena *a, size_t n);
gls_arena_mark gls_arena_get_mark(const gls_arena *a);
void gls_arena_release(gls_arena *a, gls_arena_mark m);
void gls_arena_free(gls_arena *a);

/* ---- expressions ---------------------------------------------------------- */

typedef enum {
    EX_NUM,    /* a number: num (EX_ERR if the literal is malformed or
                  not finite; the parser reported it)                    */
    EX_STR,    /* a quoted name, only ever a whole argument              */
    EX_IDENT,  /* a name: a constant, parameter, loop variable or pi, or
                  a bare word (texmode's argument)                       */
    EX_UNARY,  /* op a                                                   */
    EX_BINARY, /* a op b                                                 */
    EX_CALL,   /* a function: tok(args), args from a, nargs of them      */
    EX_NAMED,  /* a named argument tok = a (call's parameter values)     */
    EX_ERR,    /* already reported                                       */
} gls_expr_kind;

typedef struct gls_expr gls_expr;
struct gls_expr {
    gls_expr_kind kind;
    char op;           /* EX_UNARY, EX_BINARY: '+', '-', '*', '/'          */
    unsigned nargs;    /* EX_CALL                                          */
    int fn;            /* EX_CALL: the function (mathfn.h)                 */
    gls_tok tok;       /* the literal, name or operator                    */
    double num;        /* EX_NUM                                           */
    gls_expr *a, *b;   /* operands; EX_CALL and EX_NAMED use a             */
    gls_expr *next;    /* the next argument of a list                      */
};

/* A list of expressions being built (arguments). */
typedef struct {
    gls_expr *head, *tail;
    unsigned n;
} gls_elist;

/* ---- statements ----------------------------------------------------------- */

typedef enum {
    ST_INSTR,  /* name; / name(args);                                    */
    ST_BLOCK,  /* name { body }  (a primitive)                           */
    ST_CONST,  /* const name = value;                                    */
    ST_PARAM,  /* param name = value;                                    */
    ST_REPEAT, /* repeat(name, args...) { body }: args are start, end
                  and perhaps step                                       */
} gls_stmt_kind;

typedef struct gls_stmt gls_stmt;
struct gls_stmt {
    gls_stmt_kind kind;
    int parens;        /* ST_INSTR written with (...)                      */
    gls_tok kw;        /* ST_PARAM, ST_REPEAT: the keyword                  */
    gls_tok name;      /* instruction, block, constant, parameter or loop
                          variable                                         */
    gls_elist args;    /* ST_INSTR, ST_REPEAT                              */
    gls_expr *value;   /* ST_CONST, ST_PARAM                               */
    gls_stmt *body, *body_tail; /* ST_BLOCK, ST_REPEAT                     */
    gls_stmt *next;
};

/* Constructors: NULL when out of memory. */
gls_expr *gls_ast_expr(gls_arena *a, gls_expr_kind kind, gls_tok tok);
gls_stmt *gls_ast_stmt(gls_arena *a, gls_stmt_kind kind, gls_tok name);
/* Append e to the list l (e may be NULL: out of memory, nothing added). */
void gls_elist_add(gls_elist *l, gls_expr *e);
/* Append s to the body of parent. */
void gls_stmt_add(gls_stmt *parent, gls_stmt *s);
#endif
