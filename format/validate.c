/* Complete validation of a bundle's content.  A bundle that passes cannot
 * make a walker of its code read outside its arrays: see the list of
 * guarantees in bundle.h and spec/bundle.md "Validation".
 *
 * Over 500 lines because it is the checklist of spec/bundle.md 12.2: a
 * function for each group of checks (names, textures, vertices, operands,
 * code, calls, instance names, call paths) sharing the one error path and
 * the call-graph walks; the landmark names' checks, which have tables of
 * their own, are in validate_marks.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bundle.h"
#include "specname.h"

void gls_fail(gls_error *err, int line, const char *fmt, ...);
int gls_check_mark_names(const gls_bundle *b, gls_error *err); /* validate_marks.c */
#define FAIL(...) do { gls_fail(err, __LINE__, __VA_ARGS__); goto fail; } while (0)

int gls_valid_name(const char *s, size_t n)
{
    /* dot-separated identifiers: [A-Za-z_][A-Za-z0-9_]* */
    if (!s || n == 0 || n > GLS_MAX_NAME_BYTES)
        return 0;
    int start = 1;
    for (size_t i = 0; i < n; i++) {
        char ch = s[i];
        int alpha = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || ch == '_';
        int digit = ch >= '0' && ch <= '9';
        if (ch == '.') {
            if (start)
                return 0;
            start = 1;
        } else if (alpha || (digit && !start)) {
            start = 0;
        } else {
            return 0;
        }
    }
    return !start;
}

int gls_valid_instance_name(const char *s, size_t n)
{
    if (!s || n == 0 || n > GLS_MAX_INSTANCE_NAME_BYTES)
        return 0;
    for (size_t i = 0; i < n; i++) {
        char ch = s[i];
        int alpha = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || ch == '_';
        int other = (ch >= '0' && ch <= '9') || ch == '.' || ch == '-';
        if (!alpha && (i == 0 || !other))
            return 0;
    }
    return 1;
}

/* Templates (spec/bundle.md 7.7): names sorted, a source, 1..32
 * parameters with distinct identifiers and finite defaults, text without
 * NUL. */
static int check_templates(const gls_bundle *b, gls_error *err)
{
    if (b->ntemplates > GLS_MAX_OBJECTS)
        FAIL("too many templates");
    for (uint32_t i = 0; i < b->ntemplates; i++) {
        const gls_template *t = &b->templates[i];
        if (!t->name || !gls_valid_name(t->name, strlen(t->name)))
            FAIL("template %u: invalid name", i);
        if (i && strcmp(b->templates[i - 1].name, t->name) >= 0)
            FAIL("template table not sorted or has a duplicate at %s", t->name);
        if (t->source >= b->nsources)
            FAIL("template %s: source index %u out of range", t->name, t->source);
        if (t->nparams == 0 || t->nparams > GLS_MAX_PARAMS)
            FAIL("template %s: %u parameters, not 1..%u", t->name, t->nparams, GLS_MAX_PARAMS);
        for (uint32_t k = 0; k < t->nparams; k++) {
            const char *p = t->params[k];
            if (!p || !gls_valid_name(p, strlen(p)) || strchr(p, '.'))
                FAIL("template %s: parameter %u is not an identifier", t->name, k);
            for (uint32_t j = 0; j < k; j++)
                if (strcmp(t->params[j], p) == 0)
                    FAIL("template %s: parameter %s declared twice", t->name, p);
            if (!isfinite(t->defaults[k]))
                FAIL("template %s: the default of %s is not finite", t->name, p);
        }
        if (t->text_len > GLS_MAX_TEMPLATE_TEXT || !t->text || memchr(t->text, 0, t->text_len))
            FAIL("template %s: its text is too long or has a NUL byte", t->name);
    }
    return 0;
fail:
    return -1;
}

/* An object's name: a valid name, or a specialised one (spec/bundle.md
 * 2): its base has a template, its values are for exactly the template's
 * parameters in order, and they are not all the defaults (that object has
 * the plain name). */
