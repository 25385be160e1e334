/* Serialise a gls_bundle.  Mirror of bundle_read.c: every field written
 * here is read there, in the same order, through the same widths. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>
#include <zstd.h>
#include "bundle.h"
#include "layout.h"
#include "le.h"
#include "planes.h"

static int put_u32(gls_buf *b, uint32_t v)
{
    uint8_t t[4];
    gls_le_put_u32(t, v);
    return gls_buf_put(b, t, 4);
}

static int put_str(gls_buf *b, const char *s)
{
    size_t n = strlen(s);
    return put_u32(b, (uint32_t)n) || gls_buf_put(b, s, n);
}

static int sec_objects(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    if (put_u32(b, bd->nobjects))
        return -1;
    for (uint32_t i = 0; i < bd->nobjects; i++) {
        const gls_object *o = &bd->objects[i];
        if (put_str(b, o->name) || put_u32(b, o->ninsn) || put_u32(b, o->code_len) ||
            gls_buf_put(b, o->code, o->code_len))
            return -1;
    }
    return 0;
}

static int sec_sources(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    if (put_u32(b, bd->nsources))
        return -1;
    for (uint32_t i = 0; i < bd->nsources; i++)
        if (put_str(b, bd->sources[i]))
            return -1;
    for (uint32_t i = 0; i < bd->nobjects; i++) {
        const gls_object *o = &bd->objects[i];
        if (put_u32(b, o->src ? 1 : 0))
            return -1;
        for (uint32_t k = 0; o->src && k < o->ninsn; k++)
            if (put_u32(b, o->src[k].file) || put_u32(b, o->src[k].line))
                return -1;
    }
    return 0;
}

static int sec_textures(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    if (put_u32(b, bd->ntextures))
        return -1;
    for (uint32_t i = 0; i < bd->ntextures; i++) {
        const gls_texture *t = &bd->textures[i];
        if (put_str(b, t->name) || put_u32(b, t->width) || put_u32(b, t->height) || put_u32(b, t->flags))
            return -1;
    }
    for (uint32_t i = 0; i < bd->ntextures; i++) {
        const gls_texture *t = &bd->textures[i];
        if (gls_buf_put(b, t->rgba, (size_t)t->width * t->height * 4))
            return -1;
    }
    return 0;
}

/* A stream of count records of stride bytes, whose first ncomp words of
 * width bytes are written as planes, encoded straight into the buffer. */
static int put_planes(gls_buf *b, const void *vals, size_t count, size_t stride, unsigned ncomp, unsigned width)
{
    size_t n = count * ncomp * width;
    if (gls_buf_reserve(b, n))
        return -1;
    gls_planes_encode(vals, count, stride, ncomp, width, b->data + b->len);
    b->len += n;
    return 0;
}

static int sec_positions(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    /* w is stored only when some vertex has w != 1 */
    unsigned ncomp = (feat & GLS_FEAT_HOMOGENEOUS) ? 4 : 3;
    return put_u32(b, bd->npos) || put_u32(b, ncomp) ||
           put_planes(b, bd->pos, bd->npos, sizeof *bd->pos, ncomp, 8);
}

static int sec_colors(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    return put_u32(b, bd->ncol) || put_planes(b, bd->col, bd->ncol, sizeof *bd->col, 4, 4);
}

static int sec_texcoords(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    return put_u32(b, bd->ntex) || put_planes(b, bd->tc, bd->ntex, sizeof *bd->tc, 2, 4);
}

static int sec_templates(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    if (put_u32(b, bd->ntemplates))
        return -1;
    for (uint32_t i = 0; i < bd->ntemplates; i++) {
        const gls_template *t = &bd->templates[i];
        if (put_str(b, t->name) || put_u32(b, t->source) || put_u32(b, t->nparams))
            return -1;
        for (uint32_t k = 0; k < t->nparams; k++) {
            uint8_t d[8];
            gls_le_put_f64(d, t->defaults[k]);
            if (put_str(b, t->params[k]) || gls_buf_put(b, d, 8))
                return -1;
        }
        if (put_u32(b, t->text_len) || gls_buf_put(b, t->text, t->text_len))
            return -1;
    }
    return 0;
}

/* A name table (INSTANCE_NAMES, MARK_NAMES): the count, then each name
 * as a u16 length and its bytes. */
static int put_names(gls_buf *b, char *const *names, uint32_t n)
{
    if (put_u32(b, n))
        return -1;
    for (uint32_t i = 0; i < n; i++) {
        size_t k = strlen(names[i]);
        uint8_t len[2] = {(uint8_t)(k & 0xFF), (uint8_t)(k >> 8)};
        if (gls_buf_put(b, len, 2) || gls_buf_put(b, names[i], k))
            return -1;
    }
    return 0;
}

/* INSTANCE_NAMES and MARK_NAMES are written only when they have a name
 * (section_present), so bundles without stay as they were. */
static int sec_instance_names(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    return put_names(b, bd->instnames, bd->ninstnames);
}

