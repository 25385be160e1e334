/* glsplay --explain: the rendering plan, derived from the bundle's
 * feature bits (which the reader has checked against the content). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"
#include "sensor.h"
#include "aa_onepass.h"
#include "aa_render.h"
#include "distort.h"
#include "distort_render.h"
#include "lens_truth.h"
#include "distort_exposure.h"
#include "exposure.h"
#include "lighting.h"
#include "shadows.h"
#include "out_disparity.h"
#include "units.h"
#include "player.h"
#include "occlusion.h"
#include "scene_cull.h"
#include "frame_writer.h"
#include "outputs.h"
#include "frame_plan.h"

/* The GL effect each feature switches on, by feature bit; the asserts keep
 * the indices in step with bundle.h. */
_Static_assert(GLS_FEAT_TEXTURES == 1u << 0 && GLS_FEAT_ALPHA_TEST == 1u << 1 &&
                   GLS_FEAT_VERTEX_COLOR == 1u << 2 && GLS_FEAT_TEXCOORDS == 1u << 3 &&
                   GLS_FEAT_HOMOGENEOUS == 1u << 4 && GLS_FEAT_MODULATE == 1u << 5 &&
                   GLS_FEAT_REPLACE == 1u << 6 && GLS_FEAT_TRANSLUCENT == 1u << 7 &&
                   GLS_FEAT_MARKS == 1u << 8 && GLS_FEAT_LIGHTS == 1u << 9 && GLS_FEAT_SHADOWS == 1u << 10,
               "feature bits moved: update effect[]");
static const char *const effect[32] = {
    [0] = "GL_TEXTURE_2D, RGBA8 textures with mipmaps (GL_LINEAR_MIPMAP_LINEAR)",
    [1] = "GL_ALPHA_TEST, glAlphaFunc(GL_GEQUAL, 0.5): texels with alpha 0 are holes",
    [2] = "GL_COLOR_ARRAY (RGBA8 per vertex); otherwise one glColor per batch",
    [3] = "GL_TEXTURE_COORD_ARRAY (float s, t); otherwise texcoord (0, 0)",
    [4] = "none: positions are divided by w in double at load",
    [5] = "glTexEnv GL_MODULATE (texture times colour)",
    [6] = "glTexEnv GL_REPLACE (texture colour only)",
    [7] = "none: alpha is not blended, surfaces are drawn opaque (outputs are RGB)",
    [8] = "none: landmarks draw nothing (--outputs landmarks lists them)",
    [9] = "a GLSL program (Lambert + Phong per pixel) in every colour pass; normals and specular state per vertex",
    [10] = "a depth texture per directional light, a depth cube map per point light, drawn before each colour pass",
};

/* The backend asked for and what it gave (spec/backends.md). */
static void explain_backend(FILE *out, const gls_play_opts *o, const gls_glctx *ctx)
{
    const gls_glctx_info *gi = gls_glctx_describe(ctx);
    fprintf(out, "backend: %s (--backend %s", gi->backend, gls_backend_name(o->backend));
    if (gi->fallback[0])
        fprintf(out, "; EGL gave no context: %s", gi->fallback);
    else if (o->backend == GLS_BACKEND_AUTO)
        fprintf(out, ": EGL first, OSMesa if EGL fails");
    fprintf(out, "), platform: %s, device: %s\n", gi->platform, gi->device);
    fprintf(out, "GL_RENDERER: %s; GL_VERSION: %s\n", gi->renderer, gi->version);
}

/* What occlusion culling (occlusion.h) does with camera c's first frame:
 * the plan only; what the queries hide is known when GL has drawn. */
