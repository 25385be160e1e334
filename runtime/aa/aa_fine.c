/* Fine framebuffer geometry (aa_fine.h).  All exact integer arithmetic;
 * positions in units of 1/q px. */
#include <stdlib.h>
#include <string.h>
#include "aa_fine.h"

int gls_aa_fine_ok(const gls_aa_plan *p)
{
    return p->m > 1 && (p->o.pattern == GLS_AA_LATTICE || (p->o.pattern == GLS_AA_GRID && p->o.filter == GLS_AA_BOX));
}

/* The fewest parts K, a divisor of n (valid(k): k is one), with n / K <=
 * max_l; if that K is more than 4 times ceil(n / max_l), the largest
 * divisor below ceil(n / max_l) instead (aa_fine.h). */
static uint64_t choose_k(uint64_t n, uint64_t max_l)
{
    if (n <= max_l)
        return 1;
    uint64_t need = (n + max_l - 1) / max_l, k = need, below = need;
    while (k < n && n % k)
        k++;
    while (below > 1 && n % below)
        below--;
    /* far more passes than needed, and a divisor below that keeps L
     * within 16 max_l: that one (fewer, larger passes) */
    if (k > 4 * need && n / below <= 16 * max_l)
        k = below;
    return k;
}

int gls_aa_fine_init(gls_aa_fine *f, const gls_aa_plan *p, uint64_t max_l)
{
    memset(f, 0, sizeof *f);
    if (!gls_aa_fine_ok(p))
        return -1;
    if (max_l < 1)
        max_l = 1;
    f->p = p;
    if (p->o.pattern == GLS_AA_GRID) {
        /* k x k passes of (N/k)^2: k divides N, (N/k)^2 <= max_l */
        uint64_t n = p->o.n, k = 1;
        while ((n / k) * (n / k) > max_l) {
            k++;
            while (n % k)
                k++;
        }
        /* no divisor near: the largest below the need, if it keeps L
         * within 16 max_l (aa_fine.h) */
        uint64_t need = 1, below;
        while ((n + need - 1) / need * ((n + need - 1) / need) > max_l)
            need++;
        for (below = need; below > 1 && n % below; below--)
            ;
        if (k > 4 * need && (n / below) * (n / below) <= 16 * max_l)
            k = below;
        f->gk = k;
        f->k = k * k;
        f->l = (n / k) * (n / k);
        f->q = 2 * n;
        f->a[0][0] = f->a[1][1] = (int64_t)(n / k);
        return 0;
    }
    uint64_t m = p->m;
    f->k = choose_k(m, max_l);
    f->l = m / f->k;
    f->q = p->lat.q;
    /* points i = r + j K: (j / L, j a / L) + (r / M, r a / M) mod 1, so
     * the pass lattice has L points and generator a mod L (any gcd with
     * L, 0 included: only its basis is used here, the positions are the
     * plan's, so its own centring offset plays no part) */
    gls_lattice sub;
    if (gls_lattice_make(f->l, p->lat.a % f->l, &sub))
        return -1;
    f->e1 = sub.e1, f->e2 = sub.e2;
    /* A = L E^-1 = adj(E) for E = (e1 e2), det E = L */
    f->a[0][0] = sub.e2.y, f->a[0][1] = -sub.e2.x;
    f->a[1][0] = -sub.e1.y, f->a[1][1] = sub.e1.x;
    /* Image rows along fine rows: if an image pixel step (1, 0) moves
     * more rows than columns in the fine framebuffer, turn the fine
     * framebuffer by 90 degrees (R A, R = (0 1; -1 0): det 1, the same
     * lattice, still reduced).  The gather walks a row of pixels in u, and
     * neighbours in u then share the cache lines of their footprints
     * (measured: the gather of M = 256, a = 30, twice as fast). */
    if (llabs(f->a[1][0]) > llabs(f->a[0][0])) {
        int64_t r0[2] = {f->a[0][0], f->a[0][1]};
        f->a[0][0] = f->a[1][0], f->a[0][1] = f->a[1][1];
        f->a[1][0] = -r0[0], f->a[1][1] = -r0[1];
    }
    return 0;
}

void gls_aa_fine_pass(const gls_aa_fine *f, uint64_t r, int64_t shift[2], int64_t (*pos)[2], int64_t (*c)[2])
{
    const gls_aa_plan *p = f->p;
    if (p->o.pattern == GLS_AA_GRID) {
        uint64_t k = f->gk, n = p->o.n / k, rx = r % k, ry = r / k;
        shift[0] = (int64_t)(2 * rx + 1), shift[1] = (int64_t)(2 * ry + 1);
        for (uint64_t j = 0; j < f->l; j++) {
            uint64_t i = j % n, jj = j / n;
            pos[j][0] = (int64_t)(2 * (rx + k * i) + 1);
            pos[j][1] = (int64_t)(2 * (ry + k * jj) + 1);
            c[j][0] = (int64_t)i, c[j][1] = (int64_t)jj;
        }
        return;
    }
    const gls_lattice *l = &p->lat;
    /* the plan's point r, the pass lattice's point 0 */
    gls_lattice_point(l, r, &shift[0], &shift[1]);
    int64_t q = (int64_t)f->q;
    for (uint64_t j = 0; j < f->l; j++) {
        int64_t x, y;
        gls_lattice_point(l, r + j * f->k, &x, &y);
        pos[j][0] = x, pos[j][1] = y;
        __int128 dx = x - shift[0], dy = y - shift[1];
        /* exact: (dx, dy) / q is a point of the pass lattice */
        c[j][0] = (int64_t)((f->a[0][0] * dx + f->a[0][1] * dy) / q);
        c[j][1] = (int64_t)((f->a[1][0] * dx + f->a[1][1] * dy) / q);
    }
}

void gls_aa_fine_map(const gls_aa_fine *f, const int64_t shift[2], int64_t ox, int64_t oy, double m[6])
{
    /* window = A (p + (1/2, 1/2) - shift / q) + (1/2, 1/2) - origin; the
     * constant's integer part A (q - 2 shift) / (2 q) is formed exactly */
    __int128 q = (__int128)f->q;
    for (int row = 0; row < 2; row++) {
        __int128 num = f->a[row][0] * (q - 2 * (__int128)shift[0]) + f->a[row][1] * (q - 2 * (__int128)shift[1]);
        __int128 whole = num / (2 * q), rem = num % (2 * q);
        m[3 * row] = (double)f->a[row][0];
        m[3 * row + 1] = (double)f->a[row][1];
        m[3 * row + 2] = (double)(whole - (row ? oy : ox)) + (double)rem / (double)(2 * q) + 0.5;
    }
}
