/* The values of a camera as a parser found them, with where each was
 * found, shared by the two camera file parsers (camera.c: the .cam
 * format; camera_opencv.c: OpenCV FileStorage YAML) so that both check
 * the values with the same code and the same located messages. */
#ifndef GLS_CAMERA_KEYS_H
#define GLS_CAMERA_KEYS_H
#include <stddef.h>
#include <stdio.h>
#include "camera.h"
#include "srcline.h"

enum {
    K_WIDTH, K_HEIGHT, K_FX, K_FY, K_CX, K_CY, K_SKEW, K_R, K_T, K_NEAR, K_FAR, K_POSE,
    K_K,    /* the 3x3 camera matrix, instead of fx fy cx cy skew */
    K_RVEC, /* a Rodrigues vector, instead of R                   */
    K_DIST, /* Brown-Conrady k1 k2 p1 p2 [k3 [k4 k5 k6]]          */
    K_FISHEYE, /* cv::fisheye k1 k2 k3 k4, instead of K_DIST      */
    /* optional effects (spec/camera.md "Motion blur, rolling shutter,
     * depth of field"); OpenCV YAML nodes of the same names too */
    K_SHUTTER, K_LINE_DELAY, K_APERTURE, K_FOCUS, K_EXPOSURE_SAMPLES,
    K_COUNT
};

/* Where a message about a camera file points (gls_text_error): the
 * file's text and name, and where the message goes. */
typedef struct {
    const char *text, *fname;
    size_t len;
    char *err;
    size_t errlen;
} gls_camera_src;

/* The located message at line:col of *s; evaluates to -1. */
#define GLS_CAMERA_FAIL(s, line, col, ...) \
    (gls_text_error((s)->err, (s)->errlen, (s)->text, (s)->len, (s)->fname, line, col, __VA_ARGS__), -1)

typedef struct {
    double val[K_COUNT][9];
    unsigned seen[K_COUNT];       /* line of each key, 0 = absent          */
    unsigned vcol[K_COUNT];       /* a column on that line: its first value,
                                     or an OpenCV matrix's key (the values
                                     are on the data: line below)          */
    unsigned eline[K_COUNT][9];   /* line and column of each value: where  */
    unsigned ecol[K_COUNT][9];    /* a message about a number points       */
    gls_pose pose;                /* the 'pose' word, if seen              */
    unsigned ndist;               /* K_DIST: numbers given (4, 5 or 8)     */
} gls_camera_keys;

/* Check the values of a parsed camera file whose required keys are all
 * there (K may stand for fx fy cx cy skew, rvec for R) and fill cam
 * (camera_keys.c).
 * names[k] is what the file calls key k, for the messages.  Errors and
 * notes as gls_camera_parse(). */
int gls_camera_from_keys(gls_camera_keys *k, const char *const *names, const char *text, size_t len,
                         const char *fname, gls_pose use, FILE *notes, gls_camera *cam, char *err, size_t errlen);

/* The effect keys (camera_exposure.c): checked, and set in cam (zeros:
 * off).  0, or -1 with the located message in err. */
int gls_camera_exposure_keys(const gls_camera_keys *k, const char *const *names, const char *text, size_t len,
                           const char *fname, gls_camera *cam, char *err, size_t errlen);

/* A camera given as OpenCV FileStorage YAML (camera_opencv.c): the text
 * starts with "%YAML".  Parsed as gls_camera_parse() says. */
int gls_camera_is_opencv(const char *text, size_t len);
int gls_camera_parse_opencv(const char *text, size_t len, const char *fname, gls_pose use, FILE *notes,
                            gls_camera *cam, char *err, size_t errlen);
#endif