static void explain_occlusion(FILE *out, gls_occlusion *occ, const gls_scene *s, const gls_camera *c,
                              const uint8_t *vis, const gls_play_opts *o)
{
    double C[3];
    gls_camera_centre(c, C);
    if (o->occlusion == GLS_OCCLUSION_OFF) {
        fprintf(out, "    occlusion culling: off (--occlusion off)\n");
        return;
    }
    int rc = gls_occlusion_plan(occ, (gls_occlusion_mode)o->occlusion, s, c, C, vis);
    if (rc > 0) {
        uint32_t first = 0;
        for (uint32_t i = 0; i < s->nitems; i++)
            first += occ->occluder[i];
        fprintf(out, "    occlusion culling: %u units tested in occlusion queries (%u triangles of their test boxes' "
                     "front faces), nearest first, after %u draw items drawn untested (boxes over the image %.1f "
                     "times, the geometry %.1f by the model)\n",
                occ->ntested, occ->box_verts / 3, first, occ->overdraw, occ->depth);
    } else if (rc == 0) {
        fprintf(out, "    occlusion culling: not used (%s%s; boxes over the image %.1f times, the geometry %.1f by the "
                     "model, %u boxes, %llu vertices; auto needs %.0f, %.0f, %u and %u)\n",
                o->occlusion == GLS_OCCLUSION_AUTO ? "auto" : "nothing to test",
                o->occlusion == GLS_OCCLUSION_AUTO ? ", too little to gain" : "", occ->overdraw, occ->depth,
                occ->nunits, (unsigned long long)occ->total_verts, GLS_OCCLUSION_MIN_OVERDRAW,
                GLS_OCCLUSION_MIN_DEPTH, GLS_OCCLUSION_MIN_UNITS, GLS_OCCLUSION_MIN_VERTS);
    } else {
        fprintf(out, "    occlusion culling: out of memory, not used\n");
    }
}

/* Instances, their memory, and what each camera culls in its first
 * frame (cams are posed for it: with a trajectory, its first frame). */
static void explain_instances(FILE *out, const gls_scene *s, const gls_camera *cams, const char *const *names,
                              size_t n, const gls_play_opts *o)
{
    uint64_t geo, table;
    char g[32], tb[32];
    gls_scene_memory(s, &geo, &table);
    gls_fmt_bytes(g, sizeof g, geo);
    gls_fmt_bytes(tb, sizeof tb, table);
    uint32_t drawing = 0;
    for (uint32_t i = 0; i < s->ninst; i++)
        drawing += s->inst[i].nitems > 0;
    fprintf(out, "instances: %u (%u with geometry of their own, %u protos, %u draw items)%s; memory: unique geometry %s, "
                 "instance table %s\n", s->ninst, drawing, s->nprotos, s->nitems,
            o->flatten ? ", every call inlined (--flatten)" : "", g, tb);
    uint8_t *ivis = malloc(s->ninst ? s->ninst : 1), *vis = malloc(s->nitems ? s->nitems : 1);
    gls_occlusion occ;
    memset(&occ, 0, sizeof occ);
    for (size_t k = 0; ivis && vis && k < n; k++) {
        gls_cull_stats st;
        gls_scene_cull(s, &cams[k], ivis, vis, &st);
        fprintf(out, "  camera %s, first frame: %u instances drawn, %u culled (outside the view); %u of %u items drawn\n",
                names[k], st.drawn, st.culled, st.items_drawn, s->nitems);
        explain_occlusion(out, &occ, s, &cams[k], vis, o);
    }
    free(ivis);
    free(vis);
    gls_occlusion_free(&occ);
}

/* One line for disparity, disparity16 and depth16 when asked (what they
 * are made of and that they cost no extra pass); aa: the image is
 * anti-aliased (the depth then comes from the centre pass). */
