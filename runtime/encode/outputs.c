/* PNG, PFM and PLY encoders (outputs.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "le.h"
#include "outputs.h"
#include <spng.h>

/* The player's PNG settings (outputs.h).  Measured on rendered frames
 * (make bench-encode, docs/benchmarks.md): level 1 is 3 to 5 times faster
 * than level 6 and 4 to 6 times faster than stb_image_write; "sub" gives
 * the smallest files of the single filters at about the speed of none
 * (none makes the terrain's files half as large again), while the
 * adaptive choice of all five filters costs about twice the time for 1
 * to 2 % less.  16-bit: sub is within a few % of none in speed and size
 * on the road, 25 % smaller on the smooth terrain. */
#define PNG_LEVEL 1
#define PNG_FILTERS SPNG_FILTER_CHOICE_SUB

/* PNG through libspng: one encoder for every PNG the player writes.
 * channels 1 (grey) or 3 (RGB); depth 8 or 16 (16-bit samples in host
 * order: SPNG_FMT_PNG on encode converts them to the file's big-endian,
 * libspng docs/encode.md).  stride4: 8-bit pixels given as RGBA, four bytes
 * each, the alpha dropped row by row (no whole-image RGB copy).  level and
 * filters: zlib level and SPNG_FILTER_CHOICE_* bits.  Deterministic: the
 * bytes depend on the pixels, level, filters and the zlib build only. */
static int encode_spng(const void *px, uint32_t w, uint32_t h, int channels, int depth, int stride4, int level,
                       int filters, gls_buf *out)
{
    spng_ctx *ctx = spng_ctx_new(SPNG_CTX_ENCODER);
    if (!ctx)
        return -1;
    struct spng_ihdr ih;
    memset(&ih, 0, sizeof ih);
    ih.width = w;
    ih.height = h;
    ih.bit_depth = (uint8_t)depth;
    ih.color_type = channels == 1 ? SPNG_COLOR_TYPE_GRAYSCALE : SPNG_COLOR_TYPE_TRUECOLOR;
    size_t row_bytes = (size_t)w * (size_t)channels * (size_t)(depth / 8);
    uint8_t *row = NULL;
    int rc = -1;
    if (spng_set_option(ctx, SPNG_ENCODE_TO_BUFFER, 1) || spng_set_option(ctx, SPNG_IMG_COMPRESSION_LEVEL, level) ||
        spng_set_option(ctx, SPNG_FILTER_CHOICE, filters) || spng_set_ihdr(ctx, &ih))
        goto out;
    if (!stride4) {
        if (spng_encode_image(ctx, px, row_bytes * h, SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE))
            goto out;
    } else {
        row = malloc(row_bytes ? row_bytes : 1);
        if (!row || spng_encode_image(ctx, NULL, 0, SPNG_FMT_PNG, SPNG_ENCODE_PROGRESSIVE | SPNG_ENCODE_FINALIZE))
            goto out;
        const uint8_t *rgba = px;
        int e = 0;
        for (uint32_t y = 0; y < h; y++) {
            const uint8_t *src = rgba + (size_t)y * w * 4;
            for (uint32_t x = 0; x < w; x++)
                memcpy(row + 3 * (size_t)x, src + 4 * (size_t)x, 3);
            e = spng_encode_row(ctx, row, row_bytes);
            if (e && e != SPNG_EOI)
                goto out;
        }
        if (e != SPNG_EOI)
            goto out;
    }
    size_t len;
    int e = 0;
    void *png = spng_get_png_buffer(ctx, &len, &e);
    if (!png || e)
        goto out;
    rc = gls_buf_put(out, png, len) ? -1 : 0;
    free(png);
out:
    free(row);
    spng_ctx_free(ctx);
    return rc;
}

const char *gls_png_encoding(void)
{
    return "libspng, zlib level 1, the \"sub\" filter on every row";
}

int gls_encode_png_with(const void *px, uint32_t w, uint32_t h, int channels, int depth, int rgba, int level,
                        int filters, gls_buf *out)
{
    return encode_spng(px, w, h, channels, depth, rgba, level, filters, out);
}

int gls_encode_png(const uint8_t *rgba, uint32_t w, uint32_t h, gls_buf *out)
{
    return encode_spng(rgba, w, h, 3, 8, 1, PNG_LEVEL, PNG_FILTERS, out);
}

int gls_encode_png_gray(const uint8_t *g, uint32_t w, uint32_t h, gls_buf *out)
{
    return encode_spng(g, w, h, 1, 8, 0, PNG_LEVEL, PNG_FILTERS, out);
}

int gls_encode_png16_gray(const uint16_t *g, uint32_t w, uint32_t h, gls_buf *out)
{
    return encode_spng(g, w, h, 1, 16, 0, PNG_LEVEL, PNG_FILTERS, out);
}

int gls_encode_png16(const uint16_t *rgb, uint32_t w, uint32_t h, gls_buf *out)
{
    return encode_spng(rgb, w, h, 3, 16, 0, PNG_LEVEL, PNG_FILTERS, out);
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
    return gls_encode_ply_rows(c, NULL, z, rgba, out, npoints);
}

int gls_encode_ply_rows(const gls_camera *c, const double (*row_pose)[12], const float *z, const uint8_t *rgba,
                        gls_buf *out, uint64_t *npoints)
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
    gls_camera at = *c;
    for (uint32_t v = 0; v < c->height; v++) {
        if (row_pose) { /* a rolling shutter's row: its own camera pose */
            memcpy(at.R, row_pose[v], sizeof at.R);
            memcpy(at.T, row_pose[v] + 9, sizeof at.T);
        }
        for (uint32_t u = 0; u < c->width; u++) {
            size_t i = (size_t)v * c->width + u;
            if (!isfinite(z[i]))
                continue;
            double Pc[3], P[3];
            gls_camera_unproject(&at, u, v, z[i], Pc);
            gls_camera_to_world(&at, Pc, P);
            uint8_t *p = out->data + out->len;
            for (int j = 0; j < 3; j++)
                gls_le_put_f64(p + 8 * j, P[j]);
            memcpy(p + 24, rgba + 4 * i, 3);
            out->len += 27;
        }
    }
    *npoints = count;
    return 0;
}
