/* One camera frame (play_int.h): its plan made, its buffers allocated,
 * then the plan's steps in order: the centre and ground-truth passes, the
 * anti-aliased colour, the image in its file's format, boxes and flow, and
 * the files handed to the writer. */
#include <stdlib.h>
#include <string.h>
#include "distort_exact.h"
#include "distort_exposure.h"
#include "exact_scene.h"
#include "exposure_landmarks.h"
#include "frame_files.h"
#include "frame_record.h"
#include "gt_pass.h"
#include "lens_truth.h"
#include "play_int.h"
#include "progress_line.h"
#include "sensor_image.h"

/* Say why a camera frame failed.  An earlier frame's files may still be
 * in the writer: if one of them failed, a run without the writer thread
 * would have stopped there, so that message is said instead of this one
 * (the same message whatever the thread's timing). */
static void say_failure(session *s, const char *msg)
{
    char earlier[1024];
    fprintf(s->errs, "%s\n", gls_writer_finish(s->w, earlier, sizeof earlier) ? earlier : msg);
}

/* malloc for buffer k of the frame plan, its bytes counted when the run
 * is counted (gls_frame_counts: tests compare them with the plan). */
static void *frame_alloc(gls_frame_counts *cnt, int k, size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (p && cnt)
        cnt->bytes[k] += bytes;
    return p;
}

/* The centre and ground-truth passes just drawn, counted. */
static void count_passes(gls_frame_counts *cnt, int centre, int truth)
{
    if (!cnt)
        return;
    cnt->passes[GLS_PASS_I_CENTRE] += centre != 0;
    cnt->passes[GLS_PASS_I_TRUTH] += truth != 0;
}

/* What one camera frame holds while it is drawn: its plan, and the
 * buffers the plan asks for (NULL: not needed), freed together. */
typedef struct {
    gls_frame_plan fp;
    gls_distort_frame df;  /* a lens: the undistorted images (distort_render.h) */
    gls_bands bands;       /* rolling shutter: rows per band (exposure.h)      */
    uint8_t *rgba, *mask, *flowmask;
    float *z, *normal, *flow, *gt_z;
    uint32_t *gt_ids;      /* the ground-truth pass (gt_pass.h): ids for
                              instance, class, coco, flow, boxes             */
    gls_box *boxes;
    size_t nboxes;
    void *img;             /* the image in its file's format, when not rgba  */
    float *exact;          /* exact coverage's image, RGBA float            */
    gls_exact_cover *cover; /* exact coverage's areas per instance          */
    gls_exact_seg *segs;   /* exact coverage's edge segments, nsegs of them */
    size_t nsegs, capsegs;
    int segs_oom;
    gls_accum acc;
} cam_frame;

/* The buffers of n pixels cf's plan asks for (colour, depth, ids,
 * normals, the truth pass's depth), counted in cnt when not NULL: the one
 * place both the player's frame and the library's make them.  0, or -1
 * when out of memory (cam_frame_free frees what was made). */
static int frame_buffers(cam_frame *cf, gls_frame_counts *cnt, size_t n)
{
    const gls_frame_plan *fp = &cf->fp;
    if ((fp->rgba && !(cf->rgba = frame_alloc(cnt, GLS_BUF_RGBA, n * 4))) ||
        (fp->z && !(cf->z = frame_alloc(cnt, GLS_BUF_DEPTH, n * sizeof *cf->z))) ||
        (fp->ids && !(cf->gt_ids = frame_alloc(cnt, GLS_BUF_IDS, n * sizeof *cf->gt_ids))) ||
        (fp->normals && !(cf->normal = frame_alloc(cnt, GLS_BUF_NORMALS, n * 3 * sizeof *cf->normal))) ||
        (fp->truth_z && !(cf->gt_z = frame_alloc(cnt, GLS_BUF_TRUTH_DEPTH, n * sizeof *cf->gt_z))))
        return -1;
    return 0;
}

static void cam_frame_free(cam_frame *cf)
{
    gls_accum_free(&cf->acc);
    gls_distort_frame_free(&cf->df);
    free(cf->rgba);
    free(cf->z);
    free(cf->img);
    free(cf->exact);
    free(cf->cover);
    free(cf->segs);
    free(cf->mask);
    free(cf->normal);
    free(cf->flow);
    free(cf->flowmask);
    free(cf->gt_ids);
    free(cf->gt_z);
    free(cf->boxes);
}

