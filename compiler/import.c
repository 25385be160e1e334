/* Objects taken from a bundle root (spec/bundle.md 13, spec/language.md
 * 1.6): an object's code is decoded and its operands made unit-local again,
 * by their kinds (format/opcodes.h): object and texture indices become
 * names, to be resolved through the whole search path; vertices are copied
 * into the unit. */
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "linker.h"
#include "specname.h"

/* Append n elements of size elem from src to the array *arrp (a T **) of
 * *count elements and capacity *cap; returns the index of the first, or
 * GLS_NONE when out of memory. */
static uint32_t append(void *arrp, uint32_t *count, size_t *cap, const void *src, uint32_t n, size_t elem)
{
    if (gls_grow(arrp, cap, (size_t)*count + n, elem))
        return GLS_NONE;
    char *arr;
    memcpy(&arr, arrp, sizeof arr);
    memcpy(arr + (size_t)*count * elem, src, (size_t)n * elem);
    uint32_t first = *count;
    *count += n;
    return first;
}

/* A call of b's object named nm, as the call that made it was written: its
 * name without parameter values, and the values (format/specname.h).
 * Returns the reference's index, or GLS_NONE when out of memory. */
static uint32_t call_ref(gls_unit *u, const char *nm, gls_loc loc)
{
    gls_specarg args[GLS_MAX_PARAMS];
    unsigned n;
    long base = gls_specname_parse(nm, args, GLS_MAX_PARAMS, &n); /* validated at load */
    uint32_t r = gls_unit_add_ref(&u->refs, &u->nrefs, &u->refs_cap, nm, (size_t)base, loc);
    if (r == GLS_NONE || !n)
        return r;
    gls_ref *ref = &u->refs[r];
    if (!(ref->args = calloc(n, sizeof *ref->args)))
        return GLS_NONE;
    for (unsigned k = 0; k < n; k++) {
        if (!(ref->args[k].name = strndup(args[k].name, args[k].len)))
            return GLS_NONE;
        ref->args[k].value = args[k].value;
        ref->args[k].loc = loc;
        ref->nargs++;
    }
    return r;
}

/* Operand i of in, read from bundle b, made unit-local in u: object and
 * texture indices become by-name references, vertex indices point at
 * copies of the vertices in u.  Returns -1 when out of memory. */
static int import_operand(gls_unit *u, const gls_bundle *b, gls_insn *in, uint32_t i, gls_loc loc)
{
    uint32_t *v = &in->u[i];
    gls_vertex_span s = {0};
    gls_insn_vertices(in, &s);
    const char *nm;
    switch ((gls_operand_kind)gls_op[in->op].kind[i]) {
    case GLS_KIND_OBJECT:
        *v = call_ref(u, b->objects[*v].name, loc);
        break;
    case GLS_KIND_TEXTURE:
        nm = b->textures[*v].name;
        *v = gls_unit_add_ref(&u->texrefs, &u->ntexrefs, &u->texrefs_cap, nm, strlen(nm), loc);
        break;
    case GLS_KIND_INSTNAME:
        nm = b->instnames[*v];
        *v = gls_unit_add_ref(&u->instnames, &u->ninstnames, &u->instnames_cap, nm, strlen(nm), loc);
        break;
    case GLS_KIND_MARKNAME:
        nm = b->marknames[*v];
        *v = gls_unit_add_ref(&u->marknames, &u->nmarknames, &u->marknames_cap, nm, strlen(nm), loc);
        break;
    case GLS_KIND_CLASSNAME: /* a class name of the same table */
        nm = b->marknames[*v];
        *v = gls_unit_add_ref(&u->classnames, &u->nclassnames, &u->classnames_cap, nm, strlen(nm), loc);
        break;
    case GLS_KIND_FIRST_POS:
        *v = append(&u->pos, &u->npos, &u->pos_cap, b->pos + *v, s.n, sizeof *u->pos);
        break;
    case GLS_KIND_FIRST_COL:
        if (*v == GLS_NONE)
            return 0;
        *v = append(&u->col, &u->ncol, &u->col_cap, b->col + *v, s.n, sizeof *u->col);
        break;
    case GLS_KIND_FIRST_TC:
        if (*v == GLS_NONE)
            return 0;
        *v = append(&u->tc, &u->ntc, &u->tc_cap, b->tc + *v, s.n, sizeof *u->tc);
        break;
    case GLS_KIND_FIRST_NRM:
        *v = append(&u->nrm, &u->nnrm, &u->nrm_cap, b->nrm + *v, s.n, sizeof *u->nrm);
        break;
    case GLS_KIND_LIGHTKIND:
    case GLS_KIND_INTENSITY:
    case GLS_KIND_SHADOWRES:
    case GLS_KIND_NUM:
    case GLS_KIND_ANGLE:
    case GLS_KIND_COMPONENT:
    case GLS_KIND_ALPHA:
    case GLS_KIND_TEXMODE:
    case GLS_KIND_PRIMKIND:
    case GLS_KIND_NVERT:
    case GLS_KIND_COUNT:
        return 0; /* not an index */
    }
    return *v == GLS_NONE ? -1 : 0;
}

/* Import object oi of a library bundle as a unit: decode its code, turning
 * bundle indices back into by-name references and unit-local vertices. */
gls_unit *gls_unit_from_lib(gls_compiler *c, const gls_bundle *b, uint32_t oi, gls_loc loc)
{
    const gls_object *o = &b->objects[oi];
    gls_unit *u = calloc(1, sizeof *u);
    if (!u || !(u->name = strdup(o->name)))
        goto oom;
    u->src.path = "";
    size_t pos = 0;
    for (uint32_t k = 0; k < o->ninsn; k++) {
        gls_insn in;
        gls_insn_decode(o->code, o->code_len, &pos, &in); /* validated at load */
        uint32_t file = GLS_NONE, line = 0;
        if (o->src) {
            file = gls_add_source(c, b->sources[o->src[k].file]);
            line = o->src[k].line;
            if (file == GLS_NONE)
                goto oom;
        }
        for (uint32_t i = 0; i < gls_op[in.op].noperands; i++)
            if (import_operand(u, b, &in, i, loc))
                goto oom;
        u->src_file = file;
        if (gls_unit_emit(u, &in, line))
            goto oom;
        if (!o->src)
            u->lines[u->ninsn - 1].file = GLS_NONE;
    }
    return u;
oom:
    gls_unit_free(u);
    gls_error_at(&c->diag, loc, "out of memory");
    return NULL;
}
