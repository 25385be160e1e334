/* Deterministic texture generator: writes the RGBA TGA textures that the
 * scene library and the examples use, so no binary image is committed.
 * usage: gen_textures OUTROOT
 * Writes OUTROOT/<package path>/<Name>.tga for every texture listed in
 * textures[] below (scenelib/README.md lists them with their sizes).
 * A long file on purpose: it is a catalogue, one generator per texture,
 * each read on its own.
 *
 * Rows are written top row first here (row 0 is the top of the picture, as
 * an image viewer shows it); the TGA file records that, and scenes address
 * texels in the OpenGL convention: tex(0, 0) is the bottom-left corner of
 * the picture, t grows upwards.
 *
 * Everything is integer hashing and double arithmetic in a fixed order:
 * the same binary writes the same bytes on every run.  The demo textures
 * are asymmetric (a marker in their top-left corner) so that a flipped or
 * mirrored upload shows. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stb/stb_image_write.h>
#include "mkdirs.h"

#define PI 3.14159265358979323846

typedef struct {
    int w, h;
    uint8_t *px;
} image;

static void *xcalloc(size_t n, size_t size)
{
    void *p = calloc(n, size);
    if (!p) {
        fprintf(stderr, "gen_textures: out of memory\n");
        exit(1);
    }
    return p;
}

static image new_image(int w, int h)
{
    image im = {w, h, xcalloc((size_t)w * h, 4)};
    return im;
}

static int clamp255(double v)
{
    long i = lrint(v);
    return i < 0 ? 0 : i > 255 ? 255 : (int)i;
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

/* Value noise on a lattice of period (px, py) cells, smoothly interpolated:
 * it tiles, so a texture made of it repeats (GL_REPEAT) without a seam.
 * x, y are in lattice units. */