static int check_object_name(const gls_bundle *b, const char *n, uint32_t i, gls_error *err)
{
    gls_specarg args[GLS_MAX_PARAMS];
    unsigned na;
    long base = n ? gls_specname_parse(n, args, GLS_MAX_PARAMS, &na) : -1;
    if (base < 0 || !gls_valid_name(n, (size_t)base))
        FAIL("object %u: invalid name", i);
    if (!na)
        return 0;
    char key[GLS_MAX_NAME_BYTES + 1];
    memcpy(key, n, (size_t)base);
    key[base] = 0;
    uint32_t ti = gls_bundle_find_template(b, key);
    if (ti == GLS_NONE)
        FAIL("object %s: parameter values, but no template %s", n, key);
    const gls_template *t = &b->templates[ti];
    int all_default = na == t->nparams;
    for (unsigned k = 0; k < na; k++) {
        if (k >= t->nparams || strlen(t->params[k]) != args[k].len ||
            memcmp(t->params[k], args[k].name, args[k].len) != 0)
            FAIL("object %s: its parameters are not those of template %s", n, key);
        all_default &= memcmp(&args[k].value, &t->defaults[k], sizeof(double)) == 0;
    }
    if (na != t->nparams)
        FAIL("object %s: its parameters are not those of template %s", n, key);
    if (all_default)
        FAIL("object %s: every value is the default, so its name is %s", n, key);
    return 0;
fail:
    return -1;
}

static int check_names(const gls_bundle *b, gls_error *err)
{
    for (uint32_t i = 0; i < b->nobjects; i++) {
        const char *n = b->objects[i].name;
        if (check_object_name(b, n, i, err))
            return -1;
        if (i && strcmp(b->objects[i - 1].name, n) >= 0)
            FAIL("object table not sorted or has a duplicate at %s", n);
    }
    /* every template is of some object: the plain one or one with values,
       which sort right after the plain name's place */
    for (uint32_t i = 0, o = 0; i < b->ntemplates; i++) {
        const char *tn = b->templates[i].name;
        size_t len = strlen(tn);
        while (o < b->nobjects && strcmp(b->objects[o].name, tn) < 0)
            o++;
        const char *on = o < b->nobjects ? b->objects[o].name : "";
        if (strncmp(on, tn, len) != 0 || (on[len] != 0 && on[len] != '('))
            FAIL("template %s: no object of it", tn);
    }
    for (uint32_t i = 0; i < b->ntextures; i++) {
        const char *n = b->textures[i].name;
        if (!n || !gls_valid_name(n, strlen(n)))
            FAIL("texture %u: invalid name", i);
        if (i && strcmp(b->textures[i - 1].name, n) >= 0)
            FAIL("texture table not sorted or has a duplicate at %s", n);
    }
    for (uint32_t i = 0; i < b->nsources; i++)
        if (!b->sources[i])
            FAIL("source name %u missing", i);
    return 0;
fail:
    return -1;
}

static int check_textures(const gls_bundle *b, gls_error *err)
{
    for (uint32_t i = 0; i < b->ntextures; i++) {
        const gls_texture *t = &b->textures[i];
        if (t->width == 0 || t->height == 0 || t->width > GLS_MAX_TEXTURE_DIM || t->height > GLS_MAX_TEXTURE_DIM)
            FAIL("texture %s: size %ux%u is outside 1..%u", t->name, t->width, t->height, GLS_MAX_TEXTURE_DIM);
        if ((uint64_t)t->width * t->height > GLS_MAX_TEXELS)
            FAIL("texture %s: %ux%u texels, more than %llu", t->name, t->width, t->height,
                 (unsigned long long)GLS_MAX_TEXELS);
        if (t->flags & ~GLS_TEX_ALPHA_HOLES)
            FAIL("texture %s: unknown flags %#x", t->name, t->flags);
        uint32_t holes = 0;
        size_t n = (size_t)t->width * t->height;
        for (size_t k = 0; k < n; k++) {
            uint8_t a = t->rgba[k * 4 + 3];
            if (a != 0 && a != 255)
                FAIL("texture %s: alpha %u at texel %zu is not binary (0 or 255)", t->name, a, k);
            if (a == 0)
                holes = GLS_TEX_ALPHA_HOLES;
        }
        if (holes != (t->flags & GLS_TEX_ALPHA_HOLES))
            FAIL("texture %s: alpha flag does not match its texels", t->name);
    }
    return 0;
fail:
    return -1;
}

