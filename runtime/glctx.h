/* The GL context behind one small interface, so that a second backend
 * (EGL with a device platform, for GPUs) can be added next to OSMesa
 * without touching the renderer.  A context renders off-screen only: the
 * renderer draws into its own framebuffer object, so the size given here
 * only has to be valid, not the image size. */
#ifndef GLS_GLCTX_H
#define GLS_GLCTX_H

#include <stddef.h>

typedef struct gls_glctx gls_glctx;

/* Create a GL 4.5 compatibility-profile context with a width x height
 * default framebuffer.  NULL on failure with a one-line reason in err. */
gls_glctx *gls_glctx_create(int width, int height, char *err, size_t errlen);

/* Make the context current on the calling thread.  0 or -1. */
int gls_glctx_make_current(gls_glctx *c);

/* Look up a GL entry point (core or extension) by name; NULL if absent. */
void *gls_glctx_proc(gls_glctx *c, const char *name);

/* Name of the backend, e.g. "osmesa". */
const char *gls_glctx_backend(const gls_glctx *c);

void gls_glctx_destroy(gls_glctx *c);

#endif
