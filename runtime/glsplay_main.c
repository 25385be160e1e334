/* glsplay: render a compiled glscene bundle through OpenCV pinhole
 * cameras.  Argument parsing only; the work is gls_play() (player.c). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "player.h"

static const char usage_text[] =
    "usage: glsplay BUNDLE.glsb --camera CAM [--camera CAM ...] -o OUTDIR [options]\n"
    "       glsplay BUNDLE.glsb [--camera CAM ...] --explain\n"
    "Renders the bundle's top-level object through each camera (spec/camera.md)\n"
    "and writes OUTDIR/NAME/image_000000.png, depth_000000.pfm, points_000000.ply\n"
    "where NAME is the camera file name without .cam.\n"
    "options:\n"
    "  --camera CAM, -c CAM   camera file (repeatable)\n"
    "  -o OUTDIR              output directory (created if missing)\n"
    "  --outputs LIST         comma-separated subset of image,depth,points (default all)\n"
    "  --size WxH             override every camera's width and height\n"
    "  --explain              print the rendering plan; without -o, render nothing\n"
    "  --help                 this text\n"
    "exit status: 0 success, 1 input error, 2 usage error\n";

static int usage_error(const char *fmt, const char *arg)
{
    fprintf(stderr, "glsplay: error: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (try glsplay --help)\n");
    return 2;
}

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

int main(int argc, char **argv)
{
    gls_play_opts o;
    memset(&o, 0, sizeof o);
    o.outputs = GLS_OUT_IMAGE | GLS_OUT_DEPTH | GLS_OUT_POINTS;
    const char **cams = calloc((size_t)argc, sizeof *cams);
    if (!cams)
        return 1;
    o.cameras = cams;
    int rc;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int has_val = i + 1 < argc;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(usage_text, stdout);
            free(cams);
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
            o.outdir = argv[++i];
        } else if (strcmp(a, "--outputs") == 0) {
            if (!has_val || parse_outputs(argv[i + 1], &o.outputs)) {
                rc = usage_error("--outputs needs a comma-separated list of image, depth, points, got '%s'",
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
        } else if (strcmp(a, "--explain") == 0) {
            o.explain = 1;
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
    if (!o.bundle) {
        rc = usage_error("%sno bundle given", "");
        goto done;
    }
    if (!o.explain && !o.outdir) {
        rc = usage_error("%sno output directory given (-o OUTDIR), and no --explain", "");
        goto done;
    }
    if (o.outdir && o.ncameras == 0) {
        rc = usage_error("%sno camera given (--camera CAM)", "");
        goto done;
    }
    rc = gls_play(&o, stdout, stderr);
done:
    free(cams);
    return rc;
}
