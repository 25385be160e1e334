/* Read a bundle from bytes.  Mirror of bundle_write.c.  Every read goes
 * through the bounds-checked cursor below; every count is checked against
 * the bytes that remain before anything is allocated for it.  After the
 * structure is read, gls_bundle_validate() checks the content.
 *
 * Over 500 lines because it mirrors bundle_write.c section by section
 * (header, each section's decoding, each table) through that one cursor;
 * split across files, the mirror and the cursor would be too. */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>
/* ZSTD_d_stableOutBuffer (zstd 1.4.4 on): a parameter of the shared
 * library's ZSTD_DCtx_setParameter, declared among the experimental ones */
#define ZSTD_STATIC_LINKING_ONLY
#include <zstd.h>
#include "bundle.h"
#include "layout.h"
#include "le.h"
#include "planes.h"
#include "readfile.h"

#define FAIL(...) do { gls_fail(err, __LINE__, __VA_ARGS__); goto fail; } while (0)

void gls_fail(gls_error *err, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    err->check_line = line;
}

/* The one bounds-checked reader. */
typedef struct {
    const uint8_t *p;
    size_t len, pos;
    int bad;   /* set once a read ran past the end; later reads give 0 */
} cursor;

static const uint8_t *take(cursor *c, size_t n)
{
    if (c->bad || n > c->len - c->pos) {
        c->bad = 1;
        return NULL;
    }
    const uint8_t *r = c->p + c->pos;
    c->pos += n;
    return r;
}

static uint32_t get_u32(cursor *c)
{
    const uint8_t *q = take(c, 4);
    return q ? gls_le_get_u32(q) : 0;
}

/* A length-prefixed name, returned as a new NUL-terminated string. */
static char *get_str(cursor *c)
{
    uint32_t n = get_u32(c);
    if (n > GLS_MAX_NAME_BYTES) {
        c->bad = 1;
        return NULL;
    }
    const uint8_t *q = take(c, n);
    if (!q)
        return NULL;
    if (memchr(q, 0, n)) {
        c->bad = 1;
        return NULL;
    }
    return strndup((const char *)q, n);
}

/* count items of at least min_bytes each must fit in what is left */
static int count_fits(const cursor *c, uint64_t count, uint64_t min_bytes)
{
    return !c->bad && count * min_bytes <= c->len - c->pos;
}

static int read_objects(gls_bundle *b, cursor *c, gls_error *err)
{
    uint32_t n = get_u32(c);
    if (n > GLS_MAX_OBJECTS || !count_fits(c, n, 12))
        FAIL("object table: %u objects do not fit in the section", n);
    b->objects = calloc(n ? n : 1, sizeof *b->objects);
    if (!b->objects)
        FAIL("out of memory");
    b->nobjects = n;
    for (uint32_t i = 0; i < n; i++) {
        gls_object *o = &b->objects[i];
        o->name = get_str(c);
        o->ninsn = get_u32(c);
        o->code_len = get_u32(c);
        const uint8_t *code = take(c, o->code_len);
        if (!o->name || !code)
            FAIL("object table: entry %u is truncated or malformed", i);
        o->code = malloc(o->code_len ? o->code_len : 1);
        if (!o->code)
            FAIL("out of memory");
        memcpy(o->code, code, o->code_len);
    }
    if (c->pos != c->len)
        FAIL("object table: %zu stray bytes at its end", c->len - c->pos);
    return 0;
fail:
    return -1;
}

static int read_sources(gls_bundle *b, cursor *c, gls_error *err)
{
    uint32_t n = get_u32(c);
    if (!count_fits(c, n, 4))
        FAIL("source table: %u names do not fit in the section", n);
    b->sources = calloc(n ? n : 1, sizeof *b->sources);
    if (!b->sources)
        FAIL("out of memory");
    b->nsources = n;
    for (uint32_t i = 0; i < n; i++)
        if (!(b->sources[i] = get_str(c)))
            FAIL("source table: name %u is truncated or malformed", i);
    for (uint32_t i = 0; i < b->nobjects; i++) {
        gls_object *o = &b->objects[i];
        uint32_t has = get_u32(c);
        if (has > 1)
            FAIL("source map of object %u: flag %u is neither 0 nor 1", i, has);
        if (!has)
            continue;
        if (!count_fits(c, o->ninsn, 8))
            FAIL("source map of object %u: %u entries do not fit", i, o->ninsn);
        o->src = malloc((size_t)(o->ninsn ? o->ninsn : 1) * sizeof *o->src);
        if (!o->src)
            FAIL("out of memory");
        for (uint32_t k = 0; k < o->ninsn; k++) {
            o->src[k].file = get_u32(c);
            o->src[k].line = get_u32(c);
        }
    }
    if (c->bad || c->pos != c->len)
        FAIL("source table: malformed or stray bytes at its end");
    return 0;
fail:
    return -1;
}

