/* The frame plan (frame_plan.h): every decision of what a camera frame
 * needs, in one place. */
#include <string.h>
#include "aa_onepass.h"
#include "distort.h"
#include "exact.h"
#include "frame_plan.h"
#include "units.h"

const char *const gls_pass_word[GLS_PASS_COUNT] = {
#define X(id, word, what) word,
    GLS_PASSES(X)
#undef X
};
const char *const gls_pass_what[GLS_PASS_COUNT] = {
#define X(id, word, what) what,
    GLS_PASSES(X)
#undef X
};
const char *const gls_buffer_word[GLS_BUF_COUNT] = {
#define X(id, word, what) word,
    GLS_FRAME_BUFFERS(X)
#undef X
};

/* Which passes run and what they read back. */
static void plan_passes(gls_frame_plan *fp, const gls_plan_inputs *in, const gls_camera *c)
{
    unsigned out = fp->outputs, need = 0;
    for (int k = 0; k < GLS_OUT_KINDS; k++)
        if (out & gls_output_kinds[k].bit)
            need |= gls_output_kinds[k].needs;
    int colour = (need & GLS_NEED_COLOUR) != 0;
    fp->ex = gls_exposure_of(c, in->moving);
    fp->effects = gls_exposure_on(&fp->ex) && colour;
    fp->cover = in->aa->o.exact && (need & GLS_NEED_COVER);
    fp->segs = in->aa->o.exact && (need & GLS_NEED_SEGS);
    fp->exact = in->aa->o.exact && (colour || fp->cover || fp->segs);
    fp->aa = (in->aa->count > 1 || fp->effects) && colour && !fp->exact;
    fp->lens = gls_distort_on(c);
    fp->weighted = gls_aa_weighted(in->aa);
    fp->fine = gls_aa_fine_ok(in->aa);
    /* the centre pass: the image when it is not anti-aliased, and what
     * comes from the geometry at each pixel centre, never averaged across
     * an edge (depth, points and their colours, disparity, landmarks) */
    fp->rgba = (!fp->aa && !(fp->exact && colour) && colour) || (need & GLS_NEED_RGBA);
    fp->z = (need & GLS_NEED_Z) != 0;
    fp->flow = (need & GLS_NEED_NEXT) != 0;
    fp->boxes = (need & GLS_NEED_ALONE) != 0;
    fp->ids = (need & GLS_NEED_IDS) != 0;
    fp->normals = (need & GLS_NEED_NORMALS) != 0;
    fp->truth_z = fp->flow;
    if (fp->rgba || fp->z)
        fp->passes |= GLS_PASS_CENTRE;
    if (fp->ids || fp->normals || fp->truth_z)
        fp->passes |= GLS_PASS_TRUTH;
    /* a rolling shutter draws the centre and truth passes in bands of
     * rows, each at its time; how many is chosen per frame from the
     * scene's motion (exposure.h), so the plan has no count of them */
    if (fp->aa)
        fp->passes |= fp->effects ? GLS_PASS_EXPOSURE : GLS_PASS_SAMPLES;
    if (fp->exact)
        fp->passes |= GLS_PASS_EXACT;
    if (fp->lens && (fp->passes & (GLS_PASS_CENTRE | GLS_PASS_TRUTH | GLS_PASS_SAMPLES | GLS_PASS_EXPOSURE)))
        fp->passes |= GLS_PASS_LENS;
    if (fp->flow)
        fp->passes |= GLS_PASS_FLOW_NEXT;
    if (fp->boxes)
        fp->passes |= GLS_PASS_BOXES_ALONE;
    fp->gl = (fp->passes & ~(unsigned)GLS_PASS_EXACT) != 0 || fp->lens || fp->ex.rolling;
    if (!(out & GLS_OUT_IMAGE))
        fp->image = GLS_IMAGE_NONE;
    else if (c->sensor.on)
        fp->image = GLS_IMAGE_SENSOR;
    else if (fp->aa || fp->exact || in->image_format != GLS_IMG_PNG8)
        fp->image = GLS_IMAGE_CONVERTED;
    else
        fp->image = GLS_IMAGE_CENTRE;
}

/* The bytes a pixel of the image file takes in its format (RGBA8 for an
 * 8-bit PNG; one sample a pixel under a Bayer mosaic). */
static uint64_t image_bytes(const gls_frame_plan *fp, const gls_plan_inputs *in, const gls_camera *c)
{
    uint64_t px = in->image_format == GLS_IMG_PFM ? 12 : in->image_format == GLS_IMG_PNG16 ? 6 : 4;
    if (fp->image == GLS_IMAGE_SENSOR && c->sensor.bayer[0])
        px = in->image_format == GLS_IMG_PNG8 ? 1 : px / 3;
    return fp->image == GLS_IMAGE_CENTRE || fp->image == GLS_IMAGE_NONE ? 0 : px;
}

