/* The image through a distorted lens (distort_render.h; spec/camera.md
 * "The distorted image"). */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include "aa_onepass.h"
#include "distort.h"
#include "distort_render.h"

/* Fine pixels of the fine image's own border: the bilinear read of a
 * sample at the edge of the covered field needs its right and lower
 * neighbours. */
#define FINE_BORDER 2
/* Newton's residual for the anti-aliasing samples, normalised units:
 * 1e-7 px at f = 1000, far below what a sample's colour can tell. */
#define SAMPLE_TOL 1e-10

/* Smallest singular value of d(fx x + cx, fy y + cy) / d(u, v) at the
 * undistorted ray (x, y): how many undistorted pixels one image pixel
 * spans, at least, in any direction. */
static double least_stretch(const gls_camera *c, double x, double y)
{
    double xd, yd, j[4];
    gls_distort_normalized(&c->dist, x, y, &xd, &yd, j);
    double det = j[0] * j[3] - j[1] * j[2];
    /* M = diag(fx, fy) J^-1 diag(1/fx, 1/fy) */
    double m[4] = {j[3] / det, -j[1] / det * c->fx / c->fy, -j[2] / det * c->fy / c->fx, j[0] / det};
    double t = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] + m[3] * m[3], d = m[0] * m[3] - m[1] * m[2];
    double disc = t * t - 4 * d * d;
    return sqrt(fmax(0, (t - sqrt(fmax(0, disc))) / 2));
}

int gls_distort_layout_make(const gls_camera *c, const gls_aa_plan *p, double scale, uint32_t maxdim,
                            gls_distort_layout *lay, char *err, size_t errlen)
{
    memset(lay, 0, sizeof *lay);
    /* samples reach span/2 beyond a pixel's centre; the border pixel's
       centre is 0.5 inside the image */
    double margin = p && p->count > 1 ? p->span / 2 : 0;
    char why[400];
    if (gls_distort_check(c, margin, why, sizeof why)) {
        snprintf(err, errlen, "%s%s", why,
                 margin > 0 ? " (including the anti-aliasing window beyond the image border)" : "");
        return -1;
    }
    /* the covered field: the rays of the grown border (the models map the
       border of the image onto the border of the field), and the least
       stretch over a grid of the image */
    double u0 = -0.5 - margin, u1 = c->width - 0.5 + margin, v0 = -0.5 - margin, v1 = c->height - 0.5 + margin;
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY, mag = INFINITY;
    uint32_t nu = (uint32_t)ceil(u1 - u0) + 1, nv = (uint32_t)ceil(v1 - v0) + 1;
    for (uint32_t j = 0; j <= nv; j++)
        for (uint32_t i = 0; i <= nu; i++) {
            int edge = i == 0 || j == 0 || i == nu || j == nv;
            if (!edge && (i % 8 || j % 8))
                continue;
            double u = u0 + (u1 - u0) * i / nu, v = v0 + (v1 - v0) * j / nv, x, y;
            if (gls_distort_pixel_ray(c, u, v, &x, &y) < 0) {
                snprintf(err, errlen, "no ray for pixel (%.1f, %.1f) through the lens", u, v);
                return -1;
            }
            xmin = fmin(xmin, x), xmax = fmax(xmax, x), ymin = fmin(ymin, y), ymax = fmax(ymax, y);
            mag = fmin(mag, least_stretch(c, x, y));
        }
    double s = scale / mag;
    gls_camera *f = &lay->fine;
    *f = *c;
    memset(&f->dist, 0, sizeof f->dist);
    f->skew = 0;
    f->fx = s * c->fx;
    f->fy = s * c->fy;
    double w = ceil(f->fx * (xmax - xmin)) + 1 + 2 * FINE_BORDER, h = ceil(f->fy * (ymax - ymin)) + 1 + 2 * FINE_BORDER;
    uint32_t lim = maxdim ? maxdim : GLS_CAMERA_MAX_DIM;
    if (w > lim || h > lim) {
        snprintf(err, errlen, "the lens' field of view needs an undistorted image of %.0fx%.0f pixels (%g per image "
                              "pixel), more than %u a side", w, h, scale, lim);
        return -1;
    }
    f->width = (uint32_t)w;
    f->height = (uint32_t)h;
    f->cx = FINE_BORDER - f->fx * xmin;
    f->cy = FINE_BORDER - f->fy * ymin;
    lay->margin = margin;
    lay->mag = s * mag;
    return 0;
}