static int read_textures(gls_bundle *b, cursor *c, gls_error *err)
{
    uint32_t n = get_u32(c);
    if (n > GLS_MAX_TEXTURES || !count_fits(c, n, 16))
        FAIL("texture table: %u textures do not fit in the section", n);
    b->textures = calloc(n ? n : 1, sizeof *b->textures);
    if (!b->textures)
        FAIL("out of memory");
    b->ntextures = n;
    for (uint32_t i = 0; i < n; i++) {
        gls_texture *t = &b->textures[i];
        t->name = get_str(c);
        t->width = get_u32(c);
        t->height = get_u32(c);
        t->flags = get_u32(c);
        if (!t->name)
            FAIL("texture table: entry %u is truncated or malformed", i);
        if (t->width == 0 || t->height == 0 || t->width > GLS_MAX_TEXTURE_DIM || t->height > GLS_MAX_TEXTURE_DIM)
            FAIL("texture %s: size %ux%u is outside 1..%u", t->name, t->width, t->height, GLS_MAX_TEXTURE_DIM);
        if ((uint64_t)t->width * t->height > GLS_MAX_TEXELS)
            FAIL("texture %s: %ux%u texels, more than %llu", t->name, t->width, t->height,
                 (unsigned long long)GLS_MAX_TEXELS);
    }
    for (uint32_t i = 0; i < n; i++) {
        gls_texture *t = &b->textures[i];
        size_t bytes = (size_t)t->width * t->height * 4;
        const uint8_t *q = take(c, bytes);
        if (!q)
            FAIL("texture %s: texels are truncated", t->name);
        t->rgba = malloc(bytes);
        if (!t->rgba)
            FAIL("out of memory");
        memcpy(t->rgba, q, bytes);
    }
    if (c->pos != c->len)
        FAIL("texture table: %zu stray bytes at its end", c->len - c->pos);
    return 0;
fail:
    return -1;
}

static int read_positions(gls_bundle *b, cursor *c, gls_error *err)
{
    uint32_t n = get_u32(c), ncomp = get_u32(c);
    if (ncomp != 3 && ncomp != 4)
        FAIL("position stream: %u components per vertex (must be 3 or 4)", ncomp);
    if (n > GLS_MAX_VERTICES || (uint64_t)n * ncomp * 8 != c->len - c->pos || c->bad)
        FAIL("position stream: %u vertices do not match the section size", n);
    /* straight into the vertices (gls_vec4: x, y, z, w doubles), no
     * packed copy: a 300,000-vertex scene's 7 MB of fresh pages less */
    _Static_assert(sizeof(gls_vec4) == 32, "gls_vec4 is four packed doubles");
    b->pos = malloc((size_t)n * sizeof *b->pos + 1);
    if (!b->pos)
        FAIL("out of memory");
    gls_planes_decode(c->p + c->pos, n, sizeof *b->pos, ncomp, 8, b->pos);
    int some_w = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (ncomp == 3)
            b->pos[i].w = 1.0;
        some_w |= b->pos[i].w != 1.0;
    }
    /* the writer stores w only when some w != 1: one encoding per content */
    if (ncomp == 4 && !some_w)
        FAIL("position stream: w stored although every w is 1");
    b->npos = n;
    return 0;
fail:
    return -1;
}

