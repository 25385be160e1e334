/* Encoding and writing one camera frame's files (frame_files.h), or
 * handing each file's array to a sink (the library's result). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "atomic_write.h"
#include "frame_files.h"
#include "numfmt.h"
#include "out_disparity.h"
#include "out_coverage.h"
#include "out_edge_segments.h"
#include "out_flow.h"
#include "out_gt.h"
#include "out_npy.h"
#include "out_png16.h"
#include "outputs.h"
#include "progress_line.h"
#include "units.h"

void gls_frame_oom_message(char *buf, size_t len, const char *name, uint32_t w, uint32_t h, uint64_t bytes)
{
    char need[32];
    gls_fmt_bytes(need, sizeof need, bytes);
    snprintf(buf, len,
             "glsplay: error: camera %s: out of memory for the buffers of a %ux%u image (about %s); "
             "lower --size (or the camera's width and height)",
             name, w, h, need);
}

/* A float output (depth, disparity, a pfm image) in the chosen format. */
static int encode_float(const gls_frame_files *f, const float *v, unsigned channels, gls_buf *buf)
{
    const gls_camera *c = &f->cam;
    if (f->float_format == GLS_FLOAT_NPY)
        return gls_encode_npy(v, c->width, c->height, channels, buf);
    return channels == 3 ? gls_encode_pfm_rgb(v, c->width, c->height, buf) : gls_encode_pfm(v, c->width, c->height, buf);
}

/* disparity16 and depth16: a value that does not fit is refused, with
 * the pixel, the value, the limit and what to do instead.  Checked before
 * any file of the frame is written; 0, or 1 with the message in err. */
static int check_16(const gls_frame_files *f, unsigned bit, const float *v, char *err, size_t errlen)
{
    const gls_camera *c = &f->cam;
    int disp = bit == GLS_OUT_DISPARITY16;
    double scale = disp ? 256.0 : f->depth_scale;
    size_t bad = 0;
    int rc = gls_scaled16_check(v, (size_t)c->width * c->height, scale, &bad);
    if (rc == 0)
        return 0;
    char at[256], sc[32];
    snprintf(at, sizeof at, "glsplay: error: %s: camera %s, frame %u, pixel (%zu, %zu)", disp ? "disparity16" : "depth16",
             f->name, f->frame, bad % c->width, bad / c->width);
    gls_fmt_double(sc, sizeof sc, scale);
    if (disp && rc == GLS_SCALED16_OVER)
        snprintf(err, errlen,
                 "%s: disparity %.6g px is over %.6g px, the most a KITTI 16-bit PNG holds (d * 256 <= 65535); "
                 "use --outputs disparity (float) instead",
                 at, v[bad], 65535 / 256.0);
    else if (disp)
        snprintf(err, errlen,
                 "%s: disparity %.6g px rounds to 0, which a KITTI 16-bit PNG reads as no disparity "
                 "(d * 256 >= 0.5 for a surface); use --outputs disparity (float) instead",
                 at, v[bad]);
    else if (rc == GLS_SCALED16_OVER)
        snprintf(err, errlen,
                 "%s: depth %.6g is over %.6g, the largest a 16-bit PNG holds at --depth-scale %s (65535 / %s); "
                 "lower --depth-scale or use --outputs depth (float) instead",
                 at, v[bad], 65535 / scale, sc, sc);
    else
        snprintf(err, errlen,
                 "%s: depth %.6g rounds to 0 at --depth-scale %s, which means no surface; raise --depth-scale or "
                 "use --outputs depth (float) instead",
                 at, v[bad], sc);
    return 1;
}

