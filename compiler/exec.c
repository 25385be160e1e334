/* Running statements (spec/language.md 5, 7): an instruction's arguments
 * are evaluated and the instruction compiled (statements.c); a block is
 * opened, its statements run, closed; a constant or parameter is defined;
 * a repeat loop runs its body once per value of its variable.
 *
 * Loops unroll at compile time, so their size is bounded: every statement
 * run inside a loop, and every iteration, counts towards GLS_MAX_UNROLLED
 * per object and GLS_MAX_UNROLLED_TOTAL per compile; crossing either is one
 * error at the outermost loop, and nothing more of the object runs.  A loop also
 * stops after an iteration that reported an error, so that one mistake in
 * a body is not reported once per iteration. */
#include <math.h>
#include "numfmt.h"
#include "sema.h"

/* Count s against the loop budget (only inside loops).  0, or -1 when the
 * budget is spent (reported once). */
static int count(gls_parse *ctx)
{
    if (!ctx->loops)
        return 0;
    if (ctx->unroll_over)
        return -1;
    ctx->unrolled++;
    if (ctx->total_unrolled)
        ++*ctx->total_unrolled;
    gls_tok k = ctx->loop_tok;
    if (ctx->unrolled > GLS_MAX_UNROLLED)
        ERR(ctx, k.line, k.col, "'repeat' unrolls to more than %u statements in this object (the limit)",
            GLS_MAX_UNROLLED);
    else if (ctx->total_unrolled && *ctx->total_unrolled > GLS_MAX_UNROLLED_TOTAL)
        ERR(ctx, k.line, k.col, "'repeat' unrolls to more than %llu statements in all the objects of the scene",
            (unsigned long long)GLS_MAX_UNROLLED_TOTAL);
    else
        return 0;
    /* the object is cut short: nothing more of it runs, so that no error
       follows from what was cut off (an unbalanced push, a short block) */
    ctx->unroll_over = 1;
    ctx->stop = 1;
    return -1;
}

/* Stop running statements: an error that ends the file or the loops. */
static int halted(const gls_parse *ctx)
{
    return ctx->stop || ctx->d->stopped || (ctx->loops && ctx->unroll_over);
}

static void run_body(gls_parse *ctx, const gls_stmt *body)
{
    for (const gls_stmt *s = body; s && !halted(ctx); s = s->next)
        sema_run(ctx, s);
}

static void run_instr(gls_parse *ctx, const gls_stmt *s)
{
    ctx->nargs = 0;
    ctx->too_many_args = 0;
    for (const gls_expr *e = s->args.head; e; e = e->next) {
        /* keep counting past the last slot, so the message says how many */
        if (ctx->nargs >= GLS_MAX_ARGS)
            ctx->too_many_args = 1;
        else if (e->kind == EX_NUM) /* the common case, without a copy */
            ctx->args[ctx->nargs] = (gls_val){.kind = VAL_NUM, .num = e->num, .line = e->tok.line, .col = e->tok.col};
        else
            ctx->args[ctx->nargs] = sema_eval(ctx, e);
        ctx->nargs++;
    }
    sema_stmt(ctx, s->name, s->parens);
}

static void run_const(gls_parse *ctx, const gls_stmt *s)
{
    gls_val v = sema_eval(ctx, s->value);
    if (v.kind == VAL_ERR || !sema_need_number(ctx, &v))
        return;
    if (ctx->in_prim && !ctx->loops) {
        ERR(ctx, s->name.line, s->name.col, "'const' is not allowed inside a primitive block");
        return;
    }
    sema_define(ctx, NAME_CONST, s->name, v.num);
}

/* A parameter: its value from the binding, else its default (which may
 * not use names: it is the same for every run). */
