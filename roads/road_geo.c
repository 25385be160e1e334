/* Road geometry: the banked frame along the centre line, adaptive
 * tessellation by chordal deviation, and the scene and lane-boundary
 * outputs.  spec/road.md describes the model. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"
#include "road.h"

#define GRAVITY 9.81

int road_geo_init(road_geo *g, const road_desc *d, char *err, size_t errlen)
{
    memset(g, 0, sizeof *g);
    g->d = d;
    int nk = d->npts + d->degree + 1;
    double *U = d->knots;
    double *own = NULL;
    if (!U) {
        own = U = malloc(sizeof(double) * nk);
        if (!U) {
            snprintf(err, errlen, "%s: error: out of memory", d->file);
            return -1;
        }
        nurbs_uniform_knots(d->degree, d->npts, U);
    }
    char why[256];
    int r = nurbs_init(&g->c, d->degree, d->npts, d->pts, d->w, U, why, sizeof why);
    free(own);
    if (r) {
        snprintf(err, errlen, "%s:%d:1: error: %s", d->file, d->line_points, why);
        return -1;
    }
    return 0;
}

void road_geo_free(road_geo *g) { nurbs_free(&g->c); }

/* Piecewise-linear value of a profile at x (constant outside). */
static double profile_value(const road_profile *p, double x)
{
    if (p->n == 1 || x <= p->x[0])
        return p->v[0];
    if (x >= p->x[p->n - 1])
        return p->v[p->n - 1];
    int lo = 0, hi = p->n - 1;
    while (hi - lo > 1) {
        int m = (lo + hi) / 2;
        if (p->x[m] <= x)
            lo = m;
        else
            hi = m;
    }
    double f = (x - p->x[lo]) / (p->x[hi] - p->x[lo]);
    return p->v[lo] + f * (p->v[hi] - p->v[lo]);
}

void road_frame_at(const road_geo *g, double u, road_frame *f)
{
    const road_desc *d = g->d;
    rv3 CK[3];
    nurbs_derivs(&g->c, u, 2, CK);
    f->u = u;
    f->s = nurbs_s_of_u(&g->c, u);
    f->C = CK[0];
    double sp = rv_len(CK[1]);
    f->t = rv_mul(CK[1], 1 / sp);
    f->lh = rv_unit(rv_cross(rv(0, 1, 0), f->t)); /* y x z = x: left */
    f->nh = rv_cross(f->t, f->lh);
    /* curvature vector: the part of C'' normal to the tangent, / |C'|^2 */
    rv3 k = rv_mul(rv_madd(CK[2], f->t, -rv_dot(CK[2], f->t)), 1 / (sp * sp));
    f->kappa = rv_dot(k, f->lh);
    /* Superelevation e = v^2 kappa / g (the cross slope that balances the
       lateral acceleration at the design speed), limited to bank_max.
       Curving left (kappa > 0) lowers the left side. */
    double e = d->bank_speed * d->bank_speed * f->kappa / GRAVITY;
    if (e > d->bank_max)
        e = d->bank_max;
    if (e < -d->bank_max)
        e = -d->bank_max;
    f->e = e;
    f->l = rv_mul(rv_madd(f->lh, f->nh, -e), 1 / sqrt(1 + e * e));
    f->n = rv_cross(f->t, f->l);
    f->lw = profile_value(&d->lane_width, f->s);
}

void road_frame_at_s(const road_geo *g, double s, road_frame *f) { road_frame_at(g, nurbs_u_of_s(&g->c, s), f); }

double road_boundary_offset(const road_desc *d, const road_frame *f, int i) { return (0.5 * d->lanes - i) * f->lw; }
double road_edge_offset(const road_desc *d, const road_frame *f) { return 0.5 * d->lanes * f->lw + d->shoulder; }

rv3 road_edge_point(const road_frame *f, const road_edge *e)
{
    rv3 P = rv_madd(f->C, f->l, e->a * f->lw + e->b);
    P = rv_madd(P, f->n, e->h);
    return rv_madd(P, f->lh, e->x);
}

