/* The image of a camera with sensor effects (sensor.h): the player's
 * linear intensities (the anti-aliasing accumulator's exact averages, or
 * a single pass's 8-bit colours) through the camera's sensor, in the
 * image file's format.  Called only when the camera asks for an effect. */
#ifndef GLS_SENSOR_IMAGE_H
#define GLS_SENSOR_IMAGE_H

#include <stdint.h>
#include "aa.h"
#include "camera.h"
#include "output_table.h"

/* acc: the accumulated samples, or NULL for a single pass whose colours
 * are rgba (RGBA8).  Returns a malloc'd image in fmt's layout (RGBA8,
 * RGB16 or RGB float; one sample a pixel with a Bayer pattern), or NULL
 * when out of memory.  name and frame key the noise.  bytes (or NULL):
 * [0] the linear intensities' buffer when it is one of its own (none
 * without photometric effects, and the image itself for a float image),
 * [1] the image returned. */
void *gls_sensor_image(const gls_camera *c, const char *name, uint32_t frame, const gls_accum *acc,
                       const uint8_t *rgba, gls_image_format fmt, uint64_t bytes[2]);

#endif
