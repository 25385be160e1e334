/* Syntax errors and their recovery (spec/language.md 4): a statement
 * missing only its ';', the parser's syntax errors, and the collection of
 * a statement's arguments. */
#include "grammar.h"
#include "sema.h"

/* A statement's grammar rule without ';' was reduced.  If the token that
 * made the parser reduce it can follow a statement (the next statement's
 * first token, '}' or the end of the file), only the ';' is missing: the
 * statement is compiled as usual and one error points just after its last
 * token.  Otherwise the token is a syntax error of its own, reported next
 * by the parser, and the statement is dropped as error recovery would. */
static int only_semi_missing(gls_parse *ctx)
{
    int m = ctx->cur_major;
    if (m == TK_IDENT || m == TK_CONST || m == TK_RBRACE || m == 0)
        return 1;
    ctx->nargs = 0;
    ctx->too_many_args = 0;
    return 0;
}

enum { FORM_WORD, FORM_PARENS, FORM_CONST };

/* "expected ';' after 'push'", "... 'trans(...)'", "... 'const a = ...'",
 * just after the statement's last token (the one before the lookahead). */
static void missing_semi(gls_parse *ctx, int form, gls_tok name)
{
    gls_tok end = ctx->prev;
    int n = (int)(name.len > 40 ? 40 : name.len);
    ERR(ctx, end.line, end.col + end.len, "syntax error: expected ';' after '%s%.*s%s'",
        form == FORM_CONST ? "const " : "", n, name.p,
        form == FORM_CONST ? " = ..." : form == FORM_PARENS ? "(...)" : "");
}

void sema_stmt_without_semi(gls_parse *ctx, gls_tok name, int parens)
{
    if (!only_semi_missing(ctx))
        return;
    sema_stmt(ctx, name, parens);
    missing_semi(ctx, parens ? FORM_PARENS : FORM_WORD, name);
}

void sema_const_without_semi(gls_parse *ctx, gls_tok name, gls_val v)
{
    if (!only_semi_missing(ctx))
        return;
    sema_const(ctx, name, v);
    missing_semi(ctx, FORM_CONST, name);
}

void sema_arg(gls_parse *ctx, gls_val v)
{
    /* keep counting past the last slot, so the message says how many */
    if (ctx->nargs >= GLS_MAX_ARGS)
        ctx->too_many_args = 1;
    else
        ctx->args[ctx->nargs] = v;
    ctx->nargs++;
}

void sema_recover(gls_parse *ctx)
{
    ctx->nargs = 0;
    ctx->too_many_args = 0;
}

static const char *token_desc(int major)
{
    switch (major) {
    case 0: return "end of file";
    case TK_SEMI: return "';'";
    case TK_LPAREN: return "'('";
    case TK_RPAREN: return "')'";
    case TK_LBRACE: return "'{'";
    case TK_RBRACE: return "'}'";
    case TK_COMMA: return "','";
    case TK_ASSIGN: return "'='";
    default: return NULL;
    }
}

void sema_syntax_error(gls_parse *ctx, int major, gls_tok tok)
{
    ctx->nargs = 0;
    ctx->syntax_errors++;
    const char *d = token_desc(major);
    /* an unexpected end of file after an unterminated string or comment
       is explained by that error already */
    if (major == 0 && ctx->lex_eof_error)
        return;
    if (major == 0 && ctx->in_prim)
        ERR(ctx, ctx->prim_tok.line, ctx->prim_tok.col, "syntax error: '%.*s' block is not closed with '}'",
            (int)ctx->prim_tok.len, ctx->prim_tok.p);
    else if (d)
        ERR(ctx, tok.line, tok.col, "syntax error: unexpected %s", d);
    else
        ERR(ctx, tok.line, tok.col, "syntax error: unexpected '%.*s'", (int)(tok.len > 40 ? 40 : tok.len), tok.p);
}
