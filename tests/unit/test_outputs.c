/* The player's PNG encoders (runtime/encode/outputs.c): every 8-bit and 16-bit
 * sample value, mid-greys included, decodes (stb_image, a decoder
 * independent of libspng) to exactly what went in, and to exactly what the
 * encoders before issue 14 gave (stb_image_write for 8-bit, libspng at its
 * default level for 16-bit); the files are written at zlib's fastest level
 * and are the same bytes every time. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <spng.h>
#include <stb/stb_image.h>
#include "check.h"
#include "out_disparity.h"
#include "out_npy.h"
#include "out_png16.h"
#include "outputs.h"
#include "stb_png.h"

#define W 256
#define H 300

/* An RGBA image in which every channel takes every value 0..255 (rows
 * 0..255: a ramp per channel, shifted), then pseudo-random rows, with
 * mid-grey pixels (127, 128) placed in both parts. */
static uint8_t *test_rgba(void)
{
    uint8_t *p = malloc((size_t)W * H * 4);
    uint32_t s = 12345;
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            uint8_t *q = p + 4 * ((size_t)y * W + x);
            for (int c = 0; c < 4; c++) {
                s = s * 1664525u + 1013904223u;
                q[c] = y < 256 ? (uint8_t)(x + y * (uint32_t)(c + 1)) : (uint8_t)(s >> 24);
            }
        }
    for (uint32_t y = 0; y < H; y += 7)
        memcpy(p + 4 * ((size_t)y * W + 3), "\x7f\x7f\x7f\xff\x80\x80\x80\xff", 8);
    return p;
}

/* 16-bit RGB: the first 65536 samples run through every value, the rest
 * pseudo-random; mid-greys 32767, 32768 and 32896 (128 * 257) placed. */
static uint16_t *test_rgb16(void)
{
    size_t n = (size_t)W * H * 3;
    uint16_t *p = malloc(n * sizeof *p);
    uint32_t s = 777;
    for (size_t i = 0; i < n; i++) {
        s = s * 1664525u + 1013904223u;
        p[i] = i < 65536 ? (uint16_t)(i * 40503u) : (uint16_t)(s >> 16); /* 40503 odd: a permutation */
    }
    static const uint16_t grey[] = {32767, 32768, 32896};
    for (size_t k = 0; k < 3; k++)
        for (size_t c = 0; c < 3; c++)
            p[3 * (W * 100 + 7 + k) + c] = p[3 * (W * 280 + 9 + k) + c] = grey[k];
    return p;
}

/* The zlib header of the first IDAT chunk: its FLEVEL bits (top two of the
 * second byte) say which level family wrote it; 0 = fastest (level 1). */
static int idat_flevel(const gls_buf *b)
{
    size_t i = 8;
    while (i + 12 <= b->len) {
        uint32_t len = (uint32_t)b->data[i] << 24 | (uint32_t)b->data[i + 1] << 16 | (uint32_t)b->data[i + 2] << 8 |
                       b->data[i + 3];
        if (memcmp(b->data + i + 4, "IDAT", 4) == 0 && len >= 2)
            return b->data[i + 9] >> 6;
        i += 12 + (size_t)len;
    }
    return -1;
}

static void test_png8_pixels(void)
{
    uint8_t *rgba = test_rgba();
    gls_buf a = {0}, b = {0}, old = {0};
    CHECK(gls_encode_png(rgba, W, H, &a) == 0);
    CHECK(gls_encode_png(rgba, W, H, &b) == 0);
    CHECK(a.len == b.len && memcmp(a.data, b.data, a.len) == 0);
    CHECK(idat_flevel(&a) == 0);
    /* the encoder before: stb_image_write from an RGB copy */
    CHECK(stb_png_encode(rgba, W, H, &old) == 0);
    uint8_t *rgb = malloc((size_t)W * H * 3);
    for (size_t i = 0; i < (size_t)W * H; i++)
        memcpy(rgb + 3 * i, rgba + 4 * i, 3);
    CHECK(old.len != a.len || memcmp(old.data, a.data, a.len) != 0); /* other bytes ... */
    int w, h, c, w2, h2, c2;
    uint8_t *d = stbi_load_from_memory(a.data, (int)a.len, &w, &h, &c, 0);
    uint8_t *d2 = stbi_load_from_memory(old.data, (int)old.len, &w2, &h2, &c2, 0);
    CHECK(d && d2 && w == W && h == H && c == 3 && w2 == W && h2 == H && c2 == 3);
    if (d && d2) {
        CHECK(memcmp(d, rgb, (size_t)W * H * 3) == 0); /* ... the same pixels */
        CHECK(memcmp(d, d2, (size_t)W * H * 3) == 0);
        CHECK(d[3 * (W * 7 + 3)] == 127 && d[3 * (W * 7 + 4)] == 128);
    }
    stbi_image_free(d), stbi_image_free(d2);
    free(rgb), free(rgba), free(a.data), free(b.data), free(old.data);
}

