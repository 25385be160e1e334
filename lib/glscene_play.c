/* glsplay's whole job as library calls (include/glscene.h, "The player's
 * full options"): a run takes glsplay's command-line arguments one at a
 * time, checks them against each other, and renders and writes what they
 * ask for through the runtime's player (runtime/play/player.c).  glsplay's
 * main is these calls and its help text, nothing else, so that the tool
 * and a program driving the library share one parser and one set of
 * messages (tests/e2e/glsplay_public_api.sh checks that glsplay_main.o
 * reaches the renderer through glscene_* alone). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "choice.h"
#include "glscene_internal.h"
#include "occlusion.h"
#include "player.h"
#include "trajectory.h"

struct glscene_play {
    gls_play_opts o;     /* what gls_play runs; its strings are copies  */
    char **strs;         /* the copies, freed with the run              */
    size_t nstrs, strs_cap;
    const char **cams, **mots; /* o.cameras, o.motions                  */
    size_t cams_cap, mots_cap;
    int frames;          /* --frames given (needs --trajectory)         */
    double subpixel;     /* --subpixel A, 0: not given                  */
    int have_aa, have_samples;
    int checked;         /* glscene_play_check passed since the last arg */
    char *msg;           /* the last failure's whole message            */
};

/* Keep the whole message in r->msg (glscene_play_message) and as much as
 * fits in e; returns rc. */
__attribute__((format(printf, 4, 5))) static int play_fail(glscene_play *r, glscene_error *e, int rc, const char *fmt,
                                                            ...)
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

/* A copy of s that lives as long as r; NULL (with e) when out of memory. */
static char *keep(glscene_play *r, glscene_error *e, const char *s)
{
    char *c = NULL;
    if (gls_grow(&r->strs, &r->strs_cap, r->nstrs + 1, sizeof *r->strs) == 0 && (c = strdup(s)))
        r->strs[r->nstrs++] = c;
    if (!c)
        play_fail(r, e, -2, "out of memory");
    return c;
}

/* Append a copy of s to the list *arr of *n strings; 0, or -1 with e. */
static int add_string(glscene_play *r, glscene_error *e, const char ***arr, size_t *n, size_t *cap, const char *s)
{
    const char *c = keep(r, e, s);
    if (!c || gls_grow(arr, cap, *n + 1, sizeof **arr)) {
        if (c)
            play_fail(r, e, -2, "out of memory");
        return -1;
    }
    (*arr)[(*n)++] = c;
    return 0;
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
    o->progress = GLS_PROGRESS_OFF;
    return r;
}

void glscene_play_free(glscene_play *r)
{
    if (!r)
        return;
    for (size_t i = 0; i < r->nstrs; i++)
        free(r->strs[i]);
    free(r->strs);
    free(r->cams);
    free(r->mots);
    free(r->msg);
    free(r);
}

const char *glscene_play_message(const glscene_play *r)
{
    return r && r->msg ? r->msg : "";
}


/* The message of an option with a fixed set of words (choice.h); bad NULL:
 * no value given.  Returns -1. */
static int choice_fail(glscene_play *r, glscene_error *e, const char *a, int list, const char *bad, size_t badlen,
                       const char *const *words, size_t n)
{
    char m[2048];
    gls_choice_message(m, sizeof m, a, list, bad, badlen, words, n);
    return play_fail(r, e, -1, "%s", m);
}

/* --outputs LIST: 0 with *bits, or -1 after the message naming the first
 * word that is no output.  The words are the output table's
 * (output_table.h), listed in its order; mask, taken but not listed. */
static int parse_outputs(glscene_play *r, glscene_error *e, const char *s, unsigned *bits)
{
    const char *words[GLS_OUT_KINDS];
    size_t listed = gls_output_words(words, GLS_OUT_KINDS, 0);
    *bits = 0;
    for (const char *w = s ? s : ""; *w;) {
        size_t len = strcspn(w, ",");
        if (len) {
            unsigned b = gls_output_word_bits(w, len);
            if (!b)
                return choice_fail(r, e, "--outputs", 1, w, len, words, listed);
            *bits |= b;
        }
        w += len + (w[len] == ',');
    }
    return *bits ? 0 : choice_fail(r, e, "--outputs", 1, NULL, 0, words, listed);
}

