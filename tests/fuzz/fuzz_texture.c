/* libFuzzer target: texture decoding (TGA, PNG, JPEG, BMP through
 * stb_image, with glscene's size checks and alpha binarisation).  The first
 * byte chooses whether the TGA channel rule applies. */
#include <stdlib.h>
#include "compile.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    gls_texture t = {0};
    char why[256];
    if (gls_texture_decode_memory(data + 1, size - 1, data[0] & 1, "fuzz", &t, why, sizeof why) == 0)
        free(t.rgba);
    return 0;
}
