/* Unit tests of the bundle format: write/read round trip, refusal of every
 * truncation and every flipped header byte, validator rejections, and the
 * precision requirement for coordinates far from the origin.  Long on
 * purpose: one function per rule of spec/bundle.md, each read on its own. */
#include <stdlib.h>
#include <string.h>
#include "bundle.h"
#include "check.h"
#include "layout.h"
#include "le.h"
#include <zlib.h>

/* A small bundle: object "a.Top" calls "a.Tri", which draws one coloured,
 * textured triangle 1e7 units from the origin. */
static gls_bundle *make_bundle(void)
{
    gls_bundle *b = calloc(1, sizeof *b);
    b->version = GLS_FORMAT_VERSION;
    b->nobjects = 2;
    b->objects = calloc(2, sizeof *b->objects);
    b->ntextures = 1;
    b->textures = calloc(1, sizeof *b->textures);
    b->textures[0].name = strdup("a.tex.T");
    b->textures[0].width = 2;
    b->textures[0].height = 1;
    b->textures[0].flags = GLS_TEX_ALPHA_HOLES;
    b->textures[0].rgba = malloc(8);
    memcpy(b->textures[0].rgba, (uint8_t[]){255, 0, 0, 255, 0, 255, 0, 0}, 8);
    b->npos = b->ncol = b->ntex = 3;
    b->pos = malloc(3 * sizeof *b->pos);
    b->col = malloc(3 * sizeof *b->col);
    b->tc = malloc(3 * sizeof *b->tc);
    for (int i = 0; i < 3; i++) {
        b->pos[i] = (gls_vec4){1e7 + 0.001 * i, -1e7 + 0.0005 * i, 12345.678901 * i, 1};
        b->col[i] = (gls_rgba){0.25f * i, 0.5f, 1.0f, 1.0f};
        b->tc[i] = (gls_st){0.5f * i, 1.0f - 0.5f * i};
    }
    gls_buf code = {0};
    gls_insn in = {.op = GLS_OP_PUSH};
    gls_insn_encode(&code, &in);
    in = (gls_insn){.op = GLS_OP_TRANS, .d = {1, 2, 3}};
    gls_insn_encode(&code, &in);
    in = (gls_insn){.op = GLS_OP_CALL, .u = {1}};
    gls_insn_encode(&code, &in);
    in = (gls_insn){.op = GLS_OP_POP};
    gls_insn_encode(&code, &in);
    in = (gls_insn){.op = GLS_OP_END};
    gls_insn_encode(&code, &in);
    b->objects[0] = (gls_object){strdup("a.Top"), code.data, (uint32_t)code.len, 5, NULL};
    gls_buf code2 = {0};
    in = (gls_insn){.op = GLS_OP_TEXTURE, .u = {0}};
    gls_insn_encode(&code2, &in);
    in = (gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_TFAN, 3, 0, 0, 0}};
    gls_insn_encode(&code2, &in);
    in = (gls_insn){.op = GLS_OP_END};
    gls_insn_encode(&code2, &in);
    b->objects[1] = (gls_object){strdup("a.Tri"), code2.data, (uint32_t)code2.len, 3, NULL};
    /* names must be sorted: "a.Top" > "a.Tri"? 'o' < 'r', so Top first */
    b->top = 0;
    b->features = gls_bundle_features(b);
    return b;
}

static uint8_t *write_it(const gls_bundle *b, size_t *len)
{
    uint8_t *out;
    gls_error err;
    if (gls_bundle_write(b, &out, len, &err)) {
        printf("  write failed: %s\n", err.msg);
        return NULL;
    }
    return out;
}

static void test_round_trip_is_lossless(void)
{
    gls_bundle *b = make_bundle();
    gls_error err;
    CHECK(gls_bundle_validate(b, &err) == 0);
    size_t len;
    uint8_t *data = write_it(b, &len);
    CHECK(data != NULL);
    gls_bundle *r = gls_bundle_read(data, len, &err);
    CHECK_MSG(r != NULL, "%s", err.msg);
    if (r) {
        CHECK(r->nobjects == 2 && r->ntextures == 1 && r->npos == 3);
        CHECK(memcmp(r->pos, b->pos, 3 * sizeof *b->pos) == 0);
        CHECK(memcmp(r->col, b->col, 3 * sizeof *b->col) == 0);
        CHECK(memcmp(r->tc, b->tc, 3 * sizeof *b->tc) == 0);
        CHECK(memcmp(r->textures[0].rgba, b->textures[0].rgba, 8) == 0);
        CHECK(r->objects[0].code_len == b->objects[0].code_len &&
              memcmp(r->objects[0].code, b->objects[0].code, b->objects[0].code_len) == 0);
        CHECK(r->features == (GLS_FEAT_TEXTURES | GLS_FEAT_ALPHA_TEST | GLS_FEAT_VERTEX_COLOR | GLS_FEAT_TEXCOORDS));
        /* writing what was read gives the same bytes */
        size_t len2;
        uint8_t *again = write_it(r, &len2);
        CHECK(again && len2 == len && memcmp(again, data, len) == 0);
        free(again);
    }
    gls_bundle_free(r);
    gls_bundle_free(b);
    free(data);
}

/* 1e7 units from the origin, 1e-3 apart, survive write and read exactly
 * (the format stores float64, so the bound 1e-3 holds with room). */
static void test_precision_far_from_origin(void)
{
    gls_bundle *b = make_bundle();
    size_t len;
    uint8_t *data = write_it(b, &len);
    gls_error err;
    gls_bundle *r = gls_bundle_read(data, len, &err);
    CHECK(r != NULL);
    if (r) {
        CHECK_NEAR(r->pos[1].x - r->pos[0].x, 0.001, 1e-8);
        CHECK_NEAR(r->pos[2].y - r->pos[0].y, 0.001, 1e-8);
        CHECK(r->pos[1].x == 1e7 + 0.001);
    }
    gls_bundle_free(r);
    gls_bundle_free(b);
    free(data);
}

