/* One frame of a run into arrays the library owns (include/glscene.h,
 * glscene_play_render): the run is glscene_play_run's, the player's own
 * (runtime/play/player.c) with its checks, plan and passes, except that
 * each camera frame's files go to a sink (gls_play_opts' sink,
 * frame_files.h) as the arrays their encoders make, and nothing is
 * written.  The run is begun at the first render (gls_play_begin) and
 * kept open in the glscene_play for the next frames (gls_play_render_frame)
 * until a setting changes (gls_play_close_run).  The messages the run
 * would print come back in e. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "frame_files.h"
#include "glscene_internal.h"
#include "glscene_play_run.h"
#include "trajectory.h"

typedef struct {
    const char *key;     /* the output table's KEY (output_table.h)   */
    gls_frame_array a;
} result_array;

typedef struct {
    char *name;
    result_array *arr;
    size_t n, cap;
} result_camera;

struct glscene_result {
    gls_frame_sink sink; /* first: the sink is the result              */
    result_camera *cam;
    size_t n, cap;
};

static const char *key_of(unsigned bit)
{
    for (size_t k = 0; k < GLS_OUT_KINDS; k++)
        if (gls_output_kinds[k].bit == bit)
            return gls_output_kinds[k].key;
    return "?";
}

/* gls_frame_sink's take: the array kept under its camera, cameras in the
 * order they first come (the run's order). */
static int take(gls_frame_sink *s, const char *camera, uint32_t frame, unsigned bit, gls_frame_array *a, char *err,
                size_t errlen)
{
    (void)frame;
    glscene_result *res = (glscene_result *)s;
    result_camera *c = res->n ? &res->cam[res->n - 1] : NULL;
    if (!c || strcmp(c->name, camera) != 0) {
        if (gls_grow(&res->cam, &res->cap, res->n + 1, sizeof *res->cam))
            goto oom;
        c = &res->cam[res->n];
        memset(c, 0, sizeof *c);
        if (!(c->name = strdup(camera)))
            goto oom;
        res->n++;
    }
    if (gls_grow(&c->arr, &c->cap, c->n + 1, sizeof *c->arr))
        goto oom;
    c->arr[c->n].key = key_of(bit);
    c->arr[c->n++].a = *a;
    return 0;
oom:
    free(a->data);
    snprintf(err, errlen, "glsplay: error: out of memory");
    return -1;
}

void glscene_result_free(glscene_result *res)
{
    if (!res)
        return;
    for (size_t i = 0; i < res->n; i++) {
        for (size_t k = 0; k < res->cam[i].n; k++)
            free(res->cam[i].arr[k].a.data);
        free(res->cam[i].arr);
        free(res->cam[i].name);
    }
    free(res->cam);
    free(res);
}

/* The run's messages as the library's: "glsplay: error: " taken off each
 * line, the notes left out. */
static void messages(const char *text, glscene_error *e, glscene_play *r)
{
    static const char err[] = "glsplay: error: ", note[] = "glsplay: note: ";
    gls_buf b = {0};
    for (const char *p = text; p && *p;) {
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p) : strlen(p);
        if (strncmp(p, note, sizeof note - 1) != 0) {
            size_t skip = strncmp(p, err, sizeof err - 1) == 0 ? sizeof err - 1 : 0;
            gls_buf_printf(&b, "%s%.*s", b.len ? "\n" : "", (int)(len - skip), p + skip);
        }
        p += len + (nl != NULL);
    }
    if (gls_buf_reserve(&b, 1) == 0) /* a C string */
        b.data[b.len] = 0;
    gls_play_fail(r, e, -1, "%s", b.len && b.cap > b.len ? (const char *)b.data : "the run failed and said nothing");
    free(b.data);
}