static int read_floats(cursor *c, uint32_t *count, void **out, unsigned ncomp, const char *what, gls_error *err)
{
    uint32_t n = get_u32(c);
    if (n > GLS_MAX_VERTICES || (uint64_t)n * ncomp * 4 != c->len - c->pos || c->bad)
        FAIL("%s stream: %u entries do not match the section size", what, n);
    *out = malloc((size_t)n * ncomp * 4 + 1);
    if (!*out)
        FAIL("out of memory");
    gls_planes_decode(c->p + c->pos, n, (size_t)ncomp * 4, ncomp, 4, *out);
    *count = n;
    return 0;
fail:
    return -1;
}

/* TEMPLATES (format version 2): entries of at least 28 bytes (a name's
 * length, source, nparams, one parameter's name length and default, the
 * text's length). */
static int read_templates(gls_bundle *b, cursor *c, gls_error *err)
{
    uint32_t n = get_u32(c);
    if (n > GLS_MAX_OBJECTS || !count_fits(c, n, 28))
        FAIL("template table: %u templates do not fit in the section", n);
    b->templates = calloc(n ? n : 1, sizeof *b->templates);
    if (!b->templates)
        FAIL("out of memory");
    b->ntemplates = n;
    for (uint32_t i = 0; i < n; i++) {
        gls_template *t = &b->templates[i];
        t->name = get_str(c);
        t->source = get_u32(c);
        t->nparams = get_u32(c);
        if (!t->name || c->bad)
            FAIL("template table: entry %u is truncated or malformed", i);
        if (t->nparams == 0 || t->nparams > GLS_MAX_PARAMS)
            FAIL("template %s: %u parameters, not 1..%u", t->name, t->nparams, GLS_MAX_PARAMS);
        t->params = calloc(t->nparams, sizeof *t->params);
        t->defaults = calloc(t->nparams, sizeof *t->defaults);
        if (!t->params || !t->defaults)
            FAIL("out of memory");
        for (uint32_t k = 0; k < t->nparams; k++) {
            t->params[k] = get_str(c);
            const uint8_t *q = take(c, 8);
            if (!t->params[k] || !q)
                FAIL("template %s: parameter %u is truncated or malformed", t->name, k);
            t->defaults[k] = gls_le_get_f64(q);
        }
        t->text_len = get_u32(c);
        if (t->text_len > GLS_MAX_TEMPLATE_TEXT)
            FAIL("template %s: %u bytes of text, more than %u", t->name, t->text_len, GLS_MAX_TEMPLATE_TEXT);
        const uint8_t *q = take(c, t->text_len);
        if (!q)
            FAIL("template %s: text is truncated", t->name);
        if (!(t->text = malloc((size_t)t->text_len + 1)))
            FAIL("out of memory");
        memcpy(t->text, q, t->text_len);
        t->text[t->text_len] = 0; /* the compiler's scanner needs the sentinel */
    }
    if (c->pos != c->len)
        FAIL("template table: %zu stray bytes at its end", c->len - c->pos);
    return 0;
fail:
    return -1;
}

/* A name table (INSTANCE_NAMES, MARK_NAMES): present only when there is
 * a name (a bundle without omits the section: one encoding per content);
 * each name a u16 length and its bytes, checked by the validator.  what
 * names the table in messages. */
static int read_names(cursor *c, uint32_t *count, char ***names, const char *what, gls_error *err)
{
    uint32_t n = get_u32(c);
    if (n == 0 || !count_fits(c, n, 3))
        FAIL("%s table: %u names do not fit in the section (an empty table is not written)", what, n);
    *names = calloc(n, sizeof **names);
    if (!*names)
        FAIL("out of memory");
    *count = n;
    for (uint32_t i = 0; i < n; i++) {
        const uint8_t *l = take(c, 2);
        uint32_t len = l ? (uint32_t)l[0] | (uint32_t)l[1] << 8 : 0;
        const uint8_t *q = take(c, len);
        if (!q || memchr(q, 0, len))
            FAIL("%s table: name %u is truncated or malformed", what, i);
        if (!((*names)[i] = strndup((const char *)q, len)))
            FAIL("out of memory");
    }
    if (c->pos != c->len)
        FAIL("%s table: %zu stray bytes at its end", what, c->len - c->pos);
    return 0;
fail:
    return -1;
}

static int read_instance_names(gls_bundle *b, cursor *c, gls_error *err)
{
    return read_names(c, &b->ninstnames, &b->instnames, "instance name", err);
}

