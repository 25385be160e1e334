/* Building the syntax tree as the grammar reduces (ast.h), and running
 * each statement as soon as it is complete when no repeat loop is open
 * (its statements run when the outermost loop is complete).  A primitive
 * block outside loops runs as it is parsed: opened at its '{', each of its
 * statements as it comes, closed at its '}'.  Unless the file declares
 * parameters (its tree is then kept and run again, template.c), the nodes
 * of a statement that has run are released at once, so a large flat file
 * never holds more than one statement's nodes.  Checks that do not depend
 * on values (function names and argument counts, the form of repeat) are
 * made here, once, at parse time. */
#include "mathfn.h"
#include "sema.h"

static void out_of_memory(gls_parse *ctx, gls_tok t)
{
    ERR(ctx, t.line, t.col, "out of memory");
    ctx->stop = 1;
}

static gls_expr *expr(gls_parse *ctx, gls_expr_kind kind, gls_tok t)
{
    gls_expr *e = gls_ast_expr(ctx->arena, kind, t);
    if (!e)
        out_of_memory(ctx, t);
    return e;
}

static gls_stmt *stmt(gls_parse *ctx, gls_stmt_kind kind, gls_tok name)
{
    gls_stmt *s = gls_ast_stmt(ctx->arena, kind, name);
    if (!s)
        out_of_memory(ctx, name);
    return s;
}

gls_expr *sema_number(gls_parse *ctx, gls_tok t)
{
    gls_expr *e = expr(ctx, EX_NUM, t);
    if (e && sema_parse_number(ctx, t, &e->num))
        e->kind = EX_ERR;
    return e;
}

gls_expr *sema_leaf(gls_parse *ctx, gls_expr_kind kind, gls_tok t)
{
    return expr(ctx, kind, t);
}

gls_expr *sema_op(gls_parse *ctx, char op, gls_tok optok, gls_expr *a, gls_expr *b)
{
    gls_expr *e = expr(ctx, b ? EX_BINARY : EX_UNARY, optok);
    if (e) {
        e->op = op;
        e->a = a;
        e->b = b;
    }
    return e;
}

gls_expr *sema_named(gls_parse *ctx, gls_tok name, gls_expr *value)
{
    gls_expr *e = expr(ctx, EX_NAMED, name);
    if (e)
        e->a = value;
    return e;
}

gls_elist sema_list(gls_parse *ctx, gls_elist l, gls_expr *e)
{
    (void)ctx;
    gls_elist_add(&l, e);
    return l;
}

/* "'atan2' takes 2 arguments, got 1": the wording of instructions' counts */
static void count_error(gls_parse *ctx, gls_tok t, const char *name, unsigned min, unsigned max, unsigned n)
{
    if (min == max)
        ERR(ctx, t.line, t.col, "'%s' takes %u argument%s, got %u", name, min, min == 1 ? "" : "s", n);
    else if (max == min + 1)
        ERR(ctx, t.line, t.col, "'%s' takes %u or %u arguments, got %u", name, min, max, n);
    else
        ERR(ctx, t.line, t.col, "'%s' takes %u to %u arguments, got %u", name, min, max, n);
}

gls_expr *sema_fn(gls_parse *ctx, gls_tok name, gls_elist args)
{
    int fn = gls_fn_find(name.p, name.len);
    if (fn < 0) {
        const char *s = gls_suggest(name.p, name.len, gls_fn_names, (size_t)-1);
        if (s)
            ERR(ctx, name.line, name.col, "unknown function '%.*s'; did you mean '%s'?", (int)name.len, name.p, s);
        else
            ERR(ctx, name.line, name.col, "unknown function '%.*s'", (int)name.len, name.p);
        return expr(ctx, EX_ERR, name);
    }
    if (args.n < gls_fn_min_args(fn) || args.n > gls_fn_max_args(fn)) {
        count_error(ctx, name, gls_fn_name(fn), gls_fn_min_args(fn), gls_fn_max_args(fn), args.n);
        return expr(ctx, EX_ERR, name);
    }
    gls_expr *e = expr(ctx, EX_CALL, name);
    if (e) {
        e->fn = fn;
        e->a = args.head;
        e->nargs = args.n;
    }
    return e;
}