glscene_result *glscene_play_render(glscene_play *r, uint64_t frame, glscene_error *e)
{
    if (!r) {
        gls_api_fail(e, "glscene_play_render: a NULL run");
        return NULL;
    }
    r->rendering = 1;
    int bad = glscene_play_check(r, e);
    r->rendering = 0;
    r->checked = 0; /* glscene_play_run checks for itself, -o and all */
    if (bad)
        return NULL;
    glscene_result *res = calloc(1, sizeof *res);
    if (!res) {
        gls_play_fail(r, e, -1, "out of memory");
        return NULL;
    }
    /* a frame the trajectory has, said in the caller's words (the run
     * would speak of --frames, which the caller did not give) */
    if (r->o.trajectory) {
        long long n = glscene_play_trajectory_frames(r, NULL, 0, e);
        uint64_t *f = n > 0 ? malloc((size_t)n * sizeof *f) : NULL;
        long long k = n > 0 && f ? glscene_play_trajectory_frames(r, f, (size_t)n, e) : -1;
        int has = 0;
        for (long long i = 0; i < k && !has; i++)
            has = f[i] == frame;
        if (k > 0 && !has)
            gls_play_fail(r, e, -1, "%s has no frame %llu (its frames: %llu to %llu, %lld rows)", r->o.trajectory,
                          (unsigned long long)frame, (unsigned long long)f[0], (unsigned long long)f[k - 1], k);
        else if (n == 0)
            gls_play_fail(r, e, -1, "%s has no frame %llu (no rows)", r->o.trajectory, (unsigned long long)frame);
        else if (n > 0 && !f)
            gls_play_fail(r, e, -1, "out of memory");
        free(f);
        if (n < 0 || !has) {
            free(res);
            return NULL;
        }
    }
    res->sink.take = take;
    if (!r->o.trajectory && frame > UINT32_MAX) {
        gls_play_fail(r, e, -1, "frame %llu is over the largest frame number, %u", (unsigned long long)frame,
                      UINT32_MAX);
        goto fail;
    }
    char *text = NULL;
    size_t len = 0;
    FILE *errs = open_memstream(&text, &len);
    int rc = errs ? 0 : -1;
    if (rc == 0 && !r->run) {
        /* the run's options for frames into a sink: on this thread, no
         * progress, no plan printed, nothing resumed; begun at this frame
         * (the range its scan checks), and kept open for the next */
        gls_play_opts o = r->o;
        o.sink = &res->sink;
        o.outdir = NULL;
        o.explain = 0, o.resume = 0, o.write_calib = 0;
        o.progress = GLS_PROGRESS_OFF;
        o.writer_threads = 0;
        o.shard.index = 0, o.shard.count = 1;
        if (o.trajectory)
            o.frame_first = frame, o.frame_end = frame + 1;
        else
            o.frame = (uint32_t)frame;
        char *said = NULL;
        size_t saidlen = 0;
        FILE *out = open_memstream(&said, &saidlen);
        rc = out ? gls_play_begin(&o, out, errs, &r->run) : -1;
        if (out)
            fclose(out);
        free(said);
    }
    if (rc == 0)
        rc = gls_play_render_frame(r->run, frame, &res->sink, errs);
    if (rc) /* the writer keeps its first failure: the next render begins again */
        gls_play_close_run(r);
    if (errs)
        fclose(errs);
    if (rc == 0 && res->n == 0) /* checked above: cannot happen */
        gls_play_fail(r, e, -1, "frame %llu: nothing was rendered", (unsigned long long)frame);
    else if (rc)
        messages(rc < 0 ? "out of memory" : text, e, r);
    free(text);
    if (rc || res->n == 0)
        goto fail;
    return res;
fail:
    glscene_result_free(res);
    return NULL;
}

size_t glscene_result_cameras(const glscene_result *res)
{
    return res ? res->n : 0;
}

const char *glscene_result_camera(const glscene_result *res, size_t cam)
{
    return res && cam < res->n ? res->cam[cam].name : NULL;
}

size_t glscene_result_count(const glscene_result *res, size_t cam)
{
    return res && cam < res->n ? res->cam[cam].n : 0;
}

const char *glscene_result_name(const glscene_result *res, size_t cam, size_t k)
{
    return res && cam < res->n && k < res->cam[cam].n ? res->cam[cam].arr[k].key : NULL;
}

int glscene_result_array(const glscene_result *res, size_t cam, const char *name, glscene_array *out,
                         glscene_error *e)
{
    if (!res || !name || !out)
        return gls_api_fail(e, "glscene_result_array: a NULL result, name or array");
    if (cam >= res->n)
        return gls_api_fail(e, "the result has %zu camera%s; there is no camera %zu", res->n, res->n == 1 ? "" : "s",
                            cam);
    const result_camera *c = &res->cam[cam];
    gls_buf have = {0};
    for (size_t k = 0; k < c->n; k++) {
        if (strcmp(c->arr[k].key, name) == 0) {
            const gls_frame_array *a = &c->arr[k].a;
            static const glscene_dtype dtype[] = {0, GLSCENE_U8, GLSCENE_U16, GLSCENE_F32, GLSCENE_TEXT,
                                                  GLSCENE_BYTES};
            out->dtype = dtype[a->type];
            out->ndim = a->ndim;
            memcpy(out->dims, a->dims, sizeof out->dims);
            out->data = a->data;
            out->bytes = a->bytes;
            free(have.data);
            return 0;
        }
        gls_buf_printf(&have, "%s%s", k ? ", " : "", c->arr[k].key);
    }
    if (gls_buf_reserve(&have, 1) == 0) /* a C string */
        have.data[have.len] = 0;
    int rc = gls_api_fail(e, "camera %s has no array '%s' (it has: %s)", c->name, name,
                          have.len && have.cap > have.len ? (const char *)have.data : "none");
    free(have.data);
    return rc;
}

long long glscene_play_trajectory_frames(glscene_play *r, uint64_t *frames, size_t cap, glscene_error *e)
{
    if (!r || (cap && !frames))
        return gls_api_fail(e, "glscene_play_trajectory_frames: a NULL run or array");
    if (!r->o.trajectory)
        return gls_play_fail(r, e, -1, "the run has no --trajectory");
    /* the trajectory's own reader, as the run reads it */
    char err[1024];
    gls_traj_text tx;
    if (gls_traj_load(r->o.trajectory, &tx, err, sizeof err))
        return gls_play_fail(r, e, -1, "%s", err);
    gls_traj *t = gls_traj_open_text(&tx, NULL);
    long long n = 0;
    int got = t ? 0 : -1;
    gls_traj_pose p;
    while (t && (got = gls_traj_next(t, &p, err, sizeof err)) == 1) {
        if ((size_t)n < cap)
            frames[n] = p.frame;
        n++;
    }
    if (t)
        gls_traj_close(t);
    gls_traj_text_free(&tx);
    if (got < 0)
        return gls_play_fail(r, e, -1, "%s", t ? err : "out of memory");
    return n;
}