static void test_every_truncation_refused(void)
{
    gls_bundle *b = make_bundle();
    size_t len;
    uint8_t *data = write_it(b, &len);
    unsigned refused = 0;
    for (size_t n = 0; n < len; n++) {
        gls_error err;
        uint8_t *copy = malloc(n ? n : 1);
        memcpy(copy, data, n);
        gls_bundle *r = gls_bundle_read(copy, n, &err);
        if (!r && err.msg[0])
            refused++;
        CHECK_MSG(r == NULL, "truncation to %zu bytes accepted", n);
        if (n >= GLS_HEADER_SIZE)
            CHECK_MSG(strstr(err.msg, "truncated") != NULL, "len %zu: %s", n, err.msg);
        gls_bundle_free(r);
        free(copy);
    }
    CHECK(refused == len);
    gls_bundle_free(b);
    free(data);
}

static void test_every_flipped_byte_refused(void)
{
    gls_bundle *b = make_bundle();
    size_t len;
    uint8_t *data = write_it(b, &len);
    /* every byte of the file, each bit pattern inverted */
    for (size_t i = 0; i < len; i++) {
        gls_error err = {{0}, 0};
        data[i] ^= 0xFF;
        gls_bundle *r = gls_bundle_read(data, len, &err);
        CHECK_MSG(r == NULL, "flipping byte %zu was not noticed", i);
        CHECK(err.msg[0] != 0);
        gls_bundle_free(r);
        data[i] ^= 0xFF;
    }
    gls_bundle_free(b);
    free(data);
}

static void test_version_mismatch_names_both(void)
{
    gls_bundle *b = make_bundle();
    size_t len;
    uint8_t *data = write_it(b, &len);
    gls_le_put_u32(data + GLS_HDR_VERSION, 7);
    gls_error err;
    gls_bundle *r = gls_bundle_read(data, len, &err);
    CHECK(r == NULL);
    CHECK_MSG(strstr(err.msg, "version 7") && strstr(err.msg, "version 2"), "%s", err.msg);
    gls_bundle_free(b);
    free(data);
}

/* A directory entry declaring a huge decoded size is refused before
 * anything is allocated or decompressed (a decompression bomb), even with
 * a valid checksum; so is one that disagrees with its zstd frame. */
static void test_declared_size_checked_before_allocating(void)
{
    gls_bundle *b = make_bundle();
    size_t len;
    uint8_t *data = write_it(b, &len);
    uint8_t *e = data + GLS_HEADER_SIZE + 3 * GLS_DIRENT_SIZE; /* POSITIONS */
    gls_le_put_u64(e + 24, 1ull << 40);
    gls_le_put_u32(data + GLS_HDR_CRC, 0);
    gls_le_put_u32(data + GLS_HDR_CRC, (uint32_t)crc32_z(crc32(0L, Z_NULL, 0), data, len));
    gls_error err;
    gls_bundle *r = gls_bundle_read(data, len, &err);
    CHECK(r == NULL);
    CHECK_MSG(strstr(err.msg, "declares 1099511627776 decoded bytes, over the limit") != NULL, "%s", err.msg);
    gls_le_put_u64(e + 24, 1000); /* within the limit, but not what the frame says */
    gls_le_put_u32(data + GLS_HDR_CRC, 0);
    gls_le_put_u32(data + GLS_HDR_CRC, (uint32_t)crc32_z(crc32(0L, Z_NULL, 0), data, len));
    r = gls_bundle_read(data, len, &err);
    CHECK(r == NULL);
    CHECK_MSG(strstr(err.msg, "zstd frame header does not declare") != NULL, "%s", err.msg);
    gls_bundle_free(r);
    gls_bundle_free(b);
    free(data);
}

/* The validator catches what a hostile writer could put in. */
static void expect_invalid(gls_bundle *b, const char *needle)
{
    gls_error err = {{0}, 0};
    CHECK_MSG(gls_bundle_validate(b, &err) != 0, "accepted, expected '%s'", needle);
    CHECK_MSG(strstr(err.msg, needle) != NULL, "message '%s' lacks '%s'", err.msg, needle);
    gls_bundle_free(b);
}

static void test_validator_rejects(void)
{
    gls_bundle *b = make_bundle();
    b->objects[1].code[0] = 200; /* unknown opcode */
    expect_invalid(b, "unknown opcode");

    b = make_bundle();
    /* PRIM first position beyond the stream: rewrite operand p */
    size_t pos = 0;
    gls_insn in;
    gls_insn_decode(b->objects[1].code, b->objects[1].code_len, &pos, &in);
    size_t prim_at = pos;
    gls_le_put_u32(b->objects[1].code + prim_at + 1 + 1 + 4, 2); /* p = 2, n = 3 > npos - 2 */
    expect_invalid(b, "positions 2+3 beyond 3");

    b = make_bundle();
    b->objects[0].code[0] = GLS_OP_POP; /* pop before push */
    expect_invalid(b, "pop without push");

    b = make_bundle();
    gls_le_put_u32(b->objects[1].code + 1, 0); /* TEXTURE 0 stays valid; make Tri call Top instead */
    {
        gls_buf code = {0};
        gls_insn c = {.op = GLS_OP_CALL, .u = {0}};
        gls_insn_encode(&code, &c);
        c = (gls_insn){.op = GLS_OP_END};
        gls_insn_encode(&code, &c);
        free(b->objects[1].code);
        b->objects[1].code = code.data;
        b->objects[1].code_len = (uint32_t)code.len;
        b->objects[1].ninsn = 2;
    }
    expect_invalid(b, "call cycle");

    b = make_bundle();
    b->pos[1].z = 1.0 / 0.0;
    expect_invalid(b, "not finite");

    b = make_bundle();
    b->textures[0].rgba[3] = 100;
    expect_invalid(b, "not binary");

    b = make_bundle();
    char *t = b->objects[0].name;
    b->objects[0].name = b->objects[1].name;
    b->objects[1].name = t;
    expect_invalid(b, "not sorted");
}

/* make_bundle() with a.Tri made for a parameter value: the object
 * "a.Tri(size=2)" and the template a.Tri (size, default 1) with its text. */
