/* Primitive blocks (spec/language.md 8): the block's name, the state of
 * the open block that vert, col and tex fill in (instructions.c), and when
 * it closes the vertex-count check and the one PRIM instruction. */
#include "sema.h"

void sema_block_open(gls_parse *ctx, gls_tok name)
{
    ctx->nargs = 0;
    if (ctx->in_prim) {
        ERR(ctx, name.line, name.col, "primitive blocks cannot be nested");
        ctx->in_prim++;
        return;
    }
    int k = sema_prim_kind(name);
    if (k < 0) {
        int is_instr = 0;
        for (size_t i = 0; i < sema_ninstrs; i++)
            is_instr |= sema_tok_is(name, sema_instrs[i].name);
        const char *s =
            is_instr ? NULL : gls_suggest_alias(name.p, name.len, gls_prim_name, GLS_PRIM_COUNT, sema_aliases, sema_naliases);
        if (s)
            ERR(ctx, name.line, name.col, "unknown primitive '%.*s'; did you mean '%s'?", (int)name.len, name.p, s);
        else
            ERR(ctx, name.line, name.col, "'%.*s' is not a primitive; the primitives are poly, qstrip, tstrip, tfan",
                (int)name.len, name.p);
    }
    ctx->in_prim = 1;
    ctx->prim_kind = k;
    ctx->prim_tok = name;
    ctx->prim_pos0 = ctx->u->npos;
    ctx->prim_col0 = ctx->u->ncol;
    ctx->prim_tc0 = ctx->u->ntc;
    ctx->prim_nrm0 = ctx->u->nnrm;
    ctx->prim_nvert = 0;
    ctx->prim_has_col = ctx->prim_has_tc = ctx->prim_has_nrm = 0;
    ctx->errors_at_block = ctx->d->errors;
}

void sema_block_close(gls_parse *ctx)
{
    if (ctx->in_prim > 1) {
        ctx->in_prim--;
        return;
    }
    ctx->in_prim = 0;
    int k = ctx->prim_kind;
    /* an error inside the block already dropped something: do not pile a
       vertex-count error on top of it */
    if (k < 0 || ctx->d->errors != ctx->errors_at_block)
        return;
    gls_tok t = ctx->prim_tok;
    unsigned nv = ctx->prim_nvert, min = gls_prim_min_verts(k);
    if (nv < min || (gls_prim_needs_even(k) && nv % 2)) {
        if (gls_prim_needs_even(k))
            ERR(ctx, t.line, t.col, "'%s' needs an even number of vertices, at least %u; it has %u", gls_prim_name[k],
                min, nv);
        else
            ERR(ctx, t.line, t.col, "'%s' needs at least %u vertices; it has %u", gls_prim_name[k], min, nv);
        return;
    }
    /* with normals a PRIMN: PRIM's operands, then the first normal */
    gls_insn in = {.op = ctx->prim_has_nrm ? GLS_OP_PRIMN : GLS_OP_PRIM};
    in.u[GLS_ARG_PRIMN_NRM] = ctx->prim_nrm0;
    in.u[GLS_ARG_PRIM_KIND] = (uint32_t)k;
    in.u[GLS_ARG_PRIM_N] = nv;
    in.u[GLS_ARG_PRIM_POS] = ctx->prim_pos0;
    in.u[GLS_ARG_PRIM_COL] = ctx->prim_has_col ? ctx->prim_col0 : GLS_NONE;
    in.u[GLS_ARG_PRIM_TC] = ctx->prim_has_tc ? ctx->prim_tc0 : GLS_NONE;
    sema_emit(ctx, &in, t.line);
    gls_texuse_draw(&ctx->texuse);
}
