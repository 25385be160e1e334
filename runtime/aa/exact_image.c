/* Exact coverage: the box-filtered colour image (exact.h,
 * gls_exact_image): each pixel the sum of its visible regions' exact areas
 * times their colours, the colour of a region its triangle's at the
 * region's centroid (exact for colour affine in the image), and the
 * uncovered rest the background's. */
#include <stdlib.h>
#include "exact_int.h"

typedef struct {
    const gls_exact_tri *t;
    const float *bg;
    gls_exact_shade_fn shade;
    void *user;
    float *rgba;
    const uint16_t *idmap;
    gls_exact_cover *cover;
    int w;
} image_ctx;

/* The pixel's areas summed per id (a pixel shows few ids: a list, on
 * the stack up to 32, else allocated), the K largest into out.  Out of
 * memory leaves the pixel's slots empty. */
static void pixel_cover(const image_ctx *c, const gls_exact_frag *f, size_t n, gls_exact_cover *out)
{
    double stack_a[32], *sa = stack_a, area[GLS_EXACT_COVER_K];
    uint32_t stack_i[32], *si = stack_i, id[GLS_EXACT_COVER_K];
    size_t ns = 0;
    int m = 0;
    for (int k = 0; k < GLS_EXACT_COVER_K; k++)
        out[k] = (gls_exact_cover){0, 0};
    if (n > 32 && (!(sa = malloc(n * sizeof *sa)) || !(si = malloc(n * sizeof *si)))) {
        if (sa != stack_a)
            free(sa);
        return;
    }
    for (size_t k = 0; k < n; k++) {
        uint32_t d = c->t[f[k].tri].id;
        if (c->idmap)
            d = c->idmap[d];
        if (!d)
            continue;
        size_t q = 0;
        while (q < ns && si[q] != d)
            q++;
        if (q == ns)
            si[ns] = d, sa[ns++] = 0;
        sa[q] += f[k].area;
    }
    /* insertion into the K largest, largest first, ties by the smaller id */
    for (size_t q = 0; q < ns; q++) {
        int at = m;
        while (at > 0 && (sa[q] > area[at - 1] || (sa[q] == area[at - 1] && si[q] < id[at - 1])))
            at--;
        if (at >= GLS_EXACT_COVER_K)
            continue;
        if (m < GLS_EXACT_COVER_K)
            m++;
        for (int r = m - 1; r > at; r--)
            area[r] = area[r - 1], id[r] = id[r - 1];
        area[at] = sa[q], id[at] = si[q];
    }
    for (int k = 0; k < m; k++)
        out[k] = (gls_exact_cover){id[k], (float)area[k]};
    if (sa != stack_a)
        free(sa), free(si);
}

static void image_pixel(void *user, int px, int py, const gls_exact_frag *f, size_t n)
{
    image_ctx *c = user;
    double acc[4] = {0, 0, 0, 0}, cover = 0;
    size_t at = (size_t)py * (size_t)c->w + (size_t)px;
    if (c->cover)
        pixel_cover(c, f, n, c->cover + at * GLS_EXACT_COVER_K);
    if (!c->rgba)
        return;
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
    float *o = c->rgba + at * 4;
    for (int q = 0; q < 4; q++)
        o[q] = (float)(acc[q] + rest * c->bg[q]);
}

int gls_exact_image(const gls_exact_tri *t, size_t n, int w, int h, const float bg[4], gls_exact_shade_fn shade,
                    void *user, float *rgba)
{
    return gls_exact_render(t, n, w, h, bg, shade, user, NULL, rgba, NULL);
}

int gls_exact_render(const gls_exact_tri *t, size_t n, int w, int h, const float bg[4], gls_exact_shade_fn shade,
                     void *user, const uint16_t *idmap, float *rgba, gls_exact_cover *cover)
{
    image_ctx c = {t, bg, shade, user, rgba, idmap, cover, w};
    return gls_exact_visit(t, n, w, h, image_pixel, &c);
}
