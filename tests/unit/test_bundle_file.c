/* The file reader (gls_bundle_read_file) against the memory reader
 * (gls_bundle_read): the file reader holds one block of the file at a
 * time and decodes each section as it reads it (format/bundle_read.c),
 * where the memory reader has the whole bundle; for any bytes both must
 * give the same bundle, or the same message (the file's name before it).
 * The bundle's sections span several of the file reader's 256 KiB
 * blocks, so that the streaming decoder resumes across blocks. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>
#include "bundle.h"
#include "check.h"
#include "layout.h"
#include "le.h"

/* One object drawing n random triangles (positions and colours that
 * compress poorly, as a scanned or scattered scene's do). */
static gls_bundle *make_bundle(uint32_t n)
{
    gls_bundle *b = calloc(1, sizeof *b);
    b->version = GLS_FORMAT_VERSION;
    b->npos = b->ncol = 3 * n;
    b->pos = malloc(b->npos * sizeof *b->pos);
    b->col = malloc(b->ncol * sizeof *b->col);
    uint64_t s = 7;
    for (uint32_t i = 0; i < b->npos; i++) {
        double r[3];
        for (int j = 0; j < 3; j++) {
            s = s * 6364136223846793005ull + 1442695040888963407ull;
            r[j] = (double)(s >> 11) / 9007199254740992.0;
        }
        b->pos[i] = (gls_vec4){1000 * r[0], 1000 * r[1], 1000 * r[2], 1};
        b->col[i] = (gls_rgba){(float)r[1], (float)r[2], (float)r[0], 1};
    }
    gls_buf code = {0};
    for (uint32_t k = 0; k < n; k++) {
        gls_insn in = {.op = GLS_OP_PRIM, .u = {GLS_PRIM_POLY, 3, 3 * k, 3 * k, GLS_NONE}};
        gls_insn_encode(&code, &in);
    }
    gls_insn end = {.op = GLS_OP_END};
    gls_insn_encode(&code, &end);
    b->nobjects = 1;
    b->objects = calloc(1, sizeof *b->objects);
    b->objects[0] = (gls_object){strdup("a.Cloud"), code.data, (uint32_t)code.len, n + 1, NULL};
    b->top = 0;
    b->features = gls_bundle_features(b);
    return b;
}

static char dir[] = "/tmp/test_bundle_file.XXXXXX";

/* data (len bytes) read both ways: the same result.  What: the case, for
 * the failure's message. */
static int same_both_ways(const uint8_t *data, size_t len, const char *what, size_t at)
{
    char path[64];
    snprintf(path, sizeof path, "%s/b.glsb", dir);
    FILE *f = fopen(path, "wb");
    int wrote = f && fwrite(data, 1, len, f) == len;
    if (f)
        fclose(f);
    CHECK(wrote);
    gls_error em = {{0}, 0}, ef = {{0}, 0};
    gls_bundle *m = gls_bundle_read(data, len, &em);
    gls_bundle *r = gls_bundle_read_file(path, &ef);
    int same;
    if (m && r) {
        uint8_t *a = NULL, *c = NULL;
        size_t la = 0, lc = 0;
        same = !gls_bundle_write(m, &a, &la, &em) && !gls_bundle_write(r, &c, &lc, &ef) && la == lc &&
               memcmp(a, c, la) == 0;
        free(a);
        free(c);
    } else {
        char want[sizeof em.msg + 80];
        snprintf(want, sizeof want, "%s: %s", path, em.msg);
        same = !m && !r && strncmp(want, ef.msg, sizeof ef.msg - 1) == 0;
    }
    CHECK_MSG(same, "%s %zu: memory %s '%s', file %s '%s'", what, at, m ? "read" : "refused", m ? "" : em.msg,
              r ? "read" : "refused", r ? "" : ef.msg);
    gls_bundle_free(m);
    gls_bundle_free(r);
    return same;
}

static void set_crc(uint8_t *data, size_t len)
{
    gls_le_put_u32(data + GLS_HDR_CRC, 0);
    gls_le_put_u32(data + GLS_HDR_CRC, (uint32_t)crc32_z(crc32(0L, Z_NULL, 0), data, len));
}

/* The whole bundle, every truncation of its header and directory and
 * some within its sections, bytes flipped all over it (caught by the
 * CRC), and the same flips with the CRC made right (caught by the
 * directory's, zstd's, the sections' and the validator's checks). */
static void test_file_reader_as_memory_reader(void)
{
    gls_bundle *b = make_bundle(12000);
    uint8_t *data = NULL;
    size_t len = 0;
    gls_error err;
    CHECK(gls_bundle_write(b, &data, &len, &err) == 0);
    CHECK_MSG(len > 3 * (256u << 10), "the bundle is %zu bytes, not over three blocks", len);
    same_both_ways(data, len, "whole", len);
    size_t dir_end = GLS_HEADER_SIZE + gls_le_get_u32(data + GLS_HDR_NSECT) * GLS_DIRENT_SIZE;
    for (size_t n = 0; n < dir_end + 8; n++)
        if (!same_both_ways(data, n, "truncated to", n))
            break;
    for (size_t n = dir_end + 8; n < len; n += len / 13)
        if (!same_both_ways(data, n, "truncated to", n))
            break;
    /* flips: every byte of the header and directory, the first bytes
     * of each section (its zstd frame header), and bytes spread over the
     * rest */
    uint32_t nsect = gls_le_get_u32(data + GLS_HDR_NSECT);
    uint8_t *copy = malloc(len);
    for (size_t i = 0; i < len; i++) {
        int near_start = 0;
        for (uint32_t s = 0; s < nsect; s++) {
            uint64_t off = gls_le_get_u64(data + GLS_HEADER_SIZE + s * GLS_DIRENT_SIZE + 8);
            near_start |= i >= off && i < off + 24;
        }
        if (!(i < dir_end || near_start || i % (len / 29) == 0))
            continue;
        for (int fix = 0; fix < 2; fix++) {
            memcpy(copy, data, len);
            copy[i] ^= 0x5a;
            if (fix && (i < GLS_HDR_CRC || i >= GLS_HDR_CRC + 4))
                set_crc(copy, len);
            same_both_ways(copy, len, fix ? "byte flipped, CRC made right," : "byte flipped", i);
        }
    }
    free(copy);
    free(data);
    gls_bundle_free(b);
}

int main(void)
{
    if (!mkdtemp(dir)) {
        printf("FAIL test_bundle_file: mkdtemp\n");
        return 1;
    }
    RUN(test_file_reader_as_memory_reader);
    char path[64];
    snprintf(path, sizeof path, "%s/b.glsb", dir);
    unlink(path);
    rmdir(dir);
    CHECK_EXIT();
}
