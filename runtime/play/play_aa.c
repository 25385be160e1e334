/* The anti-aliasing a run draws with (spec/antialiasing.md "The
 * default"), decided once: after the cameras and the scene are read,
 * before anything is checked against the plan, explained or drawn.
 * --aa auto, glsplay's default, is exact coverage wherever the run lets it
 * draw, and one sample a pixel where it cannot; --aa exact refuses what
 * exact coverage cannot draw.  Afterwards the run's options and its
 * anti-aliasing plan hold GLS_AA_EXACT or GLS_AA_SAMPLED, never
 * GLS_AA_AUTO, and --explain says which and why (explain.c). */
#include <string.h>
#include "exact.h"
#include "exact_scene.h"
#include "play_int.h"

const char *gls_play_exact_blocker(const gls_aa_opts *aa, const gls_scene *s, const gls_camera *cams, size_t n,
                                   int moving, size_t *cam)
{
    *cam = SIZE_MAX;
    /* exact coverage is the box filter's value */
    if (aa->filter != GLS_AA_BOX)
        return "the Gaussian filter (--filter gauss)";
    const char *why = s ? gls_exact_scene_unsupported(s) : NULL;
    if (why)
        return why;
    /* a pinhole at one instant (a lens resamples its undistorted image,
     * distort_exact.h): no exposure effect, no sensor */
    for (size_t i = 0; i < n; i++) {
        gls_exposure e = gls_exposure_of(&cams[i], moving);
        why = gls_exposure_on(&e)     ? "exposure effects (shutter, line_delay or aperture)"
              : cams[i].sensor.on     ? "sensor effects"
                                      : NULL;
        if (why) {
            *cam = i;
            return why;
        }
    }
    return NULL;
}

void gls_play_aa_auto(gls_aa_opts *aa, const char *why, unsigned outputs)
{
    aa->exact = why ? GLS_AA_SAMPLED : GLS_AA_EXACT;
    /* the default bounds a pixel's cost (exact.h GLS_EXACT_AUTO_DENSE):
     * one where more triangles may show is point-sampled; coverage and
     * edge segments need every area, --aa exact asks for them all */
    aa->dense = aa->exact && !(outputs & GLS_OUT_EXACT_ONLY) ? GLS_EXACT_AUTO_DENSE : 0;
}

int play_aa_choose(gls_play_opts *o, gls_aa_plan *plan, const gls_scene *s, const gls_camera *cams,
                   const char *const *names, FILE *errs)
{
    size_t cam;
    int moving = o->trajectory || o->nmotions;
    const char *why = o->aa.exact ? gls_play_exact_blocker(&o->aa, s, cams, o->ncameras, moving, &cam) : NULL;
    if (o->aa.exact == GLS_AA_EXACT && why) {
        if (cam == SIZE_MAX)
            fprintf(errs, "glsplay: error: %s: --aa exact does not draw %s; leave out --aa exact (sampled "
                          "anti-aliasing draws it)\n", o->bundle, why);
        else
            fprintf(errs, "glsplay: error: camera %s: --aa exact needs a pinhole camera without %s; leave out "
                          "--aa exact (sampled anti-aliasing draws it) or those keys\n", names[cam], why);
        return 1;
    }
    if (o->aa.exact == GLS_AA_AUTO) {
        o->aa_auto = 1;
        gls_play_aa_auto(&o->aa, why, o->outputs);
        if (why && cam != SIZE_MAX)
            snprintf(o->aa_auto_why, sizeof o->aa_auto_why, "camera %s's %s", names[cam], why);
        else if (why)
            snprintf(o->aa_auto_why, sizeof o->aa_auto_why, "%s", why);
        if (why && (o->outputs & GLS_OUT_EXACT_ONLY)) {
            fprintf(errs, "glsplay: error: --outputs %s needs exact coverage, which does not draw %s; leave out %s\n",
                    GLS_OUT_EXACT_WORD(o->outputs), o->aa_auto_why, GLS_OUT_EXACT_WORD(o->outputs));
            return 1;
        }
    }
    plan->o.exact = o->aa.exact, plan->o.dense = o->aa.dense;
    /* alpha-tested triangles are point-sampled in the image (exact.h
     * GLS_EXACT_HOLES): their areas are not exact, so nothing reports them */
    if (o->aa.exact && (s->features & GLS_FEAT_ALPHA_TEST) && (o->outputs & GLS_OUT_EXACT_ONLY)) {
        fprintf(errs, "glsplay: error: %s: --outputs %s needs exact areas, and the scene has textures with "
                      "transparent texels (alpha-tested, sampled in the image); leave out %s\n", o->bundle,
                GLS_OUT_EXACT_WORD(o->outputs), GLS_OUT_EXACT_WORD(o->outputs));
        return 1;
    }
    return 0;
}