static gls_bundle *make_param_bundle(void)
{
    gls_bundle *b = make_bundle();
    free(b->objects[1].name);
    b->objects[1].name = strdup("a.Tri(size=2)");
    b->nsources = 1;
    b->sources = calloc(1, sizeof *b->sources);
    b->sources[0] = strdup("lib/a/Tri.scene");
    b->ntemplates = 1;
    b->templates = calloc(1, sizeof *b->templates);
    gls_template *t = &b->templates[0];
    t->name = strdup("a.Tri");
    t->source = 0;
    t->nparams = 1;
    t->params = calloc(1, sizeof *t->params);
    t->params[0] = strdup("size");
    t->defaults = calloc(1, sizeof *t->defaults);
    t->defaults[0] = 1;
    t->text = strdup("param size = 1;\ntfan { vert(0); vert(size); vert(0, size); }\n");
    t->text_len = (uint32_t)strlen(t->text);
    return b;
}

static void rename_object(gls_bundle *b, uint32_t i, const char *name)
{
    free(b->objects[i].name);
    b->objects[i].name = strdup(name);
}

/* Templates (spec/bundle.md 7.7) survive a round trip; the validator
 * checks them and the names of specialised objects (12.2). */
static void test_templates(void)
{
    gls_bundle *b = make_param_bundle();
    gls_error err;
    CHECK_MSG(gls_bundle_validate(b, &err) == 0, "%s", err.msg);
    size_t len;
    uint8_t *data = write_it(b, &len);
    gls_bundle *r = data ? gls_bundle_read(data, len, &err) : NULL;
    CHECK_MSG(r != NULL, "%s", err.msg);
    if (r) {
        const gls_template *t = &r->templates[0];
        CHECK(r->ntemplates == 1 && strcmp(t->name, "a.Tri") == 0 && t->nparams == 1 &&
              strcmp(t->params[0], "size") == 0 && t->defaults[0] == 1 && t->source == 0);
        CHECK(t->text_len == b->templates[0].text_len && memcmp(t->text, b->templates[0].text, t->text_len) == 0 &&
              t->text[t->text_len] == 0);
        CHECK(gls_bundle_find_template(r, "a.Tri") == 0 && gls_bundle_find_template(r, "a.Top") == GLS_NONE);
        size_t len2;
        uint8_t *again = write_it(r, &len2);
        CHECK(again && len2 == len && memcmp(again, data, len) == 0);
        free(again);
    }
    gls_bundle_free(r);
    gls_bundle_free(b);
    free(data);

    b = make_param_bundle();
    rename_object(b, 1, "a.Tri(size=2.0)"); /* not the shortest spelling */
    expect_invalid(b, "object 1: invalid name");
    b = make_param_bundle();
    rename_object(b, 1, "a.Tri(size=2");
    expect_invalid(b, "object 1: invalid name");
    b = make_param_bundle();
    rename_object(b, 1, "a.Tri(sise=2)");
    expect_invalid(b, "its parameters are not those of template a.Tri");
    b = make_param_bundle();
    rename_object(b, 1, "a.Tri(size=2,more=1)");
    expect_invalid(b, "its parameters are not those of template a.Tri");
    b = make_param_bundle();
    rename_object(b, 1, "a.Tri(size=1)");
    expect_invalid(b, "every value is the default, so its name is a.Tri");
    b = make_param_bundle();
    rename_object(b, 1, "a.Trj(size=2)");
    expect_invalid(b, "parameter values, but no template a.Trj");
    b = make_param_bundle();
    rename_object(b, 1, "a.Tri2"); /* the template's object is gone */
    expect_invalid(b, "template a.Tri: no object of it");
    b = make_param_bundle();
    b->templates[0].text[3] = 0;
    expect_invalid(b, "template a.Tri: its text is too long or has a NUL byte");
    b = make_param_bundle();
    b->templates[0].source = 1;
    expect_invalid(b, "template a.Tri: source index 1 out of range");
    b = make_param_bundle();
    b->templates[0].defaults[0] = 1.0 / 0.0;
    expect_invalid(b, "template a.Tri: the default of size is not finite");
    b = make_param_bundle();
    free(b->templates[0].params[0]);
    b->templates[0].params[0] = strdup("a.b");
    expect_invalid(b, "template a.Tri: parameter 0 is not an identifier");
}

/* Object oi's code becomes the n instructions of in, then END. */
static void set_code(gls_bundle *b, uint32_t oi, const gls_insn *in, uint32_t n)
{
    gls_buf code = {0};
    for (uint32_t i = 0; i < n; i++)
        gls_insn_encode(&code, &in[i]);
    gls_insn_encode(&code, &(gls_insn){.op = GLS_OP_END});
    free(b->objects[oi].code);
    b->objects[oi].code = code.data;
    b->objects[oi].code_len = (uint32_t)code.len;
    b->objects[oi].ninsn = n + 1;
}

/* The validator's message for object a.Tri's code in[0..n), verbatim. */
static void expect_code_message(const gls_insn *in, uint32_t n, const char *msg)
{
    gls_bundle *b = make_bundle();
    set_code(b, 1, in, n);
    gls_error err = {{0}, 0};
    CHECK_MSG(gls_bundle_validate(b, &err) != 0, "accepted, expected '%s'", msg);
    CHECK_MSG(strcmp(err.msg, msg) == 0, "message '%s', expected '%s'", err.msg, msg);
    gls_bundle_free(b);
}

/* Every operand check, one per operand kind, and the push/pop/end rules,
 * with their messages (spec/bundle.md 12.2). */
