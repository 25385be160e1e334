/* The player's checks before anything is drawn (play_int.h): the options
 * alone (gls_play_check_options, player.h), and the inputs once read: a
 * rectified pair for disparity, each camera's lens, and the exposure
 * effects of every camera. */
#include <stdlib.h>
#include <string.h>
#include "distort.h"
#include "distort_exact.h"
#include "out_disparity.h"
#include "play_int.h"
#include "subframe.h"

static const char *disparity_word(const gls_play_opts *o)
{
    return o->outputs & GLS_OUT_DISPARITY ? "disparity" : "disparity16";
}

int gls_play_check_options(const gls_play_opts *o, char *msg, size_t msglen)
{
    gls_aa_plan plan;
    gls_aa_opts aao = o->aa;
    if (aao.n == 0)
        aao.n = 1;
    if (gls_aa_plan_init(&plan, &aao, msg, msglen))
        return -1;
    /* coverage is exact coverage's (glscene_play_check says it first, as
     * a usage error; this holds it for gls_play's other callers) */
    if ((o->outputs & GLS_OUT_EXACT_ONLY) && !o->aa.exact) {
        snprintf(msg, msglen, "--outputs %s needs --aa exact (exact areas, no samples)", GLS_OUT_EXACT_WORD(o->outputs));
        return -1;
    }
    /* OUTDIR/NAME, NAME the camera file's name without its extension */
    for (size_t i = 0; i < o->ncameras; i++) {
        char *name = play_camera_name(o->cameras[i]);
        if (!name) {
            snprintf(msg, msglen, "out of memory");
            return -1;
        }
        int bad = !name[0] || strcmp(name, ".") == 0 || strcmp(name, "..") == 0;
        size_t j = 0;
        for (; !bad && j < i; j++) {
            char *other = play_camera_name(o->cameras[j]);
            int same = !other || strcmp(name, other) == 0;
            free(other);
            if (same)
                break;
        }
        if (bad)
            snprintf(msg, msglen, "%s: cannot name an output directory after this camera file", o->cameras[i]);
        else if (j < i)
            snprintf(msg, msglen, "cameras %s and %s would both write to %s/%s/", o->cameras[j], o->cameras[i],
                     o->outdir ? o->outdir : "OUTDIR", name);
        free(name);
        if (bad || j < i)
            return -1;
    }
    if ((o->outputs & GLS_OUT_DISPARITIES) && o->ncameras != 2) {
        snprintf(msg, msglen, "--outputs %s needs a rectified pair: exactly two cameras, the left one first; %zu given",
                 disparity_word(o), o->ncameras);
        return -1;
    }
    /* the same NAME twice: decided here; two names of one instance
       (play_motion_load) only once the bundle is read */
    for (size_t i = 0; i < o->nmotions; i++)
        for (size_t j = 0; j < i; j++) {
            size_t n = strcspn(o->motions[i], "=");
            if (n == strcspn(o->motions[j], "=") && strncmp(o->motions[i], o->motions[j], n) == 0) {
                snprintf(msg, msglen, "--motion %s: instance %.*s is moved twice", o->motions[i], (int)n,
                         o->motions[i]);
                return -1;
            }
        }
    return 0;
}

/* --outputs disparity: the two cameras (gls_play_check_options) are a
 * rectified pair with the left one first (out_disparity.h).  0 with *B,
 * or 1 after a message. */
int play_rectified_check(const gls_play_opts *o, const gls_camera *cams, const char *const *names, double *B,
                         FILE *errs)
{
    char why[512];
    const char *word = disparity_word(o);
    if (gls_rectified_pair(&cams[0], &cams[1], names[0], names[1], B, why, sizeof why) == 0)
        return 0;
    fprintf(errs, "glsplay: error: --outputs %s needs a rectified pair: %s\n", word, why);
    return 1;
}

/* The outputs not made through a lens: disparity (a rectified pair has no
 * distortion: rectify first).  0, or -1 after a message. */
