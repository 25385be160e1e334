/* Replay of a validated bundle into a gls_scene (scene.h).
 *
 * The interpreter keeps the state of opcodes.h: matrix M (double, row
 * major), colour, texture mode, texture.  PUSH/POP save and restore it on a
 * heap stack; CALL runs the callee on a copy (an implicit push/pop), so a
 * callee's changes never leak.  The validator guarantees that every index
 * is in range, the pushes balance and calls nest at most
 * GLS_MAX_CALL_DEPTH deep, so recursion on CALL is bounded and cheap.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "scene.h"
#include "vec.h"

typedef struct {
    double M[16];
    double rgba[4];
    uint32_t mode, texture;
} state;

/* One triangle before chunking: world vertices and its draw key. */
typedef struct {
    gls_drawkey key;
    int64_t cell[3];
    uint32_t idx; /* emission order: the final tie-break, for determinism */
} tri;

typedef struct {
    const gls_bundle *b;
    int has_color, has_texcoord;
    state *stack;
    size_t sp, cap;
    /* emitted triangles: 3 world vertices each, plus colours/texcoords */
    tri *tris;
    double *wpos;          /* 9 per triangle */
    uint8_t *wcol;         /* 12 per triangle */
    float *wtc;            /* 6 per triangle */
    size_t ntri, tcap;
    uint64_t dropped;
    int oom;
} walker;

static void identity(double A[16])
{
    memset(A, 0, 16 * sizeof *A);
    A[0] = A[5] = A[10] = A[15] = 1;
}

/* cos and sin of an angle in degrees, exact at multiples of 90 degrees so
 * that axis-aligned rotations keep exact coordinates exact. */
static void cos_sin_deg(double deg, double *c, double *s)
{
    double r = fmod(deg, 360.0);
    if (r < 0)
        r += 360.0;
    if (r == 0) { *c = 1; *s = 0; return; }
    if (r == 90) { *c = 0; *s = 1; return; }
    if (r == 180) { *c = -1; *s = 0; return; }
    if (r == 270) { *c = 0; *s = -1; return; }
    double a = r * (3.14159265358979323846 / 180.0);
    *c = cos(a);
    *s = sin(a);
}

/* The glRotate matrix.  A zero axis (the validator allows it) is no
 * rotation at all. */
static void rotation(double deg, double x, double y, double z, double A[16])
{
    identity(A);
    double len = sqrt(x * x + y * y + z * z);
    if (!(len > 0) || !isfinite(len))
        return;
    x /= len, y /= len, z /= len;
    double c, s;
    cos_sin_deg(deg, &c, &s);
    double t = 1 - c;
    A[0] = x * x * t + c;     A[1] = x * y * t - z * s; A[2] = x * z * t + y * s;
    A[4] = y * x * t + z * s; A[5] = y * y * t + c;     A[6] = y * z * t - x * s;
    A[8] = x * z * t - y * s; A[9] = y * z * t + x * s; A[10] = z * z * t + c;
}

static uint8_t unorm8(double v)
{
    /* colours are validated to 0..1; round to nearest like GL does */
    return (uint8_t)lrint(v * 255.0);
}

static int push_state(walker *w, const state *st)
{
    if (gls_grow(&w->stack, &w->cap, w->sp + 1, sizeof *w->stack))
        return -1;
    w->stack[w->sp++] = *st;
    return 0;
}

static int grow_tris(walker *w, size_t need)
{
    if (w->ntri + need <= w->tcap)
        return 0;
    /* four arrays of one capacity: grown by the largest element's rule */
    size_t cap = gls_grow_cap(w->tcap, w->ntri + need, 9 * sizeof *w->wpos);
    tri *t = cap ? gls_resize(w->tris, cap, sizeof *t) : NULL;
    if (t)
        w->tris = t;
    double *p = cap ? gls_resize(w->wpos, cap, 9 * sizeof *p) : NULL;
    if (p)
        w->wpos = p;
    uint8_t *c = cap ? gls_resize(w->wcol, cap, 12) : NULL;
    if (c)
        w->wcol = c;
    float *x = cap ? gls_resize(w->wtc, cap, 6 * sizeof *x) : NULL;
    if (x)
        w->wtc = x;
    if (!t || !p || !c || !x)
        return -1;
    w->tcap = cap;
    return 0;
}

/* Vertex k of a primitive, fully resolved. */
typedef struct {
    double p[3];
    uint8_t c[4];
    float st[2];
    int ok;
} vtx;

