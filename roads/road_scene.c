/* road.scene: the road as scene text (spec/road.md, "Outputs"): the
 * surface and verges as textured or coloured quad strips over the
 * tessellation's stations, each marking as a band of its own (dashes one
 * band each), the trees placed along the road; bands are checked not to
 * fold over themselves.  Its objects are road_objects.c's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"
#include "road_emit.h"

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

/* Stations for bands of per_station vertices per station, within what is
   left of ROAD_MAX_VERTICES; or -1 with the error in x. */
static long stations(const road_geo *g, double u0, double u1, const road_edge *e, int ne, double **st, ectx *x,
                     int per_station)
{
    long n = road_stations_upto(g, u0, u1, e, ne, st, (ROAD_MAX_VERTICES - x->verts) / per_station);
    if (n == -2)
        return road_too_fine(x->d, x->err, x->errlen, "the road's surface and lines");
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

/* One station of a band: its left and right vertices L and R, on edges
   e[0] and e[1] at frame fr, with texture coordinates if tile > 0. */
static void station(FILE *f, const road_frame *fr, const road_edge *e, rv3 L, rv3 R, double tile)
{
    if (tile > 0)
        texc(f, across(fr, &e[0], tile), fr->s / tile);
    road_vert(f, L);
    fputc(' ', f);
    if (tile > 0)
        texc(f, across(fr, &e[1], tile), fr->s / tile);
    road_vert(f, R);
    fputc('\n', f);
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
        return road_too_fine(x->d, x->err, x->errlen, "the road's surface and lines");
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
            if (k) /* repeat the previous station: the strips join exactly */
                station(f, &prev, e, Lp, Rp, tile);
        }
        station(f, &fr, e, L, R, tile);
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
    road_nums(f, M, 12, ", ");
    fputs(", 0, 0, 0, 1);", f);
}

/* The four corners of dash k of boundary b as landmarks (spec/road.md
   "Landmarks"): the corners of the band on the marking's surface, where
   it begins and ends along the road, on its left and right edge (e[0],
   e[1]), computed as the band's first and last stations are. */
static void dash_marks(FILE *f, const road_geo *g, int b, int k, double u0, double u1, const road_edge *e)
{
    static const char *const end[2] = {"begin", "end"}, *const side[2] = {"left", "right"};
    for (int i = 0; i < 2; i++) {
        road_frame fr;
        road_frame_at(g, i ? u1 : u0, &fr);
        for (int j = 0; j < 2; j++) {
            rv3 P = road_edge_point(&fr, &e[j]);
            double v[3] = {P.x, P.y, P.z};
            fprintf(f, "mark(\"b%d.dash%d.%s.%s\", ", b, k, end[i], side[j]);
            road_nums(f, v, 3, ", ");
            fputs(");\n", f);
        }
    }
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
            int k = 0;
            for (double s0 = 0; s0 < c->length; s0 += d->dash + d->gap, k++) {
                double s1 = fmin(s0 + d->dash, c->length);
                if (s1 - s0 < 1e-3)
                    break;
                double u0 = nurbs_u_of_s(c, s0), u1 = nurbs_u_of_s(c, s1);
                if (band(f, g, u0, u1, e, 0, x))
                    return -1;
                dash_marks(f, g, b, k, u0, u1, e);
            }
        }
    }
    return 0;
}

int road_emit_scene(const road_geo *g, road_buf *scene, road_buf *tree, road_buf *car, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    const nurbs *c = &g->c;
    ectx x = {err, errlen, d->file, d, 0};
    FILE *f = road_buf_open(scene, d->file, err, errlen);
    if (!f)
        return -1;
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
    /* the other vehicles: each drawn once, as a named instance with no
       transform, so that its world pose is the one of motion/NAME.txt
       (glsplay --motion NAME=DIR/motion/NAME.txt) */
    if (!r && d->nveh)
        fputs("// vehicles: named instances, moved by glsplay --motion NAME=motion/NAME.txt\n", f);
    for (int i = 0; !r && i < d->nveh; i++)
        fprintf(f, "call(\"%s\", \"%s\");\n", d->veh[i].object[0] ? d->veh[i].object : "roadobj.Car", d->veh[i].name);
    if (road_buf_close(f, scene, d->file, err, errlen) || r) {
        free(scene->text);
        scene->text = NULL;
        return -1;
    }
    return road_emit_objects(tree, car, d->file, err, errlen);
}
