/* Drawing a flattened scene (scene.h) through one camera (camera.h) into
 * an off-screen framebuffer, and reading the result back.
 *
 * The framebuffer: RGBA8 colour and 32-bit float depth renderbuffers in a
 * framebuffer object, reversed Z (depth 1 at near, 0 at far, cleared to 0,
 * GL_GREATER), so recovered depth keeps ~float precision relative to the
 * distance over the whole near..far range (spec/camera.md "Depth").
 * Framebuffer row r is image row r (the y flip is in the projection), so
 * read-backs come out top row first.
 */
#ifndef GLS_RENDER_H
#define GLS_RENDER_H

#include <stddef.h>
#include <stdint.h>
#include "bundle.h"
#include "camera.h"
#include "glctx.h"
#include "occlusion.h"
#include "scene.h"
#include "scene_cull.h"

typedef struct gls_renderer gls_renderer;

/* Upload the scene's vertices and the textures it uses.  The context must
 * be current; scene must outlive the renderer (its chunks are drawn from
 * it), the bundle need not.  NULL with a message on failure. */
gls_renderer *gls_renderer_create(gls_glctx *ctx, const gls_bundle *b, const gls_scene *scene, char *err,
                                  size_t errlen);

/* (Re)allocate the framebuffer for width x height images. */
int gls_renderer_set_size(gls_renderer *r, uint32_t width, uint32_t height, char *err, size_t errlen);

/* Colour of pixels no surface covers (default black), components 0..1.
 * Depth and points are unaffected: they stay +inf / absent there. */
void gls_renderer_set_background(gls_renderer *r, const float rgb[3]);

/* A framebuffer holding a mosaic of kx x ky images of width x height, so
 * that several jittered passes are drawn with one clear and read back
 * with one glReadPixels (anti-aliasing, spec/antialiasing.md).  Tile t
 * is at column t % kx, row t / kx; tile 0 is where a plain pass goes. */
int gls_renderer_set_mosaic(gls_renderer *r, uint32_t width, uint32_t height, uint32_t kx, uint32_t ky, char *err,
                            size_t errlen);
/* Memory a mosaic needs: its framebuffer (8 bytes a pixel: RGBA8 colour,
 * float depth) and the depth read-back of one image.  When it cannot be
 * had, set_size / set_mosaic say "cannot allocate a WxH framebuffer[, KxK
 * tiles of wxh images] (N GiB of memory)". */
uint64_t gls_renderer_bytes(uint32_t width, uint32_t height, uint32_t kx, uint32_t ky);
/* Largest framebuffer side GL allows (GL_MAX_RENDERBUFFER_SIZE). */
uint32_t gls_renderer_max_dim(const gls_renderer *r);

/* Render one pass: clear, draw every item (an instance's chunk) the
 * camera can see (scene_cull.h).  (du, dv) shifts the principal
 * point by a sub-pixel amount (0, 0 for a plain image): the hook for
 * anti-aliasing by jittered multi-pass accumulation.  The camera's
 * width/height must equal the framebuffer size. */
void gls_render_pass(gls_renderer *r, const gls_camera *c, double du, double dv);

/* gls_render_pass without jitter that clears and draws only framebuffer
 * (= image) rows y0..y0+rows-1 of a plain framebuffer (no mosaic): a
 * scissor, with the whole pass's viewport and projection, so those rows
 * are the whole pass's bit for bit; the other rows keep what they held.
 * For passes of which only some rows are read (distort_exposure.c). */
void gls_render_pass_rows(gls_renderer *r, const gls_camera *c, uint32_t y0, uint32_t rows);

/* Render n <= kx * ky passes into the mosaic's tiles 0..n-1, pass t with
 * jitter (du[t], dv[t]); one clear for all.  gls_render_pass() is this
 * with n = 1. */
void gls_render_tiles(gls_renderer *r, const gls_camera *c, uint32_t n, const double *du, const double *dv);
/* gls_render_tiles drawing only image rows y0..y0+rows-1 of each tile (a
 * scissor, with each tile's whole viewport and projection: those rows are
 * the whole tiles' bit for bit); rows 0..height: gls_render_tiles. */
void gls_render_tiles_rows(gls_renderer *r, const gls_camera *c, uint32_t n, const double *du, const double *dv,
                           uint32_t y0, uint32_t rows);

/* The centre sample (no jitter) drawn into whatever framebuffer is bound,
 * in the current viewport, without clearing it: the same items, culling,
 * order, matrices and depth test as gls_render_pass, with hook(ud, scene,
 * item) called just before each item's draw call (its modelview and draw
 * key are set by then).  For passes that draw other quantities than
 * colour with their own program (gt_pass.h). */
typedef void (*gls_render_item_hook)(void *ud, const gls_scene *s, const gls_item *it);
void gls_render_hooked(gls_renderer *r, const gls_camera *c, gls_render_item_hook hook, void *ud);
/* The scene r draws. */
const gls_scene *gls_renderer_scene(const gls_renderer *r);
/* Shadow maps (shadows.c): every item, depth only (no program, no colour),
 * seen by view through P, into whatever framebuffer is bound; the near
 * items as the colour pass being prepared placed them. */
void gls_render_depth_only(gls_renderer *r, const gls_camera *view, const double P[16]);
/* r's table of GL entry points beyond GL 1.1 (glcalls.h), for the passes
 * that draw with it (gt_pass.c). */
