/* PNG, PFM and PLY encoders (outputs.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "le.h"
#include "outputs.h"
#include <spng.h>
#include <stb/stb_image_write.h>

typedef struct {
    gls_buf *out;
    int failed;
} sink;

static void to_buf(void *ctx, void *data, int size)
{
    sink *s = ctx;
    if (size > 0 && gls_buf_put(s->out, data, (size_t)size))
        s->failed = 1;
}

int gls_encode_png(const uint8_t *rgba, uint32_t w, uint32_t h, gls_buf *out)
{
    size_t n = (size_t)w * h;
    uint8_t *rgb = malloc(n ? n * 3 : 1);
    if (!rgb)
        return -1;
    for (size_t i = 0; i < n; i++)
        memcpy(rgb + 3 * i, rgba + 4 * i, 3);
    sink s = {out, 0};
    int ok = stbi_write_png_to_func(to_buf, &s, (int)w, (int)h, 3, rgb, (int)(w * 3));
    free(rgb);
    return ok && !s.failed ? 0 : -1;
}

int gls_encode_png_gray(const uint8_t *g, uint32_t w, uint32_t h, gls_buf *out)
{
    sink s = {out, 0};
    int ok = stbi_write_png_to_func(to_buf, &s, (int)w, (int)h, 1, g, (int)w);
    return ok && !s.failed ? 0 : -1;
}

int gls_encode_png16(const uint16_t *rgb, uint32_t w, uint32_t h, gls_buf *out)
{
    /* SPNG_FMT_PNG on encode takes 16-bit samples in host byte order and
     * converts them to the file's big-endian itself (libspng docs/encode.md:
     * "16-bit images are assumed to be host-endian except for
     * SPNG_FMT_RAW"), so the samples go in as they are. */
    size_t n = (size_t)w * h * 3;
    spng_ctx *ctx = spng_ctx_new(SPNG_CTX_ENCODER);
    int rc = -1;
    if (!ctx)
        return -1;
    struct spng_ihdr ih;
    memset(&ih, 0, sizeof ih);
    ih.width = w;
    ih.height = h;
    ih.bit_depth = 16;
    ih.color_type = SPNG_COLOR_TYPE_TRUECOLOR;
    if (spng_set_option(ctx, SPNG_ENCODE_TO_BUFFER, 1) || spng_set_ihdr(ctx, &ih) ||
        spng_encode_image(ctx, rgb, n * sizeof *rgb, SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE))
        goto out;
    size_t len;
    int e = 0;
    void *png = spng_get_png_buffer(ctx, &len, &e);
    if (!png || e)
        goto out;
    rc = gls_buf_put(out, png, len) ? -1 : 0;
    free(png);
out:
    spng_ctx_free(ctx);
    return rc;
}

/* PFM, channels 1 ("Pf") or 3 ("PF"), float32 little-endian (scale
 * -1.0), rows bottom to top as the format (Middlebury) requires; v is top
 * row first. */
static int encode_pfm(const float *v, uint32_t w, uint32_t h, unsigned channels, gls_buf *out)
{
    char hdr[64];
    int k = snprintf(hdr, sizeof hdr, "P%c\n%u %u\n-1.0\n", channels == 3 ? 'F' : 'f', w, h);
    size_t row_values = (size_t)w * channels;
    if (gls_buf_put(out, hdr, (size_t)k) || gls_buf_reserve(out, row_values * h * 4))
        return -1;
    for (uint32_t r = h; r-- > 0;) {
        const float *row = v + (size_t)r * row_values;
        for (size_t x = 0; x < row_values; x++)
            gls_le_put_f32(out->data + out->len + 4 * x, row[x]);
        out->len += row_values * 4;
    }
    return 0;
}

int gls_encode_pfm(const float *z, uint32_t w, uint32_t h, gls_buf *out)
{
    return encode_pfm(z, w, h, 1, out);
}

int gls_encode_pfm_rgb(const float *rgb, uint32_t w, uint32_t h, gls_buf *out)
{
    return encode_pfm(rgb, w, h, 3, out);
}

int gls_encode_ply(const gls_camera *c, const float *z, const uint8_t *rgba, gls_buf *out, uint64_t *npoints)
{
    size_t n = (size_t)c->width * c->height;
    uint64_t count = 0;
    for (size_t i = 0; i < n; i++)
        count += isfinite(z[i]) != 0;
    char hdr[512];
    int k = snprintf(hdr, sizeof hdr,
                     "ply\nformat binary_little_endian 1.0\n"
                     "comment glscene: world coordinates of the surface seen at each pixel centre\n"
                     "element vertex %llu\n"
                     "property double x\nproperty double y\nproperty double z\n"
                     "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n",
                     (unsigned long long)count);
    if (gls_buf_put(out, hdr, (size_t)k) || gls_buf_reserve(out, (size_t)count * 27))
        return -1;
    for (uint32_t v = 0; v < c->height; v++)
        for (uint32_t u = 0; u < c->width; u++) {
            size_t i = (size_t)v * c->width + u;
            if (!isfinite(z[i]))
                continue;
            double Pc[3], P[3];
            gls_camera_unproject(c, u, v, z[i], Pc);
            gls_camera_to_world(c, Pc, P);
            uint8_t *p = out->data + out->len;
            for (int j = 0; j < 3; j++)
                gls_le_put_f64(p + 8 * j, P[j]);
            memcpy(p + 24, rgba + 4 * i, 3);
            out->len += 27;
        }
    *npoints = count;
    return 0;
}