/* Each buffer's size for an n-pixel frame. */
static void plan_buffers(gls_frame_plan *fp, const gls_plan_inputs *in, const gls_camera *c)
{
    uint64_t n = (uint64_t)c->width * c->height, *b = fp->bytes, enc = 0;
    unsigned out = fp->outputs;
    b[GLS_BUF_RGBA] = fp->rgba ? 4 * n : 0;
    b[GLS_BUF_DEPTH] = fp->z ? 4 * n : 0;
    b[GLS_BUF_IDS] = fp->ids ? 4 * n : 0;
    b[GLS_BUF_NORMALS] = fp->normals ? 12 * n : 0;
    b[GLS_BUF_TRUTH_DEPTH] = fp->truth_z ? 4 * n : 0;
    b[GLS_BUF_ACCUM] = fp->aa ? (fp->weighted ? 32 : 16) * n + (uint64_t)c->width * 4 * (fp->weighted ? 8 : 2) : 0;
    b[GLS_BUF_EXACT] = fp->exact && (fp->outputs & GLS_OUT_IMAGE) ? 16 * n : 0;
    b[GLS_BUF_COVER] = fp->cover ? 8 * GLS_EXACT_COVER_K * n : 0;
    b[GLS_BUF_MIXED] = fp->aa && (out & GLS_OUT_EDGE_MAPS) ? 5 * n : 0; /* GLS_NEED_MIXED */
    b[GLS_BUF_IMAGE] = image_bytes(fp, in, c) * n;
    /* the sensor's linear intensities: a buffer of their own under a
     * photometric effect, but for a float image, which they become */
    b[GLS_BUF_LINEAR] = fp->image == GLS_IMAGE_SENSOR && (c->sensor.on & ~GLS_SENSOR_BAYER) &&
                                in->image_format != GLS_IMG_PFM ? 12 * n : 0;
    b[GLS_BUF_EDGES] = (out & GLS_OUT_EDGE_MAPS) ? n : 0;
    b[GLS_BUF_FLOW] = fp->flow ? 13 * n : 0;
    b[GLS_BUF_DISPARITY] = (out & GLS_OUT_DISPARITIES) ? 4 * n : 0;
    b[GLS_BUF_CODES16] = (out & (GLS_OUT_DISPARITY16 | GLS_OUT_DEPTH16)) ? 2 * n : 0;
    /* the largest file in encoding: points (x y z double, r g b), the
     * 16-bit id image or COCO's runs, normals, the .flo, the image, a
     * float depth */
    uint64_t cand[] = {(out & GLS_OUT_POINTS) ? 27 * n : 0, (out & (GLS_OUT_IDS | GLS_OUT_BOXES_ALL)) || fp->flow ? 16 * n : 0,
                       fp->normals ? 12 * n : 0, fp->flow ? 8 * n : 0, b[GLS_BUF_IMAGE] ? b[GLS_BUF_IMAGE] : b[GLS_BUF_RGBA],
                       fp->z ? 4 * n : 0};
    for (size_t k = 0; k < sizeof cand / sizeof cand[0]; k++)
        if (cand[k] > enc)
            enc = cand[k];
    b[GLS_BUF_ENCODE] = enc;
    fp->total = 0;
    for (int k = 0; k < GLS_BUF_COUNT; k++)
        fp->total += b[k];
}

void gls_frame_plan_make(gls_frame_plan *fp, const gls_plan_inputs *in, const gls_camera *c, int has_next)
{
    memset(fp, 0, sizeof *fp);
    unsigned out = gls_outputs_with(in->outputs);
    fp->outputs = has_next ? out : out & ~(unsigned)GLS_OUT_FLOW_ALL;
    plan_passes(fp, in, c);
    plan_buffers(fp, in, c);
}

void gls_frame_plan_explain(FILE *out, const gls_frame_plan *fp, const gls_aa_plan *aa)
{
    fprintf(out, "  frame plan: passes");
    for (int k = 0; k < GLS_PASS_COUNT; k++)
        if (fp->passes & (1u << k))
            fprintf(out, " %s", gls_pass_word[k]);
    fprintf(out, "%s\n", fp->passes ? "" : " none");
    if (fp->exact)
        fprintf(out, "  exact coverage: each pixel the exact areas of what is visible in it (box filter, double "
                     "precision, CPU); no samples, no accumulator%s\n",
                fp->gl ? "" : "; no GL pass (a run whose frames all need none creates no GL context and uploads "
                              "nothing)");
    else if (!fp->aa)
        fprintf(out, "  passes: 1 per camera and frame (no anti-aliasing), jitter (0, 0); no accumulator\n");
    else
        fprintf(out, "  accumulator: %llu samples per pixel (%s)\n",
                (unsigned long long)(aa->count * (fp->effects ? fp->ex.samples : 1)),
                fp->effects ? "anti-aliasing samples x sub-frame renders" : "anti-aliasing samples");
    char b[32];
    fprintf(out, "  buffers:");
    int any = 0;
    for (int k = 0; k < GLS_BUF_COUNT; k++)
        if (fp->bytes[k]) {
            gls_fmt_bytes(b, sizeof b, fp->bytes[k]);
            fprintf(out, "%s %s %s", any ? "," : "", gls_buffer_word[k], b);
            any = 1;
        }
    gls_fmt_bytes(b, sizeof b, fp->total);
    fprintf(out, "%s; %s in all (%llu bytes, %llu of them the writer's)\n", any ? "" : " none", b,
            (unsigned long long)fp->total,
            (unsigned long long)(fp->bytes[GLS_BUF_DISPARITY] + fp->bytes[GLS_BUF_CODES16] + fp->bytes[GLS_BUF_ENCODE]));
}