/* ---- tessellation ------------------------------------------------------- */

#define MAXE 8

typedef struct {
    const road_geo *g;
    const road_edge *e;
    int ne;
    double tol, maxseg;
    double *st;
    long n, cap, max;
} tess;

static int push_station(tess *t, double u)
{
    if (t->n >= t->max) /* a tolerance too fine for the road */
        return -2;
    if (t->n == t->cap) {
        long cap = t->cap ? 2 * t->cap : 1024;
        double *p = realloc(t->st, sizeof(double) * cap);
        if (!p)
            return -1;
        t->st = p;
        t->cap = cap;
    }
    t->st[t->n++] = u;
    return 0;
}

static void edge_points(const tess *t, double u, rv3 *P)
{
    road_frame f;
    road_frame_at(t->g, u, &f);
    for (int i = 0; i < t->ne; i++)
        P[i] = road_edge_point(&f, &t->e[i]);
}

/* Split [ua, ub] until, for every edge, the points at k/8 of the
   parameter interval (k = 1..7) lie within tol of the chord and the chord
   is no longer than maxseg.  Pa, Pb: the edges' points at ua and ub.
   Inside a segment the edges are smooth (kinks of the width profile are
   stations, see road_stations), so the deviation peaks smoothly and seven
   samples find it to well under a percent. */
static int subdivide(tess *t, double ua, const rv3 *Pa, double ub, const rv3 *Pb, int depth)
{
    double um = 0.5 * (ua + ub);
    rv3 Pm[MAXE], Q[MAXE];
    edge_points(t, um, Pm);
    int ok = 1;
    for (int i = 0; i < t->ne && ok; i++)
        ok = rv_seg_dist(Pm[i], Pa[i], Pb[i]) <= t->tol && rv_len(rv_sub(Pb[i], Pa[i])) <= t->maxseg;
    for (int q = 1; q <= 7 && ok; q++) {
        if (q == 4)
            continue;
        edge_points(t, ua + 0.125 * q * (ub - ua), Q);
        for (int i = 0; i < t->ne && ok; i++)
            ok = rv_seg_dist(Q[i], Pa[i], Pb[i]) <= t->tol;
    }
    if (ok || depth >= 60 || !(um > ua && um < ub))
        return push_station(t, ub);
    int r = subdivide(t, ua, Pa, um, Pm, depth + 1);
    return r ? r : subdivide(t, um, Pm, ub, Pb, depth + 1);
}

/* road_stations, giving up (-2) beyond max stations */
static long stations_upto(const road_geo *g, double u0, double u1, const road_edge *edges, int nedges, double **st,
                          long max)
{
    tess t = {g, edges, nedges > MAXE ? MAXE : nedges, g->d->tolerance, g->d->max_segment, NULL, 0, 0, max};
    rv3 Pa[MAXE], Pb[MAXE];
    *st = NULL;
    int r = push_station(&t, u0);
    if (r)
        return r;
    edge_points(&t, u0, Pa);
    /* Knots inside [u0, u1] are stations: the curve's derivatives may jump
       there, and starting from them no span is skipped whole.  So are the
       points of the lane-width profile, where the edges have kinks. */
    const nurbs *c = &g->c;
    const road_profile *lw = &g->d->lane_width;
    int nb = 0;
    double *brk = malloc(sizeof(double) * (size_t)(c->n + 2 + lw->n));
    if (!brk) {
        free(t.st);
        return -1;
    }
    for (int k = c->p + 1; k <= c->n; k++)
        brk[nb++] = c->U[k];
    for (int k = 1; k < lw->n; k++)
        brk[nb++] = nurbs_u_of_s(c, lw->x[k]);
    brk[nb++] = u1;
    for (int i = 1; i < nb; i++) /* insertion sort: a handful of values */
        for (int j = i; j > 0 && brk[j] < brk[j - 1]; j--) {
            double x = brk[j];
            brk[j] = brk[j - 1];
            brk[j - 1] = x;
        }
    double ua = u0;
    for (int k = 0; k < nb; k++) {
        double ub = brk[k] > u1 ? u1 : brk[k];
        if (!(ub > ua))
            continue;
        edge_points(&t, ub, Pb);
        if ((r = subdivide(&t, ua, Pa, ub, Pb, 0)) != 0) {
            free(brk);
            free(t.st);
            return r;
        }
        memcpy(Pa, Pb, sizeof(rv3) * t.ne);
        ua = ub;
    }
    free(brk);
    if (t.st[t.n - 1] != u1 && (r = push_station(&t, u1)) != 0) {
        free(t.st);
        return r;
    }
    *st = t.st;
    return t.n;
}

