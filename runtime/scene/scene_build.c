/* Replay of a validated bundle into a gls_scene (scene.h): protos,
 * instances and chunks.
 *
 * Over 500 lines because it is one pipeline over one walker: the
 * interpreter that walks the code (and records and replays walks), the
 * triangles it emits into the walker's arrays; the packing of those
 * arrays into chunks and draw items is scene_pack.c, landmarks have their
 * own file (scene_marks.c), instance names and motion theirs
 * (scene_instances.c).
 *
 * The interpreter keeps the state of opcodes.h: matrix M (double, row
 * major, relative to the current instance's frame), colour, texture mode,
 * texture.  PUSH/POP save and restore it on a heap stack; CALL runs the
 * callee on a copy (an implicit push/pop), so a callee's changes never
 * leak.  An affine CALL starts a new instance (M = identity in its frame);
 * its proto is built by the first walk that enters the object with that
 * drawing state, which also records what else the walk does (record);
 * later entries replay the record instead of decoding the object again.
 * The validator guarantees that every index is in range, the pushes
 * balance, calls nest at most GLS_MAX_CALL_DEPTH deep (so recursion on
 * CALL is bounded) and there are at most GLS_MAX_CALL_PATHS call paths;
 * the limits of scene.h, checked as the walk goes, bound the rest.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "progress_line.h"
#include "scene.h"
#include "scene_marks.h"
#include "scene_pack.h"
#include "vec.h"

typedef struct {
    double M[16];
    double rgba[4];
    double spec[4];        /* specular r, g, b and Phong exponent (lit)  */
    uint32_t mode, texture;
} state;

typedef gls_pack_tri tri;

/* What a walk of an instance's object does besides drawing, recorded
 * the first time the object is entered with a drawing state and replayed
 * on every later entry with that state (enter(), replay()): so the
 * instructions of an object are decoded once per drawing state, not once
 * per call path, and load time follows the distinct protos plus the call
 * paths (spec/bundle.md 12.3).  Events come in walk order, so instances,
 * landmarks and lights come out in the same order as from a full walk. */
enum {
    EV_ENTER, /* an instance: callee obj, its call's k, state, name     */
    EV_IN,    /* an inlined call (landmark paths only): obj, k          */
    EV_OUT,   /* its end                                                */
    EV_MARK,  /* landmark obj at a position in the instance's frame     */
    EV_LIGHT  /* a light in the instance's frame                        */
};
typedef struct {
    uint8_t kind;
    uint32_t obj, k;
    size_t at;             /* ENTER: a state, MARK: double[4], LIGHT: a
                              gls_light, at this offset in data            */
    const char *name;      /* ENTER: the bundle's instance name, or NULL  */
} event;

/* The events of one proto entered with one raw texture state: the proto
 * keys on the drawing state that reaches its prims (texture and mode
 * normalised), but a texture or texmode instruction inside the object
 * makes the raw pair matter to what its calls get. */