uint64_t gls_distort_fine_samples(const gls_aa_plan *p)
{
    double s2 = GLS_DISTORT_AA_SCALE * GLS_DISTORT_AA_SCALE;
    uint64_t m = (uint64_t)ceil((double)p->m / s2);
    return m < 4 ? 4 : m;
}

int gls_distort_render_aa(gls_renderer *r, const gls_camera *f, const gls_aa_plan *p, uint64_t aa_memory,
                          uint16_t *rgb16, char *err, size_t errlen)
{
    gls_aa_opts o = gls_aa_defaults();
    o.samples = gls_distort_fine_samples(p);
    gls_aa_plan fp;
    gls_accum acc;
    memset(&acc, 0, sizeof acc);
    if (gls_aa_plan_init(&fp, &o, err, errlen))
        return -1;
    if (gls_accum_init(&acc, f->width, f->height, 0, 0)) {
        snprintf(err, errlen, "out of memory for the %ux%u anti-aliased undistorted image", f->width, f->height);
        return -1;
    }
    gls_aa_fine_opts fo = {aa_memory, 0, 0, NULL, NULL, NULL, NULL};
    int rc = gls_aa_render_fine(r, f, &fp, &fo, &acc, NULL, err, errlen);
    if (rc == 0)
        gls_accum_rgb16(&acc, rgb16);
    gls_accum_free(&acc);
    return rc;
}

/* The anti-aliased fine image: the one-pass lattice (box) through the
 * fine camera, as 16-bit RGB. */
static int render_aa(gls_distort_frame *fr, gls_renderer *r, const gls_aa_plan *p, uint64_t aa_memory, char *err,
                     size_t errlen)
{
    const gls_camera *f = &fr->lay_aa.fine;
    fr->rgb16 = malloc(3 * (size_t)f->width * f->height * sizeof *fr->rgb16);
    if (!fr->rgb16) {
        snprintf(err, errlen, "out of memory for the %ux%u anti-aliased undistorted image", f->width, f->height);
        return -1;
    }
    return gls_distort_render_aa(r, f, p, aa_memory, fr->rgb16, err, errlen);
}

int gls_distort_frame_render(gls_distort_frame *fr, gls_renderer *r, const gls_camera *c, const gls_aa_plan *p,
                             int want_rgba, int want_z, int want_aa, uint64_t aa_memory, char *err, size_t errlen)
{
    memset(fr, 0, sizeof *fr);
    uint32_t maxd = gls_renderer_max_dim(r);
    if (gls_distort_layout_make(c, NULL, GLS_DISTORT_SCALE, maxd, &fr->lay, err, errlen) ||
        (want_aa && gls_distort_layout_make(c, p, GLS_DISTORT_AA_SCALE, maxd, &fr->lay_aa, err, errlen)))
        return -1;
    const gls_camera *f = &fr->lay.fine;
    size_t n = (size_t)c->width * c->height, nf = (size_t)f->width * f->height;
    fr->ray = malloc(2 * n * sizeof *fr->ray);
    fr->jinv = malloc(4 * n * sizeof *fr->jinv);
    fr->rgba = want_rgba ? malloc(4 * nf) : NULL;
    fr->z = want_z ? malloc(nf * sizeof *fr->z) : NULL;
    if (!fr->ray || !fr->jinv || (want_rgba && !fr->rgba) || (want_z && !fr->z)) {
        snprintf(err, errlen, "out of memory for the %ux%u undistorted image", f->width, f->height);
        return -1;
    }
    for (uint32_t v = 0; v < c->height; v++)
        for (uint32_t u = 0; u < c->width; u++) {
            double *xy = fr->ray + 2 * ((size_t)v * c->width + u);
            /* checked over the border, so every pixel has its ray */
            if (gls_distort_pixel_ray(c, u, v, &xy[0], &xy[1]) < 0) {
                snprintf(err, errlen, "no ray for pixel (%u, %u) through the lens", u, v);
                return -1;
            }
            /* the inverse's Jacobian, per pixel unit: J^-1 diag(1/fx, 1/fy) */
            double xd, yd, j[4], *ji = fr->jinv + 4 * ((size_t)v * c->width + u);
            gls_distort_normalized(&c->dist, xy[0], xy[1], &xd, &yd, j);
            double det = j[0] * j[3] - j[1] * j[2];
            ji[0] = j[3] / det / c->fx, ji[1] = -j[1] / det / c->fy;
            ji[2] = -j[2] / det / c->fx, ji[3] = j[0] / det / c->fy;
        }
    if (want_rgba || want_z) {
        if (gls_renderer_set_size(r, f->width, f->height, err, errlen))
            return -1;
        gls_render_pass(r, f, 0.0, 0.0);
        if (fr->rgba)
            gls_render_read_rgba(r, fr->rgba);
        if (fr->z)
            gls_render_read_z(r, fr->z);
    }
    return want_aa ? render_aa(fr, r, p, aa_memory, err, errlen) : 0;
}