/* "glsplay: error: camera NAME: ERR" into msg; -1. */
static int camera_error(const session *s, const char *err, char *msg, size_t msglen)
{
    snprintf(msg, msglen, "glsplay: error: camera %s: %s", s->name_now, err);
    return -1;
}

/* The centre pass (colour and depth at the pixel centres) and the
 * ground-truth pass (ids, normals, the depth flow starts from), each
 * only when the plan reads it back: in bands of rows under a rolling
 * shutter, through the lens when there is one.  0, or -1 with msg
 * (empty: out of memory). */
static int frame_centre_truth(session *s, const gls_camera *c, cam_frame *cf, char *msg, size_t msglen)
{
    gls_renderer *r = s->r;
    char err[512];
    int centre = cf->rgba || cf->z, truth = cf->gt_ids || cf->normal;
    if (cf->bands.rows < c->height && cf->fp.lens) {
        /* flow starts from each band's ground-truth depth at the nearest
         * fine pixel; boxes take their 2D boxes from this instance image */
        if (gls_distort_truth_bands(r, c, &cf->df, cf->bands, play_pose_at, s, cf->rgba, cf->z, cf->gt_ids, cf->normal,
                                    cf->gt_z, err, sizeof err))
            return camera_error(s, err, msg, msglen);
        truth |= cf->gt_z != NULL;
    } else if (cf->bands.rows < c->height) {
        /* flow starts from each band's ground-truth depth; boxes take
         * their 2D boxes from this instance image */
        if (play_centre_bands(s, c, cf->bands, cf->rgba, cf->z, cf->gt_ids, cf->normal, cf->gt_z, msg, msglen))
            return -1;
        truth |= cf->gt_z != NULL;
    } else if (cf->fp.lens) {
        if (centre)
            gls_distort_frame_centre(&cf->df, c, cf->rgba, cf->z);
        /* through the lens: the ground-truth pass drawn by the plain fine
         * camera, read at each pixel centre's ray (lens_truth.h) */
        if (truth && gls_lens_gt_render(r, &cf->df, c, cf->gt_ids, cf->normal, cf->gt_z, err, sizeof err))
            return camera_error(s, err, msg, msglen);
    } else {
        if (centre) {
            gls_render_pass(r, c, 0.0, 0.0);
            if (cf->rgba)
                gls_render_read_rgba(r, cf->rgba);
            if (cf->z)
                gls_render_read_z(r, cf->z);
        }
        /* ground truth: the centre sample again, one pass for ids, normals
         * and the depth flow starts from (gt_pass.h), never blended
         * whatever --aa is */
        if (truth && gls_gt_render(r, c, cf->gt_ids, cf->normal, cf->gt_z, err, sizeof err))
            return camera_error(s, err, msg, msglen);
    }
    count_passes(s->counts, centre, truth);
    return 0;
}

/* The anti-aliased colour: the samples summed into the accumulator,
 * at each sub-frame time and lens point with exposure effects (exposure.h,
 * distort_exposure.h), through the lens's undistorted image with a lens.
 * 0, or -1 with msg (empty: out of memory). */
static int frame_colour(session *s, const gls_camera *c, cam_frame *cf, char *msg, size_t msglen)
{
    const gls_aa_plan *plan = s->plan;
    gls_frame_counts *cnt = s->counts;
    if (gls_accum_init(&cf->acc, c->width, c->height, cf->fp.weighted, (cf->fp.outputs & GLS_OUT_EDGE_MAPS) != 0))
        return -1;
    if (cnt) {
        cnt->bytes[GLS_BUF_ACCUM] += gls_accum_sums_bytes(&cf->acc);
        cnt->bytes[GLS_BUF_MIXED] += gls_accum_mask_bytes(&cf->acc);
        cnt->passes[cf->fp.effects ? GLS_PASS_I_EXPOSURE : GLS_PASS_I_SAMPLES]++;
    }
    int rc = 0;
    if (cf->fp.effects && cf->fp.lens)
        rc = gls_distort_exposure_render(s->r, c, &cf->fp.ex, plan, &cf->df, play_pose_at, s, cf->bands.rows,
                                         s->o->aa_memory, s->name_now, &cf->acc, msg, msglen);
    else if (cf->fp.effects) /* the plan at each sub-frame time and lens point */
        rc = gls_exposure_render(s->r, c, &cf->fp.ex, plan, play_pose_at, play_render_plan, s, &cf->acc, cf->bands, msg,
                                 msglen);
    else if (cf->fp.lens)
        rc = gls_distort_frame_accum(&cf->df, c, plan, &cf->acc) ? (msg[0] = 0, -1) : 0;
    else
        rc = play_render_plan(s, c, 0, c->height, &cf->acc, msg, msglen);
    if (cnt)
        cnt->accum_samples = cf->acc.samples;
    return rc;
}