static int sec_mark_names(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    return put_names(b, bd->marknames, bd->nmarknames);
}

static int sec_normals(const gls_bundle *bd, uint32_t feat, gls_buf *b)
{
    (void)feat;
    return put_u32(b, bd->nnrm) || put_planes(b, bd->nrm, bd->nnrm, sizeof *bd->nrm, 3, 4);
}

/* Is section id (GLS_SEC_*) written: every required one, an optional one
 * only when it holds an entry. */
static int section_present(const gls_bundle *bd, unsigned id)
{
    if (id == GLS_SEC_NORMALS)
        return bd->nnrm > 0;
    if (id == GLS_SEC_INSTANCE_NAMES)
        return bd->ninstnames > 0;
    if (id == GLS_SEC_MARK_NAMES)
        return bd->nmarknames > 0;
    return 1;
}

/* feat: the content's feature flags, computed once per write */
typedef int (*sec_fn)(const gls_bundle *, uint32_t feat, gls_buf *);

int gls_bundle_write(const gls_bundle *bd, uint8_t **out, size_t *outlen, gls_error *err)
{
    return gls_bundle_write_codec(bd, GLS_CODEC_ZSTD, out, outlen, err);
}

int gls_bundle_write_codec(const gls_bundle *bd, int codec, uint8_t **out, size_t *outlen, gls_error *err)
{
    static const sec_fn fns[GLS_SEC_COUNT] = {
#define GLS_X_SEC(id, name, content) sec_##name,
        GLS_SECTIONS(GLS_X_SEC)
#undef GLS_X_SEC
    };
    gls_buf file = {0};
    gls_buf raw = {0};
    ZSTD_CCtx *cctx = ZSTD_createCCtx();
    const uint32_t feat = gls_bundle_features(bd);
    unsigned nsect = 0;
    for (unsigned id = GLS_SEC_OBJECTS; id <= GLS_SEC_COUNT; id++)
        nsect += section_present(bd, id) != 0;
    uint8_t hdr[GLS_HEADER_SIZE + GLS_SEC_COUNT * GLS_DIRENT_SIZE];
    const size_t hdr_len = GLS_HEADER_SIZE + nsect * GLS_DIRENT_SIZE;
    memset(hdr, 0, sizeof hdr);
    if (!cctx || gls_buf_put(&file, hdr, hdr_len))
        goto oom;

    for (unsigned s = 0, id = GLS_SEC_OBJECTS; id <= GLS_SEC_COUNT; id++) {
        if (!section_present(bd, id))
            continue;
        raw.len = 0;
        if (fns[id - GLS_SEC_OBJECTS](bd, feat, &raw))
            goto oom;
        size_t bound = ZSTD_compressBound(raw.len);
        size_t off = file.len;
        if (gls_buf_reserve(&file, bound))
            goto oom;
        size_t z = raw.len;
        if (codec == GLS_CODEC_RAW)
            memcpy(file.data + off, raw.data, raw.len);
        else
            z = ZSTD_compressCCtx(cctx, file.data + off, bound, raw.data, raw.len, GLS_ZSTD_LEVEL);
        if (ZSTD_isError(z)) {
            snprintf(err->msg, sizeof err->msg, "zstd: %s", ZSTD_getErrorName(z));
            err->check_line = __LINE__;
            goto fail;
        }
        file.len = off + z;
        uint8_t *e = hdr + GLS_HEADER_SIZE + s++ * GLS_DIRENT_SIZE;
        gls_le_put_u32(e + 0, id);
        gls_le_put_u32(e + 4, (uint32_t)codec);
        gls_le_put_u64(e + 8, off);
        gls_le_put_u64(e + 16, z);
        gls_le_put_u64(e + 24, raw.len);
    }
    memcpy(hdr, GLS_MAGIC, GLS_MAGIC_LEN);
    gls_le_put_u32(hdr + GLS_HDR_VERSION, GLS_FORMAT_VERSION);
    gls_le_put_u32(hdr + GLS_HDR_HSIZE, GLS_HEADER_SIZE);
    gls_le_put_u32(hdr + GLS_HDR_FEATURES, feat);
    gls_le_put_u32(hdr + GLS_HDR_TOP, bd->top);
    gls_le_put_u32(hdr + GLS_HDR_NSECT, nsect);
    gls_le_put_u64(hdr + GLS_HDR_FSIZE, file.len);
    memcpy(file.data, hdr, hdr_len);
    uLong crc = crc32(0L, Z_NULL, 0);
    crc = crc32_z(crc, file.data, file.len);
    gls_le_put_u32(file.data + GLS_HDR_CRC, (uint32_t)crc);

    free(raw.data);
    ZSTD_freeCCtx(cctx);
    *out = file.data;
    *outlen = file.len;
    return 0;
oom:
    snprintf(err->msg, sizeof err->msg, "out of memory while writing the bundle");
    err->check_line = __LINE__;
fail:
    free(raw.data);
    free(file.data);
    ZSTD_freeCCtx(cctx);
    return -1;
}