/* 0, or -1 when out of memory. */
static int encode(const gls_frame_files *f, unsigned bit, const float *disp, gls_buf *buf)
{
    const gls_camera *c = &f->cam;
    uint64_t np;
    size_t bad;
    switch (bit) {
    case GLS_OUT_IMAGE:
        if (f->image_mosaic) /* one sample a pixel, in the image's bit depth */
            return f->image_format == GLS_IMG_PNG16 ? gls_encode_png16_gray(f->image, c->width, c->height, buf)
                   : f->image_format == GLS_IMG_PFM ? encode_float(f, f->image, 1, buf)
                                                    : gls_encode_png_gray(f->image, c->width, c->height, buf);
        return f->image_format == GLS_IMG_PNG16 ? gls_encode_png16(f->image, c->width, c->height, buf)
               : f->image_format == GLS_IMG_PFM ? encode_float(f, f->image, 3, buf)
                                                : gls_encode_png(f->image ? f->image : f->rgba, c->width, c->height,
                                                                 buf);
    case GLS_OUT_DEPTH:
        return encode_float(f, f->z, 1, buf);
    case GLS_OUT_POINTS:
        return gls_encode_ply_rows(c, (const double (*)[12])f->row_pose, f->z, f->rgba, buf, &np);
    case GLS_OUT_LANDMARKS:
        return gls_encode_landmarks_csv(f->landmarks, c, f->z, buf);
    case GLS_OUT_DISPARITY:
        return encode_float(f, disp, 1, buf);
    case GLS_OUT_DISPARITY16: /* checked by check_16 */
        return gls_encode_scaled16(disp, c->width, c->height, 256.0, buf, &bad);
    case GLS_OUT_DEPTH16:
        return gls_encode_scaled16(f->z, c->width, c->height, f->depth_scale, buf, &bad);
    case GLS_OUT_INSTANCE:
    case GLS_OUT_CLASS:
        return gls_encode_ids_png(f->gt_inst, f->gt, bit == GLS_OUT_CLASS, c->width, c->height, buf);
    case GLS_OUT_INSTANCES_JSON: /* instances_F.json, with either */
        return gls_encode_instances_json(f->gt_inst, f->gt, f->frame, f->name, c->width, c->height, buf);
    case GLS_OUT_COCO: {
        char image[64]; /* the image file's name, which COCO's "file_name" is */
        snprintf(image, sizeof image, "image_%06u.%s", f->frame,
                 f->image_format != GLS_IMG_PFM ? "png" : f->float_format == GLS_FLOAT_NPY ? "npy" : "pfm");
        return gls_encode_coco(f->gt_inst, f->gt, f->frame, image, c->width, c->height, buf);
    }
    case GLS_OUT_NORMALS:
        return encode_float(f, f->normal, 3, buf);
    case GLS_OUT_FLOW:
        return gls_encode_flow_kitti(f->flow, f->flowmask, c->width, c->height, buf);
    case GLS_OUT_FLOW_FLO:
        return gls_encode_flo(f->flow, c->width, c->height, buf);
    case GLS_OUT_FLOW_MASK:
        return gls_encode_png_gray(f->flowmask, c->width, c->height, buf);
    case GLS_OUT_BOXES:
        return gls_encode_boxes_kitti(f->boxes, f->nboxes, f->box_names, buf);
    case GLS_OUT_BOXES_JSON:
        return gls_encode_boxes_json(f->boxes, f->nboxes, f->box_names, c, f->name, f->frame, buf);
    case GLS_OUT_COVERAGE:
        return gls_encode_coverage_csv(f->cover, c->width, c->height, buf);
    case GLS_OUT_EDGE_SEGMENTS:
        return gls_encode_edge_segments_csv(f->segs, f->nsegs, buf);
    default: /* edges, and the same map as mask */
        return gls_encode_png_gray(f->mask, c->width, c->height, buf);
    }
}

/* An array of rows x cols x ch samples of type t, uninitialised; NULL
 * when out of memory. */