typedef struct {
    uint32_t mode, texture, next; /* next: the proto's next record      */
    event *ev;
    size_t nev, evcap;
    gls_buf data;
} record;

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
    float *wnrm;           /* lit only: 9 per triangle (3 normals)       */
    float *wspec;          /* lit only: 4 per triangle (specular state)  */
    int lit;               /* the bundle has lights (GLS_FEAT_LIGHTS)    */
    gls_light *lights;
    size_t nlights, lcap;
    uint32_t shadow_res;   /* the largest SHADOWS met                    */
    size_t ntri, tcap;
    uint64_t dropped;
    int oom;
    int instanced;         /* gls_scene_load (else gls_scene_flatten)    */
    gls_proto *protos;
    size_t nprotos, pcap;
    uint32_t *proto_head;  /* per object: its first proto, or GLS_NONE    */
    uint8_t *has_call;     /* per object: its code has a CALL             */
    gls_instance *inst;
    size_t ninst, icap;
    const char *limit;     /* a limit crossed: the message               */
    gls_markwalk marks;    /* landmarks and the call path (scene_marks.h) */
    uint64_t walked;       /* instructions decoded (GLS_SCENE_MAX_WALK)   */
    record *recs;          /* instanced: what walks did besides drawing  */
    size_t nrecs, rcap;
    uint32_t *proto_rec;   /* per proto: its first record, or GLS_NONE    */
    size_t prcap;
    size_t *saved;         /* replay: path lengths to go back to          */
    size_t nsaved, scap;
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
    /* arrays of one capacity: grown by the largest element's rule */
    size_t cap = gls_grow_cap(w->tcap, w->ntri + need, 9 * sizeof *w->wpos);
    tri *t = cap ? gls_resize(w->tris, cap, sizeof *t) : NULL;
    if (t)
        w->tris = t;
    double *p = cap ? gls_resize(w->wpos, cap, 9 * sizeof *p) : NULL;
    if (p)
        w->wpos = p;
    if (!t || !p)
        return -1;
    /* colours and texture coordinates only where the vertices carry
     * them (vertex_layout): otherwise nothing reads them, and a scattered
     * scene of 100,000 untextured triangles wrote 2.4 MB of texture
     * coordinates that were never read (issue 30's page faults) */
    if (w->has_color) {
        uint8_t *c = gls_resize(w->wcol, cap, 12);
        if (!c)
            return -1;
        w->wcol = c;
    }
    if (w->has_texcoord) {
        float *x = gls_resize(w->wtc, cap, 6 * sizeof *x);
        if (!x)
            return -1;
        w->wtc = x;
    }
    if (w->lit) { /* normals and specular state only where they are used */
        float *n = gls_resize(w->wnrm, cap, 9 * sizeof *n);
        if (n)
            w->wnrm = n;
        float *e = gls_resize(w->wspec, cap, 4 * sizeof *e);
        if (e)
            w->wspec = e;
        if (!n || !e)
            return -1;
    }
    w->tcap = cap;
    return 0;
}

/* Vertex k of a primitive, fully resolved. */
typedef struct {
    double p[3];
    uint8_t c[4];
    float st[2];
    float n[3];            /* lit primn: its unit normal in the proto's frame */
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
    if (w->lit && in->op == GLS_OP_PRIMN) { /* by M^-T, in double */
        const gls_nrm *q2 = &b->nrm[in->u[GLS_ARG_PRIMN_NRM] + k];
        double N[9];
        m4_normal_matrix(M, N);
        rv3 n = rv_unit(rm_apply(N, rv(q2->x, q2->y, q2->z)));
        v->n[0] = (float)n.x, v->n[1] = (float)n.y, v->n[2] = (float)n.z;
    }
}

/* A lit triangle's normals: the vertices' own (primn), or else its flat
 * normal from the exact positions in double, stored with length 2 to tell
 * the shader to turn it towards the camera (scene.h); a degenerate
 * triangle's is 0 (the shader then faces it to the camera). */
static void tri_normals(const gls_insn *in, const vtx *const v[3], float *out)
{
    if (in->op == GLS_OP_PRIMN) {
        for (int k = 0; k < 3; k++)
            memcpy(out + 3 * k, v[k]->n, 3 * sizeof *out);
        return;
    }
    rv3 a = rv(v[0]->p[0], v[0]->p[1], v[0]->p[2]);
    rv3 n = rv_cross(rv_sub(rv(v[1]->p[0], v[1]->p[1], v[1]->p[2]), a), rv_sub(rv(v[2]->p[0], v[2]->p[1], v[2]->p[2]), a));
    double l = rv_len(n);
    n = l > 0 ? rv_mul(n, 2.0 / l) : rv(0, 0, 0);
    for (int k = 0; k < 3; k++)
        out[3 * k] = (float)n.x, out[3 * k + 1] = (float)n.y, out[3 * k + 2] = (float)n.z;
}

/* Triangles are drawn in the Morton order of their first vertex's
 * sub-cell (GLS_SCENE_SUBCELLS per axis) within their cell, then in
 * emission order: llvmpipe bins and shades triangles that are near each
 * other on the screen faster than the same triangles in an arbitrary
 * order (make bench-instances, its random-order scene).  The sub-cell,
 * like the cell, is exact under translations by multiples of the cell
 * size (p - cell * size is exact there). */
static uint32_t cell_zorder(const double p[3], const int64_t cell[3])
{
    uint32_t q[3], z = 0;
    for (int j = 0; j < 3; j++) {
        double f = (p[j] - (double)cell[j] * GLS_SCENE_CELL) * (GLS_SCENE_SUBCELLS / GLS_SCENE_CELL);
        q[j] = f <= 0 ? 0 : f >= GLS_SCENE_SUBCELLS - 1 ? GLS_SCENE_SUBCELLS - 1 : (uint32_t)f;
    }
    for (int b = 9; b >= 0; b--)
        for (int j = 0; j < 3; j++)
            z = z << 1 | ((q[j] >> b) & 1u);
    return z;
}