static void test_validator_operand_messages(void)
{
    const double inf = 1.0 / 0.0;
    expect_code_message(&(gls_insn){.op = GLS_OP_COLOR, .d = {0, 1.5, 0, 1}}, 1,
                        "object a.Tri, instruction 0 (color): component outside 0..1");
    expect_code_message(&(gls_insn){.op = GLS_OP_COLOR, .d = {0, 1, 0, -0.5}}, 1,
                        "object a.Tri, instruction 0 (color): component outside 0..1");
    expect_code_message(&(gls_insn){.op = GLS_OP_COLOR, .d = {2, 0.0 / 0.0, 0, 1}}, 1,
                        "object a.Tri, instruction 0 (color): operand 2 is not finite");
    expect_code_message(&(gls_insn){.op = GLS_OP_ROT, .d = {inf, 0, 0, 1}}, 1,
                        "object a.Tri, instruction 0 (rot): operand 1 is not finite");
    expect_code_message(&(gls_insn){.op = GLS_OP_TRANSFORM, .d = {[15] = -inf}}, 1,
                        "object a.Tri, instruction 0 (transform): operand 16 is not finite");
    expect_code_message(&(gls_insn){.op = GLS_OP_TEXMODE, .u = {3}}, 1,
                        "object a.Tri, instruction 0 (texmode): mode 3 unknown");
    expect_code_message(&(gls_insn){.op = GLS_OP_TEXTURE, .u = {1}}, 1,
                        "object a.Tri, instruction 0 (texture): index 1 >= 1 textures");
    expect_code_message(&(gls_insn){.op = GLS_OP_CALL, .u = {2}}, 1,
                        "object a.Tri, instruction 0 (call): index 2 >= 2 objects");
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {4, 3, 0, GLS_NONE, GLS_NONE}}, 1,
                        "object a.Tri, instruction 0 (prim): kind 4 unknown");
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_QSTRIP, 3, 0, GLS_NONE, GLS_NONE}}, 1,
                        "object a.Tri, instruction 0 (qstrip): 3 vertices is not a legal count");
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_TSTRIP, 2, 0, GLS_NONE, GLS_NONE}}, 1,
                        "object a.Tri, instruction 0 (tstrip): 2 vertices is not a legal count");
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_POLY, 3, 1, GLS_NONE, GLS_NONE}}, 1,
                        "object a.Tri, instruction 0 (prim): positions 1+3 beyond 3");
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_POLY, 3, 0, 1, GLS_NONE}}, 1,
                        "object a.Tri, instruction 0 (prim): colours 1+3 beyond 3");
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_POLY, 3, 0, GLS_NONE, 4}}, 1,
                        "object a.Tri, instruction 0 (prim): texcoords 4+3 beyond 3");
    /* the kind is checked before the count, the count before the ranges */
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {9, 1, 7, 7, 7}}, 1,
                        "object a.Tri, instruction 0 (prim): kind 9 unknown");
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_TFAN, 1, 7, 7, 7}}, 1,
                        "object a.Tri, instruction 0 (tfan): 1 vertices is not a legal count");
    gls_insn pushes[GLS_MAX_PUSH_DEPTH + 1];
    for (int i = 0; i <= (int)GLS_MAX_PUSH_DEPTH; i++)
        pushes[i] = (gls_insn){.op = GLS_OP_PUSH};
    expect_code_message(pushes, GLS_MAX_PUSH_DEPTH + 1, "object a.Tri, instruction 64: push nested deeper than 64");
    expect_code_message(pushes, 2, "object a.Tri: ends with 2 unbalanced push");
    expect_code_message(&(gls_insn){.op = GLS_OP_POP}, 1, "object a.Tri, instruction 0: pop without push");
    expect_code_message(&(gls_insn){.op = GLS_OP_END}, 1, "object a.Tri: end is not the last instruction");
}

/* The opcode table's encoding (spec/bundle.md 9.1): each opcode's size in
 * bytes, and the rules the consumers of the operand kinds rely on. */
static void test_opcode_table(void)
{
    static const unsigned size[GLS_OP_COUNT] = {
        [GLS_OP_END] = 1,   [GLS_OP_COLOR] = 33, [GLS_OP_TEXMODE] = 2,    [GLS_OP_TEXTURE] = 5,
        [GLS_OP_NOTEXTURE] = 1, [GLS_OP_TRANS] = 25, [GLS_OP_ROT] = 33,   [GLS_OP_SCALE] = 25,
        [GLS_OP_TRANSFORM] = 129, [GLS_OP_PUSH] = 1, [GLS_OP_POP] = 1,    [GLS_OP_CALL] = 5,
        [GLS_OP_PRIM] = 18, [GLS_OP_CALLN] = 9, [GLS_OP_MARK] = 29,
        [GLS_OP_CLASS] = 5, [GLS_OP_LIGHT] = 58, [GLS_OP_SPECULAR] = 33, [GLS_OP_PRIMN] = 22, [GLS_OP_SHADOWS] = 5};
    for (int op = 0; op < GLS_OP_COUNT; op++) {
        gls_buf code = {0};
        gls_insn in = {.op = (gls_opcode)op};
        CHECK(gls_insn_encode(&code, &in) == 0);
        CHECK_MSG(code.len == size[op], "%s: %zu bytes, spec says %u", gls_op[op].name, code.len, size[op]);
        size_t pos = 0;
        CHECK(gls_insn_decode(code.data, code.len, &pos, &in) == 0 && pos == code.len && in.op == (gls_opcode)op);
        pos = 0;
        CHECK(code.len == 1 || gls_insn_decode(code.data, code.len - 1, &pos, &in) != 0); /* truncated */
        free(code.data);
        /* a vertex count needs a primitive kind and positions; at most one
           object, one count and one of each vertex stream per instruction */
        int count[GLS_KIND_COUNT] = {0};
        CHECK(gls_op[op].noperands <= GLS_MAX_OPERANDS && gls_op[op].kind[gls_op[op].noperands] == GLS_KIND_COUNT);
        for (uint32_t i = 0; i < gls_op[op].noperands; i++)
            count[gls_op[op].kind[i]]++;
        CHECK(count[GLS_KIND_OBJECT] <= 1 && count[GLS_KIND_NVERT] <= 1 && count[GLS_KIND_FIRST_POS] <= 1 &&
              count[GLS_KIND_FIRST_COL] <= 1 && count[GLS_KIND_FIRST_TC] <= 1 && count[GLS_KIND_PRIMKIND] <= 1);
        CHECK(count[GLS_KIND_NVERT] == count[GLS_KIND_FIRST_POS] && count[GLS_KIND_NVERT] == count[GLS_KIND_PRIMKIND]);
        CHECK(count[GLS_KIND_NVERT] ||
              (!count[GLS_KIND_FIRST_COL] && !count[GLS_KIND_FIRST_TC] && !count[GLS_KIND_FIRST_NRM]));
        CHECK(count[GLS_KIND_FIRST_NRM] <= 1);
    }
    CHECK(strcmp(gls_op[GLS_OP_TRANSFORM].name, "transform") == 0 && GLS_NARGS_TRANSFORM == 16);
    CHECK(GLS_ARG_PRIM_N == 1 && GLS_ARG_ROT_Z == 3 && GLS_ARG_TRANSFORM_A33 == 15);
}

