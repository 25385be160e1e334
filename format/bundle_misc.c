/* Small bundle utilities: feature computation, lookup, freeing. */
#include <stdlib.h>
#include <string.h>
#include "bundle.h"

/* The features an operand implies, by its kind (spec/bundle.md, section 11). */
static uint32_t operand_features(const gls_bundle *b, const gls_insn *in, uint32_t i)
{
    static const uint32_t texmode_feature[GLS_MODE_COUNT] = {
        [GLS_MODE_COLOR] = 0, [GLS_MODE_REPLACE] = GLS_FEAT_REPLACE, [GLS_MODE_MODULATE] = GLS_FEAT_MODULATE};
    uint32_t v = in->u[i];
    switch ((gls_operand_kind)gls_op[in->op].kind[i]) {
    case GLS_KIND_TEXTURE:
        if (v < b->ntextures && (b->textures[v].flags & GLS_TEX_ALPHA_HOLES))
            return GLS_FEAT_TEXTURES | GLS_FEAT_ALPHA_TEST;
        return GLS_FEAT_TEXTURES;
    case GLS_KIND_TEXMODE:
        return v < GLS_MODE_COUNT ? texmode_feature[v] : 0;
    case GLS_KIND_ALPHA:
        return in->d[i] < 1.0 ? GLS_FEAT_TRANSLUCENT : 0;
    case GLS_KIND_FIRST_COL:
        return v != GLS_NONE ? GLS_FEAT_VERTEX_COLOR : 0;
    case GLS_KIND_FIRST_TC:
        return v != GLS_NONE ? GLS_FEAT_TEXCOORDS : 0;
    case GLS_KIND_MARKNAME:
        return GLS_FEAT_MARKS;
    case GLS_KIND_LIGHTKIND:
        return GLS_FEAT_LIGHTS;
    case GLS_KIND_SHADOWRES:
        return GLS_FEAT_SHADOWS;
    case GLS_KIND_INTENSITY:
    case GLS_KIND_FIRST_NRM:
    case GLS_KIND_NUM:
    case GLS_KIND_ANGLE:
    case GLS_KIND_COMPONENT:
    case GLS_KIND_PRIMKIND:
    case GLS_KIND_NVERT:
    case GLS_KIND_OBJECT:
    case GLS_KIND_FIRST_POS:
    case GLS_KIND_INSTNAME:
    case GLS_KIND_CLASSNAME: /* a class draws nothing: no feature */
    case GLS_KIND_COUNT:
        break;
    }
    return 0;
}

uint32_t gls_bundle_features(const gls_bundle *b)
{
    uint32_t f = 0;
    for (uint32_t i = 0; i < b->npos; i++)
        if (b->pos[i].w != 1.0)
            f |= GLS_FEAT_HOMOGENEOUS;
    for (uint32_t i = 0; i < b->ncol; i++)
        if (b->col[i].a < 1.0f)
            f |= GLS_FEAT_TRANSLUCENT;
    for (uint32_t oi = 0; oi < b->nobjects; oi++) {
        const gls_object *o = &b->objects[oi];
        size_t pos = 0;
        gls_insn in;
        while (pos < o->code_len && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0)
            for (uint32_t i = 0; i < gls_op[in.op].noperands; i++)
                f |= operand_features(b, &in, i);
    }
    return f;
}

static int cmp_name(const char *key, const char *name) { return strcmp(key, name); }

#define BSEARCH(arr, n, key)                                   \
    do {                                                       \
        uint32_t lo = 0, hi = (n);                             \
        while (lo < hi) {                                      \
            uint32_t mid = lo + (hi - lo) / 2;                 \
            int c = cmp_name((key), (arr)[mid].name);          \
            if (c == 0)                                        \
                return mid;                                    \
            if (c < 0)                                         \
                hi = mid;                                      \
            else                                               \
                lo = mid + 1;                                  \
        }                                                      \
        return GLS_NONE;                                       \
    } while (0)

uint32_t gls_bundle_find_object(const gls_bundle *b, const char *name) { BSEARCH(b->objects, b->nobjects, name); }
uint32_t gls_bundle_find_texture(const gls_bundle *b, const char *name) { BSEARCH(b->textures, b->ntextures, name); }
uint32_t gls_bundle_find_template(const gls_bundle *b, const char *name)
{
    BSEARCH(b->templates, b->ntemplates, name);
}

void gls_bundle_free(gls_bundle *b)
{
    if (!b)
        return;
    for (uint32_t i = 0; b->objects && i < b->nobjects; i++) {
        free(b->objects[i].name);
        free(b->objects[i].code);
        free(b->objects[i].src);
    }
    for (uint32_t i = 0; b->textures && i < b->ntextures; i++) {
        free(b->textures[i].name);
        free(b->textures[i].rgba);
    }
    for (uint32_t i = 0; b->sources && i < b->nsources; i++)
        free(b->sources[i]);
    for (uint32_t i = 0; b->templates && i < b->ntemplates; i++) {
        gls_template *t = &b->templates[i];
        for (uint32_t k = 0; t->params && k < t->nparams; k++)
            free(t->params[k]);
        free(t->name);
        free(t->params);
        free(t->defaults);
        free(t->text);
    }
    for (uint32_t i = 0; b->instnames && i < b->ninstnames; i++)
        free(b->instnames[i]);
    free(b->instnames);
    for (uint32_t i = 0; b->marknames && i < b->nmarknames; i++)
        free(b->marknames[i]);
    free(b->marknames);
    free(b->templates);
    free(b->objects);
    free(b->textures);
    free(b->sources);
    free(b->pos);
    free(b->col);
    free(b->tc);
    free(b->nrm);
    free(b);
}
