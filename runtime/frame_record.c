/* Completion records of the player's outputs (frame_record.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "frame_record.h"
#include "numfmt.h"
#include "readfile.h"

int gls_frame_record_path(char *buf, size_t len, const char *outdir, const char *name, uint32_t frame)
{
    return gls_output_path(buf, len, outdir, name, ".frame", frame, "done");
}

int gls_frame_record_text(char *buf, size_t len, const gls_play_opts *o, const gls_camera *c, const char *name,
                          uint32_t frame)
{
    static const char *const fmt[] = {"png8", "png16", "pfm"};
    char sigma[32], bg[3][32];
    gls_fmt_double(sigma, sizeof sigma, o->aa.sigma);
    for (int i = 0; i < 3; i++)
        gls_fmt_float(bg[i], sizeof bg[i], o->background[i]);
    unsigned out = o->outputs;
    int image = (out & GLS_OUT_IMAGE) != 0;
    /* the anti-aliasing that shapes the image and mask: nothing but N when
     * N is 1, nothing at all when neither is written (depth and points
     * come from the unjittered pass) */
    char aa[128];
    uint32_t n = o->aa.n ? o->aa.n : 1;
    if (n == 1 || !(out & (GLS_OUT_IMAGE | GLS_OUT_MASK)))
        snprintf(aa, sizeof aa, "1");
    else
        snprintf(aa, sizeof aa, "%u %s%s%s %s %llu", n, o->aa.filter == GLS_AA_GAUSS ? "gauss" : "box",
                 o->aa.filter == GLS_AA_GAUSS ? ":" : "", o->aa.filter == GLS_AA_GAUSS ? sigma : "",
                 o->aa.pattern == GLS_AA_STRATIFIED ? "stratified" : "grid",
                 (unsigned long long)(o->aa.pattern == GLS_AA_STRATIFIED ? o->aa.seed : 0));
    int k = snprintf(buf, len,
                     "glsplay frame record 1\n"
                     "frame %u\n"
                     "camera %s %ux%u\n"
                     "outputs%s%s%s%s\n"
                     "image-format %s\n"
                     "aa %s\n"
                     "anisotropic %u\n"
                     "background %s %s %s\n",
                     frame, name, c->width, c->height, out & GLS_OUT_IMAGE ? " image" : "",
                     out & GLS_OUT_DEPTH ? " depth" : "", out & GLS_OUT_POINTS ? " points" : "",
                     out & GLS_OUT_MASK ? " mask" : "", image ? fmt[o->image_format] : "-", aa,
                     o->anisotropy > 1 ? o->anisotropy : 1, bg[0], bg[1], bg[2]);
    return k < 0 || (size_t)k >= len ? -1 : 0;
}

int gls_frame_record_matches(const char *path, const char *text)
{
    size_t n = strlen(text), len;
    gls_read_error e;
    char *got = gls_file_read(path, n, GLS_READ_REGULAR, &len, &e);
    int same = got && len == n && memcmp(got, text, n) == 0;
    free(got);
    return same;
}
