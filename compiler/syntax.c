/* Syntax errors and their recovery (spec/language.md 4): a statement
 * missing only its ';' and the parser's syntax errors. */
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
    return m == TK_IDENT || m == TK_CONST || m == TK_PARAM || m == TK_REPEAT || m == TK_RBRACE || m == 0;
}

enum { FORM_WORD = 1, FORM_PARENS, FORM_CONST, FORM_PARAM };

/* Remember the missing ';' of the statement being built: just after its
 * last token (the one before the lookahead).  It is reported once the
 * statement has run (sema_stmt_done), after the statement's own errors. */
static void missing_semi(gls_parse *ctx, int form, gls_tok name)
{
    ctx->missing_semi.form = form;
    ctx->missing_semi.name = name;
    ctx->missing_semi.end = ctx->prev;
}

void sema_report_missing_semi(gls_parse *ctx)
{
    int form = ctx->missing_semi.form;
    if (!form)
        return;
    ctx->missing_semi.form = 0;
    gls_tok end = ctx->missing_semi.end, name = ctx->missing_semi.name;
    int n = (int)(name.len > 40 ? 40 : name.len);
    ERR(ctx, end.line, end.col + end.len, "syntax error: expected ';' after '%s%.*s%s'",
        form == FORM_CONST ? "const " : form == FORM_PARAM ? "param " : "", n, name.p,
        form == FORM_CONST || form == FORM_PARAM ? " = ..." : form == FORM_PARENS ? "(...)" : "");
}

gls_stmt *sema_instr_without_semi(gls_parse *ctx, gls_tok name, int parens, gls_elist args)
{
    if (!only_semi_missing(ctx))
        return NULL;
    missing_semi(ctx, parens ? FORM_PARENS : FORM_WORD, name);
    return sema_instr_stmt(ctx, name, parens, args);
}

gls_stmt *sema_const_without_semi(gls_parse *ctx, gls_tok kw, gls_tok name, gls_expr *value, int is_param)
{
    if (!only_semi_missing(ctx))
        return NULL;
    missing_semi(ctx, is_param ? FORM_PARAM : FORM_CONST, name);
    return sema_const(ctx, kw, name, value, is_param);
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
    ctx->syntax_errors++;
    const char *d = token_desc(major);
    /* an unexpected end of file after an unterminated string or comment
       is explained by that error already */
    if (major == 0 && ctx->lex_eof_error)
        return;
    if (major == 0 && ctx->nopen) {
        const gls_stmt *s = ctx->open[ctx->nopen - 1].node;
        gls_tok t = s->kind == ST_REPEAT ? s->kw : s->name;
        ERR(ctx, t.line, t.col, "syntax error: '%.*s' block is not closed with '}'", (int)t.len, t.p);
    } else if (d) {
        ERR(ctx, tok.line, tok.col, "syntax error: unexpected %s", d);
    } else {
        ERR(ctx, tok.line, tok.col, "syntax error: unexpected '%.*s'", (int)(tok.len > 40 ? 40 : tok.len), tok.p);
    }
}
