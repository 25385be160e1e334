/* The GL 1.x functions the renderer calls by their plain names (glClear,
 * glDrawArrays, ...), routed through the entry points of the context
 * current on this thread (glctx.h), the way a GL loader (glad, GLEW) does
 * it.  Include it after <GL/gl.h> and <GL/glext.h>, in the files that
 * call GL.
 *
 * Why not link them: with two backends in one program, a plain glClear
 * binds to whichever library exports it first.  libOSMesa exports every
 * GL function and dispatches through Mesa's glapi; a Mesa EGL context
 * happens to set that too, an NVIDIA EGL context does not, and the
 * calls would go nowhere.  Through the backend's own lookup
 * (OSMesaGetProcAddress, eglGetProcAddress) each call reaches the context
 * that is current, and the program links no GL library at all
 * (tests/e2e/build_backends.sh checks that it imports no gl* symbol).
 *
 * A function missing here links against libOSMesa in a build that has
 * it and fails to link in one that has EGL alone: add it to both lists
 * below.  Functions beyond GL 1.1 are in GLS_GLEXT, further down. */
#ifndef GLS_GLCALLS_H
#define GLS_GLCALLS_H

#include <GL/gl.h>
#include <GL/glext.h>
#include <stddef.h>
#include "glctx.h"

#define GLS_GLCALLS(X)                                                                                  \
    X(glAlphaFunc) X(glBindTexture) X(glClear) X(glClearColor) X(glClearDepth) X(glColor4ub) X(glColorMask) \
    X(glColorPointer) X(glDeleteTextures) X(glDepthFunc) X(glDepthMask) X(glDisable) X(glDisableClientState) X(glDrawArrays) X(glDrawBuffer)   \
    X(glEnable) X(glEnableClientState) X(glFinish) X(glFlush) X(glGenTextures) X(glGetError)            \
    X(glGetFloatv) X(glGetIntegerv) X(glGetString) X(glLoadMatrixf) X(glMatrixMode) X(glNormalPointer) X(glPixelStorei)    \
    X(glReadBuffer) X(glReadPixels) X(glScissor) X(glTexCoord2f) X(glTexCoordPointer) X(glTexEnvi)      \
    X(glTexImage2D) X(glTexParameterf) X(glTexParameteri) X(glVertexPointer) X(glViewport)

/* One pointer per function, typed from its prototype in <GL/gl.h>
 * (__typeof__, which gcc and clang have: GL 1.x has no PFN typedefs). */
typedef struct {
#define GLS_GLCALL_MEMBER(name) __typeof__(&name) p_##name;
    GLS_GLCALLS(GLS_GLCALL_MEMBER)
#undef GLS_GLCALL_MEMBER
} gls_glcalls;

/* The table of the context current on this thread (set by
 * gls_glctx_make_current), NULL before any. */
extern _Thread_local const gls_glcalls *gls_glcalls_current;

#define glAlphaFunc (gls_glcalls_current->p_glAlphaFunc)
#define glBindTexture (gls_glcalls_current->p_glBindTexture)
#define glClear (gls_glcalls_current->p_glClear)
#define glClearColor (gls_glcalls_current->p_glClearColor)
#define glClearDepth (gls_glcalls_current->p_glClearDepth)
#define glColor4ub (gls_glcalls_current->p_glColor4ub)
#define glColorMask (gls_glcalls_current->p_glColorMask)
#define glColorPointer (gls_glcalls_current->p_glColorPointer)
#define glDeleteTextures (gls_glcalls_current->p_glDeleteTextures)
#define glDepthFunc (gls_glcalls_current->p_glDepthFunc)
#define glDepthMask (gls_glcalls_current->p_glDepthMask)
#define glDisable (gls_glcalls_current->p_glDisable)
#define glDisableClientState (gls_glcalls_current->p_glDisableClientState)
#define glDrawArrays (gls_glcalls_current->p_glDrawArrays)
#define glDrawBuffer (gls_glcalls_current->p_glDrawBuffer)
#define glEnable (gls_glcalls_current->p_glEnable)
#define glEnableClientState (gls_glcalls_current->p_glEnableClientState)
#define glFinish (gls_glcalls_current->p_glFinish)
#define glFlush (gls_glcalls_current->p_glFlush)
#define glGenTextures (gls_glcalls_current->p_glGenTextures)
#define glGetError (gls_glcalls_current->p_glGetError)
#define glGetFloatv (gls_glcalls_current->p_glGetFloatv)
#define glGetIntegerv (gls_glcalls_current->p_glGetIntegerv)
#define glGetString (gls_glcalls_current->p_glGetString)
#define glLoadMatrixf (gls_glcalls_current->p_glLoadMatrixf)
#define glMatrixMode (gls_glcalls_current->p_glMatrixMode)
#define glNormalPointer (gls_glcalls_current->p_glNormalPointer)
#define glPixelStorei (gls_glcalls_current->p_glPixelStorei)
#define glReadBuffer (gls_glcalls_current->p_glReadBuffer)
#define glReadPixels (gls_glcalls_current->p_glReadPixels)
#define glScissor (gls_glcalls_current->p_glScissor)
#define glTexCoord2f (gls_glcalls_current->p_glTexCoord2f)
#define glTexCoordPointer (gls_glcalls_current->p_glTexCoordPointer)
#define glTexEnvi (gls_glcalls_current->p_glTexEnvi)
#define glTexImage2D (gls_glcalls_current->p_glTexImage2D)
#define glTexParameterf (gls_glcalls_current->p_glTexParameterf)
#define glTexParameteri (gls_glcalls_current->p_glTexParameteri)
#define glVertexPointer (gls_glcalls_current->p_glVertexPointer)
#define glViewport (gls_glcalls_current->p_glViewport)

