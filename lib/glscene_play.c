/* glsplay's whole job as library calls (include/glscene.h, "The player's
 * full options"): a run takes glsplay's command-line arguments one at a
 * time (glscene_play_args.c), checks them against each other, and
 * renders and writes what they ask for through the runtime's player
 * (runtime/play/player.c).  glsplay's main is these calls and its help
 * text, nothing else, so that the tool and a program driving the library
 * share one parser and one set of messages
 * (tests/e2e/glsplay_public_api.sh checks that glsplay_main.o reaches the
 * renderer through glscene_* alone). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "glscene_internal.h"
#include "glscene_play_run.h"

int gls_play_fail(glscene_play *r, glscene_error *e, int rc, const char *fmt, ...)
{
    va_list ap, ap2;
    va_start(ap, fmt);
    va_copy(ap2, ap);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    free(r->msg);
    r->msg = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (r->msg)
        vsnprintf(r->msg, (size_t)n + 1, fmt, ap2);
    va_end(ap2);
    if (e)
        snprintf(e->message, sizeof e->message, "%s", r->msg ? r->msg : "out of memory");
    return rc;
}

char *gls_play_keep(glscene_play *r, glscene_error *e, const char *s)
{
    char *c = NULL;
    if (gls_grow(&r->strs, &r->strs_cap, r->nstrs + 1, sizeof *r->strs) == 0 && (c = strdup(s)))
        r->strs[r->nstrs++] = c;
    if (!c)
        gls_play_fail(r, e, -2, "out of memory");
    return c;
}

void gls_play_close_run(glscene_play *r)
{
    gls_play_end(r->run, 0);
    r->run = NULL;
}

glscene_play *glscene_play_new(void)
{
    glscene_play *r = calloc(1, sizeof *r);
    if (!r)
        return NULL;
    gls_play_opts *o = &r->o;
    o->frame_end = UINT64_MAX;
    o->writer_threads = 1;
    o->outputs = GLS_OUT_IMAGE | GLS_OUT_DEPTH | GLS_OUT_POINTS;
    o->aa = gls_aa_defaults();
    o->aa.exact = GLS_AA_AUTO; /* exact where the run allows it (play_aa.c) */
    o->progress = GLS_PROGRESS_OFF;
    return r;
}

void glscene_play_free(glscene_play *r)
{
    if (!r)
        return;
    gls_play_close_run(r); /* before the strings its options name */
    for (size_t i = 0; i < r->nstrs; i++)
        free(r->strs[i]);
    free(r->strs);
    free(r->cams);
    free(r->texts);
    free(r->mots);
    free(r->msg);
    free(r);
}

const char *glscene_play_message(const glscene_play *r)
{
    return r && r->msg ? r->msg : "";
}

