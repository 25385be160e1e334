/* Text dump of a validated bundle.  Stable by construction: objects and
 * textures are printed in name order, references by name, and no index or
 * offset that would shift when an unrelated object changes is printed.
 * Numbers print in their shortest exact form, so they round-trip. */
#include <zlib.h>
#include "disasm.h"
#include "numfmt.h"

static void print_d(FILE *out, double v)
{
    char buf[40];
    gls_fmt_double(buf, sizeof buf, v);
    fprintf(out, " %s", buf);
}

static void print_f(FILE *out, float v)
{
    char buf[40];
    gls_fmt_float(buf, sizeof buf, v);
    fprintf(out, " %s", buf);
}

static void print_src(const gls_bundle *b, const gls_object *o, uint32_t k, FILE *out, int with_source)
{
    if (with_source && o->src)
        fprintf(out, "  ; %s:%u", b->sources[o->src[k].file], o->src[k].line);
    fputc('\n', out);
}

static void print_prim(const gls_bundle *b, const gls_insn *in, FILE *out)
{
    uint32_t n = in->u[1], p = in->u[2], c = in->u[3], x = in->u[4];
    for (uint32_t i = 0; i < n; i++) {
        const gls_vec4 *v = &b->pos[p + i];
        fputs("    vert", out);
        print_d(out, v->x);
        print_d(out, v->y);
        print_d(out, v->z);
        if (v->w != 1.0)
            print_d(out, v->w);
        if (c != GLS_NONE) {
            const gls_rgba *q = &b->col[c + i];
            fputs("  col", out);
            print_f(out, q->r);
            print_f(out, q->g);
            print_f(out, q->b);
            print_f(out, q->a);
        }
        if (x != GLS_NONE) {
            fputs("  tex", out);
            print_f(out, b->tc[x + i].s);
            print_f(out, b->tc[x + i].t);
        }
        fputc('\n', out);
    }
}

void gls_disassemble(const gls_bundle *b, FILE *out, int with_source)
{
    fprintf(out, "glscene bundle, format version %u\n", b->version);
    fputs("features:", out);
    if (!b->features)
        fputs(" none", out);
    for (int bit = 0; bit < 32; bit++)
        if (b->features & (1u << bit))
            fprintf(out, " %s", gls_feature_name[bit] ? gls_feature_name[bit] : "unknown");
    fputc('\n', out);
    if (b->top == GLS_NONE)
        fputs("top: none (library bundle)\n", out);
    else
        fprintf(out, "top: %s\n", b->objects[b->top].name);
    fprintf(out, "objects: %u, textures: %u, vertices: %u\n", b->nobjects, b->ntextures, b->npos);

    for (uint32_t i = 0; i < b->ntextures; i++) {
        const gls_texture *t = &b->textures[i];
        uLong crc = crc32_z(crc32(0L, Z_NULL, 0), t->rgba, (size_t)t->width * t->height * 4);
        fprintf(out, "\ntexture %s %ux%u rgba8%s crc32=%08lx\n", t->name, t->width, t->height,
                (t->flags & GLS_TEX_ALPHA_HOLES) ? " alpha-holes" : "", (unsigned long)crc);
    }
    for (uint32_t i = 0; i < b->nobjects; i++) {
        const gls_object *o = &b->objects[i];
        fprintf(out, "\nobject %s\n", o->name);
        size_t pos = 0;
        for (uint32_t k = 0; k < o->ninsn; k++) {
            gls_insn in;
            gls_insn_decode(o->code, o->code_len, &pos, &in);
            switch (in.op) {
            case GLS_OP_TEXMODE:
                fprintf(out, "  texmode %s", gls_texmode_name[in.u[0]]);
                break;
            case GLS_OP_TEXTURE:
                fprintf(out, "  texture %s", b->textures[in.u[0]].name);
                break;
            case GLS_OP_CALL:
                fprintf(out, "  call %s", b->objects[in.u[0]].name);
                break;
            case GLS_OP_PRIM:
                fprintf(out, "  %s %u", gls_prim_name[in.u[0]], in.u[1]);
                break;
            default:
                fprintf(out, "  %s", gls_op_name[in.op]);
                for (uint32_t j = 0; j < in.nd; j++)
                    print_d(out, in.d[j]);
                break;
            }
            print_src(b, o, k, out, with_source);
            if (in.op == GLS_OP_PRIM)
                print_prim(b, &in, out);
        }
    }
}