long road_stations(const road_geo *g, double u0, double u1, const road_edge *edges, int nedges, double **st)
{
    return stations_upto(g, u0, u1, edges, nedges, st, ROAD_MAX_VERTICES);
}

/* ---- scene text --------------------------------------------------------- */

void road_num(FILE *f, double v)
{
    char b[64];
    gls_fmt_double(b, sizeof b, v);
    fputs(b, f);
}

static void vert(FILE *f, rv3 P)
{
    fputs("vert(", f);
    road_num(f, P.x);
    fputs(", ", f);
    road_num(f, P.y);
    fputs(", ", f);
    road_num(f, P.z);
    fputs(");", f);
}

static void texc(FILE *f, double s, double t)
{
    /* texture coordinates are float32 in the bundle: print them so */
    char b[64];
    fputs("tex(", f);
    gls_fmt_float(b, sizeof b, (float)s);
    fputs(b, f);
    fputs(", ", f);
    gls_fmt_float(b, sizeof b, (float)t);
    fputs(b, f);
    fputs("); ", f);
}

static void color3(FILE *f, const double c[3])
{
    fprintf(f, "color(%.4f, %.4f, %.4f);\n", c[0], c[1], c[2]);
}

/* The most stations per qstrip: 2^20 (2^21 vertices, well inside the
   language's 2^24 per block); the next strip repeats the last station. */
#define STRIP_MAX 1048576L

typedef struct {
    char *err;
    size_t errlen;
    const char *file;
    const road_desc *d;
    long verts; /* emitted so far, against ROAD_MAX_VERTICES */
} ectx;

/* The tessellation the tolerance asks for is too fine: at the key that
   sets it.  Returns -1. */
static int too_fine(const road_desc *d, char *err, size_t errlen, const char *what)
{
    return road_error_at(d, d->line_tolerance ? d->line_tolerance : d->line_max_segment ? d->line_max_segment
                                                                                        : d->line_points,
                         err, errlen,
                         "%s within tolerance %g m (max_segment %g m) need more than %ld vertices; raise the "
                         "tolerance or max_segment",
                         what, d->tolerance, d->max_segment, ROAD_MAX_VERTICES);
}

/* Stations for bands of per_station vertices per station, within what is
   left of ROAD_MAX_VERTICES; or -1 with the error in x. */
static long stations(const road_geo *g, double u0, double u1, const road_edge *e, int ne, double **st, ectx *x,
                     int per_station)
{
    long n = stations_upto(g, u0, u1, e, ne, st, (ROAD_MAX_VERTICES - x->verts) / per_station);
    if (n == -2)
        return too_fine(x->d, x->err, x->errlen, "the road's surface and lines");
    if (n < 0)
        snprintf(x->err, x->errlen, "%s: error: out of memory", x->file);
    return n;
}

/* Texture s across the road: s grows to the right as seen by a driver
   (towards -x, lateral offsets are positive to the left). */
static double across(const road_frame *fr, const road_edge *e, double tile)
{
    return -(e->a * fr->lw + e->b + e->x) / tile;
}