gls_stmt *sema_instr_stmt(gls_parse *ctx, gls_tok name, int parens, gls_elist args)
{
    gls_stmt *s = stmt(ctx, ST_INSTR, name);
    if (s) {
        s->parens = parens;
        s->args = args;
    }
    return s;
}

gls_stmt *sema_const(gls_parse *ctx, gls_tok kw, gls_tok name, gls_expr *value, int is_param)
{
    gls_stmt *s = stmt(ctx, is_param ? ST_PARAM : ST_CONST, name);
    if (s) {
        s->kw = kw;
        s->value = value;
    }
    return s;
}

/* Is a statement being parsed to run now?  Not inside a loop, and not
 * when only parsing. */
static int streaming(const gls_parse *ctx)
{
    return !ctx->no_run && ctx->open_repeats == 0;
}

static gls_stmt *open_node(gls_parse *ctx, gls_stmt *s, int repeat, gls_tok at)
{
    if (!s)
        return NULL;
    if (ctx->nopen == GLS_MAX_OPEN) {
        ERR(ctx, at.line, at.col, "blocks and loops nested too deeply");
        ctx->stop = 1;
        return NULL;
    }
    ctx->open[ctx->nopen++] = (gls_open){s, repeat, gls_arena_get_mark(ctx->arena)};
    ctx->open_repeats += repeat;
    return s;
}

gls_stmt *sema_block_begin(gls_parse *ctx, gls_tok name)
{
    int run = streaming(ctx);
    gls_stmt *s = open_node(ctx, stmt(ctx, ST_BLOCK, name), 0, name);
    if (s && run) {
        ctx->other_stmt_run = 1;
        sema_block_open(ctx, name);
    }
    return s;
}

gls_stmt *sema_repeat_begin(gls_parse *ctx, gls_tok kw, gls_tok var, gls_elist bounds)
{
    gls_stmt *s = stmt(ctx, ST_REPEAT, var);
    if (!s)
        return NULL;
    s->kw = kw;
    s->args = bounds;
    if (bounds.n > 3)
        ERR(ctx, kw.line, kw.col, "'repeat' takes a variable and 2 or 3 numbers (start, end, step), got %u numbers",
            bounds.n);
    else if (bounds.n < 2)
        ERR(ctx, kw.line, kw.col, "'repeat' takes a variable and 2 or 3 numbers (start, end, step), got %u number",
            bounds.n);
    return open_node(ctx, s, 1, kw);
}

gls_stmt *sema_open_end(gls_parse *ctx, gls_stmt *node, gls_tok rbrace)
{
    (void)rbrace;
    if (!node)
        return NULL;
    /* the innermost open one, always (the parser's recovery never pops a
       block it is inside of before the end of the file) */
    while (ctx->nopen) {
        gls_open o = ctx->open[--ctx->nopen];
        ctx->open_repeats -= o.repeat;
        if (o.node == node)
            break;
    }
    return node;
}

/* A statement is complete: keep it in its parent if it may run again or
 * later, run it if it is to run now, report a missing ';' after it, and
 * release what it no longer needs. */
void sema_stmt_done(gls_parse *ctx, gls_stmt *s)
{
    if (s) {
        gls_stmt *parent = ctx->nopen ? ctx->open[ctx->nopen - 1].node : &ctx->file;
        if (!ctx->nopen) {
            /* parameters come first: a file that starts with one is kept */
            if (ctx->leading_params && s->kind == ST_PARAM)
                ctx->keep_tree = 1;
            else
                ctx->leading_params = 0;
        }
        if (ctx->keep_tree || ctx->no_run || ctx->open_repeats)
            gls_stmt_add(parent, s);
        if (streaming(ctx)) {
            if (s->kind == ST_BLOCK)
                sema_block_close(ctx); /* opened and filled as it was parsed */
            else
                sema_run(ctx, s);
        }
    }
    sema_report_missing_semi(ctx);
    if (streaming(ctx) && !ctx->keep_tree)
        gls_arena_release(ctx->arena, ctx->nopen ? ctx->open[ctx->nopen - 1].mark : ctx->file_mark);
}
