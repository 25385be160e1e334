/* Unit tests of the compiler API: texture decoding orientation and alpha
 * binarisation, TGA channel counts, library override order, the precision of far-away
 * coordinates through source text, compile, write and read, and the sine
 * and cosine of angles in degrees. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "atomic_write.h"
#include "check.h"
#include "compile.h"
#include "fileio.h"
#include "mathfn.h"
#include <stb/stb_image.h>
#include <stdio.h>
#include <jpeglib.h>

static gls_bundle *compile(const char **roots, int nroots, const char *top)
{
    FILE *diag = tmpfile();
    gls_compiler *c = gls_compiler_new(diag);
    for (int i = 0; i < nroots; i++)
        gls_compiler_add_root(c, roots[i]);
    gls_bundle *b = NULL;
    if (gls_compile_top(c, top, &b) != 0) {
        rewind(diag);
        char line[512];
        while (fgets(line, sizeof line, diag))
            printf("  diag: %s", line);
    }
    gls_compiler_free(c);
    fclose(diag);
    return b;
}

/* The 2x2 TGA in tests/compiler/lang is stored top row first with a red
 * top-left texel and a transparent top-right one: the bundle keeps row 0 =
 * top, and alpha is 0 or 255. */
static void test_texture_orientation_and_alpha(void)
{
    const char *roots[] = {"tests/compiler/lang"};
    gls_bundle *b = compile(roots, 1, "Top");
    CHECK(b != NULL);
    if (!b)
        return;
    CHECK(b->ntextures == 1);
    const uint8_t *px = b->textures[0].rgba;
    CHECK(px[0] == 255 && px[1] == 0 && px[2] == 0 && px[3] == 255);  /* top-left red      */
    CHECK(px[4 + 3] == 0);                                             /* top-right: a hole */
    CHECK(px[8] == 0 && px[9] == 0 && px[10] == 255);                  /* bottom-left blue  */
    CHECK(b->textures[0].flags & GLS_TEX_ALPHA_HOLES);
    gls_bundle_free(b);
}

/* A 2x2 TGA: 18-byte header (image type, bits per pixel, descriptor with
 * the origin bit 0x20 = top row first), then the pixel bytes as given. */
static size_t make_tga(uint8_t *f, int type, int bpp, int top_first, const uint8_t *px, size_t npx)
{
    memset(f, 0, 18);
    f[2] = (uint8_t)type;
    f[12] = 2; /* width  */
    f[14] = 2; /* height */
    f[16] = (uint8_t)bpp;
    f[17] = top_first ? 0x20 : 0;
    memcpy(f + 18, px, npx);
    return 18 + npx;
}

static int texel_is(const gls_texture *t, int i, int r, int g, int b, int a)
{
    const uint8_t *p = t->rgba + 4 * i;
    return p[0] == r && p[1] == g && p[2] == b && p[3] == a;
}

/* 24-bit (BGR) and 8-bit grey TGA files are textures like RGBA ones:
 * alpha 255, channels in RGB order, row 0 = top whatever the origin bit.
 * The image: red, green on top; blue, white below (grey: 0x10, 0x80 on
 * top; 0xf0, 0x00 below). */
