/* What glctx.c asks of a backend (glctx_egl.c, glctx_osmesa.c).  Private
 * to the glctx files; everything else uses glctx.h. */
#ifndef GLS_GLCTX_BACKEND_H
#define GLS_GLCTX_BACKEND_H

#include <stddef.h>
#include "glctx.h"

typedef struct {
    /* Create a context for choice b and make it current; NULL with a
     * one-line reason ("egl: ...") in err.  Sets info->platform and
     * info->device to strings the state owns. */
    void *(*create)(gls_backend b, gls_glctx_info *info, char *err, size_t errlen);
    int (*make_current)(void *state);           /* 0 or -1 */
    void *(*proc)(void *state, const char *name); /* NULL if absent */
    void (*destroy)(void *state);
} gls_glctx_ops;

extern const gls_glctx_ops gls_glctx_egl_ops, gls_glctx_osmesa_ops;

/* A function pointer from a proc lookup as void *, the way dlsym returns
 * one (POSIX guarantees the conversion). */
#define GLS_PROC_AS_VOIDP(p, v)                                                       \
    do {                                                                          \
        _Static_assert(sizeof(p) == sizeof(v), "function and object pointers differ in size"); \
        memcpy(&(v), &(p), sizeof(v));                                            \
    } while (0)

#endif
