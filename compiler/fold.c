/* Numbers, names and constant expressions (spec/language.md 3, 5): the
 * value of a number token, what a name stands for while a file runs
 * (constants, parameters, loop variables, pi) and the scopes of loop
 * bodies, and the evaluation of an expression tree to a double. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "mathfn.h"
#include "sema.h"

static unsigned hash_name(const char *s, size_t n)
{
    unsigned h = 2166136261u;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h % GLS_MAX_CONSTS_BUCKETS;
}

static gls_const *find_name(const gls_parse *ctx, const char *s, size_t n)
{
    for (gls_const *c = ctx->consts[hash_name(s, n)]; c; c = c->next)
        if (c->len == n && memcmp(c->name, s, n) == 0)
            return c;
    return NULL;
}

static const char *const kind_word[] = {[NAME_CONST] = "constant", [NAME_PARAM] = "parameter",
                                        [NAME_LOOP] = "loop variable"};

/* Why name cannot be defined whatever is defined already: a word of the
 * language (instruction, primitive, keyword, texture mode, pi).  Function
 * names are free: a function is only ever followed by '('. */
static int reserved(gls_parse *ctx, int kind, gls_tok name)
{
    /* Which hash buckets hold a word of the language: a name in another
       bucket is none of them, without comparing it with each (a constant
       in a loop body is defined once per iteration).  Filled on first
       use; the words never change. */
    static unsigned char word_bucket[GLS_MAX_CONSTS_BUCKETS], filled;
    if (!filled) {
        for (size_t i = 0; i < sema_nwords; i++)
            word_bucket[hash_name(sema_words[i], strlen(sema_words[i]))] = 1;
        for (unsigned m = 0; m < GLS_MODE_COUNT; m++)
            word_bucket[hash_name(gls_texmode_name[m], strlen(gls_texmode_name[m]))] = 1;
        filled = 1;
    }
    const char *what = kind_word[kind];
    if (word_bucket[hash_name(name.p, name.len)]) {
        for (size_t i = 0; i < sema_nwords; i++)
            if (sema_tok_is(name, sema_words[i])) {
                ERR(ctx, name.line, name.col, "'%s' is an instruction name and cannot be a %s", sema_words[i], what);
                return 1;
            }
        for (unsigned m = 0; m < GLS_MODE_COUNT; m++)
            if (sema_tok_is(name, gls_texmode_name[m])) {
                ERR(ctx, name.line, name.col, "'%s' is a texture mode and cannot be a %s", gls_texmode_name[m], what);
                return 1;
            }
    }
    double v;
    if (gls_builtin_const(name.p, name.len, &v)) {
        ERR(ctx, name.line, name.col, "'%.*s' is built in and cannot be a %s", (int)name.len, name.p, what);
        return 1;
    }
    return 0;
}

int sema_define(gls_parse *ctx, int kind, gls_tok name, double v)
{
    if (reserved(ctx, kind, name))
        return -1;
    if (find_name(ctx, name.p, name.len)) {
        ERR(ctx, name.line, name.col, "%s '%.*s' is already defined", kind_word[kind], (int)name.len, name.p);
        return -1;
    }
    gls_const *c = malloc(sizeof *c);
    if (!c || gls_grow(&ctx->defined, &ctx->defined_cap, ctx->ndefined + 1, sizeof *ctx->defined)) {
        free(c);
        ERR(ctx, name.line, name.col, "out of memory");
        ctx->stop = 1;
        return -1;
    }
    unsigned h = hash_name(name.p, name.len);
    *c = (gls_const){name.p, name.len, v, kind, ctx->consts[h]};
    ctx->consts[h] = c;
    ctx->defined[ctx->ndefined++] = c;
    return 0;
}

void sema_set_value(gls_parse *ctx, size_t mark, double v)
{
    if (mark < ctx->ndefined)
        ctx->defined[mark]->value = v;
}

size_t sema_scope_mark(const gls_parse *ctx)
{
    return ctx->ndefined;
}

/* Undefine the names defined since mark, newest first: each is then the
 * head of its bucket. */
void sema_scope_end(gls_parse *ctx, size_t mark)
{
    while (ctx->ndefined > mark) {
        gls_const *c = ctx->defined[--ctx->ndefined];
        ctx->consts[hash_name(c->name, c->len)] = c->next;
        free(c);
    }
}

void sema_names_free(gls_parse *ctx)
{
    sema_scope_end(ctx, 0);
    free(ctx->defined);
    ctx->defined = NULL;
    ctx->defined_cap = 0;
}

/* Clinger's fast path: a decimal with at most 15 significant digits and a
 * power of ten up to 22 is one correctly rounded IEEE operation on two
 * exactly representable doubles, so it equals strtod's result.  Anything
 * else goes to strtod.  Returns 0 if the fast path does not apply. */
static int fast_decimal(const char *p, size_t len, double *out)
{
    static const double pow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                   1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    uint64_t m = 0;
    int digits = 0, frac = 0, seen_dot = 0;
    size_t i = 0;
    for (; i < len; i++) {
        char ch = p[i];
        if (ch == '.') {
            seen_dot = 1;
            continue;
        }
        if (ch < '0' || ch > '9')
            break;
        if (m == 0 && ch == '0') {
            if (seen_dot)
                frac++;
            continue; /* leading zeros are not significant */
        }
        if (++digits > 15)
            return 0;
        m = m * 10 + (uint64_t)(ch - '0');
        if (seen_dot)
            frac++;
    }
    if (i != len)
        return 0; /* an exponent: leave it to strtod */
    if (frac > 22)
        return 0;
    *out = frac ? (double)m / pow10[frac] : (double)m;
    return 1;
}

