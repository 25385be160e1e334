/* OSMesa backend of glctx.h: Mesa's software rasteriser (llvmpipe), no
 * display or GPU needed.  The compatibility profile keeps fixed-function
 * GL available (see render.c for why the renderer uses it).  Mesa 25.1
 * removed OSMesa; glctx_egl.c is its successor (spec/backends.md).
 *
 * libOSMesa is opened when the first OSMesa context is made, not linked:
 * it brings LLVM and its static constructors, 90 ms at every start of a
 * process on the CI machine, paid by every run that makes no OSMesa
 * context (EGL's, a run that draws no GL pass, --help, an input error). */
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glctx_backend.h"
#include "glctx_osmesa_soname.h" /* GLS_OSMESA_SONAME, from the Makefile */

/* The four functions this file calls, from the library once it is open. */
static struct {
    void *lib;
    OSMesaContext (*create)(const int *, OSMesaContext);
    GLboolean (*make_current)(OSMesaContext, void *, GLenum, GLsizei, GLsizei);
    void (*destroy)(OSMesaContext);
    OSMESAproc (*get_proc)(const char *);
    char why[200];      /* why it did not open, when it did not           */
} osm;
static pthread_once_t osm_once = PTHREAD_ONCE_INIT;

/* one function of the open library into dst (a function pointer); 0 when
 * the library lacks it */
static int osm_sym(const char *name, void *dst)
{
    void *v = dlsym(osm.lib, name);
    memcpy(dst, &v, sizeof v);
    return v != NULL;
}

static void osm_open(void)
{
    /* RTLD_LOCAL: its GL symbols stay out of the program's namespace
     * (glcalls.h: every call goes through OSMesaGetProcAddress) */
    if (!(osm.lib = dlopen(GLS_OSMESA_SONAME, RTLD_NOW | RTLD_LOCAL))) {
        const char *e = dlerror();
        snprintf(osm.why, sizeof osm.why, "%s", e ? e : "dlopen failed");
        return;
    }
    if (!(osm_sym("OSMesaCreateContextAttribs", &osm.create) & osm_sym("OSMesaMakeCurrent", &osm.make_current) &
          osm_sym("OSMesaDestroyContext", &osm.destroy) & osm_sym("OSMesaGetProcAddress", &osm.get_proc))) {
        snprintf(osm.why, sizeof osm.why, "%s lacks an OSMesa function", GLS_OSMESA_SONAME);
        dlclose(osm.lib);
        osm.lib = NULL;
    }
}

/* OSMesa needs a default framebuffer to make a context current; the
 * renderer never draws into it (it has its own FBO), so 1x1 will do. */
typedef struct {
    OSMesaContext ctx;
    unsigned char buf[4];
} osmesa_state;

static int osmesa_make_current(void *state)
{
    osmesa_state *s = state;
    return osm.make_current(s->ctx, s->buf, GL_UNSIGNED_BYTE, 1, 1) ? 0 : -1;
}

static void osmesa_destroy(void *state)
{
    osmesa_state *s = state;
    if (!s)
        return;
    if (s->ctx)
        osm.destroy(s->ctx);
    free(s);
}

static void *osmesa_create(gls_backend b, gls_glctx_info *info, char *err, size_t errlen)
{
    (void)b;
    info->platform = "none";
    info->device = "none (software: Mesa's OSMesa)";
    pthread_once(&osm_once, osm_open);
    if (!osm.lib) {
        snprintf(err, errlen, "osmesa: cannot load %s: %s", GLS_OSMESA_SONAME, osm.why);
        return NULL;
    }
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
    s->ctx = osm.create(attribs, NULL);
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
    OSMESAproc p = osm.get_proc(name);
    void *v;
    GLS_PROC_AS_VOIDP(p, v);
    return v;
}

const gls_glctx_ops gls_glctx_osmesa_ops = {osmesa_create, osmesa_make_current, osmesa_proc, osmesa_destroy};