static void explain_depth_outputs(FILE *out, const gls_play_opts *o, int aa)
{
    unsigned u = o->outputs;
    if (!(u & (GLS_OUT_DISPARITIES | GLS_OUT_DEPTH16)))
        return;
    char scale[32];
    gls_fmt_double(scale, sizeof scale, o->depth_scale > 0 ? o->depth_scale : GLS_DEPTH_SCALE_KITTI);
    fprintf(out, "  writes:%s%s%s%s%s from the %s's depth: no extra pass\n",
            u & GLS_OUT_DISPARITY ? (o->float_format == GLS_FLOAT_NPY ? " disparity (NPY, fx B / Zc)"
                                                                      : " disparity (PFM, fx B / Zc)")
                                  : "",
            u & GLS_OUT_DISPARITY16 ? " disparity16 (KITTI 16-bit PNG, d * 256)" : "",
            u & GLS_OUT_DEPTH16 ? " depth16 (16-bit PNG, Zc * " : "", u & GLS_OUT_DEPTH16 ? scale : "",
            u & GLS_OUT_DEPTH16 ? ")" : "", aa ? "unjittered centre pass" : "pass");
}

/* The files, the state always on, and each feature of the bundle with
 * the GL state it switches on. */
static void explain_features(FILE *out, const gls_bundle *b, const gls_scene *s, const gls_play_opts *o)
{
    if (o->writer_threads)
        fprintf(out, "files: PNG by %s; each frame's files encoded and written on a thread of their own while the "
                     "next frame renders (--writer-threads 1), at most %d frames pending\n",
                gls_png_encoding(), GLS_WRITER_DEPTH);
    else
        fprintf(out, "files: PNG by %s; each frame's files encoded and written before the next frame renders "
                     "(--writer-threads 0)\n", gls_png_encoding());
    fprintf(out, "always on: reversed-Z depth test (GL_DEPTH_COMPONENT32F, cleared to 0, GL_GREATER, "
                 "glClipControl GL_ZERO_TO_ONE); FBO with RGBA8 colour; clear colour black\n");
    fprintf(out, "features (bundle bits %#x):\n", b->features);
    for (unsigned bit = 0; bit < 32; bit++) {
        if (!gls_feature_name[bit])
            continue;
        int on = (b->features >> bit) & 1u;
        fprintf(out, "  %-14s %-3s %s\n", gls_feature_name[bit], on ? "on" : "off",
                on ? gls_feature_why[bit] : "not used by this bundle");
        if (on && effect[bit])
            fprintf(out, "  %-14s     GL: %s\n", "", effect[bit]);
        if (on && bit == 9)
            gls_lighting_explain(out, b, s);
        if (on && bit == 10)
            gls_shadows_explain(out, s);
        if (on && bit == 0) {
            if (o->anisotropy > 1)
                fprintf(out, "  %-14s     GL: anisotropic filtering up to %ux (--anisotropic %u)\n", "",
                        o->anisotropy, o->anisotropy);
            else
                fprintf(out, "  %-14s     GL: anisotropic filtering off (--anisotropic N turns it on; slow "
                             "on llvmpipe)\n", "");
        }
    }
}

/* The anti-aliasing pattern, when --aa asks for one and an output is
 * drawn with it (whether a camera's frame uses an accumulator is its
 * frame plan's: exposure effects need one even at --aa 1). */
