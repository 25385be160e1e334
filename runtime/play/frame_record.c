/* Completion records of the player's outputs (frame_record.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "sensor.h"
#include "aa_onepass.h"
#include "digest.h"
#include "distort.h"
#include "frame_record.h"
#include "numfmt.h"
#include "readfile.h"

int gls_frame_record_path(char *buf, size_t len, const char *outdir, const char *name, uint32_t frame)
{
    return gls_output_path(buf, len, outdir, name, ".frame", frame, "done");
}

/* buf + *k gets the printf; -1 when it does not fit */
static int append(char *buf, size_t len, int *k, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf + *k, len - (size_t)*k, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= len - (size_t)*k)
        return -1;
    *k += n;
    return 0;
}

/* The camera's intrinsics and depth range, and its lens when it has one:
 * what the file says, in the shortest exact form. */
static int append_intrinsics(char *buf, size_t len, int *k, const gls_camera *c)
{
    char v[7][40];
    const double x[7] = {c->fx, c->fy, c->cx, c->cy, c->skew, c->near, c->far};
    for (int i = 0; i < 7; i++)
        gls_fmt_double(v[i], sizeof v[i], x[i]);
    if (append(buf, len, k, "intrinsics fx %s fy %s cx %s cy %s skew %s near %s far %s\n", v[0], v[1], v[2], v[3],
               v[4], v[5], v[6]))
        return -1;
    if (!gls_distort_on(c))
        return 0;
    if (append(buf, len, k, "lens %s", gls_distort_model_name(&c->dist)))
        return -1;
    for (unsigned i = 0; i < c->dist.n && i < 8; i++) {
        gls_fmt_double(v[0], sizeof v[0], c->dist.k[i]);
        if (append(buf, len, k, " %s", v[0]))
            return -1;
    }
    return append(buf, len, k, "\n");
}

int gls_frame_record_text(char *buf, size_t len, const gls_play_opts *o, const gls_frame_plan *fp,
                          const gls_camera *c, const char *name, uint32_t frame, const char *inputs)
{
    static const char *const fmt[] = {"png8", "png16", "pfm"};
    char sigma[32], bg[3][32];
    gls_fmt_double(sigma, sizeof sigma, o->aa.sigma);
    for (int i = 0; i < 3; i++)
        gls_fmt_float(bg[i], sizeof bg[i], o->background[i]);
    /* keyed on the frame's plan (frame_plan.h): the files it writes (no
     * flow from a trajectory's last frame) and whether its image comes
     * from the accumulator */
    unsigned out = fp->outputs;
    int image = (out & GLS_OUT_IMAGE) != 0;
    /* the anti-aliasing that shapes the image and mask: nothing but M when
     * M is 1, nothing at all when neither is written (depth and points
     * come from the unjittered pass); the one-pass patterns also name the
     * tile memory, which sets the tiles and so GL's rounding */
    char aa[160];
    uint64_t m = o->aa.samples ? o->aa.samples : (uint64_t)(o->aa.n ? o->aa.n : 1) * (o->aa.n ? o->aa.n : 1);
    int onepass = o->aa.pattern == GLS_AA_LATTICE || (o->aa.pattern == GLS_AA_GRID && o->aa.filter == GLS_AA_BOX);
    char mem[48] = "";
    if (onepass)
        snprintf(mem, sizeof mem, " memory %llu",
                 (unsigned long long)(o->aa_memory ? o->aa_memory : GLS_AA_DEFAULT_MEMORY));
    if (fp->exact) /* exact coverage: another image than one sample's */
        snprintf(aa, sizeof aa, "exact");
    else if (m == 1 || !fp->aa)
        snprintf(aa, sizeof aa, "1");
    else
        snprintf(aa, sizeof aa, "%llu %s%s%s %s %llu%s", (unsigned long long)m,
                 o->aa.filter == GLS_AA_GAUSS ? "gauss" : "box", o->aa.filter == GLS_AA_GAUSS ? ":" : "",
                 o->aa.filter == GLS_AA_GAUSS ? sigma : "", gls_aa_pattern_name(o->aa.pattern),
                 (unsigned long long)(o->aa.pattern == GLS_AA_STRATIFIED ? o->aa.seed : 0), mem);
    /* the float format of depth, disparity and a pfm image; depth16's
     * scale ("-" when no output uses them) */
    int floats = (out & (GLS_OUT_DEPTH | GLS_OUT_DISPARITY | GLS_OUT_NORMALS)) || (image && o->image_format == GLS_IMG_PFM);
    char scale[32] = "-";
    if (out & GLS_OUT_DEPTH16)
        gls_fmt_double(scale, sizeof scale, o->depth_scale > 0 ? o->depth_scale : GLS_DEPTH_SCALE_KITTI);
    /* the words asked for, once each, in the output table's order (the
     * rows of one word are adjacent) */
    char words[256] = "";
    const char *last = NULL;
    for (int i = 0; i < GLS_OUT_KINDS; i++) {
        const char *w = gls_output_kinds[i].word;
        size_t wl = strlen(words);
        if ((out & gls_output_kinds[i].bit) && w && !(last && strcmp(last, w) == 0))
            snprintf(words + wl, sizeof words - wl, " %s", w), last = w;
    }
    int k = snprintf(buf, len,
                     "glsplay frame record 2\n"
                     "frame %u\n"
                     "camera %s %ux%u\n"
                     "outputs%s\n"
                     "image-format %s\n"
                     "float-format %s\n"
                     "depth-scale %s\n"
                     "aa %s\n"
                     "anisotropic %u\n"
                     "background %s %s %s\n",
                     frame, name, c->width, c->height, words,
                     image ? fmt[o->image_format] : "-",
                     floats ? (o->float_format == GLS_FLOAT_NPY ? "npy" : "pfm") : "-", scale, aa,
                     o->anisotropy > 1 ? o->anisotropy : 1, bg[0], bg[1], bg[2]);
    if (k < 0 || (size_t)k >= len || append_intrinsics(buf, len, &k, c))
        return -1;
    /* the sensor effects that shape the image (sensor.h), only when the
     * camera asks for one: other records stay as they were */
    if (image && c->sensor.on) {
        char sensor[512];
        if (gls_sensor_describe(sensor, sizeof sensor, &c->sensor))
            return -1;
        int k2 = snprintf(buf + k, len - (size_t)k, "%s\n", sensor);
        if (k2 < 0 || (size_t)k2 >= len - (size_t)k)
            return -1;
        k += k2;
    }
    /* the camera's effects (spec/camera.md "Motion blur, rolling shutter,
     * depth of field"), only when it has one: the records of cameras
     * without stay as they were */
    if (c->shutter > 0 || c->line_delay > 0 || c->aperture > 0) {
        char v[5][40];
        const double x[5] = {c->shutter, c->line_delay, c->aperture, c->focus, (double)c->exposure_samples};
        for (int i = 0; i < 5; i++)
            gls_fmt_double(v[i], sizeof v[i], x[i]);
        int e = snprintf(buf + k, len - (size_t)k, "effects shutter %s line_delay %s aperture %s focus %s samples %s\n",
                         v[0], v[1], v[2], v[3], v[4]);
        if (e < 0 || (size_t)e >= len - (size_t)k)
            return -1;
        k += e;
    }
    /* the digest of the input files (bundle, camera files, trajectory,
     * motions), so that --resume does not take a frame of another scene
     * or pose; "-" when one of them could not be read a second time */
    return append(buf, len, &k, "inputs %s\n", inputs);
}