static void *array_new(gls_frame_array *a, gls_arr_type t, const gls_camera *c, uint32_t ch)
{
    static const size_t size[] = {0, 1, 2, 4};
    a->type = t;
    a->ndim = ch > 1 ? 3 : 2;
    a->dims[0] = c->height, a->dims[1] = c->width, a->dims[2] = ch;
    a->bytes = (size_t)c->width * c->height * ch * size[t];
    return a->data = malloc(a->bytes ? a->bytes : 1);
}

/* A copy of v's rows x cols x ch samples. */
static int array_copy(gls_frame_array *a, gls_arr_type t, const gls_camera *c, uint32_t ch, const void *v)
{
    if (!array_new(a, t, c, ch))
        return -1;
    memcpy(a->data, v, a->bytes);
    return 0;
}

int gls_frame_array_make(const gls_frame_files *f, unsigned bit, const float *disp, gls_frame_array *a)
{
    const gls_camera *c = &f->cam;
    size_t n = (size_t)c->width * c->height;
    memset(a, 0, sizeof *a);
    switch (bit) {
    case GLS_OUT_IMAGE: {
        gls_arr_type t = f->image_format == GLS_IMG_PNG16 ? GLS_ARR_U16
                         : f->image_format == GLS_IMG_PFM ? GLS_ARR_F32 : GLS_ARR_U8;
        if (f->image_mosaic || t != GLS_ARR_U8) /* the image as the encoder takes it */
            return array_copy(a, t, c, f->image_mosaic ? 1 : 3, f->image);
        const uint8_t *rgba = f->image ? f->image : f->rgba; /* the PNG drops alpha */
        uint8_t *rgb = array_new(a, t, c, 3);
        for (size_t i = 0; rgb && i < n; i++)
            memcpy(rgb + 3 * i, rgba + 4 * i, 3);
        return rgb ? 0 : -1;
    }
    case GLS_OUT_DEPTH:
        return array_copy(a, GLS_ARR_F32, c, 1, f->z);
    case GLS_OUT_DISPARITY:
        return array_copy(a, GLS_ARR_F32, c, 1, disp);
    case GLS_OUT_NORMALS:
        return array_copy(a, GLS_ARR_F32, c, 3, f->normal);
    case GLS_OUT_FLOW_FLO:
        return array_copy(a, GLS_ARR_F32, c, 2, f->flow);
    case GLS_OUT_FLOW_MASK:
        return array_copy(a, GLS_ARR_U8, c, 1, f->flowmask);
    case GLS_OUT_EDGES:
    case GLS_OUT_EDGES_AS_MASK:
        return array_copy(a, GLS_ARR_U8, c, 1, f->mask);
    case GLS_OUT_DISPARITY16: /* checked by check_16 */
    case GLS_OUT_DEPTH16:
        if (!array_new(a, GLS_ARR_U16, c, 1))
            return -1;
        gls_scaled16_codes(bit == GLS_OUT_DEPTH16 ? f->z : disp, n, bit == GLS_OUT_DEPTH16 ? f->depth_scale : 256.0,
                           a->data);
        return 0;
    case GLS_OUT_INSTANCE:
    case GLS_OUT_CLASS:
        if (!array_new(a, GLS_ARR_U16, c, 1))
            return -1;
        gls_ids16(f->gt_inst, f->gt, bit == GLS_OUT_CLASS, n, a->data);
        return 0;
    case GLS_OUT_FLOW:
        if (!array_new(a, GLS_ARR_U16, c, 3))
            return -1;
        gls_flow_kitti_codes(f->flow, f->flowmask, n, a->data);
        return 0;
    default: { /* the records and tables: the file's own text (bytes: the PLY) */
        gls_buf buf = {0};
        if (encode(f, bit, disp, &buf) || gls_buf_reserve(&buf, 1)) {
            free(buf.data);
            return -1;
        }
        buf.data[buf.len] = 0; /* text ends with a NUL beyond its bytes */
        a->type = bit == GLS_OUT_POINTS ? GLS_ARR_BYTES : GLS_ARR_TEXT;
        a->ndim = 1;
        a->dims[0] = a->bytes = buf.len;
        a->data = buf.data;
        return 0;
    }
    }
}