static void explain_aa(FILE *out, const gls_aa_plan *pp, const gls_play_opts *o)
{
    const gls_aa_plan p = *pp;
    {
        if (p.o.n)
            fprintf(out, "anti-aliasing: %ux%u = %llu samples per pixel, %s filter", p.o.n, p.o.n,
                    (unsigned long long)p.m, p.o.filter == GLS_AA_BOX ? "box" : "Gaussian");
        else
            fprintf(out, "anti-aliasing: %llu samples per pixel, %s filter", (unsigned long long)p.m,
                    p.o.filter == GLS_AA_BOX ? "box" : "Gaussian");
        if (p.o.filter == GLS_AA_GAUSS)
            fprintf(out, " (sigma %g px, window +-%g sigma)", p.o.sigma, GLS_AA_GAUSS_SPAN);
        if (p.o.pattern == GLS_AA_LATTICE) {
            /* the criterion's keys (lattice.c): the closest distance, then
             * the points per position across axis and diagonal edges */
            fprintf(out, ", lattice pattern: generator a = %llu, closest samples %.4f px apart; samples a position "
                         "across 0, 45 and 135 degree edges: %llu, %llu and %llu (gcd(a, M), gcd(a - 1, M), "
                         "gcd(a + 1, M); positions g/%llu px apart)",
                    (unsigned long long)p.lat.a, p.lat.mindist, (unsigned long long)p.lat.g0,
                    (unsigned long long)p.lat.g45, (unsigned long long)p.lat.g135, (unsigned long long)p.m);
            if (gls_aa_weighted(&p))
                fprintf(out, ", %llu of them in the cells -%u..%u around the pixel (those outside the window weigh 0)",
                        (unsigned long long)p.count, p.radius, p.radius);
            fprintf(out, "\n");
        } else {
            fprintf(out, ", %s offsets", p.o.pattern == GLS_AA_GRID ? "grid" : "stratified");
            if (p.o.pattern == GLS_AA_STRATIFIED)
                fprintf(out, " (seed %llu)", (unsigned long long)p.o.seed);
            fprintf(out, ", step %.6g px\n", p.span / p.o.n);
        }
        fprintf(out, "  accumulator: %s, exact (no rounding until the one final division)\n",
                gls_aa_weighted(&p) ? "uint64 per channel, integer weights summing to ~2^52"
                                    : "uint32 per channel, unit weights");
        if (gls_aa_fine_ok(&p))
            fprintf(out, "  passes: one fine framebuffer whose pixel centres are the samples, drawn in tiles "
                         "(geometry culled per tile), read back (RGBA8) and gathered; whether an unjittered centre "
                         "pass is drawn too: each camera's frame plan\n");
        else
            fprintf(out, "  passes: samples drawn %s per GL pass (a mosaic of jittered viewports, one clear, "
                         "one read-back of colour only); whether an unjittered centre pass is drawn too: each "
                         "camera's frame plan\n",
                    o->aa_tiles ? "a fixed number" : "several");
    }
}

/* Exact coverage or samples, and for --aa auto (the default) why
 * (play_aa.c chose before this is printed): a line when an image or
 * exact coverage's outputs are asked for. */
static void explain_aa_choice(FILE *out, const gls_play_opts *o)
{
    if (!(o->outputs & (GLS_OUT_IMAGE | GLS_OUT_EXACT_ONLY)))
        return;
    if (o->aa.exact)
        fprintf(out, "anti-aliasing: exact coverage%s: each pixel the exact visible areas times their colours, "
                     "in double on the CPU, no samples\n", o->aa_auto ? " (--aa auto, the default)" : " (--aa exact)");
    else if (o->aa_auto)
        fprintf(out, "anti-aliasing: one sample a pixel, as --aa 1 (--aa auto, the default, chose samples: exact "
                     "coverage does not draw %s)\n", o->aa_auto_why);
}

/* Camera c's anti-aliasing: the fine framebuffer's passes and tiles, or
 * the jittered passes' mosaic, and what each reads back. */
