/* Scaled 16-bit PNG encoder (out_png16.h). */
#include <math.h>
#include <stdlib.h>
#include "out_png16.h"
#include "outputs.h"

/* v * scale rounded half up; 0 where v is not finite (no surface) */
static double code_of(float v, double scale)
{
    return isfinite(v) ? floor((double)v * scale + 0.5) : 0;
}

int gls_scaled16_check(const float *v, size_t n, double scale, size_t *bad)
{
    for (size_t i = 0; i < n; i++) {
        double c = code_of(v[i], scale);
        if (c > 65535) {
            *bad = i;
            return GLS_SCALED16_OVER;
        }
        if (c < 1 && isfinite(v[i])) { /* a surface that would read as none */
            *bad = i;
            return GLS_SCALED16_ZERO;
        }
    }
    return 0;
}

void gls_scaled16_codes(const float *v, size_t n, double scale, uint16_t *code)
{
    for (size_t i = 0; i < n; i++)
        code[i] = (uint16_t)code_of(v[i], scale);
}

int gls_encode_scaled16(const float *v, uint32_t w, uint32_t h, double scale, gls_buf *out, size_t *bad)
{
    size_t n = (size_t)w * h;
    int rc = gls_scaled16_check(v, n, scale, bad);
    if (rc)
        return rc;
    uint16_t *code = malloc((n ? n : 1) * sizeof *code);
    if (!code)
        return -1;
    gls_scaled16_codes(v, n, scale, code);
    rc = gls_encode_png16_gray(code, w, h, out);
    free(code);
    return rc;
}