/* Emit one band between edges e[0] (left) and e[1] (right) over the
   stations as qstrips; tile > 0: texture coordinates (across, along) in
   tiles.  Checks that the band does not fold: each edge must advance along
   the road from each station to the next. */
static int emit_band(FILE *f, const road_geo *g, const double *st, long n, const road_edge *e, double tile,
                     ectx *x)
{
    x->verts += 2 * (n + (n - 1) / STRIP_MAX); /* a strip after the first repeats a station */
    if (x->verts > ROAD_MAX_VERTICES)
        return too_fine(x->d, x->err, x->errlen, "the road's surface and lines");
    road_frame fr, prev = {0};
    rv3 L = {0, 0, 0}, R = {0, 0, 0}, Lp = {0, 0, 0}, Rp = {0, 0, 0};
    for (long k = 0; k < n; k++) {
        road_frame_at(g, st[k], &fr);
        L = road_edge_point(&fr, &e[0]);
        R = road_edge_point(&fr, &e[1]);
        /* An offset curve at lateral distance d runs backwards where the
           curvature towards it exceeds 1/d: the band would fold over
           itself.  Checked at every station, and as a backstop each edge
           must advance along the road from the previous station. */
        for (int i = 0; i < 2; i++) {
            double dlat = e[i].a * fr.lw + e[i].b + e[i].x;
            if (fr.kappa * dlat >= 1 ||
                (k > 0 && rv_dot(rv_sub(i ? R : L, i ? Rp : Lp), prev.t) <= 0)) {
                snprintf(x->err, x->errlen,
                         "%s: error: the road folds over itself near distance %.3f m: the curve radius there "
                         "(%.3f m) is smaller than the lateral offset of an edge (%.3f m); widen the curve or "
                         "narrow the road",
                         x->file, fr.s, fabs(fr.kappa) > 0 ? 1 / fabs(fr.kappa) : INFINITY, fabs(dlat));
                return -1;
            }
        }
        if (k % STRIP_MAX == 0) {
            if (k)
                fputs("}\n", f);
            fputs("qstrip {\n", f);
            if (k) { /* repeat the previous station: the strips join exactly */
                if (tile > 0)
                    texc(f, across(&prev, &e[0], tile), prev.s / tile);
                vert(f, Lp);
                fputc(' ', f);
                if (tile > 0)
                    texc(f, across(&prev, &e[1], tile), prev.s / tile);
                vert(f, Rp);
                fputc('\n', f);
            }
        }
        if (tile > 0)
            texc(f, across(&fr, &e[0], tile), fr.s / tile);
        vert(f, L);
        fputc(' ', f);
        if (tile > 0)
            texc(f, across(&fr, &e[1], tile), fr.s / tile);
        vert(f, R);
        fputc('\n', f);
        Lp = L;
        Rp = R;
        prev = fr;
    }
    fputs("}\n", f);
    return 0;
}

static int band(FILE *f, const road_geo *g, double u0, double u1, const road_edge *e, double tile, ectx *x)
{
    double *st;
    long n = stations(g, u0, u1, e, 2, &st, x, 2);
    if (n < 0)
        return -1;
    int r = emit_band(f, g, st, n, e, tile, x);
    free(st);
    return r;
}

/* A transform placing an upright object (x left, y up, z forward) at P
   with its z along the road's horizontal direction at f. */
static void place(FILE *f, const road_frame *fr, rv3 P, int reverse)
{
    rv3 x = fr->lh, y = rv(0, 1, 0), z = rv_cross(x, y);
    if (reverse) {
        x = rv_mul(x, -1);
        z = rv_mul(z, -1);
    }
    double M[12] = {x.x, y.x, z.x, P.x, x.y, y.y, z.y, P.y, x.z, y.z, z.z, P.z};
    fputs("transform(", f);
    for (int i = 0; i < 12; i++) {
        road_num(f, M[i]);
        fputs(", ", f);
    }
    fputs("0, 0, 0, 1);", f);
}

