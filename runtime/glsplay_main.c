/* glsplay: render a compiled glscene bundle through OpenCV pinhole
 * cameras.  Argument parsing only; the work is gls_play() (player.c). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "player.h"
#include "stdout_check.h"
#include "trajectory.h"
#include "usage.h"

static const char usage_text[] =
    "usage: glsplay BUNDLE.glsb --camera CAM [--camera CAM ...] -o OUTDIR [options]\n"
    "       glsplay BUNDLE.glsb [--camera CAM ...] --explain\n"
    "Renders the bundle's top-level object through each camera (spec/camera.md)\n"
    "and writes OUTDIR/NAME/image_000000.png, depth_000000.pfm, points_000000.ply\n"
    "where NAME is the camera file name without .cam (or .yml, .yaml: an OpenCV\n"
    "camera file, spec/camera.md).\n"
    "options:\n"
    "  --camera CAM, -c CAM   camera file (repeatable)\n"
    "  -o OUTDIR              output directory (created if missing)\n"
    "  --outputs LIST         comma-separated subset of image,depth,points,edges,\n"
    "                         disparity,disparity16,depth16,landmarks,instance,class,\n"
    "                         coco,normals,flow,boxes (default image,depth,points;\n"
    "                         spec/outputs.md):\n"
    "                         edges: edges_F.png, 255 where a pixel's anti-aliasing\n"
    "                         samples differ, i.e. it straddles an edge; it needs --aa N\n"
    "                         with N > 1 (mask: the same map as mask_F.png, its old\n"
    "                         name, for one release)\n"
    "                         disparity: fx B / Zc (float, +inf: no surface), for a\n"
    "                         rectified pair: exactly two cameras, the left one first;\n"
    "                         disparity16: the same as KITTI's 16-bit PNG (d * 256)\n"
    "                         depth16: 16-bit PNG of Zc * --depth-scale, 0: no surface\n"
    "                         landmarks: the scene's marks projected, landmarks_F.csv\n"
    "                         ground truth from the pixel centres, never blended:\n"
    "                         instance and class (16-bit PNG ids, with\n"
    "                         instances_F.json), coco (COCO JSON, RLE masks),\n"
    "                         normals (camera-frame, float)\n"
    "                         flow: optical flow to the trajectory's next frame,\n"
    "                         flow_F.png (KITTI), flow_F.flo (Middlebury),\n"
    "                         flowmask_F.png (0 no surface, 1 visible, 2 occluded,\n"
    "                         3 out of view), needs --trajectory\n"
    "                         boxes: each visible instance's 2D and 3D box,\n"
    "                         boxes_F.txt (KITTI labels), boxes_F.json\n"
    "  --depth-scale S        depth16's scale: a positive number, kitti (256, the\n"
    "                         default) or tum (5000)\n"
    "  --float-format F       pfm (default) or npy (NumPy float32): the file format of\n"
    "                         depth, disparity, normals and the image with\n"
    "                         --image-format pfm\n"
    "  --size WxH             override every camera's width and height\n"
    "  --write-calib          also write the cameras' calibration (spec/outputs.md):\n"
    "                         NAME/calib_F.yml (OpenCV), calib_F.json per frame;\n"
    "                         calib.txt (KITTI) and NAME/camera_info.yaml (ROS)\n"
    "  --explain              print the rendering plan; without -o, render nothing\n"
    "  --background R,G,B     colour where no surface is, components 0..1 (default 0,0,0)\n"
    "  --anisotropic N        anisotropic texture filtering up to N x, N in 1..16\n"
    "                         (default 1: off; sharper textures at grazing angles, but\n"
    "                         llvmpipe takes minutes per frame with it: make bench-aa)\n"
    "  --backend B            GL backend (spec/backends.md): auto (default: EGL where\n"
    "                         it gives a context, else OSMesa), egl (a GPU through\n"
    "                         EGL's device platform, else Mesa's surfaceless one),\n"
    "                         egl-device or egl-surfaceless (that platform only),\n"
    "                         osmesa; --explain says which one renders\n"
    "sequences (spec/road.md, \"Trajectory file\"):\n"
    "  --trajectory FILE      render every frame of FILE (glsroad's trajectory.txt, or\n"
    "                         KITTI or TUM poses); each camera file then gives that\n"
    "                         camera's pose relative to the rig\n"
    "  --frames A:B           only frames A..B-1 of the trajectory (also A:, :B, A), so\n"
    "                         consecutive ranges split a sequence across processes\n"
    "  --frame N              the frame number in the file names of a single render\n"
    "                         (default 0)\n"
    "  --motion NAME=FILE     move the named instance NAME by FILE's per-frame pose\n"
    "                         (object-to-parent; glsroad motion, KITTI or TUM rows;\n"
    "                         repeatable; spec/bundle.md section 9.3)\n"
    "  --flatten              draw every call inlined, as one flattened scene (the\n"
    "                         reference path; default: instanced, spec/bundle.md 9.3)\n"
    "  --resume               skip frames that are complete: every camera has the record\n"
    "                         NAME/.frame_F.done, written after its last file, for the\n"
    "                         same outputs and settings, and every file is there\n"
    "  --shard I/N            only the frames F with (F - A) mod N = I, A the first of\n"
    "                         --frames (0 without it): N processes, I = 0..N-1, render a\n"
    "                         sequence between them into one OUTDIR (a single render is\n"
    "                         shard 0's); --shard slurm: I and N from a Slurm job array's\n"
    "                         SLURM_ARRAY_TASK_ID, _COUNT (and _MIN, _STEP)\n"
    "anti-aliasing (spec/antialiasing.md):\n"
    "  --aa N                 NxN samples per pixel, N in 1..4096 (default 1: one pass)\n"
    "  --samples M            M samples per pixel, M in 1..16777216 (lattice: any M;\n"
    "                         grid and stratified: a square)\n"
    "  --subpixel A           the N whose sample step is at most A pixels (A as 1/256 or\n"
    "                         0.004): N = ceil(1/A); grid and stratified Gaussian:\n"
    "                         ceil(6 sigma/A)\n"
    "  --filter box|gauss[:SIGMA]  box: plain average over the pixel (default);\n"
    "                         gauss: Gaussian weights, SIGMA px (default 0.5), window\n"
    "                         +-3 SIGMA\n"
    "  --pattern lattice|grid|stratified   sample points: a rank-1 lattice (default;\n"
    "                         drawn in one pass as a fine framebuffer), a regular grid\n"
    "                         (one pass with the box filter), or one per grid cell\n"
    "                         with deterministic jitter (one GL pass per sample)\n"
    "  --seed S               jitter seed for stratified (default 0)\n"
    "  --image-format F       png8 (default), png16 (16-bit PNG) or pfm (float32 RGB,\n"
    "                         image_F.pfm); 8 bits limit edges to ~1/256 px\n"
    "  --aa-tiles K           stratified and grid Gaussian: samples per GL pass\n"
    "                         (default: automatic)\n"
    "  --aa-memory MB         one-pass patterns: memory for the fine framebuffer's tiles\n"
    "                         and read-backs, MB in 16..1048576 (default 256)\n"
    "progress and time:\n"
    "  on a terminal, stderr shows progress: frames done, frames/s and time left for a\n"
    "  sequence, samples done for a long anti-aliased camera frame\n"
    "  --progress             show it even when stderr is not a terminal\n"
    "  --progress json        instead, one JSON object a line on stderr per camera frame\n"
    "                         written and one at the end, for cluster logs\n"
    "  --writer-threads N     1 (default): encode and write a frame's files on a thread of\n"
    "                         their own while the next frame renders; 0: in turn, on one\n"
    "                         thread.  The files are the same either way\n"
    "  a render projected to take over a minute (timed on its first passes or frames)\n"
    "  prints the estimate on stderr first: \"glsplay: note: estimated render time ...\"\n"
    "  --help                 this text\n"
    "exit status: 0 success, 1 input error, 2 usage error\n";

#define usage_error(...) gls_usage_error("glsplay", " (try glsplay --help)\n", __VA_ARGS__)

static int parse_outputs(const char *s, unsigned *bits)
{
    *bits = 0;
    char tmp[256];
    if (strlen(s) >= sizeof tmp)
        return -1;
    strcpy(tmp, s);
    for (char *save = NULL, *t = strtok_r(tmp, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (strcmp(t, "image") == 0)
            *bits |= GLS_OUT_IMAGE;
        else if (strcmp(t, "depth") == 0)
            *bits |= GLS_OUT_DEPTH;
        else if (strcmp(t, "points") == 0)
            *bits |= GLS_OUT_POINTS;
        else if (strcmp(t, "edges") == 0)
            *bits |= GLS_OUT_EDGES;
        else if (strcmp(t, "mask") == 0) /* edges' old name, for one release */
            *bits |= GLS_OUT_EDGES_AS_MASK;
        else if (strcmp(t, "disparity") == 0)
            *bits |= GLS_OUT_DISPARITY;
        else if (strcmp(t, "disparity16") == 0)
            *bits |= GLS_OUT_DISPARITY16;
        else if (strcmp(t, "depth16") == 0)
            *bits |= GLS_OUT_DEPTH16;
        else if (strcmp(t, "landmarks") == 0)
            *bits |= GLS_OUT_LANDMARKS;
        else if (strcmp(t, "instance") == 0)
            *bits |= GLS_OUT_INSTANCE;
        else if (strcmp(t, "class") == 0)
            *bits |= GLS_OUT_CLASS;
        else if (strcmp(t, "coco") == 0)
            *bits |= GLS_OUT_COCO;
        else if (strcmp(t, "normals") == 0)
            *bits |= GLS_OUT_NORMALS;
        else if (strcmp(t, "flow") == 0)
            *bits |= GLS_OUT_FLOW_ALL;
        else if (strcmp(t, "boxes") == 0)
            *bits |= GLS_OUT_BOXES_ALL;
        else
            return -1;
    }
    return *bits ? 0 : -1;
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

