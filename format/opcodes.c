/* Tables generated from the X-macro lists in opcodes.h and bundle.h. */
#include <stddef.h>
#include "opcodes.h"
#include "bundle.h"

const char *const gls_texmode_name[GLS_MODE_COUNT] = {"color", "replace", "modulate"};
const char *const gls_prim_name[GLS_PRIM_COUNT] = {"poly", "qstrip", "tstrip", "tfan"};
const char *const gls_light_name[GLS_LIGHT_COUNT] = {"directional", "point", "ambient"};

#define BYTES_F64 8
#define BYTES_U8 1
#define BYTES_U32 4

const gls_kind_info gls_kind[GLS_KIND_COUNT] = {
#define GLS_X_KIND(kind, storage, values, names, noun) \
    [GLS_KIND_##kind] = {GLS_STORE_##storage, BYTES_##storage, values, names, noun},
    GLS_OPERAND_KINDS(GLS_X_KIND)
#undef GLS_X_KIND
};

const gls_op_info gls_op[GLS_OP_COUNT] = {
#define GLS_X_OP(e, name, flow, operands) [GLS_OP_##e] = {name, GLS_FLOW_##flow, GLS_NARGS_##e, {operands GLS_KIND_COUNT}},
#define GLS_X_KIND_OF(kind, name) GLS_KIND_##kind,
    GLS_OPCODES(GLS_X_OP, GLS_X_KIND_OF)
#undef GLS_X_OP
#undef GLS_X_KIND_OF
};

int gls_op_find(gls_opcode op, gls_operand_kind k)
{
    for (uint32_t i = 0; i < gls_op[op].noperands; i++)
        if (gls_op[op].kind[i] == k)
            return (int)i;
    return -1;
}

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
