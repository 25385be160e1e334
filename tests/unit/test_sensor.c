/* The sensor post-process (runtime/effects/sensor.c): its image does not
 * depend on how many bands of rows, on threads of their own, it is done
 * in, since each pixel's noise is keyed by the pixel.  The number is a
 * parameter of gls_sensor_apply (0: its own choice, the player's), not a
 * variable of the environment, so the test passes it. */
#include <stdlib.h>
#include <string.h>
#include "check.h"
#include "sensor.h"

enum { W = 640, H = 480 };
static const double CX = 319.5, CY = 239.5, FX = 500;

/* the pinhole's ray of pixel (u, v), for vignetting cos4 */
static void pinhole_ray(void *ctx, double u, double v, double *x, double *y)
{
    (void)ctx;
    *x = (u - CX) / FX, *y = (v - CY) / FX;
}

/* a smooth image with every intensity from black to white */
static void fill(float *rgb, uint32_t w, uint32_t h)
{
    for (uint32_t v = 0; v < h; v++)
        for (uint32_t u = 0; u < w; u++)
            for (int c = 0; c < 3; c++)
                rgb[3 * ((size_t)v * w + u) + (size_t)c] = (float)((u + v * 0.5 + 40.0 * c) / (w + h * 0.5 + 80.0));
}

/* the noisy camera of tests/py/check_sensor.py's determinism checks, with
 * vignetting cos4 (its ray callback runs on every thread) */
static gls_sensor noisy(void)
{
    gls_sensor s = gls_sensor_none();
    s.on = GLS_SENSOR_VIGNETTING | GLS_SENSOR_GAIN | GLS_SENSOR_SHOT | GLS_SENSOR_READ;
    s.vignetting = GLS_VIGNETTING_COS4;
    s.gain = 1.3, s.shot_k = 300, s.read_sigma = 0.01, s.seed = 5;
    return s;
}

/* 1 band (the reference), the automatic number (0), 2, 3, 7, 16 and 17
 * (more than the most: 16) bands: the same bits; and the noise is there
 * (the image is not the input's), so the comparison is not of nothing */
static void test_sensor_threads_same_image(void)
{
    gls_sensor s = noisy();
    size_t n = (size_t)W * H * 3;
    float *in = malloc(n * sizeof *in), *ref = malloc(n * sizeof *ref), *out = malloc(n * sizeof *out);
    CHECK(in && ref && out);
    if (!in || !ref || !out)
        goto done;
    fill(in, W, H);
    memcpy(ref, in, n * sizeof *ref);
    gls_sensor_apply(&s, ref, W, H, CX, CY, FX, pinhole_ray, NULL, gls_sensor_camera_key("big"), 0, 1);
    size_t same = 0;
    for (size_t i = 0; i < n; i++)
        same += ref[i] == in[i];
    CHECK_MSG(same < n / 10, "%zu of %zu samples have no noise", same, n);
    const unsigned threads[] = {0, 2, 3, 7, 16, 17};
    for (size_t k = 0; k < sizeof threads / sizeof *threads; k++) {
        memcpy(out, in, n * sizeof *out);
        gls_sensor_apply(&s, out, W, H, CX, CY, FX, pinhole_ray, NULL, gls_sensor_camera_key("big"), 0, threads[k]);
        CHECK_MSG(memcmp(out, ref, n * sizeof *out) == 0, "%u bands: another image than one band's", threads[k]);
    }
done:
    free(in);
    free(ref);
    free(out);
}

/* fewer rows than bands asked for: a band a row, the same bits */
static void test_sensor_threads_few_rows(void)
{
    gls_sensor s = noisy();
    enum { w = 37, h = 3 };
    float in[w * h * 3], ref[w * h * 3], out[w * h * 3];
    fill(in, w, h);
    memcpy(ref, in, sizeof ref);
    gls_sensor_apply(&s, ref, w, h, CX, CY, FX, pinhole_ray, NULL, 7, 2, 1);
    memcpy(out, in, sizeof out);
    gls_sensor_apply(&s, out, w, h, CX, CY, FX, pinhole_ray, NULL, 7, 2, 16);
    CHECK(memcmp(out, ref, sizeof out) == 0);
}

int main(void)
{
    RUN(test_sensor_threads_same_image);
    RUN(test_sensor_threads_few_rows);
    CHECK_EXIT();
}
