/* EGL backend of glctx.h (spec/backends.md): desktop OpenGL 4.5,
 * compatibility profile, with no surface at all (EGL_KHR_surfaceless_context:
 * the renderer draws into its own FBO).  Two platforms:
 *   device       EGL_EXT_platform_device with EGL_EXT_device_enumeration:
 *                one display per GPU, no window system; how NVIDIA's
 *                driver renders headless.
 *   surfaceless  EGL_MESA_platform_surfaceless: Mesa with no window
 *                system; llvmpipe where there is no GPU.
 * The display and device functions are extensions, so they come through
 * eglGetProcAddress after the client extension string says they exist. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glctx_backend.h"

typedef struct {
    EGLDisplay dpy;
    EGLContext ctx;
    char device[256];
} egl_state;

/* The extension functions this file uses. */
typedef struct {
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display;
    PFNEGLQUERYDEVICESEXTPROC query_devices;
    PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string;
} egl_ext;

static const char *egl_error_name(EGLint e)
{
    switch (e) {
#define GLS_EGL_ERR(x) case x: return #x;
        GLS_EGL_ERR(EGL_SUCCESS)
        GLS_EGL_ERR(EGL_NOT_INITIALIZED)
        GLS_EGL_ERR(EGL_BAD_ACCESS)
        GLS_EGL_ERR(EGL_BAD_ALLOC)
        GLS_EGL_ERR(EGL_BAD_ATTRIBUTE)
        GLS_EGL_ERR(EGL_BAD_CONFIG)
        GLS_EGL_ERR(EGL_BAD_CONTEXT)
        GLS_EGL_ERR(EGL_BAD_CURRENT_SURFACE)
        GLS_EGL_ERR(EGL_BAD_DISPLAY)
        GLS_EGL_ERR(EGL_BAD_MATCH)
        GLS_EGL_ERR(EGL_BAD_NATIVE_PIXMAP)
        GLS_EGL_ERR(EGL_BAD_NATIVE_WINDOW)
        GLS_EGL_ERR(EGL_BAD_PARAMETER)
        GLS_EGL_ERR(EGL_BAD_SURFACE)
        GLS_EGL_ERR(EGL_CONTEXT_LOST)
        GLS_EGL_ERR(EGL_BAD_DEVICE_EXT)
#undef GLS_EGL_ERR
    default:
        return "an unknown EGL error";
    }
}

/* Is name a whole word of the space-separated extension list? */
static int has_ext(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; p && (p = strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == 0))
            return 1;
    return 0;
}

static void *egl_proc(void *state, const char *name)
{
    (void)state;
    __eglMustCastToProperFunctionPointerType p = eglGetProcAddress(name);
    void *v;
    GLS_PROC_AS_VOIDP(p, v);
    return v;
}

/* A display's EGL_VENDOR, never NULL. */
static const char *vendor(EGLDisplay dpy)
{
    const char *v = eglQueryString(dpy, EGL_VENDOR);
    return v ? v : "unknown";
}

/* An EGL extension function by name, as its own pointer type. */
#define EGL_LOAD(dst, name)                                                   \
    do {                                                                      \
        void *v_ = egl_proc(NULL, name);                                      \
        memcpy(&(dst), &v_, sizeof v_);                                       \
    } while (0)

static int egl_make_current(void *state)
{
    egl_state *s = state;
    return eglMakeCurrent(s->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, s->ctx) ? 0 : -1;
}

/* The context is destroyed and the thread's EGL state released; the
 * display stays initialised.  EGL displays are one per process and
 * platform, shared with whatever else in the process uses EGL (another
 * library, a second player), and eglTerminate has no reference count: it
 * would take their contexts too. */