static void emit(walker *w, uint32_t proto, const gls_drawkey *key, const state *st, const gls_insn *in,
                 const vtx *a, const vtx *b2, const vtx *c)
{
    if (!a->ok || !b2->ok || !c->ok) {
        w->dropped++;
        return;
    }
    if (3 * (w->ntri + 1) > GLS_SCENE_MAX_VERTS) {
        w->limit = "more than 268435456 unique vertices: too many to draw";
        w->oom = 1;
        return;
    }
    if (grow_tris(w, 1)) {
        w->oom = 1;
        return;
    }
    size_t i = w->ntri++;
    const vtx *v[3] = {a, b2, c};
    tri *t = &w->tris[i];
    t->proto = proto;
    t->key = *key;
    t->idx = (uint32_t)i;
    /* the cell of the first vertex: exact under translations by multiples
     * of the cell size (a centroid would round differently far away) */
    for (int j = 0; j < 3; j++)
        t->cell[j] = (int64_t)floor(a->p[j] / GLS_SCENE_CELL);
    t->zorder = cell_zorder(a->p, t->cell);
    for (int k = 0; k < 3; k++) {
        memcpy(w->wpos + 9 * i + 3 * k, v[k]->p, 3 * sizeof(double));
        if (w->has_color)
            memcpy(w->wcol + 12 * i + 4 * k, v[k]->c, 4);
        if (w->has_texcoord)
            memcpy(w->wtc + 6 * i + 2 * k, v[k]->st, 2 * sizeof(float));
    }
    if (w->lit) {
        tri_normals(in, v, w->wnrm + 9 * i);
        for (int k = 0; k < 4; k++)
            w->wspec[4 * i + k] = (float)st->spec[k];
    }
}

/* The draw key of a drawing state. */
static void state_key(const walker *w, const state *st, gls_drawkey *key)
{
    memset(key, 0, sizeof *key);
    if (st->mode != GLS_MODE_COLOR && st->texture != GLS_NONE) {
        key->texture = st->texture;
        key->mode = (uint8_t)st->mode;
    } else {
        key->texture = GLS_NONE;
        key->mode = GLS_MODE_COLOR;
    }
    (void)w;
}

static void prim(walker *w, uint32_t proto, const state *st, const gls_insn *in)
{
    gls_drawkey key;
    state_key(w, st, &key);
    if (!w->has_color && !w->instanced)
        for (int j = 0; j < 3; j++)
            key.rgba[j] = unorm8(st->rgba[j]);
    key.rgba[3] = w->has_color || w->instanced ? 0 : 255;
    uint32_t n = in->u[GLS_ARG_PRIM_N];
    vtx v0, v1, v2, v3;
    switch (in->u[GLS_ARG_PRIM_KIND]) {
    case GLS_PRIM_POLY: /* convex polygon: a fan, like GL_POLYGON */
    case GLS_PRIM_TFAN:
        fetch(w, st, in, 0, &v0);
        fetch(w, st, in, 1, &v1);
        for (uint32_t k = 2; k < n; k++) {
            fetch(w, st, in, k, &v2);
            emit(w, proto, &key, st, in, &v0, &v1, &v2);
            v1 = v2;
        }
        break;
    case GLS_PRIM_TSTRIP:
        fetch(w, st, in, 0, &v0);
        fetch(w, st, in, 1, &v1);
        for (uint32_t k = 2; k < n; k++) {
            fetch(w, st, in, k, &v2);
            if (k % 2) /* keep GL's consistent winding: (k-1, k-2, k) */
                emit(w, proto, &key, st, in, &v1, &v0, &v2);
            else
                emit(w, proto, &key, st, in, &v0, &v1, &v2);
            v0 = v1, v1 = v2;
        }
        break;
    case GLS_PRIM_QSTRIP: /* quad 2k, 2k+1, 2k+3, 2k+2 */
        fetch(w, st, in, 0, &v0);
        fetch(w, st, in, 1, &v1);
        for (uint32_t k = 2; k + 1 < n; k += 2) {
            fetch(w, st, in, k, &v2);
            fetch(w, st, in, k + 1, &v3);
            emit(w, proto, &key, st, in, &v0, &v1, &v3);
            emit(w, proto, &key, st, in, &v0, &v3, &v2);
            v0 = v2, v1 = v3;
        }
        break;
    default:
        break; /* unreachable: the validator checked the kind */
    }
}