/* A valid-looking bundle whose calls unroll to 3 * 2^30 vertices on
 * 2^31 - 1 call paths: the validator refuses it for its paths (the
 * player's instances), and gls_bundle_expanded_vertices still says what
 * --flatten would need. */
static void test_expansion_bomb_refused(void)
{
    enum { LEVELS = 31 };
    gls_bundle *b = calloc(1, sizeof *b);
    b->version = GLS_FORMAT_VERSION;
    b->nobjects = LEVELS;
    b->objects = calloc(LEVELS, sizeof *b->objects);
    b->npos = 3;
    b->pos = calloc(3, sizeof *b->pos);
    for (int i = 0; i < 3; i++)
        b->pos[i] = (gls_vec4){i, i * i, 0, 1};
    for (int i = 0; i < LEVELS; i++) {
        gls_buf code = {0};
        gls_insn in;
        if (i < LEVELS - 1) {
            in = (gls_insn){.op = GLS_OP_CALL, .u = {(uint32_t)i + 1}};
            gls_insn_encode(&code, &in);
            gls_insn_encode(&code, &in);
        } else {
            in = (gls_insn){.op = GLS_OP_PRIM, .u = {GLS_PRIM_TFAN, 3, 0, GLS_NONE, GLS_NONE}};
            gls_insn_encode(&code, &in);
        }
        in = (gls_insn){.op = GLS_OP_END};
        gls_insn_encode(&code, &in);
        char name[16];
        snprintf(name, sizeof name, "b.L%02d", i); /* sorted by name = by level */
        b->objects[i] = (gls_object){strdup(name), code.data, (uint32_t)code.len, i < LEVELS - 1 ? 3u : 2u, NULL};
    }
    b->top = 0;
    CHECK(gls_bundle_expanded_vertices(b, LEVELS - 1) == 3);
    CHECK(gls_bundle_expanded_vertices(b, LEVELS - 10) == 3u << 9);
    CHECK(gls_bundle_expanded_vertices(b, 0) == GLS_MAX_EXPANDED_VERTICES + 1);
    uint64_t n = 0;
    CHECK(gls_bundle_count_paths(b, 0, &n) == 0 && n == (1ull << LEVELS) - 1);
    CHECK(gls_bundle_count_paths(b, LEVELS - 3, &n) == 0 && n == 7);
    expect_invalid(b, "top-level object b.L00 has more than 4194304 call paths (instances to draw) once its calls are "
                      "unrolled");
}

/* A top calling an object that draws nothing `calls` times: calls + 1
 * call paths. */
static gls_bundle *make_calls_bundle(uint32_t calls)
{
    gls_bundle *b = calloc(1, sizeof *b);
    b->version = GLS_FORMAT_VERSION;
    b->nobjects = 2;
    b->objects = calloc(2, sizeof *b->objects);
    gls_buf code = {0};
    gls_insn in = {.op = GLS_OP_CALL, .u = {1}};
    for (uint32_t i = 0; i < calls; i++)
        gls_insn_encode(&code, &in);
    in = (gls_insn){.op = GLS_OP_END};
    gls_insn_encode(&code, &in);
    b->objects[0] = (gls_object){strdup("a.Top"), code.data, (uint32_t)code.len, calls + 1, NULL};
    code = (gls_buf){0};
    gls_insn_encode(&code, &in);
    b->objects[1] = (gls_object){strdup("b.Empty"), code.data, (uint32_t)code.len, 1, NULL};
    b->top = 0;
    return b;
}

/* The call-path bound is exact, and counts paths to objects that draw
 * nothing: such paths cost the player an instance each. */
static void test_call_paths_bound(void)
{
    gls_bundle *b = make_calls_bundle(GLS_MAX_CALL_PATHS - 1);
    gls_error err = {{0}, 0};
    CHECK_MSG(gls_bundle_validate(b, &err) == 0, "2^22 call paths refused: %s", err.msg);
    gls_bundle_free(b);
    b = make_calls_bundle(GLS_MAX_CALL_PATHS);
    CHECK(gls_bundle_expanded_vertices(b, 0) == 0);
    expect_invalid(b, "top-level object a.Top has more than 4194304 call paths (instances to draw) once its calls are "
                      "unrolled");
}

/* make_bundle() with a.Top's call of a.Tri named: CALLN a.Tri "car1"
 * (and the names given, sorted). */
static gls_bundle *make_named_bundle(const char *const *names, uint32_t n)
{
    gls_bundle *b = make_bundle();
    set_code(b, 0, (gls_insn[]){{.op = GLS_OP_CALLN, .u = {1, 0}}}, 1);
    b->ninstnames = n;
    b->instnames = calloc(n ? n : 1, sizeof *b->instnames);
    for (uint32_t i = 0; i < n; i++)
        b->instnames[i] = strdup(names[i]);
    return b;
}

/* The bundle's validation message, verbatim. */
static void expect_message(gls_bundle *b, const char *msg)
{
    gls_error err = {{0}, 0};
    CHECK_MSG(gls_bundle_validate(b, &err) != 0, "accepted, expected '%s'", msg);
    CHECK_MSG(strcmp(err.msg, msg) == 0, "message '%s', expected '%s'", err.msg, msg);
    gls_bundle_free(b);
}

/* Re-checksum a written bundle after patching it. */
static void fix_crc(uint8_t *data, size_t len)
{
    gls_le_put_u32(data + GLS_HDR_CRC, 0);
    gls_le_put_u32(data + GLS_HDR_CRC, (uint32_t)crc32_z(crc32(0L, Z_NULL, 0), data, len));
}