/* one edge segment into the frame's list (out of memory: noted, the
 * pass fails after the walk) */
static void keep_seg(void *user, const gls_exact_seg *g)
{
    cam_frame *cf = user;
    if (cf->segs_oom)
        return;
    if (cf->nsegs == cf->capsegs) {
        size_t c = cf->capsegs ? 2 * cf->capsegs : 1024;
        gls_exact_seg *n = realloc(cf->segs, c * sizeof *n);
        if (!n) {
            cf->segs_oom = 1;
            return;
        }
        cf->segs = n, cf->capsegs = c;
    }
    cf->segs[cf->nsegs++] = *g;
}

/* The exact pass (exact_scene.h): the scene's triangles projected in
 * double, each pixel the exact areas of what is visible in it times their
 * colours, the background the rest.  0, or -1 when out of memory. */
static int frame_exact(session *s, const gls_camera *c, cam_frame *cf)
{
    size_t n = (size_t)c->width * c->height;
    gls_exact_geom g;
    float bg[4] = {s->o->background[0], s->o->background[1], s->o->background[2], 1};
    if ((cf->fp.bytes[GLS_BUF_EXACT] && !(cf->exact = frame_alloc(s->counts, GLS_BUF_EXACT, n * 4 * sizeof *cf->exact))) ||
        (cf->fp.cover && !(cf->cover = frame_alloc(s->counts, GLS_BUF_COVER, n * GLS_EXACT_COVER_K * sizeof *cf->cover))))
        return -1;
    if (s->counts)
        s->counts->passes[GLS_PASS_I_EXACT]++;
    /* coverage's ids: the instance ids of the run (gt_table.h) */
    const uint16_t *idmap = s->gt ? s->gt->id : NULL;
    size_t dense = s->plan->o.dense; /* aa.h */
    char err[400];
    if (cf->fp.lens) /* exact in the undistorted image the lens path resamples */
        return cf->exact && gls_distort_exact(&cf->df, c, s->scene, s->textures, bg, dense, cf->exact, err, 400) ? -1 : 0;
    int rc = gls_exact_geom_make(&g, s->scene, s->textures, c) ||
             ((cf->exact || cf->cover) && gls_exact_render(g.t, g.n, (int)c->width, (int)c->height, bg,
                                                           gls_exact_geom_shade, &g, idmap, cf->exact, cf->cover, dense)) ||
             (cf->fp.segs && (gls_exact_edges(g.t, g.n, (int)c->width, (int)c->height, idmap, keep_seg, cf) ||
                              cf->segs_oom));
    gls_exact_geom_free(&g);
    return rc ? -1 : 0;
}

/* The image in its file's format (through the sensor effects when the
 * camera asks for them: sensor.h, never on ground truth) and the edges
 * map.  0, or -1 when out of memory. */
