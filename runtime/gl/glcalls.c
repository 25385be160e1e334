/* glcalls.h: loading the table of GL entry points beyond GL 1.1. */
#include <stdint.h>
#include <stdio.h>
#include "glcalls.h"

int gls_glext_load(gls_glctx *ctx, gls_glext *t, char *err, size_t errlen)
{
#define GLS_GLEXT_LOAD(type, name)                                                                \
    t->name = (type)(uintptr_t)gls_glctx_proc(ctx, #name);                                        \
    if (!t->name) {                                                                               \
        snprintf(err, errlen, "%s: GL function %s is missing", gls_glctx_backend(ctx), #name);    \
        return -1;                                                                                \
    }
    GLS_GLEXT(GLS_GLEXT_LOAD)
#undef GLS_GLEXT_LOAD
    return 0;
}