/* INSTANCE_NAMES and CALLN (spec/bundle.md 7.8, 9.2, 12): a round trip;
 * the section only where there are names; each validation rule with its
 * message. */
static void test_instance_names(void)
{
    static const char *const one[] = {"car1"};
    gls_bundle *b = make_named_bundle(one, 1);
    gls_error err = {{0}, 0};
    CHECK_MSG(gls_bundle_validate(b, &err) == 0, "%s", err.msg);
    size_t len;
    uint8_t *data = write_it(b, &len);
    CHECK(data && gls_le_get_u32(data + GLS_HDR_NSECT) == GLS_SEC_INSTANCE_NAMES);
    gls_bundle *r = data ? gls_bundle_read(data, len, &err) : NULL;
    CHECK_MSG(r != NULL, "%s", err.msg);
    if (r) {
        CHECK(r->ninstnames == 1 && strcmp(r->instnames[0], "car1") == 0);
        size_t len2;
        uint8_t *again = write_it(r, &len2);
        CHECK(again && len2 == len && memcmp(again, data, len) == 0);
        free(again);
    }
    gls_bundle_free(r);
    gls_bundle_free(b);
    free(data);

    /* without names, the section is not written: the bundle is as before */
    b = make_bundle();
    data = write_it(b, &len);
    CHECK(data && gls_le_get_u32(data + GLS_HDR_NSECT) == GLS_SEC_REQUIRED && GLS_SEC_REQUIRED == 7);
    if (data) { /* a section count outside 7..10 is refused */
        gls_le_put_u32(data + GLS_HDR_NSECT, 11);
        fix_crc(data, len);
        r = gls_bundle_read(data, len, &err);
        CHECK(r == NULL);
        CHECK_MSG(strcmp(err.msg, "bundle has 11 sections, expected 7 to 10") == 0, "%s", err.msg);
    }
    gls_bundle_free(b);
    free(data);

    /* an empty table is never written, so it is refused */
    b = make_named_bundle(one, 1);
    if (gls_bundle_write_codec(b, GLS_CODEC_RAW, &data, &len, &err) == 0) {
        const uint8_t *e = data + GLS_HEADER_SIZE + (GLS_SEC_INSTANCE_NAMES - 1) * GLS_DIRENT_SIZE;
        gls_le_put_u32(data + gls_le_get_u64(e + 8), 0);
        fix_crc(data, len);
        r = gls_bundle_read(data, len, &err);
        CHECK(r == NULL);
        CHECK_MSG(strstr(err.msg, "instance name table: 0 names do not fit in the section") != NULL, "%s", err.msg);
        free(data);
    }
    gls_bundle_free(b);

    static const char *const bad[] = {"1car"};
    expect_message(make_named_bundle(bad, 1),
                   "instance name 0 is not a valid name ([A-Za-z_][A-Za-z0-9_.-]*, at most 64 bytes)");
    static const char *const long_name[] = {"a234567890123456789012345678901234567890123456789012345678901234x"};
    expect_message(make_named_bundle(long_name, 1),
                   "instance name 0 is not a valid name ([A-Za-z_][A-Za-z0-9_.-]*, at most 64 bytes)");
    static const char *const twice[] = {"car1", "car1"};
    expect_message(make_named_bundle(twice, 2), "instance name table not sorted or has a duplicate at car1");
    static const char *const unsorted[] = {"car2", "car1"};
    expect_message(make_named_bundle(unsorted, 2), "instance name table not sorted or has a duplicate at car1");
    /* the operand: an index into the table */
    expect_code_message(&(gls_insn){.op = GLS_OP_CALLN, .u = {1, 0}}, 1,
                        "object a.Tri, instruction 0 (calln): instance name 0 >= 0 names");
    /* reached twice from the top object (two callns of one name) */
    b = make_named_bundle(one, 1);
    set_code(b, 0, (gls_insn[]){{.op = GLS_OP_CALLN, .u = {1, 0}}, {.op = GLS_OP_CALLN, .u = {1, 0}}}, 2);
    expect_message(b, "instance name car1: reached 2 times from the top object, not once");
    /* a name no calln reached from the top object gives */
    static const char *const two[] = {"car1", "car2"};
    expect_message(make_named_bundle(two, 2), "instance name car2: reached 0 times from the top object, not once");
    /* a library bundle: no top, each name on some calln */
    b = make_named_bundle(two, 2);
    b->top = GLS_NONE;
    expect_message(b, "instance name car2: no calln names it");
}

/* make_bundle() with a.Tri's code replaced by marks of the names' indices
 * given in idx[0..n) (at (1, 2, 3)), and the name table names[0..nn). */
static gls_bundle *make_marked_bundle(const char *const *names, uint32_t nn, const uint32_t *idx, uint32_t n)
{
    gls_bundle *b = make_bundle();
    gls_insn in[4];
    for (uint32_t i = 0; i < n; i++)
        in[i] = (gls_insn){.op = GLS_OP_MARK, .u = {idx[i]}, .d = {0, 1, 2, 3}};
    set_code(b, 1, in, n);
    b->nmarknames = nn;
    b->marknames = calloc(nn ? nn : 1, sizeof *b->marknames);
    for (uint32_t i = 0; i < nn; i++)
        b->marknames[i] = strdup(names[i]);
    return b;
}

/* MARK_NAMES and MARK (spec/bundle.md 7.9, 9.1, 12): a round trip; the
 * section only where there are marks, after INSTANCE_NAMES or in its
 * place; each validation rule with its message. */