static int read_mark_names(gls_bundle *b, cursor *c, gls_error *err)
{
    return read_names(c, &b->nmarknames, &b->marknames, "landmark name", err);
}

/* The checks that need only the first bytes of a bundle (have of them, at
 * least the header when there is one) and its length: magic, version,
 * declared file size.  The file reader runs them on the header alone,
 * before it reads the rest, so that a file that is not a bundle, or whose
 * size disagrees with its header, costs one small read. */
static int check_start(const uint8_t *data, size_t have, uint64_t len, gls_error *err)
{
    if (have < GLS_MAGIC_LEN || memcmp(data, GLS_MAGIC, GLS_MAGIC_LEN) != 0)
        FAIL("not a glscene bundle (bad magic number)");
    if (len < GLS_HEADER_SIZE)
        FAIL("bundle is truncated: %llu bytes, shorter than its %u-byte header", (unsigned long long)len,
             GLS_HEADER_SIZE);
    uint32_t version = gls_le_get_u32(data + GLS_HDR_VERSION);
    if (version != GLS_FORMAT_VERSION)
        FAIL("bundle format version %u is not supported: this build reads version %u (recompile the scene with this glsc)",
             version, GLS_FORMAT_VERSION);
    uint64_t fsize = gls_le_get_u64(data + GLS_HDR_FSIZE);
    if (fsize > len)
        FAIL("bundle is truncated: header says %llu bytes, only %llu present", (unsigned long long)fsize,
             (unsigned long long)len);
    if (fsize < len)
        FAIL("bundle has %llu bytes after its declared end (%llu bytes)", (unsigned long long)(len - fsize),
             (unsigned long long)fsize);
    if (fsize >= GLS_MAX_FILE_BYTES)
        FAIL("bundle of %llu bytes: bundles must be smaller than %llu bytes (4 GiB)", (unsigned long long)fsize,
             (unsigned long long)GLS_MAX_FILE_BYTES);
    return 0;
fail:
    return -1;
}

static int read_colors(gls_bundle *b, cursor *c, gls_error *err)
{
    return read_floats(c, &b->ncol, (void **)&b->col, 4, "colour", err);
}

static int read_texcoords(gls_bundle *b, cursor *c, gls_error *err)
{
    return read_floats(c, &b->ntex, (void **)&b->tc, 2, "texcoord", err);
}

/* NORMALS: present only when some primn has normals (an empty stream is
 * not written: one encoding per content). */
static int read_normals(gls_bundle *b, cursor *c, gls_error *err)
{
    if (read_floats(c, &b->nnrm, (void **)&b->nrm, 3, "normal", err))
        return -1;
    if (b->nnrm == 0) {
        gls_fail(err, __LINE__, "normal stream: empty (an empty stream is not written)");
        return -1;
    }
    return 0;
}

/* The file's CRC-32 (section 6 of spec/bundle.md): every byte, the four
 * of the CRC field as zeros.  crc_span adds bytes [at, at + n) of the file,
 * p holding them, to crc. */
static uLong crc_span(uLong crc, const uint8_t *p, uint64_t at, size_t n)
{
    static const uint8_t zero[4];
    while (n) {
        /* the CRC field's bytes count as zeros */
        if (at >= GLS_HDR_CRC && at < GLS_HDR_CRC + 4) {
            size_t z = (size_t)(GLS_HDR_CRC + 4 - at) < n ? (size_t)(GLS_HDR_CRC + 4 - at) : n;
            crc = crc32_z(crc, zero, z);
            p += z, at += z, n -= z;
            continue;
        }
        size_t k = at < GLS_HDR_CRC && GLS_HDR_CRC - at < n ? (size_t)(GLS_HDR_CRC - at) : n;
        crc = crc32_z(crc, p, k);
        p += k, at += k, n -= k;
    }
    return crc;
}

/* The header after check_start: checksum (crc, the file's as computed),
 * header size, section count (into *nsect), reserved fields; version,
 * features and top into b. */