static void run_param(gls_parse *ctx, const gls_stmt *s)
{
    gls_tok n = s->name;
    if (ctx->other_stmt_run || ctx->loops || ctx->in_prim) {
        ERR(ctx, s->kw.line, s->kw.col, "'param' must come before every other statement of the file");
        return;
    }
    if (ctx->nparams >= GLS_MAX_PARAMS) {
        ERR(ctx, n.line, n.col, "an object may have at most %u parameters", GLS_MAX_PARAMS);
        return;
    }
    double value = 0;
    int bound = 0;
    for (unsigned i = 0; i < ctx->nbinding && !bound; i++)
        if (sema_tok_is(n, ctx->binding[i].name)) {
            value = ctx->binding[i].value;
            bound = 1;
        }
    if (!bound) {
        ctx->in_default = 1;
        gls_val v = sema_eval(ctx, s->value);
        ctx->in_default = 0;
        if (v.kind == VAL_ERR || !sema_need_number(ctx, &v))
            return;
        value = v.num;
    }
    if (sema_define(ctx, NAME_PARAM, n, value))
        return;
    ctx->pnames[ctx->nparams] = n;
    ctx->pvalues[ctx->nparams++] = value;
}

/* The bounds of a loop: whole numbers within 2^53 (so that the values of
 * the variable are exact), a step other than 0.  0, or -1 after an error. */
static int loop_bounds(gls_parse *ctx, const gls_stmt *s, int64_t b[3])
{
    static const char *const what[] = {"start", "end", "step"};
    int ok = 1, i = 0;
    b[2] = 1;
    for (const gls_expr *e = s->args.head; e && i < 3; e = e->next, i++) {
        gls_val v = sema_eval(ctx, e);
        if (v.kind == VAL_ERR || !sema_need_number(ctx, &v)) {
            ok = 0;
            continue;
        }
        char num[40];
        gls_fmt_double(num, sizeof num, v.num);
        if (v.num != floor(v.num) || fabs(v.num) > 9007199254740992.0) {
            ERR(ctx, v.line, v.col, "the %s of 'repeat' must be a whole number (at most 2^53), not %s", what[i], num);
            ok = 0;
        } else if (i == 2 && v.num == 0) {
            ERR(ctx, v.line, v.col, "the step of 'repeat' must not be 0");
            ok = 0;
        } else {
            b[i] = (int64_t)v.num;
        }
    }
    return ok ? 0 : -1;
}

static void run_repeat(gls_parse *ctx, const gls_stmt *s)
{
    int64_t b[3] = {0, 0, 1};
    if (s->args.n < 2 || s->args.n > 3 || loop_bounds(ctx, s, b))
        return; /* a wrong count was reported when it was parsed */
    /* the variable takes start, start + step, ... while before end */
    int64_t start = b[0], end = b[1], step = b[2], n = 0;
    if (step > 0 && end > start)
        n = (end - start + step - 1) / step;
    else if (step < 0 && end < start)
        n = (start - end - step - 1) / -step;
    if (!ctx->loops)
        ctx->loop_tok = s->kw;
    ctx->loops++;
    /* the variable is defined (and checked) at the first iteration and
       only changes its value after: defining it again each time made an
       empty loop cost about 0.4 us per iteration (the check of reserved
       words), so that a loop cut at the unroll limit ran for seconds */
    size_t var = sema_scope_mark(ctx);
    for (int64_t k = 0; k < n && !halted(ctx); k++) {
        if (count(ctx))
            break;
        double value = (double)(start + k * step);
        unsigned errors = ctx->d->errors;
        if (k == 0 && sema_define(ctx, NAME_LOOP, s->name, value))
            break;
        sema_set_value(ctx, var, value);
        size_t body = sema_scope_mark(ctx);
        run_body(ctx, s->body);
        sema_scope_end(ctx, body);
        if (ctx->d->errors != errors)
            break;
    }
    sema_scope_end(ctx, var);
    ctx->loops--;
}

void sema_run(gls_parse *ctx, const gls_stmt *s)
{
    if (halted(ctx) || count(ctx))
        return;
    if (s->kind != ST_PARAM)
        ctx->other_stmt_run = 1;
    switch (s->kind) {
    case ST_INSTR: run_instr(ctx, s); break;
    case ST_CONST: run_const(ctx, s); break;
    case ST_PARAM: run_param(ctx, s); break;
    case ST_REPEAT: run_repeat(ctx, s); break;
    case ST_BLOCK:
        sema_block_open(ctx, s->name);
        run_body(ctx, s->body);
        sema_block_close(ctx);
        break;
    }
}
