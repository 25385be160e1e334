/* Semantic actions of the scene language: called by the lemon grammar as
 * it reduces, they check each statement and emit bytecode into the unit.
 * Numbers are folded here, in double precision. */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "grammar.h"
#include "parse.h"

#define ERR(ctx, line, col, ...) gls_error_at((ctx)->d, gls_tok_loc((ctx), (line), (col)), __VA_ARGS__)

/* ---- instruction table -------------------------------------------------- */

enum { WHERE_OUTSIDE, WHERE_PRIM };
typedef void (*handler_fn)(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n);

static void h_vert(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_col(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_tex(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_color(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_texmode(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_texture(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_notexture(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_trans(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_rot(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_scale(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_transform(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_push(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_pop(gls_parse *, gls_tok, const gls_val *, unsigned);
static void h_call(gls_parse *, gls_tok, const gls_val *, unsigned);

/* kinds: one letter per argument position: n number, s string, w word */
static const struct instr {
    const char *name;
    unsigned min, max;
    const char *kinds;
    int where;
    handler_fn fn;
} instrs[] = {
    {"vert", 1, 4, "nnnn", WHERE_PRIM, h_vert},
    {"col", 3, 4, "nnnn", WHERE_PRIM, h_col},
    {"tex", 2, 2, "nn", WHERE_PRIM, h_tex},
    {"color", 3, 4, "nnnn", WHERE_OUTSIDE, h_color},
    {"texmode", 1, 1, "w", WHERE_OUTSIDE, h_texmode},
    {"texture", 1, 1, "s", WHERE_OUTSIDE, h_texture},
    {"notexture", 0, 0, "", WHERE_OUTSIDE, h_notexture},
    {"trans", 3, 3, "nnn", WHERE_OUTSIDE, h_trans},
    {"rot", 4, 4, "nnnn", WHERE_OUTSIDE, h_rot},
    {"scale", 1, 3, "nnn", WHERE_OUTSIDE, h_scale},
    {"transform", 16, 16, "nnnnnnnnnnnnnnnn", WHERE_OUTSIDE, h_transform},
    {"push", 0, 0, "", WHERE_OUTSIDE, h_push},
    {"pop", 0, 0, "", WHERE_OUTSIDE, h_pop},
    {"call", 1, 1, "s", WHERE_OUTSIDE, h_call},
};
#define NINSTRS (sizeof instrs / sizeof instrs[0])

static const char *const all_words[] = {"vert", "col", "tex", "color", "texmode", "texture", "notexture",
                                        "trans", "rot", "scale", "transform", "push", "pop", "call",
                                        "poly", "qstrip", "tstrip", "tfan", "const"};

/* Names people bring from OpenGL and other scene languages, for "did you
 * mean" (gls_suggest_alias also takes their OpenGL spellings: glRotatef,
 * glVertex3f, glPushMatrix, glTexCoord2f, glColor3ub, glMultMatrixd, ...).
 * The real names are the keys of instrs[] and gls_prim_name. */
static const gls_alias aliases[] = {
    {"rotate", "rot"},          {"rotation", "rot"},
    {"translate", "trans"},     {"translation", "trans"},   {"move", "trans"},
    {"scaling", "scale"},       {"scl", "scale"},
    {"vertex", "vert"},         {"point", "vert"},
    {"colour", "color"},        {"rgb", "color"},           {"rgba", "color"},
    {"texcoord", "tex"},        {"texcoords", "tex"},       {"uv", "tex"},
    {"bindtexture", "texture"}, {"settexture", "texture"},
    {"texenv", "texmode"},      {"texturemode", "texmode"}, {"texture_mode", "texmode"},
    {"notex", "notexture"},     {"untexture", "notexture"}, {"disabletexture", "notexture"},
    {"pushmatrix", "push"},     {"save", "push"},           {"popmatrix", "pop"},          {"restore", "pop"},
    {"multmatrix", "transform"}, {"matrix", "transform"},
    {"include", "call"},        {"import", "call"},         {"use", "call"},               {"instance", "call"},
    {"define", "const"},        {"let", "const"},           {"var", "const"},
    {"begin", "poly"},          {"polygon", "poly"},        {"triangle", "poly"},          {"triangles", "poly"},
    {"quad", "poly"},           {"quads", "poly"},
    {"quadstrip", "qstrip"},    {"quad_strip", "qstrip"},
    {"trianglestrip", "tstrip"}, {"triangle_strip", "tstrip"}, {"tristrip", "tstrip"},
    {"trianglefan", "tfan"},    {"triangle_fan", "tfan"},   {"trifan", "tfan"},
};
#define NALIASES (sizeof aliases / sizeof aliases[0])

static int tok_is(gls_tok t, const char *s)
{
    size_t n = strlen(s);
    return t.len == n && memcmp(t.p, s, n) == 0;
}

static int prim_kind_of(gls_tok t)
{
    for (int k = 0; k < GLS_PRIM_COUNT; k++)
        if (tok_is(t, gls_prim_name[k]))
            return k;
    return -1;
}

static void emit(gls_parse *ctx, gls_insn *in, unsigned line)
{
    if (gls_unit_emit(ctx->u, in, line))
        ERR(ctx, line, 1, "out of memory");
}

/* An instruction whose operands are all numbers: d holds them in order. */
static void emit_d(gls_parse *ctx, gls_opcode op, const double *d, unsigned line)
{
    gls_insn in = {.op = op};
    memcpy(in.d, d, gls_op[op].noperands * sizeof *d);
    emit(ctx, &in, line);
}

/* An instruction with one integer operand, at position arg. */
static void emit_u(gls_parse *ctx, gls_opcode op, unsigned arg, uint32_t v, unsigned line)
{
    gls_insn in = {.op = op};
    in.u[arg] = v;
    emit(ctx, &in, line);
}

/* ---- statements ----------------------------------------------------------- */

static void describe_kind(const gls_val *v, char *buf, size_t n)
{
    if (v->kind == VAL_STR)
        snprintf(buf, n, "a string");
    else if (v->kind == VAL_WORD)
        snprintf(buf, n, "the word '%.*s'", (int)v->len, v->s);
    else
        snprintf(buf, n, "a number");
}

void sema_stmt(gls_parse *ctx, gls_tok name, int parens)
{
    unsigned n = ctx->nargs;
    int too_many = ctx->too_many_args;
    ctx->nargs = 0;
    ctx->too_many_args = 0;
    (void)parens;

    const struct instr *ins = NULL;
    for (size_t i = 0; i < NINSTRS; i++)
        if (tok_is(name, instrs[i].name)) {
            ins = &instrs[i];
            break;
        }
    if (!ins) {
        if (prim_kind_of(name) >= 0) {
            ERR(ctx, name.line, name.col, "'%.*s' is a primitive block: write %.*s { vert(...); ... }",
                (int)name.len, name.p, (int)name.len, name.p);
            return;
        }
        const char *s =
            gls_suggest_alias(name.p, name.len, all_words, sizeof all_words / sizeof all_words[0], aliases, NALIASES);
        if (s)
            ERR(ctx, name.line, name.col, "unknown instruction '%.*s'; did you mean '%s'?", (int)name.len, name.p, s);
        else
            ERR(ctx, name.line, name.col, "unknown instruction '%.*s'", (int)name.len, name.p);
        return;
    }
    if (ins->where == WHERE_PRIM && !ctx->in_prim) {
        ERR(ctx, name.line, name.col, "'%s' is only allowed inside a primitive block (poly, qstrip, tstrip, tfan)",
            ins->name);
        return;
    }
    if (ins->where == WHERE_OUTSIDE && ctx->in_prim) {
        ERR(ctx, name.line, name.col, "'%s' is not allowed inside a primitive block", ins->name);
        return;
    }
    if (too_many || n < ins->min || n > ins->max || (ins->fn == h_scale && n == 2)) {
        if (ins->fn == h_scale)
            ERR(ctx, name.line, name.col, "'scale' takes 1 or 3 arguments, got %u", n);
        else if (ins->min == ins->max)
            ERR(ctx, name.line, name.col, "'%s' takes %u argument%s, got %u", ins->name, ins->min,
                ins->min == 1 ? "" : "s", n);
        else
            ERR(ctx, name.line, name.col, "'%s' takes %u to %u arguments, got %u", ins->name, ins->min, ins->max, n);
        return;
    }
    const gls_val *a = ctx->args;
    for (unsigned i = 0; i < n; i++) {
        char want = ins->kinds[i];
        if (a[i].kind == VAL_ERR)
            return; /* already reported */
        int ok = (want == 'n' && a[i].kind == VAL_NUM) || (want == 's' && a[i].kind == VAL_STR) ||
                 (want == 'w' && a[i].kind == VAL_WORD);
        if (ok)
            continue;
        if (want == 'n' && a[i].kind == VAL_WORD) {
            ERR(ctx, a[i].line, a[i].col, "unknown constant '%.*s'", (int)a[i].len, a[i].s);
            return;
        }
        char got[128];
        describe_kind(&a[i], got, sizeof got);
        ERR(ctx, a[i].line, a[i].col, "argument %u of '%s' must be %s, not %s", i + 1, ins->name,
            want == 'n' ? "a number" : want == 's' ? "a quoted name" : "a word", got);
        return;
    }
    ins->fn(ctx, name, a, n);
}

static int check_unit_range(gls_parse *ctx, const gls_val *a, unsigned n, const char *what)
{
    for (unsigned i = 0; i < n; i++)
        if (a[i].num < 0 || a[i].num > 1) {
            ERR(ctx, a[i].line, a[i].col, "%s component %g is outside 0..1", what, a[i].num);
            return -1;
        }
    return 0;
}

static int grow(void **arr, uint32_t *cap, uint32_t need, size_t elem)
{
    if (need <= *cap)
        return 0;
    uint32_t c = *cap ? *cap : 64;
    while (c < need) {
        if (c > UINT32_MAX / 2)
            return -1;
        c *= 2;
    }
    void *p = realloc(*arr, (size_t)c * elem);
    if (!p)
        return -1;
    *arr = p;
    *cap = c;
    return 0;
}

static void h_vert(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    gls_unit *u = ctx->u;
    gls_vec4 p = {a[0].num, n > 1 ? a[1].num : 0, n > 2 ? a[2].num : 0, n > 3 ? a[3].num : 1};
    if (p.w == 0) {
        ERR(ctx, a[3].line, a[3].col, "w must not be 0");
        return;
    }
    if (ctx->prim_kind < 0)
        return;
    if (ctx->prim_nvert >= GLS_MAX_PRIM_VERTICES || u->npos >= GLS_MAX_VERTICES) {
        ERR(ctx, name.line, name.col, "too many vertices (a primitive may have %u, an object %u)",
            GLS_MAX_PRIM_VERTICES, GLS_MAX_VERTICES);
        ctx->prim_kind = -1;
        return;
    }
    if (grow((void **)&u->pos, &u->pos_cap, u->npos + 1, sizeof *u->pos) ||
        (ctx->prim_has_col && grow((void **)&u->col, &u->col_cap, u->ncol + 1, sizeof *u->col)) ||
        (ctx->prim_has_tc && grow((void **)&u->tc, &u->tc_cap, u->ntc + 1, sizeof *u->tc))) {
        ERR(ctx, name.line, name.col, "out of memory");
        ctx->stop = 1;
        return;
    }
    u->pos[u->npos++] = p;
    if (ctx->prim_has_col)
        u->col[u->ncol++] = ctx->cur_col;
    if (ctx->prim_has_tc)
        u->tc[u->ntc++] = ctx->cur_tc;
    ctx->prim_nvert++;
}

static void h_col(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    if (check_unit_range(ctx, a, n, "colour"))
        return;
    if (!ctx->prim_has_col && ctx->prim_nvert > 0) {
        ERR(ctx, name.line, name.col,
            "'col' after the first 'vert' of this primitive: put a 'col' before the first vertex so every vertex has a colour");
        return;
    }
    ctx->prim_has_col = 1;
    ctx->cur_col = (gls_rgba){(float)a[0].num, (float)a[1].num, (float)a[2].num, n > 3 ? (float)a[3].num : 1.0f};
}

static void h_tex(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    for (int i = 0; i < 2; i++)
        if (fabs(a[i].num) > FLT_MAX) {
            ERR(ctx, a[i].line, a[i].col, "texture coordinate %g is outside the range of a float", a[i].num);
            return;
        }
    if (!ctx->prim_has_tc && ctx->prim_nvert > 0) {
        ERR(ctx, name.line, name.col,
            "'tex' after the first 'vert' of this primitive: put a 'tex' before the first vertex so every vertex has coordinates");
        return;
    }
    ctx->prim_has_tc = 1;
    ctx->cur_tc = (gls_st){(float)a[0].num, (float)a[1].num};
}

static void h_color(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    if (check_unit_range(ctx, a, n, "colour"))
        return;
    double d[GLS_NARGS_COLOR] = {a[0].num, a[1].num, a[2].num, n > 3 ? a[3].num : 1.0};
    emit_d(ctx, GLS_OP_COLOR, d, name.line);
}

static void h_texmode(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    for (unsigned m = 0; m < GLS_MODE_COUNT; m++) {
        size_t l = strlen(gls_texmode_name[m]);
        if (a[0].len == l && memcmp(a[0].s, gls_texmode_name[m], l) == 0) {
            emit_u(ctx, GLS_OP_TEXMODE, GLS_ARG_TEXMODE_MODE, m, name.line);
            gls_texuse_mode(&ctx->texuse, m != GLS_MODE_COLOR, name.line);
            return;
        }
    }
    const char *s = gls_suggest(a[0].s, a[0].len, gls_texmode_name, GLS_MODE_COUNT);
    ERR(ctx, a[0].line, a[0].col, "unknown texture mode '%.*s'%s%s%s (the modes are color, replace, modulate)",
        (int)a[0].len, a[0].s, s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
}

/* The string argument's text without its quotes. */
static int ref_arg(gls_parse *ctx, const gls_val *a, const char *what)
{
    if (!gls_valid_name(a->s + 1, a->len - 2)) {
        ERR(ctx, a->line, a->col, "%.*s is not a valid %s name (dotted identifiers, like \"road.vegetation.Birch\")",
            (int)a->len, a->s, what);
        return -1;
    }
    return 0;
}

static void h_texture(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    if (ref_arg(ctx, a, "texture"))
        return;
    gls_unit *u = ctx->u;
    uint32_t r = gls_unit_add_ref(&u->texrefs, &u->ntexrefs, &u->texrefs_cap, a->s + 1, a->len - 2,
                                  gls_tok_loc(ctx, a->line, a->col + 1));
    if (r == GLS_NONE) {
        ERR(ctx, name.line, name.col, "out of memory");
        return;
    }
    emit_u(ctx, GLS_OP_TEXTURE, GLS_ARG_TEXTURE_INDEX, r, name.line);
    if (gls_texuse_select(&ctx->texuse, gls_tok_loc(ctx, name.line, name.col), a->s + 1, a->len - 2))
        ERR(ctx, name.line, name.col, "out of memory");
}

static void h_notexture(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)a, (void)n;
    gls_insn in = {.op = GLS_OP_NOTEXTURE};
    emit(ctx, &in, name.line);
    gls_texuse_deselect(&ctx->texuse);
}

static void h_trans(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    double d[GLS_NARGS_TRANS] = {a[0].num, a[1].num, a[2].num};
    (void)n;
    emit_d(ctx, GLS_OP_TRANS, d, name.line);
}

static void h_rot(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    double d[GLS_NARGS_ROT] = {a[0].num, a[1].num, a[2].num, a[3].num};
    (void)n;
    if (d[GLS_ARG_ROT_X] == 0 && d[GLS_ARG_ROT_Y] == 0 && d[GLS_ARG_ROT_Z] == 0) {
        ERR(ctx, a[1].line, a[1].col, "rotation axis is zero");
        return;
    }
    emit_d(ctx, GLS_OP_ROT, d, name.line);
}

static void h_scale(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    double d[GLS_NARGS_SCALE] = {a[0].num, n == 3 ? a[1].num : a[0].num, n == 3 ? a[2].num : a[0].num};
    emit_d(ctx, GLS_OP_SCALE, d, name.line);
}

static void h_transform(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    double d[GLS_NARGS_TRANSFORM];
    for (unsigned i = 0; i < GLS_NARGS_TRANSFORM; i++)
        d[i] = a[i].num;
    (void)n;
    emit_d(ctx, GLS_OP_TRANSFORM, d, name.line);
}

static void h_push(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)a, (void)n;
    if (ctx->depth >= GLS_MAX_PUSH_DEPTH) {
        ERR(ctx, name.line, name.col, "'push' nested deeper than %u", GLS_MAX_PUSH_DEPTH);
        ctx->depth_overflow++; /* its pop must not complain as well */
        return;
    }
    gls_texuse_push(&ctx->texuse, ctx->depth);
    ctx->push_tok[ctx->depth++] = name;
    gls_insn in = {.op = GLS_OP_PUSH};
    emit(ctx, &in, name.line);
}

static void h_pop(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)a, (void)n;
    if (ctx->depth_overflow) {
        ctx->depth_overflow--; /* the pop of a push refused as too deep */
        return;
    }
    if (ctx->depth == 0) {
        /* after a syntax error the matching push may be what was dropped */
        if (!ctx->syntax_errors)
            ERR(ctx, name.line, name.col, "'pop' without a matching 'push'");
        return;
    }
    ctx->depth--;
    gls_texuse_pop(&ctx->texuse, ctx->depth);
    gls_insn in = {.op = GLS_OP_POP};
    emit(ctx, &in, name.line);
}

static void h_call(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    if (ref_arg(ctx, a, "object"))
        return;
    gls_unit *u = ctx->u;
    uint32_t r = gls_unit_add_ref(&u->refs, &u->nrefs, &u->refs_cap, a->s + 1, a->len - 2,
                                  gls_tok_loc(ctx, a->line, a->col + 1));
    if (r == GLS_NONE) {
        ERR(ctx, name.line, name.col, "out of memory");
        return;
    }
    emit_u(ctx, GLS_OP_CALL, GLS_ARG_CALL_OBJECT, r, name.line);
    gls_texuse_call(&ctx->texuse);
}

/* ---- primitive blocks ------------------------------------------------------ */

void sema_block_open(gls_parse *ctx, gls_tok name)
{
    ctx->nargs = 0;
    if (ctx->in_prim) {
        ERR(ctx, name.line, name.col, "primitive blocks cannot be nested");
        ctx->in_prim++;
        return;
    }
    int k = prim_kind_of(name);
    if (k < 0) {
        int is_instr = 0;
        for (size_t i = 0; i < NINSTRS; i++)
            is_instr |= tok_is(name, instrs[i].name);
        const char *s =
            is_instr ? NULL : gls_suggest_alias(name.p, name.len, gls_prim_name, GLS_PRIM_COUNT, aliases, NALIASES);
        if (s)
            ERR(ctx, name.line, name.col, "unknown primitive '%.*s'; did you mean '%s'?", (int)name.len, name.p, s);
        else
            ERR(ctx, name.line, name.col, "'%.*s' is not a primitive; the primitives are poly, qstrip, tstrip, tfan",
                (int)name.len, name.p);
    }
    ctx->in_prim = 1;
    ctx->prim_kind = k;
    ctx->prim_tok = name;
    ctx->prim_pos0 = ctx->u->npos;
    ctx->prim_col0 = ctx->u->ncol;
    ctx->prim_tc0 = ctx->u->ntc;
    ctx->prim_nvert = 0;
    ctx->prim_has_col = ctx->prim_has_tc = 0;
    ctx->errors_at_block = ctx->d->errors;
}

void sema_block_close(gls_parse *ctx, gls_tok rbrace)
{
    (void)rbrace;
    if (ctx->in_prim > 1) {
        ctx->in_prim--;
        return;
    }
    ctx->in_prim = 0;
    int k = ctx->prim_kind;
    /* an error inside the block already dropped something: do not pile a
       vertex-count error on top of it */
    if (k < 0 || ctx->d->errors != ctx->errors_at_block)
        return;
    gls_tok t = ctx->prim_tok;
    unsigned nv = ctx->prim_nvert, min = gls_prim_min_verts(k);
    if (nv < min || (gls_prim_needs_even(k) && nv % 2)) {
        if (gls_prim_needs_even(k))
            ERR(ctx, t.line, t.col, "'%s' needs an even number of vertices, at least %u; it has %u", gls_prim_name[k],
                min, nv);
        else
            ERR(ctx, t.line, t.col, "'%s' needs at least %u vertices; it has %u", gls_prim_name[k], min, nv);
        return;
    }
    gls_insn in = {.op = GLS_OP_PRIM};
    in.u[GLS_ARG_PRIM_KIND] = (uint32_t)k;
    in.u[GLS_ARG_PRIM_N] = nv;
    in.u[GLS_ARG_PRIM_POS] = ctx->prim_pos0;
    in.u[GLS_ARG_PRIM_COL] = ctx->prim_has_col ? ctx->prim_col0 : GLS_NONE;
    in.u[GLS_ARG_PRIM_TC] = ctx->prim_has_tc ? ctx->prim_tc0 : GLS_NONE;
    emit(ctx, &in, t.line);
    gls_texuse_draw(&ctx->texuse);
}

/* ---- constants and expressions -------------------------------------------- */

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
    for (size_t i = 0; i < sizeof all_words / sizeof all_words[0]; i++)
        if (tok_is(name, all_words[i])) {
            ERR(ctx, name.line, name.col, "'%s' is an instruction name and cannot be a constant", all_words[i]);
            return;
        }
    for (unsigned m = 0; m < GLS_MODE_COUNT; m++)
        if (tok_is(name, gls_texmode_name[m])) {
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

/* ---- a missing ';' --------------------------------------------------------- */

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