static void explain_camera_aa(FILE *out, const gls_camera *c, const gls_play_opts *o, const gls_aa_plan *pp, int aa)
{
    const gls_aa_plan p = *pp;
    char err[128];
    gls_aa_fine_layout lay;
    gls_aa_fine_opts fo = {o->aa_memory, 0, 0, NULL, NULL, NULL, NULL};
    if (aa && p.count > 1 && gls_aa_fine_ok(&p) && gls_aa_fine_plan(&p, c->width, c->height, 0, &fo, &lay, err, sizeof err) == 0) {
        char mem[32], budget[32];
        gls_fmt_bytes(mem, sizeof mem, lay.bytes);
        gls_fmt_bytes(budget, sizeof budget, o->aa_memory ? o->aa_memory : GLS_AA_DEFAULT_MEMORY);
        fprintf(out, "  anti-aliasing: %llu pass%s of %llu sample%s per pixel; fine framebuffer %lldx%lld "
                     "(A = [%lld %lld; %lld %lld]: image pixel (1, 0) -> (%lld, %lld) fine pixels)\n",
                (unsigned long long)lay.f.k, lay.f.k == 1 ? "" : "es", (unsigned long long)lay.f.l,
                lay.f.l == 1 ? "" : "s",
                (long long)lay.fw, (long long)lay.fh, (long long)lay.f.a[0][0], (long long)lay.f.a[0][1],
                (long long)lay.f.a[1][0], (long long)lay.f.a[1][1], (long long)lay.f.a[0][0],
                (long long)lay.f.a[1][0]);
        fprintf(out, "  tiles: %llu per pass of %ux%u (at most; those no pixel needs are skipped), %s of "
                     "framebuffer and read-backs (--aa-memory %s); %llu gather entries per pixel and pass\n",
                (unsigned long long)lay.tiles, lay.tw, lay.th, mem, budget, (unsigned long long)lay.kernel);
        fprintf(out, "  reads back: colour (RGBA8) per tile\n");
    } else if (aa && p.count > 1) {
        uint32_t kx, ky;
        gls_aa_mosaic_shape(NULL, c->width, c->height, p.count, o->aa_tiles, &kx, &ky);
        fprintf(out, "  anti-aliasing: %llu samples in %llu passes of %ux%u tiles (%ux%u framebuffer)\n",
                (unsigned long long)p.count, (unsigned long long)((p.count + kx * ky - 1) / (kx * ky)), kx, ky,
                kx * c->width, ky * c->height);
        fprintf(out, "  reads back: colour (RGBA8) per anti-aliasing pass\n");
    }
}

/* Each file camera c's frame plan writes, by the output table's rows
 * (output_table.h): "  files: image_F.png (the image), depth_F.pfm (Zc,
 * float32), ..." (F: the frame number). */
static void explain_files(FILE *out, const gls_frame_plan *fp, const gls_play_opts *o)
{
    const char *fl = o->float_format == GLS_FLOAT_NPY ? "npy" : "pfm";
    int any = 0;
    fprintf(out, "  files:");
    for (int k = 0; k < GLS_OUT_KINDS; k++) {
        const gls_output_kind *r = &gls_output_kinds[k];
        if (!(fp->outputs & r->bit))
            continue;
        const char *ext = !r->ext || (r->bit == GLS_OUT_IMAGE && o->image_format == GLS_IMG_PFM) ? fl : r->ext;
        fprintf(out, "%s %s_F.%s (%s)", any ? "," : "", r->stem, ext, r->what);
        any = 1;
    }
    fprintf(out, "%s\n", any ? "" : " none");
}

