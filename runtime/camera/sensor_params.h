/* What a camera file asks of its sensor (spec/camera.md "Sensor
 * effects"): the effects' bits and their parameters, read with the camera
 * (sensor_keys.c).  The post-process that applies them is the effects
 * room's (effects/sensor.h). */
#ifndef GLS_SENSOR_PARAMS_H
#define GLS_SENSOR_PARAMS_H

#include <stdint.h>

/* One bit per effect asked for (gls_sensor.on). */
enum {
    GLS_SENSOR_VIGNETTING = 1,
    GLS_SENSOR_GAIN = 2,
    GLS_SENSOR_SHOT = 4,
    GLS_SENSOR_READ = 8,
    GLS_SENSOR_BAYER = 16
};
#define GLS_SENSOR_NOISE (GLS_SENSOR_SHOT | GLS_SENSOR_READ)

typedef enum { GLS_VIGNETTING_NONE = 0, GLS_VIGNETTING_COS4 = 1, GLS_VIGNETTING_POLY = 2 } gls_vignetting;

/* The most electrons per unit intensity shot_noise takes: counts stay
 * far below 2^53, where doubles hold every whole number. */
#define GLS_SENSOR_MAX_K 1e12

typedef struct {
    unsigned on;            /* GLS_SENSOR_* bits; 0: no sensor effect      */
    gls_vignetting vignetting;
    double poly[3];         /* vignetting poly: a1 a2 a3                    */
    double gain;            /* exposure gain G (> 0; 1 when not given)      */
    double shot_k;          /* shot_noise K: electrons at intensity 1      */
    double read_sigma;      /* read_noise: standard deviation, units of
                               full scale (white = 1)                       */
    uint64_t seed;          /* noise_seed (0 when not given)                */
    char bayer[5];          /* "RGGB", "BGGR", "GRBG", "GBRG" or ""         */
} gls_sensor;

/* The sensor a camera file without sensor keys has: nothing on, gain 1. */
gls_sensor gls_sensor_none(void);

#endif