int main(int argc, char **argv)
{
    gls_check_stdout_at_exit("glsplay");
    gls_play_opts o;
    memset(&o, 0, sizeof o);
    o.frame_end = UINT64_MAX;
    o.writer_threads = 1;
    const char *frames = NULL;
    o.outputs = GLS_OUT_IMAGE | GLS_OUT_DEPTH | GLS_OUT_POINTS;
    o.aa = gls_aa_defaults();
    o.progress = isatty(2) ? GLS_PROGRESS_BAR : GLS_PROGRESS_OFF;
    double subpixel = 0;
    int have_aa = 0, have_samples = 0;
    const char **cams = calloc((size_t)argc, sizeof *cams);
    const char **mot = calloc((size_t)argc, sizeof *mot);
    if (!cams || !mot) {
        free(cams);
        free(mot);
        return 1;
    }
    o.cameras = cams;
    o.motions = mot;
    int rc;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int has_val = i + 1 < argc;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(usage_text, stdout);
            free(cams);
            free(mot);
            return 0;
        } else if (strcmp(a, "--camera") == 0 || strcmp(a, "-c") == 0) {
            if (!has_val) {
                rc = usage_error("%s needs a camera file", a);
                goto done;
            }
            cams[o.ncameras++] = argv[++i];
        } else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            if (!has_val) {
                rc = usage_error("%s needs an output directory", a);
                goto done;
            }
            if (o.outdir) {
                rc = usage_error("%s given twice", a);
                goto done;
            }
            /* "" would make OUTDIR/NAME the absolute path /NAME */
            if (!argv[i + 1][0]) {
                rc = usage_error("%s needs a non-empty output directory", a);
                goto done;
            }
            o.outdir = argv[++i];
        } else if (strcmp(a, "--outputs") == 0) {
            if (!has_val || parse_outputs(argv[i + 1], &o.outputs)) {
                rc = usage_error("--outputs needs a comma-separated list of image, depth, points, edges, disparity, "
                                 "disparity16, depth16, landmarks, instance, class, coco, normals, flow, boxes, got '%s'",
                                 has_val ? argv[i + 1] : "");
                goto done;
            }
            i++;
        } else if (strcmp(a, "--size") == 0) {
            if (!has_val || parse_size(argv[i + 1], &o.width, &o.height)) {
                rc = usage_error("--size needs WxH with both in 1..16384, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            i++;
        } else if (strcmp(a, "--aa") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 1, GLS_AA_MAX_N, &v)) {
                rc = usage_error("--aa needs N in 1..4096, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.aa.n = (uint32_t)v;
            have_aa = 1;
            i++;
        } else if (strcmp(a, "--samples") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 1, GLS_AA_MAX_SAMPLES, &v)) {
                rc = usage_error("--samples needs M in 1..16777216, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.aa.samples = v;
            have_samples = 1;
            i++;
        } else if (strcmp(a, "--aa-memory") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 16, 1048576, &v)) {
                rc = usage_error("--aa-memory needs MB in 16..1048576, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.aa_memory = (uint64_t)v << 20;
            i++;
        } else if (strcmp(a, "--subpixel") == 0) {
            if (!has_val || parse_pos(argv[i + 1], &subpixel) || subpixel > 1) {
                rc = usage_error("--subpixel needs an accuracy in pixels, 0 < A <= 1 (e.g. 1/256), got '%s'",
                                 has_val ? argv[i + 1] : "");
                goto done;
            }
            i++;
        } else if (strcmp(a, "--filter") == 0) {
            if (!has_val || parse_filter(argv[i + 1], &o.aa)) {
                rc = usage_error("--filter needs box, gauss or gauss:SIGMA, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            i++;
        } else if (strcmp(a, "--pattern") == 0) {
            if (has_val && strcmp(argv[i + 1], "grid") == 0)
                o.aa.pattern = GLS_AA_GRID;
            else if (has_val && strcmp(argv[i + 1], "stratified") == 0)
                o.aa.pattern = GLS_AA_STRATIFIED;
            else if (has_val && strcmp(argv[i + 1], "lattice") == 0)
                o.aa.pattern = GLS_AA_LATTICE;
            else {
                rc = usage_error("--pattern needs lattice, grid or stratified, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            i++;
        } else if (strcmp(a, "--seed") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 0, UINT64_MAX, &v)) {
                rc = usage_error("--seed needs an unsigned integer, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.aa.seed = v;
            i++;
        } else if (strcmp(a, "--aa-tiles") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 1, 256, &v)) {
                rc = usage_error("--aa-tiles needs K in 1..256, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.aa_tiles = (uint32_t)v;
            i++;
        } else if (strcmp(a, "--writer-threads") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 0, 1, &v)) {
                rc = usage_error("--writer-threads needs 0 or 1, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.writer_threads = (unsigned)v;
            i++;
        } else if (strcmp(a, "--anisotropic") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 1, 16, &v)) {
                rc = usage_error("--anisotropic needs N in 1..16, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.anisotropy = (uint32_t)v;
            i++;
        } else if (strcmp(a, "--backend") == 0) {
            if (!has_val || gls_backend_parse(argv[i + 1], &o.backend)) {
                rc = usage_error("--backend needs auto, egl, egl-device, egl-surfaceless or osmesa, got '%s'",
                                 has_val ? argv[i + 1] : "");
                goto done;
            }
            /* asked for by name but not in this build: said before any
               input is read, like an option this glsplay lacks */
            if (!gls_backend_built(o.backend)) {
                fprintf(stderr, "glsplay: error: --backend %s: this glsplay was built without %s: %s\n", argv[i + 1],
                        o.backend == GLS_BACKEND_OSMESA ? "OSMesa" : "EGL", gls_backend_missing(o.backend));
                rc = 2;
                goto done;
            }
            i++;
        } else if (strcmp(a, "--image-format") == 0) {
            const char *f = has_val ? argv[i + 1] : "";
            if (strcmp(f, "png8") == 0 || strcmp(f, "png") == 0)
                o.image_format = GLS_IMG_PNG8;
            else if (strcmp(f, "png16") == 0)
                o.image_format = GLS_IMG_PNG16;
            else if (strcmp(f, "pfm") == 0)
                o.image_format = GLS_IMG_PFM;
            else {
                rc = usage_error("--image-format needs png8, png16 or pfm, got '%s'", f);
                goto done;
            }
            i++;
        } else if (strcmp(a, "--depth-scale") == 0) {
            const char *v = has_val ? argv[i + 1] : "";
            if (strcmp(v, "kitti") == 0)
                o.depth_scale = GLS_DEPTH_SCALE_KITTI;
            else if (strcmp(v, "tum") == 0)
                o.depth_scale = GLS_DEPTH_SCALE_TUM;
            else if (parse_pos(v, &o.depth_scale)) {
                rc = usage_error("--depth-scale needs a positive number, kitti (256) or tum (5000), got '%s'", v);
                goto done;
            }
            i++;
        } else if (strcmp(a, "--float-format") == 0) {
            const char *v = has_val ? argv[i + 1] : "";
            if (strcmp(v, "pfm") == 0)
                o.float_format = GLS_FLOAT_PFM;
            else if (strcmp(v, "npy") == 0)
                o.float_format = GLS_FLOAT_NPY;
            else {
                rc = usage_error("--float-format needs pfm or npy, got '%s'", v);
                goto done;
            }
            i++;
        } else if (strcmp(a, "--explain") == 0) {
            o.explain = 1;
        } else if (strcmp(a, "--write-calib") == 0) {
            o.write_calib = 1;
        } else if (strcmp(a, "--resume") == 0) {
            o.resume = 1;
        } else if (strcmp(a, "--flatten") == 0) {
            o.flatten = 1;
        } else if (strcmp(a, "--motion") == 0) {
            const char *eq = has_val ? strchr(argv[i + 1], '=') : NULL;
            if (!eq || eq == argv[i + 1] || !eq[1]) {
                rc = usage_error("--motion needs NAME=FILE, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            mot[o.nmotions++] = argv[++i];
        } else if (strcmp(a, "--progress") == 0) {
            /* an optional value: only these words are taken as one */
            o.progress = GLS_PROGRESS_BAR;
            if (has_val && strcmp(argv[i + 1], "json") == 0)
                o.progress = GLS_PROGRESS_JSON, i++;
            else if (has_val && strcmp(argv[i + 1], "bar") == 0)
                i++;
        } else if (strcmp(a, "--shard") == 0) {
            char msg[512];
            if (!has_val) {
                rc = usage_error("%s--shard needs I/N with 0 <= I < N (or slurm)", "");
                goto done;
            }
            if (gls_shard_parse(argv[i + 1], getenv, &o.shard, msg, sizeof msg)) {
                rc = usage_error("%s", msg);
                goto done;
            }
            i++;
        } else if (strcmp(a, "--trajectory") == 0) {
            if (!has_val) {
                rc = usage_error("%s--trajectory needs a trajectory file", "");
                goto done;
            }
            o.trajectory = argv[++i];
        } else if (strcmp(a, "--frames") == 0) {
            char msg[256];
            if (!has_val || gls_traj_range(argv[i + 1], &o.frame_first, &o.frame_end, msg, sizeof msg)) {
                rc = usage_error("--frames needs A:B, A:, :B or A (frames A..B-1), got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            frames = argv[++i];
        } else if (strcmp(a, "--frame") == 0) {
            unsigned long long v;
            if (!has_val || parse_uint(argv[i + 1], 0, UINT32_MAX, &v)) {
                rc = usage_error("--frame needs a frame number 0..4294967295, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            o.frame = (uint32_t)v;
            i++;
        } else if (strcmp(a, "--background") == 0) {
            float c[3];
            char tail;
            if (!has_val || sscanf(argv[i + 1], "%f,%f,%f%c", &c[0], &c[1], &c[2], &tail) != 3 ||
                !(c[0] >= 0 && c[0] <= 1 && c[1] >= 0 && c[1] <= 1 && c[2] >= 0 && c[2] <= 1)) {
                rc = usage_error("--background needs R,G,B with components in 0..1, got '%s'", has_val ? argv[i + 1] : "");
                goto done;
            }
            memcpy(o.background, c, sizeof c);
            i++;
        } else if (a[0] == '-' && a[1]) {
            rc = usage_error("unknown option '%s'", a);
            goto done;
        } else if (!o.bundle) {
            o.bundle = a;
        } else {
            rc = usage_error("more than one bundle given ('%s')", a);
            goto done;
        }
    }
    if (have_aa + have_samples + (subpixel > 0) > 1) {
        rc = usage_error("%s--aa, --samples and --subpixel all choose the samples; give one", "");
        goto done;
    }
    if (have_samples && o.aa.pattern != GLS_AA_LATTICE) {
        unsigned long long r = (unsigned long long)sqrt((double)o.aa.samples);
        if (r * r != o.aa.samples) {
            char m[32];
            snprintf(m, sizeof m, "%llu", (unsigned long long)o.aa.samples);
            rc = usage_error(o.aa.pattern == GLS_AA_GRID
                                 ? "--pattern grid needs a square --samples (N x N), got %s; the lattice takes any M"
                                 : "--pattern stratified needs a square --samples (N x N), got %s; the lattice takes any M",
                             m);
            goto done;
        }
    }
    if (subpixel > 0) {
        o.aa.n = gls_aa_n_for_accuracy(o.aa.filter, o.aa.pattern, o.aa.sigma, subpixel);
        if (!o.aa.n) {
            rc = usage_error("--subpixel %s needs a window larger than 4096x4096", "given");
            goto done;
        }
    }
    /* one sample per pixel: no pixel is mixed, the map would be all 0 */
    if ((o.outputs & GLS_OUT_EDGE_MAPS) && (o.aa.samples ? o.aa.samples : (uint64_t)o.aa.n * o.aa.n) <= 1) {
        rc = usage_error("--outputs %s needs anti-aliasing, --aa N with N > 1",
                         o.outputs & GLS_OUT_EDGES ? "edges" : "mask");
        goto done;
    }
    if (!o.bundle) {
        rc = usage_error("%sno bundle given", "");
        goto done;
    }
    /* the flattened path inlines every call: there is no instance to move */
    if (o.flatten && o.nmotions) {
        rc = usage_error("%s--motion moves instances, and --flatten draws none; leave out --flatten", "");
        goto done;
    }
    /* flow goes from each frame of a trajectory to the next */
    if ((o.outputs & GLS_OUT_FLOW_ALL) && !o.trajectory) {
        rc = usage_error("%s--outputs flow needs a --trajectory: the flow goes from each frame to the next", "");
        goto done;
    }
    if (frames && !o.trajectory) {
        rc = usage_error("%s--frames selects frames of a --trajectory; for a single render use --frame N", "");
        goto done;
    }
    if (!o.explain && !o.outdir) {
        rc = usage_error("%sno output directory given (-o OUTDIR), and no --explain", "");
        goto done;
    }
    if (o.write_calib && !o.outdir) {
        rc = usage_error("%s--write-calib writes into the output directory: give -o OUTDIR", "");
        goto done;
    }
    if (o.outdir && o.ncameras == 0) {
        rc = usage_error("%sno camera given (--camera CAM)", "");
        goto done;
    }
    if (o.outputs & GLS_OUT_EDGES_AS_MASK)
        fprintf(stderr, "glsplay: note: --outputs mask is now called edges (the word mask will mean object masks); "
                        "mask_F.png is written as before\n");
    rc = gls_play(&o, stdout, stderr);
done:
    free(cams);
    free(mot);
    return rc;
}