static double vnoise(double x, double y, int px, int py, uint32_t seed)
{
    double fx = floor(x), fy = floor(y);
    double tx = x - fx, ty = y - fy;
    int ix = (int)fx, iy = (int)fy;
    int x0 = ((ix % px) + px) % px, y0 = ((iy % py) + py) % py;
    int x1 = (x0 + 1) % px, y1 = (y0 + 1) % py;
    double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
    double a = noise((uint32_t)x0, (uint32_t)y0, seed), b = noise((uint32_t)x1, (uint32_t)y0, seed);
    double c = noise((uint32_t)x0, (uint32_t)y1, seed), d = noise((uint32_t)x1, (uint32_t)y1, seed);
    return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

/* Fractal sum of octaves of tileable value noise over a w x h image whose
 * coarsest lattice has cells x cells cells; result in [0,1). */
static double fbm(int x, int y, int w, int h, int cells, int octaves, uint32_t seed)
{
    double sum = 0, amp = 0.5, norm = 0;
    int c = cells;
    for (int o = 0; o < octaves; o++) {
        sum += amp * vnoise((x + 0.5) * c / w, (y + 0.5) * c / h, c, c, seed + (uint32_t)o * 101u);
        norm += amp;
        amp *= 0.5;
        c *= 2;
    }
    return sum / norm;
}

/* ---- demo textures (examples/demo; unchanged) ----------------------------- */

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

/* ---- canvas: shapes in physical units, supersampled ----------------------- */

/* A canvas covers pw x ph physical units (metres on the object), u to the
 * right and v UP, with (0,0) at the bottom-left: the same frame as the
 * object's texture coordinates, so shapes are written with the numbers of
 * the geometry that carries them.  It is rendered at SS x SS samples per
 * texel and averaged down, which anti-aliases edges. */
enum { SS = 4 };

typedef struct {
    int w, h;         /* texels */
    double pw, ph;    /* physical size */
    float *rgba;      /* (w*SS) x (h*SS) samples, top row first */
} canvas;

typedef struct {
    double r, g, b;   /* 0..1 */
    double var;       /* relative brightness variation by value noise, 0 = flat */
    double feat;      /* noise feature size, physical units */
    uint32_t seed;
} paint;

static paint flat(double r, double g, double b)
{
    paint p = {r, g, b, 0, 1, 0};
    return p;
}

static canvas new_canvas(int w, int h, double pw, double ph)
{
    canvas c = {w, h, pw, ph, xcalloc((size_t)w * SS * h * SS, 4 * sizeof(float))};
    return c;
}

static void sample_uv(const canvas *c, int i, int j, double *u, double *v)
{
    *u = (i + 0.5) / (c->w * SS) * c->pw;
    *v = c->ph - (j + 0.5) / (c->h * SS) * c->ph;
}

static void plot(canvas *c, int i, int j, double u, double v, const paint *p)
{
    double k = 1;
    if (p->var > 0) /* non-tiling noise is fine here: shapes are not tiles */
        k = 1 + p->var * (2 * vnoise(u / p->feat, v / p->feat, 1 << 20, 1 << 20, p->seed) - 1);
    float *s = c->rgba + ((size_t)j * c->w * SS + i) * 4;
    s[0] = (float)(p->r * k), s[1] = (float)(p->g * k), s[2] = (float)(p->b * k), s[3] = 1;
}

/* The sample index range covering physical [u0,u1] x [v0,v1]. */
static void sample_box(const canvas *c, double u0, double v0, double u1, double v1, int *i0, int *j0, int *i1,
                       int *j1)
{
    int W = c->w * SS, H = c->h * SS;
    *i0 = (int)floor(u0 / c->pw * W) - 1, *i1 = (int)ceil(u1 / c->pw * W) + 1;
    *j0 = (int)floor((c->ph - v1) / c->ph * H) - 1, *j1 = (int)ceil((c->ph - v0) / c->ph * H) + 1;
    if (*i0 < 0) *i0 = 0;
    if (*j0 < 0) *j0 = 0;
    if (*i1 > W) *i1 = W;
    if (*j1 > H) *j1 = H;
}

static void fill_all(canvas *c, paint p)
{
    for (int j = 0; j < c->h * SS; j++)
        for (int i = 0; i < c->w * SS; i++) {
            double u, v;
            sample_uv(c, i, j, &u, &v);
            plot(c, i, j, u, v, &p);
        }
}

/* Polygon (any simple polygon, even-odd rule); pts are u,v pairs. */
static void fill_poly(canvas *c, const double *pts, int n, paint p)
{
    double u0 = 1e30, v0 = 1e30, u1 = -1e30, v1 = -1e30;
    for (int k = 0; k < n; k++) {
        u0 = fmin(u0, pts[2 * k]), u1 = fmax(u1, pts[2 * k]);
        v0 = fmin(v0, pts[2 * k + 1]), v1 = fmax(v1, pts[2 * k + 1]);
    }
    int i0, j0, i1, j1;
    sample_box(c, u0, v0, u1, v1, &i0, &j0, &i1, &j1);
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1; i++) {
            double u, v;
            sample_uv(c, i, j, &u, &v);
            int in = 0;
            for (int a = 0, b = n - 1; a < n; b = a++) {
                double ua = pts[2 * a], va = pts[2 * a + 1], ub = pts[2 * b], vb = pts[2 * b + 1];
                if ((va > v) != (vb > v) && u < (ub - ua) * (v - va) / (vb - va) + ua)
                    in = !in;
            }
            if (in)
                plot(c, i, j, u, v, &p);
        }
}

static void fill_disc(canvas *c, double cu, double cv, double r, paint p)
{
    int i0, j0, i1, j1;
    sample_box(c, cu - r, cv - r, cu + r, cv + r, &i0, &j0, &i1, &j1);
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1; i++) {
            double u, v;
            sample_uv(c, i, j, &u, &v);
            if ((u - cu) * (u - cu) + (v - cv) * (v - cv) < r * r)
                plot(c, i, j, u, v, &p);
        }
}

