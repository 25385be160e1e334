/* glctx.h: the choice of backend, the entry points of glcalls.h and what
 * a context reports.  The backends themselves are glctx_egl.c and
 * glctx_osmesa.c; which of them this build has is in the generated
 * glctx_backends.h (the Makefile writes it from pkg-config, GLS_NO_EGL
 * and GLS_NO_OSMESA). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glcalls.h"
#include "glctx.h"
#include "glctx_backend.h"
#include "glctx_backends.h"

#if !GLS_HAVE_EGL && !GLS_HAVE_OSMESA
#error "no GL backend: glscene needs libEGL (libegl-dev) or libOSMesa (libosmesa6-dev)"
#endif

/* Every function of glcalls.h's list must also be one of its macros:
 * then its name here is the table's pointer, not the library's function. */
#define GLS_CHECK_ROUTED(name)                                                                   \
    _Static_assert(__builtin_types_compatible_p(__typeof__(name), __typeof__(((gls_glcalls *)0)->p_##name)), \
                   #name " is in GLS_GLCALLS but has no macro in glcalls.h");
GLS_GLCALLS(GLS_CHECK_ROUTED)
#undef GLS_CHECK_ROUTED

_Thread_local const gls_glcalls *gls_glcalls_current;

struct gls_glctx {
    const gls_glctx_ops *ops;
    void *state;
    const char *name; /* "egl" or "osmesa" */
    gls_glctx_info info;
    gls_glcalls calls;
    char fallback[512], renderer[256], version[256];
};

static const struct {
    const char *name;
    gls_backend b;
} choices[] = {
    {"auto", GLS_BACKEND_AUTO},
    {"egl", GLS_BACKEND_EGL},
    {"egl-device", GLS_BACKEND_EGL_DEVICE},
    {"egl-surfaceless", GLS_BACKEND_EGL_SURFACELESS},
    {"osmesa", GLS_BACKEND_OSMESA},
};

const char *gls_backend_name(gls_backend b)
{
    for (size_t i = 0; i < sizeof choices / sizeof choices[0]; i++)
        if (choices[i].b == b)
            return choices[i].name;
    return "?";
}

int gls_backend_parse(const char *s, gls_backend *b)
{
    for (size_t i = 0; i < sizeof choices / sizeof choices[0]; i++)
        if (strcmp(s, choices[i].name) == 0) {
            *b = choices[i].b;
            return 0;
        }
    return -1;
}

static int is_egl(gls_backend b)
{
    return b == GLS_BACKEND_EGL || b == GLS_BACKEND_EGL_DEVICE || b == GLS_BACKEND_EGL_SURFACELESS;
}

int gls_backend_built(gls_backend b)
{
    if (b == GLS_BACKEND_AUTO)
        return 1;
    return is_egl(b) ? GLS_HAVE_EGL : GLS_HAVE_OSMESA;
}

const char *gls_backend_missing(gls_backend b)
{
    return is_egl(b) ? "libEGL was not found when it was built (Debian: install libegl-dev and rebuild)"
                     : "libOSMesa was not found when it was built (Debian 12: install libosmesa6-dev and rebuild; "
                       "Mesa 25.1 and later have no OSMesa: use --backend egl)";
}

static const gls_glctx_ops *ops_of(gls_backend b)
{
#if GLS_HAVE_EGL
    if (is_egl(b))
        return &gls_glctx_egl_ops;
#endif
#if GLS_HAVE_OSMESA
    if (b == GLS_BACKEND_OSMESA)
        return &gls_glctx_osmesa_ops;
#endif
    return NULL;
}

/* The backend's context, its glcalls table and GL strings; 0, or -1
 * with err set and nothing left behind. */
static int open_backend(gls_glctx *c, gls_backend b, char *err, size_t errlen)
{
    const char *name = is_egl(b) ? "egl" : "osmesa";
    const gls_glctx_ops *ops = ops_of(b);
    if (!ops) {
        snprintf(err, errlen, "%s: not built into this program: %s", name, gls_backend_missing(b));
        return -1;
    }
    void *state = ops->create(b, &c->info, err, errlen);
    if (!state)
        return -1;
    c->ops = ops;
    c->state = state;
    c->name = name;
#define GLS_LOAD(fn)                                                                       \
    {                                                                                      \
        void *v = ops->proc(state, #fn);                                                   \
        if (!v) {                                                                          \
            snprintf(err, errlen, "%s: GL function %s is missing", name, #fn);             \
            goto fail;                                                                     \
        }                                                                                  \
        memcpy(&c->calls.p_##fn, &v, sizeof v);                                            \
    }
    _Static_assert(sizeof(void *) == sizeof(c->calls.p_glClear), "function and object pointers differ in size");
    GLS_GLCALLS(GLS_LOAD)
#undef GLS_LOAD
    gls_glcalls_current = &c->calls;
    const char *r = (const char *)glGetString(GL_RENDERER), *v = (const char *)glGetString(GL_VERSION);
    if (!r || !v) {
        snprintf(err, errlen, "%s: glGetString gives no GL_RENDERER or GL_VERSION: the context is not current", name);
        goto fail;
    }
    snprintf(c->renderer, sizeof c->renderer, "%s", r);
    snprintf(c->version, sizeof c->version, "%s", v);
    return 0;
fail:
    gls_glcalls_current = NULL;
    ops->destroy(state);
    c->ops = NULL;
    c->state = NULL;
    return -1;
}

gls_glctx *gls_glctx_create(gls_backend b, char *err, size_t errlen)
{
    gls_glctx *c = calloc(1, sizeof *c);
    if (!c) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    int rc;
    if (b != GLS_BACKEND_AUTO) {
        rc = open_backend(c, b, err, errlen);
    } else {
        /* EGL first: it reaches a GPU, it is Mesa's maintained way to
         * render headless, and on llvmpipe its images equal OSMesa's. */
        char egl_err[sizeof c->fallback];
        rc = open_backend(c, GLS_BACKEND_EGL, egl_err, sizeof egl_err);
        if (rc) {
            snprintf(c->fallback, sizeof c->fallback, "%s", egl_err);
            char os_err[512];
            rc = open_backend(c, GLS_BACKEND_OSMESA, os_err, sizeof os_err);
            if (rc)
                snprintf(err, errlen, "no GL backend works: %s; %s", egl_err, os_err);
        }
    }
    if (rc) {
        free(c);
        return NULL;
    }
    c->info.backend = c->name;
    c->info.fallback = c->fallback;
    c->info.renderer = c->renderer;
    c->info.version = c->version;
    return c;
}

int gls_glctx_make_current(gls_glctx *c)
{
    if (c->ops->make_current(c->state))
        return -1;
    gls_glcalls_current = &c->calls;
    return 0;
}

void *gls_glctx_proc(gls_glctx *c, const char *name)
{
    return c->ops->proc(c->state, name);
}

const gls_glctx_info *gls_glctx_describe(const gls_glctx *c)
{
    return &c->info;
}

const char *gls_glctx_backend(const gls_glctx *c)
{
    return c->name;
}

void gls_glctx_destroy(gls_glctx *c)
{
    if (!c)
        return;
    if (gls_glcalls_current == &c->calls)
        gls_glcalls_current = NULL;
    c->ops->destroy(c->state);
    free(c);
}