static void test_png_gray_pixels(void)
{
    uint8_t *g = test_rgba(); /* its first W*H bytes as grey */
    gls_buf a = {0};
    CHECK(gls_encode_png_gray(g, W, H, &a) == 0);
    CHECK(idat_flevel(&a) == 0);
    int w, h, c;
    uint8_t *d = stbi_load_from_memory(a.data, (int)a.len, &w, &h, &c, 0);
    CHECK(d && w == W && h == H && c == 1);
    if (d)
        CHECK(memcmp(d, g, (size_t)W * H) == 0);
    stbi_image_free(d);
    free(g), free(a.data);
}

static void test_png16_pixels(void)
{
    uint16_t *p = test_rgb16();
    size_t n = (size_t)W * H * 3;
    gls_buf a = {0}, b = {0}, old = {0};
    CHECK(gls_encode_png16(p, W, H, &a) == 0);
    CHECK(gls_encode_png16(p, W, H, &b) == 0);
    CHECK(a.len == b.len && memcmp(a.data, b.data, a.len) == 0);
    CHECK(idat_flevel(&a) == 0);
    /* the encoder before: libspng at its default level and filters */
    CHECK(gls_encode_png_with(p, W, H, 3, 16, 0, 6, SPNG_FILTER_CHOICE_ALL, &old) == 0);
    int w, h, c, w2, h2, c2;
    uint16_t *d = stbi_load_16_from_memory(a.data, (int)a.len, &w, &h, &c, 0);
    uint16_t *d2 = stbi_load_16_from_memory(old.data, (int)old.len, &w2, &h2, &c2, 0);
    CHECK(d && d2 && w == W && h == H && c == 3 && w2 == W && h2 == H && c2 == 3);
    if (d && d2) {
        CHECK(memcmp(d, p, n * 2) == 0);
        CHECK(memcmp(d, d2, n * 2) == 0);
        CHECK(d[3 * (W * 100 + 7)] == 32767 && d[3 * (W * 100 + 8)] == 32768 && d[3 * (W * 100 + 9)] == 32896);
    }
    stbi_image_free(d), stbi_image_free(d2);
    free(p), free(a.data), free(b.data), free(old.data);
}

/* .npy (out_npy.h): numpy's header for (h, w) and (h, w, 3), padded so
 * the data starts at byte 128 (10 + 60 or 63 header bytes, rounded up to
 * a multiple of 64), the floats little-endian in C order. */
static void test_npy_layout(void)
{
    float v[2 * 3 * 3];
    for (int i = 0; i < 18; i++)
        v[i] = (float)i - 0.5f;
    v[4] = INFINITY;
    static const char h1[] = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }";
    static const char h3[] = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3, 3), }";
    for (unsigned ch = 1; ch <= 3; ch += 2) {
        gls_buf a = {0};
        CHECK(gls_encode_npy(v, 3, 2, ch, &a) == 0);
        const char *h = ch == 1 ? h1 : h3;
        size_t hl = strlen(h);
        CHECK(a.len == 128 + 6 * ch * 4);
        CHECK(memcmp(a.data, "\x93NUMPY\x01\x00", 8) == 0 && a.data[8] == 118 && a.data[9] == 0);
        CHECK(memcmp(a.data + 10, h, hl) == 0);
        for (size_t i = 10 + hl; i < 127; i++)
            CHECK(a.data[i] == ' ');
        CHECK(a.data[127] == '\n');
        for (unsigned i = 0; a.len == 128 + 6 * ch * 4 && i < 6 * ch; i++) {
            uint32_t bits, want;
            memcpy(&want, &v[i], 4);
            const uint8_t *p = a.data + 128 + 4 * i;
            bits = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
            CHECK(bits == want);
        }
        free(a.data);
    }
}