static int check_vertices(const gls_bundle *b, gls_error *err)
{
    if (b->npos > GLS_MAX_VERTICES || b->ncol > GLS_MAX_VERTICES || b->ntex > GLS_MAX_VERTICES)
        FAIL("more than %u vertices", GLS_MAX_VERTICES);
    for (uint32_t i = 0; i < b->npos; i++) {
        const gls_vec4 *p = &b->pos[i];
        if (!isfinite(p->x) || !isfinite(p->y) || !isfinite(p->z) || !isfinite(p->w) || p->w == 0)
            FAIL("position %u is not finite or has w = 0", i);
    }
    for (uint32_t i = 0; i < b->ncol; i++) {
        const gls_rgba *c = &b->col[i];
        if (!(c->r >= 0 && c->r <= 1 && c->g >= 0 && c->g <= 1 && c->b >= 0 && c->b <= 1 && c->a >= 0 && c->a <= 1))
            FAIL("colour %u has a component outside 0..1 or not a number", i);
    }
    for (uint32_t i = 0; i < b->ntex; i++)
        if (!isfinite(b->tc[i].s) || !isfinite(b->tc[i].t))
            FAIL("texture coordinate %u is not finite", i);
    if (b->nnrm > GLS_MAX_VERTICES)
        FAIL("more than %u normals", GLS_MAX_VERTICES);
    for (uint32_t i = 0; i < b->nnrm; i++) {
        /* unit length as the compiler wrote it, in float: within 1e-5 */
        const gls_nrm *q = &b->nrm[i];
        double l = (double)q->x * q->x + (double)q->y * q->y + (double)q->z * q->z;
        if (!(fabs(l - 1.0) <= 1e-5))
            FAIL("normal %u is not a finite unit vector", i);
    }
    return 0;
fail:
    return -1;
}

static int is_vertex_kind(uint8_t kind)
{
    return kind == GLS_KIND_NVERT || kind == GLS_KIND_FIRST_POS || kind == GLS_KIND_FIRST_COL ||
           kind == GLS_KIND_FIRST_TC || kind == GLS_KIND_FIRST_NRM;
}

/* Operand i of in, by its kind: in range, or a message in err.  The
 * vertex kinds come after the others (check_operands), so that the
 * primitive kind they depend on is known to be valid. */
static int check_operand(const gls_bundle *b, const gls_object *o, uint32_t k, const gls_insn *in, uint32_t i,
                         gls_error *err)
{
    const char *nm = gls_op[in->op].name;
    const gls_kind_info *ki = &gls_kind[gls_op[in->op].kind[i]];
    uint32_t v = in->u[i];
    gls_vertex_span s = {0};
    if (is_vertex_kind(gls_op[in->op].kind[i]))
        gls_insn_vertices(in, &s);
    switch ((gls_operand_kind)gls_op[in->op].kind[i]) {
    case GLS_KIND_COMPONENT:
    case GLS_KIND_ALPHA:
        if (in->d[i] < 0 || in->d[i] > 1)
            FAIL("object %s, instruction %u (%s): component outside 0..1", o->name, k, nm);
        break;
    case GLS_KIND_SHADOWRES:
        if (v < GLS_SHADOW_RES_MIN || v > GLS_SHADOW_RES_MAX || (v & (v - 1)))
            FAIL("object %s, instruction %u (%s): shadow map side %u is not a power of two in %u..%u", o->name, k, nm,
                 v, GLS_SHADOW_RES_MIN, GLS_SHADOW_RES_MAX);
        break;
    case GLS_KIND_INTENSITY:
        if (!(in->d[i] >= 0))
            FAIL("object %s, instruction %u (%s): operand %u is negative", o->name, k, nm, i + 1);
        break;
    case GLS_KIND_TEXMODE:
    case GLS_KIND_PRIMKIND:
    case GLS_KIND_LIGHTKIND:
        if (v >= ki->values)
            FAIL("object %s, instruction %u (%s): %s %u unknown", o->name, k, nm, ki->noun, v);
        break;
    /* an index into a table of lim entries: "WHAT v >= lim NOUN" */
#define INDEX_IN(lim, what, noun)                                                                              \
    if (v >= (lim))                                                                                            \
        FAIL("object %s, instruction %u (%s): " what " %u >= %u " noun, o->name, k, nm, v, (lim));           \
    break
    case GLS_KIND_OBJECT:
        INDEX_IN(b->nobjects, "index", "objects");
    case GLS_KIND_TEXTURE:
        INDEX_IN(b->ntextures, "index", "textures");
    case GLS_KIND_INSTNAME:
        INDEX_IN(b->ninstnames, "instance name", "names");
    case GLS_KIND_MARKNAME:
        INDEX_IN(b->nmarknames, "landmark name", "names");
    case GLS_KIND_CLASSNAME: /* class names share the landmarks' table */
        INDEX_IN(b->nmarknames, "class name", "names");
#undef INDEX_IN
    case GLS_KIND_NVERT: {
        int pk = gls_op_find(in->op, GLS_KIND_PRIMKIND);
        gls_primkind kind = (gls_primkind)in->u[pk];
        if (v < gls_prim_min_verts(kind) || v > GLS_MAX_PRIM_VERTICES || (gls_prim_needs_even(kind) && v % 2))
            FAIL("object %s, instruction %u (%s): %u vertices is not a legal count", o->name, k,
                 gls_prim_name[kind], v);
        break;
    }
    /* the first of s.n entries of a stream of lim (none_ok: or GLS_NONE,
       the stream unused): "NOUN v+count beyond lim" */
#define SPAN_IN(lim, none_ok, noun)                                                                            \
    if (!((none_ok) && v == GLS_NONE) && (v > (lim) || s.n > (lim) - v))                                       \
        FAIL("object %s, instruction %u (%s): " noun " %u+%u beyond %u", o->name, k, nm, v, s.n, (lim));      \
    break
    case GLS_KIND_FIRST_POS:
        SPAN_IN(b->npos, 0, "positions");
    case GLS_KIND_FIRST_COL:
        SPAN_IN(b->ncol, 1, "colours");
    case GLS_KIND_FIRST_TC:
        SPAN_IN(b->ntex, 1, "texcoords");
    case GLS_KIND_FIRST_NRM:
        SPAN_IN(b->nnrm, 0, "normals");
#undef SPAN_IN
    case GLS_KIND_NUM:
    case GLS_KIND_ANGLE:
    case GLS_KIND_COUNT:
        break; /* finite: checked first, for every F64 operand */
    }
    return 0;
fail:
    return -1;
}

