/* road_montage OUT.png COLS WIDTH IMAGE...: scale every image to WIDTH
 * pixels wide (box filter), lay them out COLS to a row with 4-pixel dark
 * gaps, write a PNG.  Used by `make demo-road` for docs/road_strip.png. */
#include <stdio.h>
#include <stdlib.h>
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

int main(int argc, char **argv)
{
    if (argc < 5) {
        fprintf(stderr, "usage: road_montage OUT.png COLS WIDTH IMAGE...\n");
        return 2;
    }
    int cols = atoi(argv[2]), tw = atoi(argv[3]), n = argc - 4, gap = 4;
    if (cols < 1 || tw < 8 || tw > 4096) {
        fprintf(stderr, "road_montage: error: bad COLS or WIDTH\n");
        return 2;
    }
    int w0, h0, c0;
    if (!stbi_info(argv[4], &w0, &h0, &c0)) {
        fprintf(stderr, "road_montage: error: cannot read %s\n", argv[4]);
        return 1;
    }
    int th = (int)((double)h0 * tw / w0 + 0.5);
    int rows = (n + cols - 1) / cols;
    int W = cols * tw + (cols + 1) * gap, H = rows * th + (rows + 1) * gap;
    unsigned char *out = calloc((size_t)W * H * 3, 1);
    if (!out)
        return 1;
    for (size_t i = 0; i < (size_t)W * H * 3; i++)
        out[i] = 24;
    for (int k = 0; k < n; k++) {
        int w, h, c;
        unsigned char *im = stbi_load(argv[4 + k], &w, &h, &c, 3);
        if (!im || w != w0 || h != h0) {
            fprintf(stderr, "road_montage: error: cannot read %s (or its size differs)\n", argv[4 + k]);
            return 1;
        }
        int ox = gap + (k % cols) * (tw + gap), oy = gap + (k / cols) * (th + gap);
        for (int y = 0; y < th; y++)
            for (int x = 0; x < tw; x++) {
                /* box filter over the source pixels this pixel covers */
                int x0 = x * w / tw, x1 = (x + 1) * w / tw, y0 = y * h / th, y1 = (y + 1) * h / th;
                if (x1 <= x0)
                    x1 = x0 + 1;
                if (y1 <= y0)
                    y1 = y0 + 1;
                for (int ch = 0; ch < 3; ch++) {
                    long s = 0;
                    for (int yy = y0; yy < y1; yy++)
                        for (int xx = x0; xx < x1; xx++)
                            s += im[((size_t)yy * w + xx) * 3 + ch];
                    out[((size_t)(oy + y) * W + ox + x) * 3 + ch] = (unsigned char)(s / ((x1 - x0) * (y1 - y0)));
                }
            }
        stbi_image_free(im);
    }
    if (!stbi_write_png(argv[1], W, H, 3, out, W * 3)) {
        fprintf(stderr, "road_montage: error: cannot write %s\n", argv[1]);
        return 1;
    }
    free(out);
    return 0;
}
