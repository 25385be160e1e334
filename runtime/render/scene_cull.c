/* View-frustum culling of a gls_scene's instances and items (scene.h),
 * by their world boxes: a box is drawn unless the camera cannot see any
 * of it.  GL-free, so that --explain counts what the renderer skips. */
#include <math.h>
#include <string.h>
#include "scene_cull.h"

void gls_box_image_bounds(const gls_camera *c, const double lo[3], const double hi[3], double b[4])
{
    double l[2] = {INFINITY, INFINITY}, h[2] = {-INFINITY, -INFINITY};
    int nearer = 0, beyond = 0;
    for (int k = 0; k < 8; k++) {
        double P[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]};
        double u, v, z = gls_camera_project(c, P, &u, &v);
        if (!(z >= c->near)) {
            nearer++;
            continue;
        }
        beyond += z > c->far;
        l[0] = fmin(l[0], u), l[1] = fmin(l[1], v);
        h[0] = fmax(h[0], u), h[1] = fmax(h[1], v);
    }
    if (nearer == 8 || beyond == 8) { /* wholly clipped: nowhere */
        b[0] = b[1] = INFINITY;
        b[2] = b[3] = -INFINITY;
    } else if (nearer || !isfinite(l[0] + l[1] + h[0] + h[1])) { /* crosses the near plane */
        b[0] = b[1] = -INFINITY;
        b[2] = b[3] = INFINITY;
    } else {
        /* corners in front of the camera: the box projects inside their
         * convex hull; a pixel of margin for rounding */
        b[0] = l[0] - 1, b[1] = l[1] - 1;
        b[2] = h[0] + 1, b[3] = h[1] + 1;
    }
}

/* Can bounds b reach the image (with half a pixel for jitter)? */
static int in_image(const gls_camera *c, const double b[4])
{
    return !(b[2] < -1.0 || b[3] < -1.0 || b[0] > c->width + 0.0 || b[1] > c->height + 0.0);
}

void gls_scene_cull(const gls_scene *s, const gls_camera *c, uint8_t *ivis, uint8_t *vis, gls_cull_stats *st)
{
    memset(st, 0, sizeof *st);
    for (uint32_t i = 0; i < s->ninst; i++) {
        const gls_instance *in = &s->inst[i];
        ivis[i] = 0;
        if (!in->nitems)
            continue;
        double b[4];
        gls_box_image_bounds(c, in->lo, in->hi, b);
        ivis[i] = (uint8_t)(s->no_cull || in_image(c, b));
        if (ivis[i])
            st->drawn++;
        else
            st->culled++;
    }
    for (uint32_t k = 0; k < s->nitems; k++) {
        const gls_item *it = &s->items[k];
        vis[k] = ivis[it->inst];
        if (vis[k] && s->inst[it->inst].nitems > 1 && !s->no_cull) {
            double b[4];
            gls_box_image_bounds(c, it->lo, it->hi, b);
            vis[k] = (uint8_t)in_image(c, b);
        }
        st->items_drawn += vis[k];
    }
}