int gls_frame_record_matches(const char *path, const char *text)
{
    size_t n = strlen(text), len;
    gls_read_error e;
    char *got = gls_file_read(path, n, &len, &e);
    int same = got && len == n && memcmp(got, text, n) == 0;
    free(got);
    return same;
}

/* the files' part: the bundle, then every camera file */
static void *inputs_files(void *arg)
{
    gls_inputs_job *j = arg;
    j->h = GLS_DIGEST_INIT;
    j->ok = gls_digest_file(&j->h, j->bundle) == 0;
    for (size_t i = 0; j->ok && i < j->ncameras; i++)
        j->ok = gls_digest_file(&j->h, j->cameras[i]) == 0;
    return NULL;
}

void gls_frame_inputs_start(gls_inputs_job *j, const gls_play_opts *o)
{
    j->bundle = o->bundle, j->cameras = o->cameras, j->ncameras = o->ncameras;
    j->threaded = pthread_create(&j->th, NULL, inputs_files, j) == 0;
    if (!j->threaded)
        inputs_files(j);
}

void gls_frame_inputs_join(gls_inputs_job *j)
{
    if (j->threaded)
        pthread_join(j->th, NULL);
    j->threaded = 0;
}

void gls_frame_inputs_finish(gls_inputs_job *j, const gls_play_opts *o, const gls_traj_text *traj, char out[17])
{
    gls_frame_inputs_join(j);
    uint64_t h = j->h;
    int ok = j->ok;
    if (ok && traj) /* the bytes read once (a pipe too), as a file's */
        h = gls_digest_sized(h, traj->data, traj->len);
    for (size_t i = 0; ok && i < o->nmotions; i++) {
        const char *eq = strchr(o->motions[i], '=');
        size_t n = eq ? (size_t)(eq - o->motions[i]) : strlen(o->motions[i]);
        h = gls_digest_bytes(h, o->motions[i], n + 1); /* the name and its '=' */
        ok = eq && gls_digest_file(&h, eq + 1) == 0;
    }
    if (o->flatten) /* the flattened path rounds edges its own way */
        h = gls_digest_bytes(h, "flatten", 7);
    if (ok)
        snprintf(out, 17, "%016llx", (unsigned long long)h);
    else
        snprintf(out, 17, "-");
}
