/* make bench-aa: what sub-pixel accuracy costs (bench/aa.sh drives it).
 *
 *   aa_bench accuracy W H PATTERN M       box filter, M samples: per-row
 *        RMS edge error of straight edges at the listed angles, at their
 *        mirror images (180 - theta, and 0 and 90: both diagonals and both
 *        axes) and over a sweep of directions, against the exact answer,
 *        and seconds per frame; float output for every pattern, also 8-
 *        and 16-bit for the lattice (one line each: pattern M output
 *        seconds, then worst and its angle for listed, listed + mirrored
 *        and sweep, then the listed and the mirrored angles' errors)
 *   aa_bench analytic PATTERN M           the same errors computed from the
 *        sample positions alone (no renderer): the listed and mirrored
 *        angles and a dense sweep of [0, 180) degrees in 0.05-degree steps
 *   aa_bench generators M D               every lattice generator a of M
 *        points against the target 1/D px at the listed angles, from the
 *        sample positions: how many meet it there (and at the mirrored
 *        angles too), the best, and the generators with the largest
 *        minimum distance (spec/antialiasing.md, "Accuracy")
 *   aa_bench scene DIR                    write the 100k-triangle bench
 *        scene (bench/play_scene.h) as DIR/terrain.glsb and DIR/cam.cam,
 *        for timing whole glsplay runs
 *   aa_bench texlod BUNDLE CAMFILE M      a textured scene through the
 *        lattice's one pass and through M jittered passes: how the fine
 *        framebuffer's finer mipmap levels change the image
 *   aa_bench snap                         llvmpipe's vertex snapping seen
 *        through the fine framebuffer of grid N = 1, 4, 16, 64
 *
 * AA_BENCH_MULTIPASS=1 in the environment draws lattice and grid plans
 * through the multi-pass path too (one jittered pass per sample), for
 * comparing the two.
 *
 * The scenes and the exact answer are bench/aa_scene.h.  Seconds per frame
 * include the sample plan, every pass, the gather and the conversion to
 * the output format (not the file encoding); best of up to 3 runs under a
 * second. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "aa_onepass.h"
#include "aa_render.h"
#include "aa_scene.h"
#include "lattice.h"
#include "play_bundle.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The angles of the target (degrees). */
static const double listed[] = {0.5, 1, 3, 10, 22.5, 30, 45, 60, 80};
#define NLISTED (sizeof listed / sizeof listed[0])
/* Their mirror images 180 - theta (45 -> 135: the other diagonal), and
 * both axes.  A lattice is not symmetric under the mirror: an edge at
 * 180 - theta may see another error than one at theta. */
static const double mirrored[] = {179.5, 179, 177, 170, 157.5, 150, 135, 120, 100, 0, 90};
#define NMIRRORED (sizeof mirrored / sizeof mirrored[0])
/* The mirrored scene's squares: a square at angle b has edges at b and
 * b + 90, so 180 - theta for each listed theta, and 0 (0 and 90). */
static const double mirrored_squares[] = {179.5, 179, 177, 170, 157.5, 150, 135, 120, 100, 0};
#define NMIRSQ (sizeof mirrored_squares / sizeof mirrored_squares[0])

static int parse_pattern(const char *s, gls_aa_pattern *p)
{
    if (strcmp(s, "lattice") == 0)
        *p = GLS_AA_LATTICE;
    else if (strcmp(s, "grid") == 0)
        *p = GLS_AA_GRID;
    else if (strcmp(s, "stratified") == 0)
        *p = GLS_AA_STRATIFIED;
    else
        return -1;
    return 0;
}

static int make_plan(const char *pat, uint64_t m, gls_aa_plan *p)
{
    char err[256];
    gls_aa_opts o = gls_aa_defaults();
    o.samples = m;
    if (parse_pattern(pat, &o.pattern) || gls_aa_plan_init(p, &o, err, sizeof err)) {
        fprintf(stderr, "aa_bench: pattern %s, %llu samples: %s\n", pat, (unsigned long long)m, err);
        return -1;
    }
    return 0;
}

