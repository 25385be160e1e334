/* Deterministic texture generator: writes the RGBA TGA textures that the
 * scene library and the examples use, so no binary image is committed.
 * usage: gen_textures OUTROOT
 * Writes OUTROOT/<package path>/<Name>.tga for every texture listed below.
 * Every texture is asymmetric (a marker in its top-left corner) so that a
 * flipped or mirrored upload shows. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <stb/stb_image_write.h>

typedef struct {
    int w, h;
    uint8_t *px;
} image;

static image new_image(int w, int h)
{
    image im = {w, h, calloc((size_t)w * h, 4)};
    if (!im.px) {
        fprintf(stderr, "gen_textures: out of memory\n");
        exit(1);
    }
    return im;
}

static void put(image *im, int x, int y, int r, int g, int b, int a)
{
    uint8_t *p = im->px + ((size_t)y * im->w + x) * 4;
    p[0] = (uint8_t)r, p[1] = (uint8_t)g, p[2] = (uint8_t)b, p[3] = (uint8_t)a;
}

/* Small deterministic hash noise in [0,1). */
static double noise(uint32_t x, uint32_t y, uint32_t seed)
{
    uint32_t h = x * 374761393u + y * 668265263u + seed * 2246822519u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return (double)((h ^ (h >> 16)) & 0xFFFFFF) / 16777216.0;
}

/* 8x8 black and white squares, 32 texels each, a red marker in the top-left
 * square. */
static image checker(void)
{
    image im = new_image(256, 256);
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++) {
            int white = ((x / 32) + (y / 32)) % 2 == 0;
            int marker = x >= 8 && x < 24 && y >= 8 && y < 24;
            if (marker)
                put(&im, x, y, 220, 30, 30, 255);
            else
                put(&im, x, y, white ? 240 : 15, white ? 240 : 15, white ? 240 : 15, 255);
        }
    return im;
}

/* A tree silhouette: green crown, brown trunk, transparent elsewhere (so the
 * alpha test is used for real). */
static image tree(void)
{
    image im = new_image(128, 256);
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 128; x++) {
            double dx = (x - 64) / 56.0, dy = (y - 90) / 88.0;
            double wobble = 0.12 * sin(atan2(dy, dx) * 7);
            int crown = dx * dx + dy * dy < (1 + wobble) * (1 + wobble);
            int trunk = y >= 150 && abs(x - 64) < 7;
            double n = noise((uint32_t)x, (uint32_t)y, 7);
            if (crown)
                put(&im, x, y, 30 + (int)(40 * n), 110 + (int)(60 * n), 30, 255);
            else if (trunk)
                put(&im, x, y, 100, 70, 40, 255);
            else
                put(&im, x, y, 0, 0, 0, 0);
        }
    return im;
}

/* Grey asphalt with fine noise: texture for stereo matchers. */
static image asphalt(void)
{
    image im = new_image(256, 256);
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++) {
            int v = 70 + (int)(50 * noise((uint32_t)x, (uint32_t)y, 1));
            put(&im, x, y, v, v, v + 4, 255);
        }
    return im;
}

typedef struct {
    const char *path;      /* relative to OUTROOT */
    image (*make)(void);
} entry;

static const entry textures[] = {
    {"demo/tex/Checker.tga", checker},
    {"demo/tex/Tree.tga", tree},
    {"demo/tex/Asphalt.tga", asphalt},
};

static int mkdirs(char *path)
{
    for (char *p = path + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = 0;
        int r = mkdir(path, 0755);
        *p = '/';
        if (r != 0 && errno != EEXIST)
            return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: gen_textures OUTROOT\n");
        return 2;
    }
    stbi_write_tga_with_rle = 0;
    for (size_t i = 0; i < sizeof textures / sizeof textures[0]; i++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", argv[1], textures[i].path);
        image im = textures[i].make();
        if (mkdirs(path) || !stbi_write_tga(path, im.w, im.h, 4, im.px)) {
            fprintf(stderr, "gen_textures: cannot write %s\n", path);
            return 1;
        }
        free(im.px);
    }
    return 0;
}