static int emit_markings(FILE *f, const road_geo *g, ectx *x)
{
    const road_desc *d = g->d;
    const nurbs *c = &g->c;
    double mw = d->marking_width, h = d->marking_height;
    for (int b = 0; b <= d->lanes; b++) {
        int st = d->marking[b];
        if (st == MARK_NONE)
            continue;
        double a = 0.5 * d->lanes - b;
        fprintf(f, "// boundary %d: %s\n", b, st == MARK_SOLID ? "solid" : st == MARK_DASHED ? "dashed" : "double");
        if (st == MARK_SOLID || st == MARK_DOUBLE) {
            int lines = st == MARK_DOUBLE ? 2 : 1;
            for (int k = 0; k < lines; k++) {
                double off = lines == 2 ? (k ? -1 : 1) * 0.5 * (d->double_gap + mw) : 0;
                road_edge e[2] = {{a, off + 0.5 * mw, h, 0}, {a, off - 0.5 * mw, h, 0}};
                if (band(f, g, nurbs_umin(c), nurbs_umax(c), e, 0, x))
                    return -1;
            }
        } else {
            road_edge e[2] = {{a, 0.5 * mw, h, 0}, {a, -0.5 * mw, h, 0}};
            for (double s0 = 0; s0 < c->length; s0 += d->dash + d->gap) {
                double s1 = fmin(s0 + d->dash, c->length);
                if (s1 - s0 < 1e-3)
                    break;
                if (band(f, g, nurbs_u_of_s(c, s0), nurbs_u_of_s(c, s1), e, 0, x))
                    return -1;
            }
        }
    }
    return 0;
}

static int close_buf(FILE *f, road_buf *b, ectx *x)
{
    if (fclose(f) != 0 || !b->text) {
        snprintf(x->err, x->errlen, "%s: error: out of memory", x->file);
        return -1;
    }
    return 0;
}