static void test_mark_names(void)
{
    static const char *const two[] = {"post.foot", "post.top"};
    static const uint32_t both[] = {1, 0};
    gls_bundle *b = make_marked_bundle(two, 2, both, 2);
    gls_error err = {{0}, 0};
    CHECK_MSG(gls_bundle_validate(b, &err) == 0, "%s", err.msg);
    size_t len;
    uint8_t *data = write_it(b, &len);
    /* 8 sections: the required 7, then MARK_NAMES (id 9) */
    CHECK(data && gls_le_get_u32(data + GLS_HDR_NSECT) == GLS_SEC_REQUIRED + 1);
    CHECK(data && gls_le_get_u32(data + GLS_HEADER_SIZE + GLS_SEC_REQUIRED * GLS_DIRENT_SIZE) == GLS_SEC_MARK_NAMES);
    CHECK(data && (gls_le_get_u32(data + GLS_HDR_FEATURES) & GLS_FEAT_MARKS));
    gls_bundle *r = data ? gls_bundle_read(data, len, &err) : NULL;
    CHECK_MSG(r != NULL, "%s", err.msg);
    if (r) {
        CHECK(r->nmarknames == 2 && strcmp(r->marknames[1], "post.top") == 0);
        size_t pos = 0;
        gls_insn in;
        CHECK(gls_insn_decode(r->objects[1].code, r->objects[1].code_len, &pos, &in) == 0);
        CHECK(in.op == GLS_OP_MARK && in.u[GLS_ARG_MARK_NAME] == 1 && in.d[GLS_ARG_MARK_X] == 1 &&
              in.d[GLS_ARG_MARK_Y] == 2 && in.d[GLS_ARG_MARK_Z] == 3);
        size_t len2;
        uint8_t *again = write_it(r, &len2);
        CHECK(again && len2 == len && memcmp(again, data, len) == 0);
        free(again);
    }
    gls_bundle_free(r);
    if (data) { /* an optional section's id must follow the one before it */
        gls_le_put_u32(data + GLS_HEADER_SIZE + GLS_SEC_REQUIRED * GLS_DIRENT_SIZE, 11);
        fix_crc(data, len);
        r = gls_bundle_read(data, len, &err);
        CHECK(r == NULL);
        CHECK_MSG(strcmp(err.msg, "section directory entry 7 has id 11, expected an optional section after 7 (up to 10)") ==
                      0, "%s", err.msg);
    }
    free(data);

    /* with instance names too: all sections but NORMALS (9 of 10), in id order */
    static const char *const car[] = {"car1"};
    b->ninstnames = 1;
    b->instnames = calloc(1, sizeof *b->instnames);
    b->instnames[0] = strdup(car[0]);
    set_code(b, 0, (gls_insn[]){{.op = GLS_OP_CALLN, .u = {1, 0}}}, 1);
    data = write_it(b, &len);
    CHECK(data && gls_le_get_u32(data + GLS_HDR_NSECT) == GLS_SEC_COUNT - 1 && GLS_SEC_COUNT == 10);
    r = data ? gls_bundle_read(data, len, &err) : NULL;
    CHECK_MSG(r && r->ninstnames == 1 && r->nmarknames == 2, "%s", err.msg);
    gls_bundle_free(r);
    free(data);
    gls_bundle_free(b);

    static const uint32_t first[] = {0};
    static const char *const bad[] = {"post top"};
    expect_message(make_marked_bundle(bad, 1, first, 1),
                   "landmark name 0 is not a valid name ([A-Za-z0-9_.-], 1 to 64 bytes)");
    static const char *const twice[] = {"a", "a"};
    expect_message(make_marked_bundle(twice, 2, first, 1), "landmark name table not sorted or has a duplicate at a");
    static const char *const unsorted[] = {"b", "a"};
    expect_message(make_marked_bundle(unsorted, 2, both, 2), "landmark name table not sorted or has a duplicate at a");
    /* one object places a name once */
    static const uint32_t again[] = {1, 0, 1};
    expect_message(make_marked_bundle(two, 2, again, 3),
                   "object a.Tri, instruction 2 (mark): landmark post.top is placed twice in the object");
    /* every name is placed by some mark */
    expect_message(make_marked_bundle(two, 2, first, 1), "landmark name post.top: no mark or class uses it");
    /* the operand: an index into the table */
    expect_code_message(&(gls_insn){.op = GLS_OP_MARK, .u = {0}}, 1,
                        "object a.Tri, instruction 0 (mark): landmark name 0 >= 0 names");
    expect_code_message(&(gls_insn){.op = GLS_OP_MARK, .u = {0}, .d = {0, 1, NAN, 3}}, 1,
                        "object a.Tri, instruction 0 (mark): operand 3 is not finite");
}

/* CLASS (spec/bundle.md 7.9, 9.1, 12): a class name lives in MARK_NAMES
 * with the landmark names; a round trip; gls_object_class; an object has
 * at most one; the table's rules cover class names; the operand is an
 * index into the table. */
static void test_class_names(void)
{
    static const char *const names[] = {"Car", "post.top"};
    gls_bundle *b = make_marked_bundle(names, 2, (const uint32_t[]){1}, 1);
    set_code(b, 1, (gls_insn[]){{.op = GLS_OP_CLASS, .u = {0}}, {.op = GLS_OP_MARK, .u = {1}, .d = {0, 1, 2, 3}}}, 2);
    gls_error err = {{0}, 0};
    CHECK_MSG(gls_bundle_validate(b, &err) == 0, "%s", err.msg);
    CHECK(gls_object_class(b, 0) == NULL && gls_object_class(b, 1) && strcmp(gls_object_class(b, 1), "Car") == 0);
    size_t len;
    uint8_t *data = write_it(b, &len);
    CHECK(data && gls_le_get_u32(data + GLS_HDR_NSECT) == GLS_SEC_REQUIRED + 1);
    gls_bundle *r = data ? gls_bundle_read(data, len, &err) : NULL;
    CHECK_MSG(r != NULL, "%s", err.msg);
    if (r) {
        CHECK(r->nmarknames == 2 && gls_object_class(r, 1) && strcmp(gls_object_class(r, 1), "Car") == 0);
        CHECK(gls_bundle_validate(r, &err) == 0);
    }
    gls_bundle_free(r);
    free(data);
    gls_bundle_free(b);

    /* a second class in one object */
    b = make_marked_bundle(names, 2, NULL, 0);
    set_code(b, 1, (gls_insn[]){{.op = GLS_OP_CLASS, .u = {0}}, {.op = GLS_OP_CLASS, .u = {1}}}, 2);
    expect_message(b, "object a.Tri, instruction 1 (class): the object has a second class post.top");
    /* a malformed class name, an unused one */
    static const char *const bad[] = {"Person sitting"};
    b = make_marked_bundle(bad, 1, NULL, 0);
    set_code(b, 1, (gls_insn[]){{.op = GLS_OP_CLASS, .u = {0}}}, 1);
    expect_message(b, "landmark name 0 is not a valid name ([A-Za-z0-9_.-], 1 to 64 bytes)");
    b = make_marked_bundle(names, 2, NULL, 0);
    set_code(b, 1, (gls_insn[]){{.op = GLS_OP_CLASS, .u = {0}}}, 1);
    expect_message(b, "landmark name post.top: no mark or class uses it");
    /* the operand: an index into the table */
    expect_code_message(&(gls_insn){.op = GLS_OP_CLASS, .u = {0}}, 1,
                        "object a.Tri, instruction 0 (class): class name 0 >= 0 names");
}