/* A light's operands together (spec/bundle.md 9.2): one encoding per
 * light, so what a kind does not use is zero, and a direction is not. */
static int check_light(const gls_object *o, uint32_t k, const gls_insn *in, gls_error *err)
{
    uint32_t kind = in->u[GLS_ARG_LIGHT_KIND];
    int zero_xyz = in->d[GLS_ARG_LIGHT_X] == 0 && in->d[GLS_ARG_LIGHT_Y] == 0 && in->d[GLS_ARG_LIGHT_Z] == 0;
    if (kind == GLS_LIGHT_DIRECTIONAL && zero_xyz)
        FAIL("object %s, instruction %u (light): directional light with a zero direction", o->name, k);
    if (kind == GLS_LIGHT_AMBIENT && !zero_xyz)
        FAIL("object %s, instruction %u (light): ambient light with a position", o->name, k);
    if (kind != GLS_LIGHT_POINT && in->d[GLS_ARG_LIGHT_ATTEN] != 0)
        FAIL("object %s, instruction %u (light): attenuation on a light that is not a point light", o->name, k);
    return 0;
fail:
    return -1;
}

/* Every operand of instruction k: F64 operands finite, the source map's
 * file index in range, then each operand in range for its kind. */
static int check_operands(const gls_bundle *b, const gls_object *o, uint32_t k, const gls_insn *in, gls_error *err)
{
    const gls_op_info *op = &gls_op[in->op];
    for (uint32_t i = 0; i < op->noperands; i++)
        if (gls_kind[op->kind[i]].storage == GLS_STORE_F64 && !isfinite(in->d[i]))
            FAIL("object %s, instruction %u (%s): operand %u is not finite", o->name, k, op->name, i + 1);
    if (o->src && (o->src[k].file >= b->nsources))
        FAIL("object %s, instruction %u: source file index out of range", o->name, k);
    for (int vertex_kinds = 0; vertex_kinds < 2; vertex_kinds++)
        for (uint32_t i = 0; i < op->noperands; i++)
            if (is_vertex_kind(op->kind[i]) == vertex_kinds && check_operand(b, o, k, in, i, err))
                return -1;
    if (in->op == GLS_OP_LIGHT && check_light(o, k, in, err))
        return -1;
    return 0;
fail:
    return -1;
}

