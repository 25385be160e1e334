/* Exact coverage: the box-filtered colour image (exact.h,
 * gls_exact_image): each pixel the sum of its visible regions' exact areas
 * times their colours, the colour of a region its triangle's at the
 * region's centroid (exact for colour affine in the image), and the
 * uncovered rest the background's. */
#include "exact_int.h"

typedef struct {
    const gls_exact_tri *t;
    const float *bg;
    gls_exact_shade_fn shade;
    void *user;
    float *rgba;
    int w;
} image_ctx;

static void image_pixel(void *user, int px, int py, const gls_exact_frag *f, size_t n)
{
    image_ctx *c = user;
    double acc[4] = {0, 0, 0, 0}, cover = 0;
    for (size_t k = 0; k < n; k++) {
        float col[4];
        const gls_exact_tri *t = &c->t[f[k].tri];
        if (c->shade)
            c->shade(c->user, t, f[k].tri, f[k].cx, f[k].cy, col);
        else
            for (int q = 0; q < 4; q++)
                col[q] = t->rgba[q];
        for (int q = 0; q < 4; q++)
            acc[q] += f[k].area * col[q];
        cover += f[k].area;
    }
    /* rounding can put the sum of areas a few ulps over 1 */
    double rest = cover < 1 ? 1 - cover : 0;
    float *o = c->rgba + ((size_t)py * (size_t)c->w + (size_t)px) * 4;
    for (int q = 0; q < 4; q++)
        o[q] = (float)(acc[q] + rest * c->bg[q]);
}

int gls_exact_image(const gls_exact_tri *t, size_t n, int w, int h, const float bg[4], gls_exact_shade_fn shade,
                    void *user, float *rgba)
{
    image_ctx c = {t, bg, shade, user, rgba, w};
    return gls_exact_visit(t, n, w, h, image_pixel, &c);
}
