/* glscene_play_arg: glsplay's command-line arguments, one table of its
 * options (options[] below) whose rows say how each takes its value, so
 * that an option is added in one row and the messages of a kind of value
 * are made in one place.  The checks between arguments are
 * glscene_play.c's. */
#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "choice.h"
#include "glscene_internal.h"
#include "glscene_play_run.h"
#include "occlusion.h"
#include "trajectory.h"

/* Append a copy of s to the list *arr of *n strings; 0, or -1 with e. */
static int add_string(glscene_play *r, glscene_error *e, const char ***arr, size_t *n, size_t *cap, const char *s)
{
    const char *c = gls_play_keep(r, e, s);
    if (!c || gls_grow(arr, cap, *n + 1, sizeof **arr)) {
        if (c)
            gls_play_fail(r, e, -2, "out of memory");
        return -1;
    }
    (*arr)[(*n)++] = c;
    return 0;
}

/* The message of an option with a fixed set of words (choice.h); bad NULL:
 * no value given.  Returns -1. */
static int choice_fail(glscene_play *r, glscene_error *e, const char *a, int list, const char *bad, size_t badlen,
                       const char *const *words, size_t n)
{
    char m[2048];
    gls_choice_message(m, sizeof m, a, list, bad, badlen, words, n);
    return gls_play_fail(r, e, -1, "%s", m);
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

/* The options, one row each (the table below): how an option takes its
 * value is its row's take function, the kind; the generic kinds read what
 * the row says, the others are an option's own.  Each returns as
 * glscene_play_arg does: the arguments taken (1 or 2), or -1 or -2 after
 * the message. */
typedef struct option option;
typedef int take_fn(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e);
struct option {
    const char *name, *alias;
    take_fn *take;
    int eq;                  /* also --NAME=VALUE (only --progress)      */
    /* take_uint, take_value: refused as "NAME needs NEED, got 'V'"      */
    const char *need;
    unsigned long long lo, hi;                          /* take_uint     */
    void (*set)(glscene_play *r, unsigned long long v); /* take_uint: the
                                number; take_choice: the word's index   */
    int (*read)(glscene_play *r, const char *v);        /* take_value: 0,
                                                           or -1: refused */
    const char *const *words;                           /* take_choice:  */
    size_t nwords, nlisted;  /* the words taken, and the first nlisted of
                                them named in the message               */
    size_t flag;             /* take_flag: offsetof the int set to 1     */
};

/* --explain, --times, --write-calib, --resume, --flatten */
static int take_flag(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)a, (void)next, (void)e;
    *(int *)((char *)&r->o + op->flag) = 1;
    return 1;
}

/* A whole number in op->lo..op->hi */
static int take_uint(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)a;
    unsigned long long v;
    if (!next || parse_uint(next, op->lo, op->hi, &v))
        return gls_play_fail(r, e, -1, "%s needs %s, got '%s'", op->name, op->need, next ? next : "");
    op->set(r, v);
    return 2;
}

/* --aa: N, exact (exact coverage) or auto (the default: exact where the
 * run allows it; spec/antialiasing.md "The default") */
static int take_aa(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    if (next && (strcmp(next, "exact") == 0 || strcmp(next, "auto") == 0)) {
        r->o.aa.exact = next[0] == 'e' ? GLS_AA_EXACT : GLS_AA_AUTO, r->o.aa.n = 1, r->have_aa = 1;
        return 2;
    }
    return take_uint(r, op, a, next, e);
}

/* A value op->read reads */
static int take_value(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)a;
    if (!next || op->read(r, next))
        return gls_play_fail(r, e, -1, "%s needs %s, got '%s'", op->name, op->need, next ? next : "");
    return 2;
}

/* One of op->words */
static int take_choice(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    int i = next ? gls_choice_find(next, strlen(next), op->words, op->nwords) : -1;
    if (i < 0)
        return choice_fail(r, e, a, 0, next, next ? strlen(next) : 0, op->words, op->nlisted);
    op->set(r, (unsigned long long)i);
    return 2;
}

