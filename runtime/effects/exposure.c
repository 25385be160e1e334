/* Motion blur, rolling shutter, depth of field (exposure.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "exposure.h"
#include "scene.h"

gls_exposure gls_exposure_of(const gls_camera *c, int moving)
{
    gls_exposure e;
    e.blur = moving && c->shutter > 0;
    e.rolling = moving && c->line_delay > 0;
    e.dof = c->aperture > 0;
    e.samples = (e.blur || e.dof) ? c->exposure_samples : 1;
    if (!e.samples)
        e.samples = 1;
    return e;
}

void gls_exposure_span(const gls_camera *c, const gls_exposure *e, double *s0, double *s1)
{
    *s0 = e->blur ? -c->shutter / 2 : 0;
    *s1 = (e->blur ? c->shutter / 2 : 0) + (e->rolling ? (double)(c->height - 1) * c->line_delay : 0);
}

static uint64_t gcd64(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b, b = t;
    }
    return a;
}

void gls_exposure_sample(const gls_camera *c, const gls_exposure *e, uint32_t j, double *s, double *lx, double *ly)
{
    uint64_t K = e->samples;
    *s = 0, *lx = 0, *ly = 0;
    if (e->blur) {
        /* the stride nearest K / phi that is coprime to K: a permutation */
        uint64_t a = (uint64_t)floor((double)K * 0.6180339887498949 + 0.5);
        while (a > 1 && gcd64(a, K) != 1)
            a--;
        if (a < 1)
            a = 1;
        uint64_t p = (j * a) % K;
        *s = c->shutter * (((double)p + 0.5) / (double)K - 0.5);
    }
    if (e->dof) {
        const double golden = 3.14159265358979323846 * (3 - sqrt(5.0));
        double r = c->aperture / 2 * sqrt(((double)j + 0.5) / (double)K), th = golden * (double)j;
        *lx = r * cos(th);
        *ly = r * sin(th);
    }
}

void gls_exposure_lens(const gls_camera *c, double lx, double ly, gls_camera *out)
{
    *out = *c;
    if (lx == 0 && ly == 0)
        return;
    /* P_cam' = P_cam - l: the centre of projection at l; the principal
     * point shifted so that Zc = F stays in place */
    out->T[0] = c->T[0] - lx;
    out->T[1] = c->T[1] - ly;
    out->cx = c->cx + (c->fx * lx + c->skew * ly) / c->focus;
    out->cy = c->cy + c->fy * ly / c->focus;
}

int gls_exposure_fits(const gls_exposure *e, const gls_aa_plan *p, char *why, size_t whylen)
{
    /* unweighted: uint32 sums of K * count samples of <= 255;
     * weighted: uint64 sums of K * wsum * 255 */
    uint64_t K = e->samples;
    if (gls_aa_weighted(p) ? K > UINT64_MAX / 255 / p->wsum : K * p->count > GLS_ACCUM_MAX_SAMPLES) {
        snprintf(why, whylen,
                 "exposure_samples %llu times the anti-aliasing's %llu samples exceed what the accumulator adds "
                 "exactly (%s); lower exposure_samples or --aa",
                 (unsigned long long)K, (unsigned long long)p->count,
                 gls_aa_weighted(p) ? "a Gaussian filter: at most 16 sub-frame renders"
                                    : "at most 4096^2 samples per pixel");
        return -1;
    }
    return 0;
}

/* Corners of every item's world box in the image of c (NAN when not in
 * front of the near plane). */
static void project_corners(const gls_scene *s, const gls_camera *c, double *uv)
{
    for (uint32_t i = 0; i < s->nitems; i++) {
        const gls_item *it = &s->items[i];
        for (int k = 0; k < 8; k++) {
            double P[3] = {k & 1 ? it->hi[0] : it->lo[0], k & 2 ? it->hi[1] : it->lo[1],
                           k & 4 ? it->hi[2] : it->lo[2]};
            double u, v, z = gls_camera_project(c, P, &u, &v);
            double *o = uv + 2 * (8 * (size_t)i + k);
            o[0] = z > c->near && isfinite(u) ? u : NAN;
            o[1] = z > c->near && isfinite(v) ? v : NAN;
        }
    }
}