static int is_affine(const double M[16]) { return M[12] == 0 && M[13] == 0 && M[14] == 0 && M[15] == 1; }

/* Does object oi's code contain a CALL, CALLN, MARK or LIGHT?  (A proto
 * already built for an object without them needs no further walk.) */
static int object_calls(walker *w, uint32_t oi)
{
    if (w->has_call[oi] == 0) {
        const gls_object *o = &w->b->objects[oi];
        size_t pos = 0;
        gls_insn in;
        w->has_call[oi] = 1;
        while (gls_insn_decode(o->code, o->code_len, &pos, &in) == 0 && in.op != GLS_OP_END)
            if (in.op == GLS_OP_CALL || in.op == GLS_OP_CALLN || in.op == GLS_OP_MARK || in.op == GLS_OP_LIGHT) {
                w->has_call[oi] = 2;
                break;
            }
    }
    return w->has_call[oi] == 2;
}

/* The proto of object oi entered with st's drawing state; *fresh = 1 if
 * it was just made (then this walk builds it).  GLS_NONE when out of
 * memory. */
static uint32_t proto_for(walker *w, uint32_t oi, const state *st, int *fresh)
{
    uint8_t rgba[4] = {unorm8(st->rgba[0]), unorm8(st->rgba[1]), unorm8(st->rgba[2]), 255};
    for (uint32_t p = w->proto_head[oi]; p != GLS_NONE; p = w->protos[p].next) {
        const gls_proto *q = &w->protos[p];
        if (q->texture == st->texture && q->mode == st->mode && memcmp(q->rgba, rgba, 4) == 0 &&
            memcmp(q->spec, st->spec, sizeof q->spec) == 0) {
            *fresh = 0;
            return p;
        }
    }
    if (gls_grow(&w->protos, &w->pcap, w->nprotos + 1, sizeof *w->protos) ||
        gls_grow(&w->proto_rec, &w->prcap, w->nprotos + 1, sizeof *w->proto_rec)) {
        w->oom = 1;
        return GLS_NONE;
    }
    w->proto_rec[w->nprotos] = GLS_NONE;
    gls_proto *q = &w->protos[w->nprotos];
    memset(q, 0, sizeof *q);
    q->object = oi;
    q->texture = st->texture;
    q->mode = st->mode;
    memcpy(q->rgba, rgba, 4);
    memcpy(q->spec, st->spec, sizeof q->spec);
    q->next = w->proto_head[oi];
    w->proto_head[oi] = (uint32_t)w->nprotos;
    *fresh = 1;
    return (uint32_t)w->nprotos++;
}

static void run(walker *w, uint32_t oi, state st, uint32_t inst, uint32_t proto, uint32_t rec);

/* The record of proto p entered with st's raw texture state; *made = 1
 * if it was just made (then this walk fills it).  GLS_NONE when out of
 * memory. */
static uint32_t record_for(walker *w, uint32_t p, const state *st, int *made)
{
    for (uint32_t r = w->proto_rec[p]; r != GLS_NONE; r = w->recs[r].next)
        if (w->recs[r].mode == st->mode && w->recs[r].texture == st->texture) {
            *made = 0;
            return r;
        }
    if (gls_grow(&w->recs, &w->rcap, w->nrecs + 1, sizeof *w->recs)) {
        w->oom = 1;
        return GLS_NONE;
    }
    record *r = &w->recs[w->nrecs];
    memset(r, 0, sizeof *r);
    r->mode = st->mode;
    r->texture = st->texture;
    r->next = w->proto_rec[p];
    w->proto_rec[p] = (uint32_t)w->nrecs;
    *made = 1;
    return (uint32_t)w->nrecs++;
}

/* Append an event (and n bytes of data) to record r; none when r is
 * GLS_NONE (a flattened walk, or an object already recorded). */
static void rec_put(walker *w, uint32_t r, int kind, uint32_t obj, uint32_t k, const void *data, size_t n,
                    const char *name)
{
    if (r == GLS_NONE)
        return;
    record *rc = &w->recs[r];
    if (gls_grow(&rc->ev, &rc->evcap, rc->nev + 1, sizeof *rc->ev) || (n && gls_buf_put(&rc->data, data, n))) {
        w->oom = 1;
        return;
    }
    rc->ev[rc->nev++] = (event){(uint8_t)kind, obj, k, rc->data.len - n, name};
}