/* A thick segment with round caps, its width tapering from w0 to w1. */
static void fill_capsule(canvas *c, double ua, double va, double ub, double vb, double w0, double w1, paint p)
{
    double rmax = fmax(w0, w1) / 2;
    int i0, j0, i1, j1;
    sample_box(c, fmin(ua, ub) - rmax, fmin(va, vb) - rmax, fmax(ua, ub) + rmax, fmax(va, vb) + rmax, &i0, &j0, &i1,
               &j1);
    double du = ub - ua, dv = vb - va, len2 = du * du + dv * dv;
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1; i++) {
            double u, v;
            sample_uv(c, i, j, &u, &v);
            double t = len2 > 0 ? ((u - ua) * du + (v - va) * dv) / len2 : 0;
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            double eu = u - (ua + t * du), ev = v - (va + t * dv), r = (w0 + (w1 - w0) * t) / 2;
            if (eu * eu + ev * ev < r * r)
                plot(c, i, j, u, v, &p);
        }
}

static void stroke(canvas *c, const double *pts, int n, double width, paint p)
{
    for (int k = 0; k + 1 < n; k++)
        fill_capsule(c, pts[2 * k], pts[2 * k + 1], pts[2 * k + 2], pts[2 * k + 3], width, width, p);
}

/* Average the samples down to texels.  Opaque canvases keep alpha 255.
 * With binary_alpha, a texel is opaque when at least half its samples are
 * covered; its colour is the mean of the covered samples only, and an
 * uncovered texel gets the colour `halo`, so that linear filtering at a
 * silhouette blends towards a plausible colour instead of black. */
static image resolve(const canvas *c, int binary_alpha, paint halo)
{
    image im = new_image(c->w, c->h);
    for (int y = 0; y < c->h; y++)
        for (int x = 0; x < c->w; x++) {
            double sum[4] = {0, 0, 0, 0};
            for (int j = 0; j < SS; j++)
                for (int i = 0; i < SS; i++) {
                    const float *s = c->rgba + ((size_t)(y * SS + j) * c->w * SS + (size_t)(x * SS + i)) * 4;
                    for (int k = 0; k < 4; k++)
                        sum[k] += s[k];
                }
            if (!binary_alpha) {
                double n = SS * SS;
                put(&im, x, y, clamp255(255 * sum[0] / n), clamp255(255 * sum[1] / n), clamp255(255 * sum[2] / n), 255);
            } else if (sum[3] * 2 >= SS * SS) {
                put(&im, x, y, clamp255(255 * sum[0] / sum[3]), clamp255(255 * sum[1] / sum[3]),
                    clamp255(255 * sum[2] / sum[3]), 255);
            } else {
                put(&im, x, y, clamp255(255 * halo.r), clamp255(255 * halo.g), clamp255(255 * halo.b), 0);
            }
        }
    free(c->rgba);
    return im;
}

/* A deterministic sequence of doubles in [0,1) for placing shapes. */
typedef struct {
    uint32_t seed, n;
} rng;

static double rnd(rng *r)
{
    r->n++;
    return noise(r->n, r->n * 7u + 3u, r->seed);
}

/* ---- lettering ------------------------------------------------------------ */

/* Stroke glyphs in a box 0.6 wide and 1 high (cap height 1), written as
 * polylines of the stroke centre.  Only the characters the sign faces
 * need. */
enum { MAXPTS = 64 };
typedef struct {
    int n;
    double p[2 * MAXPTS];
} polyline;

static void arc(polyline *pl, double cx, double cy, double rx, double ry, double a0, double a1, int steps)
{
    for (int k = 0; k <= steps && pl->n < MAXPTS; k++) {
        double a = (a0 + (a1 - a0) * k / steps) * PI / 180;
        pl->p[2 * pl->n] = cx + rx * cos(a);
        pl->p[2 * pl->n + 1] = cy + ry * sin(a);
        pl->n++;
    }
}

static void pt(polyline *pl, double x, double y)
{
    if (pl->n < MAXPTS) {
        pl->p[2 * pl->n] = x, pl->p[2 * pl->n + 1] = y;
        pl->n++;
    }
}