static int check_header(const uint8_t *data, uLong crc, gls_bundle *b, uint32_t *nsect, gls_error *err)
{
    uint32_t version = gls_le_get_u32(data + GLS_HDR_VERSION);
    if ((uint32_t)crc != gls_le_get_u32(data + GLS_HDR_CRC))
        FAIL("bundle is corrupted: checksum mismatch (stored %08x, computed %08x)",
             gls_le_get_u32(data + GLS_HDR_CRC), (unsigned)crc);
    if (gls_le_get_u32(data + GLS_HDR_HSIZE) != GLS_HEADER_SIZE)
        FAIL("bundle header size %u is not %u", gls_le_get_u32(data + GLS_HDR_HSIZE), GLS_HEADER_SIZE);
    /* every required section, and those of the optional ones present */
    *nsect = gls_le_get_u32(data + GLS_HDR_NSECT);
    if (*nsect < GLS_SEC_REQUIRED || *nsect > GLS_SEC_COUNT)
        FAIL("bundle has %u sections, expected %u to %u", *nsect, GLS_SEC_REQUIRED, GLS_SEC_COUNT);
    if (gls_le_get_u32(data + GLS_HDR_RES0) || gls_le_get_u32(data + GLS_HDR_RES1))
        FAIL("bundle header: reserved fields are not zero");
    b->version = version;
    b->features = gls_le_get_u32(data + GLS_HDR_FEATURES);
    b->top = gls_le_get_u32(data + GLS_HDR_TOP);
    return 0;
fail:
    return -1;
}

/* Where the sections' stored bytes come from: the bundle in memory (mem,
 * gls_bundle_read), or the file fd read in order, block by block into
 * buf (gls_bundle_read_file), its CRC-32 taken again on the way.  The
 * file reader so holds one block of the file at a time, not the whole
 * file: a 9 MB bundle was 9 MB of fresh pages read, checksummed and
 * dropped, a third of glsplay's load (issue 30). */
#define BLOCK_BYTES (256u << 10)
typedef struct {
    const uint8_t *mem;
    int fd;
    uint8_t *buf;
    uint64_t at;           /* the file's offset fd is at                 */
    uLong crc;             /* of the bytes read up to at                 */
    const char *path;
    int io_failed;         /* a read failed: its message names the file  */
    ZSTD_DCtx *dctx;
} source;

/* n (<= BLOCK_BYTES) bytes of the file at its offset into buf, the CRC
 * taken.  0, or -1 with the message. */
static int src_read(source *src, size_t n, gls_error *err)
{
    if (gls_read_full(src->fd, src->buf, n)) {
        src->io_failed = 1;
        FAIL("%s: cannot read: %s", src->path, errno ? strerror(errno) : "the file shrank while reading");
    }
    src->crc = crc_span(src->crc, src->buf, src->at, n);
    src->at += n;
    return 0;
fail:
    return -1;
}

/* A section's stored bytes [off, off + stored) into raw (rl bytes, the
 * codec's checks made), from memory in one call or from the file block
 * by block (zstd's streaming decoder writing straight into raw).  Message
 * texts are the same either way: id names the section. */