/* Sample positions of a box plan in the unit pixel (x right, y down). */
static void positions(const gls_aa_plan *p, double *x, double *y)
{
    for (uint64_t k = 0; k < p->count; k++) {
        double du, dv;
        uint64_t w;
        gls_aa_sample(p, k, &du, &dv, &w);
        x[k] = du + 0.5, y[k] = dv + 0.5;
    }
}

typedef struct {
    double worst, at;
} worst;

/* Analytic worst over [0, 180) in steps of step degrees. */
static worst analytic_sweep(const double *x, const double *y, long m, double step, double *scratch)
{
    worst w = {0, 0};
    for (long i = 0; i * step < 180; i++) {
        double e = as_pattern_rms(x, y, m, i * step, scratch);
        if (e > w.worst)
            w.worst = e, w.at = i * step;
    }
    return w;
}

static int analytic(const char *pat, uint64_t m)
{
    gls_aa_plan p;
    if (make_plan(pat, m, &p))
        return 1;
    double *x = malloc(m * sizeof *x), *y = malloc(m * sizeof *y), *s = malloc(m * sizeof *s);
    positions(&p, x, y);
    printf("# analytic per-row RMS edge error (box, exact sample positions, no rasteriser)\n");
    printf("# pattern M listed_worst at_deg listed+mirrored_worst at_deg sweep_worst at_deg, then at 0.5 1 3 10 "
           "22.5 30 45 60 80, then at 179.5 179 177 170 157.5 150 135 120 100 0 90\n");
    worst wl = {0, 0}, wm;
    double e[NLISTED], em[NMIRRORED];
    for (size_t i = 0; i < NLISTED; i++) {
        e[i] = as_pattern_rms(x, y, (long)m, listed[i], s);
        if (e[i] > wl.worst)
            wl.worst = e[i], wl.at = listed[i];
    }
    wm = wl;
    for (size_t i = 0; i < NMIRRORED; i++) {
        em[i] = as_pattern_rms(x, y, (long)m, mirrored[i], s);
        if (em[i] > wm.worst)
            wm.worst = em[i], wm.at = mirrored[i];
    }
    worst ws = analytic_sweep(x, y, (long)m, 0.05, s);
    printf("%s %llu %.6f %g %.6f %g %.6f %g", pat, (unsigned long long)m, wl.worst, wl.at, wm.worst, wm.at, ws.worst,
           ws.at);
    for (size_t i = 0; i < NLISTED; i++)
        printf(" %.6f", e[i]);
    for (size_t i = 0; i < NMIRRORED; i++)
        printf(" %.6f", em[i]);
    printf("\n");
    free(x), free(y), free(s);
    return 0;
}

/* Worst analytic error of generator a's points over n angles. */
static worst lattice_worst(const gls_lattice *l, double *x, double *y, double *s, const double *ang, size_t n)
{
    for (uint64_t i = 0; i < l->m; i++) {
        int64_t X, Y;
        gls_lattice_point(l, i, &X, &Y);
        x[i] = (double)X / (double)l->q, y[i] = (double)Y / (double)l->q;
    }
    worst w = {0, 0};
    for (size_t k = 0; k < n; k++) {
        double e = as_pattern_rms(x, y, (long)l->m, ang[k], s);
        if (e > w.worst)
            w.worst = e, w.at = ang[k];
    }
    return w;
}