/* The strokes of glyph ch; returns their number. */
static int glyph(char ch, polyline out[3])
{
    memset(out, 0, 3 * sizeof *out);
    switch (ch) {
    case 'S':
        arc(&out[0], 0.3, 0.725, 0.22, 0.205, 20, 270, 20);
        arc(&out[0], 0.3, 0.29, 0.23, 0.21, 90, -160, 22);
        return 1;
    case 'T':
        pt(&out[0], 0.0, 0.93), pt(&out[0], 0.6, 0.93);
        pt(&out[1], 0.3, 0.93), pt(&out[1], 0.3, 0.07);
        return 2;
    case 'O':
    case '0':
        arc(&out[0], 0.3, 0.5, 0.23, 0.43, 0, 360, 40);
        return 1;
    case 'P':
        pt(&out[0], 0.08, 0.07), pt(&out[0], 0.08, 0.93), pt(&out[0], 0.3, 0.93);
        arc(&out[0], 0.3, 0.72, 0.22, 0.21, 90, -90, 16);
        pt(&out[0], 0.08, 0.51);
        return 1;
    case '5':
        pt(&out[0], 0.53, 0.93), pt(&out[0], 0.12, 0.93), pt(&out[0], 0.09, 0.53);
        arc(&out[0], 0.3, 0.32, 0.23, 0.25, 125, -145, 26);
        return 1;
    default:
        return 0;
    }
}

/* Text centred at (cu, cv) with cap height hgt, stroke width sw x hgt. */
static void text(canvas *c, const char *s, double cu, double cv, double hgt, double sw, double advance, paint p)
{
    size_t n = strlen(s);
    double width = (double)n * advance * hgt - (advance - 0.6) * hgt;
    double u0 = cu - width / 2, v0 = cv - hgt / 2;
    for (size_t k = 0; k < n; k++) {
        polyline pl[3];
        int m = glyph(s[k], pl);
        for (int q = 0; q < m; q++) {
            for (int i = 0; i < pl[q].n; i++) {
                pl[q].p[2 * i] = u0 + (double)k * advance * hgt + pl[q].p[2 * i] * hgt;
                pl[q].p[2 * i + 1] = v0 + pl[q].p[2 * i + 1] * hgt;
            }
            stroke(c, pl[q].p, pl[q].n, sw * hgt, p);
        }
    }
}

/* ---- road.tex -------------------------------------------------------------- */

/* Asphalt, 512 x 512 texels for a 2 m x 2 m tile (3.9 mm per texel): grey
 * with tileable multi-scale noise, light aggregate grains and dark pores,
 * so that stereo matchers find texture on the road surface. */
static image road_asphalt(void)
{
    image im = new_image(512, 512);
    for (int y = 0; y < 512; y++)
        for (int x = 0; x < 512; x++) {
            double g = noise((uint32_t)x, (uint32_t)y, 12);
            double v = 0.24 + 0.14 * fbm(x, y, 512, 512, 8, 6, 11) + 0.06 * (g - 0.5);
            if (g > 0.97)
                v += 0.18 * (g - 0.97) / 0.03 + 0.06;  /* aggregate grain */
            else if (g < 0.04)
                v -= 0.08;                             /* pore */
            put(&im, x, y, clamp255(255 * v), clamp255(255 * v), clamp255(255 * (v + 0.012)), 255);
        }
    return im;
}

/* Grass, 256 x 256 texels for a 4 m x 4 m tile: green with tileable
 * patches and blade-scale noise. */
static image road_grass(void)
{
    image im = new_image(256, 256);
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++) {
            double patch = fbm(x, y, 256, 256, 4, 3, 21);
            double fine = noise((uint32_t)x, (uint32_t)y, 22);
            double k = 0.7 + 0.5 * patch + 0.25 * (fine - 0.5);
            put(&im, x, y, clamp255(255 * k * (0.20 + 0.10 * patch)), clamp255(255 * k * 0.42),
                clamp255(255 * k * 0.14), 255);
        }
    return im;
}