/* samples asked for: --aa N, --samples M (and --subpixel, glscene_play_check) */
static void set_aa(glscene_play *r, unsigned long long v)
{
    r->o.aa.n = (uint32_t)v, r->o.aa.exact = GLS_AA_SAMPLED, r->have_aa = 1;
}
static void set_samples(glscene_play *r, unsigned long long v)
{
    r->o.aa.samples = v, r->o.aa.exact = GLS_AA_SAMPLED, r->have_samples = 1;
}
static void set_aa_memory(glscene_play *r, unsigned long long v) { r->o.aa_memory = (uint64_t)v << 20; }
static void set_seed(glscene_play *r, unsigned long long v) { r->o.aa.seed = v; }
static void set_aa_tiles(glscene_play *r, unsigned long long v) { r->o.aa_tiles = (uint32_t)v; }
static void set_writer_threads(glscene_play *r, unsigned long long v) { r->o.writer_threads = (unsigned)v; }
static void set_anisotropic(glscene_play *r, unsigned long long v) { r->o.anisotropy = (uint32_t)v; }
static void set_frame(glscene_play *r, unsigned long long v) { r->o.frame = (uint32_t)v; }

static int read_size(glscene_play *r, const char *v) { return parse_size(v, &r->o.width, &r->o.height); }
static int read_subpixel(glscene_play *r, const char *v) { return parse_pos(v, &r->subpixel) || r->subpixel > 1; }
static int read_depth_scale(glscene_play *r, const char *v)
{
    if (strcmp(v, "kitti") == 0)
        r->o.depth_scale = GLS_DEPTH_SCALE_KITTI;
    else if (strcmp(v, "tum") == 0)
        r->o.depth_scale = GLS_DEPTH_SCALE_TUM;
    else
        return parse_pos(v, &r->o.depth_scale);
    return 0;
}
static int read_frames(glscene_play *r, const char *v)
{
    char msg[256];
    if (gls_traj_range(v, &r->o.frame_first, &r->o.frame_end, msg, sizeof msg))
        return -1;
    r->frames = 1;
    return 0;
}
static int read_background(glscene_play *r, const char *v)
{
    float c[3];
    char tail;
    if (sscanf(v, "%f,%f,%f%c", &c[0], &c[1], &c[2], &tail) != 3 ||
        !(c[0] >= 0 && c[0] <= 1 && c[1] >= 0 && c[1] <= 1 && c[2] >= 0 && c[2] <= 1))
        return -1;
    memcpy(r->o.background, c, sizeof c);
    return 0;
}

static const char *const pattern_words[] = {"lattice", "grid", "stratified"};
static void set_pattern(glscene_play *r, unsigned long long i)
{
    static const gls_aa_pattern pattern[] = {GLS_AA_LATTICE, GLS_AA_GRID, GLS_AA_STRATIFIED};
    r->o.aa.pattern = pattern[i];
}
static const char *const occlusion_words[] = {"auto", "on", "off"};
static void set_occlusion(glscene_play *r, unsigned long long i)
{
    static const int mode[] = {GLS_OCCLUSION_AUTO, GLS_OCCLUSION_ON, GLS_OCCLUSION_OFF};
    r->o.occlusion = mode[i];
}
/* "png" is taken for png8 but not listed */
static const char *const image_format_words[] = {"png8", "png16", "pfm", "png"};
static void set_image_format(glscene_play *r, unsigned long long i)
{
    static const gls_image_format format[] = {GLS_IMG_PNG8, GLS_IMG_PNG16, GLS_IMG_PFM, GLS_IMG_PNG8};
    r->o.image_format = format[i];
}
static const char *const float_format_words[] = {"pfm", "npy"};
static void set_float_format(glscene_play *r, unsigned long long i)
{
    static const gls_float_format format[] = {GLS_FLOAT_PFM, GLS_FLOAT_NPY};
    r->o.float_format = format[i];
}

int gls_play_add_camera(glscene_play *r, glscene_error *e, const char *path, const char *text)
{
    /* the texts beside the paths, one a camera */
    const char *t = text ? gls_play_keep(r, e, text) : NULL;
    if ((text && !t) || gls_grow(&r->texts, &r->texts_cap, r->o.ncameras + 1, sizeof *r->texts))
        return text && !t ? -1 : gls_play_fail(r, e, -2, "out of memory");
    r->texts[r->o.ncameras] = t;
    if (add_string(r, e, &r->cams, &r->o.ncameras, &r->cams_cap, path))
        return -1;
    r->o.cameras = r->cams;
    r->o.camera_texts = r->texts;
    return 0;
}