/* One object's code: decodable, operands in range, stack balanced. */
static int check_code(const gls_bundle *b, uint32_t oi, gls_error *err)
{
    const gls_object *o = &b->objects[oi];
    size_t pos = 0;
    uint32_t k = 0, depth = 0;
    gls_insn in;
    for (;; k++) {
        if (k >= o->ninsn)
            FAIL("object %s: more instructions than the %u declared", o->name, o->ninsn);
        if (gls_insn_decode(o->code, o->code_len, &pos, &in))
            FAIL("object %s, instruction %u: unknown opcode or truncated operands", o->name, k);
        if (check_operands(b, o, k, &in, err))
            return -1;
        switch (gls_op[in.op].flow) {
        case GLS_FLOW_END:
            if (depth != 0)
                FAIL("object %s: ends with %u unbalanced push", o->name, depth);
            if (pos != o->code_len || k + 1 != o->ninsn)
                FAIL("object %s: end is not the last instruction", o->name);
            return 0;
        case GLS_FLOW_PUSH:
            if (++depth > GLS_MAX_PUSH_DEPTH)
                FAIL("object %s, instruction %u: push nested deeper than %u", o->name, k, GLS_MAX_PUSH_DEPTH);
            break;
        case GLS_FLOW_POP:
            if (depth == 0)
                FAIL("object %s, instruction %u: pop without push", o->name, k);
            depth--;
            break;
        case GLS_FLOW_NEXT:
            break;
        }
    }
fail:
    return -1;
}

/* One iterative depth-first walk of the call graph from root, over the
 * objects whose state is 0 (0 new, 1 on the walk's path, 2 finished):
 * edge(u, from, to, state of to) for every call met (a callee in state 1
 * closes a cycle), done(u, obj, parent) when an object is finished, all
 * its callees first (postorder; parent GLS_NONE for root).  Iterative, so
 * a hostile bundle cannot exhaust the C stack; stack and pc hold
 * nobjects entries.  0, or the first non-zero a callback returns. */
typedef struct {
    int (*edge)(void *u, uint32_t from, uint32_t to, uint8_t to_state);
    int (*done)(void *u, uint32_t obj, uint32_t parent);
    void *u;
} call_visitor;

static int call_dfs(const gls_bundle *b, uint32_t root, uint8_t *state, uint32_t *stack, size_t *pc,
                    const call_visitor *v)
{
    uint32_t sp = 0;
    stack[sp] = root, pc[sp] = 0, sp++;
    state[root] = 1;
    while (sp) {
        uint32_t cur = stack[sp - 1];
        const gls_object *o = &b->objects[cur];
        gls_insn in;
        int descended = 0, rc;
        while (pc[sp - 1] < o->code_len) {
            gls_insn_decode(o->code, o->code_len, &pc[sp - 1], &in);
            int arg = gls_op_find(in.op, GLS_KIND_OBJECT);
            if (arg < 0)
                continue;
            uint32_t callee = in.u[arg];
            if (v->edge && (rc = v->edge(v->u, cur, callee, state[callee])))
                return rc;
            if (state[callee])
                continue;
            state[callee] = 1;
            stack[sp] = callee, pc[sp] = 0, sp++;
            descended = 1;
            break;
        }
        if (descended)
            continue;
        state[cur] = 2;
        sp--;
        if (v->done && (rc = v->done(v->u, cur, sp ? stack[sp - 1] : GLS_NONE)))
            return rc;
    }
    return 0;
}

/* check_calls' walk: heights memoised over the DAG. */
typedef struct {
    const gls_bundle *b;
    uint32_t *height;
    gls_error *err;
} depth_walk;

static int depth_edge(void *u, uint32_t from, uint32_t to, uint8_t to_state)
{
    depth_walk *d = u;
    if (to_state == 1) {
        gls_fail(d->err, __LINE__, "call cycle through %s and %s", d->b->objects[from].name, d->b->objects[to].name);
        return -1;
    }
    if (to_state == 2 && d->height[to] + 1 > d->height[from])
        d->height[from] = d->height[to] + 1;
    return 0;
}

static int depth_done(void *u, uint32_t obj, uint32_t parent)
{
    depth_walk *d = u;
    if (d->height[obj] > GLS_MAX_CALL_DEPTH) {
        gls_fail(d->err, __LINE__, "object %s: calls nest %u deep, more than %u", d->b->objects[obj].name,
                 d->height[obj], GLS_MAX_CALL_DEPTH);
        return -1;
    }
    if (parent != GLS_NONE && d->height[obj] + 1 > d->height[parent])
        d->height[parent] = d->height[obj] + 1;
    return 0;
}

