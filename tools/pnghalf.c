/* pnghalf: shrink a PNG by an integer factor (box filter: each output
 * pixel is the mean of a K x K block), for small committed gallery images.
 * usage: pnghalf IN.png OUT.png [K]   (K default 2; width and height must be
 * multiples of K).  An image whose pixels are all grey (R = G = B) is
 * written as a one-channel PNG, a third of the size. */
#include <stdio.h>
#include <stdlib.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4) {
        fprintf(stderr, "usage: pnghalf IN.png OUT.png [K]\n");
        return 2;
    }
    int k = argc == 4 ? atoi(argv[3]) : 2;
    int w, h, n;
    unsigned char *in = stbi_load(argv[1], &w, &h, &n, 3);
    if (!in) {
        fprintf(stderr, "pnghalf: error: cannot read %s: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    if (k < 1 || k > 64 || w % k || h % k) {
        fprintf(stderr, "pnghalf: error: %d x %d is not divisible by %d\n", w, h, k);
        stbi_image_free(in);
        return 2;
    }
    int ow = w / k, oh = h / k, grey = 1;
    unsigned char *out = malloc((size_t)ow * oh * 3);
    if (!out) {
        stbi_image_free(in);
        return 1;
    }
    for (int y = 0; y < oh; y++)
        for (int x = 0; x < ow; x++)
            for (int c = 0; c < 3; c++) {
                unsigned s = 0;
                for (int j = 0; j < k; j++)
                    for (int i = 0; i < k; i++)
                        s += in[((size_t)(y * k + j) * w + x * k + i) * 3 + c];
                out[((size_t)y * ow + x) * 3 + c] = (unsigned char)((s + k * k / 2) / (k * k));
            }
    for (size_t i = 0; i < (size_t)ow * oh && grey; i++)
        grey = out[3 * i] == out[3 * i + 1] && out[3 * i] == out[3 * i + 2];
    if (grey)
        for (size_t i = 0; i < (size_t)ow * oh; i++)
            out[i] = out[3 * i];
    stbi_write_png_compression_level = 9;
    int ok = stbi_write_png(argv[2], ow, oh, grey ? 1 : 3, out, ow * (grey ? 1 : 3));
    stbi_image_free(in);
    free(out);
    if (!ok) {
        fprintf(stderr, "pnghalf: error: cannot write %s\n", argv[2]);
        return 1;
    }
    return 0;
}