int sema_parse_number(gls_parse *ctx, gls_tok t, double *v)
{
    if (fast_decimal(t.p, t.len, v))
        return 0;
    char *end;
    errno = 0;
    *v = strtod(t.p, &end);
    if (end != t.p + t.len)
        return 1; /* the lexer reported the malformed number */
    if (!isfinite(*v)) {
        ERR(ctx, t.line, t.col, "number '%.*s' is not finite (outside the range of a double)", (int)t.len, t.p);
        return -1;
    }
    return 0;
}

int sema_need_number(gls_parse *ctx, const gls_val *a)
{
    if (a->kind == VAL_NUM)
        return 1;
    if (a->kind == VAL_WORD)
        ERR(ctx, a->line, a->col, "unknown constant '%.*s'", (int)a->len, a->s);
    else if (a->kind == VAL_STR)
        ERR(ctx, a->line, a->col, "a string cannot be used in arithmetic");
    return 0;
}

static gls_val at(int kind, gls_tok t)
{
    gls_val v = {.kind = kind, .s = t.p, .len = t.len, .line = t.line, .col = t.col};
    return v;
}

/* A name: a constant, parameter or loop variable, pi, or else a bare word
 * (texmode's argument; "unknown constant" where a number is needed).  In
 * a parameter's default no name of the file may be used. */
static gls_val eval_ident(gls_parse *ctx, gls_tok t)
{
    gls_val v = at(VAL_WORD, t);
    const gls_const *c = find_name(ctx, t.p, t.len);
    if (c && ctx->in_default) {
        ERR(ctx, t.line, t.col, "a parameter's default cannot use '%.*s': it must be a constant expression of numbers",
            (int)t.len, t.p);
        v.kind = VAL_ERR;
    } else if (c) {
        v.kind = VAL_NUM;
        v.num = c->value;
    } else if (gls_builtin_const(t.p, t.len, &v.num)) {
        v.kind = VAL_NUM;
    }
    return v;
}

static gls_val eval_op(gls_parse *ctx, const gls_expr *e)
{
    gls_val a = sema_eval(ctx, e->a);
    if (e->kind == EX_UNARY) {
        gls_val r = a;
        r.line = e->tok.line;
        r.col = e->tok.col;
        if (!sema_need_number(ctx, &a))
            r.kind = VAL_ERR;
        else if (e->op == '-')
            r.num = -a.num;
        return r;
    }
    gls_val b = sema_eval(ctx, e->b);
    gls_val r = {.kind = VAL_NUM, .line = a.line, .col = a.col};
    int ok = sema_need_number(ctx, &a);
    ok &= sema_need_number(ctx, &b);
    if (!ok) {
        r.kind = VAL_ERR;
        return r;
    }
    switch (e->op) {
    case '+': r.num = a.num + b.num; break;
    case '-': r.num = a.num - b.num; break;
    case '*': r.num = a.num * b.num; break;
    default:
        if (b.num == 0) {
            ERR(ctx, e->tok.line, e->tok.col, "division by zero");
            r.kind = VAL_ERR;
            return r;
        }
        r.num = a.num / b.num;
        break;
    }
    if (!isfinite(r.num)) {
        ERR(ctx, e->tok.line, e->tok.col, "result of '%c' is not finite", e->op);
        r.kind = VAL_ERR;
    }
    return r;
}

/* A function: its arguments, then the function (tree.c checked its name
 * and argument count); errors at the function's name. */
static gls_val eval_fn(gls_parse *ctx, const gls_expr *e)
{
    gls_val r = at(VAL_NUM, e->tok);
    double x[GLS_MAX_FN_ARGS];
    unsigned n = 0;
    int ok = 1;
    for (const gls_expr *a = e->a; a && n < GLS_MAX_FN_ARGS; a = a->next) {
        gls_val v = sema_eval(ctx, a);
        ok &= sema_need_number(ctx, &v);
        x[n++] = v.num;
    }
    if (!ok) {
        r.kind = VAL_ERR;
        return r;
    }
    char why[160];
    const char *msg = gls_fn_eval(e->fn, x, n, &r.num, why, sizeof why);
    if (msg) {
        ERR(ctx, e->tok.line, e->tok.col, "%s", msg);
        r.kind = VAL_ERR;
    }
    return r;
}

gls_val sema_eval(gls_parse *ctx, const gls_expr *e)
{
    gls_val v = {.kind = VAL_ERR};
    if (!e)
        return v; /* out of memory while parsing: reported */
    switch (e->kind) {
    case EX_NUM:
        v = at(VAL_NUM, e->tok);
        v.num = e->num;
        return v;
    case EX_STR: return at(VAL_STR, e->tok);
    case EX_IDENT: return eval_ident(ctx, e->tok);
    case EX_UNARY:
    case EX_BINARY: return eval_op(ctx, e);
    case EX_CALL: return eval_fn(ctx, e);
    case EX_NAMED:
        v = sema_eval(ctx, e->a);
        v.pname = &e->tok;
        return v;
    case EX_ERR: return at(VAL_ERR, e->tok);
    }
    return v;
}