/* Calls form a DAG no deeper than GLS_MAX_CALL_DEPTH. */
static int check_calls(const gls_bundle *b, gls_error *err)
{
    uint32_t n = b->nobjects;
    uint8_t *state = calloc(n ? n : 1, 1);
    uint32_t *height = calloc(n ? n : 1, sizeof *height);
    uint32_t *stack = malloc((size_t)(n ? n : 1) * sizeof *stack);
    size_t *pc = malloc((size_t)(n ? n : 1) * sizeof *pc);
    if (!state || !height || !stack || !pc)
        FAIL("out of memory");
    depth_walk d = {b, height, err};
    call_visitor v = {depth_edge, depth_done, &d};
    for (uint32_t root = 0; root < n; root++)
        if (!state[root] && call_dfs(b, root, state, stack, pc, &v))
            goto fail;
    free(state), free(height), free(stack), free(pc);
    return 0;
fail:
    free(state), free(height), free(stack), free(pc);
    return -1;
}

/* Memoised over the DAG; recursion depth is bounded by the call depth
 * limit, which check_calls has enforced before this runs. */
static uint64_t expanded(const gls_bundle *b, uint32_t oi, uint64_t *memo)
{
    const uint64_t cap = GLS_MAX_EXPANDED_VERTICES + 1;
    if (memo[oi] != UINT64_MAX)
        return memo[oi];
    const gls_object *o = &b->objects[oi];
    uint64_t n = 0;
    size_t pos = 0;
    gls_insn in;
    while (n < cap && pos < o->code_len && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0) {
        gls_vertex_span s;
        int callee = gls_op_find(in.op, GLS_KIND_OBJECT);
        if (gls_insn_vertices(&in, &s))
            n += s.n;
        if (callee >= 0)
            n += expanded(b, in.u[callee], memo);
    }
    memo[oi] = n < cap ? n : cap;
    return memo[oi];
}

uint64_t gls_bundle_expanded_vertices(const gls_bundle *b, uint32_t oi)
{
    uint64_t *memo = malloc((size_t)b->nobjects * sizeof *memo);
    if (!memo)
        return GLS_MAX_EXPANDED_VERTICES + 1;
    memset(memo, 0xFF, (size_t)b->nobjects * sizeof *memo);
    uint64_t n = expanded(b, oi, memo);
    free(memo);
    return n;
}

/* Instance names (spec/bundle.md 7.8): valid, sorted and unique (one
 * encoding per content), each used by some calln; in a bundle with a top
 * object, each reached exactly once from it, so that a name picks out one
 * drawn instance.  Runs after check_calls: the call graph is acyclic. */
static int check_instance_names(const gls_bundle *b, gls_error *err)
{
    uint64_t *paths = NULL, *reached = NULL;
    for (uint32_t i = 0; i < b->ninstnames; i++) {
        const char *n = b->instnames[i];
        if (!n || !gls_valid_instance_name(n, strlen(n)))
            FAIL("instance name %u is not a valid name ([A-Za-z_][A-Za-z0-9_.-]*, at most %u bytes)", i,
                 GLS_MAX_INSTANCE_NAME_BYTES);
        if (i && strcmp(b->instnames[i - 1], n) >= 0)
            FAIL("instance name table not sorted or has a duplicate at %s", n);
    }
    if (!b->ninstnames)
        return 0;
    reached = calloc(b->ninstnames, sizeof *reached);
    paths = b->top != GLS_NONE ? gls_bundle_paths(b, b->top) : NULL;
    if (!reached || (b->top != GLS_NONE && !paths))
        FAIL("out of memory");
    /* in a library bundle, uses count once per calln; else paths from top */
    for (uint32_t oi = 0; oi < b->nobjects; oi++) {
        const gls_object *o = &b->objects[oi];
        uint64_t times = paths ? paths[oi] : 1;
        size_t pos = 0;
        gls_insn in;
        while (pos < o->code_len && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0) {
            int arg = gls_op_find(in.op, GLS_KIND_INSTNAME);
            if (arg < 0)
                continue;
            uint32_t v = in.u[arg];
            reached[v] = reached[v] + times < reached[v] ? UINT64_MAX : reached[v] + times;
        }
    }
    for (uint32_t i = 0; i < b->ninstnames; i++) {
        if (!paths && !reached[i])
            FAIL("instance name %s: no calln names it", b->instnames[i]);
        if (paths && reached[i] != 1)
            FAIL("instance name %s: reached %llu times from the top object, not once", b->instnames[i],
                 (unsigned long long)reached[i]);
    }
    free(paths), free(reached);
    return 0;
fail:
    free(paths), free(reached);
    return -1;
}

