/* The landmarks output (gt_landmarks.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "distort.h"
#include "gt_landmarks.h"
#include "numfmt.h"

gls_landmarks *gls_landmarks_take(const gls_scene *s)
{
    gls_landmarks *l = calloc(1, sizeof *l);
    size_t n = s->nmarks ? s->nmarks : 1;
    if (!l || !(l->name = malloc(n * sizeof *l->name)) || !(l->path = malloc(n * sizeof *l->path)) ||
        !(l->X = malloc(3 * n * sizeof *l->X))) {
        gls_landmarks_free(l);
        return NULL;
    }
    l->n = s->nmarks;
    for (uint32_t k = 0; k < s->nmarks; k++) {
        l->name[k] = s->marknames[s->marks[k].name];
        l->path[k] = s->marks[k].path;
        gls_scene_mark_world(s, k, l->X + 3 * (size_t)k);
    }
    return l;
}

void gls_landmarks_free(gls_landmarks *l)
{
    if (!l)
        return;
    free(l->name);
    free(l->path);
    free(l->X);
    free(l->pose);
    free(l);
}

/* How fast the surface's depth changes per pixel along one axis at pixel
 * i, from its neighbours a (before) and b (after), either of which may be
 * missing (NULL) or show another surface (+inf, or far off): the smaller
 * one-sided difference, so that an occluding edge next to the pixel does
 * not count as slope. */
static double slope(const float *a, float c, const float *b)
{
    double s = INFINITY;
    if (a && isfinite(*a))
        s = fabs((double)c - *a);
    if (b && isfinite(*b) && fabs((double)*b - c) < s)
        s = fabs((double)*b - c);
    return isfinite(s) ? s : 0;
}

/* The tolerance: the depth buffer recovers Zc to about 6e-8 relative on
 * a plane facing the camera and 6.5e-6 at a grazing angle (spec/camera.md
 * "Depth"), so 1e-4 Zc leaves a margin of 15 over the worst measured; and
 * the pixel centre is up to half a pixel from (u, v), where a sloped
 * surface is nearer or farther by the slope times that offset, doubled
 * because Zc is not linear across the image (1/Zc is). */
int gls_landmark_visible(const float *z, uint32_t width, uint32_t height, double u, double v, double zc)
{
    uint32_t i = (uint32_t)floor(u + 0.5), j = (uint32_t)floor(v + 0.5);
    const float *p = z + (size_t)j * width + i;
    if (!isfinite(*p))
        return 1; /* nothing drawn there */
    double su = slope(i > 0 ? p - 1 : NULL, *p, i + 1 < width ? p + 1 : NULL);
    double sv = slope(j > 0 ? p - width : NULL, *p, j + 1 < height ? p + width : NULL);
    double tol = GLS_LANDMARK_DEPTH_REL * zc + 2 * (fabs(u - i) * su + fabs(v - j) * sv);
    return (double)*p >= zc - tol;
}

/* A CSV field: quoted when it holds a comma or a quote (RFC 4180); a
 * specialised object's name in a path has commas. */
static int put_field(gls_buf *b, const char *s)
{
    if (!strpbrk(s, ",\"\n"))
        return gls_buf_put(b, s, strlen(s));
    if (gls_buf_put(b, "\"", 1))
        return -1;
    for (const char *q = s; *q; q++)
        if ((*q == '"' && gls_buf_put(b, "\"", 1)) || gls_buf_put(b, q, 1))
            return -1;
    return gls_buf_put(b, "\"", 1);
}

static int put_num(gls_buf *b, double v)
{
    char t[40];
    if (isnan(v))
        snprintf(t, sizeof t, "nan");
    else
        gls_fmt_double(t, sizeof t, v);
    return gls_buf_put(b, ",", 1) || gls_buf_put(b, t, strlen(t));
}

int gls_encode_landmarks_csv(const gls_landmarks *l, const gls_camera *c, const float *z, gls_buf *buf)
{
    static const char header[] = "name,path,X,Y,Z,u,v,depth,in_image,visible\n";
    if (gls_buf_put(buf, header, sizeof header - 1))
        return -1;
    for (uint32_t k = 0; k < l->n; k++) {
        const double *X = l->X + 3 * (size_t)k, *R = l->pose ? l->pose[k] : c->R, *T = l->pose ? l->pose[k] + 9 : c->T;
        double pc[3];
        for (int r = 0; r < 3; r++)
            pc[r] = R[3 * r] * X[0] + R[3 * r + 1] * X[1] + R[3 * r + 2] * X[2] + T[r];
        /* spec/camera.md: u = (fx Xc + skew Yc) / Zc + cx, v = fy Yc / Zc + cy,
         * through the lens model in front of a distorted camera (the
         * model is not defined behind it: the pinhole formula there too,
         * so the row says where the point is, out of the image) */
        double u = NAN, v = NAN;
        if (pc[2] > 0 && gls_distort_on(c)) {
            gls_distort_project(c, pc, &u, &v);
        } else if (pc[2] != 0) {
            u = (c->fx * pc[0] + c->skew * pc[1]) / pc[2] + c->cx;
            v = c->fy * pc[1] / pc[2] + c->cy;
        }
        int in = pc[2] > c->near && u >= -0.5 && u < c->width - 0.5 && v >= -0.5 && v < c->height - 0.5;
        int vis = in && gls_landmark_visible(z, c->width, c->height, u, v, pc[2]);
        char flags[8];
        snprintf(flags, sizeof flags, ",%d,%d\n", in, vis);
        if (put_field(buf, l->name[k]) || gls_buf_put(buf, ",", 1) || put_field(buf, l->path[k]) ||
            put_num(buf, X[0]) || put_num(buf, X[1]) || put_num(buf, X[2]) || put_num(buf, u) || put_num(buf, v) ||
            put_num(buf, pc[2]) || gls_buf_put(buf, flags, strlen(flags)))
            return -1;
    }
    return 0;
}
