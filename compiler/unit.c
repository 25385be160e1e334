/* Compilation units: storage, and the driver that feeds the scanner's
 * tokens to the lemon parser for one .scene file. */
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "fileio.h"
#include "grammar.h"
#include "sema.h"

void gls_unit_free(gls_unit *u)
{
    if (!u)
        return;
    free(u->name);
    if (u->src.text && !u->src_borrowed)
        gls_release_file(u->src.text, u->src.mapped);
    free(u->code.data);
    free(u->lines);
    for (uint32_t i = 0; i < u->nrefs; i++) {
        free(u->refs[i].name);
        for (unsigned k = 0; k < u->refs[i].nargs; k++)
            free(u->refs[i].args[k].name);
        free(u->refs[i].args);
    }
    for (uint32_t i = 0; i < u->ntexrefs; i++)
        free(u->texrefs[i].name);
    for (uint32_t i = 0; i < u->ninstnames; i++)
        free(u->instnames[i].name);
    free(u->instnames);
    for (uint32_t i = 0; i < u->nmarknames; i++)
        free(u->marknames[i].name);
    free(u->marknames);
    for (uint32_t i = 0; i < u->nclassnames; i++)
        free(u->classnames[i].name);
    free(u->classnames);
    free(u->refs);
    free(u->texrefs);
    free(u->pos);
    free(u->col);
    free(u->tc);
    free(u->nrm);
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
    (*arr)[*n] = (gls_ref){.name = s, .loc = loc};
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

static void out_of_memory(gls_diag *d, const gls_source *src)
{
    gls_error_at(d, (gls_loc){src, 0, 0}, "out of memory");
}

/* A new context ready to run statements into u; NULL after reporting
 * that there is no memory for it. */
static gls_parse *run_begin(gls_unit *u, gls_diag *d, uint64_t *total)
{
    gls_parse *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        out_of_memory(d, &u->src);
        return NULL;
    }
    ctx->u = u;
    ctx->src = &u->src;
    ctx->d = d;
    ctx->errors_at_start = d->errors;
    ctx->total_unrolled = total;
    gls_texuse_init(&ctx->texuse, u->is_top);
    return ctx;
}

/* The end of the object: every push must have been popped (unless error
 * recovery dropped statements or the loop budget cut the object short,
 * which would make this a false alarm), the
 * texture warnings, END at end_line. */
static void run_end(gls_parse *ctx, unsigned end_line)
{
    gls_diag *d = ctx->d;
    for (unsigned i = 0; i < ctx->depth && !ctx->in_prim && !ctx->syntax_errors && !ctx->unroll_over; i++) {
        gls_tok p = ctx->push_tok[i];
        gls_error_at(d, gls_tok_loc(ctx, p.line, p.col), "'push' without a matching 'pop' before the end of the object");
    }
    gls_texuse_finish(&ctx->texuse, d);
    gls_insn end = {.op = GLS_OP_END};
    if (gls_unit_emit(ctx->u, &end, end_line))
        gls_error_at(d, (gls_loc){ctx->src, 0, 0}, "out of memory");
    sema_names_free(ctx);
}

/* Feed the scanner's tokens to the parser: the grammar's actions build the
 * tree and run what is complete (tree.c).  Returns the line count plus 1
 * (the line of the end), or 0 when out of memory. */
static unsigned parse(gls_parse *ctx, gls_arena *arena)
{
    const gls_source *src = ctx->src;
    ctx->arena = arena;
    ctx->leading_params = 1;
    /* a first allocation, so that releasing to the file's mark keeps a chunk */
    if (!gls_arena_alloc(arena, 1))
        return 0;
    ctx->file_mark = gls_arena_get_mark(arena);
    void *parser = glsParseAlloc(malloc, ctx);
    if (!parser)
        return 0;
    gls_lexer lx;
    gls_lexer_init(&lx, src->text, src->len);
    gls_tok t;
    int code;
    do {
        code = next_token(&lx, &t, ctx);
        ctx->prev = ctx->last;
        ctx->last = t;
        ctx->cur_major = code;
        glsParse(parser, code, t);
    } while (code != 0 && !ctx->stop && !ctx->d->stopped);
    glsParseFree(parser, free);
    return lx.line;
}

/* Move what a parameterised file's later runs need into keep. */
static void keep_tree(gls_parse *ctx, gls_arena *arena, unsigned end_line, gls_tree *keep)
{
    keep->arena = *arena;
    *arena = (gls_arena){0};
    keep->top = ctx->file.body;
    keep->syntax_errors = ctx->syntax_errors;
    keep->end_line = end_line;
    keep->nparams = ctx->nparams;
    for (unsigned i = 0; i < ctx->nparams; i++) {
        keep->pnames[i] = ctx->pnames[i];
        keep->defaults[i] = ctx->pvalues[i];
    }
}

int gls_compile_source_keep(gls_unit *u, gls_diag *d, gls_tree *keep, uint64_t *total)
{
    unsigned errors0 = d->errors;
    gls_parse *ctx = run_begin(u, d, total);
    if (!ctx)
        return -1;
    gls_arena arena = {0};
    unsigned end_line = parse(ctx, &arena);
    if (!end_line)
        out_of_memory(d, &u->src);
    run_end(ctx, end_line);
    if (keep && ctx->keep_tree && ctx->nparams)
        keep_tree(ctx, &arena, end_line, keep);
    gls_arena_free(&arena);
    free(ctx);
    return d->errors == errors0 ? 0 : -1;
}

int gls_compile_source(gls_unit *u, gls_diag *d)
{
    return gls_compile_source_keep(u, d, NULL, NULL);
}

int gls_parse_tree(const gls_source *src, gls_diag *d, gls_tree *out)
{
    unsigned errors0 = d->errors;
    gls_unit scratch = {.src = *src};
    gls_parse *ctx = run_begin(&scratch, d, NULL);
    if (!ctx)
        return -1;
    ctx->no_run = 1;
    gls_arena arena = {0};
    unsigned end_line = parse(ctx, &arena);
    if (!end_line)
        out_of_memory(d, src);
    /* the parameters' defaults: their statements come first */
    ctx->no_run = 0;
    for (const gls_stmt *s = ctx->file.body; s && s->kind == ST_PARAM; s = s->next)
        sema_run(ctx, s);
    sema_names_free(ctx);
    gls_texuse_finish(&ctx->texuse, d);
    keep_tree(ctx, &arena, end_line, out);
    free(ctx);
    return d->errors == errors0 ? 0 : -1;
}

int gls_run_tree(gls_unit *u, gls_diag *d, const gls_tree *t, const gls_named *binding, unsigned nbinding,
                 uint64_t *total)
{
    unsigned errors0 = d->errors;
    gls_parse *ctx = run_begin(u, d, total);
    if (!ctx)
        return -1;
    ctx->binding = binding;
    ctx->nbinding = nbinding;
    ctx->syntax_errors = t->syntax_errors;
    for (const gls_stmt *s = t->top; s && !ctx->stop && !d->stopped; s = s->next)
        sema_run(ctx, s);
    if (ctx->in_prim) /* a block left open by a syntax error */
        sema_block_close(ctx);
    run_end(ctx, t->end_line);
    free(ctx);
    return d->errors == errors0 ? 0 : -1;
}

void gls_tree_free(gls_tree *t)
{
    gls_arena_free(&t->arena);
    t->top = NULL;
}
