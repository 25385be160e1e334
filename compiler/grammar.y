/* The scene language grammar, for lemon.  spec/language.md has it in
 * prose.  Values are folded as they are reduced: expressions evaluate to
 * numbers at parse time and arguments are collected in ctx->args, so no
 * nonterminal owns heap memory and no %destructor is needed. */
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

%type expr {gls_val}

file ::= stmts.

stmts ::= .
stmts ::= stmts stmt.

stmt ::= IDENT(N) SEMI.                         { sema_stmt(ctx, N, 0); }
stmt ::= IDENT(N) LPAREN args RPAREN SEMI.      { sema_stmt(ctx, N, 1); }
stmt ::= bopen stmts RBRACE(R).                 { sema_block_close(ctx, R); }
stmt ::= CONST IDENT(N) ASSIGN expr(E) SEMI.    { sema_const(ctx, N, E); }
stmt ::= error SEMI.                            { sema_recover(ctx); }

/* A statement without its ';'.  Only the start of the next statement, '}'
 * or the end of the file can follow a statement, so these rules add no
 * conflict; lemon may still reduce them on any other token (a default
 * reduction), and the action then leaves that token's syntax error to be
 * reported as before (syntax.c). */
stmt ::= IDENT(N).                              { sema_stmt_without_semi(ctx, N, 0); }
stmt ::= IDENT(N) LPAREN args RPAREN.           { sema_stmt_without_semi(ctx, N, 1); }
stmt ::= CONST IDENT(N) ASSIGN expr(E).         { sema_const_without_semi(ctx, N, E); }

bopen ::= IDENT(N) LBRACE.                      { sema_block_open(ctx, N); }

args ::= .
args ::= arglist.
arglist ::= arg.
arglist ::= arglist COMMA arg.
arg ::= expr(E).                                { sema_arg(ctx, E); }
arg ::= STRING(S).                              { sema_arg(ctx, sema_string(ctx, S)); }

expr(A) ::= NUMBER(N).                          { A = sema_number(ctx, N); }
expr(A) ::= IDENT(N).                           { A = sema_ident(ctx, N); }
expr(A) ::= LPAREN expr(B) RPAREN.              { A = B; }
expr(A) ::= MINUS(O) expr(B). [UNARY]           { A = sema_unary(ctx, '-', B, O); }
expr(A) ::= PLUS(O) expr(B). [UNARY]            { A = sema_unary(ctx, '+', B, O); }
expr(A) ::= expr(B) PLUS(O) expr(C).            { A = sema_binary(ctx, '+', B, C, O); }
expr(A) ::= expr(B) MINUS(O) expr(C).           { A = sema_binary(ctx, '-', B, C, O); }
expr(A) ::= expr(B) STAR(O) expr(C).            { A = sema_binary(ctx, '*', B, C, O); }
expr(A) ::= expr(B) SLASH(O) expr(C).           { A = sema_binary(ctx, '/', B, C, O); }
