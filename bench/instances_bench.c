/* make bench-instances (bench/instances.sh): the instanced player against
 * its flattened path (--flatten) and the bare-GL floor.  Not a test: it
 * prints figures, one line per run.
 *
 * usage: instances_bench random [--flatten]
 *          bench/play_scene.h's 100,352 height-field triangles, each its
 *          own 3-vertex polygon in random order (bench/random_order.h),
 *          PS_FRAMES frames on ps_camera's path, colour and depth read
 *          back each frame, as bench/play_floor.c draws them;
 *          prints "random FPS triangles T items I renderer NAME"
 *        instances_bench forest edge|all [--flatten] [--one] FRAMES
 *          FOREST_N x FOREST_N instances of a TREE_TRIS-triangle tree,
 *          seen from the forest's edge looking along it (edge: most of it
 *          outside the view) or from above (all: all of it in view);
 *          --one: a single tree (the memory baseline); --no-cull:
 *          every item drawn (gls_scene.no_cull), to measure what culling
 *          saves; --no-occlusion: occlusion culling off (render.h; on
 *          by default, as in glsplay); --sparse: each of the tree's
 *          quads a tenth as wide (ribs with gaps between them: the same
 *          triangles and boxes, which overlap in the view as much, but
 *          hide little: the case occlusion culling cannot win).  One
 *          untimed frame
 *          (warm-up), then FRAMES timed; prints "forest FPS drawn D culled C
 *          items I of N rss KIB loaded KIB geometry B table B setup S": rss
 *          is the peak resident set (KiB), loaded the peak before the
 *          first frame (bundle, scene and GL buffers), geometry and table
 *          gls_scene_memory's bytes, setup the seconds to build the
 *          bundle and the scene and draw the first frame; then "occluded
 *          O same S showing V": items the first timed frame skipped as
 *          occluded, S = 1 when that frame's colour and depth are
 *          byte-identical to the same frame drawn with occlusion culling
 *          off (0 otherwise), and V the instances that show at some pixel
 *          centre of that frame (its ground-truth id pass). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include "player_scene.h"
#include "random_order.h"
#include "gt_pass.h"
#include "scene_cull.h"

#define FOREST_N 100         /* trees a side: 10,000 instances            */
#define FOREST_STEP 10.0     /* metres between trees, before the jitter   */
#define TREE_SEG 20          /* quads around the trunk and each crown ring */
#define TREE_RINGS 49        /* crown strips: (1 + 49) * 2 * 20 = 2000 tris */
#define TREE_TRIS ((1 + TREE_RINGS) * 2 * TREE_SEG)

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static gls_bundle *random_bundle(void)
{
    tb t;
    tb_init(&t);
    tb_object(&t, "random", 1);
    uint32_t *order = ro_order();
    if (!order)
        tb_die("out of memory");
    for (uint32_t k = 0; k < RO_NTRI; k++) {
        gls_vec4 p[3];
        gls_rgba c[3];
        for (int q = 0; q < 3; q++) {
            int i, j;
            double x[3];
            float col[4];
            ro_corner(order[k], q, &i, &j);
            ps_vertex(i, j, x, col);
            p[q] = (gls_vec4){x[0], x[1], x[2], 1};
            c[q] = (gls_rgba){col[0], col[1], col[2], col[3]};
        }
        tb_prim4(&t, GLS_PRIM_POLY, 3, p, c, NULL);
    }
    free(order);
    return tb_finish(&t);
}

/* Ring k of the tree: height and radius.  Ring 0..1 is the trunk (radius
 * 0.3 m, 0 to 2 m); rings 1..TREE_RINGS + 1 the crown, an ellipsoid
 * (radius 2.5 m, 2 to 9 m tall). */
static int sparse; /* --sparse: each quad a tenth as wide (ribs) */
static void ring(int k, double *y, double *r)
{
    if (k == 0) {
        *y = 0, *r = 0.3;
        return;
    }
    double a = M_PI * (k - 1) / TREE_RINGS;
    *y = 5.5 - 3.5 * cos(a), *r = k == 1 ? 0.3 : 2.5 * sin(a);
}

/* The tree: one quad strip per ring pair, TREE_SEG quads each, brown
 * trunk, green crown shaded by height (per-vertex colours). */
