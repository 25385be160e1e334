/* depth2png: show a glscene depth map (PFM, metric Zc, +inf = no surface)
 * as a colour PNG for people: inverse depth mapped through a perceptual
 * colour map (near = bright yellow, far = dark blue), no surface black.
 * usage: depth2png DEPTH.pfm OUT.png
 * For looking at, not for measuring: the PFM is the ground truth. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stb/stb_image_write.h>

/* Viridis, by a 6-point piecewise-linear approximation (good enough to look at). */
static void colormap(double t, unsigned char *rgb)
{
    static const double k[6][3] = {{68, 1, 84}, {65, 68, 135}, {42, 120, 142}, {34, 168, 132}, {122, 209, 81}, {253, 231, 37}};
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double x = t * 5;
    int i = (int)x;
    if (i > 4)
        i = 4;
    double f = x - i;
    for (int c = 0; c < 3; c++)
        rgb[c] = (unsigned char)lrint(k[i][c] + f * (k[i + 1][c] - k[i][c]));
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: depth2png DEPTH.pfm OUT.png\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "rb");
    if (!f) {
        fprintf(stderr, "depth2png: error: cannot open %s\n", argv[1]);
        return 1;
    }
    char magic[3] = {0};
    int w, h;
    double scale;
    if (fscanf(f, "%2s %d %d %lf", magic, &w, &h, &scale) != 4 || strcmp(magic, "Pf") != 0 || w <= 0 || h <= 0 ||
        w > 16384 || h > 16384 || scale >= 0 || fgetc(f) != '\n') {
        fprintf(stderr, "depth2png: error: %s is not a little-endian greyscale PFM\n", argv[1]);
        fclose(f);
        return 1;
    }
    size_t n = (size_t)w * h;
    float *d = malloc(n * sizeof *d);
    unsigned char *rgb = malloc(n * 3);
    if (!d || !rgb || fread(d, sizeof *d, n, f) != n) {
        fprintf(stderr, "depth2png: error: %s is truncated\n", argv[1]);
        fclose(f);
        return 1;
    }
    fclose(f);
    double lo = INFINITY, hi = 0; /* inverse depth range */
    for (size_t i = 0; i < n; i++)
        if (isfinite(d[i]) && d[i] > 0) {
            double inv = 1.0 / d[i];
            lo = inv < lo ? inv : lo;
            hi = inv > hi ? inv : hi;
        }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float z = d[(size_t)(h - 1 - y) * w + x]; /* PFM rows run bottom to top */
            unsigned char *p = rgb + ((size_t)y * w + x) * 3;
            if (!isfinite(z) || z <= 0)
                p[0] = p[1] = p[2] = 0;
            else
                colormap(hi > lo ? (1.0 / z - lo) / (hi - lo) : 1, p);
        }
    int ok = stbi_write_png(argv[2], w, h, 3, rgb, w * 3);
    free(d);
    free(rgb);
    if (!ok) {
        fprintf(stderr, "depth2png: error: cannot write %s\n", argv[2]);
        return 1;
    }
    return 0;
}