uint32_t gls_exposure_band_rows(const gls_renderer *r, const gls_camera *c, const gls_exposure *e,
                                gls_pose_at_fn pose_at, void *ud)
{
    const gls_scene *s = gls_renderer_scene(r);
    uint32_t H = c->height;
    if (!e->rolling || H < 2 || !s->nitems)
        return H;
    double s0, s1;
    gls_exposure_span(c, e, &s0, &s1);
    size_t n = (size_t)s->nitems * 16;
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    if (!a || !b) {
        free(a);
        free(b);
        return 1; /* no estimate: one row a band is always right */
    }
    enum { STEPS = 8 };
    double dt = (s1 - s0) / STEPS, speed = 0; /* pixels per frame interval */
    gls_camera cam = *c;
    pose_at(ud, s0, &cam);
    project_corners(s, &cam, a);
    for (int k = 1; k <= STEPS; k++) {
        pose_at(ud, s0 + dt * k, &cam);
        project_corners(s, &cam, b);
        for (size_t i = 0; i < n; i += 2)
            if (!isnan(a[i]) && !isnan(b[i])) {
                double d = hypot(b[i] - a[i], b[i + 1] - a[i + 1]) / dt;
                if (d > speed)
                    speed = d;
            }
        double *t = a;
        a = b, b = t;
    }
    pose_at(ud, 0, &cam);
    free(a);
    free(b);
    double h = GLS_BAND_PX / (speed * c->line_delay);
    return !(speed > 0) || h >= H ? H : h < 1 ? 1 : (uint32_t)h;
}

/* acc's rows v0..v1-1 += src's (sums, and which pixels are mixed); first:
 * src is acc's first sample of those rows. */
static void add_rows(gls_accum *acc, const gls_accum *src, uint32_t v0, uint32_t v1, int first)
{
    size_t a = (size_t)acc->width * v0, b = (size_t)acc->width * v1;
    if (acc->weighted)
        for (size_t i = 4 * a; i < 4 * b; i++)
            acc->sum64[i] += src->sum64[i];
    else
        for (size_t i = 4 * a; i < 4 * b; i++)
            acc->sum32[i] += src->sum32[i];
    if (!acc->mixed)
        return;
    for (size_t i = a; i < b; i++) {
        if (first)
            acc->first[i] = src->first[i];
        acc->mixed[i] |= src->mixed[i] | (acc->first[i] != src->first[i]);
    }
}

/* a's rows v0..v1-1 cleared and its counts reset: a band's scratch.  Only
 * those rows are read back from it (add_rows), so the others may hold
 * what earlier bands left (or what a band drawn whole, gls_bands' whole,
 * added there).  Clearing the whole accumulator for every band cost a
 * tenth of a rolling frame (make bench-effects' road, rolling_shutter:
 * 357 ms a frame, 317 ms with this). */
static void accum_clear_rows(gls_accum *a, uint32_t v0, uint32_t v1)
{
    size_t i0 = (size_t)a->width * v0, n = (size_t)a->width * (v1 - v0);
    if (a->weighted)
        memset(a->sum64 + 4 * i0, 0, 4 * n * sizeof *a->sum64);
    else
        memset(a->sum32 + 4 * i0, 0, 4 * n * sizeof *a->sum32);
    if (a->mixed)
        memset(a->mixed + i0, 0, n);
    a->samples = a->wsum = 0;
}

int gls_exposure_render_bands(const gls_camera *c, const gls_exposure *e, const gls_aa_plan *p,
                              gls_pose_at_fn pose_at, void *pose_ud, gls_render_band_fn render_band, void *band_ud,
                              gls_accum *acc, uint32_t band, char *msg, size_t msglen)
{
    char why[300];
    if (gls_exposure_fits(e, p, why, sizeof why)) {
        snprintf(msg, msglen, "glsplay: error: camera: %s", why);
        return -1;
    }
    uint32_t H = c->height, h = band ? band : H;
    gls_accum tmp;
    if (gls_accum_init(&tmp, c->width, H, acc->weighted, acc->mixed != NULL)) {
        snprintf(msg, msglen, "glsplay: error: out of memory for the exposure's accumulator");
        return -1;
    }
    int rc = 0;
    for (uint32_t j = 0; j < e->samples && rc == 0; j++) {
        double s, lx, ly;
        gls_exposure_sample(c, e, j, &s, &lx, &ly);
        uint64_t wsum = 0, samples = 0;
        for (uint32_t v0 = 0; v0 < H && rc == 0; v0 += h) {
            uint32_t v1 = v0 + h < H ? v0 + h : H;
            /* the band's middle row's time */
            double t = s + (e->rolling ? c->line_delay * (v0 + v1 - 1) / 2.0 : 0);
            gls_camera at = *c;
            pose_at(pose_ud, t, &at);
            accum_clear_rows(&tmp, v0, v1);
            rc = render_band(band_ud, &at, lx, ly, v0, v1, &tmp, msg, msglen);
            if (rc == 0)
                add_rows(acc, &tmp, v0, v1, j == 0);
            wsum = tmp.wsum, samples = tmp.samples;
        }
        acc->wsum += wsum;
        acc->samples += samples;
    }
    gls_camera cam = *c;
    pose_at(pose_ud, 0, &cam);
    gls_accum_free(&tmp);
    return rc;
}

