/* The limit on decoded sections in total (spec/bundle.md 5,
 * GLS_MAX_SECTION_RAW), tested where it can be reached: this program and
 * its copy of format/bundle_read.c are compiled with the limit lowered to
 * 2^16 bytes (the Makefile's TEST_SECTION_RAW), so that a real bundle's
 * first sections plus one declared size add up past it without gigabytes.
 * At the real limit a section is decoded before the next one is looked
 * at, so two that each fit but together do not would need 2 GiB of
 * decoded data for the test. */
#include <stdlib.h>
#include <string.h>
#include <zlib.h>
#include "bundle.h"
#include "check.h"
#include "layout.h"
#include "le.h"

#define L 65536ull
#if !defined(GLS_MAX_SECTION_RAW)
#error "GLS_MAX_SECTION_RAW must be given (the Makefile's TEST_SECTION_RAW)"
#endif

/* One object, a.Top, drawing one grey triangle. */
static uint8_t *small_bundle(size_t *len)
{
    gls_bundle *b = calloc(1, sizeof *b);
    b->version = GLS_FORMAT_VERSION;
    b->nobjects = 1;
    b->objects = calloc(1, sizeof *b->objects);
    b->npos = b->ncol = b->ntex = 3;
    b->pos = malloc(3 * sizeof *b->pos);
    b->col = malloc(3 * sizeof *b->col);
    b->tc = calloc(3, sizeof *b->tc);
    for (int i = 0; i < 3; i++) {
        b->pos[i] = (gls_vec4){i, i == 1, 0, 1};
        b->col[i] = (gls_rgba){0.5f, 0.5f, 0.5f, 1};
    }
    gls_buf code = {0};
    gls_insn in = {.op = GLS_OP_PRIM, .u = {GLS_PRIM_TFAN, 3, 0, 0, 0}};
    gls_insn_encode(&code, &in);
    in = (gls_insn){.op = GLS_OP_END};
    gls_insn_encode(&code, &in);
    b->objects[0] = (gls_object){strdup("a.Top"), code.data, (uint32_t)code.len, 2, NULL};
    b->features = gls_bundle_features(b);
    uint8_t *out = NULL;
    gls_error err;
    if (gls_bundle_write(b, &out, len, &err))
        printf("  write failed: %s\n", err.msg);
    gls_bundle_free(b);
    return out;
}

/* Section s's decoded size set to rl (the checksum made good again), then
 * read: NULL expected, with message msg (a prefix of it when prefix). */
static void expect_refused(const uint8_t *orig, size_t len, unsigned s, uint64_t rl, const char *msg, int prefix)
{
    uint8_t *d = malloc(len);
    memcpy(d, orig, len);
    gls_le_put_u64(d + GLS_HEADER_SIZE + s * GLS_DIRENT_SIZE + 24, rl);
    gls_le_put_u32(d + GLS_HDR_CRC, 0);
    gls_le_put_u32(d + GLS_HDR_CRC, (uint32_t)crc32_z(crc32(0L, Z_NULL, 0), d, len));
    gls_error err;
    gls_bundle *r = gls_bundle_read(d, len, &err);
    CHECK_MSG(r == NULL, "section %u declaring %llu bytes was read", s, (unsigned long long)rl);
    if (!r)
        CHECK_MSG(prefix ? strncmp(err.msg, msg, strlen(msg)) == 0 : strcmp(err.msg, msg) == 0,
                  "message '%s', expected '%s'%s", err.msg, msg, prefix ? "..." : "");
    gls_bundle_free(r);
    free(d);
}

/* Two sections that each fit but together do not: the second is refused
 * by name, with both sizes; at exactly the limit in total the sizes pass
 * (and the frame check, next, finds the forged size); alone over the
 * limit, the section's own size is the message. */
static void test_sections_in_total(void)
{
    CHECK(GLS_MAX_SECTION_RAW == L);
    size_t len;
    uint8_t *data = small_bundle(&len);
    CHECK(data != NULL);
    if (!data)
        return;
    gls_error err;
    gls_bundle *ok = gls_bundle_read(data, len, &err);
    CHECK_MSG(ok != NULL, "the bundle itself: %s", err.msg);
    gls_bundle_free(ok);
    /* the POSITIONS section (directory entry 3): the decoded bytes before it */
    const unsigned s = 3;
    uint64_t before = 0;
    for (unsigned i = 0; i < s; i++)
        before += gls_le_get_u64(data + GLS_HEADER_SIZE + i * GLS_DIRENT_SIZE + 24);
    unsigned id = gls_le_get_u32(data + GLS_HEADER_SIZE + s * GLS_DIRENT_SIZE);
    CHECK(before > 0 && before < L && id == GLS_SEC_POSITIONS);
    char msg[256];
    uint64_t rl = L - before + 1; /* fits alone, one byte too many in all */
    snprintf(msg, sizeof msg,
             "section %u declares %llu decoded bytes, %llu with the sections before it, over the limit of %llu "
             "for all sections",
             id, (unsigned long long)rl, L + 1, L);
    expect_refused(data, len, s, rl, msg, 0);
    snprintf(msg, sizeof msg, "section %u: zstd frame header does not declare", id);
    expect_refused(data, len, s, L - before, msg, 1);
    snprintf(msg, sizeof msg, "section %u declares %llu decoded bytes, over the limit of %llu", id, L + 1, L);
    expect_refused(data, len, s, L + 1, msg, 0);
    free(data);
}

int main(void)
{
    RUN(test_sections_in_total);
    CHECK_EXIT();
}