typedef struct gls_glext gls_glext;
const gls_glext *gls_renderer_gl(const gls_renderer *r);
/* One extension's state hangs off the renderer (the ground-truth pass's
 * program and framebuffer): set replaces (and frees) the previous one;
 * ext_free(ext) runs at gls_renderer_destroy, while the context lives. */
void gls_renderer_set_ext(gls_renderer *r, void *ext, void (*ext_free)(void *));
void *gls_renderer_ext(const gls_renderer *r);

/* Fine-framebuffer passes (one-pass anti-aliasing, aa_onepass.c).
 * Image-space bounds of every draw item (an instance's chunk; the
 * lattice's "chunks") for camera c, b[i] = {u0, v0, u1,
 * v1}: the bounding box of its box's projected corners; {-inf, -inf,
 * inf, inf} when the box reaches nearer than the near plane (it may be
 * anywhere), {inf, inf, -inf, -inf} when it is wholly nearer than near or
 * beyond far (nowhere), or outside the view (culled).  Returns the
 * number of items. */
uint32_t gls_render_chunk_bounds(gls_renderer *r, const gls_camera *c, double (*b)[4]);
/* Instances drawn and culled by the last pass or chunk bounds. */
gls_cull_stats gls_render_cull_stats(const gls_renderer *r);
uint32_t gls_renderer_nchunks(const gls_renderer *r);
/* Upload what camera c needs before gls_render_mapped (the re-anchored
 * near chunks), and draw its shadow maps (a scene with shadows: fitted to
 * what the whole camera sees, the same for every mapped tile). */
void gls_render_prepare(gls_renderer *r, const gls_camera *c);
/* Clear and draw the chunks with vis[i] != 0 (NULL: all) through camera
 * c with the image -> window map m (gls_camera_projection_map) in the
 * viewport (0, 0, vw, vh), only inside the scissor rectangle sc = {x, y,
 * w, h} (the framebuffer, from gls_renderer_set_size, may be larger). */
void gls_render_mapped(gls_renderer *r, const gls_camera *c, const double m[6], uint32_t vw, uint32_t vh,
                       const uint32_t sc[4], const uint8_t *vis);
/* Read back the rectangle sc = {x, y, w, h}: RGBA8 into an image of rows
 * of `width` pixels (framebuffer row 0 first) at its place (x, y). */
void gls_render_read_rect(gls_renderer *r, uint32_t width, const uint32_t sc[4], uint8_t *rgba);

/* Start the rasteriser on what was drawn (glFlush) without waiting, so
 * the CPU can accumulate the previous read-back meanwhile. */
void gls_render_flush(gls_renderer *r);
/* Wait until drawing is done (glFinish): for timing the parts apart. */
void gls_render_finish(gls_renderer *r);

/* Read back the first `rows` rows of tiles of the mosaic: RGBA8, rows of
 * kx * width pixels, framebuffer row 0 first. */
void gls_render_read_mosaic(gls_renderer *r, uint32_t rows, uint8_t *rgba);
/* The same for image rows y0..y0+n-1 of each tile only, each at its place
 * in rgba (the other rows untouched). */
void gls_render_read_mosaic_rows(gls_renderer *r, uint32_t rows, uint32_t y0, uint32_t n, uint8_t *rgba);

/* Read back the last pass (tile 0 of a mosaic): RGBA8 top row first (width*height*4 bytes);
 * depth as camera Zc (float, +inf where nothing was drawn), top row first.
 * Zc is recovered from the depth buffer with the projection coefficients
 * exactly as they were handed to GL (as float), in double. */
void gls_render_read_rgba(gls_renderer *r, uint8_t *rgba);
void gls_render_read_z(gls_renderer *r, float *z);
/* The same for rows y0..y0+rows-1 only, into rgba / z at their place in
 * the whole image (the other rows untouched). */
void gls_render_read_rgba_rows(gls_renderer *r, uint32_t y0, uint32_t rows, uint8_t *rgba);
void gls_render_read_z_rows(gls_renderer *r, uint32_t y0, uint32_t rows, float *z);

/* Occlusion culling of colour passes (occlusion.h): GLS_OCCLUSION_AUTO by
 * default; the image is the same in every mode, only the time differs. */
void gls_renderer_set_occlusion(gls_renderer *r, gls_occlusion_mode mode);
/* Items the last colour pass (or mapped tile) skipped as occluded. */
uint32_t gls_render_occluded(const gls_renderer *r);

/* GL_RENDERER and GL_VERSION strings of the context, for reports. */
const char *gls_renderer_gl_name(const gls_renderer *r);
const char *gls_renderer_gl_version(const gls_renderer *r);
/* 1 if anisotropic filtering is available (GL_*_texture_filter_anisotropic). */
int gls_renderer_anisotropic(const gls_renderer *r);
/* Anisotropic filtering of every texture, up to n x (n <= 1: off, the
 * default; capped at what GL allows).  Off by default because llvmpipe's
 * anisotropic sampler is very slow: minutes instead of a fraction of a
 * second for a 640x480 frame of the road demo (make bench-aa measures
 * it).  -1 with a message when n > 1 and GL lacks the extension. */
int gls_renderer_set_anisotropy(gls_renderer *r, uint32_t n, char *err, size_t errlen);

void gls_renderer_destroy(gls_renderer *r);

/* Column-major float copy of a row-major double matrix, for glLoadMatrixf. */
void gls_mat_to_gl(const double rm[16], float cm[16]);

#endif