/* The end of an inlined call: an EV_IN just before it is dropped with it
 * (nothing in between needs the path), so an object's record holds no
 * more path events than it has landmarks, lights and instances to place
 * under them. */
static void rec_out(walker *w, uint32_t r)
{
    if (r == GLS_NONE)
        return;
    record *rc = &w->recs[r];
    if (rc->nev && rc->ev[rc->nev - 1].kind == EV_IN)
        rc->nev--;
    else
        rec_put(w, r, EV_OUT, 0, 0, NULL, 0, NULL);
}

/* A light met on the walk, in its instance's frame (like a landmark): a
 * direction by M (w = 0), a position by M divided by its w. */
static void light_of(const state *st, const gls_insn *in, gls_light *l)
{
    memset(l, 0, sizeof *l);
    l->kind = in->u[GLS_ARG_LIGHT_KIND];
    double hw = l->kind == GLS_LIGHT_POINT ? 1.0 : 0.0;
    if (l->kind != GLS_LIGHT_AMBIENT)
        m4_apply(st->M, in->d[GLS_ARG_LIGHT_X], in->d[GLS_ARG_LIGHT_Y], in->d[GLS_ARG_LIGHT_Z], hw, l->p);
    if (l->kind == GLS_LIGHT_POINT && l->p[3] != 1.0 && l->p[3] != 0.0)
        for (int i = 0; i < 4; i++)
            l->p[i] /= l->p[3];
    for (int i = 0; i < 3; i++)
        l->rgb[i] = in->d[GLS_ARG_LIGHT_R + i];
    l->atten = in->d[GLS_ARG_LIGHT_ATTEN];
}

/* Keep light l with instance inst; the limit bounds what a bundle whose
 * lights sit on many call paths can ask for. */
static void put_light(walker *w, const gls_light *l, uint32_t inst)
{
    if (w->nlights >= GLS_SCENE_MAX_PLACED_LIGHTS) {
        w->limit = "more than 65536 lights (lights on every call path): too many to shade";
        w->oom = 1;
        return;
    }
    if (gls_grow(&w->lights, &w->lcap, w->nlights + 1, sizeof *w->lights)) {
        w->oom = 1;
        return;
    }
    w->lights[w->nlights] = *l;
    w->lights[w->nlights++].inst = inst;
}

/* A landmark placed by the current call path. */
static void put_mark(walker *w, uint32_t inst, uint32_t name, const double h[4])
{
    switch (gls_markwalk_place(&w->marks, inst, name, h)) {
    case -2:
        w->limit = "more than 16777216 landmarks (marks on every call path): too many to report";
        /* fall through */
    case -1:
        w->oom = 1;
        break;
    default:
        break;
    }
}

static void enter(walker *w, uint32_t oi, state st, uint32_t parent, const char *name);

/* Instance inst's object entered again with the state of record r: what
 * its first walk did besides drawing, without decoding it again. */
static void replay(walker *w, uint32_t r, uint32_t inst)
{
    size_t base = w->nsaved;
    for (size_t e = 0; !w->oom && e < w->recs[r].nev; e++) {
        const event ev = w->recs[r].ev[e]; /* enter() may move w->recs */
        const uint8_t *at = w->recs[r].data.data + ev.at;
        size_t saved;
        switch (ev.kind) {
        case EV_ENTER: {
            state st;
            memcpy(&st, at, sizeof st);
            if (gls_markwalk_enter(&w->marks, ev.obj, ev.k, &saved)) {
                w->oom = 1;
                break;
            }
            enter(w, ev.obj, st, inst, ev.name);
            gls_markwalk_leave(&w->marks, saved);
            break;
        }
        case EV_IN:
            if (gls_grow(&w->saved, &w->scap, w->nsaved + 1, sizeof *w->saved) ||
                gls_markwalk_enter(&w->marks, ev.obj, ev.k, &w->saved[w->nsaved++]))
                w->oom = 1;
            break;
        case EV_OUT:
            gls_markwalk_leave(&w->marks, w->saved[--w->nsaved]);
            break;
        case EV_MARK: {
            double h[4];
            memcpy(h, at, sizeof h);
            put_mark(w, inst, ev.obj, h);
            break;
        }
        case EV_LIGHT: {
            gls_light l;
            memcpy(&l, at, sizeof l);
            put_light(w, &l, inst);
            break;
        }
        default:
            break;
        }
    }
    w->nsaved = base;
}