/* GL entry points beyond GL 1.1, by their glext.h PFN types: the renderer
 * loads them once from its context (gls_glext_load, when it is created)
 * and everything that draws with it calls them through that table:
 * render.c, the ground-truth pass (gt_pass.c, through gls_renderer_gl),
 * the lighting and the shadow maps (lighting.c, shadows.c) and the shader
 * programs they build (glprog.c).  One list, so that a function is named
 * and loaded in one place. */
#define GLS_GLEXT(X)                                                      \
    X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                        \
    X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                  \
    X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                        \
    X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                      \
    X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                \
    X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                      \
    X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)                \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)        \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)          \
    X(PFNGLCLIPCONTROLPROC, glClipControl)                                \
    X(PFNGLGENBUFFERSPROC, glGenBuffers)                                  \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                            \
    X(PFNGLBINDBUFFERPROC, glBindBuffer)                                  \
    X(PFNGLBUFFERDATAPROC, glBufferData)                                  \
    X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                          \
    X(PFNGLGETSTRINGIPROC, glGetStringi)                                  \
    X(PFNGLCLIENTACTIVETEXTUREARBPROC, glClientActiveTexture) /* GL 1.3 */ \
    X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                            \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                            \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                                  \
    X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                  \
    X(PFNGLUNIFORM1IPROC, glUniform1i)                                    \
    X(PFNGLUNIFORM1UIPROC, glUniform1ui)                                  \
    X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                      \
    X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                                \
    X(PFNGLCLEARBUFFERUIVPROC, glClearBufferuiv)                          \
    X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                            \
    X(PFNGLTEXBUFFERPROC, glTexBuffer)                                    \
    X(PFNGLUNIFORM3FPROC, glUniform3f)                                    \
    X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                  \
    X(PFNGLUNIFORM1IVPROC, glUniform1iv)                                  \
    X(PFNGLUNIFORM1FVPROC, glUniform1fv)                                  \
    X(PFNGLUNIFORM1FPROC, glUniform1f)                                    \
    X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                      \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)              \
    X(PFNGLCREATESHADERPROC, glCreateShader)                              \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                              \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                            \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                      \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                              \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                            \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                              \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                              \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                    \
    X(PFNGLGENQUERIESPROC, glGenQueries)                                  \
    X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                            \
    X(PFNGLBEGINQUERYPROC, glBeginQuery)                                  \
    X(PFNGLENDQUERYPROC, glEndQuery)                                      \
    X(PFNGLGETQUERYOBJECTUIVPROC, glGetQueryObjectuiv)

typedef struct gls_glext {
#define GLS_GLEXT_MEMBER(type, name) type name;
    GLS_GLEXT(GLS_GLEXT_MEMBER)
#undef GLS_GLEXT_MEMBER
} gls_glext;

/* Fill t from ctx's backend (glcalls.c).  0, or -1 with "BACKEND: GL
 * function NAME is missing" in err. */
int gls_glext_load(gls_glctx *ctx, gls_glext *t, char *err, size_t errlen);

#endif
