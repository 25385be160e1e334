/* Which of a scene's instances and chunks may meet a pinhole's view
 * (exact_scene.h gls_exact_view): the exact pass projects only their
 * triangles. */
#include <string.h>
#include "exact_scene.h"

static void world_of(const double W[16], const double *p, double q[3])
{
    for (int r = 0; r < 3; r++)
        q[r] = W[4 * r] * p[0] + W[4 * r + 1] * p[1] + W[4 * r + 2] * p[2] + W[4 * r + 3];
}

void gls_exact_view_make(const gls_exact_pinhole *cam, uint32_t w, uint32_t h, gls_exact_view *v)
{
    /* u = (fx X + skew Y) / Z + cx: u >= -1.5 <=> fx X + skew Y + (cx + 1.5) Z >= 0 for Z > 0,
     * which the near plane holds */
    const double n[6][3] = {{cam->fx, cam->skew, cam->cx + 1.5},
                            {-cam->fx, -cam->skew, w + 0.5 - cam->cx},
                            {0, cam->fy, cam->cy + 1.5},
                            {0, -cam->fy, h + 0.5 - cam->cy},
                            {0, 0, 1},
                            {0, 0, -1}};
    memcpy(v->n, n, sizeof n);
    for (int k = 0; k < 4; k++)
        v->d[k] = 0;
    /* the clip (gls_exact_project) cuts at exactly near and far: these
     * keep a relative margin, so a box touching either plane is kept */
    v->d[4] = -cam->znear * (1 - 1e-9);
    v->d[5] = cam->zfar * (1 + 1e-9);
}

/* Whether the world box lo..hi under the row-major affine W (NULL: the
 * box is in the world already) may meet the view. */
static int box_in_view(const gls_exact_view *v, const gls_exact_pinhole *cam, const double *W, const double lo[3],
                       const double hi[3])
{
    double c[8][3];
    for (int k = 0; k < 8; k++) {
        double p[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]}, q[3];
        if (W)
            world_of(W, p, q);
        else
            memcpy(q, p, sizeof q);
        for (int r = 0; r < 3; r++)
            q[r] -= cam->C[r];
        for (int r = 0; r < 3; r++)
            c[k][r] = cam->R[3 * r] * q[0] + cam->R[3 * r + 1] * q[1] + cam->R[3 * r + 2] * q[2];
    }
    for (int j = 0; j < 6; j++) {
        int k = 0;
        while (k < 8 && v->n[j][0] * c[k][0] + v->n[j][1] * c[k][1] + v->n[j][2] * c[k][2] + v->d[j] < 0)
            k++;
        if (k == 8)
            return 0;
    }
    return 1;
}

uint32_t gls_exact_view_next(const gls_exact_view *v, const gls_exact_pinhole *cam, const gls_scene *s, uint32_t i,
                             uint32_t ch)
{
    const gls_instance *in = &s->inst[i];
    const gls_proto *pr = &s->protos[in->proto];
    for (ch++; ch < pr->first_chunk + pr->nchunks; ch++)
        if (pr->nchunks == 1 || box_in_view(v, cam, in->world, s->chunks[ch].lo, s->chunks[ch].hi))
            return ch;
    return GLS_NONE;
}

uint32_t gls_exact_view_first(const gls_exact_view *v, const gls_exact_pinhole *cam, const gls_scene *s, uint32_t i)
{
    const gls_instance *in = &s->inst[i];
    if (in->proto == GLS_NONE || !box_in_view(v, cam, NULL, in->lo, in->hi))
        return GLS_NONE;
    return gls_exact_view_next(v, cam, s, i, s->protos[in->proto].first_chunk - 1);
}
