/* Numbers, named constants and constant expressions (spec/language.md 3,
 * 5): every expression is folded to a double as it is reduced, so only
 * numbers reach the instructions. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "sema.h"

static unsigned hash_name(const char *s, size_t n)
{
    unsigned h = 2166136261u;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h % GLS_MAX_CONSTS_BUCKETS;
}

static gls_const *find_const(gls_parse *ctx, const char *s, size_t n)
{
    for (gls_const *c = ctx->consts[hash_name(s, n)]; c; c = c->next)
        if (c->len == n && memcmp(c->name, s, n) == 0)
            return c;
    return NULL;
}

void sema_const(gls_parse *ctx, gls_tok name, gls_val v)
{
    if (v.kind == VAL_ERR)
        return;
    if (v.kind == VAL_WORD) {
        ERR(ctx, v.line, v.col, "unknown constant '%.*s'", (int)v.len, v.s);
        return;
    }
    if (ctx->in_prim) {
        ERR(ctx, name.line, name.col, "'const' is not allowed inside a primitive block");
        return;
    }
    for (size_t i = 0; i < sema_nwords; i++)
        if (sema_tok_is(name, sema_words[i])) {
            ERR(ctx, name.line, name.col, "'%s' is an instruction name and cannot be a constant", sema_words[i]);
            return;
        }
    for (unsigned m = 0; m < GLS_MODE_COUNT; m++)
        if (sema_tok_is(name, gls_texmode_name[m])) {
            ERR(ctx, name.line, name.col, "'%s' is a texture mode and cannot be a constant", gls_texmode_name[m]);
            return;
        }
    if (find_const(ctx, name.p, name.len)) {
        ERR(ctx, name.line, name.col, "constant '%.*s' is already defined", (int)name.len, name.p);
        return;
    }
    gls_const *c = malloc(sizeof *c);
    if (!c) {
        ERR(ctx, name.line, name.col, "out of memory");
        return;
    }
    unsigned h = hash_name(name.p, name.len);
    *c = (gls_const){name.p, name.len, v.num, ctx->consts[h]};
    ctx->consts[h] = c;
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

gls_val sema_number(gls_parse *ctx, gls_tok t)
{
    gls_val v = {.kind = VAL_NUM, .line = t.line, .col = t.col};
    if (fast_decimal(t.p, t.len, &v.num))
        return v;
    char *end;
    errno = 0;
    v.num = strtod(t.p, &end);
    if (end != t.p + t.len) {
        v.kind = VAL_ERR; /* the lexer reported the malformed number */
        return v;
    }
    if (!isfinite(v.num)) {
        ERR(ctx, t.line, t.col, "number '%.*s' is not finite (outside the range of a double)", (int)t.len, t.p);
        v.kind = VAL_ERR;
    }
    return v;
}

gls_val sema_string(gls_parse *ctx, gls_tok t)
{
    (void)ctx;
    gls_val v = {.kind = VAL_STR, .s = t.p, .len = t.len, .line = t.line, .col = t.col};
    return v;
}

gls_val sema_ident(gls_parse *ctx, gls_tok t)
{
    gls_val v = {.kind = VAL_WORD, .s = t.p, .len = t.len, .line = t.line, .col = t.col};
    gls_const *c = find_const(ctx, t.p, t.len);
    if (c) {
        v.kind = VAL_NUM;
        v.num = c->value;
    }
    return v;
}

static int need_number(gls_parse *ctx, const gls_val *a)
{
    if (a->kind == VAL_NUM)
        return 1;
    if (a->kind == VAL_WORD)
        ERR(ctx, a->line, a->col, "unknown constant '%.*s'", (int)a->len, a->s);
    else if (a->kind == VAL_STR)
        ERR(ctx, a->line, a->col, "a string cannot be used in arithmetic");
    return 0;
}

gls_val sema_unary(gls_parse *ctx, char op, gls_val a, gls_tok optok)
{
    gls_val r = a;
    r.line = optok.line;
    r.col = optok.col;
    if (!need_number(ctx, &a)) {
        r.kind = VAL_ERR;
        return r;
    }
    if (op == '-')
        r.num = -a.num;
    return r;
}

gls_val sema_binary(gls_parse *ctx, char op, gls_val a, gls_val b, gls_tok optok)
{
    gls_val r = {.kind = VAL_NUM, .line = a.line, .col = a.col};
    int ok = need_number(ctx, &a);
    ok &= need_number(ctx, &b);
    if (!ok) {
        r.kind = VAL_ERR;
        return r;
    }
    switch (op) {
    case '+': r.num = a.num + b.num; break;
    case '-': r.num = a.num - b.num; break;
    case '*': r.num = a.num * b.num; break;
    default:
        if (b.num == 0) {
            ERR(ctx, optok.line, optok.col, "division by zero");
            r.kind = VAL_ERR;
            return r;
        }
        r.num = a.num / b.num;
        break;
    }
    if (!isfinite(r.num)) {
        ERR(ctx, optok.line, optok.col, "result of '%c' is not finite", op);
        r.kind = VAL_ERR;
    }
    return r;
}