/* Option a's value val (NULL: none given) as one of words[0..n): its
 * index, or -1 after the message. */
static int choose(glscene_play *r, glscene_error *e, const char *a, const char *val, const char *const *words,
                  size_t n)
{
    int i = val ? gls_choice_find(val, strlen(val), words, n) : -1;
    return i >= 0 ? i : choice_fail(r, e, a, 0, val, val ? strlen(val) : 0, words, n);
}

/* --progress's words, and whether an argument after --progress is meant
 * as one: a bare word, no path (no '.' or '/') and no option, so that
 * "--progress xml" is refused rather than taken for the bundle (a bundle
 * has a name with a dot, NAME.glsb, or a path) */
static const char *const progress_words[] = {"bar", "json"};
static int progress_word(const char *next)
{
    return next && next[0] && next[0] != '-' && !strpbrk(next, "./");
}

static int parse_size(const char *s, uint32_t *w, uint32_t *h)
{
    char *e;
    errno = 0;
    unsigned long a = strtoul(s, &e, 10);
    if (e == s || (*e != 'x' && *e != 'X') || s[0] == '-' || s[0] == '+')
        return -1;
    const char *s2 = e + 1;
    if (*s2 == '-' || *s2 == '+')
        return -1;
    unsigned long b = strtoul(s2, &e, 10);
    if (e == s2 || *e || errno || a < 1 || b < 1 || a > GLS_CAMERA_MAX_DIM || b > GLS_CAMERA_MAX_DIM)
        return -1;
    *w = (uint32_t)a;
    *h = (uint32_t)b;
    return 0;
}

/* Whole unsigned decimal number in lo..hi. */
static int parse_uint(const char *s, unsigned long long lo, unsigned long long hi, unsigned long long *v)
{
    char *e;
    errno = 0;
    if (!s[0] || s[0] == '-' || s[0] == '+')
        return -1;
    unsigned long long x = strtoull(s, &e, 10);
    if (*e || errno || x < lo || x > hi)
        return -1;
    *v = x;
    return 0;
}

/* Positive finite number; "1/256" is accepted as a fraction. */
static int parse_pos(const char *s, double *v)
{
    char *e;
    double a = strtod(s, &e);
    if (e == s)
        return -1;
    if (*e == '/') {
        const char *s2 = e + 1;
        double b = strtod(s2, &e);
        if (e == s2 || !(b > 0))
            return -1;
        a /= b;
    }
    if (*e || !(a > 0) || a > 1e9)
        return -1;
    *v = a;
    return 0;
}

static int parse_filter(const char *s, gls_aa_opts *o)
{
    if (strcmp(s, "box") == 0) {
        o->filter = GLS_AA_BOX;
        return 0;
    }
    if (strncmp(s, "gauss", 5) == 0 && (s[5] == 0 || s[5] == ':')) {
        o->filter = GLS_AA_GAUSS;
        return s[5] == ':' ? parse_pos(s + 6, &o->sigma) : 0;
    }
    return -1;
}

