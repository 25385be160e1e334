/* Rewrites a bundle with uncompressed sections, for fuzzing seeds.
 * usage: rawseed IN.glsb OUT.glsb */
#include <stdio.h>
#include <stdlib.h>
#include "atomic_write.h"
#include "bundle.h"
#include "layout.h"

int main(int argc, char **argv)
{
    if (argc != 3)
        return 2;
    gls_error err;
    gls_bundle *b = gls_bundle_read_file(argv[1], &err);
    uint8_t *out;
    size_t len;
    if (!b || gls_bundle_write_codec(b, GLS_CODEC_RAW, &out, &len, &err) || gls_write_file_atomic(argv[2], out, len)) {
        fprintf(stderr, "rawseed: %s\n", err.msg);
        return 1;
    }
    free(out);
    gls_bundle_free(b);
    return 0;
}
