/* JPEG textures through libjpeg-turbo (Debian's libjpeg62-turbo).
 *
 * Why not stb_image, which decodes the other formats: the texture fuzzer
 * found four defects in Debian's stb_image 2.27 JPEG decoder (a write past
 * a table, reads of memory it never wrote, a shift by more than 31 bits on
 * truncated scan data; tests/fuzz/README.md, findings 3, 10 and 11), and
 * each guard in front of it covered only the case found.  libjpeg-turbo is
 * the reference decoder (OpenCV, browsers and image tools use it) and is
 * fuzzed continuously upstream.
 *
 * Every libjpeg warning is an error here: a JPEG libjpeg has to patch up
 * (a premature end of data, a corrupt segment) is refused with libjpeg's
 * own message rather than turned into a texture with made-up texels.
 * libjpeg reports errors through error_exit, which must not return: it
 * jumps back to the caller with longjmp, the documented way. */
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <jpeglib.h>
#include "texture_codecs.h"

/* A progressive JPEG may have any number of scans, each a pass over the
 * whole image; a tiny file with thousands of empty scans takes minutes
 * (a known denial of service; libjpeg-turbo's own fuzzers cap it too).
 * Real encoders write about ten. */
#define JPEG_MAX_SCANS 1000

typedef struct {
    struct jpeg_error_mgr mgr; /* first: libjpeg passes a pointer to it */
    struct jpeg_progress_mgr progress;
    jmp_buf back;
    char msg[JMSG_LENGTH_MAX + 64];
} jpeg_guard;

static void jpeg_fail(j_common_ptr cinfo)
{
    jpeg_guard *g = (jpeg_guard *)cinfo->err;
    char m[JMSG_LENGTH_MAX];
    g->mgr.format_message(cinfo, m);
    snprintf(g->msg, sizeof g->msg, "%s", m);
    longjmp(g->back, 1);
}

/* msg_level -1 is a warning (corrupt data libjpeg would work around);
   higher levels are trace messages, which are ignored */
static void jpeg_message(j_common_ptr cinfo, int msg_level)
{
    if (msg_level < 0)
        jpeg_fail(cinfo);
}

static void jpeg_progress(j_common_ptr cinfo)
{
    j_decompress_ptr d = (j_decompress_ptr)cinfo;
    jpeg_guard *g = (jpeg_guard *)cinfo->err;
    if (d->input_scan_number > JPEG_MAX_SCANS) {
        snprintf(g->msg, sizeof g->msg, "more than %d scans", JPEG_MAX_SCANS);
        longjmp(g->back, 1);
    }
}

/* A JPEG starts with 0xFF D8.  Any file starting with 0xFF goes to
 * libjpeg, so that a JPEG with a damaged start gets its message ("Not a
 * JPEG file: starts with ..."), except a TGA with a 255-byte ID field: its
 * second byte, the colour map type, is 0 or 1. */
int gls_jpeg_is(const unsigned char *data, size_t len)
{
    return len >= 2 && data[0] == 0xFF && data[1] > 1;
}

/* Create d and read the header into it; on an error libjpeg jumps to the
 * caller's setjmp with g->msg set.  Either way the caller destroys d. */
static void jpeg_open(struct jpeg_decompress_struct *d, jpeg_guard *g, const unsigned char *data, size_t len)
{
    d->err = jpeg_std_error(&g->mgr);
    g->mgr.error_exit = jpeg_fail;
    g->mgr.emit_message = jpeg_message;
    g->msg[0] = 0;
    jpeg_create_decompress(d);
    g->progress.progress_monitor = jpeg_progress;
    d->progress = &g->progress;
    jpeg_mem_src(d, data, (unsigned long)len);
    jpeg_read_header(d, TRUE);
}

int gls_jpeg_info(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen)
{
    struct jpeg_decompress_struct d;
    jpeg_guard g;
    memset(&d, 0, sizeof d);
    if (setjmp(g.back)) {
        snprintf(why, whylen, "%s", g.msg);
        jpeg_destroy_decompress(&d);
        return -1;
    }
    jpeg_open(&d, &g, data, len);
    *w = (int)d.image_width;
    *h = (int)d.image_height;
    jpeg_destroy_decompress(&d);
    return 0;
}

/* one CMYK texel to RGB.  Adobe's applications store CMYK inverted (255 =
 * no ink) and say so with their APP14 marker, which libjpeg reports;
 * without it the values are ink amounts.  Rounded x*y/255 as stb_image
 * does for the other formats' conversions. */
static unsigned char mul255(unsigned x, unsigned y)
{
    unsigned t = x * y + 128;
    return (unsigned char)((t + (t >> 8)) >> 8);
}

unsigned char *gls_jpeg_load_rgba(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen)
{
    struct jpeg_decompress_struct d;
    jpeg_guard g;
    /* volatile: changed between setjmp and longjmp, read after it */
    unsigned char *volatile out = NULL;
    unsigned char *volatile row = NULL;
    memset(&d, 0, sizeof d);
    if (setjmp(g.back)) {
        snprintf(why, whylen, "%s", g.msg);
        free(out);
        free(row);
        jpeg_destroy_decompress(&d);
        return NULL;
    }
    jpeg_open(&d, &g, data, len);
    int cmyk = d.jpeg_color_space == JCS_CMYK || d.jpeg_color_space == JCS_YCCK;
    int inverted = cmyk && d.saw_Adobe_marker;
    d.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
    /* the defaults, named because images must not depend on them: the
       exact integer IDCT and smooth (fancy) chroma upsampling */
    d.dct_method = JDCT_ISLOW;
    d.do_fancy_upsampling = TRUE;
    jpeg_start_decompress(&d);
    size_t width = d.output_width, height = d.output_height;
    out = malloc(width * height * 4);
    row = malloc(width * 4);
    if (!out || !row) {
        snprintf(g.msg, sizeof g.msg, "out of memory");
        longjmp(g.back, 1);
    }
    while (d.output_scanline < d.output_height) {
        size_t y = d.output_scanline;
        JSAMPROW dst = cmyk ? row : out + y * width * 4;
        jpeg_read_scanlines(&d, &dst, 1);
        if (!cmyk)
            continue;
        unsigned char *o = out + y * width * 4;
        for (size_t x = 0; x < width; x++) {
            const unsigned char *s = row + x * 4;
            unsigned k = inverted ? s[3] : 255u - s[3];
            for (int c = 0; c < 3; c++)
                o[x * 4 + c] = mul255(inverted ? s[c] : 255u - s[c], k);
            o[x * 4 + 3] = 255;
        }
    }
    jpeg_finish_decompress(&d);
    jpeg_destroy_decompress(&d);
    free(row);
    *w = (int)width;
    *h = (int)height;
    return out;
}