/* topo_order's walk: objects appended as they are finished. */
typedef struct {
    uint32_t *order, n;
} post_walk;

static int post_done(void *u, uint32_t obj, uint32_t parent)
{
    post_walk *p = u;
    (void)parent;
    p->order[p->n++] = obj;
    return 0;
}

/* Objects reachable from top in reverse postorder (callers before their
 * callees), in order[0 .. *n). */
static void topo_order(const gls_bundle *b, uint32_t top, uint8_t *seen, uint32_t *order, uint32_t *n,
                       uint32_t *stack, size_t *pc)
{
    post_walk p = {order, 0};
    call_visitor v = {NULL, post_done, &p};
    call_dfs(b, top, seen, stack, pc, &v);
    uint32_t post = p.n;
    for (uint32_t i = 0; i < post / 2; i++) { /* reversed: callers first */
        uint32_t t = order[i];
        order[i] = order[post - 1 - i];
        order[post - 1 - i] = t;
    }
    *n = post;
}

uint64_t *gls_bundle_paths(const gls_bundle *b, uint32_t top)
{
    uint32_t n = b->nobjects ? b->nobjects : 1, norder = 0;
    uint64_t *paths = calloc(n, sizeof *paths);
    uint8_t *seen = calloc(n, 1);
    uint32_t *order = malloc(n * sizeof *order), *stack = malloc(n * sizeof *stack);
    size_t *pc = malloc(n * sizeof *pc);
    if (!paths || !seen || !order || !stack || !pc) {
        free(paths);
        paths = NULL;
        goto done;
    }
    topo_order(b, top, seen, order, &norder, stack, pc);
    paths[top] = 1;
    for (uint32_t i = 0; i < norder; i++) {
        const gls_object *o = &b->objects[order[i]];
        size_t pos = 0;
        gls_insn in;
        while (pos < o->code_len && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0) {
            int arg = gls_op_find(in.op, GLS_KIND_OBJECT);
            if (arg < 0)
                continue;
            uint64_t *p = &paths[in.u[arg]], add = paths[order[i]];
            *p = *p + add < *p ? UINT64_MAX : *p + add;
        }
    }
done:
    free(seen), free(order), free(stack), free(pc);
    return paths;
}

int gls_bundle_count_paths(const gls_bundle *b, uint32_t top, uint64_t *n)
{
    uint64_t *paths = gls_bundle_paths(b, top);
    if (!paths)
        return -1;
    *n = 0;
    for (uint32_t i = 0; i < b->nobjects; i++)
        *n = *n + paths[i] < *n ? UINT64_MAX : *n + paths[i];
    free(paths);
    return 0;
}

int gls_bundle_validate(const gls_bundle *b, gls_error *err)
{
    if (b->nobjects > GLS_MAX_OBJECTS || b->ntextures > GLS_MAX_TEXTURES)
        FAIL("too many objects or textures");
    if (b->top != GLS_NONE && b->top >= b->nobjects)
        FAIL("top-level object index %u >= %u objects", b->top, b->nobjects);
    if (check_templates(b, err) || check_names(b, err) || check_textures(b, err) || check_vertices(b, err))
        return -1;
    for (uint32_t i = 0; i < b->nobjects; i++)
        if (check_code(b, i, err))
            return -1;
    if (check_calls(b, err) || check_instance_names(b, err) || gls_check_mark_names(b, err))
        return -1;
    uint64_t paths = 0;
    if (b->top != GLS_NONE && gls_bundle_count_paths(b, b->top, &paths))
        FAIL("out of memory");
    if (paths > GLS_MAX_CALL_PATHS)
        FAIL("top-level object %s has more than %u call paths (instances to draw) once its calls are unrolled",
             b->objects[b->top].name, GLS_MAX_CALL_PATHS);
    return 0;
fail:
    return -1;
}
