/* The geometry of a point light's shadow cube map (spec/camera.md
 * "Shadows"): six 90-degree perspective views from the light, one per
 * face of GL's cube map, each storing the reversed depth near / z of the
 * nearest caster, z the distance along the face's axis (the largest of
 * |x|, |y|, |z| of the caster's offset from the light, in world axes).
 *
 * The faces are oriented as GL samples them (the GL 4.6 specification's
 * table 8.19, "Selection of cube map images"): face f's camera looks down
 * its axis with image x = s_c and image y = -t_c, so that the texel a
 * colour pass's lookup direction selects is the one the face's draw wrote.
 * Every matrix is composed in double, the light's position relative to
 * the items through the renderer's camera-relative modelviews. */
#ifndef GLS_SHADOWS_CUBE_H
#define GLS_SHADOWS_CUBE_H

#include "camera.h"
#include "scene.h"

/* Face f (0..5: +X, -X, +Y, -Y, +Z, -Z, GL's order) of the map of a light
 * at world position X: R, T (OpenCV frame, world to face camera). */
void gls_cube_face_camera(const double X[3], int f, double near, gls_camera *c);
/* The faces' projection from GL eye coordinates: 90 degrees, reversed
 * depth near / z with no far plane (z = near -> 1, z -> infinity -> 0). */
void gls_cube_projection(double near, double P[16]);
/* The near distance of a light at X: a small fraction of the farthest
 * corner of the items' boxes (geometry nearer the light than it casts
 * nothing); the reversed float depth keeps the relative precision of z
 * whatever it is. */
double gls_cube_near(const gls_scene *s, const double X[3]);

/* The near plane as a fraction of that farthest distance. */
#define GLS_CUBE_NEAR_FRACTION 1e-4

#endif
