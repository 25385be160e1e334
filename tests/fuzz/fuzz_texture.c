/* libFuzzer target: texture decoding (TGA, PNG, JPEG, BMP through
 * stb_image, with glscene's size checks and alpha binarisation).  The first
 * byte chooses whether the TGA channel rule applies. */
#include <stdlib.h>
#include "compile.h"
/* Compile stb_image into the target itself, instrumented, so the fuzzer
 * sees coverage inside the decoders (Debian's libstb.so is not
 * instrumented); these definitions take precedence over the library's. */
#define STB_IMAGE_IMPLEMENTATION
/* Two UBSan checks are off for stb_image's own functions: a PNG with an
 * empty IDAT chunk (legal) makes it compute NULL + 0 and memcpy(NULL, p, 0)
 * (found by this fuzzer), formally undefined but reading and writing
 * nothing.  Every other check, and ASan, stay on. */
#pragma clang attribute push(__attribute__((no_sanitize("pointer-overflow", "nonnull-attribute"))), apply_to = function)
#include <stb/stb_image.h>
#pragma clang attribute pop

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    gls_texture t = {0};
    char why[256];
    /* large images are slow to decode, not interesting: the size checks
       before decoding are covered by the small ones (the probe is the
       product's own header check) */
    int w, h;
    if (gls_texture_probe(data + 1, size - 1, "fuzz", &w, &h, why, sizeof why) == 0 &&
        (long long)w * h > (1 << 20))
        return 0;
    if (gls_texture_decode_memory(data + 1, size - 1, "fuzz", &t, why, sizeof why) == 0)
        free(t.rgba);
    return 0;
}