/* A new instance of object oi, called from instance parent with st (its
 * M the call-site transform in the parent's frame), named name (NULL:
 * unnamed; the bundle validator checks that names are valid and unique,
 * spec/bundle.md). */
static void enter(walker *w, uint32_t oi, state st, uint32_t parent, const char *name)
{
    if (w->ninst >= GLS_SCENE_MAX_INSTANCES) {
        w->limit = "more than 4194304 instances (call paths): too many to draw";
        w->oom = 1;
        return;
    }
    if (gls_grow(&w->inst, &w->icap, w->ninst + 1, sizeof *w->inst)) {
        w->oom = 1;
        return;
    }
    uint32_t i = (uint32_t)w->ninst++;
    gls_instance *n = &w->inst[i];
    memset(n, 0, sizeof *n);
    n->parent = parent;
    n->object = oi;
    memcpy(n->local, st.M, sizeof n->local);
    identity(n->motion);
    if (name) {
        size_t len = strlen(name) + 1;
        if (!(n->name = malloc(len))) {
            w->oom = 1;
            return;
        }
        memcpy(n->name, name, len);
    }
    int fresh = 0;
    n->proto = proto_for(w, oi, &st, &fresh);
    if (n->proto == GLS_NONE)
        return;
    if (!fresh && !object_calls(w, oi))
        return;
    identity(st.M);
    uint32_t r = GLS_NONE;
    int made = 1;
    if (w->instanced && object_calls(w, oi)) { /* flattened: one entry, the top */
        r = record_for(w, n->proto, &st, &made);
        if (r == GLS_NONE)
            return;
    }
    if (made)
        run(w, oi, st, i, fresh ? n->proto : GLS_NONE, r);
    else
        replay(w, r, i);
}

/* A CALL or CALLN of run's, with the drawing state st at the call; k:
 * the call's index among the object's calls for the landmarks' call
 * path (gls_markwalk_calls).
 *
 * By value: the callee gets a copy.  Instanced: an affine call is an
 * instance; a named call (CALLN) always is one, with the bundle's name,
 * so --motion can move it (a projective matrix goes to GL as it is: no
 * exactness claim for that rare case).  Flattened (--flatten): both are
 * inlined, names unused.  The call path goes on for the landmarks in the
 * callee. */
static void call(walker *w, const gls_insn *in, const state *st, uint32_t inst, uint32_t proto, uint32_t rec,
                 uint32_t k)
{
    uint32_t callee = in->u[GLS_ARG_CALL_OBJECT];
    size_t saved;
    if (gls_markwalk_enter(&w->marks, callee, k, &saved)) {
        w->oom = 1;
        return;
    }
    if (w->instanced && (in->op == GLS_OP_CALLN || is_affine(st->M))) {
        const char *name = in->op == GLS_OP_CALLN ? w->b->instnames[in->u[GLS_ARG_CALLN_NAME]] : NULL;
        rec_put(w, rec, EV_ENTER, callee, k, st, sizeof *st, name);
        enter(w, callee, *st, inst, name);
    } else {
        if (w->marks.on)
            rec_put(w, rec, EV_IN, callee, k, NULL, 0, NULL);
        run(w, callee, *st, inst, proto, rec);
        if (w->marks.on)
            rec_out(w, rec);
    }
    gls_markwalk_leave(&w->marks, saved);
}

/* Walk object oi in instance inst's frame; prims go to proto (GLS_NONE:
 * built already, only calls matter), what else it does to record rec
 * (GLS_NONE: none). */
