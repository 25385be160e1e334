/* The GL context behind one small interface, with two backends
 * (spec/backends.md): EGL (glctx_egl.c: a GPU through the device platform,
 * or Mesa through the surfaceless platform) and OSMesa (glctx_osmesa.c:
 * Mesa's software rasteriser, removed from Mesa in 25.1).  Either may be
 * left out of a build (no library at build time); at least one is in.
 * A context renders off-screen only: the renderer draws into its own
 * framebuffer object, so no context has a default framebuffer worth
 * drawing into.
 *
 * Every GL function the renderer calls goes through the entry points of
 * the context's backend (gls_glctx_proc, and glcalls.h for the functions
 * called by their plain names), never through a symbol a library happens
 * to export: libOSMesa exports glClear too, and its glClear does not
 * reach an NVIDIA EGL context. */
#ifndef GLS_GLCTX_H
#define GLS_GLCTX_H

#include <stddef.h>

typedef struct gls_glctx gls_glctx;

/* Which backend to use.  AUTO: EGL where it gives a context, OSMesa
 * otherwise.  EGL: a GPU through the device platform if one gives a
 * context, else Mesa's surfaceless platform.  EGL_DEVICE and
 * EGL_SURFACELESS: that platform only (the device platform then also
 * takes Mesa's software device, after any GPU). */
typedef enum {
    GLS_BACKEND_AUTO = 0,
    GLS_BACKEND_EGL,
    GLS_BACKEND_EGL_DEVICE,
    GLS_BACKEND_EGL_SURFACELESS,
    GLS_BACKEND_OSMESA,
} gls_backend;

/* The name of a choice as --backend spells it ("auto", "egl",
 * "egl-device", "egl-surfaceless", "osmesa"); parse: 0, or -1 if s names
 * none. */
const char *gls_backend_name(gls_backend b);
int gls_backend_parse(const char *s, gls_backend *b);
/* 1 if the library behind b was in the build (AUTO: always 1). */
int gls_backend_built(gls_backend b);
/* Why b is not in the build and what to do, e.g. "libEGL was not found
 * when it was built (Debian: install libegl-dev and rebuild)". */
const char *gls_backend_missing(gls_backend b);

/* Create a GL 4.5 compatibility-profile context through backend b and
 * make it current on the calling thread.  NULL on failure with a
 * one-line reason in err naming the backend, the step and, for EGL, the
 * EGL error (e.g. "egl: surfaceless platform: eglInitialize failed:
 * EGL_NOT_INITIALIZED"). */
gls_glctx *gls_glctx_create(gls_backend b, char *err, size_t errlen);

/* Make the context current on the calling thread.  0 or -1. */
int gls_glctx_make_current(gls_glctx *c);

/* Look up a GL entry point (core or extension) by name; NULL if absent. */
void *gls_glctx_proc(gls_glctx *c, const char *name);

/* What the context is, for --explain and reports: strings that live as
 * long as the context. */
typedef struct {
    const char *backend;  /* "egl" or "osmesa" */
    const char *platform; /* EGL: "device" or "surfaceless"; OSMesa: "none" */
    const char *device;   /* which device or driver, in words */
    const char *fallback; /* auto fell back to OSMesa: why EGL failed; else "" */
    const char *renderer; /* GL_RENDERER */
    const char *version;  /* GL_VERSION */
} gls_glctx_info;
const gls_glctx_info *gls_glctx_describe(const gls_glctx *c);

/* Name of the backend, "egl" or "osmesa" (gls_glctx_describe()->backend). */
const char *gls_glctx_backend(const gls_glctx *c);

void gls_glctx_destroy(gls_glctx *c);

#endif