static void test_tga_rgb_and_grey(void)
{
    /* BGR, bottom row first / top row first */
    static const uint8_t up[] = {255, 0, 0, 255, 255, 255, 0, 0, 255, 0, 255, 0};
    static const uint8_t down[] = {0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255};
    /* run-length encoded (type 10), bottom row first: one raw packet of
       blue and white, then a run of one red and one raw green */
    static const uint8_t rle[] = {0x01, 255, 0, 0, 255, 255, 255, 0x80, 0, 0, 255, 0x00, 0, 255, 0};
    static const uint8_t grey[] = {0xf0, 0x00, 0x10, 0x80};
    const struct {
        int type, bpp, top_first;
        const uint8_t *px;
        size_t n;
    } cases[] = {{2, 24, 0, up, sizeof up}, {2, 24, 1, down, sizeof down}, {10, 24, 0, rle, sizeof rle},
                 {3, 8, 0, grey, sizeof grey}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        uint8_t file[64];
        size_t len = make_tga(file, cases[k].type, cases[k].bpp, cases[k].top_first, cases[k].px, cases[k].n);
        gls_texture t = {0};
        char why[256] = "";
        int r = gls_texture_decode_memory(file, len, "t.tga", &t, why, sizeof why);
        if (r != 0)
            printf("  case %zu: %s\n", k, why);
        CHECK(r == 0);
        if (r != 0)
            continue;
        CHECK(t.width == 2 && t.height == 2 && t.flags == 0);
        if (cases[k].bpp == 8) {
            CHECK(texel_is(&t, 0, 0x10, 0x10, 0x10, 255) && texel_is(&t, 1, 0x80, 0x80, 0x80, 255));
            CHECK(texel_is(&t, 2, 0xf0, 0xf0, 0xf0, 255) && texel_is(&t, 3, 0, 0, 0, 255));
        } else {
            CHECK(texel_is(&t, 0, 255, 0, 0, 255) && texel_is(&t, 1, 0, 255, 0, 255));
            CHECK(texel_is(&t, 2, 0, 0, 255, 255) && texel_is(&t, 3, 255, 255, 255, 255));
        }
        free(t.rgba);
    }
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

/* Far from the origin: source text 1e7 + 0.001 reaches the loaded bundle
 * with the exact double strtod gives, through compile, write and read. */
static void test_far_coordinates_exact_through_bundle(void)
{
    char dir[] = "/tmp/glstestXXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char path[256];
    snprintf(path, sizeof path, "%s/Far.scene", dir);
    write_text(path, "poly { vert(10000000.001, -10000000.002, 9999999.999); vert(10000000.002, 0, 0); vert(0, 0, 1e7); }\n");
    const char *roots[] = {dir};
    gls_bundle *b = compile(roots, 1, "Far");
    CHECK(b != NULL);
    if (!b)
        return;
    uint8_t *bytes = NULL;
    size_t len = 0;
    gls_error err;
    CHECK(gls_bundle_write(b, &bytes, &len, &err) == 0);
    gls_bundle *r = gls_bundle_read(bytes, len, &err);
    CHECK(r != NULL);
    if (r) {
        CHECK(r->pos[0].x == strtod("10000000.001", NULL));
        CHECK(r->pos[0].y == strtod("-10000000.002", NULL));
        CHECK_NEAR(r->pos[1].x - r->pos[0].x, 0.001, 1e-6);
    }
    gls_bundle_free(r);
    gls_bundle_free(b);
    free(bytes);
    remove(path);
    remove(dir);
}

/* Roots are searched in order: an object in an earlier directory overrides
 * the library bundle's object of the same name, also for calls made from
 * inside the library (names bind at link time, through the search path). */
static void test_earlier_root_overrides_library(void)
{
    char dir[] = "/tmp/glstestXXXXXX", lib[] = "/tmp/glstestXXXXXX";
    CHECK(mkdtemp(dir) && mkdtemp(lib));
    char p[256], libfile[300];
    snprintf(p, sizeof p, "%s/Leaf.scene", lib);
    write_text(p, "color(1, 0, 0);\n");
    snprintf(p, sizeof p, "%s/Tree.scene", lib);
    write_text(p, "call(\"Leaf\");\n");
    FILE *diag = tmpfile();
    gls_compiler *c = gls_compiler_new(diag);
    gls_bundle *lb = NULL;
    CHECK(gls_compile_lib(c, lib, &lb) == 0);
    gls_compiler_free(c);
    fclose(diag);
    snprintf(libfile, sizeof libfile, "%s/lib.glsb", lib);
    uint8_t *bytes = NULL;
    size_t len = 0;
    gls_error err;
    CHECK(lb && gls_bundle_write(lb, &bytes, &len, &err) == 0);
    CHECK(gls_write_file_atomic(libfile, bytes, len) == 0);
    free(bytes);
    gls_bundle_free(lb);
    snprintf(p, sizeof p, "%s/Leaf.scene", dir);
    write_text(p, "color(0, 1, 0);\n");
    const char *roots[] = {dir, libfile};
    gls_bundle *b = compile(roots, 2, "Tree");
    CHECK(b != NULL);
    if (b) {
        uint32_t leaf = gls_bundle_find_object(b, "Leaf");
        CHECK(leaf != GLS_NONE);
        gls_insn in;
        size_t pos = 0;
        CHECK(gls_insn_decode(b->objects[leaf].code, b->objects[leaf].code_len, &pos, &in) == 0);
        CHECK(in.op == GLS_OP_COLOR && in.d[0] == 0 && in.d[1] == 1); /* the directory's green Leaf */
    }
    gls_bundle_free(b);
}

/* Compile library directory dir, let edit change the bundle, write it to
 * dir/lib.glsb; then compile a scene (text, in a directory of its own)
 * against it alone: the diagnostics into msg (NULL bundle), or the
 * bundle. */
static gls_bundle *via_edited_library(const char *dir, void (*edit)(gls_bundle *), const char *text, char *msg,
                                      size_t msglen)
{
    FILE *diag = tmpfile();
    gls_compiler *c = gls_compiler_new(diag);
    gls_bundle *lb = NULL, *b = NULL;
    CHECK(gls_compile_lib(c, dir, &lb) == 0);
    gls_compiler_free(c);
    fclose(diag);
    char libfile[300], top[300], topdir[] = "/tmp/glstestXXXXXX";
    CHECK(mkdtemp(topdir) != NULL); /* not in dir: the next library would hold it */
    snprintf(libfile, sizeof libfile, "%s/lib.glsb", dir);
    snprintf(top, sizeof top, "%s/Top.scene", topdir);
    uint8_t *bytes = NULL;
    size_t len = 0;
    gls_error err;
    if (lb)
        edit(lb);
    CHECK(lb && gls_bundle_write(lb, &bytes, &len, &err) == 0);
    CHECK(gls_write_file_atomic(libfile, bytes, len) == 0);
    free(bytes);
    gls_bundle_free(lb);
    write_text(top, text);
    diag = tmpfile();
    c = gls_compiler_new(diag);
    gls_compiler_add_root(c, libfile);
    msg[0] = 0;
    if (gls_compile_top(c, top, &b) != 0) {
        rewind(diag);
        size_t n = fread(msg, 1, msglen - 1, diag);
        msg[n] = 0;
    }
    gls_compiler_free(c);
    fclose(diag);
    return b;
}

static void other_default(gls_bundle *b)
{
    uint32_t t = gls_bundle_find_template(b, "Sized");
    CHECK(t != GLS_NONE);
    if (t != GLS_NONE)
        b->templates[t].defaults[0] = 5;
}

static void broken_text(gls_bundle *b)
{
    uint32_t t = gls_bundle_find_template(b, "Sized");
    CHECK(t != GLS_NONE);
    if (t != GLS_NONE)
        b->templates[t].text_len = 22; /* "param size = 1;\npoly {" */
}

/* A library bundle's template is made for new values from its text
 * (spec/bundle.md 13): a text that does not declare the parameters and
 * defaults its table lists is refused, and errors in the text are
 * reported in it, at its source path. */
static void test_library_template_checked(void)
{
    char dir[] = "/tmp/glstestXXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char p[256], msg[4096];
    snprintf(p, sizeof p, "%s/Sized.scene", dir);
    write_text(p, "param size = 1;\npoly { vert(0); vert(size); vert(0, size); }\n");
    gls_bundle *b = via_edited_library(dir, other_default, "call(\"Sized\", size = 3);\n", msg, sizeof msg);
    CHECK_MSG(!b && strstr(msg, "error: the template of 'Sized' in a search root does not match its source text "
                                "(other parameters or defaults): rebuild that bundle"), "%s", msg);
    gls_bundle_free(b);
    b = via_edited_library(dir, broken_text, "call(\"Sized\", size = 3);\n", msg, sizeof msg);
    CHECK_MSG(!b && strstr(msg, "Sized.scene:2:1: error: syntax error: 'poly' block is not closed with '}'"), "%s",
              msg);
    gls_bundle_free(b);
}

/* Angles are reduced exactly before any conversion to radians
 * (spec/language.md 5.2): multiples of 90 degrees are exact, also far from
 * 0, and so are 30, 45 and 60; a zero is +0; other angles agree with the
 * C library's result in radians (which is off by more near its zeros, its
 * angle in radians being rounded). */
static void test_trig_degrees_exact(void)
{
    static const double s30[12] = {0, 0.5, 0.8660254037844386, 1, 0.8660254037844386, 0.5,
                                   0, -0.5, -0.8660254037844386, -1, -0.8660254037844386, -0.5};
    for (int k = -48; k <= 48; k++) {
        int i = ((k % 12) + 12) % 12;
        double a = 30.0 * k, s = gls_sin_deg(a), c = gls_cos_deg(a);
        CHECK_MSG(s == s30[i] && !(s == 0 && signbit(s)), "sin(%g) = %.17g", a, s);
        CHECK_MSG(c == s30[(i + 3) % 12] && !(c == 0 && signbit(c)), "cos(%g) = %.17g", a, c);
    }
    CHECK(gls_sin_deg(180) == 0 && gls_cos_deg(90) == 0 && gls_cos_deg(-90) == 0);
    CHECK(gls_sin_deg(45) == gls_cos_deg(45) && gls_sin_deg(45) == 0.7071067811865476);
    CHECK(gls_sin_deg(360.0 * 1e9 + 90) == 1 && gls_cos_deg(-360.0 * 1e9 + 180) == -1);
    for (double a = -720; a <= 720; a += 7.25) {
        double r = a * 3.141592653589793 / 180;
        CHECK_MSG(fabs(gls_sin_deg(a) - sin(r)) <= 1e-14 && fabs(gls_cos_deg(a) - cos(r)) <= 1e-14, "angle %g", a);
    }
}

/* JPEG textures (tests/jpeg/, written once by make.py with Debian's OpenCV,
 * libjpeg-turbo): each variant a user's files may come in decodes to the
 * texels OpenCV gives, the right way up with its channels in order;
 * corrupt files are refused with libjpeg's message. */
static unsigned char *read_all(const char *path, size_t *len)
{
    char why[256];
    unsigned char *d = (unsigned char *)gls_read_file(path, 1 << 20, len, why, sizeof why);
    if (!d)
        printf("  %s\n", why);
    return d;
}

static void test_jpeg_variants_decode(void)
{
    const char *names[] = {"baseline", "grey", "progressive", "progressive_grey", "restart", "optimized"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        char path[128], ref[128], why[256] = "";
        snprintf(path, sizeof path, "tests/jpeg/%s.jpg", names[k]);
        snprintf(ref, sizeof ref, "tests/jpeg/%s.decoded.png", names[k]);
        size_t len;
        unsigned char *d = read_all(path, &len);
        int rw, rh, rc;
        unsigned char *want = stbi_load(ref, &rw, &rh, &rc, 4);
        CHECK(d && want);
        gls_texture t = {0};
        int r = d ? gls_texture_decode_memory(d, len, path, &t, why, sizeof why) : -1;
        if (r != 0)
            printf("  %s: %s\n", names[k], why);
        CHECK(r == 0);
        if (r == 0 && want) {
            CHECK(t.width == 24 && t.height == 16 && rw == 24 && rh == 16);
            /* the same library with the same settings (exact integer
               IDCT, smooth upsampling): the same texels as OpenCV */
            int maxd = 0;
            for (int i = 0; i < 24 * 16 * 4; i++)
                maxd = abs((int)t.rgba[i] - (int)want[i]) > maxd ? abs((int)t.rgba[i] - (int)want[i]) : maxd;
            if (maxd)
                printf("  %s: glscene and OpenCV differ by up to %d levels\n", names[k], maxd);
            CHECK(maxd == 0);
            /* independent of the reference: the blue square at the top
               left, the white bar at the bottom right, the red ramp rising
               to the right (grey files: their luminance) */
            const unsigned char *sq = t.rgba + (4 * 24 + 4) * 4, *bar = t.rgba + (13 * 24 + 18) * 4;
            const unsigned char *left = t.rgba + (10 * 24 + 0) * 4, *right = t.rgba + (10 * 24 + 23) * 4;
            if (strstr(names[k], "grey"))
                CHECK(bar[0] > 240 && sq[0] < 60 && sq[0] == sq[2] && left[0] < right[0]);
            else
                CHECK(sq[2] > 200 && sq[0] < 60 && bar[0] > 230 && bar[1] > 230 && bar[2] > 200 &&
                      right[0] > left[0] + 150);
        }
        free(t.rgba);
        stbi_image_free(want);
        free(d);
    }
}

static void test_jpeg_refused(void)
{
    /* libjpeg-turbo's messages; a warning (corrupt data it would patch up)
       is an error too */
    const struct {
        const char *name, *why;
    } cases[] = {{"bad_undefined_huffman", "Corrupt JPEG data: 121 extraneous bytes before marker 0xd9"},
                 {"bad_undefined_quant", "Quantization table 0x01 was not defined"},
                 {"bad_truncated", "Premature end of JPEG file"},
                 {"bad_huffman_overflow", "Bogus Huffman table definition"}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char path[128], why[256] = "", want[256];
        snprintf(path, sizeof path, "tests/jpeg/%s.jpg", cases[k].name);
        snprintf(want, sizeof want, "cannot decode %s: JPEG: %s", path, cases[k].why);
        size_t len;
        unsigned char *d = read_all(path, &len);
        CHECK(d != NULL);
        if (!d)
            continue;
        gls_texture t = {0};
        int r = gls_texture_decode_memory(d, len, path, &t, why, sizeof why);
        if (r != -1 || strcmp(why, want) != 0)
            printf("  %s: %d '%s'\n", cases[k].name, r, why);
        CHECK(r == -1 && strcmp(why, want) == 0 && t.rgba == NULL);
        free(d);
    }
}

/* A frame whose two chroma components are in no scan: libjpeg-turbo
 * zeroes coefficients it never read, so the chroma is neutral and the
 * file decodes, the same on every run, to its grey luminance (stb_image
 * decoded memory it never wrote). */
static void test_jpeg_component_in_no_scan(void)
{
    size_t len, glen;
    unsigned char *d = read_all("tests/jpeg/component_in_no_scan.jpg", &len);
    unsigned char *g = read_all("tests/jpeg/grey.jpg", &glen);
    CHECK(d && g);
    if (!d || !g) {
        free(d);
        free(g);
        return;
    }
    gls_texture a = {0}, b = {0}, grey = {0};
    char why[256] = "";
    CHECK(gls_texture_decode_memory(d, len, "a.jpg", &a, why, sizeof why) == 0);
    CHECK(gls_texture_decode_memory(d, len, "b.jpg", &b, why, sizeof why) == 0);
    CHECK(gls_texture_decode_memory(g, glen, "grey.jpg", &grey, why, sizeof why) == 0);
    if (a.rgba && b.rgba && grey.rgba) {
        CHECK(memcmp(a.rgba, b.rgba, 24 * 16 * 4) == 0);
        int maxd = 0;
        for (int i = 0; i < 24 * 16 * 4; i++)
            maxd = abs(a.rgba[i] - grey.rgba[i]) > maxd ? abs(a.rgba[i] - grey.rgba[i]) : maxd;
        if (maxd > 1)
            printf("  differs from the grey decoding by %d levels\n", maxd);
        CHECK(maxd <= 1);
    }
    free(a.rgba);
    free(b.rgba);
    free(grey.rgba);
    free(d);
    free(g);
}

/* CMYK JPEGs (libjpeg-turbo encodes them here; OpenCV cannot): Adobe's
 * APP14 marker means the values are stored inverted (255 = no ink), and
 * without it they are ink amounts.  Each 8x8 block is one flat colour, so
 * quality 100 keeps it within a level. */
static unsigned char *encode_cmyk(int adobe, unsigned long *len)
{
    struct jpeg_compress_struct c;
    struct jpeg_error_mgr err;
    unsigned char *out = NULL;
    c.err = jpeg_std_error(&err);
    jpeg_create_compress(&c);
    jpeg_mem_dest(&c, &out, len);
    c.image_width = 16;
    c.image_height = 8;
    c.input_components = 4;
    c.in_color_space = JCS_CMYK;
    jpeg_set_defaults(&c);
    jpeg_set_colorspace(&c, JCS_CMYK);
    jpeg_set_quality(&c, 100, TRUE);
    c.write_Adobe_marker = adobe ? TRUE : FALSE;
    jpeg_start_compress(&c, TRUE);
    unsigned char row[16 * 4];
    for (int x = 0; x < 16; x++) {
        static const unsigned char left[4] = {255, 0, 255, 255}, right[4] = {0, 255, 255, 128};
        memcpy(row + x * 4, x < 8 ? left : right, 4);
    }
    JSAMPROW r = row;
    for (int y = 0; y < 8; y++)
        jpeg_write_scanlines(&c, &r, 1);
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    return out;
}

static void test_jpeg_cmyk(void)
{
    /* RGB expected at the left and right halves: Adobe (inverted) C*K/255;
       plain (255-C)*(255-K)/255 */
    static const int want[2][2][3] = {{{0, 0, 0}, {127, 0, 0}}, {{255, 0, 255}, {0, 128, 128}}};
    for (int adobe = 0; adobe <= 1; adobe++) {
        unsigned long len = 0;
        unsigned char *file = encode_cmyk(adobe, &len);
        gls_texture t = {0};
        char why[256] = "";
        int r = gls_texture_decode_memory(file, len, "cmyk.jpg", &t, why, sizeof why);
        if (r)
            printf("  %s\n", why);
        CHECK(r == 0 && t.width == 16 && t.height == 8);
        for (int half = 0; r == 0 && half < 2; half++)
            for (int y = 0; y < 8; y++)
                for (int x = half * 8; x < half * 8 + 8; x++) {
                    const unsigned char *p = t.rgba + (y * 16 + x) * 4;
                    int ok = p[3] == 255;
                    for (int ch = 0; ch < 3; ch++)
                        ok = ok && abs(p[ch] - want[adobe][half][ch]) <= 1;
                    if (!ok)
                        printf("  adobe %d texel %d,%d: %d %d %d %d\n", adobe, x, y, p[0], p[1], p[2], p[3]);
                    CHECK(ok);
                }
        free(t.rgba);
        free(file);
    }
}

/* PNG and BMP textures (tests/png_bmp/, written once by make.py with
 * OpenCV; the expected texels computed there with numpy, no decoder):
 * every channel layout and depth decodes to exactly those RGBA8 texels,
 * 16-bit samples to their high byte, alpha made binary at 128. */
static void test_png_bmp_variants_decode(void)
{
    const char *names[] = {"rgba8.png", "rgb8.png", "grey8.png", "rgba16.png",
                           "rgb16.png", "grey16.png", "rgb24.bmp", "grey8.bmp"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        char path[128], ref[128], why[256] = "";
        snprintf(path, sizeof path, "tests/png_bmp/%s", names[k]);
        snprintf(ref, sizeof ref, "tests/png_bmp/%.*s.rgba", (int)(strchr(names[k], '.') - names[k]), names[k]);
        size_t len, rlen;
        unsigned char *d = read_all(path, &len), *want = read_all(ref, &rlen);
        CHECK(d && want && rlen == 24 * 16 * 4);
        gls_texture t = {0};
        int r = d ? gls_texture_decode_memory(d, len, path, &t, why, sizeof why) : -1;
        if (r != 0)
            printf("  %s: %s\n", names[k], why);
        CHECK(r == 0);
        if (r == 0 && want && rlen == 24 * 16 * 4) {
            CHECK(t.width == 24 && t.height == 16);
            int differ = 0;
            for (int i = 0; i < 24 * 16 * 4; i++)
                differ += t.rgba[i] != want[i];
            if (differ)
                printf("  %s: %d of %d bytes differ from make.py's texels\n", names[k], differ, 24 * 16 * 4);
            CHECK(differ == 0);
            /* the transparent corner flags the texture (the RGBA files) */
            CHECK(!!(t.flags & GLS_TEX_ALPHA_HOLES) == (strstr(names[k], "rgba") != NULL));
        }
        free(t.rgba);
        free(want);
        free(d);
    }
}

int main(void)
{
    RUN(test_texture_orientation_and_alpha);
    RUN(test_tga_rgb_and_grey);
    RUN(test_png_bmp_variants_decode);
    RUN(test_jpeg_variants_decode);
    RUN(test_jpeg_refused);
    RUN(test_jpeg_component_in_no_scan);
    RUN(test_jpeg_cmyk);
    RUN(test_far_coordinates_exact_through_bundle);
    RUN(test_earlier_root_overrides_library);
    RUN(test_trig_degrees_exact);
    RUN(test_library_template_checked);
    CHECK_EXIT();
}