/* Lights and normals (issue 16): a PRIMN's normals round-trip through
 * the optional NORMALS section, a LIGHT sets the lights feature, and the
 * validator's messages for each of their operand rules. */
static void test_lights_and_normals(void)
{
    gls_bundle *b = make_bundle();
    gls_error err = {{0}, 0};
    b->nnrm = 3;
    b->nrm = malloc(3 * sizeof *b->nrm);
    b->nrm[0] = (gls_nrm){0, 1, 0}, b->nrm[1] = (gls_nrm){0.6f, 0.8f, 0}, b->nrm[2] = (gls_nrm){0, 0, -1};
    gls_insn lit[] = {{.op = GLS_OP_LIGHT, .u = {GLS_LIGHT_POINT}, .d = {0, 1, 2, 3, 1, 0.5, 0.25, 0.1}},
                      {.op = GLS_OP_SPECULAR, .d = {1, 1, 1, 30}},
                      {.op = GLS_OP_PRIMN, .u = {GLS_PRIM_TFAN, 3, 0, GLS_NONE, GLS_NONE, 0}}};
    set_code(b, 1, lit, 3);
    b->features = gls_bundle_features(b);
    CHECK(b->features == GLS_FEAT_LIGHTS);
    CHECK_MSG(gls_bundle_validate(b, &err) == 0, "%s", err.msg);
    size_t len;
    uint8_t *data = write_it(b, &len);
    gls_bundle *r = data ? gls_bundle_read(data, len, &err) : NULL;
    CHECK_MSG(r != NULL, "%s", err.msg);
    if (r)
        CHECK(r->nnrm == 3 && memcmp(r->nrm, b->nrm, 3 * sizeof *b->nrm) == 0 && r->features == GLS_FEAT_LIGHTS);
    gls_bundle_free(r);
    free(data);
    b->nrm[1] = (gls_nrm){0.6f, 0.6f, 0};
    CHECK(gls_bundle_validate(b, &err) != 0 && strcmp(err.msg, "normal 1 is not a finite unit vector") == 0);
    gls_bundle_free(b);
    expect_code_message(&(gls_insn){.op = GLS_OP_PRIMN, .u = {GLS_PRIM_POLY, 3, 0, GLS_NONE, GLS_NONE, 0}}, 1,
                        "object a.Tri, instruction 0 (primn): normals 0+3 beyond 0");
    expect_code_message(&(gls_insn){.op = GLS_OP_LIGHT, .u = {3}}, 1,
                        "object a.Tri, instruction 0 (light): light kind 3 unknown");
    expect_code_message(&(gls_insn){.op = GLS_OP_LIGHT, .u = {GLS_LIGHT_POINT}, .d = {0, 0, 0, 0, 1, -1, 1, 0}}, 1,
                        "object a.Tri, instruction 0 (light): operand 6 is negative");
    expect_code_message(&(gls_insn){.op = GLS_OP_SPECULAR, .d = {1, 1, 1, -3}}, 1,
                        "object a.Tri, instruction 0 (specular): operand 4 is negative");
    expect_code_message(&(gls_insn){.op = GLS_OP_LIGHT, .u = {GLS_LIGHT_DIRECTIONAL}, .d = {0, 0, 0, 0, 1, 1, 1, 0}},
                        1, "object a.Tri, instruction 0 (light): directional light with a zero direction");
    expect_code_message(&(gls_insn){.op = GLS_OP_LIGHT, .u = {GLS_LIGHT_AMBIENT}, .d = {0, 0, 1, 0, 1, 1, 1, 0}}, 1,
                        "object a.Tri, instruction 0 (light): ambient light with a position");
    expect_code_message(&(gls_insn){.op = GLS_OP_LIGHT, .u = {GLS_LIGHT_DIRECTIONAL}, .d = {0, 0, 1, 0, 1, 1, 1, 2}},
                        1, "object a.Tri, instruction 0 (light): attenuation on a light that is not a point light");
    expect_code_message(&(gls_insn){.op = GLS_OP_SHADOWS, .u = {1536}}, 1,
                        "object a.Tri, instruction 0 (shadows): shadow map side 1536 is not a power of two in 256..8192");
    expect_code_message(&(gls_insn){.op = GLS_OP_SHADOWS, .u = {16384}}, 1,
                        "object a.Tri, instruction 0 (shadows): shadow map side 16384 is not a power of two in 256..8192");
    gls_bundle *sb = make_bundle();
    set_code(sb, 1, &(gls_insn){.op = GLS_OP_SHADOWS, .u = {2048}}, 1);
    CHECK(gls_bundle_features(sb) == GLS_FEAT_SHADOWS && gls_bundle_validate(sb, &err) == 0);
    gls_bundle_free(sb);
}

int main(void)
{
    RUN(test_round_trip_is_lossless);
    RUN(test_precision_far_from_origin);
    RUN(test_every_truncation_refused);
    RUN(test_every_flipped_byte_refused);
    RUN(test_version_mismatch_names_both);
    RUN(test_declared_size_checked_before_allocating);
    RUN(test_validator_rejects);
    RUN(test_validator_operand_messages);
    RUN(test_templates);
    RUN(test_opcode_table);
    RUN(test_expansion_bomb_refused);
    RUN(test_call_paths_bound);
    RUN(test_instance_names);
    RUN(test_mark_names);
    RUN(test_class_names);
    RUN(test_lights_and_normals);
    CHECK_EXIT();
}