static void tree(tb *t)
{
    gls_vec4 p[2 * (TREE_SEG + 1)];
    gls_rgba c[2 * (TREE_SEG + 1)];
    for (int k = 0; k <= TREE_RINGS; k++) {
        for (int s = 0; s <= TREE_SEG; s++)
            for (int e = 0; e < 2; e++) {
                double y, r, a = 2 * M_PI * s / TREE_SEG;
                ring(k + e, &y, &r);
                p[2 * s + e] = (gls_vec4){r * cos(a), y, r * sin(a), 1};
                c[2 * s + e] = k == 0 ? (gls_rgba){0.4f, 0.25f, 0.1f, 1}
                                      : (gls_rgba){0.1f, (float)(0.3 + 0.04 * y), 0.1f, 1};
            }
        if (!sparse) {
            tb_prim4(t, GLS_PRIM_QSTRIP, 2 * (TREE_SEG + 1), p, c, NULL);
            continue;
        }
        for (int s = 0; s < TREE_SEG; s++) { /* a rib: the quad's first tenth */
            gls_vec4 q[4];
            gls_rgba qc[4];
            for (int v = 0; v < 4; v++) {
                int e = v == 1 || v == 2, w = v >= 2; /* corners (s, 0) (s, 1) (s+.1, 1) (s+.1, 0) */
                double y, r, a = 2 * M_PI * (s + 0.1 * w) / TREE_SEG;
                ring(k + e, &y, &r);
                q[v] = (gls_vec4){r * cos(a), y, r * sin(a), 1};
                qc[v] = c[2 * s + e];
            }
            tb_prim4(t, GLS_PRIM_POLY, 4, q, qc, NULL);
        }
    }
}

/* n x n trees on a jittered FOREST_STEP grid (x, z from 0), each turned
 * about the vertical: every call one instance of the one tree. */
static gls_bundle *forest_bundle(int n)
{
    tb t;
    tb_init(&t);
    tb_object(&t, "forest", 1);
    uint64_t seed = 10000;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double jx = (double)(ro_splitmix(&seed) % 1000) / 1000 - 0.5;
            double jz = (double)(ro_splitmix(&seed) % 1000) / 1000 - 0.5;
            double yaw = (double)(ro_splitmix(&seed) % 360);
            tb_op0(&t, GLS_OP_PUSH);
            tb_trans(&t, FOREST_STEP * (i + 0.6 * jx), 0, FOREST_STEP * (j + 0.6 * jz));
            tb_rot(&t, yaw, 0, 1, 0);
            tb_call(&t, 1);
            tb_op0(&t, GLS_OP_POP);
        }
    tb_object(&t, "tree", 0);
    tree(&t);
    return tb_finish(&t);
}

/* Frame k's camera, 640x480, f 500 (a 65-degree horizontal view).
 * edge: 1.7 m above the ground, 10 m in front of the forest's x = 0 edge
 * and 6 m outside it, looking along the edge (+z) turned 15 degrees away
 * from the forest, walking along it; all: 1300 m above the forest's
 * centre looking straight down, drifting. */
static gls_camera forest_camera(int edge, int k)
{
    gls_camera c;
    memset(&c, 0, sizeof c);
    c.width = 640, c.height = 480;
    c.fx = c.fy = 500, c.cx = 319.5, c.cy = 239.5;
    double C[3];
    if (edge) {
        /* world y up; camera x right, y down, z forward: forward
         * (-sin a, 0, cos a) turns away from the forest (x > 0) */
        double a = 15 * M_PI / 180;
        double R[9] = {-cos(a), 0, -sin(a), 0, -1, 0, -sin(a), 0, cos(a)};
        memcpy(c.R, R, sizeof R);
        C[0] = -6, C[1] = 1.7, C[2] = -10 + 0.5 * k;
        c.near = 0.1, c.far = 2000;
    } else {
        double R[9] = {1, 0, 0, 0, 0, 1, 0, -1, 0}; /* forward: world -y */
        memcpy(c.R, R, sizeof R);
        double mid = FOREST_STEP * (FOREST_N - 1) / 2;
        C[0] = mid + 0.5 * k, C[1] = 1300, C[2] = mid;
        c.near = 1, c.far = 2000;
    }
    for (int i = 0; i < 3; i++)
        c.T[i] = -(c.R[3 * i] * C[0] + c.R[3 * i + 1] * C[1] + c.R[3 * i + 2] * C[2]);
    return c;
}

