/* The instance table of a gls_scene (scene.h) after it is built: names,
 * motions, and the world transforms and boxes that follow from them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene.h"
#include "vec.h"

static int name_char(char c, int first)
{
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_')
        return 1;
    return !first && ((c >= '0' && c <= '9') || c == '.' || c == '-');
}

int gls_scene_name_instance(gls_scene *s, uint32_t i, const char *name)
{
    size_t n = strlen(name);
    if (i >= s->ninst || n == 0 || n > GLS_INSTANCE_NAME_MAX || gls_scene_find_instance(s, name) != GLS_NONE)
        return -1;
    for (size_t k = 0; k < n; k++)
        if (!name_char(name[k], k == 0))
            return -1;
    char *c = malloc(n + 1);
    if (!c)
        return -1;
    memcpy(c, name, n + 1);
    free(s->inst[i].name);
    s->inst[i].name = c;
    return 0;
}

uint32_t gls_scene_find_instance(const gls_scene *s, const char *name)
{
    for (uint32_t i = 0; i < s->ninst; i++)
        if (s->inst[i].name && strcmp(s->inst[i].name, name) == 0)
            return i;
    return GLS_NONE;
}

void gls_scene_move(gls_scene *s, uint32_t i, const double R[9], const double T[3])
{
    double *M = s->inst[i].motion;
    memset(M, 0, 16 * sizeof *M);
    M[15] = 1;
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++)
            M[4 * r + c] = R ? R[3 * r + c] : r == c;
        M[4 * r + 3] = R ? T[r] : 0;
    }
    s->moving = 1;
}

static int is_identity(const double M[16])
{
    for (int k = 0; k < 16; k++)
        if (M[k] != (k % 5 == 0))
            return 0;
    return 1;
}

/* World box of the box lo..hi under the affine W: centre and half
 * extents (|A| e), widened by a relative 2^-50 for the rounding. */
static void box_under(const double W[16], const double lo[3], const double hi[3], double olo[3], double ohi[3])
{
    if (is_identity(W)) {
        memcpy(olo, lo, 3 * sizeof *lo);
        memcpy(ohi, hi, 3 * sizeof *hi);
        return;
    }
    double c[3], e[3];
    for (int j = 0; j < 3; j++)
        c[j] = 0.5 * lo[j] + 0.5 * hi[j], e[j] = 0.5 * hi[j] - 0.5 * lo[j];
    for (int i = 0; i < 3; i++) {
        const double *A = W + 4 * i;
        double ci = A[0] * c[0] + A[1] * c[1] + A[2] * c[2] + A[3];
        double ei = fabs(A[0]) * e[0] + fabs(A[1]) * e[1] + fabs(A[2]) * e[2];
        ei += (fabs(ci) + ei) * 0x1p-50;
        olo[i] = ci - ei, ohi[i] = ci + ei;
    }
}

void gls_scene_update(gls_scene *s)
{
    for (uint32_t i = 0; i < s->ninst; i++) {
        gls_instance *in = &s->inst[i];
        double L[16];
        m4_mul(in->local, in->motion, L);
        if (in->parent == GLS_NONE)
            memcpy(in->world, L, sizeof L);
        else
            m4_mul(s->inst[in->parent].world, L, in->world); /* parents come first */
        in->scale = 0;
        for (int r = 0; r < 3; r++) {
            double t = fabs(in->world[4 * r]) + fabs(in->world[4 * r + 1]) + fabs(in->world[4 * r + 2]);
            if (t > in->scale)
                in->scale = t;
        }
        if (in->proto != GLS_NONE)
            box_under(in->world, s->protos[in->proto].lo, s->protos[in->proto].hi, in->lo, in->hi);
    }
    for (uint32_t k = 0; k < s->nitems; k++) {
        gls_item *it = &s->items[k];
        const gls_chunk *ch = &s->chunks[it->chunk];
        box_under(s->inst[it->inst].world, ch->lo, ch->hi, it->lo, it->hi);
    }
}

void gls_scene_mark_world(const gls_scene *s, uint32_t k, double X[3])
{
    const gls_mark *m = &s->marks[k];
    double h[4];
    m4_apply(s->inst[m->inst].world, m->p[0], m->p[1], m->p[2], m->p[3], h);
    for (int i = 0; i < 3; i++)
        X[i] = h[3] == 1.0 ? h[i] : h[i] / h[3];
}

void gls_scene_memory(const gls_scene *s, uint64_t *geometry, uint64_t *table)
{
    *geometry = (uint64_t)s->nverts * (s->stride + 3 * sizeof(double)) + (uint64_t)s->nchunks * sizeof(gls_chunk) +
                (uint64_t)s->nprotos * sizeof(gls_proto) + (uint64_t)s->ntboxes * sizeof(gls_tbox);
    *table = (uint64_t)s->ninst * sizeof(gls_instance) + (uint64_t)s->nitems * sizeof(gls_item);
    for (uint32_t i = 0; i < s->ninst; i++)
        if (s->inst[i].name)
            *table += strlen(s->inst[i].name) + 1;
}
