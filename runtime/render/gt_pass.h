/* The ground-truth pass: which instance each pixel shows and the camera-frame
 * normal of the surface there, from the centre sample (never blended,
 * whatever the anti-aliasing), drawn with the renderer's own items, culling,
 * order, matrices and reversed-Z depth test (render.h), so that ids and
 * normals belong exactly to the surface the image shows at the pixel
 * centre.
 *
 * It draws with a GLSL program into a framebuffer of its own (GL_R32UI
 * ids, RGBA32F normals, 32-bit float depth), created on first use and
 * kept with the renderer; the colour pass is untouched.  Alpha-tested
 * textures cut ids and normals where they cut the image: the fragment
 * shader samples the texture's alpha with the texture environment's rule
 * (REPLACE: the texel's alpha, MODULATE: texel alpha times colour alpha)
 * and discards below 0.5, as glAlphaFunc(GL_GEQUAL, 0.5) does.
 */
#ifndef GLS_GT_PASS_H
#define GLS_GT_PASS_H

#include <stddef.h>
#include <stdint.h>
#include "camera.h"
#include "render.h"

/* Draw camera c's centre sample (no jitter, same culling and depth test as
 * gls_render_pass) into the renderer's ground-truth framebuffer and read
 * back, all top row first: inst[i] = scene instance index + 1 of the
 * surface at pixel i (0: none); normal[3i..3i+2] = unit camera-frame
 * normal (OpenCV axes: x right, y down, z forward; facing the camera,
 * n . ray <= 0), 0 0 0 where none; z the depth Zc as gls_render_read_z
 * gives it (+inf where none), so ids and depth come from the same pass.
 * Any of inst, normal, z may be NULL.  The camera's size must be the
 * renderer's (gls_renderer_set_size).  0, or -1 with a message (a GL
 * without what the pass needs, out of memory). */
int gls_gt_render(gls_renderer *r, const gls_camera *c, uint32_t *inst, float *normal, float *z, char *err,
                  size_t errlen);
/* The same drawing and reading only image rows y0..y0+rows-1 (a scissor,
 * the whole pass's viewport and projection: those rows bit for bit the
 * whole pass's), into inst, normal, z (whole images) at their place; the
 * other rows untouched. */
int gls_gt_render_rows(gls_renderer *r, const gls_camera *c, uint32_t y0, uint32_t rows, uint32_t *inst,
                       float *normal, float *z, char *err, size_t errlen);

#endif
