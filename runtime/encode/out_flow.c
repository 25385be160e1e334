/* .flo and KITTI flow PNG encoders (out_flow.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "gt_flow.h"
#include "le.h"
#include "out_flow.h"
#include "outputs.h"

int gls_encode_flo(const float *uv, uint32_t w, uint32_t h, gls_buf *out)
{
    size_t n = (size_t)w * h;
    if (gls_buf_reserve(out, 12 + 8 * n))
        return -1;
    uint8_t *p = out->data + out->len;
    gls_le_put_f32(p, 202021.25f); /* the bytes "PIEH" */
    gls_le_put_u32(p + 4, w);
    gls_le_put_u32(p + 8, h);
    for (size_t i = 0; i < 2 * n; i++)
        gls_le_put_f32(p + 12 + 4 * i, uv[i]);
    out->len += 12 + 8 * n;
    return 0;
}

/* The stored sample of a flow component: flow * 64 + 2^15 rounded to the
 * nearest (halves up), as a double so that the range check sees it. */
static double kitti_sample(float f)
{
    return floor((double)f * 64.0 + 32768.0 + 0.5);
}

int gls_flow_kitti_check(const float *uv, const uint8_t *mask, uint32_t w, uint32_t h, uint32_t *x, uint32_t *y,
                         float *u, float *v)
{
    size_t n = (size_t)w * h;
    for (size_t i = 0; i < n; i++) {
        if (mask[i] != GLS_FLOW_VISIBLE)
            continue;
        double a = kitti_sample(uv[2 * i]), b = kitti_sample(uv[2 * i + 1]);
        if (!(a >= 0 && a <= 65535 && b >= 0 && b <= 65535)) {
            *x = (uint32_t)(i % w), *y = (uint32_t)(i / w);
            *u = uv[2 * i], *v = uv[2 * i + 1];
            return -1;
        }
    }
    return 0;
}

void gls_flow_kitti_codes(const float *uv, const uint8_t *mask, size_t n, uint16_t *rgb)
{
    memset(rgb, 0, 3 * n * sizeof *rgb);
    for (size_t i = 0; i < n; i++)
        if (mask[i] == GLS_FLOW_VISIBLE) {
            rgb[3 * i] = (uint16_t)kitti_sample(uv[2 * i]);
            rgb[3 * i + 1] = (uint16_t)kitti_sample(uv[2 * i + 1]);
            rgb[3 * i + 2] = 1;
        }
}

int gls_encode_flow_kitti(const float *uv, const uint8_t *mask, uint32_t w, uint32_t h, gls_buf *out)
{
    size_t n = (size_t)w * h;
    uint16_t *rgb = calloc(n ? 3 * n : 1, sizeof *rgb);
    if (!rgb)
        return -1;
    gls_flow_kitti_codes(uv, mask, n, rgb);
    int rc = gls_encode_png16(rgb, w, h, out);
    free(rgb);
    return rc;
}
