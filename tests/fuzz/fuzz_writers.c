/* libFuzzer target: the output writers (PNG 8/16-bit, grey PNG, PFM depth
 * and colour, PLY points) fed odd sizes and arbitrary pixel values (NaN,
 * infinities, denormals, negative depths), with a camera whose numbers
 * come from the input too.  Checks what the files must hold: PFM sizes
 * match their headers; PLY holds exactly the points with a finite depth. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "outputs.h"

static double take_double(const uint8_t **p, size_t *n)
{
    double v = 0;
    if (*n >= 8) {
        memcpy(&v, *p, 8);
        *p += 8;
        *n -= 8;
    }
    return v;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    uint32_t w = 1 + data[0] % 37, h = 1 + data[1] % 29; /* odd sizes, 1x1 included */
    const uint8_t *p = data + 2;
    size_t n = size - 2;
    gls_camera c;
    memset(&c, 0, sizeof c);
    c.width = w, c.height = h;
    c.fx = take_double(&p, &n), c.fy = take_double(&p, &n);
    c.cx = take_double(&p, &n), c.cy = take_double(&p, &n), c.skew = take_double(&p, &n);
    /* the camera parser guarantees these; the writers may rely on them */
    if (!(isfinite(c.fx) && c.fx > 0 && isfinite(c.fy) && c.fy > 0 && isfinite(c.cx) && isfinite(c.cy) &&
          isfinite(c.skew)))
        c.fx = c.fy = 1, c.cx = c.cy = c.skew = 0;
    c.R[0] = c.R[4] = c.R[8] = 1;
    c.near = 0.1, c.far = 100;
    size_t px = (size_t)w * h;
    float *z = calloc(px, sizeof *z), *rgbf = calloc(px * 3, sizeof *rgbf);
    uint8_t *rgba = calloc(px, 4);
    uint16_t *rgb16 = calloc(px * 3, sizeof *rgb16);
    if (!z || !rgbf || !rgba || !rgb16)
        goto out;
    memcpy(z, p, n < px * 4 ? n : px * 4); /* any bit patterns */
    memcpy(rgbf, p, n < px * 12 ? n : px * 12);
    memcpy(rgba, p, n < px * 4 ? n : px * 4);
    memcpy(rgb16, p, n < px * 6 ? n : px * 6);
    gls_buf b = {0};
    if (gls_encode_pfm(z, w, h, &b) == 0 && b.len < px * 4)
        abort(); /* the pixels must all be there */
    b.len = 0;
    if (gls_encode_pfm_rgb(rgbf, w, h, &b) == 0 && b.len < px * 12)
        abort();
    b.len = 0;
    gls_encode_png(rgba, w, h, &b);
    b.len = 0;
    gls_encode_png16(rgb16, w, h, &b);
    b.len = 0;
    gls_encode_png_gray(rgba, w, h, &b);
    b.len = 0;
    uint64_t np = 0, finite = 0;
    for (size_t i = 0; i < px; i++)
        finite += isfinite(z[i]) != 0; /* a surface pixel: finite depth */
    if (gls_encode_ply(&c, z, rgba, &b, &np) == 0 && np != finite)
        abort(); /* a point for every surface pixel, none for the others */
    free(b.data);
out:
    free(z), free(rgbf), free(rgba), free(rgb16);
    return 0;
}
