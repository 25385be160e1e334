/* Texture decoding through stb_image.  TGA must have 4 channels (RGBA), as
 * the original system required; PNG, JPEG and BMP are converted to RGBA.
 * Alpha is made binary here (transparent below 0.5), once, at compile time,
 * so the bundle holds exactly what the player alpha-tests. */
#include <stdlib.h>
#include <string.h>
#include <stb/stb_image.h>
#include "compile.h"
#include "fileio.h"

int gls_texture_decode_memory(const unsigned char *data, size_t len, int is_tga, const char *path, gls_texture *out,
                              char *why, size_t whylen)
{
    int w, h, comp;
    if (len > INT32_MAX || !stbi_info_from_memory(data, (int)len, &w, &h, &comp)) {
        snprintf(why, whylen, "cannot decode %s: %s", path, stbi_failure_reason() ? stbi_failure_reason() : "unknown format");
        return -1;
    }
    /* check the size from the header before decoding anything */
    if (w <= 0 || h <= 0 || (unsigned)w > GLS_MAX_TEXTURE_DIM || (unsigned)h > GLS_MAX_TEXTURE_DIM) {
        snprintf(why, whylen, "%s is %dx%d, larger than the GL limit of %ux%u", path, w, h, GLS_MAX_TEXTURE_DIM,
                 GLS_MAX_TEXTURE_DIM);
        return -1;
    }
    if (is_tga && comp != 4) {
        snprintf(why, whylen, "%s has %d channel%s; a TGA texture must be RGBA (4 channels)", path, comp,
                 comp == 1 ? "" : "s");
        return -1;
    }
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
    size_t n = strlen(path);
    int is_tga = n >= 4 && strcmp(path + n - 4, ".tga") == 0;
    int r = gls_texture_decode_memory(data, len, is_tga, path, out, why, whylen);
    free(data);
    return r;
}
