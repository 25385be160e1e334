/* Encoding and decoding of one instruction, driven by the operand kinds of
 * the opcode table (opcodes.h).  The encoder and decoder mirror each other. */
#include <stdlib.h>
#include <string.h>
#include "bundle.h"
#include "le.h"

int gls_insn_encode(gls_buf *b, const gls_insn *in)
{
    uint8_t tmp[1 + GLS_MAX_OPERANDS * 8];
    size_t k = 0;
    const gls_op_info *op = &gls_op[in->op];
    tmp[k++] = (uint8_t)in->op;
    for (uint32_t i = 0; i < op->noperands; i++) {
        switch (gls_kind[op->kind[i]].storage) {
        case GLS_STORE_F64: gls_le_put_f64(tmp + k, in->d[i]); break;
        case GLS_STORE_U8: tmp[k] = (uint8_t)in->u[i]; break;
        case GLS_STORE_U32: gls_le_put_u32(tmp + k, in->u[i]); break;
        }
        k += gls_kind[op->kind[i]].bytes;
    }
    return gls_buf_put(b, tmp, k);
}

int gls_insn_decode(const uint8_t *code, size_t len, size_t *pos, gls_insn *out)
{
    size_t p = *pos;
    if (p >= len || code[p] >= GLS_OP_COUNT)
        return -1;
    out->op = (gls_opcode)code[p++];
    const gls_op_info *op = &gls_op[out->op];
    for (uint32_t i = 0; i < op->noperands; i++) {
        const gls_kind_info *k = &gls_kind[op->kind[i]];
        if (len - p < k->bytes)
            return -1;
        switch (k->storage) {
        case GLS_STORE_F64: out->d[i] = gls_le_get_f64(code + p); break;
        case GLS_STORE_U8: out->u[i] = code[p]; break;
        case GLS_STORE_U32: out->u[i] = gls_le_get_u32(code + p); break;
        }
        p += k->bytes;
    }
    *pos = p;
    return 0;
}

int gls_insn_vertices(const gls_insn *in, gls_vertex_span *v)
{
    int n = gls_op_find(in->op, GLS_KIND_NVERT), p = gls_op_find(in->op, GLS_KIND_FIRST_POS);
    int c = gls_op_find(in->op, GLS_KIND_FIRST_COL), x = gls_op_find(in->op, GLS_KIND_FIRST_TC);
    int m = gls_op_find(in->op, GLS_KIND_FIRST_NRM);
    if (n < 0 || p < 0)
        return 0;
    v->n = in->u[n];
    v->first_pos = in->u[p];
    v->first_col = c < 0 ? GLS_NONE : in->u[c];
    v->first_tc = x < 0 ? GLS_NONE : in->u[x];
    v->first_nrm = m < 0 ? GLS_NONE : in->u[m];
    return 1;
}