/* The frame's arrays to f->sink, in the files' order, instead of files. */
static int run_sink(gls_frame_files *f, const float *disp, char *err, size_t errlen)
{
    for (size_t k = 0; k < f->nfiles; k++) {
        gls_frame_array a;
        if (gls_frame_array_make(f, f->files[k].bit, disp, &a)) {
            gls_frame_oom_message(err, errlen, f->name, f->cam.width, f->cam.height, f->buffer_bytes);
            return -1;
        }
        if (f->sink->take(f->sink, f->name, f->frame, f->files[k].bit, &a, err, errlen))
            return -1;
    }
    return 0;
}

static int run(gls_write_job *job, char *err, size_t errlen)
{
    gls_frame_files *f = (gls_frame_files *)job;
    gls_buf buf = {0};
    float *disp = NULL;
    int rc = -1;
    /* The disparity, made once for disparity and disparity16; a value
     * a 16-bit file cannot hold stops the frame before any file of it
     * is written. */
    size_t n = (size_t)f->cam.width * f->cam.height;
    for (size_t k = 0; k < f->nfiles; k++) {
        unsigned bit = f->files[k].bit;
        if ((bit & GLS_OUT_DISPARITIES) && !disp) {
            disp = malloc((n ? n : 1) * sizeof *disp);
            if (!disp) {
                gls_frame_oom_message(err, errlen, f->name, f->cam.width, f->cam.height, f->buffer_bytes);
                return -1;
            }
            gls_disparity_from_z(f->z, n, f->fxB, disp);
        }
        if ((bit & (GLS_OUT_DISPARITY16 | GLS_OUT_DEPTH16)) &&
            check_16(f, bit, bit == GLS_OUT_DISPARITY16 ? disp : f->z, err, errlen))
            goto out;
    }
    if (f->sink) {
        rc = run_sink(f, disp, err, errlen);
        goto out;
    }
    /* The frame is incomplete from the first file rewritten until the
     * last is written: no record meanwhile (frame_record.h). */
    if (unlink(f->record) != 0 && errno != ENOENT) {
        snprintf(err, errlen, "glsplay: error: cannot remove %s: %s", f->record, strerror(errno));
        goto out;
    }
    for (size_t k = 0; k < f->nfiles; k++) {
        buf.len = 0;
        if (encode(f, f->files[k].bit, disp, &buf)) {
            gls_frame_oom_message(err, errlen, f->name, f->cam.width, f->cam.height, f->buffer_bytes);
            goto out;
        }
        const char *path = f->files[k].path;
        if (gls_write_file_atomic(path, buf.data, buf.len)) {
            snprintf(err, errlen, "glsplay: error: cannot write %s: %s", path, gls_write_error(path, errno));
            goto out;
        }
    }
    if (gls_write_file_atomic(f->record, f->record_text, strlen(f->record_text))) {
        snprintf(err, errlen, "glsplay: error: cannot write %s: %s", f->record, strerror(errno));
        goto out;
    }
    gls_progress_json_frame(f->json, f->frame, f->name, gls_now());
    rc = 0;
out:
    free(buf.data);
    free(disp);
    return rc;
}

static void destroy(gls_write_job *job)
{
    gls_frame_files *f = (gls_frame_files *)job;
    free(f->rgba);
    free(f->mask);
    free(f->image);
    free(f->z);
    free(f->row_pose);
    gls_landmarks_free(f->landmarks);
    free(f->gt_inst);
    free(f->normal);
    free(f->flow);
    free(f->flowmask);
    free(f->boxes);
    free(f->cover);
    free(f->segs);
    free(f);
}

gls_frame_files *gls_frame_files_new(void)
{
    gls_frame_files *f = calloc(1, sizeof *f);
    if (f) {
        f->job.run = run;
        f->job.destroy = destroy;
    }
    return f;
}