static int frame_image(session *s, const gls_camera *c, const char *name, uint32_t frame, cam_frame *cf)
{
    const gls_play_opts *o = s->o;
    gls_frame_counts *cnt = s->counts;
    size_t n = (size_t)c->width * c->height;
    int aa = cf->fp.aa;
    if (cf->fp.image == GLS_IMAGE_SENSOR) {
        /* on the linear intensities before quantisation */
        uint64_t b[2];
        cf->img = gls_sensor_image(c, name, frame, aa ? &cf->acc : NULL, cf->rgba, o->image_format, b);
        if (!cf->img)
            return -1;
        if (cnt) /* what sensor_image.c allocated */
            cnt->bytes[GLS_BUF_LINEAR] += b[0], cnt->bytes[GLS_BUF_IMAGE] += b[1];
    } else if (cf->fp.image == GLS_IMAGE_CONVERTED) {
        size_t px = o->image_format == GLS_IMG_PNG16 ? 3 * sizeof(uint16_t)
                    : o->image_format == GLS_IMG_PFM ? 3 * sizeof(float) : 4;
        if (!(cf->img = frame_alloc(cnt, GLS_BUF_IMAGE, n * px)))
            return -1;
        if (cf->exact && o->image_format == GLS_IMG_PNG16)
            gls_exact_rgb16(cf->exact, n, cf->img);
        else if (cf->exact && o->image_format == GLS_IMG_PFM)
            gls_exact_rgbf(cf->exact, n, cf->img);
        else if (cf->exact)
            gls_exact_rgba8(cf->exact, n, cf->img);
        else if (o->image_format == GLS_IMG_PNG16 && aa)
            gls_accum_rgb16(&cf->acc, cf->img);
        else if (o->image_format == GLS_IMG_PNG16)
            gls_rgba8_to_rgb16(cf->rgba, n, cf->img);
        else if (o->image_format == GLS_IMG_PFM && aa)
            gls_accum_rgbf(&cf->acc, cf->img);
        else if (o->image_format == GLS_IMG_PFM)
            gls_rgba8_to_rgbf(cf->rgba, n, cf->img);
        else
            gls_accum_rgba8(&cf->acc, cf->img);
    }
    if (cf->fp.outputs & GLS_OUT_EDGE_MAPS) {
        /* one sample per pixel cannot straddle anything: all zero */
        if (!(cf->mask = calloc(n ? n : 1, 1)))
            return -1;
        if (cnt)
            cnt->bytes[GLS_BUF_EDGES] += n;
        for (size_t i = 0; aa && i < n; i++)
            cf->mask[i] = cf->acc.mixed[i] ? 255 : 0;
    }
    return 0;
}

/* Boxes and flow, from the ground-truth pass's ids.  0, or -1 with msg
 * (empty: out of memory). */
static int frame_boxes_flow(session *s, const gls_camera *c, uint32_t frame, cam_frame *cf, char *msg,
                            size_t msglen)
{
    char err[512];
    if (cf->fp.boxes && s->counts)
        s->counts->passes[GLS_PASS_I_BOXES_ALONE]++;
    if (cf->fp.boxes && cf->fp.lens) {
        if (gls_boxes_compute_lens(s->r, s->ms->scene, c, &cf->df, cf->gt_ids, &cf->boxes, &cf->nboxes, err,
                                   sizeof err))
            return camera_error(s, err, msg, msglen);
    } else if (cf->fp.boxes && gls_boxes_compute(s->r, s->ms->scene, c, cf->gt_ids, &cf->boxes, &cf->nboxes)) {
        return -1;
    }
    if (cf->fp.flow && play_flow_frame(s, c, cf->fp.lens ? &cf->df : NULL, s->name_now, frame, cf->bands, cf->gt_ids,
                                       cf->gt_z, &cf->flow, &cf->flowmask, msg, msglen))
        return -1;
    return 0;
}

/* The files go to the writer (frame_writer.h, frame_files.h), which
 * encodes and writes them, with its thread while the next frame renders,
 * and writes the frame record after the last one; the buffers it takes
 * are the writer's from here.  0, or -1 with msg (empty: out of memory). */