static int generators(uint64_t m, double denom)
{
    gls_lattice chosen;
    if (m < 2 || m > 65536 || denom <= 0 || gls_lattice_choose(m, &chosen)) {
        fprintf(stderr, "aa_bench: generators: M in 2..65536 and D > 0\n");
        return 2;
    }
    double target = 1 / denom, *x = malloc(m * sizeof *x), *y = malloc(m * sizeof *y), *s = malloc(m * sizeof *s);
    int64_t best_len2 = 0;
    for (uint64_t a = 1; a < m; a++) {
        gls_lattice o;
        if (gls_lattice_make(m, a, &o) == 0 && o.len2 > best_len2)
            best_len2 = o.len2;
    }
    uint64_t n_listed = 0, n_both = 0, best_a = 0, best_both_a = 0;
    double best = 1, best_both = 1;
    printf("# generators of M = %llu against 1/%g = %.6f px (analytic per-row RMS, box filter)\n",
           (unsigned long long)m, denom, target);
    for (uint64_t a = 1; a < m; a++) {
        gls_lattice o;
        if (gls_lattice_make(m, a, &o))
            continue;
        worst w = lattice_worst(&o, x, y, s, listed, NLISTED);
        if (o.len2 == best_len2 || a == chosen.a)
            printf("a = %llu%s%s: closest samples %.5f px, worst at the listed angles %.6f px (%g deg)\n",
                   (unsigned long long)a, o.len2 == best_len2 ? " (largest minimum distance)" : "",
                   a == chosen.a ? " (glsplay's choice)" : "", o.mindist, w.worst, w.at);
        if (w.worst < best)
            best = w.worst, best_a = a;
        if (w.worst > target)
            continue;
        n_listed++;
        worst wm = lattice_worst(&o, x, y, s, mirrored, NMIRRORED);
        if (wm.worst <= target)
            n_both++;
        if (fmax(w.worst, wm.worst) < best_both)
            best_both = fmax(w.worst, wm.worst), best_both_a = a;
    }
    printf("meet the target at the listed angles: %llu of %llu generators; at the listed and mirrored angles: %llu\n",
           (unsigned long long)n_listed, (unsigned long long)(m - 1), (unsigned long long)n_both);
    printf("best at the listed angles: a = %llu, %.6f px\n", (unsigned long long)best_a, best);
    if (n_both)
        printf("best at the listed and mirrored angles: a = %llu, %.6f px\n", (unsigned long long)best_both_a,
               best_both);
    free(x), free(y), free(s);
    return 0;
}

/* ---- rendering ------------------------------------------------------ */

typedef struct {
    gls_glctx *ctx;
} gl;

/* Render scene s with plan p (fine path where it applies) into acc; the
 * best time of up to 3 runs under a second.  -1 on failure. */
static double render(gls_glctx *ctx, as_scene *s, const gls_aa_plan *p, gls_accum *acc)
{
    char err[256];
    gls_camera cam = as_camera(s, 1, 100);
    gls_bundle *b = as_bundle(s, &cam);
    gls_scene sc;
    gls_renderer *r = NULL;
    double best = -1;
    if (gls_scene_flatten(b, &sc, err, sizeof err) || !(r = gls_renderer_create(ctx, b, &sc, err, sizeof err))) {
        fprintf(stderr, "aa_bench: %s\n", err);
        return -1;
    }
    for (int rep = 0; rep < 3 && (best < 0 || best < 1.0); rep++) {
        gls_accum a;
        double t0 = now();
        int rc = gls_accum_init(&a, s->w, s->h, gls_aa_weighted(p), 0) ||
                 gls_renderer_set_size(r, s->w, s->h, err, sizeof err);
        gls_aa_fine_stats fs;
        if (!rc && gls_aa_fine_ok(p) && !getenv("AA_BENCH_MULTIPASS")) {
            rc = gls_aa_render_fine(r, &cam, p, NULL, &a, &fs, err, sizeof err);
            if (!rc && getenv("AA_BENCH_STATS"))
                fprintf(stderr, "%llu passes, tiles %llu drawn %llu skipped (%ux%u): draw %.3f s, read-back %.3f s, "
                                "gather %.3f s, total %.3f s\n",
                        (unsigned long long)fs.lay.f.k, (unsigned long long)fs.tiles_drawn,
                        (unsigned long long)fs.tiles_skipped, fs.lay.tw, fs.lay.th, fs.draw_s, fs.read_s,
                        fs.gather_s, fs.total_s);
        }
        else if (!rc) {
            gls_aa_run_opts ro = {0, 0, NULL, NULL, NULL, NULL};
            rc = gls_aa_render(r, &cam, p, &ro, &a, NULL, err, sizeof err);
        }
        double t = now() - t0;
        if (rc) {
            fprintf(stderr, "aa_bench: %s\n", err);
            best = -1;
            break;
        }
        if (best < 0 || t < best) {
            best = t;
            if (rep)
                gls_accum_free(acc);
            *acc = a;
        } else
            gls_accum_free(&a);
    }
    gls_renderer_destroy(r);
    gls_scene_free(&sc);
    gls_bundle_free(b);
    return best;
}

