/* PNG, TGA and BMP textures through stb_image, compiled in here with only
 * those decoders (Debian's libstb would also take JPEG, GIF, PSD, HDR, PIC
 * and PNM files, and its JPEG decoder is unsafe on corrupt input:
 * texture_jpeg.c).  Its functions are static to this file, so the rest of
 * the program (and libstb, still linked for stb_image_write) never sees
 * them.  stb_image swaps TGA's BGR(A) to RGB(A) and honours its origin
 * bit. */
#include <limits.h>
#include <stdio.h>
#include "texture_codecs.h"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_TGA
#define STBI_ONLY_BMP
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
/* for the whole file: GCC reports a static function declared but never
   defined (stb_image's GIF and thread-local entry points, left out here)
   at the end of the file, after a pop */
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#ifdef __clang__
/* Two UBSan checks are off for stb_image's own functions: a PNG with an
 * empty IDAT chunk (legal) makes it compute NULL + 0 and memcpy(NULL, p,
 * 0) (found by the texture fuzzer), formally undefined but reading and
 * writing nothing.  Every other check, and ASan, stay on in the
 * sanitizer builds. */
#pragma clang attribute push(__attribute__((no_sanitize("pointer-overflow", "nonnull-attribute"))), apply_to = function)
#endif
#include <stb/stb_image.h>
#ifdef __clang__
#pragma clang attribute pop
#endif
#pragma GCC diagnostic pop

int gls_stb_info(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen)
{
    int comp;
    if (len > INT_MAX || !stbi_info_from_memory(data, (int)len, w, h, &comp)) {
        snprintf(why, whylen, "%s", stbi_failure_reason() ? stbi_failure_reason() : "unknown image type");
        return -1;
    }
    return 0;
}

/* stb_image allocates with malloc (its default STBI_MALLOC) */
unsigned char *gls_stb_load_rgba(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen)
{
    int comp;
    unsigned char *px = len > INT_MAX ? NULL : stbi_load_from_memory(data, (int)len, w, h, &comp, 4);
    if (!px)
        snprintf(why, whylen, "%s", stbi_failure_reason() ? stbi_failure_reason() : "corrupt");
    return px;
}
