/* libFuzzer target: the bundle reader and validator on arbitrary bytes;
 * whatever it accepts is then walked the way the tools walk it (dump,
 * scene flattening, the player's instanced load with its recorded walks),
 * which must stay in bounds.
 *
 * The target rewrites the header's file size and CRC to match the input
 * before reading, so that mutations get past the checksum and exercise
 * the structure and content checks (the checksum itself is tested
 * exhaustively in tests/unit/test_bundle.c).  Seeds are uncompressed
 * bundles, so mutations land in the content rather than in zstd frames. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>
#include "bundle.h"
#include "disasm.h"
#include "layout.h"
#include "le.h"
#include "scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static FILE *sink;
    if (!sink)
        sink = fopen("/dev/null", "w");
    uint8_t *copy = malloc(size ? size : 1);
    if (!copy)
        return 0;
    memcpy(copy, data, size);
    if (size >= GLS_HEADER_SIZE) {
        gls_le_put_u64(copy + GLS_HDR_FSIZE, size);
        gls_le_put_u32(copy + GLS_HDR_CRC, 0);
        gls_le_put_u32(copy + GLS_HDR_CRC, (uint32_t)crc32_z(crc32(0L, Z_NULL, 0), copy, size));
    }
    gls_error err;
    gls_bundle *b = gls_bundle_read(copy, size, &err);
    free(copy);
    if (!b)
        return 0;
    gls_disassemble(b, sink, 1);
    /* flatten small scenes only: large valid ones are slow, not wrong */
    if (b->top != GLS_NONE && gls_bundle_expanded_vertices(b, b->top) < (1u << 16)) {
        gls_scene s;
        char msg[256];
        if (gls_scene_flatten(b, &s, msg, sizeof msg) == 0)
            gls_scene_free(&s);
    }
    /* the instanced load (what glsplay draws by default), scenes of up to
     * 4096 call paths: records replayed on every path after the first */
    uint64_t paths;
    if (b->top != GLS_NONE && gls_bundle_count_paths(b, b->top, &paths) == 0 && paths <= 4096) {
        gls_scene s;
        char msg[256];
        if (gls_scene_load(b, &s, msg, sizeof msg) == 0)
            gls_scene_free(&s);
    }
    gls_bundle_free(b);
    return 0;
}
