/* The player of the library (include/glscene.h): a bundle's scene, its GL
 * context and renderer, kept open across renders.  Each render does what
 * glsplay's play_camera does for the same outputs
 * (runtime/play/play_frame.c): the centre pass for depth and an image of
 * one sample, the anti-aliasing passes for an image of more, the
 * ground-truth pass for ids and normals, with the same functions, so that
 * the numbers are glsplay's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "aa.h"
#include "bundle.h"
#include "exact_scene.h"
#include "glctx.h"
#include "glscene_internal.h"
#include "gt_table.h"
#include "player.h"
#include "render.h"
#include "rotation.h"
#include "scene.h"

struct glscene_player {
    gls_scene scene;       /* outlives the renderer, which draws from it   */
    gls_glctx *ctx;
    gls_renderer *r;
    gls_aa_plan plan;
    gls_gt_table gt;       /* instance ids and call paths (gt_table.h)     */
    int have_gt;           /* 0: more instances draw than ids can number   */
    uint32_t drawing;      /* how many instances draw something           */
    float background[3];   /* the exact pass's (the renderer has its own)  */
    gls_bundle *b;         /* exact coverage only: its textures, which the
                              exact pass shades on the CPU                 */
};

const char *glscene_version(void)
{
    return GLSCENE_VERSION;
}

static gls_backend backend_of(glscene_backend b)
{
    return b == GLSCENE_BACKEND_EGL ? GLS_BACKEND_EGL : b == GLSCENE_BACKEND_OSMESA ? GLS_BACKEND_OSMESA
                                                                                     : GLS_BACKEND_AUTO;
}

glscene_player *glscene_open(const char *bundle_path, const glscene_options *opt, glscene_error *e)
{
    static const glscene_options defaults;
    char err[sizeof e->message];
    gls_error gerr;
    if (!opt)
        opt = &defaults;
    if (!bundle_path) {
        gls_api_fail(e, "glscene_open: no bundle path");
        return NULL;
    }
    if (opt->backend < GLSCENE_BACKEND_AUTO || opt->backend > GLSCENE_BACKEND_OSMESA ||
        opt->pattern < GLSCENE_AA_LATTICE || opt->pattern > GLSCENE_AA_STRATIFIED) {
        gls_api_fail(e, "glscene_open: options: backend %d or pattern %d is not one of the enum's values",
                     (int)opt->backend, (int)opt->pattern);
        return NULL;
    }
    glscene_player *p = calloc(1, sizeof *p);
    if (!p) {
        gls_api_fail(e, "out of memory");
        return NULL;
    }
    gls_aa_opts aa = gls_aa_defaults();
    /* 0: glsplay's default, --aa auto (chosen once the scene is read) */
    aa.exact = opt->aa == GLSCENE_AA_EXACT ? GLS_AA_EXACT : opt->aa == 0 ? GLS_AA_AUTO : GLS_AA_SAMPLED;
    aa.n = opt->aa && aa.exact == GLS_AA_SAMPLED ? opt->aa : 1;
    memcpy(p->background, opt->background, sizeof p->background);
    aa.pattern = opt->pattern == GLSCENE_AA_GRID         ? GLS_AA_GRID
                 : opt->pattern == GLSCENE_AA_STRATIFIED ? GLS_AA_STRATIFIED
                                                         : GLS_AA_LATTICE;
    aa.seed = opt->seed;
    gls_bundle *b = NULL;
    if (gls_aa_plan_init(&p->plan, &aa, err, sizeof err)) {
        gls_api_fail(e, "%s", err);
        goto fail;
    }
    b = gls_bundle_read_file(bundle_path, &gerr);
    if (!b) {
        gls_api_fail(e, "%s", gerr.msg); /* the message names the file */
        goto fail;
    }
    if (b->top == GLS_NONE) {
        gls_api_fail(e, "%s: a library bundle (no top-level object) cannot be played; compile a scene with a "
                        "top-level object", bundle_path);
        goto fail;
    }
    if (gls_scene_load(b, &p->scene, err, sizeof err)) {
        gls_api_fail(e, "%s: %s", bundle_path, err);
        goto fail;
    }
    /* glsplay's rule (runtime/play/play_aa.c), in the library's words:
     * its cameras are pinholes without exposure or sensor effects, so
     * the scene alone decides */
    size_t cam;
    const char *why = aa.exact ? gls_play_exact_blocker(&aa, &p->scene, NULL, 0, 0, &cam) : NULL;
    if (why && aa.exact == GLS_AA_EXACT) {
        gls_api_fail(e, "%s: exact coverage (aa GLSCENE_AA_EXACT) does not draw %s; ask for samples (aa N) instead",
                     bundle_path, why);
        goto fail;
    }
    if (aa.exact == GLS_AA_AUTO) { /* glscene_render writes no coverage */
        gls_play_aa_auto(&aa, why, 0);
        p->plan.o.exact = aa.exact, p->plan.o.dense = aa.dense;
    }
    int k = gls_gt_table_build(&p->gt, b, &p->scene, &p->drawing);
    if (k < 0) {
        gls_api_fail(e, "out of memory");
        goto fail;
    }
    p->have_gt = k == 0;
    p->ctx = gls_glctx_create(backend_of(opt->backend), err, sizeof err);
    if (!p->ctx) {
        gls_api_fail(e, "%s", err);
        goto fail;
    }
    p->r = gls_renderer_create(p->ctx, b, &p->scene, err, sizeof err);
    if (!p->r) {
        gls_api_fail(e, "%s", err);
        goto fail;
    }
    gls_renderer_set_background(p->r, opt->background);
    if (aa.exact)
        p->b = b; /* the exact pass shades its textures (glscene_render) */
    else
        gls_bundle_free(b);
    return p;
fail:
    gls_bundle_free(b);
    glscene_close(p);
    return NULL;
}

