/* Compilation units: storage, and the driver that feeds the scanner's
 * tokens to the lemon parser for one .scene file. */
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "fileio.h"
#include "grammar.h"
#include "parse.h"

void gls_unit_free(gls_unit *u)
{
    if (!u)
        return;
    free(u->name);
    if (u->src.text)
        gls_release_file(u->src.text, u->src.mapped);
    free(u->code.data);
    free(u->lines);
    for (uint32_t i = 0; i < u->nrefs; i++)
        free(u->refs[i].name);
    for (uint32_t i = 0; i < u->ntexrefs; i++)
        free(u->texrefs[i].name);
    free(u->refs);
    free(u->texrefs);
    free(u->pos);
    free(u->col);
    free(u->tc);
    free(u);
}

int gls_unit_emit(gls_unit *u, const gls_insn *in, uint32_t line)
{
    if (gls_grow(&u->lines, &u->lines_cap, (size_t)u->ninsn + 1, sizeof *u->lines))
        return -1;
    if (gls_insn_encode(&u->code, in))
        return -1;
    u->lines[u->ninsn].file = u->src_file;
    u->lines[u->ninsn].line = line;
    u->ninsn++;
    return 0;
}

uint32_t gls_unit_add_ref(gls_ref **arr, uint32_t *n, size_t *cap, const char *name, size_t len, gls_loc loc)
{
    if (gls_grow(arr, cap, (size_t)*n + 1, sizeof **arr))
        return GLS_NONE;
    char *s = strndup(name, len); /* a valid name: no NUL inside */
    if (!s)
        return GLS_NONE;
    (*arr)[*n].name = s;
    (*arr)[*n].loc = loc;
    return (*n)++;
}

/* The next token for the parser.  Lexical errors are reported here, in
 * the order they occur, and the parser never sees them: a malformed number
 * stands for a number (so its statement parses, and is dropped silently
 * by sema_number), every other error token is skipped.  After an
 * unterminated string or comment, the parser's "unexpected end of file"
 * would only repeat it (lex_eof_error). */
static int next_token(gls_lexer *lx, gls_tok *t, gls_parse *ctx)
{
    int code;
    while ((code = gls_lex(lx, t)) == TK_INVALID) {
        char small[128], *msg = small;
        int need = gls_lex_message(t, small, sizeof small);
        if (need >= (int)sizeof small && (msg = malloc((size_t)need + 1)))
            gls_lex_message(t, msg, (size_t)need + 1);
        gls_error_at(ctx->d, gls_tok_loc(ctx, t->line, t->col), "%s", msg ? msg : small);
        if (msg != small)
            free(msg);
        if (t->err == GLS_LEX_UNTERMINATED_COMMENT || t->err == GLS_LEX_UNTERMINATED_STRING)
            ctx->lex_eof_error = 1;
        if (t->err == GLS_LEX_MALFORMED_NUMBER)
            return TK_NUMBER;
    }
    return code;
}

int gls_compile_source(gls_unit *u, gls_diag *d)
{
    gls_parse *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        gls_error_at(d, (gls_loc){&u->src, 0, 0}, "out of memory");
        return -1;
    }
    ctx->u = u;
    ctx->d = d;
    ctx->errors_at_start = d->errors;
    gls_texuse_init(&ctx->texuse, u->is_top);
    unsigned errors0 = d->errors;
    void *parser = glsParseAlloc(malloc, ctx);
    if (!parser) {
        free(ctx);
        gls_error_at(d, (gls_loc){&u->src, 0, 0}, "out of memory");
        return -1;
    }
    gls_lexer lx;
    gls_lexer_init(&lx, u->src.text, u->src.len);
    gls_tok t;
    int code;
    do {
        code = next_token(&lx, &t, ctx);
        ctx->prev = ctx->last;
        ctx->last = t;
        ctx->cur_major = code;
        glsParse(parser, code, t);
    } while (code != 0 && !ctx->stop && !d->stopped);
    glsParseFree(parser, free);

    /* end of the object: every push must have been popped (unless error
       recovery dropped statements, which would make this a false alarm) */
    for (unsigned i = 0; i < ctx->depth && !ctx->in_prim && !ctx->syntax_errors; i++) {
        gls_tok p = ctx->push_tok[i];
        gls_error_at(d, gls_tok_loc(ctx, p.line, p.col), "'push' without a matching 'pop' before the end of the object");
    }
    gls_texuse_finish(&ctx->texuse, d);
    gls_insn end = {.op = GLS_OP_END};
    if (gls_unit_emit(u, &end, lx.line))
        gls_error_at(d, (gls_loc){&u->src, 0, 0}, "out of memory");
    for (unsigned h = 0; h < GLS_MAX_CONSTS_BUCKETS; h++)
        for (gls_const *c = ctx->consts[h], *next; c; c = next) {
            next = c->next;
            free(c);
        }
    free(ctx);
    return d->errors == errors0 ? 0 : -1;
}
