/* The camera file's sensor keys (spec/camera.md "Sensor effects"): gain,
 * read_noise, shot_noise, noise_seed, vignetting, bayer.  camera.c hands
 * each line whose key is one of these to gls_sensor_key_parse and puts
 * the result into the camera (gls_camera.sensor).  Kept apart from
 * camera.c's table of geometric keys so that the two grow independently. */
#ifndef GLS_SENSOR_KEYS_H
#define GLS_SENSOR_KEYS_H

#include <stddef.h>
#include "sensor_params.h"

#define GLS_SENSOR_NKEYS 6
/* The key names, in the order of the "keys:" list of messages. */
extern const char *const gls_sensor_key_names[GLS_SENSOR_NKEYS];

typedef struct {
    gls_sensor s;
    unsigned seen[GLS_SENSOR_NKEYS]; /* line of each key, 0 = absent */
} gls_sensor_keys;

void gls_sensor_keys_init(gls_sensor_keys *k);

/* The index of a sensor key, or -1 when word is not one. */
int gls_sensor_key(const char *word);

/* One line of a camera file whose first word is sensor key `key`: tok[0]
 * the key, tok[1..nt) its values, all pointing into line (a word's column
 * is tok[i] - line + 1); more: the line had more words than tok holds.
 * 0, or -1 with "fname:LINE:COL: error: ..." and the excerpt in err. */
int gls_sensor_key_parse(gls_sensor_keys *k, int key, char *const *tok, int nt, int more, const char *line,
                         unsigned lineno, const char *text, size_t len, const char *fname, char *err, size_t errlen);

#endif