static void run(walker *w, uint32_t oi, state st, uint32_t inst, uint32_t proto, uint32_t rec)
{
    const gls_object *o = &w->b->objects[oi];
    size_t pos = 0, base = w->sp;
    gls_insn in;
    double A[16], h[4];
    uint32_t ncall = 0; /* calls so far: their index into callk */
    const uint32_t *callk = w->marks.on ? gls_markwalk_calls(&w->marks, oi) : NULL;
    if (w->marks.on && !callk)
        w->oom = 1;
    gls_light l;
    while (!w->oom && gls_insn_decode(o->code, o->code_len, &pos, &in) == 0) {
        if (++w->walked > GLS_SCENE_MAX_WALK) {
            w->limit = "more than 268435456 instructions to walk (objects once per drawing state, inlined calls once "
                       "per call): too large to load";
            w->oom = 1;
            break;
        }
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
        case GLS_OP_CALLN:
            call(w, &in, &st, inst, proto, rec, callk ? callk[ncall++] : 0);
            break;
        case GLS_OP_MARK: /* in the instance's frame, like a vertex; drawn by no proto */
            m4_apply(st.M, in.d[GLS_ARG_MARK_X], in.d[GLS_ARG_MARK_Y], in.d[GLS_ARG_MARK_Z], 1.0, h);
            rec_put(w, rec, EV_MARK, in.u[GLS_ARG_MARK_NAME], 0, h, sizeof h, NULL);
            put_mark(w, inst, in.u[GLS_ARG_MARK_NAME], h);
            break;
        case GLS_OP_PRIM:
        case GLS_OP_PRIMN: /* normals: fetch(); unlit, exactly a PRIM */
            if (proto != GLS_NONE)
                prim(w, proto, &st, &in);
            break;
        case GLS_OP_SHADOWS:
            if (in.u[GLS_ARG_SHADOWS_RES] > w->shadow_res)
                w->shadow_res = in.u[GLS_ARG_SHADOWS_RES];
            break;
        case GLS_OP_SPECULAR:
            memcpy(st.spec, in.d + GLS_ARG_SPECULAR_R, sizeof st.spec);
            break;
        case GLS_OP_LIGHT: /* in the instance's frame, like a mark */
            light_of(&st, &in, &l);
            rec_put(w, rec, EV_LIGHT, 0, 0, &l, sizeof l, NULL);
            put_light(w, &l, inst);
            break;
        default:
            break;
        }
    }
    w->sp = base;
}

/* The vertex layout the walk's attributes ask for: position, then
 * colour, texture coordinates, and normal and specular when lit. */
static void vertex_layout(const walker *w, gls_scene *s)
{
    s->has_color = w->has_color;
    s->has_texcoord = w->has_texcoord;
    s->stride = 12;
    s->color_offset = s->texcoord_offset = 0;
    if (s->has_color)
        s->color_offset = s->stride, s->stride += 4;
    if (s->has_texcoord)
        s->texcoord_offset = s->stride, s->stride += 8;
    s->lit = w->lit;
    if (s->lit) {
        s->normal_offset = s->stride, s->stride += 12;
        s->specular_offset = s->stride, s->stride += 16;
    }
}

/* What the walker holds that the scene did not take. */
static void walker_free(walker *w)
{
    free(w->stack);
    free(w->tris);
    free(w->wpos);
    free(w->wcol);
    free(w->wtc);
    free(w->wnrm);
    free(w->wspec);
    free(w->lights);
    free(w->protos);
    for (size_t i = 0; w->inst && i < w->ninst; i++)
        free(w->inst[i].name);
    free(w->inst);
    free(w->proto_head);
    free(w->has_call);
    for (size_t i = 0; i < w->nrecs; i++)
        free(w->recs[i].ev), free(w->recs[i].data.data);
    free(w->recs);
    free(w->proto_rec);
    free(w->saved);
    gls_markwalk_free(&w->marks);
}

