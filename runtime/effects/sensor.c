/* The sensor post-process (sensor.h, spec/camera.md "Sensor effects"):
 * linear intensity -> vignetting -> gain -> shot noise -> read noise ->
 * clip -> quantise -> Bayer mosaic. */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "sensor.h"
#include "sensor_rng.h"

double gls_sensor_vignetting(const gls_sensor *s, double u, double v, double cx, double cy, double fx, double x,
                             double y)
{
    double f = 1;
    if (s->vignetting == GLS_VIGNETTING_COS4) {
        double q = 1 + x * x + y * y; /* 1 / cos^2 of the ray's angle */
        f = 1 / (q * q);
    } else if (s->vignetting == GLS_VIGNETTING_POLY) {
        double du = u - cx, dv = v - cy, r2 = (du * du + dv * dv) / (fx * fx);
        f = 1 + r2 * (s->poly[0] + r2 * (s->poly[1] + r2 * s->poly[2]));
    }
    return f > 0 ? f : 0; /* also NaN -> 0 */
}

uint64_t gls_sensor_camera_key(const char *name)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (const unsigned char *p = (const unsigned char *)name; *p; p++)
        h = (h ^ *p) * 0x100000001b3ull;
    return h;
}

/* The streams of one run: shot and read noise draw from unrelated keys,
 * so switching one on does not change the other's numbers. */
enum { STREAM_SHOT = 1, STREAM_READ = 2 };

/* One band of rows, [y0, y1), of gls_sensor_apply's image. */
typedef struct {
    const gls_sensor *s;
    float *rgb;
    uint32_t w, y0, y1;
    double cx, cy, fx;
    void (*ray)(void *ctx, double u, double v, double *x, double *y);
    void *ctx;
    uint64_t kshot, kread;
} band;

static void *apply_band(void *arg)
{
    const band *b = arg;
    const gls_sensor *s = b->s;
    int shot = (s->on & GLS_SENSOR_SHOT) != 0, rd = (s->on & GLS_SENSOR_READ) != 0;
    double g = s->gain, K = s->shot_k, sigma = s->read_sigma;
    gls_poisson pois[3]; /* per channel: the last mean's constants */
    for (int c = 0; c < 3; c++)
        gls_poisson_setup(&pois[c], 0);
    for (uint32_t v = b->y0; v < b->y1; v++)
        for (uint32_t u = 0; u < b->w; u++) {
            size_t i = (size_t)v * b->w + u;
            double f = 1;
            if (s->vignetting) {
                double x = 0, y = 0;
                if (s->vignetting == GLS_VIGNETTING_COS4)
                    b->ray(b->ctx, u, v, &x, &y);
                f = gls_sensor_vignetting(s, u, v, b->cx, b->cy, b->fx, x, y);
            }
            float *px = b->rgb + 3 * i;
            for (int c = 0; c < 3; c++) {
                double J = px[c] * f;
                if (shot) {
                    /* the photons collected, before the gain amplifies
                     * them: variance G^2 J / K after the gain */
                    gls_rng r = gls_rng_stream(gls_rng_key(b->kshot, 3 * (uint64_t)i + (uint64_t)c));
                    if (K * J != pois[c].lambda)
                        gls_poisson_setup(&pois[c], K * J);
                    J = gls_rng_poisson(&r, &pois[c]) / K;
                }
                J *= g;
                if (rd) {
                    gls_rng r = gls_rng_stream(gls_rng_key(b->kread, 3 * (uint64_t)i + (uint64_t)c));
                    J += sigma * gls_rng_normal(&r);
                }
                px[c] = (float)(J < 0 ? 0 : J > 1 ? 1 : J);
            }
        }
    return NULL;
}

#define MAX_THREADS GLS_SENSOR_MAX_THREADS

void gls_sensor_apply(const gls_sensor *s, float *rgb, uint32_t w, uint32_t h, double cx, double cy, double fx,
                      void (*ray)(void *ctx, double u, double v, double *x, double *y), void *ctx,
                      uint64_t camera, uint32_t frame, unsigned threads)
{
    uint64_t key = gls_rng_key(gls_rng_key(gls_rng_key(0, s->seed), camera), frame);
    band proto = {s, rgb, w, 0, h, cx, cy, fx, ray, ctx, gls_rng_key(key, STREAM_SHOT), gls_rng_key(key, STREAM_READ)};
    /* Each pixel's noise is keyed by the pixel, so the bands may run on
     * threads in any order and give the same numbers. */
    uint64_t nb = threads;
    if (!nb) {
        long cpus = sysconf(_SC_NPROCESSORS_ONLN);
        nb = (uint64_t)w * h / GLS_SENSOR_BAND_PIXELS;
        if (nb > (uint64_t)(cpus > 0 ? cpus : 1))
            nb = (uint64_t)(cpus > 0 ? cpus : 1);
    }
    if (nb > MAX_THREADS)
        nb = MAX_THREADS;
    if (nb > h)
        nb = h;
    if (nb <= 1) {
        apply_band(&proto);
        return;
    }
    band bands[MAX_THREADS];
    pthread_t th[MAX_THREADS];
    int started[MAX_THREADS] = {0};
    for (uint64_t k = 0; k < nb; k++) {
        bands[k] = proto;
        bands[k].y0 = (uint32_t)(h * k / nb);
        bands[k].y1 = (uint32_t)(h * (k + 1) / nb);
        /* the first band on this thread; the others on their own, or here
         * when a thread cannot be had */
        if (k > 0)
            started[k] = pthread_create(&th[k], NULL, apply_band, &bands[k]) == 0;
    }
    for (uint64_t k = 0; k < nb; k++)
        if (k == 0 || !started[k])
            apply_band(&bands[k]);
    for (uint64_t k = 1; k < nb; k++)
        if (started[k])
            pthread_join(th[k], NULL);
}