static void egl_destroy(void *state)
{
    egl_state *s = state;
    if (!s)
        return;
    if (s->ctx != EGL_NO_CONTEXT) {
        if (eglGetCurrentContext() == s->ctx)
            eglMakeCurrent(s->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(s->dpy, s->ctx);
    }
    eglReleaseThread();
    free(s);
}

/* "egl: PLATFORM: STEP failed: EGL_ERROR" */
static void *fail(egl_state *s, char *err, size_t errlen, const char *platform, const char *step)
{
    snprintf(err, errlen, "egl: %s: %s failed: %s", platform, step, egl_error_name(eglGetError()));
    egl_destroy(s);
    return NULL;
}

/* A GL 4.5 compatibility context on display dpy, current with no
 * surface; NULL with err set. */
static egl_state *open_display(EGLDisplay dpy, const char *client, const char *platform, char *err, size_t errlen)
{
    egl_state *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "egl: out of memory");
        return NULL;
    }
    s->dpy = dpy;
    s->ctx = EGL_NO_CONTEXT;
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY)
        return fail(s, err, errlen, platform, "eglGetPlatformDisplayEXT");
    if (!eglInitialize(dpy, &major, &minor))
        return fail(s, err, errlen, platform, "eglInitialize");
    const char *ext = eglQueryString(dpy, EGL_EXTENSIONS);
    int egl15 = major > 1 || (major == 1 && minor >= 5);
    /* What the steps below rely on, said before they fail obscurely. */
    const char *lacks = !has_ext(ext, "EGL_KHR_surfaceless_context") ? "EGL_KHR_surfaceless_context"
                        : !egl15 && !has_ext(ext, "EGL_KHR_create_context") ? "EGL_KHR_create_context"
                        /* eglGetProcAddress must return core GL 1.x functions (glcalls.h) */
                        : !egl15 && !has_ext(ext, "EGL_KHR_get_all_proc_addresses") &&
                                  !has_ext(client, "EGL_KHR_client_get_all_proc_addresses")
                            ? "EGL_KHR_get_all_proc_addresses"
                            : NULL;
    if (lacks) {
        snprintf(err, errlen, "egl: %s: the display (EGL %d.%d, %s) lacks %s", platform, major, minor, vendor(dpy),
                 lacks);
        egl_destroy(s);
        return NULL;
    }
    if (!eglBindAPI(EGL_OPENGL_API))
        return fail(s, err, errlen, platform, "eglBindAPI(EGL_OPENGL_API)");
    EGLConfig cfg = EGL_NO_CONFIG_KHR;
    if (!has_ext(ext, "EGL_KHR_no_config_context")) {
        /* no surface will ever be made: any config that renders GL */
        static const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
        EGLint n = 0;
        if (!eglChooseConfig(dpy, want, &cfg, 1, &n))
            return fail(s, err, errlen, platform, "eglChooseConfig");
        if (n < 1) {
            snprintf(err, errlen, "egl: %s: eglChooseConfig found no config that renders OpenGL", platform);
            egl_destroy(s);
            return NULL;
        }
    }
    static const EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION, 4,
        EGL_CONTEXT_MINOR_VERSION, 5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
        EGL_NONE,
    };
    s->ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, attribs);
    if (s->ctx == EGL_NO_CONTEXT)
        return fail(s, err, errlen, platform, "eglCreateContext (OpenGL 4.5 compatibility profile)");
    if (egl_make_current(s))
        return fail(s, err, errlen, platform, "eglMakeCurrent (no surface)");
    return s;
}

/* Mesa's name for the driver behind a display (EGL_MESA_query_driver),
 * or NULL. */
static const char *driver_name(EGLDisplay dpy)
{
    if (!has_ext(eglQueryString(dpy, EGL_EXTENSIONS), "EGL_MESA_query_driver"))
        return NULL;
    const char *(*name)(EGLDisplay) = NULL;
    EGL_LOAD(name, "eglGetDisplayDriverName");
    return name ? name(dpy) : NULL;
}

static int is_software(const egl_ext *x, EGLDeviceEXT d)
{
    return has_ext(x->query_device_string(d, EGL_EXTENSIONS), "EGL_MESA_device_software");
}

/* The device platform: the first device that gives a context.  GPUs
 * only, unless software is set (--backend egl-device): then Mesa's
 * software device too, after every GPU.  NULL with err set. */