/* The fine pixel nearest to the ray (x, y). */
static size_t nearest(const gls_camera *f, double x, double y)
{
    double fu = f->fx * x + f->cx, fv = f->fy * y + f->cy;
    size_t i = (size_t)floor(fu + 0.5), j = (size_t)floor(fv + 0.5);
    return j * f->width + i;
}

size_t gls_distort_frame_nearest(const gls_distort_frame *fr, size_t i)
{
    return nearest(&fr->lay.fine, fr->ray[2 * i], fr->ray[2 * i + 1]);
}

void gls_distort_frame_read_truth(const gls_distort_frame *fr, size_t i0, size_t i1, const uint32_t *fine_ids,
                                  const float *fine_normals, const float *fine_z, uint32_t *ids, float *normals,
                                  float *z)
{
    for (size_t i = i0; i < i1; i++) {
        size_t k = gls_distort_frame_nearest(fr, i);
        if (ids)
            ids[i] = fine_ids[k];
        if (normals)
            memcpy(normals + 3 * i, fine_normals + 3 * k, 3 * sizeof *normals);
        if (z)
            z[i] = fine_z[k];
    }
}

void gls_distort_frame_nearest_rows(const gls_distort_frame *fr, size_t i0, size_t i1, uint32_t *r0, uint32_t *r1)
{
    size_t lo = SIZE_MAX, hi = 0, w = fr->lay.fine.width;
    for (size_t i = i0; i < i1; i++) {
        size_t row = gls_distort_frame_nearest(fr, i) / w;
        lo = row < lo ? row : lo;
        hi = row > hi ? row : hi;
    }
    if (lo > hi) /* no pixels: one row, read by none */
        lo = hi = 0;
    *r0 = (uint32_t)lo, *r1 = (uint32_t)hi;
}

void gls_distort_frame_centre(const gls_distort_frame *fr, const gls_camera *c, uint8_t *rgba, float *z)
{
    gls_distort_frame_centre_range(fr, 0, (size_t)c->width * c->height, rgba, z);
}

void gls_distort_frame_centre_range(const gls_distort_frame *fr, size_t i0, size_t i1, uint8_t *rgba, float *z)
{
    for (size_t i = i0; i < i1; i++) {
        size_t k = gls_distort_frame_nearest(fr, i);
        if (rgba)
            memcpy(rgba + 4 * i, fr->rgba + 4 * k, 4);
        if (z)
            z[i] = fr->z[k];
    }
}

/* Bilinear RGB of the anti-aliased fine image at the ray (x, y), to
 * 8 bits (rounded; alpha 255). */
static void bilinear(const gls_camera *f, const uint16_t *img, double x, double y, uint8_t *out)
{
    double fu = f->fx * x + f->cx, fv = f->fy * y + f->cy;
    double iu = floor(fu), iv = floor(fv), a = fu - iu, b = fv - iv;
    const uint16_t *p = img + 3 * ((size_t)iv * f->width + (size_t)iu), *q = p + 3 * (size_t)f->width;
    for (int ch = 0; ch < 3; ch++) {
        double top = p[ch] + a * (p[3 + ch] - p[ch]), bot = q[ch] + a * (q[3 + ch] - q[ch]);
        out[ch] = (uint8_t)floor((top + b * (bot - top)) / 257.0 + 0.5);
    }
    out[3] = 255;
}

/* One sample's image, rows v0..v1-1: the sample at offset (ou, ov) of
 * every pixel, through the lens, read in the fine image. */
typedef struct {
    const gls_distort_frame *fr;
    const gls_camera *c;
    double ou, ov;
    uint32_t v0, v1;
    uint8_t *img;
} sample_rows;

static void *sample_image(void *arg)
{
    const sample_rows *t = arg;
    const gls_distort_frame *fr = t->fr;
    const gls_camera *c = t->c, *f = &fr->lay_aa.fine;
    double ou = t->ou, ov = t->ov;
    for (uint32_t v = t->v0; v < t->v1; v++) {
        double yd = (v + ov - c->cy) / c->fy;
        for (uint32_t u = 0; u < c->width; u++) {
            size_t i = (size_t)v * c->width + u;
            const double *r0 = fr->ray + 2 * i, *ji = fr->jinv + 4 * i;
            double xd = (u + ou - c->cx) / c->fx, x, y;
            /* from the centre's ray moved along the inverse's tangent:
               Newton's method is one step from there; the layout checked
               that every sample has a ray */
            double gx = r0[0] + ji[0] * ou + ji[1] * ov, gy = r0[1] + ji[2] * ou + ji[3] * ov;
            if (gls_distort_undistort_tol(&c->dist, xd, yd, gx, gy, SAMPLE_TOL, &x, &y) < 0)
                x = r0[0], y = r0[1];
            bilinear(f, fr->rgb16, x, y, t->img + 4 * i);
        }
    }
    return NULL;
}