/* Image of output format out (0 float, 1 16-bit, 2 8-bit) as doubles. */
static double convert(const gls_accum *a, int out, double *img)
{
    size_t n = (size_t)a->width * a->height;
    double t0 = now();
    if (out == 0) {
        float *f = malloc(n * 12);
        gls_accum_rgbf(a, f);
        for (size_t i = 0; i < n; i++)
            img[i] = f[3 * i];
        free(f);
    } else if (out == 1) {
        uint16_t *f = malloc(n * 6);
        gls_accum_rgb16(a, f);
        for (size_t i = 0; i < n; i++)
            img[i] = f[3 * i] / 65535.0;
        free(f);
    } else {
        uint8_t *f = malloc(n * 4);
        gls_accum_rgba8(a, f);
        for (size_t i = 0; i < n; i++)
            img[i] = f[4 * i] / 255.0;
        free(f);
    }
    return now() - t0;
}

/* Worst per-row RMS over the distinct edge directions of scene s. */
static worst scene_worst(const as_scene *s, const double *img, double *per, const double *dirs, size_t ndirs)
{
    worst w = {0, 0};
    for (size_t i = 0; i < ndirs; i++) {
        long rows;
        double e = as_dir_rms(s, img, dirs[i], &rows);
        if (getenv("AA_BENCH_DIRS"))
            fprintf(stderr, "dir %g: %.6f over %ld rows\n", dirs[i], e, rows);
        if (per)
            per[i] = e;
        if (e > w.worst)
            w.worst = e, w.at = dirs[i];
    }
    return w;
}

