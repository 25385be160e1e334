/* The on-disk layout of a bundle: header, section directory, section ids.
 * spec/bundle.md is the prose version of this file; keep them in step. */
#ifndef GLS_LAYOUT_H
#define GLS_LAYOUT_H

/* PNG-style magic: a high byte (catches 7-bit transfers), the name, CR LF
 * (catches newline translation), ^Z (stops DOS type), LF. */
#define GLS_MAGIC "\x89GLS\r\n\x1a\n"
#define GLS_MAGIC_LEN 8

/* Header: 48 bytes.
 *   0  magic[8]
 *   8  u32 format version
 *  12  u32 header size (48)
 *  16  u32 feature flags
 *  20  u32 top object index, or 0xFFFFFFFF for a library bundle
 *  24  u32 number of sections (GLS_SEC_COUNT)
 *  28  u32 reserved, zero
 *  32  u64 total file size
 *  40  u32 CRC-32 of the whole file with this field taken as zero
 *  44  u32 reserved, zero
 */
#define GLS_HEADER_SIZE 48u
#define GLS_HDR_VERSION 8
#define GLS_HDR_HSIZE 12
#define GLS_HDR_FEATURES 16
#define GLS_HDR_TOP 20
#define GLS_HDR_NSECT 24
#define GLS_HDR_RES0 28
#define GLS_HDR_FSIZE 32
#define GLS_HDR_CRC 40
#define GLS_HDR_RES1 44

/* Directory entry: 32 bytes: u32 id, u32 codec, u64 offset, u64 stored size,
 * u64 raw (decoded) size.  Entries appear in id order, sections in the file
 * in the same order, contiguous, right after the directory. */
#define GLS_DIRENT_SIZE 32u

/* The sections, in id and file order:  X(ID, name, content).  Section ID
 * is GLS_SEC_ID, numbered from 1; bundle_write.c writes each with
 * sec_<name>() and bundle_read.c reads it with read_<name>(), in this
 * order (SOURCES needs the objects read before it).  TEMPLATES came with
 * format version 2, INSTANCE_NAMES later in version 2 (before its
 * release), MARK_NAMES after it (landmarks, issue 15), NORMALS after that
 * (lighting, issue 16).  The last three are optional: each is present
 * exactly when it has an entry, so a bundle without instance names,
 * landmarks and normals has GLS_SEC_REQUIRED sections and the bytes it had
 * before any existed; the directory lists the present ones in id order
 * (bundle_read.c). */
#define GLS_SECTIONS(X)                                                              \
    X(OBJECTS,   objects,   "names, instruction counts, bytecode")                 \
    X(SOURCES,   sources,   "source file names and per-instruction lines")         \
    X(TEXTURES,  textures,  "texture names, sizes, flags, then texels")            \
    X(POSITIONS, positions, "vertex positions, float64, delta+byte planes")        \
    X(COLORS,    colors,    "vertex colours, float32, delta+byte planes")          \
    X(TEXCOORDS, texcoords, "texture coordinates, float32, delta+byte planes")     \
    X(TEMPLATES, templates, "parameterised objects: names, parameters, source text")   \
    X(INSTANCE_NAMES, instance_names, "names of named instances (calln), sorted") \
    X(MARK_NAMES, mark_names, "names of landmarks (mark), sorted")                 \
    X(NORMALS,   normals,   "unit normals of primn vertices, float32, byte planes")

enum {
    GLS_SEC_BEFORE_FIRST_ = 0,
#define GLS_X_SEC(id, name, content) GLS_SEC_##id,
    GLS_SECTIONS(GLS_X_SEC)
#undef GLS_X_SEC
    GLS_SEC_AFTER_LAST_
};
#define GLS_SEC_COUNT ((unsigned)GLS_SEC_AFTER_LAST_ - 1u)
/* Sections every bundle has: all but INSTANCE_NAMES, MARK_NAMES and
 * NORMALS, each written only when the bundle has an entry for it. */
#define GLS_SEC_REQUIRED ((unsigned)GLS_SEC_INSTANCE_NAMES - 1u)

enum { GLS_CODEC_RAW = 0, GLS_CODEC_ZSTD = 1 };

/* zstd level used by the writer: fixed, so output is deterministic. */
#define GLS_ZSTD_LEVEL 6

#endif