int glscene_play_arg(glscene_play *r, const char *a, const char *next, glscene_error *e)
{
    if (!r || !a) {
        gls_api_fail(e, "glscene_play_arg: a NULL run or argument");
        return -2;
    }
    gls_play_opts *o = &r->o;
    int has_val = next != NULL;
    const char *val = has_val ? next : "";
    r->checked = 0;
    if (strcmp(a, "--camera") == 0 || strcmp(a, "-c") == 0) {
        if (!has_val)
            return play_fail(r, e, -1, "%s needs a camera file", a);
        if (add_string(r, e, &r->cams, &o->ncameras, &r->cams_cap, next))
            return -2;
        o->cameras = r->cams;
        return 2;
    } else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
        if (!has_val)
            return play_fail(r, e, -1, "%s needs an output directory", a);
        if (o->outdir)
            return play_fail(r, e, -1, "%s given twice", a);
        /* "" would make OUTDIR/NAME the absolute path /NAME */
        if (!next[0])
            return play_fail(r, e, -1, "%s needs a non-empty output directory", a);
        return (o->outdir = keep(r, e, next)) ? 2 : -2;
    } else if (strcmp(a, "--outputs") == 0) {
        return parse_outputs(r, e, next, &o->outputs) ? -1 : 2;
    } else if (strcmp(a, "--size") == 0) {
        if (!has_val || parse_size(next, &o->width, &o->height))
            return play_fail(r, e, -1, "--size needs WxH with both in 1..16384, got '%s'", val);
        return 2;
    } else if (strcmp(a, "--aa") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 1, GLS_AA_MAX_N, &v))
            return play_fail(r, e, -1, "--aa needs N in 1..4096, got '%s'", val);
        o->aa.n = (uint32_t)v;
        r->have_aa = 1;
        return 2;
    } else if (strcmp(a, "--samples") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 1, GLS_AA_MAX_SAMPLES, &v))
            return play_fail(r, e, -1, "--samples needs M in 1..16777216, got '%s'", val);
        o->aa.samples = v;
        r->have_samples = 1;
        return 2;
    } else if (strcmp(a, "--aa-memory") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 16, 1048576, &v))
            return play_fail(r, e, -1, "--aa-memory needs MB in 16..1048576, got '%s'", val);
        o->aa_memory = (uint64_t)v << 20;
        return 2;
    } else if (strcmp(a, "--subpixel") == 0) {
        if (!has_val || parse_pos(next, &r->subpixel) || r->subpixel > 1)
            return play_fail(r, e, -1, "--subpixel needs an accuracy in pixels, 0 < A <= 1 (e.g. 1/256), got '%s'",
                             val);
        return 2;
    } else if (strcmp(a, "--filter") == 0) {
        static const char *const filters[] = {"box", "gauss", "gauss:SIGMA"};
        if (!has_val || parse_filter(next, &o->aa))
            return choice_fail(r, e, a, 0, next, has_val ? strlen(next) : 0, filters, 3);
        return 2;
    } else if (strcmp(a, "--pattern") == 0) {
        static const char *const words[] = {"lattice", "grid", "stratified"};
        static const gls_aa_pattern pattern[] = {GLS_AA_LATTICE, GLS_AA_GRID, GLS_AA_STRATIFIED};
        int i = choose(r, e, a, next, words, 3);
        if (i < 0)
            return -1;
        o->aa.pattern = pattern[i];
        return 2;
    } else if (strcmp(a, "--seed") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 0, UINT64_MAX, &v))
            return play_fail(r, e, -1, "--seed needs an unsigned integer, got '%s'", val);
        o->aa.seed = v;
        return 2;
    } else if (strcmp(a, "--aa-tiles") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 1, 256, &v))
            return play_fail(r, e, -1, "--aa-tiles needs K in 1..256, got '%s'", val);
        o->aa_tiles = (uint32_t)v;
        return 2;
    } else if (strcmp(a, "--writer-threads") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 0, 1, &v))
            return play_fail(r, e, -1, "--writer-threads needs 0 or 1, got '%s'", val);
        o->writer_threads = (unsigned)v;
        return 2;
    } else if (strcmp(a, "--occlusion") == 0) {
        static const char *const words[] = {"auto", "on", "off"};
        static const int mode[] = {GLS_OCCLUSION_AUTO, GLS_OCCLUSION_ON, GLS_OCCLUSION_OFF};
        int i = choose(r, e, a, next, words, 3);
        if (i < 0)
            return -1;
        o->occlusion = mode[i];
        return 2;
    } else if (strcmp(a, "--anisotropic") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 1, 16, &v))
            return play_fail(r, e, -1, "--anisotropic needs N in 1..16, got '%s'", val);
        o->anisotropy = (uint32_t)v;
        return 2;
    } else if (strcmp(a, "--backend") == 0) {
        const char *words[GLS_BACKEND_OSMESA + 1];
        for (int i = 0; i <= GLS_BACKEND_OSMESA; i++)
            words[i] = gls_backend_name((gls_backend)i);
        if (choose(r, e, a, next, words, GLS_BACKEND_OSMESA + 1) < 0)
            return -1;
        gls_backend_parse(next, &o->backend);
        /* asked for by name but not in this build: said before any
           input is read, like an option this glsplay lacks */
        if (!gls_backend_built(o->backend))
            return play_fail(r, e, -2, "--backend %s: this glsplay was built without %s: %s", next,
                             o->backend == GLS_BACKEND_OSMESA ? "OSMesa" : "EGL", gls_backend_missing(o->backend));
        return 2;
    } else if (strcmp(a, "--image-format") == 0) {
        /* "png" is taken for png8 but not listed */
        static const char *const words[] = {"png8", "png16", "pfm", "png"};
        static const gls_image_format format[] = {GLS_IMG_PNG8, GLS_IMG_PNG16, GLS_IMG_PFM, GLS_IMG_PNG8};
        int i = has_val ? gls_choice_find(next, strlen(next), words, 4) : -1;
        if (i < 0)
            return choice_fail(r, e, a, 0, next, has_val ? strlen(next) : 0, words, 3);
        o->image_format = format[i];
        return 2;
    } else if (strcmp(a, "--depth-scale") == 0) {
        const char *v = val;
        if (strcmp(v, "kitti") == 0)
            o->depth_scale = GLS_DEPTH_SCALE_KITTI;
        else if (strcmp(v, "tum") == 0)
            o->depth_scale = GLS_DEPTH_SCALE_TUM;
        else if (parse_pos(v, &o->depth_scale))
            return play_fail(r, e, -1, "--depth-scale needs a positive number, kitti (256) or tum (5000), got '%s'", val);
        return 2;
    } else if (strcmp(a, "--float-format") == 0) {
        static const char *const words[] = {"pfm", "npy"};
        static const gls_float_format format[] = {GLS_FLOAT_PFM, GLS_FLOAT_NPY};
        int i = choose(r, e, a, next, words, 2);
        if (i < 0)
            return -1;
        o->float_format = format[i];
        return 2;
    } else if (strcmp(a, "--explain") == 0) {
        o->explain = 1;
        return 1;
    } else if (strcmp(a, "--write-calib") == 0) {
        o->write_calib = 1;
        return 1;
    } else if (strcmp(a, "--resume") == 0) {
        o->resume = 1;
        return 1;
    } else if (strcmp(a, "--flatten") == 0) {
        o->flatten = 1;
        return 1;
    } else if (strcmp(a, "--motion") == 0) {
        const char *eq = has_val ? strchr(next, '=') : NULL;
        if (!eq || eq == next || !eq[1])
            return play_fail(r, e, -1, "--motion needs NAME=FILE, got '%s'", val);
        if (add_string(r, e, &r->mots, &o->nmotions, &r->mots_cap, next))
            return -2;
        o->motions = r->mots;
        return 2;
    } else if (strcmp(a, "--progress") == 0 || strncmp(a, "--progress=", 11) == 0) {
        /* an optional value: --progress=WORD, or a bare word after it
           (progress_word); --progress alone is the bar */
        const char *w = a[10] == '=' ? a + 11 : progress_word(next) ? next : NULL;
        int i = w ? choose(r, e, "--progress", w, progress_words, 2) : 0;
        if (i < 0)
            return -1;
        o->progress = i == 1 ? GLS_PROGRESS_JSON : GLS_PROGRESS_BAR;
        return w == next ? 2 : 1;
    } else if (strcmp(a, "--shard") == 0) {
        char msg[512];
        if (!has_val)
            return play_fail(r, e, -1, "--shard needs I/N with 0 <= I < N (or slurm)");
        if (gls_shard_parse(next, getenv, &o->shard, msg, sizeof msg))
            return play_fail(r, e, -1, "%s", msg);
        return 2;
    } else if (strcmp(a, "--trajectory") == 0) {
        if (!has_val || !next[0])
            return play_fail(r, e, -1, "--trajectory needs a trajectory file");
        return (o->trajectory = keep(r, e, next)) ? 2 : -2;
    } else if (strcmp(a, "--frames") == 0) {
        char msg[256];
        if (!has_val || gls_traj_range(next, &o->frame_first, &o->frame_end, msg, sizeof msg))
            return play_fail(r, e, -1, "--frames needs A:B, A:, :B or A (frames A..B-1), got '%s'", val);
        r->frames = 1;
        return 2;
    } else if (strcmp(a, "--frame") == 0) {
        unsigned long long v;
        if (!has_val || parse_uint(next, 0, UINT32_MAX, &v))
            return play_fail(r, e, -1, "--frame needs a frame number 0..4294967295, got '%s'", val);
        o->frame = (uint32_t)v;
        return 2;
    } else if (strcmp(a, "--background") == 0) {
        float c[3];
        char tail;
        if (!has_val || sscanf(next, "%f,%f,%f%c", &c[0], &c[1], &c[2], &tail) != 3 ||
            !(c[0] >= 0 && c[0] <= 1 && c[1] >= 0 && c[1] <= 1 && c[2] >= 0 && c[2] <= 1))
            return play_fail(r, e, -1, "--background needs R,G,B with components in 0..1, got '%s'", val);
        memcpy(o->background, c, sizeof c);
        return 2;
    } else if (a[0] == '-' && a[1])
        return play_fail(r, e, -1, "unknown option '%s'", a);
    else if (!a[0]) /* names no file (spec/exit_status.md) */
        return play_fail(r, e, -1, "an empty bundle name");
    else if (!o->bundle) {
        return (o->bundle = keep(r, e, a)) ? 1 : -2;
    } else 
        return play_fail(r, e, -1, "more than one bundle given ('%s')", a);
}