/* ---- road.signs.tex ---------------------------------------------------------- */

/* The sign faces.  Each covers the bounding box of its plate, in metres, as
 * the road.signs objects map it (tex(0,0) at the plate's bottom-left seen from
 * the front).  Outside the plate's outline the texture repeats the
 * outermost colour, so that filtering at the plate's geometric edge never
 * picks up a foreign colour.  Colours: RAL 3020 traffic red, RAL 9016
 * traffic white, RAL 5017 traffic blue, approximately, in sRGB. */
static const double RED[3] = {0.76, 0.07, 0.10}, WHITE[3] = {0.95, 0.95, 0.93}, BLUE[3] = {0.0, 0.32, 0.62},
                    BLACK[3] = {0.06, 0.06, 0.06};

static paint pc(const double c[3])
{
    return flat(c[0], c[1], c[2]);
}

/* Regular n-gon with its centre at (cu,cv), circumradius r, first vertex at
 * angle a0 degrees. */
static void ngon(double *pts, int n, double cu, double cv, double r, double a0)
{
    for (int k = 0; k < n; k++) {
        double a = (a0 + 360.0 * k / n) * PI / 180;
        pts[2 * k] = cu + r * cos(a), pts[2 * k + 1] = cv + r * sin(a);
    }
}

/* Stop (Vienna Convention B,2a; German StVO sign 206): a red octagon 0.9 m
 * across flats with a white rim and the word STOP in white. */
static image sign_stop(void)
{
    canvas c = new_canvas(256, 256, 0.9, 0.9);
    double oct[16];
    fill_all(&c, pc(WHITE));
    double rim = 0.02;
    ngon(oct, 8, 0.45, 0.45, (0.45 - rim) / cos(PI / 8), 22.5);
    fill_poly(&c, oct, 8, pc(RED));
    text(&c, "STOP", 0.45, 0.45, 0.25, 0.16, 0.78, pc(WHITE));
    return resolve(&c, 0, pc(WHITE));
}

/* Speed limit 50 (Vienna C,14; StVO 274): a disc 0.6 m across, red ring
 * 0.065 m wide, white field, black "50". */
static image sign_speed50(void)
{
    canvas c = new_canvas(256, 256, 0.6, 0.6);
    fill_all(&c, pc(RED));
    fill_disc(&c, 0.3, 0.3, 0.3 - 0.065, pc(WHITE));
    text(&c, "50", 0.3, 0.3, 0.24, 0.15, 0.8, pc(BLACK));
    return resolve(&c, 0, pc(RED));
}

/* Yield (Vienna B,1; StVO 205): a triangle pointing down, 0.9 m sides, red
 * border 0.09 m wide (measured perpendicular to the sides), white field.
 * The bounding box is 0.9 m x 0.9*sqrt(3)/2 m. */
static image sign_yield(void)
{
    double w = 0.9, h = 0.9 * sqrt(3) / 2, b = 0.09;
    canvas c = new_canvas(256, 222, w, h);
    fill_all(&c, pc(RED));
    /* inner triangle: the incentre is at height h/3 above the bottom
     * vertex... measured from the top edge it is at h - r with r = h/3;
     * insetting the sides by b shrinks the inradius by b */
    double r = h / 3, k = (r - b) / r, cu = w / 2, cv = h - r;
    double tri[6] = {cu + (0 - cu) * k, cv + (h - cv) * k, cu + (w - cu) * k, cv + (h - cv) * k, cu, cv + (0 - cv) * k};
    fill_poly(&c, tri, 3, pc(WHITE));
    return resolve(&c, 0, pc(RED));
}

/* Pedestrian crossing (Vienna E,12a; StVO 350): a blue square 0.6 m with a
 * white rim, a white triangle and a black pedestrian walking on a zebra. */