static egl_state *open_device(const egl_ext *x, const char *client, int software, char *err, size_t errlen)
{
    static const char platform[] = "device platform";
    if (!has_ext(client, "EGL_EXT_platform_device") || !x->query_devices || !x->query_device_string) {
        snprintf(err, errlen, "egl: %s: the EGL library lacks EGL_EXT_platform_device or "
                              "EGL_EXT_device_enumeration", platform);
        return NULL;
    }
    EGLint n = 0;
    if (!x->query_devices(0, NULL, &n)) {
        snprintf(err, errlen, "egl: %s: eglQueryDevicesEXT failed: %s", platform, egl_error_name(eglGetError()));
        return NULL;
    }
    EGLDeviceEXT *devs = calloc(n > 0 ? (size_t)n : 1, sizeof *devs);
    if (!devs) {
        snprintf(err, errlen, "egl: out of memory");
        return NULL;
    }
    if (n > 0 && !x->query_devices(n, devs, &n)) {
        snprintf(err, errlen, "egl: %s: eglQueryDevicesEXT failed: %s", platform, egl_error_name(eglGetError()));
        free(devs);
        return NULL;
    }
    egl_state *s = NULL;
    if (n == 0)
        snprintf(err, errlen, "egl: %s: eglQueryDevicesEXT finds no device", platform);
    else
        snprintf(err, errlen, "egl: %s: no GPU among the %d device%s (Mesa's software device is for --backend "
                              "egl-device)", platform, (int)n, n == 1 ? "" : "s");
    for (int pass = 0; pass < 1 + software && !s; pass++)
        for (EGLint i = 0; i < n && !s; i++) {
            int sw = is_software(x, devs[i]);
            if (sw != pass)
                continue; /* GPUs in the first pass, software in the second */
            char where[64];
            snprintf(where, sizeof where, "%s, device %d of %d", platform, (int)i, (int)n);
            EGLDisplay dpy = x->get_platform_display(EGL_PLATFORM_DEVICE_EXT, devs[i], NULL);
            s = open_display(dpy, client, where, err, errlen);
            if (!s)
                continue;
            const char *file = has_ext(x->query_device_string(devs[i], EGL_EXTENSIONS), "EGL_EXT_device_drm")
                                   ? x->query_device_string(devs[i], EGL_DRM_DEVICE_FILE_EXT)
                                   : NULL;
            const char *drv = driver_name(dpy);
            snprintf(s->device, sizeof s->device, "device %d of %d: %s%s%s%s, EGL vendor %s", (int)i, (int)n,
                     sw ? "software" : file ? file : "GPU", drv ? " (driver " : "", drv ? drv : "", drv ? ")" : "",
                     vendor(dpy));
        }
    free(devs);
    return s;
}

static egl_state *open_surfaceless(const egl_ext *x, const char *client, char *err, size_t errlen)
{
    static const char platform[] = "surfaceless platform";
    if (!has_ext(client, "EGL_MESA_platform_surfaceless")) {
        snprintf(err, errlen, "egl: %s: the EGL library lacks EGL_MESA_platform_surfaceless", platform);
        return NULL;
    }
    EGLDisplay dpy = x->get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    egl_state *s = open_display(dpy, client, platform, err, errlen);
    if (s) {
        const char *drv = driver_name(dpy);
        snprintf(s->device, sizeof s->device, "%s%s%sEGL vendor %s", drv ? "driver " : "", drv ? drv : "",
                 drv ? ", " : "", vendor(dpy));
    }
    return s;
}

static void *egl_create(gls_backend b, gls_glctx_info *info, char *err, size_t errlen)
{
    /* Client extensions (EGL 1.5, or EGL_EXT_client_extensions): NULL
     * from an older EGL, which has no platform displays either. */
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client || !has_ext(client, "EGL_EXT_platform_base")) {
        snprintf(err, errlen, "egl: the EGL library lacks EGL_EXT_platform_base (client extensions: %s)",
                 client && client[0] ? client : "none");
        return NULL;
    }
    egl_ext x;
    EGL_LOAD(x.get_platform_display, "eglGetPlatformDisplayEXT");
    EGL_LOAD(x.query_devices, "eglQueryDevicesEXT");
    EGL_LOAD(x.query_device_string, "eglQueryDeviceStringEXT");
    if (!x.get_platform_display) {
        snprintf(err, errlen, "egl: eglGetProcAddress gives no eglGetPlatformDisplayEXT");
        return NULL;
    }
    egl_state *s = NULL;
    if (b != GLS_BACKEND_EGL_SURFACELESS) {
        s = open_device(&x, client, b == GLS_BACKEND_EGL_DEVICE, err, errlen);
        info->platform = "device";
    }
    if (!s && b != GLS_BACKEND_EGL_DEVICE) {
        /* no GPU gave a context (or none was asked for): Mesa */
        s = open_surfaceless(&x, client, err, errlen);
        info->platform = "surfaceless";
    }
    if (s)
        info->device = s->device;
    return s;
}

const gls_glctx_ops gls_glctx_egl_ops = {egl_create, egl_make_current, egl_proc, egl_destroy};
