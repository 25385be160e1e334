/* Rolling shutter's landmarks (exposure.h): each landmark at the time of
 * the band of rows it is drawn in, so that its u, v and depth agree with
 * the image and the depth of those rows (spec/outputs.md "Ground truth of
 * blurred, rolling-shutter and defocused frames"). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "distort.h"
#include "exposure_landmarks.h"

int gls_exposure_landmarks(const gls_scene *s, const gls_camera *c, uint32_t band, gls_pose_at_fn pose_at, void *ud,
                           gls_landmarks *l)
{
    size_t n = l->n;
    double *best = malloc((n ? n : 1) * sizeof *best);
    l->pose = malloc((n ? n : 1) * sizeof *l->pose);
    if (!best || !l->pose) {
        free(best);
        return -1;
    }
    /* by default the frame time's pose (a landmark never in front of the
     * camera) */
    for (size_t k = 0; k < n; k++) {
        best[k] = INFINITY;
        memcpy(l->pose[k], c->R, 9 * sizeof *c->R);
        memcpy(l->pose[k] + 9, c->T, 3 * sizeof *c->T);
    }
    /* A landmark belongs to the band its row falls in when posed at that
     * band's time; where motion makes it jump over its band (or land in
     * two), the band it lands nearest to, the earliest of equals. */
    for (uint32_t v0 = 0; v0 < c->height; v0 += band) {
        uint32_t v1 = v0 + band < c->height ? v0 + band : c->height;
        gls_camera at = *c;
        pose_at(ud, c->line_delay * (v0 + v1 - 1) / 2.0, &at);
        for (size_t k = 0; k < n; k++) {
            double X[3], pc[3];
            gls_scene_mark_world(s, (uint32_t)k, X);
            gls_camera_to_cam(&at, X, pc);
            if (!(pc[2] > at.near))
                continue;
            /* through a lens, the row it is drawn in is the distorted one */
            double u, v = at.fy * pc[1] / pc[2] + at.cy;
            if (gls_distort_on(&at))
                gls_distort_project(&at, pc, &u, &v);
            double row = floor(v + 0.5);
            double d = row < v0 ? v0 - row : row > v1 - 1 ? row - (v1 - 1) : 0;
            if (d < best[k]) {
                best[k] = d;
                memcpy(l->X + 3 * k, X, sizeof X);
                memcpy(l->pose[k], at.R, 9 * sizeof *at.R);
                memcpy(l->pose[k] + 9, at.T, 3 * sizeof *at.T);
            }
        }
    }
    gls_camera at = *c;
    pose_at(ud, 0, &at);
    free(best);
    return 0;
}