static void fetch(const walker *w, const state *st, const gls_insn *in, uint32_t k, vtx *v)
{
    const gls_bundle *b = w->b;
    const gls_vec4 *q = &b->pos[in->u[GLS_ARG_PRIM_POS] + k];
    const double *M = st->M;
    double h[4];
    m4_apply(M, q->x, q->y, q->z, q->w, h);
    /* homogeneous: divide through in double; 1/w is skipped when w == 1 so
     * ordinary coordinates stay bit-exact */
    /* A vertex must be finite and within GLS_SCENE_MAX_COORD of the
     * origin: beyond that a double no longer resolves a millimetre-sized
     * scene unit, and cell indices (coordinate / cell) would overflow the
     * integers they are stored in.  Such a vertex (from a huge scale, say)
     * drops its triangles, counted and shown by --explain. */
    v->ok = 1;
    for (int i = 0; i < 3; i++) {
        v->p[i] = h[3] == 1.0 ? h[i] : h[i] / h[3];
        if (!(fabs(v->p[i]) <= GLS_SCENE_MAX_COORD))
            v->ok = 0;
    }
    if (in->u[GLS_ARG_PRIM_COL] != GLS_NONE) {
        const gls_rgba *c = &b->col[in->u[GLS_ARG_PRIM_COL] + k];
        v->c[0] = unorm8(c->r), v->c[1] = unorm8(c->g), v->c[2] = unorm8(c->b);
    } else {
        v->c[0] = unorm8(st->rgba[0]), v->c[1] = unorm8(st->rgba[1]), v->c[2] = unorm8(st->rgba[2]);
    }
    /* Alpha is not blended (outputs are RGB): opaque, so that the alpha
     * test sees only the texture's binary alpha. */
    v->c[3] = 255;
    if (in->u[GLS_ARG_PRIM_TC] != GLS_NONE) {
        v->st[0] = b->tc[in->u[GLS_ARG_PRIM_TC] + k].s;
        v->st[1] = b->tc[in->u[GLS_ARG_PRIM_TC] + k].t;
    } else {
        v->st[0] = v->st[1] = 0;
    }
}

static void emit(walker *w, const gls_drawkey *key, const vtx *a, const vtx *b2, const vtx *c)
{
    if (!a->ok || !b2->ok || !c->ok) {
        w->dropped++;
        return;
    }
    if (grow_tris(w, 1)) {
        w->oom = 1;
        return;
    }
    size_t i = w->ntri++;
    const vtx *v[3] = {a, b2, c};
    tri *t = &w->tris[i];
    t->key = *key;
    t->idx = (uint32_t)i;
    /* the cell of the first vertex: exact under translations by multiples
     * of the cell size (a centroid would round differently far away) */
    for (int j = 0; j < 3; j++)
        t->cell[j] = (int64_t)floor(a->p[j] / GLS_SCENE_CELL);
    for (int k = 0; k < 3; k++) {
        memcpy(w->wpos + 9 * i + 3 * k, v[k]->p, 3 * sizeof(double));
        memcpy(w->wcol + 12 * i + 4 * k, v[k]->c, 4);
        memcpy(w->wtc + 6 * i + 2 * k, v[k]->st, 2 * sizeof(float));
    }
}

static void prim(walker *w, const state *st, const gls_insn *in)
{
    gls_drawkey key;
    memset(&key, 0, sizeof key);
    if (st->mode != GLS_MODE_COLOR && st->texture != GLS_NONE) {
        key.texture = st->texture;
        key.mode = (uint8_t)st->mode;
    } else {
        key.texture = GLS_NONE;
        key.mode = GLS_MODE_COLOR;
    }
    if (!w->has_color)
        for (int j = 0; j < 3; j++)
            key.rgba[j] = unorm8(st->rgba[j]);
    key.rgba[3] = w->has_color ? 0 : 255;
    uint32_t n = in->u[GLS_ARG_PRIM_N];
    vtx v0, v1, v2, v3;
    switch (in->u[GLS_ARG_PRIM_KIND]) {
    case GLS_PRIM_POLY: /* convex polygon: a fan, like GL_POLYGON */
    case GLS_PRIM_TFAN:
        fetch(w, st, in, 0, &v0);
        fetch(w, st, in, 1, &v1);
        for (uint32_t k = 2; k < n; k++) {
            fetch(w, st, in, k, &v2);
            emit(w, &key, &v0, &v1, &v2);
            v1 = v2;
        }
        break;
    case GLS_PRIM_TSTRIP:
        fetch(w, st, in, 0, &v0);
        fetch(w, st, in, 1, &v1);
        for (uint32_t k = 2; k < n; k++) {
            fetch(w, st, in, k, &v2);
            if (k % 2) /* keep GL's consistent winding: (k-1, k-2, k) */
                emit(w, &key, &v1, &v0, &v2);
            else
                emit(w, &key, &v0, &v1, &v2);
            v0 = v1, v1 = v2;
        }
        break;
    case GLS_PRIM_QSTRIP: /* quad 2k, 2k+1, 2k+3, 2k+2 */
        fetch(w, st, in, 0, &v0);
        fetch(w, st, in, 1, &v1);
        for (uint32_t k = 2; k + 1 < n; k += 2) {
            fetch(w, st, in, k, &v2);
            fetch(w, st, in, k + 1, &v3);
            emit(w, &key, &v0, &v1, &v3);
            emit(w, &key, &v0, &v3, &v2);
            v0 = v2, v1 = v3;
        }
        break;
    default:
        break; /* unreachable: the validator checked the kind */
    }
}

