/* The player's names (play_int.h): a camera's name from its file, and the
 * path each output file of a camera frame goes to (OUTDIR/NAME/KIND_FRAME.EXT). */
#include <stdlib.h>
#include <string.h>
#include "play_int.h"

int gls_output_path(char *buf, size_t len, const char *outdir, const char *name, const char *kind,
                    uint32_t frame, const char *ext)
{
    int k = snprintf(buf, len, "%s/%s/%s_%06u.%s", outdir, name, kind, frame, ext);
    return k < 0 || (size_t)k >= len ? -1 : 0;
}

/* Camera name: the file name without directory and without ".cam" (or
 * ".yml", ".yaml": an OpenCV camera file). */
char *play_camera_name(const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t n = strlen(base);
    static const char *const ext[] = {".cam", ".yml", ".yaml"};
    for (size_t i = 0; i < 3; i++) {
        size_t e = strlen(ext[i]);
        if (n > e && strcmp(base + n - e, ext[i]) == 0) {
            n -= e;
            break;
        }
    }
    char *s = malloc(n + 1);
    if (s) {
        memcpy(s, base, n);
        s[n] = 0;
    }
    return s;
}


/* The file an output kind of one camera and frame goes to; -1 if too long. */
int play_output_file(char *path, size_t len, const gls_play_opts *o, const char *name, size_t k, uint32_t frame)
{
    const char *ext = gls_output_kinds[k].ext;
    if (!ext || (gls_output_kinds[k].bit == GLS_OUT_IMAGE && o->image_format == GLS_IMG_PFM))
        ext = o->float_format == GLS_FLOAT_NPY ? "npy" : "pfm";
    return gls_output_path(path, len, o->outdir, name, gls_output_kinds[k].stem, frame, ext);
}