void glscene_close(glscene_player *p)
{
    if (!p)
        return;
    if (p->ctx)
        gls_glctx_make_current(p->ctx); /* the renderer frees GL objects */
    gls_renderer_destroy(p->r);
    gls_glctx_destroy(p->ctx);
    gls_gt_table_free(&p->gt);
    gls_scene_free(&p->scene);
    gls_bundle_free(p->b);
    free(p);
}

int glscene_move_instance(glscene_player *p, const char *name, const double R[9], const double T[3],
                          glscene_error *e)
{
    uint32_t i = name && strlen(name) <= GLS_INSTANCE_NAME_MAX ? gls_scene_find_instance(&p->scene, name) : GLS_NONE;
    if (i == GLS_NONE)
        return gls_api_fail(e, "the scene has no instance named '%s'", name ? name : "(null)");
    double r[9], t[3] = {0, 0, 0};
    char why[300];
    if (R) {
        memcpy(r, R, sizeof r);
        if (T)
            memcpy(t, T, sizeof t);
        for (int k = 0; k < 12; k++)
            if (!isfinite(k < 9 ? r[k] : t[k - 9]))
                return gls_api_fail(e, "move %s: %s[%d] is not a finite number", name, k < 9 ? "R" : "T",
                                    k < 9 ? k : k - 9);
        if (gls_rotation_check(r, why, sizeof why) < 0)
            return gls_api_fail(e, "move %s: R: %s", name, why);
    }
    gls_scene_move(&p->scene, i, R ? r : NULL, t);
    gls_scene_update(&p->scene);
    return 0;
}

const char *glscene_instance_path(glscene_player *p, uint32_t id)
{
    return p && p->have_gt && id >= 1 && id <= p->gt.nids ? p->gt.path[id - 1] : NULL;
}

uint32_t glscene_instance_count(glscene_player *p)
{
    return p ? p->drawing : 0;
}

static void rgba_to_rgb(const uint8_t *rgba, size_t n, uint8_t *rgb)
{
    for (size_t i = 0; i < n; i++)
        memcpy(rgb + 3 * i, rgba + 4 * i, 3);
}

int glscene_render(glscene_player *p, const glscene_camera *cam, const glscene_buffers *out, glscene_error *e)
{
    gls_camera c;
    char err[512];
    if (!p || !cam || !out)
        return gls_api_fail(e, "glscene_render: a NULL player, camera or buffers");
    if (gls_api_camera(cam, &c, e))
        return -1;
    if (out->instance && !p->have_gt)
        return gls_api_fail(e, "%u instances draw something, more than the %u instance ids", p->drawing,
                            GLS_GT_MAX_IDS);
    if (gls_glctx_make_current(p->ctx))
        return gls_api_fail(e, "cannot make the player's GL context current on this thread");
    if (gls_renderer_set_size(p->r, c.width, c.height, err, sizeof err))
        return gls_api_fail(e, "%s", err);
    size_t n = (size_t)c.width * c.height;
    /* the frame drawn by the player's own steps (player.h gls_play_frame):
     * its frame plan for the outputs these buffers ask for, its centre
     * and truth passes, its accumulator; here only the conversions into
     * the caller's layouts */
    int image = out->rgb8 || out->rgbf;
    unsigned outputs = (image ? GLS_OUT_IMAGE : 0u) | (out->depth ? GLS_OUT_DEPTH : 0u) |
                       (out->instance ? GLS_OUT_INSTANCE : 0u) | (out->normals ? GLS_OUT_NORMALS : 0u);
    gls_play_frame_result res;
    if (gls_play_frame(p->r, &p->scene, &p->plan, &c, outputs, p->background, p->b ? p->b->textures : NULL, &res, err,
                       sizeof err))
        return err[0] ? gls_api_fail(e, "%s", err)
                      : gls_api_fail(e, "out of memory for a %ux%u image", c.width, c.height);
    int rc = -1;
    uint8_t *rgba = NULL;
    if (out->depth)
        memcpy(out->depth, res.z, n * sizeof *res.z);
    if (out->normals)
        memcpy(out->normals, res.normals, 3 * n * sizeof *res.normals);
    /* scene instance index + 1 -> the id glsplay's instance output has */
    for (size_t i = 0; out->instance && i < n; i++)
        out->instance[i] = res.ids[i] ? p->gt.id[res.ids[i] - 1] : 0;
    if (res.exact) { /* exact coverage: the conversions of glsplay's PNG and PFM */
        if (out->rgb8) {
            if (!(rgba = malloc(n * 4))) {
                gls_api_fail(e, "out of memory for a %ux%u image", c.width, c.height);
                goto done;
            }
            gls_exact_rgba8(res.exact, n, rgba);
            rgba_to_rgb(rgba, n, out->rgb8);
        }
        if (out->rgbf)
            gls_exact_rgbf(res.exact, n, out->rgbf);
    } else if (res.fp.aa) {
        if (out->rgb8) {
            if (!(rgba = malloc(n * 4))) {
                gls_api_fail(e, "out of memory for a %ux%u image", c.width, c.height);
                goto done;
            }
            gls_accum_rgba8(&res.acc, rgba);
            rgba_to_rgb(rgba, n, out->rgb8);
        }
        if (out->rgbf)
            gls_accum_rgbf(&res.acc, out->rgbf);
    } else if (image) {
        if (out->rgb8)
            rgba_to_rgb(res.rgba, n, out->rgb8);
        if (out->rgbf)
            gls_rgba8_to_rgbf(res.rgba, n, out->rgbf);
    }
    rc = 0;
done:
    free(rgba);
    gls_play_frame_free(&res);
    return rc;
}