/* The options with their own messages or more than a value to store. */
static int take_camera(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op;
    if (!next)
        return gls_play_fail(r, e, -1, "%s needs a camera file", a);
    return gls_play_add_camera(r, e, next, NULL) ? -2 : 2;
}

static int take_output(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op;
    if (!next)
        return gls_play_fail(r, e, -1, "%s needs an output directory", a);
    if (r->o.outdir)
        return gls_play_fail(r, e, -1, "%s given twice", a);
    /* "" would make OUTDIR/NAME the absolute path /NAME */
    if (!next[0])
        return gls_play_fail(r, e, -1, "%s needs a non-empty output directory", a);
    return (r->o.outdir = gls_play_keep(r, e, next)) ? 2 : -2;
}

static int take_outputs(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op, (void)a;
    return parse_outputs(r, e, next, &r->o.outputs) ? -1 : 2;
}

static int take_filter(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op;
    static const char *const filters[] = {"box", "gauss", "gauss:SIGMA"};
    if (!next || parse_filter(next, &r->o.aa))
        return choice_fail(r, e, a, 0, next, next ? strlen(next) : 0, filters, 3);
    return 2;
}

static int take_backend(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op;
    gls_play_opts *o = &r->o;
    const char *words[GLS_BACKEND_OSMESA + 1];
    for (int i = 0; i <= GLS_BACKEND_OSMESA; i++)
        words[i] = gls_backend_name((gls_backend)i);
    if (choose(r, e, a, next, words, GLS_BACKEND_OSMESA + 1) < 0)
        return -1;
    gls_backend_parse(next, &o->backend);
    /* asked for by name but not in this build: said before any
       input is read, like an option this glsplay lacks */
    if (!gls_backend_built(o->backend))
        return gls_play_fail(r, e, -2, "--backend %s: this glsplay was built without %s: %s", next,
                         o->backend == GLS_BACKEND_OSMESA ? "OSMesa" : "EGL", gls_backend_missing(o->backend));
    return 2;
}

static int take_motion(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op, (void)a;
    const char *eq = next ? strchr(next, '=') : NULL;
    if (!eq || eq == next || !eq[1])
        return gls_play_fail(r, e, -1, "--motion needs NAME=FILE, got '%s'", next ? next : "");
    if (add_string(r, e, &r->mots, &r->o.nmotions, &r->mots_cap, next))
        return -2;
    r->o.motions = r->mots;
    return 2;
}

/* An optional value: --progress=WORD, or a bare word after it
   (progress_word); --progress alone is the bar */
static int take_progress(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op;
    int takes_next = a[10] != '=' && progress_word(next);
    const char *w = a[10] == '=' ? a + 11 : takes_next ? next : NULL;
    int i = w ? choose(r, e, "--progress", w, progress_words, 2) : 0;
    if (i < 0)
        return -1;
    r->o.progress = i == 1 ? GLS_PROGRESS_JSON : GLS_PROGRESS_BAR;
    return takes_next ? 2 : 1;
}

static int take_shard(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op, (void)a;
    char msg[512];
    if (!next)
        return gls_play_fail(r, e, -1, "--shard needs I/N with 0 <= I < N (or slurm)");
    if (gls_shard_parse(next, getenv, &r->o.shard, msg, sizeof msg))
        return gls_play_fail(r, e, -1, "%s", msg);
    return 2;
}

static int take_trajectory(glscene_play *r, const option *op, const char *a, const char *next, glscene_error *e)
{
    (void)op, (void)a;
    if (!next || !next[0])
        return gls_play_fail(r, e, -1, "--trajectory needs a trajectory file");
    return (r->o.trajectory = gls_play_keep(r, e, next)) ? 2 : -2;
}

#define UINT(name, need, lo, hi, set) {name, NULL, take_uint, 0, need, lo, hi, set, NULL, NULL, 0, 0, 0}
#define VALUE(name, need, read) {name, NULL, take_value, 0, need, 0, 0, NULL, read, NULL, 0, 0, 0}
#define CHOICE(name, words, nlisted, set) \
    {name, NULL, take_choice, 0, NULL, 0, 0, set, NULL, words, sizeof words / sizeof *words, nlisted, 0}