static void box(FILE *f, double x0, double x1, double y0, double y1, double z0, double z1, const double c[3])
{
    /* faces shaded by hand (the player has no lighting): top brightest,
       sides by direction, so the shape reads */
    static const double shade[6] = {1.0, 0.55, 0.8, 0.7, 0.85, 0.6};
    rv3 v[8];
    for (int i = 0; i < 8; i++)
        v[i] = rv(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
    static const int face[6][4] = {{2, 3, 7, 6}, {0, 4, 5, 1}, {0, 2, 6, 4}, {1, 5, 7, 3}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (int k = 0; k < 6; k++) {
        double s = shade[k];
        fprintf(f, "color(%.4f, %.4f, %.4f);\npoly { ", c[0] * s, c[1] * s, c[2] * s);
        for (int j = 0; j < 4; j++) {
            vert(f, v[face[k][j]]);
            fputc(' ', f);
        }
        fputs("}\n", f);
    }
}

static void tree_object(FILE *f)
{
    static const double bark[3] = {0.36, 0.25, 0.14};
    fputs("// A tree 7 m tall: a trunk and two stacked eight-sided cones, standing on\n"
          "// y = 0 at x = z = 0, shaded by hand (generated by glsroad).\n",
          f);
    box(f, -0.15, 0.15, 0, 2.2, -0.15, 0.15, bark);
    static const double cone[2][3] = {{1.5, 2.2, 5.5}, {1.1, 4.2, 7.0}}; /* radius, base, apex */
    for (int k = 0; k < 2; k++) {
        fputs("tfan {\n", f);
        fputs("col(0.2, 0.5, 0.2); ", f);
        vert(f, rv(0, cone[k][2], 0));
        fputc('\n', f);
        for (int i = 0; i <= 8; i++) {
            double a = 2 * M_PI * (i % 8) / 8;
            double light = 0.55 + 0.45 * (0.5 + 0.5 * cos(a - 0.8));
            fprintf(f, "col(%.4f, %.4f, %.4f); ", 0.12 * light, 0.42 * light, 0.13 * light);
            vert(f, rv(cone[k][0] * cos(a), cone[k][1], cone[k][0] * sin(a)));
            fputc('\n', f);
        }
        fputs("}\n", f);
    }
}

static void car_object(FILE *f)
{
    static const double body[3] = {0.70, 0.12, 0.10}, glass[3] = {0.25, 0.3, 0.38}, tyre[3] = {0.08, 0.08, 0.08};
    fputs("// A car 4.4 m long, 1.8 m wide, 1.5 m high: origin on the ground under\n"
          "// its centre, x left, y up, z forward (generated by glsroad).\n",
          f);
    box(f, -0.9, 0.9, 0.3, 1.0, -2.2, 2.2, body);
    box(f, -0.8, 0.8, 1.0, 1.5, -1.3, 0.7, glass);
    for (int i = 0; i < 4; i++)
        box(f, i & 1 ? 0.62 : -0.92, i & 1 ? 0.92 : -0.62, 0, 0.62, i & 2 ? 1.05 : -1.65, i & 2 ? 1.65 : -1.05,
            tyre);
}

int road_emit_scene(const road_geo *g, road_buf *scene, road_buf *tree, road_buf *car, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    const nurbs *c = &g->c;
    ectx x = {err, errlen, d->file, d, 0};
    memset(scene, 0, sizeof *scene);
    FILE *f = open_memstream(&scene->text, &scene->len);
    if (!f) {
        snprintf(err, errlen, "%s: error: out of memory", d->file);
        return -1;
    }
    fprintf(f, "// Generated by glsroad from %s; edit that file, not this one.\n", d->file);
    fprintf(f, "// World frame: x left, y up, z forward; metres.  Road length %.3f m,\n", c->length);
    fprintf(f, "// %d lane(s), chordal tolerance %g m.\n", d->lanes, d->tolerance);
    double hl = 0.5 * d->lanes, sh = d->shoulder;
    road_edge e[6] = {
        {hl, sh, 0, d->verge}, {hl, sh, 0, 0}, /* left verge */
        {hl, sh, 0, 0}, {-hl, -sh, 0, 0},      /* road */
        {-hl, -sh, 0, 0}, {-hl, -sh, 0, -d->verge}, /* right verge */
    };
    /* Road and verges share one set of stations, so the verge's inner
       edge is the road's edge vertex for vertex: no gaps between them. */
    double *st;
    long n = d->verge > 0 ? stations(g, nurbs_umin(c), nurbs_umax(c), e, 6, &st, &x, 6)
                          : stations(g, nurbs_umin(c), nurbs_umax(c), e + 2, 2, &st, &x, 2);
    if (n < 0) {
        fclose(f);
        free(scene->text);
        scene->text = NULL; /* the caller frees the buffers after an error too */
        return -1;
    }
    fputs("// road surface\n", f);
    if (d->road_texture[0])
        fprintf(f, "texture(\"%s\");\ntexmode(replace);\n", d->road_texture);
    else
        color3(f, d->road_color);
    int r = emit_band(f, g, st, n, e + 2, d->road_texture[0] ? d->road_tile : 0, &x);
    if (!r && d->verge > 0) {
        fputs("// verges\n", f);
        if (d->verge_texture[0])
            fprintf(f, "texture(\"%s\");\ntexmode(replace);\n", d->verge_texture);
        else
            fputs("notexture;\ntexmode(color);\n", f), color3(f, d->verge_color);
        r = emit_band(f, g, st, n, e, d->verge_texture[0] ? d->verge_tile : 0, &x);
        if (!r)
            r = emit_band(f, g, st, n, e + 4, d->verge_texture[0] ? d->verge_tile : 0, &x);
    }
    free(st);
    if (!r) {
        fputs("// markings\nnotexture;\ntexmode(color);\n", f);
        color3(f, d->marking_color);
        r = emit_markings(f, g, &x);
    }
    for (int k = 0; !r && k < d->ntrees; k++) {
        const road_trees *t = &d->trees[k];
        fprintf(f, "// trees every %g m, %g m from the edge\n", t->every, t->offset);
        for (double s = t->start; s <= c->length; s += t->every) {
            road_frame fr;
            road_frame_at_s(g, s, &fr);
            for (int side = 1; side <= 2; side++) {
                if (!(t->sides & side))
                    continue;
                double sg = side == 1 ? 1 : -1;
                road_edge te = {sg * hl, sg * sh, 0, sg * t->offset};
                rv3 P = road_edge_point(&fr, &te);
                fputs("push; ", f);
                place(f, &fr, P, 0);
                fprintf(f, " call(\"%s\"); pop;\n", t->object[0] ? t->object : "roadobj.Tree");
            }
        }
    }
    if (close_buf(f, scene, &x) || r) {
        free(scene->text);
        scene->text = NULL;
        return -1;
    }
    memset(tree, 0, sizeof *tree);
    memset(car, 0, sizeof *car);
    f = open_memstream(&tree->text, &tree->len);
    if (!f)
        return snprintf(err, errlen, "%s: error: out of memory", d->file), -1;
    tree_object(f);
    if (close_buf(f, tree, &x))
        return -1;
    f = open_memstream(&car->text, &car->len);
    if (!f)
        return snprintf(err, errlen, "%s: error: out of memory", d->file), -1;
    car_object(f);
    if (close_buf(f, car, &x))
        return -1;
    return 0;
}

static const char *style_name(int s)
{
    return s == MARK_SOLID ? "solid" : s == MARK_DASHED ? "dashed" : s == MARK_DOUBLE ? "double" : "none";
}

int road_emit_lanes(const road_geo *g, road_buf *out, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    const nurbs *c = &g->c;
    memset(out, 0, sizeof *out);
    FILE *f = open_memstream(&out->text, &out->len);
    if (!f)
        return snprintf(err, errlen, "%s: error: out of memory", d->file), -1;
    fprintf(f, "# glsroad lane boundaries 1\n"
               "# Lane boundaries (the centre of each painted line) as world-coordinate\n"
               "# polylines on the road surface, within the tolerance (%g m) of the true\n"
               "# curves.  World frame: x left, y up, z forward; metres.\n"
               "# Boundary 0 is the leftmost looking along increasing distance.\n"
               "# Columns: boundary distance x y z  (distance along the centre line, m)\n",
            d->tolerance);
    for (int b = 0; b <= d->lanes; b++)
        fprintf(f, "# boundary %d %s\n", b, style_name(d->marking[b]));
    long points = 0;
    for (int b = 0; b <= d->lanes; b++) {
        road_edge e = {0.5 * d->lanes - b, 0, 0, 0};
        double *st;
        long n = stations_upto(g, nurbs_umin(c), nurbs_umax(c), &e, 1, &st, ROAD_MAX_VERTICES - points);
        if (n >= 0)
            points += n;
        if (n < 0) {
            fclose(f);
            free(out->text);
            out->text = NULL;
            if (n == -2)
                return too_fine(d, err, errlen, "the lane polylines (lanes.txt)");
            return snprintf(err, errlen, "%s: error: out of memory", d->file), -1;
        }
        for (long k = 0; k < n; k++) {
            road_frame fr;
            road_frame_at(g, st[k], &fr);
            rv3 P = road_edge_point(&fr, &e);
            fprintf(f, "%d ", b);
            road_num(f, fr.s);
            fputc(' ', f);
            road_num(f, P.x);
            fputc(' ', f);
            road_num(f, P.y);
            fputc(' ', f);
            road_num(f, P.z);
            fputc('\n', f);
        }
        free(st);
    }
    if (fclose(f) != 0 || !out->text)
        return snprintf(err, errlen, "%s: error: out of memory", d->file), -1;
    return 0;
}