/* gls_exposure_render's band: the plan through the pinhole camera at the
 * band's pose and lens point, asked for the band's rows (all of them when
 * whole, the test's choice: gls_bands); the band's kept. */
typedef struct {
    gls_render_plan_fn render_plan;
    void *ud;
    int whole;
} plan_band;

static int render_plan_band(void *ud, const gls_camera *at, double lx, double ly, uint32_t v0, uint32_t v1,
                            gls_accum *tmp, char *msg, size_t msglen)
{
    const plan_band *pb = ud;
    gls_camera cam;
    gls_exposure_lens(at, lx, ly, &cam);
    if (pb->whole)
        v0 = 0, v1 = at->height;
    return pb->render_plan(pb->ud, &cam, v0, v1, tmp, msg, msglen);
}

int gls_exposure_render(gls_renderer *r, const gls_camera *c, const gls_exposure *e, const gls_aa_plan *p,
                        gls_pose_at_fn pose_at, gls_render_plan_fn render_plan, void *ud, gls_accum *acc,
                        gls_bands bands, char *msg, size_t msglen)
{
    (void)r;
    plan_band pb = {render_plan, ud, bands.whole};
    return gls_exposure_render_bands(c, e, p, pose_at, ud, render_plan_band, &pb, acc, bands.rows, msg, msglen);
}

void gls_exposure_explain(FILE *out, const gls_camera *c, int moving, const gls_aa_plan *p, int image)
{
    gls_exposure e = gls_exposure_of(c, moving);
    unsigned long long per = p->count, K = e.samples;
    if (c->shutter > 0 && !moving)
        fprintf(out, "  motion blur: off: shutter %g is given but nothing moves (no --trajectory, no --motion)\n",
                c->shutter);
    if (c->line_delay > 0 && !moving)
        fprintf(out, "  rolling shutter: off: line_delay %g is given but nothing moves (no --trajectory, no "
                     "--motion)\n", c->line_delay);
    if (!gls_exposure_on(&e))
        return;
    if (!image) {
        fprintf(out, "  exposure effects: asked for, but no output is drawn with them (image, edges): depth and "
                     "ground truth from the unblurred centre pass%s\n",
                e.rolling ? ", row by row at each row's time" : " at the frame time, lens centre");
        return;
    }
    if (e.blur)
        fprintf(out, "  motion blur: on (key shutter %g): exposure [-%g, %g] frame intervals around the frame time, "
                     "%llu sub-frame poses (midpoints of equal sub-intervals)\n",
                c->shutter, c->shutter / 2, c->shutter / 2, K);
    if (e.dof)
        fprintf(out, "  depth of field: on (keys aperture %g, focus %g): %llu lens points on the aperture disk "
                     "(Vogel spiral), projection sheared so the plane Zc = %g stays in place\n",
                c->aperture, c->focus, K, c->focus);
    if (e.rolling)
        fprintf(out, "  rolling shutter: on (key line_delay %g): row v exposed at the frame time + v * %g frame "
                     "intervals; rows in bands in which the image moves at most %g px (chosen per frame from the "
                     "scene's motion; 1 to %u bands)\n",
                c->line_delay, c->line_delay, GLS_BAND_PX, c->height);
    fprintf(out, "  exposure cost: %llu sub-frame render%s x %llu anti-aliasing sample%s per pixel%s; the image "
                 "from an accumulator of %llu samples per pixel; depth and ground truth from the unblurred %s\n",
            K, K == 1 ? "" : "s", per, per == 1 ? "" : "s", e.rolling ? ", x the bands of rows" : "", K * per,
            e.rolling ? "centre pass, row by row at each row's time" : "centre pass at the frame time, lens centre");
}

double (*gls_exposure_row_poses(const gls_camera *c, uint32_t band, gls_pose_at_fn pose_at, void *ud))[12]
{
    double (*pose)[12] = malloc((c->height ? c->height : 1) * sizeof *pose);
    if (!pose)
        return NULL;
    uint32_t h = band ? band : c->height;
    for (uint32_t v0 = 0; v0 < c->height; v0 += h) {
        uint32_t v1 = v0 + h < c->height ? v0 + h : c->height;
        gls_camera at = *c;
        pose_at(ud, c->line_delay * (v0 + v1 - 1) / 2.0, &at);
        for (uint32_t v = v0; v < v1; v++) {
            memcpy(pose[v], at.R, sizeof at.R);
            memcpy(pose[v] + 9, at.T, sizeof at.T);
        }
    }
    gls_camera at = *c;
    pose_at(ud, 0, &at);
    return pose;
}