int gls_distort_frame_accum_rows(const gls_distort_frame *fr, const gls_camera *c, const gls_aa_plan *p, uint32_t v0,
                                 uint32_t v1, gls_accum *acc)
{
    size_t n = (size_t)c->width * c->height;
    /* zero: the rows outside v0..v1 are added too, and never read */
    uint8_t *img = v0 == 0 && v1 == c->height ? malloc(4 * n) : calloc(n ? 4 * n : 1, 1);
    if (!img)
        return -1;
    uint32_t mid = v0 + (v1 - v0) / 2;
    for (uint64_t k = 0; k < p->count; k++) {
        uint64_t w;
        sample_rows part[2] = {{fr, c, 0, 0, v0, mid, img}, {fr, c, 0, 0, mid, v1, img}};
        gls_aa_sample(p, k, &part[0].ou, &part[0].ov, &w);
        if (!w)
            continue; /* outside a lattice Gaussian's window */
        part[1].ou = part[0].ou, part[1].ov = part[0].ov;
        /* the lower half on a second thread (the same bytes either way:
           each pixel is computed alone) */
        pthread_t th;
        int two = pthread_create(&th, NULL, sample_image, &part[1]) == 0;
        sample_image(&part[0]);
        if (two)
            pthread_join(th, NULL);
        else
            sample_image(&part[1]);
        gls_accum_add(acc, img, 4 * (size_t)c->width, w);
    }
    free(img);
    return 0;
}

int gls_distort_frame_accum(const gls_distort_frame *fr, const gls_camera *c, const gls_aa_plan *p, gls_accum *acc)
{
    return gls_distort_frame_accum_rows(fr, c, p, 0, c->height, acc);
}

void gls_distort_frame_free(gls_distort_frame *f)
{
    free(f->rgba);
    free(f->z);
    free(f->rgb16);
    free(f->ray);
    free(f->jinv);
    memset(f, 0, sizeof *f);
}

void gls_distort_explain(FILE *out, const gls_camera *c, const gls_aa_plan *p)
{
    if (!gls_distort_on(c))
        return;
    static const char *const brown[8] = {"k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6"};
    static const char *const fish[4] = {"k1", "k2", "k3", "k4"};
    fprintf(out, "  lens: %s (%s):", gls_distort_model_name(&c->dist),
            c->dist.model == GLS_LENS_FISHEYE ? "cv::fisheye" : "cv::projectPoints");
    for (unsigned i = 0; i < c->dist.n; i++)
        fprintf(out, " %s %g", c->dist.model == GLS_LENS_FISHEYE ? fish[i] : brown[i], c->dist.k[i]);
    fprintf(out, "\n");
    gls_distort_layout lay, la;
    char err[400];
    int aa = p->count > 1;
    if (gls_distort_layout_make(c, NULL, GLS_DISTORT_SCALE, 0, &lay, err, sizeof err) ||
        (aa && gls_distort_layout_make(c, p, GLS_DISTORT_AA_SCALE, 0, &la, err, sizeof err))) {
        fprintf(out, "  lens: %s\n", err);
        return;
    }
    fprintf(out, "  lens: ground truth (depth, points and their colours%s): one plain pass undistorted at %ux%u (fx %g "
                 "fy %g, at least %g pixels per image pixel), each pixel taking the nearest of those pixels to its "
                 "centre's ray (inverse model, Newton), never blended\n",
            aa ? "" : ", the image", lay.fine.width, lay.fine.height, lay.fine.fx, lay.fine.fy, lay.mag);
    if (aa)
        fprintf(out, "  lens: image: undistorted at %ux%u (at least %g pixels per image pixel, %g beyond the border) "
                     "with %llu lattice samples per pixel (one pass), then each of the %llu anti-aliasing samples of "
                     "a pixel mapped through the inverse model and read there bilinearly\n",
                la.fine.width, la.fine.height, la.mag, la.margin, (unsigned long long)gls_distort_fine_samples(p),
                (unsigned long long)p->count);
}
