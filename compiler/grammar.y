/* The scene language grammar, for lemon.  spec/language.md has it in
 * prose.  The actions build the syntax tree (ast.h) in an arena (so no
 * nonterminal owns heap memory and no %destructor is needed); a finished
 * statement goes to sema_stmt_done, which runs it at once unless it is
 * inside a repeat loop (tree.c). */
%include {
#include <assert.h>
#include <stdlib.h>
#include "parse.h"
}

%name glsParse
%token_prefix TK_
%token_type {gls_tok}
%extra_context {gls_parse *ctx}
%stack_size 200
%start_symbol file

%stack_overflow {
    gls_error_at(ctx->d, gls_tok_loc(ctx, ctx->last.line, ctx->last.col), "expression nested too deeply");
    ctx->stop = 1;
}

%syntax_error {
    sema_syntax_error(ctx, yymajor, TOKEN);
}

/* INVALID: the scanner's error token (lexer.h); unit.c reports it and never
 * passes it to the parser. */
%token INVALID.

%left PLUS MINUS.
%left STAR SLASH.
%right UNARY.

%type stmt {gls_stmt *}
%type bopen {gls_stmt *}
%type ropen {gls_stmt *}
%type expr {gls_expr *}
%type arg {gls_expr *}
%type args {gls_elist}
%type arglist {gls_elist}
%type exprs {gls_elist}
%type exprlist {gls_elist}

file ::= stmts.

stmts ::= .
stmts ::= stmts stmt(S).                         { sema_stmt_done(ctx, S); }

stmt(S) ::= IDENT(N) SEMI.                       { S = sema_instr_stmt(ctx, N, 0, (gls_elist){0}); }
stmt(S) ::= IDENT(N) LPAREN args(A) RPAREN SEMI. { S = sema_instr_stmt(ctx, N, 1, A); }
stmt(S) ::= bopen(B) stmts RBRACE(R).            { S = sema_open_end(ctx, B, R); }
stmt(S) ::= ropen(B) stmts RBRACE(R).            { S = sema_open_end(ctx, B, R); }
stmt(S) ::= CONST(K) IDENT(N) ASSIGN expr(E) SEMI.   { S = sema_const(ctx, K, N, E, 0); }
stmt(S) ::= PARAM(K) IDENT(N) ASSIGN expr(E) SEMI.   { S = sema_const(ctx, K, N, E, 1); }
stmt(S) ::= error SEMI.                          { S = NULL; }

/* A statement without its ';'.  Only the start of the next statement, '}'
 * or the end of the file can follow a statement, so these rules add no
 * conflict; lemon may still reduce them on any other token (a default
 * reduction), and the action then leaves that token's syntax error to be
 * reported as before (syntax.c). */
stmt(S) ::= IDENT(N).                            { S = sema_instr_without_semi(ctx, N, 0, (gls_elist){0}); }
stmt(S) ::= IDENT(N) LPAREN args(A) RPAREN.      { S = sema_instr_without_semi(ctx, N, 1, A); }
stmt(S) ::= CONST(K) IDENT(N) ASSIGN expr(E).    { S = sema_const_without_semi(ctx, K, N, E, 0); }
stmt(S) ::= PARAM(K) IDENT(N) ASSIGN expr(E).    { S = sema_const_without_semi(ctx, K, N, E, 1); }

bopen(B) ::= IDENT(N) LBRACE.                    { B = sema_block_begin(ctx, N); }
ropen(B) ::= REPEAT(K) LPAREN IDENT(V) COMMA exprlist(L) RPAREN LBRACE.
                                                 { B = sema_repeat_begin(ctx, K, V, L); }

args(A) ::= .                                    { A = (gls_elist){0}; }
args(A) ::= arglist(L).                          { A = L; }
arglist(A) ::= arg(E).                           { A = sema_list(ctx, (gls_elist){0}, E); }
arglist(A) ::= arglist(L) COMMA arg(E).          { A = sema_list(ctx, L, E); }
arg(A) ::= expr(E).                              { A = E; }
arg(A) ::= STRING(S).                            { A = sema_leaf(ctx, EX_STR, S); }
arg(A) ::= IDENT(N) ASSIGN expr(E).              { A = sema_named(ctx, N, E); }

exprs(A) ::= .                                   { A = (gls_elist){0}; }
exprs(A) ::= exprlist(L).                        { A = L; }
exprlist(A) ::= expr(E).                         { A = sema_list(ctx, (gls_elist){0}, E); }
exprlist(A) ::= exprlist(L) COMMA expr(E).       { A = sema_list(ctx, L, E); }

expr(A) ::= NUMBER(N).                           { A = sema_number(ctx, N); }
expr(A) ::= IDENT(N).                            { A = sema_leaf(ctx, EX_IDENT, N); }
expr(A) ::= IDENT(N) LPAREN exprs(L) RPAREN.     { A = sema_fn(ctx, N, L); }
expr(A) ::= LPAREN expr(B) RPAREN.               { A = B; }
expr(A) ::= MINUS(O) expr(B). [UNARY]            { A = sema_op(ctx, '-', O, B, NULL); }
expr(A) ::= PLUS(O) expr(B). [UNARY]             { A = sema_op(ctx, '+', O, B, NULL); }
expr(A) ::= expr(B) PLUS(O) expr(C).             { A = sema_op(ctx, '+', O, B, C); }
expr(A) ::= expr(B) MINUS(O) expr(C).            { A = sema_op(ctx, '-', O, B, C); }
expr(A) ::= expr(B) STAR(O) expr(C).             { A = sema_op(ctx, '*', O, B, C); }
expr(A) ::= expr(B) SLASH(O) expr(C).            { A = sema_op(ctx, '/', O, B, C); }