static void run(walker *w, uint32_t oi, state st)
{
    const gls_object *o = &w->b->objects[oi];
    size_t pos = 0, base = w->sp;
    gls_insn in;
    double A[16];
    while (!w->oom && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0) {
        switch (in.op) {
        case GLS_OP_END:
            w->sp = base;
            return;
        case GLS_OP_COLOR:
            memcpy(st.rgba, in.d + GLS_ARG_COLOR_R, sizeof st.rgba);
            break;
        case GLS_OP_TEXMODE:
            st.mode = in.u[GLS_ARG_TEXMODE_MODE];
            break;
        case GLS_OP_TEXTURE:
            st.texture = in.u[GLS_ARG_TEXTURE_INDEX];
            break;
        case GLS_OP_NOTEXTURE:
            st.texture = GLS_NONE;
            break;
        case GLS_OP_TRANS:
            identity(A);
            A[3] = in.d[GLS_ARG_TRANS_X], A[7] = in.d[GLS_ARG_TRANS_Y], A[11] = in.d[GLS_ARG_TRANS_Z];
            m4_mul(st.M, A, st.M);
            break;
        case GLS_OP_ROT:
            rotation(in.d[GLS_ARG_ROT_ANGLE], in.d[GLS_ARG_ROT_X], in.d[GLS_ARG_ROT_Y], in.d[GLS_ARG_ROT_Z], A);
            m4_mul(st.M, A, st.M);
            break;
        case GLS_OP_SCALE:
            identity(A);
            A[0] = in.d[GLS_ARG_SCALE_X], A[5] = in.d[GLS_ARG_SCALE_Y], A[10] = in.d[GLS_ARG_SCALE_Z];
            m4_mul(st.M, A, st.M);
            break;
        case GLS_OP_TRANSFORM:
            m4_mul(st.M, in.d + GLS_ARG_TRANSFORM_A00, st.M); /* operands are row-major, like M */
            break;
        case GLS_OP_PUSH:
            if (push_state(w, &st))
                w->oom = 1;
            break;
        case GLS_OP_POP:
            st = w->stack[--w->sp];
            break;
        case GLS_OP_CALL:
        case GLS_OP_CALLN: /* a named instance: drawn like call (motion is the player's, issue 14) */
            run(w, in.u[GLS_ARG_CALL_OBJECT], st); /* by value: the callee gets a copy */
            break;
        case GLS_OP_PRIM:
            prim(w, &st, &in);
            break;
        default:
            break;
        }
    }
    w->sp = base;
}

static int key_cmp(const gls_drawkey *a, const gls_drawkey *b)
{
    if (a->texture != b->texture)
        return a->texture < b->texture ? -1 : 1;
    if (a->mode != b->mode)
        return a->mode < b->mode ? -1 : 1;
    return memcmp(a->rgba, b->rgba, 4);
}

static int tri_cmp(const void *pa, const void *pb)
{
    const tri *a = pa, *b = pb;
    int k = key_cmp(&a->key, &b->key);
    if (k)
        return k;
    for (int j = 0; j < 3; j++)
        if (a->cell[j] != b->cell[j])
            return a->cell[j] < b->cell[j] ? -1 : 1;
    return a->idx < b->idx ? -1 : a->idx > b->idx;
}

