/* OSMesa backend of glctx.h: Mesa's software rasteriser (llvmpipe), no
 * display or GPU needed.  The compatibility profile keeps fixed-function
 * GL available (see render.c for why the renderer uses it). */
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glctx.h"

struct gls_glctx {
    OSMesaContext ctx;
    int width, height;
    unsigned char *buf; /* the default framebuffer OSMesa renders into */
};

gls_glctx *gls_glctx_create(int width, int height, char *err, size_t errlen)
{
    if (width < 1 || height < 1) {
        snprintf(err, errlen, "osmesa: invalid context size %dx%d", width, height);
        return NULL;
    }
    gls_glctx *c = calloc(1, sizeof *c);
    if (!c) {
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
    c->ctx = OSMesaCreateContextAttribs(attribs, NULL);
    if (!c->ctx) {
        snprintf(err, errlen, "osmesa: cannot create a GL 4.5 compatibility context");
        free(c);
        return NULL;
    }
    c->width = width;
    c->height = height;
    c->buf = calloc((size_t)width * (size_t)height, 4);
    if (!c->buf || gls_glctx_make_current(c)) {
        snprintf(err, errlen, "osmesa: cannot make the context current");
        gls_glctx_destroy(c);
        return NULL;
    }
    return c;
}

int gls_glctx_make_current(gls_glctx *c)
{
    return OSMesaMakeCurrent(c->ctx, c->buf, GL_UNSIGNED_BYTE, c->width, c->height) ? 0 : -1;
}

void *gls_glctx_proc(gls_glctx *c, const char *name)
{
    (void)c;
    /* OSMesaGetProcAddress returns a function pointer as OSMESAproc; the
     * conversion to void * is what dlsym does too (POSIX guarantees it). */
    OSMESAproc p = OSMesaGetProcAddress(name);
    void *v;
    _Static_assert(sizeof p == sizeof v, "function and object pointers differ in size");
    memcpy(&v, &p, sizeof v);
    return v;
}

const char *gls_glctx_backend(const gls_glctx *c)
{
    (void)c;
    return "osmesa";
}

void gls_glctx_destroy(gls_glctx *c)
{
    if (!c)
        return;
    if (c->ctx)
        OSMesaDestroyContext(c->ctx);
    free(c->buf);
    free(c);
}
