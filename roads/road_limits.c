/* The counts a road description asks for, checked against the limits in
 * road.h before anything is generated (spec/road.md, "Limits").  Several
 * of them follow from more than one key (frames = duration x fps, the
 * frames to the end of the road from its length, the speed and the fps,
 * vertices from the length and max_segment), so no single key's range
 * can bound them.  Each error points at the key to change. */
#include <math.h>
#include "road.h"

/* Frames of the sequence, its length in seconds, and the other vehicles'
   poses (one line of vehicles.txt each, at most). */
static int check_motion(const road_geo *g, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    double L = g->c.length, frames = (double)d->frames;
    if (d->frames < 0) {
        /* until the end of the road; road_run_trajectory reports a start
           beyond it or a vehicle that never gets there */
        double tend = d->start <= L ? road_profile_time_to(&d->speed, L - d->start) : 0;
        if (!isfinite(tend))
            return 0;
        frames = floor(tend * d->fps) + 1;
        if (!(frames <= ROAD_MAX_FRAMES))
            return road_error_at(d, d->line_fps ? d->line_fps : d->speed.line, err, errlen,
                                 "the vehicle reaches the end of the road (%.3f m) after %.6g s: %.6g frames at "
                                 "%g fps, more than the %ld allowed; lower the fps or give 'frames' or 'duration'",
                                 L, tend, frames, d->fps, ROAD_MAX_FRAMES);
    }
    double secs = (frames - 1) / d->fps;
    if (!(secs <= ROAD_MAX_SECONDS))
        return road_error_at(d, d->line_frames ? d->line_frames : d->speed.line, err, errlen,
                             "%.6g frames at %g fps last %.6g s, more than the %g s allowed (the body's motion is "
                             "integrated in steps of 1 ms)",
                             frames, d->fps, secs, ROAD_MAX_SECONDS);
    if (d->nveh > 0 && !(frames * d->nveh <= ROAD_MAX_VEHICLE_POSES))
        return road_error_at(d, d->line_frames ? d->line_frames : d->veh[d->nveh - 1].line, err, errlen,
                             "%.6g frames x %d vehicles are %.6g vehicle poses, more than the %ld allowed", frames,
                             d->nveh, frames * d->nveh, ROAD_MAX_VEHICLE_POSES);
    return 0;
}

/* Stations along the centre line that tolerance and max_segment ask for,
   estimated from its curvature k: a chord of length h deviates k h^2 / 8
   from the arc, so the tolerance allows h = sqrt(8 tol / k) and the
   station density is max(1 / max_segment, sqrt(k / (8 tol))) per metre;
   every knot is a station too.  Sampled at the midpoints of 32 equal
   parameter steps per knot span.  *by_tol: the part the tolerance adds. */
static double estimate_stations(const road_geo *g, double *by_tol)
{
    const nurbs *c = &g->c;
    const road_desc *d = g->d;
    double total = 1, tol_only = 0;
    for (int k = c->p; k <= c->n; k++) {
        double u0 = c->U[k], u1 = c->U[k + 1], du = (u1 - u0) / 32, span = 0;
        if (!(u1 > u0))
            continue;
        for (int i = 0; i < 32; i++) {
            rv3 CK[3];
            nurbs_derivs(c, u0 + (i + 0.5) * du, 2, CK);
            double sp = rv_len(CK[1]), kappa = sp > 0 ? rv_len(rv_cross(CK[1], CK[2])) / (sp * sp * sp) : 0;
            double ds = sp * du, dt = sqrt(kappa / (8 * d->tolerance)) * ds, dm = ds / d->max_segment;
            span += fmax(dt, dm);
            tol_only += fmax(dt - dm, 0);
        }
        total += fmax(1, ceil(span));
    }
    *by_tol = tol_only;
    return total;
}

/* The vertices the tessellation will emit, two per station of each band
   (the surface, the verges, each line; the stations estimated above, an
   underestimate: halving intervals overshoots), a dash at least two
   stations.  road_stations enforces the limit exactly as it goes; this
   refuses at once what is over it even by the estimate. */
static int check_vertices(const road_geo *g, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    double L = g->c.length, by_tol;
    double stations = estimate_stations(g, &by_tol);
    double per_station = d->verge > 0 ? 6 : 2; /* road surface, verges */
    int dashed = 0;
    for (int b = 0; b <= d->lanes; b++) {
        per_station += d->marking[b] == MARK_SOLID ? 2 : d->marking[b] == MARK_DOUBLE ? 4 : 0;
        dashed += d->marking[b] == MARK_DASHED;
    }
    double dashes = dashed * ceil(L / (d->dash + d->gap));
    double bands = stations * (per_station + 2.0 * dashed * d->dash / (d->dash + d->gap));
    double verts = bands + 4 * dashes;
    if (verts <= ROAD_MAX_VERTICES)
        return 0;
    if (4 * dashes > bands)
        return road_error_at(d, d->line_dash ? d->line_dash : d->line_points, err, errlen,
                             "%.6g dashes (%g m dash, %g m gap along %.3f m of road) and the rest of the road need "
                             "about %.3g vertices, more than the %ld allowed; lengthen the dashes and gaps",
                             dashes, d->dash, d->gap, L, verts, ROAD_MAX_VERTICES);
    /* blame the key that asks for most of them */
    int tol = by_tol > 0.5 * stations;
    int line = tol ? d->line_tolerance : d->line_max_segment;
    return road_error_at(d, line ? line : d->line_points, err, errlen,
                         "%.3f m of road within tolerance %g m and max_segment %g m need about %.3g vertices for "
                         "its surface and lines, more than the %ld allowed; raise %s",
                         L, d->tolerance, d->max_segment, verts, ROAD_MAX_VERTICES,
                         tol ? "the tolerance" : "max_segment");
}

static int check_trees(const road_geo *g, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    double L = g->c.length, trees = 0;
    for (int k = 0; k < d->ntrees; k++) {
        const road_trees *t = &d->trees[k];
        if (t->start <= L)
            trees += (floor((L - t->start) / t->every) + 1) * (t->sides == 3 ? 2 : 1);
        if (!(trees <= ROAD_MAX_TREES))
            return road_error_at(d, t->line, err, errlen,
                                 "the 'trees' lines place %.6g trees along %.3f m of road, more than the %ld "
                                 "allowed; space them further apart",
                                 trees, L, ROAD_MAX_TREES);
    }
    return 0;
}

int road_check_limits(const road_geo *g, char *err, size_t errlen)
{
    if (check_motion(g, err, errlen) || check_vertices(g, err, errlen) || check_trees(g, err, errlen))
        return -1;
    return 0;
}