/* What camera c's passes read back and its files hold. */
static void explain_camera_writes(FILE *out, const gls_scene *s, const gls_camera *c, const gls_play_opts *o,
                                  const gls_frame_plan *fpp, int aa, int centre)
{
    const gls_frame_plan fp = *fpp;
    unsigned outputs = o->outputs;
    explain_files(out, &fp, o);
    int npy = o->float_format == GLS_FLOAT_NPY;
    static const char *const fmt_name[] = {"8-bit PNG", "16-bit PNG", "float32 PFM (PF, RGB)"};
    if (centre)
        fprintf(out, "  reads back%s: %s%s\n", aa ? " (unjittered centre pass)" : "",
                fp.rgba ? "colour (RGBA8) " : "", fp.z ? "depth (float32) " : "");
    fprintf(out, "  writes:%s%s%s%s%s\n", outputs & GLS_OUT_IMAGE ? " image (" : "",
            outputs & GLS_OUT_IMAGE ? (npy && o->image_format == GLS_IMG_PFM ? "float32 NPY (H, W, 3)"
                                                                             : fmt_name[o->image_format])
                                    : "",
            outputs & GLS_OUT_IMAGE ? ")" : "",
            outputs & GLS_OUT_DEPTH ? (npy ? " depth (NPY, Zc)" : " depth (PFM, Zc)") : "",
            outputs & GLS_OUT_POINTS ? " points (PLY, world, double)" : "");
    if (outputs & GLS_OUT_EDGE_MAPS)
        fprintf(out, "  writes: %s (8-bit PNG, 255 where the samples of a pixel differ)\n",
                outputs & GLS_OUT_EDGES ? "edges" : "mask");
    explain_depth_outputs(out, o, aa);
    gls_sensor_explain(out, &c->sensor, (uint64_t)c->width * c->height, (outputs & GLS_OUT_IMAGE) != 0);
    if (outputs & GLS_OUT_LANDMARKS)
        fprintf(out, "  writes: landmarks (CSV, %u per frame): the centre pass's depth, %s\n", s ? s->nmarks : 0,
                !aa || (outputs & (GLS_OUT_DEPTH | GLS_OUT_POINTS)) ? "no extra pass"
                                                                     : "one extra unjittered pass (--aa)");
    if (fp.passes & GLS_PASS_TRUTH) /* what the plan's truth pass reads back */
        fprintf(out, "  ground truth: one extra pass (%s%s%s%s)\n", fp.ids ? "instance ids" : "",
                fp.ids && fp.normals ? ", " : "", fp.normals ? "normals" : "", fp.truth_z ? ", depth of frame t" : "");
    if (outputs & GLS_OUT_FLOW_ALL)
        fprintf(out, "  flow: 1 more centre pass (the depth of frame t+1 with its poses); writes flow (KITTI "
                     "PNG), .flo, flowmask (PNG)\n");
    if (outputs & GLS_OUT_BOXES_ALL)
        fprintf(out, "  boxes: the ground-truth pass's instance ids and one pass per visible instance drawn "
                     "alone (its occlusion); writes boxes (KITTI labels, JSON)\n");
    if (gls_distort_on(c) && (outputs & GLS_OUT_FLOW_ALL))
        fprintf(out, "  lens: flow: the depth of frame t+1 drawn by the fine camera and read at each pixel "
                     "centre's ray; points projected by the %s model\n", gls_distort_model_name(&c->dist));
    if (gls_distort_on(c) && (outputs & GLS_OUT_BOXES_ALL))
        fprintf(out, "  lens: boxes: each instance drawn alone by the fine camera and read at each pixel "
                     "centre's ray; truncated from %d points an edge through the %s model\n",
                GLS_LENS_BOX_EDGE_STEPS + 1, gls_distort_model_name(&c->dist));
    if ((outputs & (GLS_OUT_FLOW_ALL | GLS_OUT_BOXES_ALL)) && fp.ex.rolling)
        fprintf(out, "  rolling shutter: %s%s%s\n",
                outputs & GLS_OUT_FLOW_ALL ? "flow from each row's time to the row of frame t+1 whose time sees "
                                             "the point (a fixed point, the poses of every row of frame t+1), the "
                                             "depth of frame t+1 in its bands of rows"
                                           : "",
                (outputs & GLS_OUT_FLOW_ALL) && (outputs & GLS_OUT_BOXES_ALL) ? "; " : "",
                outputs & GLS_OUT_BOXES_ALL ? "boxes' 2D boxes from the rolling instance image, their 3D boxes "
                                              "and occlusion passes at the frame time"
                                            : "");
    if ((outputs & (GLS_OUT_FLOW_ALL | GLS_OUT_BOXES_ALL)) && gls_distort_on(c) &&
        fp.ex.rolling)
        fprintf(out, "  lens with the rolling shutter: %s%s%s\n",
                outputs & GLS_OUT_FLOW_ALL ? "flow: each pixel's point on its centre's ray at its band's depth, "
                                             "the row of frame t+1 whose time sees it through the model at every "
                                             "row's pose, the depth of frame t+1 from one more ground-truth pass of "
                                             "the whole fine image per band, read at the pixel centres' rays"
                                           : "",
                (outputs & GLS_OUT_FLOW_ALL) && (outputs & GLS_OUT_BOXES_ALL) ? "; " : "",
                outputs & GLS_OUT_BOXES_ALL ? "boxes: 2D boxes from the rolling instance image through the lens, "
                                              "truncation and occlusion through the model at the frame time"
                                            : "");
}

