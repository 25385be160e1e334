/* A camera's image through its sensor (sensor_image.h). */
#include <stdlib.h>
#include <string.h>
#include "sensor.h"
#include "sensor_image.h"

/* The camera-frame ray (x, y, 1) of pixel (u, v): the camera model's
 * own back-projection, so cos4 follows whatever the model is. */
static void camera_ray(void *ctx, double u, double v, double *x, double *y)
{
    double Pc[3];
    gls_camera_unproject(ctx, u, v, 1.0, Pc);
    *x = Pc[0], *y = Pc[1];
}

/* The image without photometric effects, as the player makes it when
 * the camera asks for none: the exact conversions of aa.h, so that a
 * Bayer mosaic alone keeps each sample of the colour image. */
static void *plain_image(const gls_camera *c, const gls_accum *acc, const uint8_t *rgba, gls_image_format fmt)
{
    size_t n = (size_t)c->width * c->height;
    size_t size = fmt == GLS_IMG_PNG8 ? 4 : fmt == GLS_IMG_PNG16 ? 3 * sizeof(uint16_t) : 3 * sizeof(float);
    void *img = malloc((n ? n : 1) * size);
    if (!img)
        return NULL;
    if (fmt == GLS_IMG_PNG16)
        acc ? gls_accum_rgb16(acc, img) : gls_rgba8_to_rgb16(rgba, n, img);
    else if (fmt == GLS_IMG_PFM)
        acc ? gls_accum_rgbf(acc, img) : gls_rgba8_to_rgbf(rgba, n, img);
    else if (acc)
        gls_accum_rgba8(acc, img);
    else
        memcpy(img, rgba, n * 4);
    return img;
}

void *gls_sensor_image(const gls_camera *c, const char *name, uint32_t frame, const gls_accum *acc,
                       const uint8_t *rgba, gls_image_format fmt, uint64_t bytes[2])
{
    const gls_sensor *s = &c->sensor;
    size_t n = (size_t)c->width * c->height;
    void *img;
    /* what is allocated, for the caller's count: the linear intensities
     * when they are a buffer of their own, and the image returned */
    uint64_t px = fmt == GLS_IMG_PNG8 ? 4 : fmt == GLS_IMG_PNG16 ? 3 * sizeof(uint16_t) : 3 * sizeof(float);
    if (bytes)
        bytes[0] = (s->on & ~GLS_SENSOR_BAYER) && fmt != GLS_IMG_PFM ? 3 * sizeof(float) * (uint64_t)n : 0,
        bytes[1] = (s->bayer[0] ? px / (fmt == GLS_IMG_PNG8 ? 4 : 3) : px) * (uint64_t)n;
    if (!(s->on & ~GLS_SENSOR_BAYER)) {
        img = plain_image(c, acc, rgba, fmt);
    } else {
        float *rgb = malloc((n ? n : 1) * 3 * sizeof *rgb);
        if (!rgb)
            return NULL;
        /* linear intensity in [0, 1]: sum / wsum / 255, or the 8-bit colour / 255 */
        if (acc)
            gls_accum_rgbf(acc, rgb);
        else
            gls_rgba8_to_rgbf(rgba, n, rgb);
        gls_sensor_apply(s, rgb, c->width, c->height, c->cx, c->cy, c->fx, camera_ray, (void *)c,
                         gls_sensor_camera_key(name), frame, 0);
        if (fmt == GLS_IMG_PFM) {
            img = rgb;
        } else {
            img = gls_sensor_quantise(rgb, c->width, c->height, fmt == GLS_IMG_PNG8 ? 8 : 16);
            free(rgb);
        }
    }
    if (!img || !s->bayer[0])
        return img;
    void *m = gls_sensor_mosaic(s->bayer, img, fmt == GLS_IMG_PNG8 ? 4 : 3,
                                fmt == GLS_IMG_PNG8 ? 1 : fmt == GLS_IMG_PNG16 ? sizeof(uint16_t) : sizeof(float),
                                c->width, c->height);
    free(img);
    return m;
}
