/* Tables generated from the X-macro lists in opcodes.h and bundle.h. */
#include "opcodes.h"
#include "bundle.h"

const char *const gls_op_name[GLS_OP_COUNT] = {
#define GLS_X_NAME(e, name, schema) name,
    GLS_OPCODES(GLS_X_NAME)
#undef GLS_X_NAME
};

const char *const gls_op_schema[GLS_OP_COUNT] = {
#define GLS_X_SCHEMA(e, name, schema) schema,
    GLS_OPCODES(GLS_X_SCHEMA)
#undef GLS_X_SCHEMA
};

const char *const gls_texmode_name[GLS_MODE_COUNT] = {"color", "replace", "modulate"};
const char *const gls_prim_name[GLS_PRIM_COUNT] = {"poly", "qstrip", "tstrip", "tfan"};

const char *const gls_feature_name[32] = {
#define GLS_X_FNAME(e, bit, name, why) [bit] = name,
    GLS_FEATURES(GLS_X_FNAME)
#undef GLS_X_FNAME
};

const char *const gls_feature_why[32] = {
#define GLS_X_FWHY(e, bit, name, why) [bit] = why,
    GLS_FEATURES(GLS_X_FWHY)
#undef GLS_X_FWHY
};

unsigned gls_prim_min_verts(gls_primkind k)
{
    return k == GLS_PRIM_QSTRIP ? 4u : 3u;
}

int gls_prim_needs_even(gls_primkind k)
{
    return k == GLS_PRIM_QSTRIP;
}
