/* Assembly: the reachable units and the textures they use become one
 * bundle, objects and textures sorted by name, vertex streams concatenated
 * in that order, and every unit-local operand relocated to its bundle-wide
 * index by its kind (format/opcodes.h). */
#include <stdlib.h>
#include <string.h>
#include "linker.h"

static int cmp_unit(const void *a, const void *b)
{
    return strcmp((*(gls_unit *const *)a)->name, (*(gls_unit *const *)b)->name);
}

static int cmp_tex(const void *a, const void *b)
{
    return strcmp((*(tex_entry *const *)a)->name, (*(tex_entry *const *)b)->name);
}

static int cmp_tpl(const void *a, const void *b)
{
    return strcmp((*(gls_tpl *const *)a)->name, (*(gls_tpl *const *)b)->name);
}

/* The template of every parameterised object in the bundle (units[0..nu)),
 * sorted by name, with its source text: what a later compile needs to
 * make its object for other values (spec/bundle.md 7.7).  0, or -1 when
 * out of memory. */
static int add_templates(gls_bundle *b, gls_unit **units, uint32_t nu)
{
    gls_tpl **ts = malloc((nu ? nu : 1) * sizeof *ts);
    uint32_t nt = 0;
    if (!ts)
        return -1;
    for (uint32_t i = 0; i < nu; i++) {
        gls_tpl *t = units[i]->tpl;
        if (t && t->nparams && !t->in_bundle) {
            t->in_bundle = 1;
            ts[nt++] = t;
        }
    }
    qsort(ts, nt, sizeof *ts, cmp_tpl);
    for (uint32_t i = 0; i < nt; i++)
        ts[i]->in_bundle = 0;
    b->templates = calloc(nt ? nt : 1, sizeof *b->templates);
    if (!b->templates) {
        free(ts);
        return -1;
    }
    b->ntemplates = nt;
    for (uint32_t i = 0; i < nt; i++) {
        const gls_tpl *t = ts[i];
        gls_template *o = &b->templates[i];
        o->source = t->src_file;
        o->nparams = t->nparams;
        o->text_len = (uint32_t)t->src.len;
        o->name = strdup(t->name);
        o->params = calloc(t->nparams, sizeof *o->params);
        o->defaults = malloc(t->nparams * sizeof *o->defaults);
        o->text = malloc(t->src.len + 1);
        if (!o->name || !o->params || !o->defaults || !o->text) {
            free(ts);
            return -1;
        }
        memcpy(o->text, t->src.text, t->src.len);
        o->text[t->src.len] = 0;
        memcpy(o->defaults, t->defaults, t->nparams * sizeof *o->defaults);
        for (uint32_t k = 0; k < t->nparams; k++)
            if (!(o->params[k] = strdup(t->pnames[k]))) {
                free(ts);
                return -1;
            }
    }
    free(ts);
    return 0;
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The names of one kind a unit gives (instance names, landmark names). */
typedef const gls_ref *(*names_of)(const gls_unit *u, uint32_t *n);
static const gls_ref *instnames_of(const gls_unit *u, uint32_t *n) { *n = u->ninstnames; return u->instnames; }
static const gls_ref *marknames_of(const gls_unit *u, uint32_t *n) { *n = u->nmarknames; return u->marknames; }
static const gls_ref *classnames_of(const gls_unit *u, uint32_t *n) { *n = u->nclassnames; return u->classnames; }

/* A name table of the bundle (*out, *nout) from the units' names of the
 * kinds get[0..nget) (units[0..nu)): sorted, each once (a library may name
 * calls alike in different objects, objects place landmarks of one name,
 * and landmarks and classes share a table; in a scene instance names are
 * unique, instnames.c).  0, or -1 when out of memory. */
static int add_names(char ***out, uint32_t *nout, gls_unit **units, uint32_t nu, const names_of *get, int nget)
{
    size_t total = 0;
    uint32_t n;
    for (uint32_t i = 0; i < nu; i++)
        for (int g = 0; g < nget; g++) {
            get[g](units[i], &n);
            total += n;
        }
    if (!total)
        return 0;
    char **names = malloc(total * sizeof *names);
    if (!names)
        return -1;
    size_t k = 0;
    for (uint32_t i = 0; i < nu; i++)
        for (int g = 0; g < nget; g++) {
            const gls_ref *refs = get[g](units[i], &n);
            for (uint32_t j = 0; j < n; j++)
                names[k++] = refs[j].name;
        }
    qsort(names, total, sizeof *names, cmp_str);
    *out = calloc(total, sizeof **out);
    if (!*out) {
        free(names);
        return -1;
    }
    for (size_t i = 0; i < total; i++) {
        if (*nout && strcmp((*out)[*nout - 1], names[i]) == 0)
            continue;
        if (!((*out)[*nout] = strdup(names[i]))) {
            free(names);
            return -1;
        }
        (*nout)++;
    }
    free(names);
    return 0;
}

/* The index of name s in the sorted table names[0..n) (it is there). */
static uint32_t find_name(char *const *names, uint32_t n, const char *s)
{
    char *const *hit = bsearch(&s, names, n, sizeof *names, cmp_str);
    return hit ? (uint32_t)(hit - names) : GLS_NONE;
}

/* Operand j of in, an index into unit u's tables (or its vertices, which
 * start at p0, c0, t0, n0 in the bundle's), made an index into the
 * bundle's: the operand kinds say which index is which. */
static void relocate(const gls_bundle *b, const gls_unit *u, gls_insn *in, uint32_t p0, uint32_t c0, uint32_t t0,
                     uint32_t n0)
{
    for (uint32_t j = 0; j < gls_op[in->op].noperands; j++) {
        uint32_t *v = &in->u[j];
        switch ((gls_operand_kind)gls_op[in->op].kind[j]) {
        case GLS_KIND_OBJECT: *v = u->refs[*v].target->final_index; break;
        case GLS_KIND_TEXTURE: *v = gls_bundle_find_texture(b, u->texrefs[*v].name); break;
        case GLS_KIND_FIRST_POS: *v += p0; break;
        case GLS_KIND_FIRST_COL: if (*v != GLS_NONE) *v += c0; break;
        case GLS_KIND_FIRST_TC: if (*v != GLS_NONE) *v += t0; break;
        case GLS_KIND_FIRST_NRM: *v += n0; break;
        case GLS_KIND_INSTNAME: *v = find_name(b->instnames, b->ninstnames, u->instnames[*v].name); break;
        case GLS_KIND_MARKNAME: *v = find_name(b->marknames, b->nmarknames, u->marknames[*v].name); break;
        case GLS_KIND_CLASSNAME: *v = find_name(b->marknames, b->nmarknames, u->classnames[*v].name); break;
        case GLS_KIND_NUM: case GLS_KIND_ANGLE: case GLS_KIND_COMPONENT: case GLS_KIND_ALPHA:
        case GLS_KIND_TEXMODE: case GLS_KIND_PRIMKIND: case GLS_KIND_NVERT: case GLS_KIND_COUNT:
        case GLS_KIND_LIGHTKIND: case GLS_KIND_INTENSITY: case GLS_KIND_SHADOWRES:
            break; /* not an index */
        }
    }
}

/* Unit u as object o of the bundle: its vertices appended to the bundle's,
 * its code relocated, its source lines.  0, or -1: out of memory. */
static int add_object(gls_bundle *b, const gls_unit *u, gls_object *o)
{
    uint32_t p0 = b->npos, c0 = b->ncol, t0 = b->ntex, n0 = b->nnrm;
    /* a unit without colours has u->col == NULL: memcpy(NULL, 0) is undefined */
    if (u->npos)
        memcpy(b->pos + p0, u->pos, u->npos * sizeof *u->pos);
    if (u->ncol)
        memcpy(b->col + c0, u->col, u->ncol * sizeof *u->col);
    if (u->ntc)
        memcpy(b->tc + t0, u->tc, u->ntc * sizeof *u->tc);
    b->npos += u->npos;
    b->ncol += u->ncol;
    b->ntex += u->ntc;
    if (u->nnrm)
        memcpy(b->nrm + n0, u->nrm, u->nnrm * sizeof *u->nrm);
    b->nnrm += u->nnrm;
    gls_buf code = {0};
    size_t pos = 0;
    int has_src = u->ninsn && u->lines[0].file != GLS_NONE;
    o->src = has_src ? malloc(u->ninsn * sizeof *o->src) : NULL;
    if (!(o->name = strdup(u->name)) || (has_src && !o->src))
        return -1;
    for (uint32_t k = 0; k < u->ninsn; k++) {
        gls_insn in;
        gls_insn_decode(u->code.data, u->code.len, &pos, &in);
        relocate(b, u, &in, p0, c0, t0, n0);
        if (gls_insn_encode(&code, &in)) {
            free(code.data);
            return -1;
        }
        if (has_src)
            o->src[k] = u->lines[k];
    }
    o->code = code.data;
    o->code_len = (uint32_t)code.len;
    o->ninsn = u->ninsn;
    return 0;
}

/* The textures of the bundle, sorted: every loaded one (all_textures) or
 * those a unit of units[0..nu) uses; their count. */
static uint32_t pick_textures(gls_compiler *c, gls_unit *const *units, uint32_t nu, int all_textures,
                              tex_entry **texs)
{
    uint32_t nt = 0;
    gls_strmap used = {0};
    for (uint32_t i = 0; i < nu; i++)
        for (uint32_t k = 0; k < units[i]->ntexrefs; k++)
            gls_strmap_put(&used, units[i]->texrefs[k].name, (void *)1);
    for (size_t i = 0; i < c->nalltex; i++)
        if (c->alltex[i]->ok && (all_textures || gls_strmap_get(&used, c->alltex[i]->name)))
            texs[nt++] = c->alltex[i];
    gls_strmap_free(&used);
    qsort(texs, nt, sizeof *texs, cmp_tex);
    return nt;
}

/* Build the bundle from every unit with state 2 and every loaded texture
 * that a reachable unit uses (all loaded ones in library mode). */
gls_bundle *gls_assemble(gls_compiler *c, const gls_unit *top, int all_textures)
{
    gls_bundle *b = calloc(1, sizeof *b);
    gls_unit **units = malloc((c->nall ? c->nall : 1) * sizeof *units);
    tex_entry **texs = malloc((c->nalltex ? c->nalltex : 1) * sizeof *texs);
    uint32_t nu = 0, nt = 0;
    if (!b || !units || !texs)
        goto oom;
    for (size_t i = 0; i < c->nall; i++)
        if (c->all[i]->state == 2)
            units[nu++] = c->all[i];
    qsort(units, nu, sizeof *units, cmp_unit);
    nt = pick_textures(c, units, nu, all_textures, texs);

    b->version = GLS_FORMAT_VERSION;
    b->nobjects = nu;
    b->ntextures = nt;
    b->objects = calloc(nu ? nu : 1, sizeof *b->objects);
    b->textures = calloc(nt ? nt : 1, sizeof *b->textures);
    if (!b->objects || !b->textures)
        goto oom;
    b->top = GLS_NONE;
    uint64_t npos = 0, ncol = 0, ntc = 0, nnrm = 0;
    for (uint32_t i = 0; i < nu; i++) {
        units[i]->final_index = i;
        if (units[i] == top)
            b->top = i;
        npos += units[i]->npos;
        ncol += units[i]->ncol;
        ntc += units[i]->ntc;
        nnrm += units[i]->nnrm;
    }
    if (npos > GLS_MAX_VERTICES || ncol > GLS_MAX_VERTICES || ntc > GLS_MAX_VERTICES || nnrm > GLS_MAX_VERTICES) {
        gls_error_at(&c->diag, GLS_NOLOC, "the scene has more than %u vertices", GLS_MAX_VERTICES);
        goto fail;
    }
    for (uint32_t i = 0; i < nt; i++) {
        b->textures[i] = texs[i]->tex;
        b->textures[i].name = strdup(texs[i]->name);
        b->textures[i].rgba = malloc((size_t)texs[i]->tex.width * texs[i]->tex.height * 4);
        if (!b->textures[i].name || !b->textures[i].rgba)
            goto oom;
        memcpy(b->textures[i].rgba, texs[i]->tex.rgba, (size_t)texs[i]->tex.width * texs[i]->tex.height * 4);
    }
    static const names_of inst_kinds[] = {instnames_of}, mark_kinds[] = {marknames_of, classnames_of};
    if (add_names(&b->instnames, &b->ninstnames, units, nu, inst_kinds, 1) ||
        add_names(&b->marknames, &b->nmarknames, units, nu, mark_kinds, 2))
        goto oom;
    b->pos = malloc(npos * sizeof *b->pos + 1);
    b->col = malloc(ncol * sizeof *b->col + 1);
    b->tc = malloc(ntc * sizeof *b->tc + 1);
    b->nrm = nnrm ? malloc(nnrm * sizeof *b->nrm) : NULL;
    if (!b->pos || !b->col || !b->tc || (nnrm && !b->nrm))
        goto oom;
    for (uint32_t i = 0; i < nu; i++)
        if (add_object(b, units[i], &b->objects[i]))
            goto oom;
    b->nsources = c->nsources;
    b->sources = calloc(c->nsources ? c->nsources : 1, sizeof *b->sources);
    if (!b->sources)
        goto oom;
    for (uint32_t i = 0; i < c->nsources; i++)
        if (!(b->sources[i] = strdup(c->sources[i])))
            goto oom;
    if (add_templates(b, units, nu))
        goto oom;
    b->features = gls_bundle_features(b);
    free(units);
    free(texs);
    return b;
oom:
    gls_error_at(&c->diag, GLS_NOLOC, "out of memory assembling the bundle");
fail:
    free(units);
    free(texs);
    gls_bundle_free(b);
    return NULL;
}