int gls_scene_flatten(const gls_bundle *b, gls_scene *s, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (b->top == GLS_NONE) {
        snprintf(err, errlen, "the bundle is a library (it has no top-level object): nothing to play");
        return -1;
    }
    walker w;
    memset(&w, 0, sizeof w);
    w.b = b;
    w.has_color = (b->features & GLS_FEAT_VERTEX_COLOR) != 0;
    w.has_texcoord = (b->features & GLS_FEAT_TEXCOORDS) && (b->features & GLS_FEAT_TEXTURES);
    state st;
    identity(st.M);
    st.rgba[0] = st.rgba[1] = st.rgba[2] = st.rgba[3] = 1.0; /* opaque white */
    st.mode = GLS_MODE_COLOR;
    st.texture = GLS_NONE;
    run(&w, b->top, st);
    int rc = -1;
    if (w.oom) {
        snprintf(err, errlen, "out of memory while flattening the scene");
        goto out;
    }
    if (w.ntri * 3 > UINT32_MAX) {
        snprintf(err, errlen, "scene has %zu triangles: too many to draw", w.ntri);
        goto out;
    }
    if (w.ntri) /* qsort(NULL, 0) is undefined */
        qsort(w.tris, w.ntri, sizeof *w.tris, tri_cmp);

    s->features = b->features;
    s->has_color = w.has_color;
    s->has_texcoord = w.has_texcoord;
    s->stride = 12;
    s->color_offset = s->texcoord_offset = 0;
    if (s->has_color)
        s->color_offset = s->stride, s->stride += 4;
    if (s->has_texcoord)
        s->texcoord_offset = s->stride, s->stride += 8;
    s->nverts = (uint32_t)(w.ntri * 3);
    s->dropped = w.dropped;
    s->verts = malloc(w.ntri ? w.ntri * 3 * s->stride : 1);
    s->chunks = malloc((w.ntri ? w.ntri : 1) * sizeof *s->chunks);
    s->world = malloc((w.ntri ? w.ntri : 1) * 9 * sizeof *s->world);
    if (!s->verts || !s->chunks || !s->world) {
        snprintf(err, errlen, "out of memory while flattening the scene");
        goto out;
    }
    for (int j = 0; j < 3; j++)
        s->lo[j] = INFINITY, s->hi[j] = -INFINITY;
    gls_chunk *ch = NULL;
    for (size_t i = 0; i < w.ntri; i++) {
        const tri *t = &w.tris[i];
        if (!ch || key_cmp(&ch->key, &t->key) || i == 0 ||
            memcmp(w.tris[i - 1].cell, t->cell, sizeof t->cell)) {
            if (!ch || key_cmp(&ch->key, &t->key))
                s->nbatches++;
            ch = &s->chunks[s->nchunks++];
            ch->key = t->key;
            ch->first = (uint32_t)(i * 3);
            ch->count = 0;
            ch->maxoff = 0;
            for (int j = 0; j < 3; j++) {
                ch->anchor[j] = ((double)t->cell[j] + 0.5) * GLS_SCENE_CELL;
                ch->lo[j] = INFINITY, ch->hi[j] = -INFINITY;
            }
        }
        for (int k = 0; k < 3; k++) {
            uint8_t *v = s->verts + (i * 3 + (size_t)k) * s->stride;
            const double *p = w.wpos + 9 * (size_t)t->idx + 3 * k;
            float off[3];
            memcpy(s->world + (i * 3 + (size_t)k) * 3, p, 3 * sizeof *p);
            for (int j = 0; j < 3; j++) {
                off[j] = (float)(p[j] - ch->anchor[j]);
                if (fabs(p[j] - ch->anchor[j]) > ch->maxoff)
                    ch->maxoff = fabs(p[j] - ch->anchor[j]);
                if (p[j] < ch->lo[j])
                    ch->lo[j] = p[j];
                if (p[j] > ch->hi[j])
                    ch->hi[j] = p[j];
                if (p[j] < s->lo[j])
                    s->lo[j] = p[j];
                if (p[j] > s->hi[j])
                    s->hi[j] = p[j];
            }
            memcpy(v, off, sizeof off);
            if (s->has_color)
                memcpy(v + s->color_offset, w.wcol + 12 * (size_t)t->idx + 4 * k, 4);
            if (s->has_texcoord)
                memcpy(v + s->texcoord_offset, w.wtc + 6 * (size_t)t->idx + 2 * k, 8);
        }
        ch->count += 3;
    }
    rc = 0;
out:
    free(w.stack);
    free(w.tris);
    free(w.wpos);
    free(w.wcol);
    free(w.wtc);
    if (rc)
        gls_scene_free(s);
    return rc;
}

void gls_scene_free(gls_scene *s)
{
    free(s->verts);
    free(s->world);
    free(s->chunks);
    memset(s, 0, sizeof *s);
}