static int accuracy(uint32_t W, uint32_t H, const char *pat, uint64_t m)
{
    char err[256];
    gls_glctx *ctx = gls_glctx_create(GLS_BACKEND_AUTO, err, sizeof err);
    gls_aa_plan p;
    if (!ctx || make_plan(pat, m, &p)) {
        fprintf(stderr, "aa_bench: %s\n", ctx ? "plan" : err);
        return 1;
    }
    /* the sweep: squares at 0..89 degrees (each also gives +90), and the
     * pattern's analytically worst direction */
    double *x = malloc(m * sizeof *x), *y = malloc(m * sizeof *y), *sc = malloc(m * sizeof *sc);
    positions(&p, x, y);
    worst aw = analytic_sweep(x, y, (long)m, 0.05, sc);
    free(x), free(y), free(sc);
    double sweep[92];
    int ns = 0;
    for (int a = 0; a < 90; a++)
        sweep[ns++] = a;
    sweep[ns++] = fmod(aw.at, 90);
    double sdirs[184];
    size_t nsd = 0;
    for (int i = 0; i < ns; i++)
        for (int q = 0; q < 2; q++) {
            double d = fmod(sweep[i] + 90.0 * q, 180.0);
            int dup = 0;
            for (size_t j = 0; j < nsd; j++)
                dup |= fabs(sdirs[j] - d) < 1e-9;
            if (!dup)
                sdirs[nsd++] = d;
        }
    static as_scene ls, ms, ss;
    if (!as_layout_angles(&ls, W, H, listed, (int)NLISTED, 6) ||
        !as_layout_angles(&ms, W, H, mirrored_squares, (int)NMIRSQ, 6) || !as_layout_angles(&ss, W, H, sweep, ns, 2)) {
        fprintf(stderr, "aa_bench: too many squares\n");
        return 1;
    }
    size_t n = (size_t)W * H;
    double *img = malloc(n * sizeof *img), per[NLISTED], perm[NMIRRORED];
    gls_accum al, am, as;
    double t = render(ctx, &ls, &p, &al), tm = t < 0 ? -1 : render(ctx, &ms, &p, &am),
           ts = tm < 0 ? -1 : render(ctx, &ss, &p, &as);
    if (t < 0 || tm < 0 || ts < 0)
        return 1;
    int nout = p.o.pattern == GLS_AA_LATTICE ? 3 : 1;
    static const char *oname[] = {"pfm", "png16", "png8"};
    for (int out = 0; out < nout; out++) {
        double tc = convert(&al, out, img);
        worst wl = scene_worst(&ls, img, per, listed, NLISTED);
        convert(&am, out, img);
        worst wm = scene_worst(&ms, img, perm, mirrored, NMIRRORED);
        if (wl.worst >= wm.worst)
            wm = wl;
        convert(&as, out, img);
        worst ws = scene_worst(&ss, img, NULL, sdirs, nsd);
        printf("%s %llu %s %.4f %.6f %g %.6f %g %.6f %g", pat, (unsigned long long)m, oname[out], t + tc, wl.worst,
               wl.at, wm.worst, wm.at, ws.worst, ws.at);
        for (size_t i = 0; i < NLISTED; i++)
            printf(" %.6f", per[i]);
        for (size_t i = 0; i < NMIRRORED; i++)
            printf(" %.6f", perm[i]);
        printf("\n");
        fflush(stdout);
    }
    gls_accum_free(&al);
    gls_accum_free(&am);
    gls_accum_free(&as);
    free(img);
    gls_glctx_destroy(ctx);
    return 0;
}

/* ---- the 100k-triangle scene ----------------------------------------- */

static int scene(const char *dir)
{
    char path[1024];
    gls_bundle *b = ps_bundle();
    snprintf(path, sizeof path, "%s/terrain.glsb", dir);
    int rc = tb_write(b, path);
    gls_bundle_free(b);
    gls_camera cam = ps_camera(0);
    snprintf(path, sizeof path, "%s/cam.cam", dir);
    return rc || tb_write_camera(&cam, path) ? 1 : 0;
}

/* ---- textures: the fine framebuffer's mipmap levels ------------------- */

static double grad_energy(const uint8_t *rgba, uint32_t w, uint32_t h)
{
    double s = 0;
    for (uint32_t v = 0; v + 1 < h; v++)
        for (uint32_t u = 0; u + 1 < w; u++) {
            const uint8_t *p = rgba + 4 * ((size_t)v * w + u);
            double g = p[1], gx = p[4 + 1] - g, gy = p[4 * w + 1] - g;
            s += gx * gx + gy * gy;
        }
    return sqrt(s / ((double)(w - 1) * (h - 1)));
}

