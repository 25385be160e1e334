/* What the library's files share (lib/): the error setter and the
 * conversion of a public camera into the runtime's.  Not installed. */
#ifndef GLSCENE_INTERNAL_H
#define GLSCENE_INTERNAL_H
#include "camera.h"
#include "glscene.h"
#include "player.h"

/* Write the formatted message into e (if not NULL); returns -1, so that
 * a failing call can `return gls_api_fail(e, ...)`. */
int gls_api_fail(glscene_error *e, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Check c as glscene_camera_set does and convert it (pose: the world).
 * 0, or -1 with e. */
int gls_api_camera(const glscene_camera *c, gls_camera *out, glscene_error *e);

/* The options run r hands to gls_play, for a test's program to set what
 * no argument of glsplay sets (gls_play_opts' bands_whole:
 * tools/glsplay_bands_whole.c).  Not in the shared library's exports
 * (lib/glscene.map: glscene_* only). */
gls_play_opts *gls_api_play_opts(glscene_play *r);
#endif