static int frame_submit(session *s, const gls_camera *c, const char *name, uint32_t frame, cam_frame *cf, char *msg,
                        size_t msglen)
{
    const gls_play_opts *o = s->o;
    uint32_t band = cf->bands.rows;
    gls_frame_files *f = gls_frame_files_new();
    if (!f)
        return -1;
    f->cam = *c;
    f->name = name;
    f->frame = frame;
    f->image_format = o->image_format;
    f->image_mosaic = c->sensor.bayer[0] != 0;
    f->float_format = o->float_format;
    f->fxB = c->fx * s->baseline;
    f->depth_scale = o->depth_scale > 0 ? o->depth_scale : GLS_DEPTH_SCALE_KITTI;
    f->buffer_bytes = cf->fp.total;
    f->json = s->json;
    f->sink = o->sink;
    int too_long = !o->sink && (gls_frame_record_path(f->record, sizeof f->record, o->outdir, name, frame) ||
                   gls_frame_record_text(f->record_text, sizeof f->record_text, o, &cf->fp, c, name, frame, s->inputs));
    /* one file a kind at most: files[] has room for every kind */
    for (size_t k = 0; k < GLS_OUT_KINDS && !too_long; k++)
        if (cf->fp.outputs & gls_output_kinds[k].bit) {
            f->files[f->nfiles].bit = gls_output_kinds[k].bit;
            too_long = !o->sink && play_output_file(f->files[f->nfiles].path, GLS_FRAME_PATH, o, name, k, frame) != 0;
            f->nfiles++;
        }
    int rc = -1;
    if (too_long) {
        snprintf(msg, msglen, "glsplay: error: output path for camera %s is too long", name);
        goto fail;
    }
    /* where the landmarks are in this frame: motion moves them; under a
     * rolling shutter each at its band's time, as its rows */
    if ((cf->fp.outputs & GLS_OUT_LANDMARKS) && !(f->landmarks = gls_landmarks_take(s->scene)))
        goto fail;
    if (f->landmarks && band < c->height && gls_exposure_landmarks(s->scene, c, band, play_pose_at, s, f->landmarks))
        goto fail;
    /* rolling shutter: each row's points through the pose its depth was
     * drawn with (spec/outputs.md) */
    if ((cf->fp.outputs & GLS_OUT_POINTS) && band < c->height &&
        !(f->row_pose = gls_exposure_row_poses(c, band, play_pose_at, s)))
        goto fail;
    f->rgba = cf->rgba, f->z = cf->z, f->image = cf->img, f->mask = cf->mask, f->cover = cf->cover;
    f->segs = cf->segs, f->nsegs = cf->nsegs;
    cf->cover = NULL, cf->segs = NULL;
    /* the writer needs the ids only for the id images and tables */
    int ids = (cf->fp.outputs & GLS_OUT_IDS) != 0;
    f->gt_inst = ids ? cf->gt_ids : NULL, f->normal = cf->normal, f->gt = s->gt;
    f->flow = cf->flow, f->flowmask = cf->flowmask;
    f->boxes = cf->boxes, f->nboxes = cf->nboxes, f->box_names = s->box_names;
    if (ids)
        cf->gt_ids = NULL;
    cf->rgba = cf->mask = cf->flowmask = NULL, cf->z = cf->flow = cf->normal = NULL, cf->img = NULL;
    cf->boxes = NULL;
    /* the writer's now, submitted or freed */
    return gls_writer_submit(s->w, &f->job, msg, msglen) ? -1 : 0;
fail:
    f->job.destroy(&f->job);
    return rc;
}

/* Render one camera and write what was asked for.
 *
 * Plain (N = 1): one pass at jitter (0, 0), no accumulator.
 * Anti-aliased (N > 1): the image (and mask) come from the accumulated
 * samples (one fine framebuffer for the lattice and grid, jittered passes
 * for stratified); depth and points come from one extra unjittered pass
 * (the geometry at each pixel centre, never averaged across an edge),
 * drawn only when they are asked for; the points' colours come from that
 * pass too, so each point has the colour of the surface it lies on.
 * Instance ids and normals come from one more unjittered pass
 * (gt_pass.h), drawn only when an output needs them. */