static int section_bytes(source *src, uint32_t id, uint32_t codec, uint64_t off, uint64_t stored, uint64_t rl,
                         uint8_t **rawp, gls_error *err)
{
    size_t first = 0; /* file: the first block, read before raw is allocated */
    if (!src->mem) {
        first = stored < BLOCK_BYTES ? (size_t)stored : BLOCK_BYTES;
        if (src_read(src, first, err))
            goto fail;
    }
    const uint8_t *head = src->mem ? src->mem + off : src->buf;
    if (codec == GLS_CODEC_ZSTD) {
        unsigned long long fcs = ZSTD_getFrameContentSize(head, src->mem ? stored : first);
        if (fcs == ZSTD_CONTENTSIZE_ERROR || fcs == ZSTD_CONTENTSIZE_UNKNOWN || fcs != rl)
            FAIL("section %u: zstd frame header does not declare the %llu bytes the directory says", id,
                 (unsigned long long)rl);
    }
    uint8_t *raw = *rawp = malloc(rl ? rl : 1);
    if (!raw)
        FAIL("out of memory for section %u (%llu bytes)", id, (unsigned long long)rl);
    if (src->mem) {
        if (codec == GLS_CODEC_RAW) {
            memcpy(raw, head, rl);
        } else {
            size_t got = ZSTD_decompress(raw, rl, head, stored);
            if (ZSTD_isError(got) || got != rl)
                FAIL("section %u: zstd data is corrupted (%s)", id,
                     ZSTD_isError(got) ? ZSTD_getErrorName(got) : "short");
        }
        return 0;
    }
    ZSTD_outBuffer out = {raw, rl, 0};
    size_t zr = 1; /* ZSTD_decompressStream's last answer: 0 once a frame ends */
    if (codec == GLS_CODEC_ZSTD) {
        if (!src->dctx && !(src->dctx = ZSTD_createDCtx()))
            FAIL("out of memory for section %u (%llu bytes)", id, (unsigned long long)rl);
        ZSTD_DCtx_reset(src->dctx, ZSTD_reset_session_only);
        /* into raw as it stands, without zstd's own window buffer */
        ZSTD_DCtx_setParameter(src->dctx, ZSTD_d_stableOutBuffer, 1);
    }
    for (uint64_t left = stored;;) {
        size_t n = first;
        if (codec == GLS_CODEC_RAW) {
            memcpy(raw + out.pos, src->buf, n);
            out.pos += n;
        } else {
            ZSTD_inBuffer in = {src->buf, n, 0};
            while (in.pos < in.size) {
                zr = ZSTD_decompressStream(src->dctx, &out, &in);
                /* an error, or more than rl bytes (no progress) */
                if (ZSTD_isError(zr) || (zr && out.pos == out.size && in.pos < in.size))
                    goto corrupted;
            }
        }
        left -= n;
        if (!left)
            break;
        first = left < BLOCK_BYTES ? (size_t)left : BLOCK_BYTES;
        if (src_read(src, first, err))
            goto fail;
    }
    if ((codec == GLS_CODEC_ZSTD && zr != 0) || out.pos != rl)
        goto corrupted;
    return 0;
corrupted:
    /* The reason in the memory reader's words: those of ZSTD_decompress
     * on the whole section, which streaming words differently (a frame
     * cut short, trailing bytes); read again for that, on this path only. */
    {
        const char *why = "short";
        uint8_t *whole = malloc(stored ? stored : 1);
        if (whole && pread(src->fd, whole, stored, (off_t)off) == (ssize_t)stored) {
            size_t got = ZSTD_decompress(raw, rl, whole, stored);
            if (ZSTD_isError(got))
                why = ZSTD_getErrorName(got);
        }
        free(whole);
        FAIL("section %u: zstd data is corrupted (%s)", id, why);
    }
fail:
    return -1;
}

/* Section directory entry s (e, in the directory read): its id (in order
 * after ids[0..s), into ids[s]), its place (at *expect_off, contiguous;
 * *expect_off moves past it), its decoded size (under the limit, alone
 * and with *total_raw, the sections' before it), its codec; decoded into
 * raw[s], rawlen[s]. */
static int read_section(const uint8_t *e, size_t len, unsigned s, uint32_t *ids, uint64_t *expect_off,
                        uint64_t *total_raw, uint8_t **raw, uint64_t *rawlen, source *src, gls_error *err)
{
    uint32_t id = gls_le_get_u32(e), codec = gls_le_get_u32(e + 4);
    uint64_t off = gls_le_get_u64(e + 8), stored = gls_le_get_u64(e + 16), rl = gls_le_get_u64(e + 24);
    /* the required sections in order, then optional ones in id order */
    if (s < GLS_SEC_REQUIRED && id != GLS_SEC_OBJECTS + s)
        FAIL("section directory entry %u has id %u, expected %u", s, id, GLS_SEC_OBJECTS + s);
    if (s >= GLS_SEC_REQUIRED && (id <= ids[s - 1] || id > GLS_SEC_COUNT))
        FAIL("section directory entry %u has id %u, expected an optional section after %u (up to %u)", s, id,
             ids[s - 1], GLS_SEC_COUNT);
    ids[s] = id;
    if (off != *expect_off || stored > len - off)
        FAIL("section %u: offset %llu / size %llu outside the file or not contiguous", id,
             (unsigned long long)off, (unsigned long long)stored);
    *expect_off = off + stored;
    if (rl > GLS_MAX_SECTION_RAW)
        FAIL("section %u declares %llu decoded bytes, over the limit of %llu", id,
             (unsigned long long)rl, (unsigned long long)GLS_MAX_SECTION_RAW);
    /* the sum too: what the reader allocates in all (spec/bundle.md 5) */
    if (*total_raw + rl > GLS_MAX_SECTION_RAW)
        FAIL("section %u declares %llu decoded bytes, %llu with the sections before it, over the limit of %llu "
             "for all sections",
             id, (unsigned long long)rl, (unsigned long long)(*total_raw + rl),
             (unsigned long long)GLS_MAX_SECTION_RAW);
    *total_raw += rl;
    if (codec == GLS_CODEC_RAW) {
        if (rl != stored)
            FAIL("section %u: raw section with stored size %llu != decoded size %llu", id,
                 (unsigned long long)stored, (unsigned long long)rl);
    } else if (codec != GLS_CODEC_ZSTD) {
        FAIL("section %u: unknown codec %u", id, codec);
    }
    rawlen[s] = rl;
    return section_bytes(src, id, codec, off, stored, rl, &raw[s], err);
fail:
    return -1;
}

