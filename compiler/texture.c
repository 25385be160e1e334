/* Texture decoding through stb_image.  Every format is converted to RGBA:
 * TGA, PNG, JPEG and BMP with 1 (grey), 2 (grey + alpha), 3 (RGB) or 4
 * channels; a missing alpha channel means opaque.  stb_image swaps TGA's
 * BGR(A) byte order to RGB(A) and honours its origin bit.
 * Alpha is made binary here (transparent below 0.5), once, at compile time,
 * so the bundle holds exactly what the player alpha-tests. */
#include <stdlib.h>
#include <string.h>
#include <stb/stb_image.h>
#include "compile.h"
#include "fileio.h"

/* Debian's stb_image (2022-09) writes past a 257-entry table when a JPEG
 * Huffman table (DHT segment) declares more than 256 codes; the texture
 * fuzzer found it.  Walk all of the JPEG's marker segments (DHT may also
 * come between the scans of a progressive JPEG) and refuse such a table,
 * or a segment that runs past the end of the file (stb_image would read
 * zeros there), before stb_image sees the file.  Returns 1 to refuse. */
static int jpeg_bad_huffman(const unsigned char *d, size_t len)
{
    /* stb_image, like the JPEG standard, lets any number of 0xFF fill
       bytes precede a marker code, the first (SOI) included */
    size_t p = 0;
    while (p < len && d[p] == 0xFF)
        p++;
    if (p == 0 || p >= len || d[p] != 0xD8)
        return 0;
    p++;
    while (p + 2 <= len) {
        if (d[p] != 0xFF) {
            p++; /* entropy-coded data of a scan: skip to the next marker */
            continue;
        }
        unsigned marker = d[p + 1];
        if (marker == 0xFF) {
            p++; /* fill byte */
            continue;
        }
        if (marker == 0x00 || marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
            p += 2; /* stuffed 0xFF in scan data, SOI, TEM, restart markers */
            continue;
        }
        if (marker == 0xD9)
            return 0; /* end of image */
        if (p + 4 > len)
            return 1;
        size_t seglen = ((size_t)d[p + 2] << 8) | d[p + 3];
        if (seglen < 2 || p + 2 + seglen > len)
            return 1;
        if (marker == 0xC4) {
            size_t q = p + 4, end = p + 2 + seglen;
            while (q < end) {
                if (q + 17 > end)
                    return 1;
                size_t codes = 0;
                for (int i = 0; i < 16; i++)
                    codes += d[q + 1 + i];
                if (codes > 256 || q + 17 + codes > end)
                    return 1;
                q += 17 + codes;
            }
        }
        p += 2 + seglen;
    }
    return 0;
}

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

int gls_texture_probe(const unsigned char *data, size_t len, const char *path, int *w, int *h, char *why,
                      size_t whylen)
{
    int comp;
    if (jpeg_bad_huffman(data, len)) {
        snprintf(why, whylen, "cannot decode %s: corrupt JPEG (a Huffman table has more than 256 codes)", path);
        return -1;
    }
    if (png_chunk_overrun(data, len)) {
        snprintf(why, whylen, "cannot decode %s: corrupt PNG (a chunk runs past the end of the file)", path);
        return -1;
    }
    if (len > INT32_MAX || !stbi_info_from_memory(data, (int)len, w, h, &comp)) {
        snprintf(why, whylen, "cannot decode %s: %s", path, stbi_failure_reason() ? stbi_failure_reason() : "unknown format");
        return -1;
    }
    /* check the size from the header before decoding anything: a 20-byte
       file can declare a gigabyte of texels (found by the texture fuzzer) */
    if (*w <= 0 || *h <= 0 || (unsigned)*w > GLS_MAX_TEXTURE_DIM || (unsigned)*h > GLS_MAX_TEXTURE_DIM) {
        snprintf(why, whylen, "%s is %dx%d, larger than the GL limit of %ux%u", path, *w, *h, GLS_MAX_TEXTURE_DIM,
                 GLS_MAX_TEXTURE_DIM);
        return -1;
    }
    if ((uint64_t)*w * (uint64_t)*h > GLS_MAX_TEXELS) {
        snprintf(why, whylen, "%s is %dx%d = %llu texels, more than the limit of %llu (256 MiB of RGBA)", path, *w, *h,
                 (unsigned long long)*w * (unsigned long long)*h, (unsigned long long)GLS_MAX_TEXELS);
        return -1;
    }
    return 0;
}

int gls_texture_decode_memory(const unsigned char *data, size_t len, const char *path, gls_texture *out, char *why,
                              size_t whylen)
{
    int w, h, comp;
    if (gls_texture_probe(data, len, path, &w, &h, why, whylen))
        return -1;
    unsigned char *px = stbi_load_from_memory(data, (int)len, &w, &h, &comp, 4);
    if (!px) {
        snprintf(why, whylen, "cannot decode %s: %s", path, stbi_failure_reason() ? stbi_failure_reason() : "corrupt");
        return -1;
    }
    size_t texels = (size_t)w * (size_t)h;
    out->rgba = malloc(texels * 4);
    if (!out->rgba) {
        stbi_image_free(px);
        snprintf(why, whylen, "out of memory decoding %s", path);
        return -1;
    }
    memcpy(out->rgba, px, texels * 4);
    stbi_image_free(px);
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
