/* Encoding and decoding of one instruction, driven by the operand schema in
 * opcodes.h.  The encoder and decoder mirror each other. */
#include <stdlib.h>
#include <string.h>
#include "bundle.h"
#include "le.h"

int gls_buf_reserve(gls_buf *b, size_t n)
{
    if (n > SIZE_MAX - b->len)
        return -1;
    if (b->len + n > b->cap) {
        size_t cap = b->cap ? b->cap : 256;
        while (cap < b->len + n) {
            if (cap > SIZE_MAX / 2)
                return -1;
            cap *= 2;
        }
        uint8_t *d = realloc(b->data, cap);
        if (!d)
            return -1;
        b->data = d;
        b->cap = cap;
    }
    return 0;
}

int gls_buf_put(gls_buf *b, const void *p, size_t n)
{
    if (gls_buf_reserve(b, n))
        return -1;
    if (n)
        memcpy(b->data + b->len, p, n);
    b->len += n;
    return 0;
}

int gls_insn_encode(gls_buf *b, const gls_insn *in)
{
    uint8_t tmp[1 + GLS_MAX_OPERANDS * 8];
    size_t k = 0;
    uint32_t di = 0, ui = 0;
    tmp[k++] = (uint8_t)in->op;
    for (const char *s = gls_op_schema[in->op]; *s; s++) {
        if (*s == 'd') {
            gls_le_put_f64(tmp + k, in->d[di++]);
            k += 8;
        } else if (*s == 'b') {
            tmp[k++] = (uint8_t)in->u[ui++];
        } else {
            gls_le_put_u32(tmp + k, in->u[ui++]);
            k += 4;
        }
    }
    return gls_buf_put(b, tmp, k);
}

int gls_insn_decode(const uint8_t *code, size_t len, size_t *pos, gls_insn *out)
{
    size_t p = *pos;
    if (p >= len || code[p] >= GLS_OP_COUNT)
        return -1;
    out->op = (gls_opcode)code[p++];
    out->nd = out->nu = 0;
    for (const char *s = gls_op_schema[out->op]; *s; s++) {
        size_t w = *s == 'd' ? 8 : *s == 'b' ? 1 : 4;
        if (len - p < w)
            return -1;
        if (*s == 'd')
            out->d[out->nd++] = gls_le_get_f64(code + p);
        else if (*s == 'b')
            out->u[out->nu++] = code[p];
        else
            out->u[out->nu++] = gls_le_get_u32(code + p);
        p += w;
    }
    *pos = p;
    return 0;
}