/* After check_start and check_header (data: the header and as much of
 * the directory as len holds): the directory, each section decoded from
 * src, each section's content read, the whole validated.  b is freed on
 * failure. */
static gls_bundle *read_sections(const uint8_t *data, size_t have, size_t len, uint32_t nsect, gls_bundle *b,
                                 source *src, gls_error *err)
{
    uint8_t *raw[GLS_SEC_COUNT] = {0};
    uint64_t rawlen[GLS_SEC_COUNT] = {0};
    size_t dir_end = GLS_HEADER_SIZE + nsect * GLS_DIRENT_SIZE;
    if (len < dir_end || have < dir_end)
        FAIL("bundle is truncated inside its section directory");
    uint64_t expect_off = dir_end, total_raw = 0;
    uint32_t ids[GLS_SEC_COUNT];
    for (unsigned s = 0; s < nsect; s++)
        if (read_section(data + GLS_HEADER_SIZE + s * GLS_DIRENT_SIZE, len, s, ids, &expect_off, &total_raw, raw,
                         rawlen, src, err))
            goto fail;
    if (expect_off != len)
        FAIL("bundle has %llu bytes after its last section", (unsigned long long)(len - expect_off));

    static int (*const readers[GLS_SEC_COUNT])(gls_bundle *, cursor *, gls_error *) = {
#define GLS_X_SEC(id, name, content) read_##name,
        GLS_SECTIONS(GLS_X_SEC)
#undef GLS_X_SEC
    };
    /* each section's raw bytes dropped once read: the next reader's
     * arrays take their pages */
    for (unsigned s = 0; s < nsect; s++) {
        cursor c = {raw[s], rawlen[s], 0, 0};
        int bad = readers[ids[s] - GLS_SEC_OBJECTS](b, &c, err);
        free(raw[s]);
        raw[s] = NULL;
        if (bad)
            goto fail;
    }
    if (gls_bundle_validate(b, err)) {
        gls_bundle_free(b);
        return NULL;
    }
    if (b->features != gls_bundle_features(b)) {
        gls_fail(err, __LINE__, "bundle header feature flags %#x do not match its content (%#x)", b->features,
                 gls_bundle_features(b));
        gls_bundle_free(b);
        return NULL;
    }
    return b;
fail:
    for (unsigned s = 0; s < GLS_SEC_COUNT; s++)
        free(raw[s]);
    gls_bundle_free(b);
    return NULL;
}

gls_bundle *gls_bundle_read(const uint8_t *data, size_t len, gls_error *err)
{
    gls_bundle *b = calloc(1, sizeof *b);
    if (!b)
        FAIL("out of memory");
    uint32_t nsect;
    if (check_start(data, len, len, err) ||
        check_header(data, crc_span(crc32(0L, Z_NULL, 0), data, 0, len), b, &nsect, err))
        goto fail;
    source src = {data, -1, NULL, 0, 0, NULL, 0, NULL};
    return read_sections(data, len, len, nsect, b, &src, err);
fail:
    gls_bundle_free(b);
    return NULL;
}

