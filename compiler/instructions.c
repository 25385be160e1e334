/* Each instruction's own checks and the bytecode it emits
 * (spec/language.md 7), and the table of instructions that statements.c
 * looks names up in.
 *
 * Over 500 lines because it is a catalogue: one short function per
 * instruction of the language (about thirty), each read on its own, and
 * the table that names them; splitting it would only scatter the table's
 * entries. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "sema.h"

void sema_emit(gls_parse *ctx, gls_insn *in, unsigned line)
{
    if (gls_unit_emit(ctx->u, in, line))
        ERR(ctx, line, 1, "out of memory");
}

/* An instruction whose operands are all numbers: d holds them in order. */
static void emit_d(gls_parse *ctx, gls_opcode op, const double *d, unsigned line)
{
    gls_insn in = {.op = op};
    memcpy(in.d, d, gls_op[op].noperands * sizeof *d);
    sema_emit(ctx, &in, line);
}

/* An instruction with one integer operand, at position arg. */
static void emit_u(gls_parse *ctx, gls_opcode op, unsigned arg, uint32_t v, unsigned line)
{
    gls_insn in = {.op = op};
    in.u[arg] = v;
    sema_emit(ctx, &in, line);
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
    if (gls_grow(&u->pos, &u->pos_cap, (size_t)u->npos + 1, sizeof *u->pos) ||
        (ctx->prim_has_col && gls_grow(&u->col, &u->col_cap, (size_t)u->ncol + 1, sizeof *u->col)) ||
        (ctx->prim_has_tc && gls_grow(&u->tc, &u->tc_cap, (size_t)u->ntc + 1, sizeof *u->tc)) ||
        (ctx->prim_has_nrm && gls_grow(&u->nrm, &u->nrm_cap, (size_t)u->nnrm + 1, sizeof *u->nrm))) {
        ERR(ctx, name.line, name.col, "out of memory");
        ctx->stop = 1;
        return;
    }
    u->pos[u->npos++] = p;
    if (ctx->prim_has_col)
        u->col[u->ncol++] = ctx->cur_col;
    if (ctx->prim_has_tc)
        u->tc[u->ntc++] = ctx->cur_tc;
    if (ctx->prim_has_nrm)
        u->nrm[u->nnrm++] = ctx->cur_nrm;
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

/* normal(nx, ny, nz): the normal of the following vertices of this
 * primitive, stored unit length (spec/language.md 7). */
static void h_normal(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    double l = sqrt(a[0].num * a[0].num + a[1].num * a[1].num + a[2].num * a[2].num);
    if (!(l > 0) || !isfinite(l)) {
        ERR(ctx, a[0].line, a[0].col, "normal (%g, %g, %g) has no direction", a[0].num, a[1].num, a[2].num);
        return;
    }
    if (!ctx->prim_has_nrm && ctx->prim_nvert > 0) {
        ERR(ctx, name.line, name.col,
            "'normal' after the first 'vert' of this primitive: put a 'normal' before the first vertex so every vertex has one");
        return;
    }
    ctx->prim_has_nrm = 1;
    ctx->cur_nrm = (gls_nrm){(float)(a[0].num / l), (float)(a[1].num / l), (float)(a[2].num / l)};
}

/* A light's colour (and attenuation): each >= 0, linear. */
static int check_nonnegative(gls_parse *ctx, const gls_val *a, unsigned n, const char *what)
{
    for (unsigned i = 0; i < n; i++)
        if (!(a[i].num >= 0)) {
            ERR(ctx, a[i].line, a[i].col, "%s %g is negative", what, a[i].num);
            return -1;
        }
    return 0;
}

/* light(directional, dx, dy, dz, r, g, b) or light(point, x, y, z, r, g,
 * b[, attenuation]): placed under the current transform like a vertex
 * (spec/language.md 7). */
static void h_light(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    static const char *const kinds[] = {"directional", "point"};
    int kind = -1;
    for (int k = 0; k < 2; k++)
        if (a[0].len == strlen(kinds[k]) && memcmp(a[0].s, kinds[k], a[0].len) == 0)
            kind = k;
    if (kind < 0) {
        const char *s = gls_suggest(a[0].s, a[0].len, kinds, 2);
        ERR(ctx, a[0].line, a[0].col, "unknown light kind '%.*s'%s%s%s (the kinds are directional, point; ambient light is 'ambient(r, g, b)')",
            (int)a[0].len, a[0].s, s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
        return;
    }
    if (check_nonnegative(ctx, a + 4, 3, "light colour component"))
        return;
    if (kind == GLS_LIGHT_DIRECTIONAL && n > 7) {
        ERR(ctx, a[7].line, a[7].col, "a directional light has no attenuation (only point lights fade with distance)");
        return;
    }
    if (n > 7 && check_nonnegative(ctx, a + 7, 1, "attenuation"))
        return;
    if (kind == GLS_LIGHT_DIRECTIONAL && a[1].num == 0 && a[2].num == 0 && a[3].num == 0) {
        ERR(ctx, a[1].line, a[1].col, "directional light with a zero direction");
        return;
    }
    double d[GLS_NARGS_LIGHT] = {0, a[1].num, a[2].num, a[3].num, a[4].num, a[5].num, a[6].num, n > 7 ? a[7].num : 0};
    gls_insn in = {.op = GLS_OP_LIGHT};
    memcpy(in.d, d, sizeof d);
    in.u[GLS_ARG_LIGHT_KIND] = (uint32_t)kind;
    sema_emit(ctx, &in, name.line);
}

/* ambient(r, g, b): light reaching every surface from every side. */
static void h_ambient(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    if (check_nonnegative(ctx, a, 3, "light colour component"))
        return;
    gls_insn in = {.op = GLS_OP_LIGHT};
    in.u[GLS_ARG_LIGHT_KIND] = GLS_LIGHT_AMBIENT;
    in.d[GLS_ARG_LIGHT_R] = a[0].num, in.d[GLS_ARG_LIGHT_G] = a[1].num, in.d[GLS_ARG_LIGHT_B] = a[2].num;
    sema_emit(ctx, &in, name.line);
}

/* specular(r, g, b, exponent): Phong highlight of the following
 * primitives (state, like color). */
static void h_specular(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    if (check_unit_range(ctx, a, 3, "specular") || check_nonnegative(ctx, a + 3, 1, "Phong exponent"))
        return;
    double d[GLS_NARGS_SPECULAR] = {a[0].num, a[1].num, a[2].num, a[3].num};
    emit_d(ctx, GLS_OP_SPECULAR, d, name.line);
}

/* shadows(res): directional and point lights cast shadows through res x res maps
 * (spec/language.md 7). */
static void h_shadows(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    double v = a[0].num;
    if (!(v >= GLS_SHADOW_RES_MIN && v <= GLS_SHADOW_RES_MAX) || v != floor(v) || ((uint32_t)v & ((uint32_t)v - 1))) {
        ERR(ctx, a[0].line, a[0].col, "shadow map side %g is not a power of two in %u..%u", v, GLS_SHADOW_RES_MIN,
            GLS_SHADOW_RES_MAX);
        return;
    }
    emit_u(ctx, GLS_OP_SHADOWS, GLS_ARG_SHADOWS_RES, (uint32_t)v, name.line);
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

/* The quoted name a (texture or object, says what) checked and added to
 * the unit's references (*arr, *n, *cap), located at its first character
 * inside the quotes; then the instruction in, whose operand arg indexes
 * it.  Returns 0, or -1 after reporting an invalid name or running out of
 * memory. */
static int emit_ref(gls_parse *ctx, gls_tok name, const gls_val *a, const char *what, gls_ref **arr, uint32_t *n,
                    size_t *cap, gls_insn *in, unsigned arg)
{
    if (!gls_valid_name(a->s + 1, a->len - 2)) {
        ERR(ctx, a->line, a->col, "%.*s is not a valid %s name (dotted identifiers, like \"road.vegetation.Birch\")",
            (int)a->len, a->s, what);
        return -1;
    }
    uint32_t r = gls_unit_add_ref(arr, n, cap, a->s + 1, a->len - 2, gls_tok_loc(ctx, a->line, a->col + 1));
    if (r == GLS_NONE) {
        ERR(ctx, name.line, name.col, "out of memory");
        return -1;
    }
    in->u[arg] = r;
    sema_emit(ctx, in, name.line);
    return 0;
}

static void h_texture(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    gls_unit *u = ctx->u;
    gls_insn in = {.op = GLS_OP_TEXTURE};
    if (emit_ref(ctx, name, a, "texture", &u->texrefs, &u->ntexrefs, &u->texrefs_cap, &in, GLS_ARG_TEXTURE_INDEX))
        return;
    if (gls_texuse_select(&ctx->texuse, gls_tok_loc(ctx, name.line, name.col), a->s + 1, a->len - 2))
        ERR(ctx, name.line, name.col, "out of memory");
}

static void h_notexture(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)a, (void)n;
    gls_insn in = {.op = GLS_OP_NOTEXTURE};
    sema_emit(ctx, &in, name.line);
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
    sema_emit(ctx, &in, name.line);
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
    sema_emit(ctx, &in, name.line);
}

/* call("name", "instance", p = v, ...)'s instance name, the optional
 * second quoted string (spec/language.md 7): checked and added to the
 * unit's instance names; its index into them, or GLS_NONE after an error.
 * Whether it is unique in the scene is known only once the scene is
 * linked (instnames.c). */
static uint32_t instance_name(gls_parse *ctx, gls_tok name, const gls_val *a)
{
    gls_unit *u = ctx->u;
    size_t len = a->len - 2;
    if (len > GLS_MAX_INSTANCE_NAME_BYTES) {
        ERR(ctx, a->line, a->col, "instance name %.*s is %zu bytes long, more than %u", (int)a->len, a->s, len,
            GLS_MAX_INSTANCE_NAME_BYTES);
        return GLS_NONE;
    }
    if (!gls_valid_instance_name(a->s + 1, len)) {
        ERR(ctx, a->line, a->col,
            "%.*s is not a valid instance name (a letter or '_', then letters, digits, '_', '.' or '-', like \"car1\")",
            (int)a->len, a->s);
        return GLS_NONE;
    }
    uint32_t r = gls_unit_add_ref(&u->instnames, &u->ninstnames, &u->instnames_cap, a->s + 1, len,
                                  gls_tok_loc(ctx, a->line, a->col));
    if (r == GLS_NONE)
        ERR(ctx, name.line, name.col, "out of memory");
    return r;
}

/* call("name", p = v, ...), or call("name", "instance", p = v, ...): the
 * instance name (a CALLN then), and the parameter values, checked
 * (numbers, each parameter once; the grammar allows no string there) and
 * kept with the reference, to be matched with the callee's parameters
 * when it is linked (template.c). */
static void h_call(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    gls_unit *u = ctx->u;
    unsigned first = n > 1 && !a[1].pname ? 2 : 1; /* the first parameter value */
    for (unsigned i = first; i < n; i++) {
        gls_tok p = *a[i].pname;
        if (a[i].kind == VAL_ERR)
            return; /* already reported */
        if (!sema_need_number(ctx, &a[i]))
            return;
        for (unsigned j = first; j < i; j++)
            if (a[j].pname->len == p.len && memcmp(a[j].pname->p, p.p, p.len) == 0) {
                ERR(ctx, p.line, p.col, "parameter '%.*s' is given twice", (int)p.len, p.p);
                return;
            }
    }
    gls_insn in = {.op = GLS_OP_CALL};
    if (first == 2) {
        in.op = GLS_OP_CALLN;
        if ((in.u[GLS_ARG_CALLN_NAME] = instance_name(ctx, name, &a[1])) == GLS_NONE)
            return;
    }
    _Static_assert((int)GLS_ARG_CALL_OBJECT == (int)GLS_ARG_CALLN_OBJECT, "call and calln name their object alike");
    if (emit_ref(ctx, name, a, "object", &u->refs, &u->nrefs, &u->refs_cap, &in, GLS_ARG_CALL_OBJECT))
        return;
    gls_texuse_call(&ctx->texuse);
    if (n <= first)
        return;
    gls_ref *r = &u->refs[u->nrefs - 1];
    r->args = calloc(n - first, sizeof *r->args);
    for (unsigned i = first; r->args && i < n; i++) {
        gls_tok p = *a[i].pname;
        gls_named *g = &r->args[r->nargs];
        if (!(g->name = strndup(p.p, p.len)))
            break;
        g->value = a[i].num;
        g->loc = gls_tok_loc(ctx, p.line, p.col);
        r->nargs++;
    }
    if (r->nargs != n - first) {
        ERR(ctx, name.line, name.col, "out of memory");
        ctx->stop = 1;
    }
}

/* What mark and class share: a quoted name with the landmark name rules
 * (class names share the bundle's MARK_NAMES), placed once per object.
 * place_name_check reports an invalid name (what: "landmark", "class";
 * example: a valid one) and finds an earlier placement in names (any of
 * them when any is set: an object has one class; else one of the same
 * name).  PLACE_NEW: none; PLACE_LOOP: it is this very statement, met
 * again by a loop; PLACE_TWICE: another statement (*first says which).
 * The caller words the repeat, which differs between the two. */
typedef enum { PLACE_BAD, PLACE_NEW, PLACE_LOOP, PLACE_TWICE } place_status;

static place_status place_name_check(gls_parse *ctx, const gls_val *a, const char *what, const char *example,
                                     const gls_ref *names, uint32_t nnames, int any, const gls_ref **first)
{
    const char *s = a->s + 1;
    size_t len = a->len - 2;
    if (!gls_valid_mark_name(s, len)) {
        ERR(ctx, a->line, a->col, "%.*s is not a valid %s name (1 to %u letters, digits, '_', '.' or '-', like \"%s\")",
            (int)a->len, a->s, what, GLS_MAX_MARK_NAME_BYTES, example);
        return PLACE_BAD;
    }
    for (uint32_t i = 0; i < nnames; i++)
        if (any || (strlen(names[i].name) == len && memcmp(names[i].name, s, len) == 0)) {
            *first = &names[i];
            return names[i].loc.line == a->line && names[i].loc.col == a->col ? PLACE_LOOP : PLACE_TWICE;
        }
    return PLACE_NEW;
}

/* Add a's name to names and emit in with its index as argument arg. */
static void place_name_emit(gls_parse *ctx, gls_tok name, const gls_val *a, gls_ref **names, uint32_t *nnames,
                            size_t *cap, gls_insn *in, unsigned arg)
{
    in->u[arg] = gls_unit_add_ref(names, nnames, cap, a->s + 1, a->len - 2, gls_tok_loc(ctx, a->line, a->col));
    if (in->u[arg] == GLS_NONE) {
        ERR(ctx, name.line, name.col, "out of memory");
        return;
    }
    sema_emit(ctx, in, name.line);
}

/* mark("name", x, y, z): a landmark at (x, y, z) under the current
 * transform, drawing nothing (spec/language.md 7).  Its name identifies
 * it within the object, so an object places each name once: the second
 * place is an error, with a note at the first (a mark in a loop body
 * meets it on the second iteration; spec/language.md says what to do). */
static void h_mark(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    gls_unit *u = ctx->u;
    const gls_ref *first = NULL;
    switch (place_name_check(ctx, &a[0], "landmark", "post.top", u->marknames, u->nmarknames, 0, &first)) {
    case PLACE_BAD:
        return;
    case PLACE_LOOP:
        ERR(ctx, a[0].line, a[0].col,
            "landmark %.*s is placed on every iteration of this loop, but an object places a name once "
            "(call an object that places it: its rows differ by path)",
            (int)a[0].len, a[0].s);
        return;
    case PLACE_TWICE:
        ERR(ctx, a[0].line, a[0].col, "landmark %.*s is placed twice in this object", (int)a[0].len, a[0].s);
        gls_note_at(ctx->d, first->loc, "%.*s is first placed here", (int)a[0].len, a[0].s);
        return;
    case PLACE_NEW:
        break;
    }
    gls_insn in = {.op = GLS_OP_MARK};
    in.d[GLS_ARG_MARK_X] = a[1].num, in.d[GLS_ARG_MARK_Y] = a[2].num, in.d[GLS_ARG_MARK_Z] = a[3].num;
    place_name_emit(ctx, name, &a[0], &u->marknames, &u->nmarknames, &u->marknames_cap, &in, GLS_ARG_MARK_NAME);
}

/* class("name"): the object's class, which ground truth gives its
 * instances instead of its package (spec/language.md 7, spec/outputs.md).
 * Names are those of landmarks (they share the bundle's MARK_NAMES).  An
 * object has one class: a second `class` is an error with a note at the
 * first, and one in a loop body meets itself on the second iteration. */
static void h_class(gls_parse *ctx, gls_tok name, const gls_val *a, unsigned n)
{
    (void)n;
    gls_unit *u = ctx->u;
    const gls_ref *first = NULL;
    switch (place_name_check(ctx, &a[0], "class", "Car", u->classnames, u->nclassnames, 1, &first)) {
    case PLACE_BAD:
        return;
    case PLACE_LOOP:
        ERR(ctx, a[0].line, a[0].col,
            "class is given on every iteration of this loop, but an object has one class (give it before "
            "the loop)");
        return;
    case PLACE_TWICE:
        ERR(ctx, a[0].line, a[0].col, "this object's class is given twice (an object has one class)");
        gls_note_at(ctx->d, first->loc, "its class is first given here, as \"%s\"", first->name);
        return;
    case PLACE_NEW:
        break;
    }
    gls_insn in = {.op = GLS_OP_CLASS};
    place_name_emit(ctx, name, &a[0], &u->classnames, &u->nclassnames, &u->classnames_cap, &in, GLS_ARG_CLASS_NAME);
}

/* The instructions (sema.h says what each field means). */
const sema_instr sema_instrs[] = {
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
    {"call", 1, 2, "ss", WHERE_OUTSIDE, h_call},
    {"mark", 4, 4, "snnn", WHERE_OUTSIDE, h_mark},
    {"class", 1, 1, "s", WHERE_OUTSIDE, h_class},
    {"normal", 3, 3, "nnn", WHERE_PRIM, h_normal},
    {"light", 7, 8, "wnnnnnnn", WHERE_OUTSIDE, h_light},
    {"ambient", 3, 3, "nnn", WHERE_OUTSIDE, h_ambient},
    {"specular", 4, 4, "nnnn", WHERE_OUTSIDE, h_specular},
    {"shadows", 1, 1, "n", WHERE_OUTSIDE, h_shadows},
};
const size_t sema_ninstrs = sizeof sema_instrs / sizeof sema_instrs[0];