static int texlod(const char *bundle, const char *camfile, uint64_t m)
{
    char err[1024];
    gls_error ge;
    gls_glctx *ctx = gls_glctx_create(GLS_BACKEND_AUTO, err, sizeof err);
    gls_bundle *b = gls_bundle_read_file(bundle, &ge);
    gls_camera cam;
    gls_scene sc;
    gls_aa_plan p;
    gls_renderer *r = NULL;
    if (!ctx || !b || gls_camera_load(camfile, GLS_POSE_WORLD, NULL, &cam, err, sizeof err) ||
        gls_scene_flatten(b, &sc, err, sizeof err) || !(r = gls_renderer_create(ctx, b, &sc, err, sizeof err)) ||
        make_plan("lattice", m, &p)) {
        fprintf(stderr, "aa_bench: texlod: %s\n", b ? err : ge.msg);
        return 1;
    }
    size_t n = (size_t)cam.width * cam.height;
    uint8_t *img[3];
    double t[3];
    for (int k = 0; k < 3; k++) {
        img[k] = malloc(n * 4);
        gls_accum a;
        double t0 = now();
        if (gls_renderer_set_size(r, cam.width, cam.height, err, sizeof err))
            return 1;
        if (k == 2) { /* one plain pass, for reference */
            gls_render_pass(r, &cam, 0, 0);
            gls_render_read_rgba(r, img[k]);
        } else {
            if (gls_accum_init(&a, cam.width, cam.height, 0, 0))
                return 1;
            gls_aa_run_opts ro = {0, 0, NULL, NULL, NULL, NULL};
            if (k == 0 ? gls_aa_render_fine(r, &cam, &p, NULL, &a, NULL, err, sizeof err)
                       : gls_aa_render(r, &cam, &p, &ro, &a, NULL, err, sizeof err)) {
                fprintf(stderr, "aa_bench: texlod: %s\n", err);
                return 1;
            }
            gls_accum_rgba8(&a, img[k]);
            gls_accum_free(&a);
        }
        t[k] = now() - t0;
    }
    double d = 0, dmax = 0;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double e = fabs((double)img[0][4 * i + c] - img[1][4 * i + c]);
            d += e, dmax = fmax(dmax, e);
        }
    printf("texlod M %llu %ux%u: one pass %.2f s, %llu passes %.2f s; mean |difference| %.3f, max %.0f (8-bit "
           "levels); RMS gradient: one pass %.2f, passes %.2f, plain %.2f\n",
           (unsigned long long)m, cam.width, cam.height, t[0], (unsigned long long)m, t[1], d / (3.0 * (double)n),
           dmax, grad_energy(img[0], cam.width, cam.height), grad_energy(img[1], cam.width, cam.height),
           grad_energy(img[2], cam.width, cam.height));
    for (int k = 0; k < 3; k++)
        free(img[k]);
    gls_renderer_destroy(r);
    gls_scene_free(&sc);
    gls_bundle_free(b);
    gls_glctx_destroy(ctx);
    return 0;
}

/* ---- snapping --------------------------------------------------------- */

static int snap(void)
{
    char err[256];
    gls_glctx *ctx = gls_glctx_create(GLS_BACKEND_AUTO, err, sizeof err);
    if (!ctx)
        return 1;
    static const uint32_t ns[] = {1, 4, 16, 64};
    for (int i = 0; i < 4; i++) {
        double w = as_snap_worst(ctx, ns[i]);
        printf("snap N %u (fine pixel 1/%u px): largest edge displacement %.7f px = 1/%.0f px (half a snap step: "
               "1/%u px)\n",
               ns[i], ns[i], w, w > 0 ? 1 / w : 0, 512 * ns[i]);
    }
    gls_glctx_destroy(ctx);
    return 0;
}

int main(int argc, char **argv)
{
    int rc = 2;
    if (argc == 6 && strcmp(argv[1], "accuracy") == 0)
        rc = accuracy((uint32_t)atoi(argv[2]), (uint32_t)atoi(argv[3]), argv[4], strtoull(argv[5], NULL, 10));
    else if (argc == 4 && strcmp(argv[1], "analytic") == 0)
        rc = analytic(argv[2], strtoull(argv[3], NULL, 10));
    else if (argc == 4 && strcmp(argv[1], "generators") == 0)
        rc = generators(strtoull(argv[2], NULL, 10), atof(argv[3]));
    else if (argc == 3 && strcmp(argv[1], "scene") == 0)
        rc = scene(argv[2]);
    else if (argc == 5 && strcmp(argv[1], "texlod") == 0)
        rc = texlod(argv[2], argv[3], strtoull(argv[4], NULL, 10));
    else if (argc == 2 && strcmp(argv[1], "snap") == 0)
        rc = snap();
    if (rc == 2)
        fprintf(stderr, "usage: aa_bench accuracy W H PATTERN M | analytic PATTERN M | generators M D | scene DIR | "
                        "texlod BUNDLE CAM M | snap\n");
    return rc;
}