int glscene_play_check(glscene_play *r, glscene_error *e)
{
    if (!r)
        return gls_api_fail(e, "glscene_play_check: a NULL run");
    gls_play_opts *o = &r->o;
    if (r->have_aa + r->have_samples + (r->subpixel > 0) > 1) {
        return play_fail(r, e, -1, "--aa, --samples and --subpixel all choose the samples; give one");
    }
    if (r->have_samples && o->aa.pattern != GLS_AA_LATTICE) {
        unsigned long long root = (unsigned long long)sqrt((double)o->aa.samples);
        if (root * root != o->aa.samples) {
            char m[32];
            snprintf(m, sizeof m, "%llu", (unsigned long long)o->aa.samples);
            return play_fail(r, e, -1, o->aa.pattern == GLS_AA_GRID
                                 ? "--pattern grid needs a square --samples (N x N), got %s; the lattice takes any M"
                                 : "--pattern stratified needs a square --samples (N x N), got %s; the lattice takes any M",
                             m);
        }
    }
    if (r->subpixel > 0) {
        o->aa.n = gls_aa_n_for_accuracy(o->aa.filter, o->aa.pattern, o->aa.sigma, r->subpixel);
        if (!o->aa.n)
            return play_fail(r, e, -1, "--subpixel given needs a window larger than 4096x4096");
    }
    /* one sample per pixel: no pixel is mixed, the map would be all 0 */
    if ((o->outputs & GLS_OUT_EDGE_MAPS) && (o->aa.samples ? o->aa.samples : (uint64_t)o->aa.n * o->aa.n) <= 1)
        return play_fail(r, e, -1, "--outputs %s needs anti-aliasing, --aa N with N > 1",
                         o->outputs & GLS_OUT_EDGES ? "edges" : "mask");
    if (!o->bundle)
        return play_fail(r, e, -1, "no bundle given");
    /* the flattened path inlines every call: there is no instance to move */
    if (o->flatten && o->nmotions) {
        return play_fail(r, e, -1, "--motion moves instances, and --flatten draws none; leave out --flatten");
    }
    /* flow goes from each frame of a trajectory to the next */
    if ((o->outputs & GLS_OUT_FLOW_ALL) && !o->trajectory)
        return play_fail(r, e, -1, "--outputs flow needs a --trajectory: the flow goes from each frame to the next");
    if (r->frames && !o->trajectory) {
        return play_fail(r, e, -1, "--frames selects frames of a --trajectory; for a single render use --frame N");
    }
    if (!o->explain && !o->outdir)
        return play_fail(r, e, -1, "no output directory given (-o OUTDIR), and no --explain");
    if (o->write_calib && !o->outdir)
        return play_fail(r, e, -1, "--write-calib writes into the output directory: give -o OUTDIR");
    if (o->outdir && o->ncameras == 0)
        return play_fail(r, e, -1, "no camera given (--camera CAM)");
    /* what the runtime refuses from the options alone (two cameras for
       disparity, their output names, ...): usage errors too */
    char msg[2048];
    if (gls_play_check_options(o, msg, sizeof msg))
        return play_fail(r, e, -1, "%s", msg);
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