static long peak_rss_kib(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

int main(int argc, char **argv)
{
    char err[256];
    int flatten = 0, no_cull = 0, no_occlusion = 0, one = 0, forest = argc > 1 && strcmp(argv[1], "forest") == 0, edge = 0, frames = PS_FRAMES;
    int a = 2;
    if (forest && argc > 2 && (strcmp(argv[2], "edge") == 0 || strcmp(argv[2], "all") == 0))
        edge = strcmp(argv[2], "edge") == 0, a = 3;
    for (; a < argc && argv[a][0] == '-'; a++) {
        if (strcmp(argv[a], "--flatten") == 0)
            flatten = 1;
        else if (strcmp(argv[a], "--no-cull") == 0)
            no_cull = 1;
        else if (strcmp(argv[a], "--no-occlusion") == 0)
            no_occlusion = 1;
        else if (forest && strcmp(argv[a], "--sparse") == 0)
            sparse = 1;
        else if (forest && strcmp(argv[a], "--one") == 0)
            one = 1;
        else
            break;
    }
    if (forest && a + 1 == argc)
        frames = atoi(argv[a++]);
    if (argc < 2 || (!forest && strcmp(argv[1], "random") != 0) || (forest && a == 2) || a != argc || frames < 1) {
        fprintf(stderr, "usage: instances_bench random [--flatten]\n"
                        "       instances_bench forest edge|all [--flatten] [--no-cull] [--no-occlusion] [--sparse] [--one] FRAMES\n");
        return 2;
    }
    gls_glctx *ctx = gls_glctx_create(GLS_BACKEND_AUTO, err, sizeof err);
    if (!ctx) {
        fprintf(stderr, "instances_bench: %s\n", err);
        return 1;
    }
    double t0 = now();
    gls_bundle *b = forest ? forest_bundle(one ? 1 : FOREST_N) : random_bundle();
    gls_scene sc;
    if ((flatten ? gls_scene_flatten : gls_scene_load)(b, &sc, err, sizeof err)) {
        fprintf(stderr, "instances_bench: %s\n", err);
        return 1;
    }
    sc.no_cull = no_cull;
    gls_renderer *r = gls_renderer_create(ctx, b, &sc, err, sizeof err);
    if (r && no_occlusion)
        gls_renderer_set_occlusion(r, GLS_OCCLUSION_OFF);
    if (!r || gls_renderer_set_size(r, 640, 480, err, sizeof err)) {
        fprintf(stderr, "instances_bench: %s\n", err);
        return 1;
    }
    long rss_loaded = peak_rss_kib(); /* scene built and uploaded, nothing drawn */
    uint8_t *rgba = malloc((size_t)640 * 480 * 4);
    float *z = malloc((size_t)640 * 480 * 4);
    if (forest) { /* a warm-up frame, not timed: llvmpipe compiles its shaders on the first draw */
        gls_camera c0 = forest_camera(edge, 0);
        gls_render_pass(r, &c0, 0, 0);
        gls_render_read_rgba(r, rgba);
    }
    double t1 = now();
    for (int f = 0; f < frames; f++) {
        gls_camera cam = forest ? forest_camera(edge, f) : ps_camera(f);
        gls_render_pass(r, &cam, 0, 0);
        gls_render_read_rgba(r, rgba);
        gls_render_read_z(r, z);
    }
    double t2 = now();
    ps_dump(rgba);
    if (forest) {
        /* drawn and culled in the first timed frame (the counts barely
         * move along the short path) */
        gls_camera c0 = forest_camera(edge, 0);
        uint8_t *ivis = malloc(sc.ninst), *vis = malloc(sc.nitems);
        gls_cull_stats st;
        uint64_t geo, table;
        gls_scene_cull(&sc, &c0, ivis, vis, &st);
        gls_scene_memory(&sc, &geo, &table);
        printf("forest %.3f drawn %u culled %u items %u of %u rss %ld loaded %ld geometry %llu table %llu setup %.2f",
               frames / (t2 - t1), st.drawn, st.culled, st.items_drawn, sc.nitems, peak_rss_kib(), rss_loaded,
               (unsigned long long)geo, (unsigned long long)table, t1 - t0);
        /* the first timed frame again, as drawn and with occlusion off */
        size_t np = (size_t)640 * 480;
        uint8_t *rgba2 = malloc(np * 4);
        float *z2 = malloc(np * 4);
        gls_render_pass(r, &c0, 0, 0);
        uint32_t occluded = gls_render_occluded(r);
        gls_render_read_rgba(r, rgba);
        gls_render_read_z(r, z);
        gls_renderer_set_occlusion(r, GLS_OCCLUSION_OFF);
        gls_render_pass(r, &c0, 0, 0);
        gls_render_read_rgba(r, rgba2);
        gls_render_read_z(r, z2);
        /* the instances that show at some pixel centre (the ground-truth
         * id pass): what a perfect occlusion test would keep */
        uint32_t *ids = malloc(np * sizeof *ids), shown = 0;
        uint8_t *seen = calloc((size_t)sc.ninst + 1, 1);
        if (!ids || !seen || gls_gt_render(r, &c0, ids, NULL, NULL, err, sizeof err)) {
            fprintf(stderr, "instances_bench: %s\n", ids && seen ? err : "out of memory");
            return 1;
        }
        for (size_t i = 0; i < np; i++)
            if (ids[i] && !seen[ids[i]])
                seen[ids[i]] = 1, shown++;
        free(ids), free(seen);
        printf(" occluded %u same %d showing %u\n", occluded, memcmp(rgba, rgba2, np * 4) == 0 && memcmp(z, z2, np * 4) == 0,
               shown);
        free(rgba2), free(z2);
        free(ivis), free(vis);
    } else {
        printf("random %.2f triangles %u items %u renderer %s\n", frames / (t2 - t1), sc.nverts / 3, sc.nitems,
               gls_renderer_gl_name(r));
    }
    free(rgba), free(z);
    gls_renderer_destroy(r);
    gls_scene_free(&sc);
    gls_bundle_free(b);
    gls_glctx_destroy(ctx);
    return 0;
}
