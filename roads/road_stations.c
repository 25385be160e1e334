/* Adaptive tessellation of the road's edges: the stations (curve
 * parameters) at which every edge's polyline stays within the chordal
 * tolerance of the true edge and no segment exceeds max_segment
 * (spec/road.md).  Knots and the lane-width profile's points are always
 * stations. */
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "road.h"
#include "road_emit.h"

#define MAXE 8

typedef struct {
    const road_geo *g;
    const road_edge *e;
    int ne;
    double tol, maxseg;
    double *st;
    size_t cap;
    long n, max;
} tess;

static int push_station(tess *t, double u)
{
    if (t->n >= t->max) /* a tolerance too fine for the road */
        return -2;
    if (gls_grow(&t->st, &t->cap, (size_t)t->n + 1, sizeof(double)))
        return -1;
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

long road_stations_upto(const road_geo *g, double u0, double u1, const road_edge *edges, int nedges, double **st,
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
    return road_stations_upto(g, u0, u1, edges, nedges, st, ROAD_MAX_VERTICES);
}
