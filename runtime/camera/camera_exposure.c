/* The camera keys of motion blur, rolling shutter and depth of field
 * (spec/camera.md "Motion blur, rolling shutter, depth of field"): each
 * optional, each off when absent, checked here with located messages. */
#include <math.h>
#include <string.h>
#include "camera_keys.h"
#include "numfmt.h"
#include "srcline.h"

int gls_camera_exposure_keys(const gls_camera_keys *k, const char *const *names, const char *text, size_t len,
                           const char *fname, gls_camera *cam, char *err, size_t errlen)
{
    const unsigned *seen = k->seen, *vcol = k->vcol;
    char num[40];
#define VAL(key) (k->val[key][0])
#define FAIL(key, ...)                                                                                          \
    do {                                                                                                        \
        gls_fmt_double(num, sizeof num, VAL(key));                                                              \
        gls_text_error(err, errlen, text, len, fname, seen[key], vcol[key], __VA_ARGS__);                       \
        return -1;                                                                                              \
    } while (0)
    if (seen[K_SHUTTER] && !(VAL(K_SHUTTER) > 0 && VAL(K_SHUTTER) <= 1))
        FAIL(K_SHUTTER, "%s %s must be in (0, 1]: the exposure as a fraction of the frame interval", names[K_SHUTTER],
             num);
    if (seen[K_LINE_DELAY] && !(VAL(K_LINE_DELAY) > 0 && VAL(K_LINE_DELAY) <= 1))
        FAIL(K_LINE_DELAY, "%s %s must be in (0, 1]: the time between consecutive rows' exposures, in frame intervals",
             names[K_LINE_DELAY], num);
    if (seen[K_APERTURE] && !(VAL(K_APERTURE) > 0))
        FAIL(K_APERTURE, "%s %s must be > 0: the lens diameter, in scene units", names[K_APERTURE], num);
    if (seen[K_FOCUS] && !(VAL(K_FOCUS) > 0))
        FAIL(K_FOCUS, "%s %s must be > 0: the focus distance along the optical axis, in scene units", names[K_FOCUS],
             num);
    /* depth of field needs both: a lens, and where it focuses */
    if (seen[K_APERTURE] != 0 && !seen[K_FOCUS])
        FAIL(K_APERTURE, "key '%s' needs key '%s' (the focus distance along the optical axis)", names[K_APERTURE],
             names[K_FOCUS]);
    if (seen[K_FOCUS] != 0 && !seen[K_APERTURE])
        FAIL(K_FOCUS, "key '%s' needs key '%s' (the lens diameter)", names[K_FOCUS], names[K_APERTURE]);
    if (seen[K_EXPOSURE_SAMPLES]) {
        double v = VAL(K_EXPOSURE_SAMPLES);
        if (!(v >= 1 && v <= GLS_EXPOSURE_SAMPLES_MAX && v == floor(v)))
            FAIL(K_EXPOSURE_SAMPLES, "%s %s must be a whole number in 1..%u", names[K_EXPOSURE_SAMPLES], num,
                 GLS_EXPOSURE_SAMPLES_MAX);
        if (!seen[K_SHUTTER] && !seen[K_APERTURE])
            FAIL(K_EXPOSURE_SAMPLES, "key '%s' without 'shutter' or 'aperture': there is nothing to sample",
                 names[K_EXPOSURE_SAMPLES]);
    }
#undef FAIL
#undef VAL
    cam->shutter = seen[K_SHUTTER] ? k->val[K_SHUTTER][0] : 0;
    cam->line_delay = seen[K_LINE_DELAY] ? k->val[K_LINE_DELAY][0] : 0;
    cam->aperture = seen[K_APERTURE] ? k->val[K_APERTURE][0] : 0;
    cam->focus = seen[K_FOCUS] ? k->val[K_FOCUS][0] : 0;
    cam->exposure_samples = 0;
    if (cam->shutter > 0 || cam->aperture > 0)
        cam->exposure_samples =
            seen[K_EXPOSURE_SAMPLES] ? (uint32_t)k->val[K_EXPOSURE_SAMPLES][0] : GLS_EXPOSURE_SAMPLES_DEFAULT;
    return 0;
}
