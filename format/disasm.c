/* Text dump of a validated bundle.  Stable by construction: objects and
 * textures are printed in name order, references by name, and no index or
 * offset that would shift when an unrelated object changes is printed.
 * Numbers print in their shortest exact form, so they round-trip. */
#include <stdlib.h>
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

/* The vertex lines after an instruction that draws vertices. */
static void print_vertices(const gls_bundle *b, const gls_vertex_span *s, FILE *out)
{
    for (uint32_t i = 0; i < s->n; i++) {
        const gls_vec4 *v = &b->pos[s->first_pos + i];
        fputs("    vert", out);
        print_d(out, v->x);
        print_d(out, v->y);
        print_d(out, v->z);
        if (v->w != 1.0)
            print_d(out, v->w);
        if (s->first_col != GLS_NONE) {
            const gls_rgba *q = &b->col[s->first_col + i];
            fputs("  col", out);
            print_f(out, q->r);
            print_f(out, q->g);
            print_f(out, q->b);
            print_f(out, q->a);
        }
        if (s->first_tc != GLS_NONE) {
            fputs("  tex", out);
            print_f(out, b->tc[s->first_tc + i].s);
            print_f(out, b->tc[s->first_tc + i].t);
        }
        if (s->first_nrm != GLS_NONE) {
            const gls_nrm *q = &b->nrm[s->first_nrm + i];
            fputs("  normal", out);
            print_f(out, q->x);
            print_f(out, q->y);
            print_f(out, q->z);
        }
        fputc('\n', out);
    }
}

/* One instruction line, without its end: the opcode's name (or the
 * primitive's kind, for an instruction that has one), then its operands
 * as their kinds print: numbers, enumeration names, vertex counts, object
 * and texture names.  FIRST_ indices are not printed: the vertex lines
 * show what they select. */
static void print_insn(const gls_bundle *b, const gls_insn *in, FILE *out)
{
    const gls_op_info *op = &gls_op[in->op];
    int kind = gls_op_find(in->op, GLS_KIND_PRIMKIND);
    fprintf(out, "  %s", kind >= 0 ? gls_prim_name[in->u[kind]] : op->name);
    for (uint32_t i = 0; i < op->noperands; i++) {
        uint32_t v = in->u[i];
        switch ((gls_operand_kind)op->kind[i]) {
        case GLS_KIND_NUM:
        case GLS_KIND_ANGLE:
        case GLS_KIND_COMPONENT:
        case GLS_KIND_ALPHA:
        case GLS_KIND_INTENSITY:
            print_d(out, in->d[i]);
            break;
        case GLS_KIND_TEXMODE:
        case GLS_KIND_LIGHTKIND:
            fprintf(out, " %s", gls_kind[op->kind[i]].value_names[v]);
            break;
        case GLS_KIND_NVERT:
        case GLS_KIND_SHADOWRES:
            fprintf(out, " %u", v);
            break;
        case GLS_KIND_OBJECT:
            fprintf(out, " %s", b->objects[v].name);
            break;
        case GLS_KIND_TEXTURE:
            fprintf(out, " %s", b->textures[v].name);
            break;
        case GLS_KIND_INSTNAME: /* quoted, as the call wrote it */
            fprintf(out, " \"%s\"", b->instnames[v]);
            break;
        case GLS_KIND_MARKNAME: /* quoted, as mark wrote it */
        case GLS_KIND_CLASSNAME: /* likewise, as class wrote it */
            fprintf(out, " \"%s\"", b->marknames[v]);
            break;
        case GLS_KIND_PRIMKIND:  /* printed as the name */
        case GLS_KIND_FIRST_POS: /* shown by the vertex lines */
        case GLS_KIND_FIRST_COL:
        case GLS_KIND_FIRST_TC:
        case GLS_KIND_FIRST_NRM:
        case GLS_KIND_COUNT:
            break;
        }
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
    fprintf(out, "objects: %u, textures: %u, templates: %u, vertices: %u\n", b->nobjects, b->ntextures,
            b->ntemplates, b->npos);
    if (b->ninstnames) /* a line only where there are names: other dumps stay as they were */
        fprintf(out, "instance names: %u\n", b->ninstnames);
    if (b->nmarknames) { /* likewise: marks (instructions) and their distinct names, */
        uint64_t nmarks = 0;  /* and the objects given a class, and their classes      */
        uint32_t nlandmarks = 0, nclassed = 0, nclasses = 0;
        uint8_t *use = calloc(b->nmarknames, 1); /* per name: 1 mark, 2 class */
        for (uint32_t i = 0; use && i < b->nobjects; i++) {
            size_t pos = 0;
            gls_insn in;
            while (pos < b->objects[i].code_len &&
                   gls_insn_decode(b->objects[i].code, b->objects[i].code_len, &pos, &in) == 0) {
                nmarks += in.op == GLS_OP_MARK;
                nclassed += in.op == GLS_OP_CLASS;
                uint32_t v = in.op == GLS_OP_MARK ? in.u[GLS_ARG_MARK_NAME] : in.u[GLS_ARG_CLASS_NAME];
                if ((in.op == GLS_OP_MARK || in.op == GLS_OP_CLASS) && v < b->nmarknames)
                    use[v] |= in.op == GLS_OP_MARK ? 1 : 2;
            }
        }
        for (uint32_t i = 0; use && i < b->nmarknames; i++)
            nlandmarks += use[i] & 1, nclasses += use[i] >> 1;
        free(use);
        if (nmarks)
            fprintf(out, "marks: %llu, landmark names: %u\n", (unsigned long long)nmarks, nlandmarks);
        if (nclassed)
            fprintf(out, "classes: %u objects, %u classes\n", nclassed, nclasses);
    }

    for (uint32_t i = 0; i < b->ntextures; i++) {
        const gls_texture *t = &b->textures[i];
        uLong crc = crc32_z(crc32(0L, Z_NULL, 0), t->rgba, (size_t)t->width * t->height * 4);
        fprintf(out, "\ntexture %s %ux%u rgba8%s crc32=%08lx\n", t->name, t->width, t->height,
                (t->flags & GLS_TEX_ALPHA_HOLES) ? " alpha-holes" : "", (unsigned long)crc);
    }
    /* a template: its parameters with their defaults, and what its text is */
    for (uint32_t i = 0; i < b->ntemplates; i++) {
        const gls_template *t = &b->templates[i];
        fprintf(out, "\ntemplate %s", t->name);
        for (uint32_t k = 0; k < t->nparams; k++) {
            char num[40];
            gls_fmt_double(num, sizeof num, t->defaults[k]);
            fprintf(out, "%s%s=%s", k ? "," : "(", t->params[k], num);
        }
        uLong crc = crc32_z(crc32(0L, Z_NULL, 0), (const Bytef *)t->text, t->text_len);
        fprintf(out, ") text %u bytes crc32=%08lx", t->text_len, (unsigned long)crc);
        if (with_source)
            fprintf(out, "  ; %s", b->sources[t->source]);
        fputc('\n', out);
    }
    for (uint32_t i = 0; i < b->nobjects; i++) {
        const gls_object *o = &b->objects[i];
        fprintf(out, "\nobject %s\n", o->name);
        size_t pos = 0;
        for (uint32_t k = 0; k < o->ninsn; k++) {
            gls_insn in;
            gls_insn_decode(o->code, o->code_len, &pos, &in);
            print_insn(b, &in, out);
            print_src(b, o, k, out, with_source);
            gls_vertex_span s;
            if (gls_insn_vertices(&in, &s))
                print_vertices(b, &s, out);
        }
    }
}
