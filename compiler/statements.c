/* Statements (spec/language.md 7): an instruction's name is looked up
 * (with "did you mean" for unknown ones, aliases from other languages
 * included), then the checks every instruction shares, in this order:
 * placement inside or outside a primitive block, argument count, the kind
 * of each argument; then its handler (instructions.c). */
#include <stdio.h>
#include <string.h>
#include "sema.h"

const char *const sema_words[] = {"vert",  "col", "tex",   "color",     "texmode", "texture", "notexture",
                                  "trans", "rot", "scale", "transform", "push",    "pop",     "call",    "mark",
                                  "normal", "light", "ambient", "specular", "shadows",
                                  "poly",  "qstrip", "tstrip", "tfan",  "const",   "param",   "repeat",
                                  "class"};
const size_t sema_nwords = sizeof sema_words / sizeof sema_words[0];

/* Names people bring from OpenGL and other scene languages, for "did you
 * mean" (gls_suggest_alias also takes their OpenGL spellings: glRotatef,
 * glVertex3f, glPushMatrix, glTexCoord2f, glColor3ub, glMultMatrixd, ...).
 * The real names are the keys of sema_instrs[] and gls_prim_name. */
const gls_alias sema_aliases[] = {
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
    {"lamp", "light"},          {"sun", "light"},           {"lightsource", "light"},
    {"norm", "normal"},         {"glnormal", "normal"},     {"shininess", "specular"},
    {"shadow", "shadows"},      {"shadowmap", "shadows"},
    {"landmark", "mark"},       {"marker", "mark"},         {"keypoint", "mark"},
    {"category", "class"},      {"classname", "class"},
    {"include", "call"},        {"import", "call"},         {"use", "call"},               {"instance", "call"},
    {"define", "const"},        {"let", "const"},           {"var", "const"},
    {"for", "repeat"},          {"loop", "repeat"},         {"while", "repeat"},           {"times", "repeat"},
    {"parameter", "param"},     {"arg", "param"},
    {"begin", "poly"},          {"polygon", "poly"},        {"triangle", "poly"},          {"triangles", "poly"},
    {"quad", "poly"},           {"quads", "poly"},
    {"quadstrip", "qstrip"},    {"quad_strip", "qstrip"},
    {"trianglestrip", "tstrip"}, {"triangle_strip", "tstrip"}, {"tristrip", "tstrip"},
    {"trianglefan", "tfan"},    {"triangle_fan", "tfan"},   {"trifan", "tfan"},
};
const size_t sema_naliases = sizeof sema_aliases / sizeof sema_aliases[0];

int sema_tok_is(gls_tok t, const char *s)
{
    /* stops at the first byte that differs, usually the first: defining a
       name compares it with every word of the language */
    for (uint32_t i = 0; i < t.len; i++)
        if (t.p[i] != s[i] || !s[i])
            return 0;
    return s[t.len] == 0;
}

int sema_prim_kind(gls_tok t)
{
    for (int k = 0; k < GLS_PRIM_COUNT; k++)
        if (sema_tok_is(t, gls_prim_name[k]))
            return k;
    return -1;
}

static void describe_kind(const gls_val *v, char *buf, size_t n)
{
    if (v->kind == VAL_STR)
        snprintf(buf, n, "a string");
    else if (v->kind == VAL_WORD)
        snprintf(buf, n, "the word '%.*s'", (int)v->len, v->s);
    else
        snprintf(buf, n, "a number");
}

/* Named arguments (NAME = value) are call's parameter values and come
 * after its quoted name; any other instruction takes none.  Returns how
 * many arguments come before the first named one, or -1 after an error. */
static int positional(gls_parse *ctx, const sema_instr *ins, const gls_val *a, unsigned n)
{
    unsigned k = 0;
    while (k < n && !a[k].pname)
        k++;
    int named = strcmp(ins->name, "call") == 0;
    if (k < n && (!named || k == 0)) {
        gls_tok p = *a[k].pname;
        if (named)
            ERR(ctx, p.line, p.col, "argument 1 of 'call' must be a quoted name, not a parameter value");
        else
            ERR(ctx, p.line, p.col, "'%s' takes no named arguments ('%.*s = ...' gives a parameter value to call)",
                ins->name, (int)p.len, p.p);
        return -1;
    }
    for (unsigned i = k; i < n; i++)
        if (!a[i].pname) {
            ERR(ctx, a[i].line, a[i].col, "argument %u of 'call' must be a parameter value (NAME = value), like the one before it",
                i + 1);
            return -1;
        }
    return (int)k;
}

void sema_stmt(gls_parse *ctx, gls_tok name, int parens)
{
    unsigned n = ctx->nargs;
    int too_many = ctx->too_many_args;
    ctx->nargs = 0;
    ctx->too_many_args = 0;
    (void)parens;

    const sema_instr *ins = NULL;
    for (size_t i = 0; i < sema_ninstrs; i++)
        if (sema_tok_is(name, sema_instrs[i].name)) {
            ins = &sema_instrs[i];
            break;
        }
    if (!ins) {
        if (sema_prim_kind(name) >= 0) {
            ERR(ctx, name.line, name.col, "'%.*s' is a primitive block: write %.*s { vert(...); ... }",
                (int)name.len, name.p, (int)name.len, name.p);
            return;
        }
        const char *s =
            gls_suggest_alias(name.p, name.len, sema_words, sema_nwords, sema_aliases, sema_naliases);
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
    const gls_val *a = ctx->args;
    int is_scale = strcmp(ins->name, "scale") == 0; /* 1 or 3 arguments, not 2 */
    int is_call = strcmp(ins->name, "call") == 0;
    if (is_call && too_many) {
        ERR(ctx, name.line, name.col, "'call' passes at most %u parameter values, got %u", GLS_MAX_PARAMS, n - 1);
        return;
    }
    unsigned npos = n;
    if (!too_many) {
        int k = positional(ctx, ins, a, n);
        if (k < 0)
            return;
        npos = (unsigned)k;
    }
    /* call's second positional argument may be an instance name, its
       third none: say what may go there */
    if (is_call && !too_many && npos >= 2 && (npos > 2 || a[1].kind != VAL_STR) && a[1].kind != VAL_ERR) {
        if (npos > 2 && a[1].kind == VAL_STR)
            ERR(ctx, a[2].line, a[2].col, "argument 3 of 'call' must be a parameter value (NAME = value)");
        else
            ERR(ctx, a[1].line, a[1].col,
                "argument 2 of 'call' must be an instance name (a quoted string) or a parameter value (NAME = value)");
        return;
    }
    if (too_many || npos < ins->min || npos > ins->max || (is_scale && npos == 2)) {
        if (is_scale)
            ERR(ctx, name.line, name.col, "'scale' takes 1 or 3 arguments, got %u", n);
        else if (ins->min == ins->max)
            ERR(ctx, name.line, name.col, "'%s' takes %u argument%s, got %u", ins->name, ins->min,
                ins->min == 1 ? "" : "s", n);
        else
            ERR(ctx, name.line, name.col, "'%s' takes %u to %u arguments, got %u", ins->name, ins->min, ins->max, n);
        return;
    }
    for (unsigned i = 0; i < npos; i++) {
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