static image sign_pedestrian(void)
{
    canvas c = new_canvas(256, 256, 0.6, 0.6);
    fill_all(&c, pc(WHITE));
    double sq[8] = {0.015, 0.015, 0.585, 0.015, 0.585, 0.585, 0.015, 0.585};
    fill_poly(&c, sq, 4, pc(BLUE));
    double tri[6] = {0.3, 0.53, 0.055, 0.09, 0.545, 0.09};
    fill_poly(&c, tri, 3, pc(WHITE));
    paint k = pc(BLACK);
    /* zebra stripes under the feet */
    for (int s = 0; s < 4; s++) {
        double u = 0.17 + 0.075 * s;
        double z[8] = {u, 0.115, u + 0.045, 0.115, u + 0.03, 0.145, u - 0.015, 0.145};
        fill_poly(&c, z, 4, k);
    }
    /* the walker, facing right: head, body, arms, legs */
    fill_disc(&c, 0.315, 0.415, 0.027, k);
    fill_capsule(&c, 0.305, 0.375, 0.29, 0.27, 0.05, 0.045, k);
    fill_capsule(&c, 0.30, 0.36, 0.35, 0.31, 0.022, 0.02, k);
    fill_capsule(&c, 0.30, 0.36, 0.255, 0.30, 0.022, 0.02, k);
    fill_capsule(&c, 0.29, 0.27, 0.34, 0.16, 0.028, 0.024, k);
    fill_capsule(&c, 0.29, 0.27, 0.25, 0.205, 0.028, 0.024, k);
    fill_capsule(&c, 0.25, 0.205, 0.235, 0.155, 0.024, 0.022, k);
    return resolve(&c, 0, pc(WHITE));
}

/* ---- road.vegetation.tex ----------------------------------------------------- */

/* Tree and bush silhouettes with binary alpha: crowns are unions of many
 * leaf clusters (discs), so light shows through between them and the
 * player's alpha test cuts real holes.  Each covers the billboard quad of
 * its object (metres, v up from the ground). */

/* Leaf clusters: ngroups branch tips scattered in an ellipse (denser
 * towards its middle), each carrying per discs around it.  Grouping leaves
 * gaps between the groups, as in a real crown. */
static void crown(canvas *c, rng *r, int ngroups, int per, double cu, double cv, double ru, double rv, double spread,
                  double rmin, double rmax, paint p)
{
    for (int g = 0; g < ngroups; g++) {
        double a = 2 * PI * rnd(r), d = sqrt(rnd(r));
        double gu = cu + ru * d * cos(a), gv = cv + rv * d * sin(a);
        double shade = 0.8 + 0.35 * rnd(r) - 0.15 * (cv - gv) / rv; /* lower groups darker */
        for (int k = 0; k < per; k++) {
            double b = 2 * PI * rnd(r), e = spread * sqrt(rnd(r));
            double rr = rmin + (rmax - rmin) * rnd(r);
            paint q = p;
            q.r *= shade, q.g *= shade, q.b *= shade;
            q.seed = (uint32_t)g;
            fill_disc(c, gu + e * cos(b), gv + e * sin(b) * 0.8, rr, q);
        }
    }
}

/* Birch: 5 m wide, 10 m tall; white bark with black marks, light sparse
 * crown of small clusters. */
static image veg_birch(void)
{
    canvas c = new_canvas(256, 512, 5, 10);
    rng r = {31, 0};
    paint bark = flat(0.88, 0.87, 0.82);
    bark.var = 0.08, bark.feat = 0.05;
    fill_capsule(&c, 2.5, 0.0, 2.45, 8.6, 0.30, 0.10, bark);
    for (int k = 0; k < 26; k++) {
        double v = 0.3 + 7.5 * rnd(&r), half = 0.04 + 0.06 * rnd(&r);
        fill_capsule(&c, 2.5 - half, v, 2.5 + half, v + 0.02, 0.04, 0.04, flat(0.1, 0.1, 0.1));
    }
    for (int k = 0; k < 12; k++) { /* branches, hanging slightly */
        double v = 3.5 + 5 * rnd(&r), side = k % 2 ? 1 : -1, len = 0.8 + 1.2 * rnd(&r);
        fill_capsule(&c, 2.48, v, 2.48 + side * len, v + 0.4 + 0.5 * rnd(&r), 0.07, 0.03, flat(0.35, 0.3, 0.28));
    }
    paint leaf = flat(0.45, 0.62, 0.22);
    leaf.var = 0.2, leaf.feat = 0.08;
    crown(&c, &r, 40, 9, 2.5, 6.5, 2.0, 3.1, 0.55, 0.1, 0.2, leaf);
    return resolve(&c, 1, leaf);
}

