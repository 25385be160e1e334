/* The landmarks output (glsplay --outputs landmarks, spec/outputs.md
 * "Landmarks"): per camera and frame, every landmark instance of the
 * scene projected by the camera model in double, with its depth and
 * whether it is in the image and not hidden, as CSV. */
#ifndef GLS_GT_LANDMARKS_H
#define GLS_GT_LANDMARKS_H

#include <stdint.h>
#include "buf.h"
#include "camera.h"
#include "scene.h"

/* A landmark's tolerance against the depth buffer: relative part (see
 * gls_landmark_visible). */
#define GLS_LANDMARK_DEPTH_REL 1e-4

/* One frame's landmarks, taken on the rendering thread (motion moves
 * them per frame), encoded on the writer's.  name and path point into
 * the scene, which outlives the writer's jobs. */
typedef struct {
    uint32_t n;
    const char **name, **path; /* n each */
    double *X;                 /* 3 n: world positions                    */
    double (*pose)[12];        /* NULL: every landmark through the frame's
                                  camera; else landmark k through the
                                  camera R = pose[k][0..8], T = pose[k][9..11]
                                  (rolling shutter: its band's time,
                                  exposure_landmarks.c)                   */
} gls_landmarks;

/* The scene's landmarks where its instances are now; NULL when out of
 * memory.  Free with gls_landmarks_free (NULL is fine). */
gls_landmarks *gls_landmarks_take(const gls_scene *s);
void gls_landmarks_free(gls_landmarks *l);

/* Is a point at depth zc, projected to (u, v), in front of the surface
 * the centre-sample depth z (width x height, top row first, +inf where
 * nothing was drawn) shows at its nearest pixel?  Assumes the point is in
 * the image (-0.5 <= u < width - 0.5, the same for v). */
int gls_landmark_visible(const float *z, uint32_t width, uint32_t height, double u, double v, double zc);

/* The CSV (header line, one row per landmark) for camera c (or the
 * landmarks' own poses) and its centre-sample depth z.  0, or -1 when out of memory. */
int gls_encode_landmarks_csv(const gls_landmarks *l, const gls_camera *c, const float *z, gls_buf *buf);

#endif