int play_lens_outputs_check(const gls_play_opts *o, const gls_camera *c, const char *path, FILE *errs)
{
    static const struct {
        unsigned bits;
        const char *word, *why;
    } no[] = {{GLS_OUT_DISPARITY, "disparity", "a rectified pair has no lens distortion"},
              {GLS_OUT_DISPARITY16, "disparity16", "a rectified pair has no lens distortion"}};
    if (!gls_distort_on(c))
        return 0;
    for (size_t i = 0; i < sizeof no / sizeof no[0]; i++)
        if (o->outputs & no[i].bits) {
            fprintf(errs, "glsplay: error: %s: --outputs %s needs a camera without lens distortion: %s\n", path,
                    no[i].word, no[i].why);
            return -1;
        }
    return 0;
}

/* A camera with lens distortion: the model must be one-to-one over the
 * image as --size makes it (the file was checked at its own size) and the
 * anti-aliasing window beyond it, before anything is drawn.  0, or -1
 * after a message. */
int play_lens_check(const gls_camera *c, const char *path, const gls_aa_plan *plan, FILE *errs)
{
    gls_distort_layout lay;
    char why[600];
    /* --aa exact resamples its undistorted image with its own plan */
    gls_aa_plan ep;
    if (plan->o.exact && gls_distort_on(c) && gls_distort_exact_plan(&ep, why, sizeof why) == 0)
        plan = &ep;
    if (gls_distort_on(c) && (gls_distort_layout_make(c, NULL, GLS_DISTORT_SCALE, 0, &lay, why, sizeof why) ||
                              gls_distort_layout_make(c, plan, GLS_DISTORT_AA_SCALE, 0, &lay, why, sizeof why))) {
        fprintf(errs, "glsplay: error: %s: %s\n", path, why);
        return -1;
    }
    return 0;
}

/* The effects of every camera, before anything is drawn: a note for a
 * shutter or line_delay with nothing moving (no effect), the
 * accumulator's range, and the trajectory read whole when a camera needs
 * sub-frame poses of the rig.  0, or 1 after a message. */
int play_exposure_setup(const gls_play_opts *o, motion_set *ms, const gls_camera *cams, const char *const *names,
                        const gls_aa_plan *plan, FILE *errs)
{
    int need_rig = 0;
    ms->moving = o->trajectory || o->nmotions;
    for (size_t i = 0; i < o->ncameras; i++) {
        const gls_camera *c = &cams[i];
        if (!ms->moving && (c->shutter > 0 || c->line_delay > 0))
            fprintf(errs, "glsplay: note: camera %s: %s no effect: nothing moves (no --trajectory, no --motion)\n",
                    names[i], c->shutter > 0 && c->line_delay > 0 ? "shutter and line_delay have"
                              : c->shutter > 0                    ? "shutter has"
                                                                  : "line_delay has");
        gls_exposure e = gls_exposure_of(c, ms->moving);
        char why[300];
        /* through a lens the exact areas are the undistorted image's */
        if (plan->o.exact && gls_distort_on(c) && (o->outputs & GLS_OUT_EXACT_ONLY)) {
            fprintf(errs, "glsplay: error: camera %s: --outputs %s needs a pinhole camera: through a lens the exact "
                          "areas are of the undistorted image, not of the pixels; leave out %s or the distortion\n",
                    names[i], GLS_OUT_EXACT_WORD(o->outputs), GLS_OUT_EXACT_WORD(o->outputs));
            return 1;
        }
        if (gls_exposure_on(&e) && (o->outputs & (GLS_OUT_IMAGE | GLS_OUT_EDGE_MAPS)) &&
            gls_exposure_fits(&e, plan, why, sizeof why)) {
            fprintf(errs, "glsplay: error: camera %s: %s\n", names[i], why);
            return 1;
        }
        need_rig |= e.blur || e.rolling;
    }
    char err[1024];
    if (need_rig && o->trajectory && gls_traj_read_all(&ms->traj, NULL, &ms->rig, err, sizeof err)) {
        fprintf(errs, "%s\n", err);
        return 1;
    }
    return 0;
}