int gls_sensor_bayer_channel(const char *pattern, uint32_t x, uint32_t y)
{
    char ch = pattern[2 * (y & 1) + (x & 1)];
    return ch == 'R' ? 0 : ch == 'G' ? 1 : 2;
}

void *gls_sensor_quantise(const float *rgb, uint32_t w, uint32_t h, int bits)
{
    size_t n = (size_t)w * h;
    size_t per = bits == 8 ? 4 : 3; /* 8-bit: RGBA, the layout the PNG encoder takes */
    void *out = malloc((n ? n : 1) * per * (size_t)(bits / 8));
    if (!out)
        return NULL;
    uint8_t *o8 = out;
    uint16_t *o16 = out;
    float *o32 = out;
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) {
            double v = rgb[3 * i + c]; /* clipped by gls_sensor_apply */
            if (bits == 8)
                o8[per * i + (size_t)c] = (uint8_t)floor(v * 255 + 0.5);
            else if (bits == 16)
                o16[per * i + (size_t)c] = (uint16_t)floor(v * 65535 + 0.5);
            else
                o32[per * i + (size_t)c] = (float)v;
        }
        if (bits == 8)
            o8[4 * i + 3] = 255;
    }
    return out;
}

void *gls_sensor_mosaic(const char *pattern, const void *px, size_t per, size_t size, uint32_t w, uint32_t h)
{
    size_t n = (size_t)w * h;
    unsigned char *out = malloc((n ? n : 1) * size);
    const unsigned char *in = px;
    if (!out)
        return NULL;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            memcpy(out + i * size, in + (per * i + (size_t)gls_sensor_bayer_channel(pattern, x, y)) * size, size);
        }
    return out;
}

/* --explain: each effect on, in order, with the key that asks for it. */
void gls_sensor_explain(FILE *out, const gls_sensor *s, uint64_t npixels, int image)
{
    if (!s->on)
        return;
    if (!image) {
        fprintf(out, "  sensor: effects asked for by the camera file, not applied: no image is written "
                     "(ground truth never has them)\n");
        return;
    }
    fprintf(out, "  sensor (camera file keys; applied to the image only, never to depth, points or other "
                 "ground truth), in this order:\n");
    if (s->vignetting == GLS_VIGNETTING_COS4)
        fprintf(out, "    vignetting cos4 ('vignetting cos4'): times cos^4 of each pixel centre's ray angle\n");
    else if (s->vignetting == GLS_VIGNETTING_POLY)
        fprintf(out, "    vignetting poly ('vignetting poly %g %g %g'): times 1 + a1 r^2 + a2 r^4 + a3 r^6, "
                     "r = distance to (cx, cy) / fx\n", s->poly[0], s->poly[1], s->poly[2]);
    if (s->on & GLS_SENSOR_GAIN)
        fprintf(out, "    gain %g ('gain')\n", s->gain);
    if (s->on & GLS_SENSOR_SHOT)
        fprintf(out, "    shot noise ('shot_noise %g'): Poisson photon counts, %g electrons at intensity 1\n",
                s->shot_k, s->shot_k);
    if (s->on & GLS_SENSOR_READ)
        fprintf(out, "    read noise ('read_noise %g'): Gaussian, sigma %g of full scale\n", s->read_sigma,
                s->read_sigma);
    if (s->on & GLS_SENSOR_NOISE)
        fprintf(out, "    noise seed %llu ('noise_seed'), keyed by camera name, frame and pixel\n",
                (unsigned long long)s->seed);
    fprintf(out, "    clip to [0, 1], quantise\n");
    if (s->on & GLS_SENSOR_BAYER)
        fprintf(out, "    bayer %s ('bayer %s'): the image is a one-channel mosaic\n", s->bayer, s->bayer);
    fprintf(out, "    cost: a post-process over %llu pixels (no extra pass)\n", (unsigned long long)npixels);
}

int gls_sensor_describe(char *buf, size_t len, const gls_sensor *s)
{
    size_t at = 0;
    int k;
    buf[0] = 0;
    if (!s->on)
        return 0;
#define ADD(...)                                                                                                    \
    do {                                                                                                            \
        k = snprintf(buf + at, len - at, __VA_ARGS__);                                                              \
        if (k < 0 || (size_t)k >= len - at)                                                                         \
            return -1;                                                                                              \
        at += (size_t)k;                                                                                            \
    } while (0)
    ADD("sensor");
    if (s->vignetting == GLS_VIGNETTING_COS4)
        ADD(" vignetting cos4");
    else if (s->vignetting == GLS_VIGNETTING_POLY)
        ADD(" vignetting poly %.17g %.17g %.17g", s->poly[0], s->poly[1], s->poly[2]);
    if (s->on & GLS_SENSOR_GAIN)
        ADD(" gain %.17g", s->gain);
    if (s->on & GLS_SENSOR_SHOT)
        ADD(" shot_noise %.17g", s->shot_k);
    if (s->on & GLS_SENSOR_READ)
        ADD(" read_noise %.17g", s->read_sigma);
    if (s->on & GLS_SENSOR_NOISE)
        ADD(" noise_seed %llu", (unsigned long long)s->seed);
    if (s->on & GLS_SENSOR_BAYER)
        ADD(" bayer %s", s->bayer);
#undef ADD
    return 0;
}