int glscene_play_check(glscene_play *r, glscene_error *e)
{
    if (!r)
        return gls_api_fail(e, "glscene_play_check: a NULL run");
    gls_play_opts *o = &r->o;
    if (r->have_aa + r->have_samples + (r->subpixel > 0) > 1) {
        return gls_play_fail(r, e, -1, "--aa, --samples and --subpixel all choose the samples; give one");
    }
    /* exact coverage is the box filter's value, with no samples */
    if (o->aa.exact == GLS_AA_EXACT && o->aa.filter != GLS_AA_BOX)
        return gls_play_fail(r, e, -1, "--aa exact is the box filter's exact value; leave out --filter gauss");
    if ((o->outputs & GLS_OUT_EXACT_ONLY) && !o->aa.exact)
        return gls_play_fail(r, e, -1, "--outputs %s needs --aa exact (exact areas, no samples)",
                             GLS_OUT_EXACT_WORD(o->outputs));
    if (r->have_samples && o->aa.pattern != GLS_AA_LATTICE) {
        unsigned long long root = (unsigned long long)sqrt((double)o->aa.samples);
        if (root * root != o->aa.samples) {
            char m[32];
            snprintf(m, sizeof m, "%llu", (unsigned long long)o->aa.samples);
            return gls_play_fail(r, e, -1, o->aa.pattern == GLS_AA_GRID
                                 ? "--pattern grid needs a square --samples (N x N), got %s; the lattice takes any M"
                                 : "--pattern stratified needs a square --samples (N x N), got %s; the lattice takes any M",
                             m);
        }
    }
    if (r->subpixel > 0) {
        o->aa.exact = GLS_AA_SAMPLED;
        o->aa.n = gls_aa_n_for_accuracy(o->aa.filter, o->aa.pattern, o->aa.sigma, r->subpixel);
        if (!o->aa.n)
            return gls_play_fail(r, e, -1, "--subpixel given needs a window larger than 4096x4096");
    }
    /* one sample per pixel: no pixel is mixed, the map would be all 0 */
    if ((o->outputs & GLS_OUT_EDGE_MAPS) && (o->aa.samples ? o->aa.samples : (uint64_t)o->aa.n * o->aa.n) <= 1)
        return gls_play_fail(r, e, -1, "--outputs %s needs anti-aliasing, --aa N with N > 1",
                         o->outputs & GLS_OUT_EDGES ? "edges" : "mask");
    if (!o->bundle)
        return gls_play_fail(r, e, -1, "no bundle given");
    /* the flattened path inlines every call: there is no instance to move */
    if (o->flatten && o->nmotions) {
        return gls_play_fail(r, e, -1, "--motion moves instances, and --flatten draws none; leave out --flatten");
    }
    /* flow goes from each frame of a trajectory to the next */
    if ((o->outputs & GLS_OUT_FLOW_ALL) && !o->trajectory)
        return gls_play_fail(r, e, -1, "--outputs flow needs a --trajectory: the flow goes from each frame to the next");
    if (r->frames && !o->trajectory) {
        return gls_play_fail(r, e, -1, "--frames selects frames of a --trajectory; for a single render use --frame N");
    }
    if (!o->explain && !o->outdir && !r->rendering)
        return gls_play_fail(r, e, -1, "no output directory given (-o OUTDIR), and no --explain");
    if (o->write_calib && !o->outdir)
        return gls_play_fail(r, e, -1, "--write-calib writes into the output directory: give -o OUTDIR");
    if ((o->outdir || r->rendering) && o->ncameras == 0)
        return gls_play_fail(r, e, -1, "no camera given (--camera CAM)");
    /* what the runtime refuses from the options alone (two cameras for
       disparity, their output names, ...): usage errors too */
    char msg[2048];
    if (gls_play_check_options(o, msg, sizeof msg))
        return gls_play_fail(r, e, -1, "%s", msg);
    r->checked = 1;
    return 0;
}

gls_play_opts *gls_api_play_opts(glscene_play *r)
{
    return &r->o;
}

int glscene_play_run(glscene_play *r, FILE *out, FILE *errs)
{
    if (!r || !out || !errs)
        return 2; /* nowhere to say why */
    if (!r->checked && glscene_play_check(r, NULL)) {
        fprintf(errs, "glsplay: error: %s\n", glscene_play_message(r));
        return 2;
    }
    if (r->o.outputs & GLS_OUT_EDGES_AS_MASK)
        fprintf(errs, "glsplay: note: --outputs mask is now called edges (the word mask will mean object masks); "
                      "mask_F.png is written as before\n");
    return gls_play(&r->o, out, errs);
}

int glscene_play_camera_text(glscene_play *r, const char *name, const char *text, glscene_error *e)
{
    if (!r || !name || !text)
        return gls_api_fail(e, "glscene_play_camera_text: a NULL run, name or text");
    if (!name[0])
        return gls_play_fail(r, e, -1, "a camera's text needs a name");
    r->checked = 0;
    gls_play_close_run(r); /* another camera: the open run has not got it */
    return gls_play_add_camera(r, e, name, text) ? -1 : 0;
}
