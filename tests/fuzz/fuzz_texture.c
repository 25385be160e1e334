/* libFuzzer target: texture decoding (JPEG through libjpeg-turbo; TGA,
 * PNG, BMP through stb_image; glscene's size checks and alpha
 * binarisation).  The first byte is skipped: it once chose a TGA rule
 * that is gone, and the corpus and regressions keep it. */
#include <stdlib.h>
#include "compile.h"
/* stb_image is compiled into the compiler (compiler/texture_stb.c), so in
 * the fuzz build it is instrumented like the rest, and the fuzzer sees
 * coverage inside its decoders.  libjpeg-turbo is Debian's library, not
 * instrumented: ASan sees its allocations and copies, not its reads. */

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