int play_camera(session *s, const gls_camera *c, const char *name, uint32_t frame)
{
    static const char lower_size[] = "lower --size (or the camera's width and height)";
    const gls_play_opts *o = s->o;
    gls_renderer *r = s->r;
    char err[512], msg[1024] = "";
    size_t n = (size_t)c->width * c->height;
    cam_frame cf;
    memset(&cf, 0, sizeof cf);
    /* everything this frame needs, decided once (frame_plan.h) */
    gls_plan_inputs pin = {o->outputs, o->image_format, s->plan, s->moving};
    gls_frame_plan_make(&cf.fp, &pin, c, s->next != NULL);
    const gls_frame_plan *fp = &cf.fp;
    if (s->times && !s->times->plan)
        s->times->plan = gls_now();
    gls_frame_counts *cnt = s->counts;
    if (cnt)
        memset(cnt, 0, sizeof *cnt), cnt->frames = 1;
    int rc = -1;
    s->name_now = name;
    if (fp->gl && gls_renderer_set_size(r, c->width, c->height, err, sizeof err)) {
        snprintf(msg, sizeof msg, "glsplay: error: camera %s: %s; %s", name, err, lower_size);
        goto out;
    }
    /* a lens: one undistorted fine image, read through the inverse model
       (distort_render.h); with the exposure's effects, one at each
       sub-frame time, lens point and band (distort_exposure.h) */
    if (fp->lens && gls_distort_frame_render(&cf.df, r, c, s->plan, fp->rgba, fp->z, fp->aa && !fp->effects,
                                             o->aa_memory, err, sizeof err)) {
        snprintf(msg, sizeof msg, "glsplay: error: camera %s: %s; %s", name, err, lower_size);
        goto out;
    }
    if (fp->lens && cnt)
        cnt->passes[GLS_PASS_I_LENS]++;
    /* rolling shutter: the ground truth of each band of rows at its time
     * (exposure.h), the bands chosen from this frame's motion; one band,
     * the whole image, otherwise.  Each band draws its own rows, or the
     * whole image when a test asks (gls_play_opts' bands_whole) */
    cf.bands.rows = fp->ex.rolling ? gls_exposure_band_rows(r, c, &fp->ex, play_pose_at, s) : c->height;
    cf.bands.whole = o->bands_whole != 0;
    if (frame_buffers(&cf, cnt, n))
        goto out;
    if (frame_centre_truth(s, c, &cf, msg, sizeof msg) || (fp->aa && frame_colour(s, c, &cf, msg, sizeof msg)) ||
        (fp->exact && frame_exact(s, c, &cf)))
        goto out;
    if (s->times && !s->times->draw)
        s->times->draw = gls_now(); /* drawn and read back */
    if (frame_image(s, c, name, frame, &cf) || frame_boxes_flow(s, c, frame, &cf, msg, sizeof msg) ||
        frame_submit(s, c, name, frame, &cf, msg, sizeof msg))
        goto out;
    play_view_done(s);
    rc = 0;
out:
    if (rc && !msg[0])
        gls_frame_oom_message(msg, sizeof msg, name, c->width, c->height, fp->total);
    if (rc)
        say_failure(s, msg);
    cam_frame_free(&cf);
    return rc;
}

int gls_play_frame(gls_renderer *r, const gls_scene *scene, const gls_aa_plan *plan, const gls_camera *c,
                   unsigned outputs, const float background[3], const gls_texture *textures,
                   gls_play_frame_result *res, char *msg, size_t msglen)
{
    /* a session of one still frame: no motion, no writer, no progress */
    gls_play_opts o;
    memset(&o, 0, sizeof o);
    o.outputs = outputs;
    o.aa = plan->o;
    memcpy(o.background, background, sizeof o.background);
    motion_set ms;
    memset(&ms, 0, sizeof ms);
    ms.scene = (gls_scene *)scene;
    session s;
    memset(&s, 0, sizeof s);
    s.o = &o, s.ms = &ms, s.scene = scene, s.plan = plan, s.r = r, s.name_now = "glscene";
    s.textures = textures;
    cam_frame cf;
    memset(&cf, 0, sizeof cf);
    memset(res, 0, sizeof *res);
    msg[0] = 0;
    gls_plan_inputs pin = {outputs, GLS_IMG_PNG8, plan, 0};
    gls_frame_plan_make(&cf.fp, &pin, c, 0);
    size_t n = (size_t)c->width * c->height;
    const gls_frame_plan *fp = &cf.fp;
    cf.bands.rows = c->height;
    int rc = -1;
    if (frame_buffers(&cf, NULL, n))
        goto out;
    if (frame_centre_truth(&s, c, &cf, msg, msglen) || (fp->aa && frame_colour(&s, c, &cf, msg, msglen)) ||
        (fp->exact && frame_exact(&s, c, &cf)))
        goto out;
    res->fp = cf.fp, res->rgba = cf.rgba, res->z = cf.z, res->ids = cf.gt_ids, res->normals = cf.normal;
    res->acc = cf.acc, res->exact = cf.exact;
    memset(&cf.acc, 0, sizeof cf.acc);
    cf.rgba = NULL, cf.z = NULL, cf.gt_ids = NULL, cf.normal = NULL, cf.exact = NULL;
    rc = 0;
out:
    cam_frame_free(&cf);
    return rc;
}

void gls_play_frame_free(gls_play_frame_result *res)
{
    free(res->rgba);
    free(res->z);
    free(res->ids);
    free(res->normals);
    free(res->exact);
    gls_accum_free(&res->acc);
    memset(res, 0, sizeof *res);
}
