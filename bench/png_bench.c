/* bench-encode, encoder side: how long one PNG takes to encode and how
 * large it is, for stb_image_write (the player's encoder before issue 14)
 * and libspng at zlib levels 1..3 and 6 with several filter choices, on
 * frames the player rendered (bench/encode.sh passes them).  Not a
 * pass/fail test; timings only.
 *
 * usage: png_bench [-n REPEAT] FILE.png...
 *   8-bit files are encoded as the player encodes its 8-bit images (RGBA
 *   in, RGB out), 16-bit ones as its png16 images (RGB, host order).
 *   Prints one line per file and encoder: "FILE ENCODER ms BYTES", ms the
 *   best of REPEAT encodes (default 5). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <spng.h>
#include <stb/stb_image.h>
#include "outputs.h"
#include "stb_png.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static const struct {
    const char *name;
    int bits;
} filters[] = {
    {"none", SPNG_FILTER_CHOICE_NONE}, {"sub", SPNG_FILTER_CHOICE_SUB}, {"up", SPNG_FILTER_CHOICE_UP},
    {"paeth", SPNG_FILTER_CHOICE_PAETH}, {"all", SPNG_FILTER_CHOICE_ALL},
};
static const int levels[] = {1, 2, 3, 6};

int main(int argc, char **argv)
{
    int repeat = 5, i = 1;
    if (argc > 2 && strcmp(argv[1], "-n") == 0)
        repeat = atoi(argv[2]), i = 3;
    if (i >= argc || repeat < 1) {
        fprintf(stderr, "usage: png_bench [-n REPEAT] FILE.png...\n");
        return 2;
    }
    gls_buf buf = {0};
    for (; i < argc; i++) {
        const char *f = argv[i];
        int w, h, c, sixteen = stbi_is_16_bit(f);
        void *px = sixteen ? (void *)stbi_load_16(f, &w, &h, &c, 3) : (void *)stbi_load(f, &w, &h, &c, 4);
        if (!px) {
            fprintf(stderr, "png_bench: cannot read %s\n", f);
            return 1;
        }
        /* -1: stb (8-bit only), then every level x filter */
        for (int k = sixteen ? 0 : -1; k < (int)(sizeof levels / sizeof *levels * (sizeof filters / sizeof *filters));
             k++) {
            int lv = k < 0 ? 0 : levels[k / (int)(sizeof filters / sizeof *filters)];
            int fi = k < 0 ? 0 : k % (int)(sizeof filters / sizeof *filters);
            double best = 1e30;
            for (int r = 0; r < repeat; r++) {
                buf.len = 0;
                double t0 = now();
                int e = k < 0 ? stb_png_encode(px, w, h, &buf)
                              : gls_encode_png_with(px, (uint32_t)w, (uint32_t)h, 3, sixteen ? 16 : 8, !sixteen, lv,
                                                    filters[fi].bits, &buf);
                double t = now() - t0;
                if (e) {
                    fprintf(stderr, "png_bench: encoding %s failed\n", f);
                    return 1;
                }
                if (t < best)
                    best = t;
            }
            char name[64];
            if (k < 0)
                snprintf(name, sizeof name, "stb");
            else
                snprintf(name, sizeof name, "spng-%d-%s", lv, filters[fi].name);
            printf("%s %dx%d %s %s %.2f %zu\n", f, w, h, sixteen ? "16-bit" : "8-bit", name, best * 1e3, buf.len);
        }
        stbi_image_free(px);
    }
    free(buf.data);
    return 0;
}
