/* Exact coverage through a lens (distort_exact.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "distort_exact.h"

int gls_distort_exact_plan(gls_aa_plan *p, char *err, size_t errlen)
{
    gls_aa_opts o = gls_aa_defaults();
    o.samples = GLS_DISTORT_EXACT_SAMPLES;
    return gls_aa_plan_init(p, &o, err, errlen);
}

int gls_distort_exact(gls_distort_frame *fr, const gls_camera *c, const gls_scene *s, const gls_texture *textures,
                      const float bg[4], size_t dense, float *rgba, char *err, size_t errlen)
{
    gls_aa_plan p;
    if (gls_distort_exact_plan(&p, err, errlen) ||
        gls_distort_layout_make(c, &p, GLS_DISTORT_AA_SCALE, 0, &fr->lay_aa, err, errlen))
        return -1;
    const gls_camera *f = &fr->lay_aa.fine;
    size_t nf = (size_t)f->width * f->height, n = (size_t)c->width * c->height;
    float *fine = malloc(nf * 4 * sizeof *fine), *rgb = malloc(n * 3 * sizeof *rgb);
    free(fr->rgb16);
    fr->rgb16 = malloc(nf * 3 * sizeof *fr->rgb16);
    gls_exact_geom g;
    gls_accum acc;
    memset(&g, 0, sizeof g);
    memset(&acc, 0, sizeof acc);
    int rc = -1;
    if (fine && rgb && fr->rgb16 && gls_exact_geom_make(&g, s, textures, f) == 0) {
        /* the undistorted image exactly, then the lens path's reads */
        rc = gls_exact_render(g.t, g.n, (int)f->width, (int)f->height, bg, gls_exact_geom_shade, &g, NULL, fine, NULL,
                              dense) ||
                     gls_accum_init(&acc, c->width, c->height, 0, 0)
                 ? -1
                 : 0;
        if (rc == 0) {
            gls_exact_rgb16(fine, nf, fr->rgb16);
            rc = gls_distort_frame_accum(fr, c, &p, &acc);
        }
        if (rc == 0) {
            gls_accum_rgbf(&acc, rgb);
            for (size_t i = 0; i < n; i++)
                rgba[4 * i] = rgb[3 * i], rgba[4 * i + 1] = rgb[3 * i + 1], rgba[4 * i + 2] = rgb[3 * i + 2],
                rgba[4 * i + 3] = 1;
        }
    }
    gls_exact_geom_free(&g);
    gls_accum_free(&acc);
    free(fine), free(rgb);
    if (rc)
        snprintf(err, errlen, "out of memory for the %ux%u undistorted exact image", f->width, f->height);
    return rc;
}
