/* Small bundle utilities: feature computation, lookup, freeing. */
#include <stdlib.h>
#include <string.h>
#include "bundle.h"

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
        while (pos < o->code_len && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0) {
            switch (in.op) {
            case GLS_OP_TEXTURE:
                f |= GLS_FEAT_TEXTURES;
                if (in.u[0] < b->ntextures && (b->textures[in.u[0]].flags & GLS_TEX_ALPHA_HOLES))
                    f |= GLS_FEAT_ALPHA_TEST;
                break;
            case GLS_OP_TEXMODE:
                if (in.u[0] == GLS_MODE_MODULATE)
                    f |= GLS_FEAT_MODULATE;
                if (in.u[0] == GLS_MODE_REPLACE)
                    f |= GLS_FEAT_REPLACE;
                break;
            case GLS_OP_COLOR:
                if (in.d[3] < 1.0)
                    f |= GLS_FEAT_TRANSLUCENT;
                break;
            case GLS_OP_PRIM:
                if (in.u[3] != GLS_NONE)
                    f |= GLS_FEAT_VERTEX_COLOR;
                if (in.u[4] != GLS_NONE)
                    f |= GLS_FEAT_TEXCOORDS;
                break;
            default:
                break;
            }
        }
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
    free(b->objects);
    free(b->textures);
    free(b->sources);
    free(b->pos);
    free(b->col);
    free(b->tc);
    free(b);
}