#define FLAG(name, field) {name, NULL, take_flag, 0, NULL, 0, 0, NULL, NULL, NULL, 0, 0, offsetof(gls_play_opts, field)}
#define OWN(name, alias, take, eq) {name, alias, take, eq, NULL, 0, 0, NULL, NULL, NULL, 0, 0, 0}

/* glsplay's options (its --help lists them) */
static const option options[] = {
    OWN("--camera", "-c", take_camera, 0),
    OWN("-o", "--output", take_output, 0),
    OWN("--outputs", NULL, take_outputs, 0),
    VALUE("--size", "WxH with both in 1..16384", read_size),
    {"--aa", NULL, take_aa, 0, "N in 1..4096, exact or auto", 1, GLS_AA_MAX_N, set_aa, NULL, NULL, 0, 0, 0},
    UINT("--samples", "M in 1..16777216", 1, GLS_AA_MAX_SAMPLES, set_samples),
    UINT("--aa-memory", "MB in 16..1048576", 16, 1048576, set_aa_memory),
    VALUE("--subpixel", "an accuracy in pixels, 0 < A <= 1 (e.g. 1/256)", read_subpixel),
    OWN("--filter", NULL, take_filter, 0),
    CHOICE("--pattern", pattern_words, 3, set_pattern),
    UINT("--seed", "an unsigned integer", 0, UINT64_MAX, set_seed),
    UINT("--aa-tiles", "K in 1..256", 1, 256, set_aa_tiles),
    UINT("--writer-threads", "0 or 1", 0, 1, set_writer_threads),
    CHOICE("--occlusion", occlusion_words, 3, set_occlusion),
    UINT("--anisotropic", "N in 1..16", 1, 16, set_anisotropic),
    OWN("--backend", NULL, take_backend, 0),
    CHOICE("--image-format", image_format_words, 3, set_image_format),
    VALUE("--depth-scale", "a positive number, kitti (256) or tum (5000)", read_depth_scale),
    CHOICE("--float-format", float_format_words, 2, set_float_format),
    FLAG("--explain", explain),
    FLAG("--times", times),
    FLAG("--write-calib", write_calib),
    FLAG("--resume", resume),
    FLAG("--flatten", flatten),
    OWN("--motion", NULL, take_motion, 0),
    OWN("--progress", NULL, take_progress, 1),
    OWN("--shard", NULL, take_shard, 0),
    OWN("--trajectory", NULL, take_trajectory, 0),
    VALUE("--frames", "A:B, A:, :B or A (frames A..B-1)", read_frames),
    UINT("--frame", "a frame number 0..4294967295", 0, UINT32_MAX, set_frame),
    VALUE("--background", "R,G,B with components in 0..1", read_background),
};

/* The row of option a, or NULL */
static const option *find_option(const char *a)
{
    for (size_t i = 0; i < sizeof options / sizeof *options; i++) {
        const option *op = &options[i];
        size_t n = strlen(op->name);
        if (strcmp(a, op->name) == 0 || (op->alias && strcmp(a, op->alias) == 0) ||
            (op->eq && strncmp(a, op->name, n) == 0 && a[n] == '='))
            return op;
    }
    return NULL;
}

int glscene_play_arg(glscene_play *r, const char *a, const char *next, glscene_error *e)
{
    if (!r || !a) {
        gls_api_fail(e, "glscene_play_arg: a NULL run or argument");
        return -2;
    }
    r->checked = 0;
    gls_play_close_run(r); /* a setting changes: the next render begins again */
    const option *op = find_option(a);
    if (op)
        return op->take(r, op, a, next, e);
    if (a[0] == '-' && a[1])
        return gls_play_fail(r, e, -1, "unknown option '%s'", a);
    if (!a[0]) /* names no file (spec/exit_status.md) */
        return gls_play_fail(r, e, -1, "an empty bundle name");
    if (r->o.bundle)
        return gls_play_fail(r, e, -1, "more than one bundle given ('%s')", a);
    return (r->o.bundle = gls_play_keep(r, e, a)) ? 1 : -2;
}