/* Camera c: its model and pose, its effects, its frame plan, and what its
 * passes read back and its files hold. */
static void explain_camera(FILE *out, const gls_scene *s, const gls_camera *c, const char *name,
                           const gls_play_opts *o, const gls_aa_plan *pp)
{
    const gls_aa_plan p = *pp;
    unsigned outputs = o->outputs;
    int moving = o->trajectory || o->nmotions;
    gls_plan_inputs pin = {outputs, o->image_format, &p, moving};
    /* the first frame's plan, the one the player runs (frame_plan.h);
     * with a trajectory, taken to have a next row (flow) */
    gls_frame_plan fp;
    gls_frame_plan_make(&fp, &pin, c, o->trajectory != NULL);
    int aa = fp.aa, centre = (fp.passes & GLS_PASS_CENTRE) != 0;
    fprintf(out, "camera %s: %ux%u fx %g fy %g cx %g cy %g skew %g near %g far %g\n", name, c->width,
            c->height, c->fx, c->fy, c->cx, c->cy, c->skew, c->near, c->far);
    /* the frame R and T are in: declared by the file, or implied by
       --trajectory (spec/camera.md "The pose's frame") */
    if (o->trajectory)
        fprintf(out, "  pose: rig (%s): R and T map the rig into the camera, composed with each frame of %s\n",
                c->pose == GLS_POSE_RIG ? "declared by 'pose rig'" : "not declared; implied by --trajectory",
                o->trajectory);
    else
        fprintf(out, "  pose: world (%s): R and T map the world into the camera\n",
                c->pose == GLS_POSE_WORLD ? "declared by 'pose world'" : "not declared; the default without --trajectory");
    gls_distort_explain(out, c, &p);
    gls_exposure_explain(out, c, moving, &p, fp.effects);
    if (fp.effects)
        gls_distort_exposure_explain(out, c, moving, &p);
    gls_frame_plan_explain(out, &fp, &p);
    explain_camera_aa(out, c, o, &p, aa);
    explain_camera_writes(out, s, c, o, &fp, aa, centre);
}

void gls_explain(FILE *out, const char *bundle_path, const gls_bundle *b, const gls_scene *s,
                 const gls_camera *cams, const char *const *names, size_t n, const gls_play_opts *o,
                 const gls_glctx *ctx)
{
    unsigned outputs = o->outputs;
    gls_aa_opts ao = o->aa;
    if (ao.n == 0)
        ao.n = 1;
    gls_aa_plan p;
    char err[128];
    if (gls_aa_plan_init(&p, &ao, err, sizeof err))
        p.count = 1, p.o = ao, p.o.n = 1;
    int aa = p.count > 1 && (outputs & (GLS_OUT_IMAGE | GLS_OUT_EDGE_MAPS));
    fprintf(out, "plan for %s: top object '%s', %u objects, %u textures, %u positions\n", bundle_path,
            b->objects[b->top].name, b->nobjects, b->ntextures, b->npos);
    fprintf(out, "geometry: %u unique triangles in %u chunks (cells of %g units, double anchors), %u state batches",
            s->nverts / 3, s->nchunks, ldexp(GLS_SCENE_CELL, (int)s->cell_level), s->nbatches);
    if (s->dropped)
        fprintf(out, ", %llu triangles dropped (a vertex beyond 2^50 units from the origin, or at infinity)", (unsigned long long)s->dropped);
    fprintf(out, "\n");
    explain_instances(out, s, cams, names, n, o);
    explain_backend(out, o, ctx);
    explain_features(out, b, s, o);
    explain_aa_choice(out, o);
    if (aa)
        explain_aa(out, &p, o);
    if (!n) {
        fprintf(out, "cameras: none given\n");
        return;
    }
    for (size_t i = 0; i < n; i++)
        explain_camera(out, s, &cams[i], names[i], o, &p);
}
