/* Scaled 16-bit PNG encoder (out_png16.h). */
#include <math.h>
#include <stdlib.h>
#include "out_png16.h"
#include "outputs.h"

int gls_encode_scaled16(const float *v, uint32_t w, uint32_t h, double scale, gls_buf *out, size_t *bad)
{
    size_t n = (size_t)w * h;
    uint16_t *code = malloc((n ? n : 1) * sizeof *code);
    if (!code)
        return -1;
    int rc = 0;
    for (size_t i = 0; i < n && rc == 0; i++) {
        if (!isfinite(v[i])) {
            code[i] = 0;
            continue;
        }
        double c = floor((double)v[i] * scale + 0.5);
        if (c > 65535)
            rc = GLS_SCALED16_OVER, *bad = i;
        else if (c < 1) /* a surface (v >= 0 here) that would read as none */
            rc = GLS_SCALED16_ZERO, *bad = i;
        else
            code[i] = (uint16_t)c;
    }
    if (rc == 0)
        rc = gls_encode_png16_gray(code, w, h, out);
    free(code);
    return rc;
}