static int build(const gls_bundle *b, gls_scene *s, int instanced, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (b->top == GLS_NONE) {
        snprintf(err, errlen, "the bundle is a library (it has no top-level object): nothing to play");
        return -1;
    }
    /* the flattened form holds every vertex on every call path: bounded
     * by that, before anything is built */
    if (!instanced && gls_bundle_expanded_vertices(b, b->top) > GLS_MAX_EXPANDED_VERTICES) {
        snprintf(err, errlen,
                 "%s draws more than %llu vertices once its calls are unrolled: too large to flatten (drop "
                 "--flatten to draw it instanced)",
                 b->objects[b->top].name, (unsigned long long)GLS_MAX_EXPANDED_VERTICES);
        return -1;
    }
    walker w;
    memset(&w, 0, sizeof w);
    w.b = b;
    w.instanced = instanced;
    /* instanced: colours always in the vertices, so keys are texture and
     * mode only and a colour change does not split a draw */
    w.has_color = instanced || (b->features & GLS_FEAT_VERTEX_COLOR) != 0;
    w.has_texcoord = (b->features & GLS_FEAT_TEXCOORDS) && (b->features & GLS_FEAT_TEXTURES);
    w.lit = (b->features & GLS_FEAT_LIGHTS) != 0;
    w.proto_head = malloc((b->nobjects ? b->nobjects : 1) * sizeof *w.proto_head);
    w.has_call = calloc(b->nobjects ? b->nobjects : 1, 1);
    int rc = -1;
    if (!w.proto_head || !w.has_call) {
        snprintf(err, errlen, "out of memory while building the scene");
        goto out;
    }
    for (uint32_t i = 0; i < b->nobjects; i++)
        w.proto_head[i] = GLS_NONE;
    if (gls_markwalk_init(&w.marks, b)) {
        snprintf(err, errlen, "out of memory while building the scene");
        goto out;
    }
    state st;
    identity(st.M);
    st.rgba[0] = st.rgba[1] = st.rgba[2] = st.rgba[3] = 1.0; /* opaque white */
    st.spec[0] = st.spec[1] = st.spec[2] = st.spec[3] = 0.0;  /* no highlight */
    st.mode = GLS_MODE_COLOR;
    st.texture = GLS_NONE;
    enter(&w, b->top, st, GLS_NONE, NULL);
    s->protos = w.protos, s->nprotos = (uint32_t)w.nprotos;
    s->inst = w.inst, s->ninst = (uint32_t)w.ninst;
    w.protos = NULL, w.inst = NULL;
    if (w.oom) {
        snprintf(err, errlen, "%s", w.limit ? w.limit : "out of memory while building the scene");
        goto out;
    }
    double t_pack = gls_now();
    s->cell_level = gls_pack_sort(w.tris, w.ntri, GLS_SCENE_CHUNK_BUDGET);

    s->features = b->features;
    vertex_layout(&w, s);
    s->lights = w.lights, s->nlights = (uint32_t)w.nlights;
    s->shadow_res = w.shadow_res; /* drawn only when lit (render.c) */
    w.lights = NULL;
    s->nverts = (uint32_t)(w.ntri * 3);
    s->dropped = w.dropped;
    gls_pack_input in = {w.tris, w.ntri, w.wpos, w.wcol, w.wtc, w.wnrm, w.wspec};
    int made = gls_pack_chunks(&in, s);
    if (!made)
        made = gls_pack_exact(w.wpos, w.tris, w.ntri);
    if (!made) {
        /* the walk's positions are the exact ones now; its other arrays
         * are read no more: freed before the rest is allocated */
        double *e = gls_resize(w.wpos, w.ntri, 9 * sizeof *e); /* its length, no more */
        if (e) {
            s->exact = e;
            w.wpos = NULL;
        }
        free(w.tris), free(w.wcol), free(w.wtc), free(w.wnrm), free(w.wspec);
        w.tris = NULL, w.wcol = NULL, w.wtc = NULL, w.wnrm = NULL, w.wspec = NULL;
        made = e ? 0 : -1;
    }
    if (!made)
        made = gls_scene_test_boxes(s);
    if (!made)
        made = gls_pack_items(s);
    s->pack_seconds = gls_now() - t_pack;
    if (!made)
        made = gls_markwalk_finish(&w.marks, s);
    if (made) {
        snprintf(err, errlen, "%s",
                 made == -2 ? "more than 67108864 draw items (instances times the chunks of their geometry): too "
                              "many to draw"
                            : "out of memory while building the scene");
        goto out;
    }
    gls_scene_update(s);
    rc = 0;
out:
    walker_free(&w);
    if (rc)
        gls_scene_free(s);
    return rc;
}

int gls_scene_load(const gls_bundle *b, gls_scene *s, char *err, size_t errlen)
{
    return build(b, s, 1, err, errlen);
}

int gls_scene_flatten(const gls_bundle *b, gls_scene *s, char *err, size_t errlen)
{
    return build(b, s, 0, err, errlen);
}

void gls_scene_free(gls_scene *s)
{
    for (uint32_t i = 0; s->inst && i < s->ninst; i++)
        free(s->inst[i].name);
    for (uint32_t i = 0; s->marks && i < s->nmarks; i++)
        free(s->marks[i].path);
    for (uint32_t i = 0; s->marknames && i < s->nmarknames; i++)
        free(s->marknames[i]);
    free(s->marks);
    free(s->marknames);
    free(s->lights);
    free(s->verts);
    free(s->exact);
    free(s->chunks);
    free(s->protos);
    free(s->tboxes);
    free(s->inst);
    free(s->items);
    memset(s, 0, sizeof *s);
}