/* Scaled 16-bit PNGs (out_png16.h): floor(v s + 0.5), 0 for no surface,
 * and the first value that does not fit refused at its boundary:
 * 255.998046875 * 256 = 65535.5 rounds to 65536. */
static void test_scaled16(void)
{
    float v[6] = {1.0f, INFINITY, 255.998f, 0.5f / 256, 12.25f, NAN};
    gls_buf a = {0};
    size_t bad = 99;
    CHECK(gls_encode_scaled16(v, 3, 2, 256, &a, &bad) == 0);
    int w, h, c;
    uint16_t *d = stbi_load_16_from_memory(a.data, (int)a.len, &w, &h, &c, 0);
    CHECK(d && w == 3 && h == 2 && c == 1);
    if (d)
        CHECK(d[0] == 256 && d[1] == 0 && d[2] == 65535 && d[3] == 1 && d[4] == 3136 && d[5] == 0);
    stbi_image_free(d);
    free(a.data);
    a = (gls_buf){0};
    float over[2] = {3, 255.998046875f};
    CHECK(gls_encode_scaled16(over, 2, 1, 256, &a, &bad) == GLS_SCALED16_OVER && bad == 1 && a.len == 0);
    float zero[3] = {INFINITY, 1, 0.4f / 256};
    CHECK(gls_encode_scaled16(zero, 3, 1, 256, &a, &bad) == GLS_SCALED16_ZERO && bad == 2 && a.len == 0);
    float tum[1] = {13.107f}; /* 65535 / 5000 */
    CHECK(gls_encode_scaled16(tum, 1, 1, 5000, &a, &bad) == 0);
    free(a.data);
}

/* The rectified-pair check's tolerances (out_disparity.h): 1e-9 per
 * rotation entry, 1e-9 B off the x axis, 1e-9 relative on intrinsics;
 * B from the centres. */
static gls_camera pair_cam(double bx, double by, double fx, double r01)
{
    gls_camera c;
    memset(&c, 0, sizeof c);
    c.width = 64, c.height = 48, c.fx = fx, c.fy = 500, c.cx = 31.5, c.cy = 23.5;
    double R[9] = {1, r01, 0, -r01, 1, 0, 0, 0, 1};
    memcpy(c.R, R, sizeof R);
    c.T[0] = -bx, c.T[1] = -by; /* centre (bx, by, 0) for R = I */
    c.near = 0.1, c.far = 100;
    return c;
}

static void test_rectified_tolerance(void)
{
    char err[256];
    double B = 0;
    gls_camera l = pair_cam(0, 0, 500, 0);
    gls_camera r = pair_cam(0.5, 0, 500, 0);
    CHECK(gls_rectified_pair(&l, &r, "l", "r", &B, err, sizeof err) == 0 && B == 0.5);
    r = pair_cam(0.5, 0.5e-10, 500 * (1 + 1e-10), 0);
    CHECK(gls_rectified_pair(&l, &r, "l", "r", &B, err, sizeof err) == 0);
    r = pair_cam(0.5, 0.5e-8, 500, 0);
    CHECK(gls_rectified_pair(&l, &r, "l", "r", &B, err, sizeof err) == -1 && strstr(err, "not along x"));
    r = pair_cam(0.5, 0, 500 * (1 + 1e-8), 0);
    CHECK(gls_rectified_pair(&l, &r, "l", "r", &B, err, sizeof err) == -1 && strstr(err, "different fx"));
    r = pair_cam(0.5, 0, 500, 1e-8);
    CHECK(gls_rectified_pair(&l, &r, "l", "r", &B, err, sizeof err) == -1);
    CHECK_STR(err, "cameras l and r have different rotations");
    r = pair_cam(0.5, 0, 500, 1e-10); /* rotation within 1e-9: the centre moves by 1e-10 B too */
    CHECK(gls_rectified_pair(&l, &r, "l", "r", &B, err, sizeof err) == 0);
    r = pair_cam(-0.5, 0, 500, 0);
    CHECK(gls_rectified_pair(&l, &r, "l", "r", &B, err, sizeof err) == -1 && strstr(err, "not to the right"));
}

int main(void)
{
    RUN(test_png8_pixels);
    RUN(test_png_gray_pixels);
    RUN(test_png16_pixels);
    RUN(test_npy_layout);
    RUN(test_scaled16);
    RUN(test_rectified_tolerance);
    CHECK_EXIT();
}
