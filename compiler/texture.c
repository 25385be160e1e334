/* Texture decoding: every format is converted to RGBA8, row 0 at the
 * top.  JPEG goes through libjpeg-turbo, PNG, TGA and BMP through
 * stb_image (texture_codecs.h says why), with 1 (grey), 2 (grey + alpha),
 * 3 (RGB) or 4 channels (JPEG: grey, YCbCr, RGB, CMYK); a missing alpha
 * channel means opaque.  The size is checked from the header before
 * anything is decoded.  Alpha is made binary here (transparent below 0.5),
 * once, at compile time, so the bundle holds exactly what the player
 * alpha-tests. */
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include "compile.h"
#include "fileio.h"
#include "texture_codecs.h"

/* stb_image trusts a PNG chunk's declared length and grows its buffer to
 * it before reading (the texture fuzzer found a 100-byte PNG making it
 * reallocate 2 GiB).  A chunk longer than what is left of the file is
 * corrupt anyway: refuse it first.  Returns 1 to refuse. */
static int png_chunk_overrun(const unsigned char *d, size_t len)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (len < 8 || memcmp(d, sig, 8) != 0)
        return 0;
    size_t p = 8;
    while (p + 8 <= len) {
        uint32_t n = (uint32_t)d[p] << 24 | (uint32_t)d[p + 1] << 16 | (uint32_t)d[p + 2] << 8 | d[p + 3];
        if ((uint64_t)n + 12 > len - p)
            return 1;
        if (memcmp(d + p + 4, "IEND", 4) == 0)
            return 0;
        p += (size_t)n + 12;
    }
    return 0;
}

/* A PNG's size from its IHDR chunk (the first, at byte 8), read here
 * rather than by stb_image: stb_image refuses a side over 2^24 with no
 * PNG-specific reason and then tries the other formats, so a PNG declaring
 * 2^31 - 1 texels a side was reported as "unknown image type" instead of
 * as too large.  1 with *w and *h set, 0 when data is no PNG with an IHDR. */
static int png_header_size(const unsigned char *d, size_t len, uint32_t *w, uint32_t *h)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (len < 24 || memcmp(d, sig, 8) != 0 || memcmp(d + 12, "IHDR", 4) != 0)
        return 0;
    *w = (uint32_t)d[16] << 24 | (uint32_t)d[17] << 16 | (uint32_t)d[18] << 8 | d[19];
    *h = (uint32_t)d[20] << 24 | (uint32_t)d[21] << 16 | (uint32_t)d[22] << 8 | d[23];
    return 1;
}

/* The size rule of spec/language.md 2.2: 0, or -1 with the message. */
static int size_refused(uint32_t w, uint32_t h, const char *path, char *why, size_t whylen)
{
    if (w == 0 || h == 0 || w > GLS_MAX_TEXTURE_DIM || h > GLS_MAX_TEXTURE_DIM) {
        snprintf(why, whylen, "%s is %" PRIu32 "x%" PRIu32 ", larger than the GL limit of %ux%u", path, w, h,
                 GLS_MAX_TEXTURE_DIM, GLS_MAX_TEXTURE_DIM);
        return -1;
    }
    if ((uint64_t)w * h > GLS_MAX_TEXELS) {
        snprintf(why, whylen, "%s is %" PRIu32 "x%" PRIu32 " = %llu texels, more than the limit of %llu "
                 "(256 MiB of RGBA)", path, w, h, (unsigned long long)w * h, (unsigned long long)GLS_MAX_TEXELS);
        return -1;
    }
    return 0;
}

int gls_texture_probe(const unsigned char *data, size_t len, const char *path, int *w, int *h, char *why,
                      size_t whylen)
{
    char reason[256];
    if (gls_jpeg_is(data, len)) {
        if (gls_jpeg_info(data, len, w, h, reason, sizeof reason)) {
            snprintf(why, whylen, "cannot decode %s: JPEG: %s", path, reason);
            return -1;
        }
    } else {
        uint32_t pw, ph;
        if (png_header_size(data, len, &pw, &ph) && size_refused(pw, ph, path, why, whylen))
            return -1;
        if (png_chunk_overrun(data, len)) {
            snprintf(why, whylen, "cannot decode %s: corrupt PNG (a chunk runs past the end of the file)", path);
            return -1;
        }
        if (gls_stb_info(data, len, w, h, reason, sizeof reason)) {
            snprintf(why, whylen, "cannot decode %s: %s", path, reason);
            return -1;
        }
    }
    /* check the size from the header before decoding anything: a 20-byte
       file can declare a gigabyte of texels (found by the texture fuzzer) */
    return size_refused(*w < 0 ? 0 : (uint32_t)*w, *h < 0 ? 0 : (uint32_t)*h, path, why, whylen);
}

int gls_texture_decode_memory(const unsigned char *data, size_t len, const char *path, gls_texture *out, char *why,
                              size_t whylen)
{
    int w, h;
    if (gls_texture_probe(data, len, path, &w, &h, why, whylen))
        return -1;
    char reason[256];
    int jpeg = gls_jpeg_is(data, len);
    unsigned char *px = jpeg ? gls_jpeg_load_rgba(data, len, &w, &h, reason, sizeof reason)
                             : gls_stb_load_rgba(data, len, &w, &h, reason, sizeof reason);
    if (!px) {
        snprintf(why, whylen, "cannot decode %s: %s%s", path, jpeg ? "JPEG: " : "", reason);
        return -1;
    }
    size_t texels = (size_t)w * (size_t)h;
    out->rgba = px;
    out->width = (uint32_t)w;
    out->height = (uint32_t)h;
    out->flags = 0;
    for (size_t i = 0; i < texels; i++) {
        uint8_t *a = &out->rgba[i * 4 + 3];
        *a = *a >= 128 ? 255 : 0;
        if (!*a)
            out->flags |= GLS_TEX_ALPHA_HOLES;
    }
    return 0;
}

int gls_texture_decode(const char *path, gls_texture *out, char *why, size_t whylen)
{
    size_t len;
    char ioerr[256];
    unsigned char *data = (unsigned char *)gls_read_file(path, GLS_MAX_INPUT_BYTES, &len, ioerr, sizeof ioerr);
    if (!data) {
        snprintf(why, whylen, "%s", ioerr);
        return -1;
    }
    int r = gls_texture_decode_memory(data, len, path, out, why, whylen);
    free(data);
    return r;
}
