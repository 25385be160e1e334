/* lanes.txt: the lane boundaries (the centre of each painted line) as
 * world-coordinate polylines within the tolerance of the true curves
 * (spec/road.md, "Outputs"). */
#include <stdio.h>
#include <stdlib.h>
#include "road_emit.h"

static const char *style_name(int s)
{
    return s == MARK_SOLID ? "solid" : s == MARK_DASHED ? "dashed" : s == MARK_DOUBLE ? "double" : "none";
}

int road_emit_lanes(const road_geo *g, road_buf *out, char *err, size_t errlen)
{
    const road_desc *d = g->d;
    const nurbs *c = &g->c;
    FILE *f = road_buf_open(out, d->file, err, errlen);
    if (!f)
        return -1;
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
        long n = road_stations_upto(g, nurbs_umin(c), nurbs_umax(c), &e, 1, &st, ROAD_MAX_VERTICES - points);
        if (n >= 0)
            points += n;
        if (n < 0) {
            fclose(f);
            free(out->text);
            out->text = NULL;
            if (n == -2)
                return road_too_fine(d, err, errlen, "the lane polylines (lanes.txt)");
            return snprintf(err, errlen, "%s: error: out of memory", d->file), -1;
        }
        for (long k = 0; k < n; k++) {
            road_frame fr;
            road_frame_at(g, st[k], &fr);
            rv3 P = road_edge_point(&fr, &e);
            double row[4] = {fr.s, P.x, P.y, P.z};
            fprintf(f, "%d ", b);
            road_nums(f, row, 4, " ");
            fputc('\n', f);
        }
        free(st);
    }
    return road_buf_close(f, out, d->file, err, errlen);
}