/* Spruce: 5 m wide, 12 m tall; a dark green cone of drooping tiers on a
 * short brown trunk. */
static image veg_spruce(void)
{
    canvas c = new_canvas(256, 512, 5, 12);
    rng r = {41, 0};
    fill_capsule(&c, 2.5, 0.0, 2.5, 11.5, 0.32, 0.06, flat(0.36, 0.25, 0.16));
    paint needle = flat(0.10, 0.30, 0.13);
    needle.var = 0.25, needle.feat = 0.06;
    for (int t = 0; t < 14; t++) {
        double v = 1.2 + t * 0.74, hw = 2.45 * (1 - (v - 1.2) / 11.0) + 0.15;
        double tier[2 * 12];
        int n = 0;
        tier[n++] = 2.5, tier[n++] = v + 1.3;
        for (int s = 0; s <= 8; s++) { /* sagging lower edge with jagged tips */
            double u = 2.5 - hw + 2 * hw * s / 8.0, sag = 0.35 * (1 - fabs(u - 2.5) / hw);
            tier[n++] = u, tier[n++] = v - sag * 0.6 + (s % 2 ? 0.18 : 0) * (0.5 + rnd(&r));
        }
        tier[n++] = 2.5 + hw * 0.2, tier[n++] = v + 1.0;
        paint q = needle;
        double shade = 0.8 + 0.3 * rnd(&r);
        q.r *= shade, q.g *= shade, q.b *= shade;
        q.seed = (uint32_t)t;
        fill_poly(&c, tier, n / 2, q);
    }
    return resolve(&c, 1, needle);
}

/* Oak: 9 m wide, 10 m tall; thick trunk, a few limbs, a broad crown of
 * large clusters. */
static image veg_oak(void)
{
    canvas c = new_canvas(384, 448, 9, 10);
    rng r = {51, 0};
    paint bark = flat(0.33, 0.26, 0.19);
    bark.var = 0.2, bark.feat = 0.04;
    fill_capsule(&c, 4.5, 0.0, 4.45, 5.0, 0.75, 0.45, bark);
    for (int k = 0; k < 7; k++) {
        double a = (30 + 120 * k / 6.0) * PI / 180, len = 2.0 + 1.2 * rnd(&r);
        fill_capsule(&c, 4.45, 3.8, 4.45 + len * cos(a), 3.8 + len * sin(a), 0.3, 0.1, bark);
    }
    paint leaf = flat(0.22, 0.42, 0.12);
    leaf.var = 0.2, leaf.feat = 0.1;
    crown(&c, &r, 45, 9, 4.5, 6.4, 3.7, 2.9, 0.9, 0.2, 0.42, leaf);
    return resolve(&c, 1, leaf);
}

/* Bush: 2 m wide, 1.4 m tall; clusters from the ground up, no trunk. */
static image veg_bush(void)
{
    canvas c = new_canvas(256, 180, 2, 1.4);
    rng r = {61, 0};
    paint leaf = flat(0.20, 0.40, 0.14);
    leaf.var = 0.25, leaf.feat = 0.05;
    crown(&c, &r, 40, 8, 1.0, 0.65, 0.75, 0.5, 0.22, 0.06, 0.13, leaf);
    for (int k = 0; k < 9; k++) /* close the base */
        fill_disc(&c, 0.25 + 0.19 * k, 0.1, 0.13, leaf);
    return resolve(&c, 1, leaf);
}

