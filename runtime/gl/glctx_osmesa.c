/* OSMesa backend of glctx.h: Mesa's software rasteriser (llvmpipe), no
 * display or GPU needed.  The compatibility profile keeps fixed-function
 * GL available (see render.c for why the renderer uses it).  Mesa 25.1
 * removed OSMesa; glctx_egl.c is its successor (spec/backends.md). */
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glctx_backend.h"

/* OSMesa needs a default framebuffer to make a context current; the
 * renderer never draws into it (it has its own FBO), so 1x1 will do. */
typedef struct {
    OSMesaContext ctx;
    unsigned char buf[4];
} osmesa_state;

static int osmesa_make_current(void *state)
{
    osmesa_state *s = state;
    return OSMesaMakeCurrent(s->ctx, s->buf, GL_UNSIGNED_BYTE, 1, 1) ? 0 : -1;
}

static void osmesa_destroy(void *state)
{
    osmesa_state *s = state;
    if (!s)
        return;
    if (s->ctx)
        OSMesaDestroyContext(s->ctx);
    free(s);
}

static void *osmesa_create(gls_backend b, gls_glctx_info *info, char *err, size_t errlen)
{
    (void)b;
    info->platform = "none";
    info->device = "none (software: Mesa's OSMesa)";
    osmesa_state *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "osmesa: out of memory");
        return NULL;
    }
    static const int attribs[] = {
        OSMESA_FORMAT, OSMESA_RGBA,
        OSMESA_DEPTH_BITS, 0,      /* depth lives in the renderer's FBO */
        OSMESA_STENCIL_BITS, 0,
        OSMESA_ACCUM_BITS, 0,
        OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION, 4,
        OSMESA_CONTEXT_MINOR_VERSION, 5,
        0,
    };
    s->ctx = OSMesaCreateContextAttribs(attribs, NULL);
    if (!s->ctx) {
        snprintf(err, errlen, "osmesa: cannot create a GL 4.5 compatibility context");
        free(s);
        return NULL;
    }
    if (osmesa_make_current(s)) {
        snprintf(err, errlen, "osmesa: cannot make the context current");
        osmesa_destroy(s);
        return NULL;
    }
    return s;
}

static void *osmesa_proc(void *state, const char *name)
{
    (void)state;
    OSMESAproc p = OSMesaGetProcAddress(name);
    void *v;
    GLS_PROC_AS_VOIDP(p, v);
    return v;
}

const gls_glctx_ops gls_glctx_osmesa_ops = {osmesa_create, osmesa_make_current, osmesa_proc, osmesa_destroy};
