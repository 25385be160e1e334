/* Road geometry: the road's banked frame along its centre line (position,
 * tangent, left and normal directions, curvature, bank and lane width at
 * any parameter or distance) and the points of its edges.  spec/road.md
 * describes the model; road_stations.c tessellates it, road_scene.c and
 * road_lanes.c write it out. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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
    if (r) /* at the first point, with the line and a caret like every located error */
        return road_error_at(d, d->line_points, err, errlen, "%s", why);
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