/* ---- stereo.tex, objects.tex ------------------------------------------------- */

/* Random dots: 256 x 256 texels, each black or white with probability 1/2
 * (the classic random-dot stereogram texture; independent texels, so it
 * tiles).  The stereo objects map one texel to 1 cm. */
static image stereo_random_dots(void)
{
    image im = new_image(256, 256);
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++) {
            int v = noise((uint32_t)x, (uint32_t)y, 71) < 0.5 ? 20 : 235;
            put(&im, x, y, v, v, v, 255);
        }
    return im;
}

/* Grey multi-scale noise, 256 x 256, tileable: texture at every scale for
 * matchers working on image pyramids. */
static image stereo_noise(void)
{
    image im = new_image(256, 256);
    for (int y = 0; y < 256; y++)
        for (int x = 0; x < 256; x++) {
            double v = 0.1 + 0.8 * fbm(x, y, 256, 256, 4, 6, 81);
            v = 0.5 + (v - 0.5) * 1.8;
            put(&im, x, y, clamp255(255 * v), clamp255(255 * v), clamp255(255 * v), 255);
        }
    return im;
}

/* Speckle: coloured discs of random sizes on light grey, 256 x 256: many
 * well-localised corners and blobs for feature trackers. */
static image objects_speckle(void)
{
    canvas c = new_canvas(256, 256, 1, 1);
    rng r = {91, 0};
    fill_all(&c, flat(0.85, 0.85, 0.82));
    static const double pal[6][3] = {{0.8, 0.1, 0.1}, {0.1, 0.5, 0.15}, {0.1, 0.2, 0.7},
                                      {0.9, 0.7, 0.1}, {0.1, 0.1, 0.1}, {0.6, 0.2, 0.6}};
    for (int k = 0; k < 140; k++) {
        const double *q = pal[k % 6];
        /* drawn in sequence: the order in which a call's arguments are
           evaluated is unspecified (gcc and clang differ), and the texture
           must not depend on the compiler.  This is gcc's order, in which
           the committed bundles and images were made. */
        double radius = 0.01 + 0.04 * rnd(&r), v = rnd(&r), u = rnd(&r);
        fill_disc(&c, u, v, radius, flat(q[0], q[1], q[2]));
    }
    return resolve(&c, 0, flat(0, 0, 0));
}

/* ---- the list ------------------------------------------------------------------ */

typedef struct {
    const char *path;      /* relative to OUTROOT */
    image (*make)(void);
} entry;

static const entry textures[] = {
    {"demo/tex/Checker.tga", checker},
    {"demo/tex/Tree.tga", tree},
    {"demo/tex/Asphalt.tga", asphalt},
    {"road/tex/Asphalt.tga", road_asphalt},
    {"road/tex/Grass.tga", road_grass},
    {"road/signs/tex/Stop.tga", sign_stop},
    {"road/signs/tex/SpeedLimit50.tga", sign_speed50},
    {"road/signs/tex/Yield.tga", sign_yield},
    {"road/signs/tex/PedestrianCrossing.tga", sign_pedestrian},
    {"road/vegetation/tex/Birch.tga", veg_birch},
    {"road/vegetation/tex/Spruce.tga", veg_spruce},
    {"road/vegetation/tex/Oak.tga", veg_oak},
    {"road/vegetation/tex/Bush.tga", veg_bush},
    {"stereo/tex/RandomDots.tga", stereo_random_dots},
    {"stereo/tex/Noise.tga", stereo_noise},
    {"objects/tex/Speckle.tga", objects_speckle},
};

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
        if (gls_mkdir_parents(path) || !stbi_write_tga(path, im.w, im.h, 4, im.px)) {
            fprintf(stderr, "gen_textures: cannot write %s\n", path);
            return 1;
        }
        free(im.px);
    }
    return 0;
}