gls_bundle *gls_bundle_read_file(const char *path, gls_error *err)
{
    /* only a regular file, opened without waiting (readfile.h) */
    struct stat st;
    gls_read_error e;
    int fd = gls_file_open(path, &st, &e);
    gls_bundle *b = NULL;
    source src = {NULL, fd, NULL, 0, crc32(0L, Z_NULL, 0), path, 0, NULL};
    uint8_t *dir = NULL;
    if (fd < 0) {
        if (e.status == GLS_READ_OPEN)
            gls_fail(err, __LINE__, "%s: cannot open: %s", path, strerror(e.err));
        else if (e.status == GLS_READ_STAT)
            gls_fail(err, __LINE__, "%s: cannot read: %s", path, strerror(e.err));
        else if (e.status == GLS_READ_DIR)
            gls_fail(err, __LINE__, "%s: is a directory, not a bundle", path);
        else
            gls_fail(err, __LINE__, "%s: cannot read: %s", path, gls_file_kind(e.mode));
        goto fail;
    }
    /* The header first: magic, version and declared size against the
     * file's size, before anything else is read or allocated. */
    uint64_t len = (uint64_t)st.st_size;
    uint8_t head[GLS_HEADER_SIZE];
    size_t nh = len < sizeof head ? (size_t)len : sizeof head;
    if (gls_read_full(fd, head, nh)) {
        gls_fail(err, __LINE__, "%s: cannot read: %s", path, errno ? strerror(errno) : "the file shrank while reading");
        goto fail;
    }
    if (check_start(head, nh, len, err))
        goto prefix;
    /* Then the CRC of the whole file, block by block, before anything is
     * decoded (spec/bundle.md 6); then the file again from its start
     * (the page cache's copy), each section decoded as it is read, its
     * CRC taken again: a file that changed in between is refused. */
    if (!(src.buf = malloc(BLOCK_BYTES)) || !(b = calloc(1, sizeof *b))) {
        gls_fail(err, __LINE__, "%s: out of memory (%llu bytes)", path, (unsigned long long)len);
        goto fail;
    }
    src.crc = crc_span(src.crc, head, 0, nh), src.at = nh;
    for (uint64_t left = len - nh; left;) {
        size_t n = left < BLOCK_BYTES ? (size_t)left : BLOCK_BYTES;
        if (src_read(&src, n, err))
            goto fail;
        left -= n;
    }
    uint32_t nsect;
    if (check_header(head, src.crc, b, &nsect, err))
        goto prefix;
    uLong whole = src.crc;
    /* the header and the directory (at most GLS_SEC_COUNT entries) */
    size_t have = GLS_HEADER_SIZE + nsect * GLS_DIRENT_SIZE;
    if (have > len)
        have = (size_t)len;
    if (lseek(fd, 0, SEEK_SET) != 0 || !(dir = malloc(have))) {
        gls_fail(err, __LINE__, "%s: cannot read: %s", path, errno ? strerror(errno) : "out of memory");
        goto fail;
    }
    if (gls_read_full(fd, dir, have)) {
        gls_fail(err, __LINE__, "%s: cannot read: %s", path, errno ? strerror(errno) : "the file shrank while reading");
        goto fail;
    }
    src.crc = crc_span(crc32(0L, Z_NULL, 0), dir, 0, have), src.at = have;
    gls_bundle *r = read_sections(dir, have, (size_t)len, nsect, b, &src, err);
    b = NULL; /* read_sections frees it on failure */
    if (r && src.crc != whole) {
        gls_bundle_free(r);
        r = NULL;
        gls_fail(err, __LINE__, "%s: the file changed while it was read", path);
        goto fail;
    }
    if (r) {
        free(dir);
        free(src.buf);
        ZSTD_freeDCtx(src.dctx);
        close(fd);
        return r;
    }
    if (src.io_failed)
        goto fail; /* a read error's message names the file already */
prefix:
    {
        /* prefix the file name, keeping the message one line */
        char tmp[sizeof err->msg];
        memcpy(tmp, err->msg, sizeof tmp);
        snprintf(err->msg, sizeof err->msg, "%.200s: %.300s", path, tmp);
    }
fail:
    if (fd >= 0)
        close(fd);
    free(dir);
    free(src.buf);
    ZSTD_freeDCtx(src.dctx);
    gls_bundle_free(b);
    return NULL;
}
