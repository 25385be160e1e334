/* make bench-aa, exact coverage (spec/antialiasing.md "Exact coverage"):
 * the full sweep of directions and offsets the sampled patterns are judged
 * on, through the exact engine (runtime/aa/exact.h) against a closed form.
 *
 *   aa_exact sweep STEP OFFSETS: half-planes at every direction of
 *   [0, 180) in STEP-degree steps, OFFSETS random sub-pixel offsets each
 *   (seeded, so the run is the same every time), on a 12x12 image; prints
 *   the worst per-pixel error against the closed-form area of a square
 *   below a line, the worst per-row edge error (per column for
 *   near-horizontal edges: the line's sum of image - exact, a displacement
 *   in px), each with its direction, and the time.
 *   aa_exact listed OFFSETS, aa_exact mirrored OFFSETS: the same at the
 *   listed angles of section 1, and at them, their mirror images, 0 and 90.
 *
 * The closed form: the area of {a x + b y + c > 0} in [-.5, .5]^2 is a box
 * spline, a sum of quadratic ramps at the corners' offsets; within 1e-6 of
 * an axis the line crosses two opposite sides, where the area is linear in
 * c (exact). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "exact.h"
#include "halfplane_area.h"


#define W 12
typedef struct {
    double cover[W * W];
} img;
static void pixel(void *u, int px, int py, const gls_exact_frag *f, size_t n)
{
    img *m = u;
    double s = 0;
    for (size_t k = 0; k < n; k++)
        s += f[k].area;
    m->cover[py * W + px] = s;
}

static unsigned long long rng = 0x9E3779B97F4A7C15ull;
static double urand(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* half-planes at the directions deg[0..n), offsets random offsets each */
static int run_dirs(const double *deg, long n, int offsets, const char *name)
{
    double worst = 0, worst_row = 0, wdeg = 0, rdeg = 0;
    long pixels = 0;
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (long k = 0; k < n; k++)
        for (int o = 0; o < offsets; o++) {
            double th = deg[k] * M_PI / 180, nx = cos(th), ny = sin(th);
            double px = W / 2 - 0.5 + urand(), py = W / 2 - 0.5 + urand(), L = 1e4;
            gls_exact_tri t = {{px - L * ny, px + L * ny, px + L * nx}, {py + L * nx, py - L * nx, py + L * ny},
                               {1, 1, 1}, 0, {1, 1, 1, 1}, 0};
            img m;
            memset(&m, 0, sizeof m);
            if (gls_exact_visit(&t, 1, W, W, pixel, &m))
                return 1;
            /* per row across steep edges, per column across flat ones */
            int steep = fabs(nx) >= fabs(ny);
            for (int j = 0; j < W; j++) {
                double line = 0;
                for (int i = 0; i < W; i++) {
                    int x = steep ? i : j, y = steep ? j : i;
                    double e = m.cover[y * W + x] - gls_halfplane_area(nx, ny, nx * (x - px) + ny * (y - py));
                    line += e, pixels++;
                    if (fabs(e) > worst)
                        worst = fabs(e), wdeg = deg[k];
                }
                if (fabs(line) > worst_row)
                    worst_row = fabs(line), rdeg = deg[k];
            }
        }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    /* name, directions, offsets, pixels, worst pixel (deg), worst row (deg), seconds */
    printf("%s %ld %d %ld %.3g %g %.3g %g %.2f\n", name, n, offsets, pixels, worst, wdeg, worst_row, rdeg,
           (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    return 0;
}

static const double listed[] = {0.5, 1, 3, 10, 22.5, 30, 45, 60, 80};

int main(int argc, char **argv)
{
    int offsets = argc == 3 || argc == 4 ? atoi(argv[argc - 1]) : 0;
    if (argc == 4 && strcmp(argv[1], "sweep") == 0 && offsets > 0) {
        double step = atof(argv[2]);
        long n = step > 0 ? lround(180 / step) : 0;
        double *d = malloc((n ? n : 1) * sizeof *d);
        for (long k = 0; k < n && d; k++)
            d[k] = k * step;
        int rc = d && n ? run_dirs(d, n, offsets, "sweep") : 2;
        free(d);
        return rc;
    }
    if (argc == 3 && strcmp(argv[1], "listed") == 0 && offsets > 0)
        return run_dirs(listed, 9, offsets, "listed");
    if (argc == 3 && strcmp(argv[1], "mirrored") == 0 && offsets > 0) {
        double d[20];
        for (int k = 0; k < 9; k++)
            d[k] = listed[k], d[9 + k] = 180 - listed[k];
        d[18] = 0, d[19] = 90;
        return run_dirs(d, 20, offsets, "mirrored");
    }
    fprintf(stderr, "usage: aa_exact sweep STEP OFFSETS | listed OFFSETS | mirrored OFFSETS\n");
    return 2;
}
