/* Encoding and writing one camera frame's files (frame_files.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "atomic_write.h"
#include "frame_files.h"
#include "outputs.h"
#include "progress.h"
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

static int encode(const gls_frame_files *f, unsigned bit, gls_buf *buf)
{
    const gls_camera *c = &f->cam;
    uint64_t np;
    switch (bit) {
    case GLS_OUT_IMAGE:
        return f->image_format == GLS_IMG_PNG16 ? gls_encode_png16(f->image, c->width, c->height, buf)
               : f->image_format == GLS_IMG_PFM ? gls_encode_pfm_rgb(f->image, c->width, c->height, buf)
                                                : gls_encode_png(f->image ? f->image : f->rgba, c->width, c->height,
                                                                 buf);
    case GLS_OUT_DEPTH:
        return gls_encode_pfm(f->z, c->width, c->height, buf);
    case GLS_OUT_POINTS:
        return gls_encode_ply(c, f->z, f->rgba, buf, &np);
    default:
        return gls_encode_png_gray(f->mask, c->width, c->height, buf);
    }
}

static int run(gls_write_job *job, char *err, size_t errlen)
{
    gls_frame_files *f = (gls_frame_files *)job;
    gls_buf buf = {0};
    int rc = -1;
    /* The frame is incomplete from the first file rewritten until the
     * last is written: no record meanwhile (frame_record.h). */
    if (unlink(f->record) != 0 && errno != ENOENT) {
        snprintf(err, errlen, "glsplay: error: cannot remove %s: %s", f->record, strerror(errno));
        return -1;
    }
    for (size_t k = 0; k < f->nfiles; k++) {
        buf.len = 0;
        if (encode(f, f->files[k].bit, &buf)) {
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
    return rc;
}

static void destroy(gls_write_job *job)
{
    gls_frame_files *f = (gls_frame_files *)job;
    free(f->rgba);
    free(f->mask);
    free(f->image);
    free(f->z);
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
