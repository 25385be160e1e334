/* glprog.h: compile two shaders and link them. */
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdint.h>
#include <stdio.h>
#include "glprog.h"

#define PROG_GLFUNCS(X)                                             \
    X(PFNGLCREATESHADERPROC, glCreateShader)                        \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                        \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                      \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                          \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                        \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                      \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                        \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                          \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                        \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)              \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)

typedef struct {
#define PROG_X_FN(type, name) type name;
    PROG_GLFUNCS(PROG_X_FN)
#undef PROG_X_FN
} prog_fns;

static GLuint compile(const prog_fns *f, GLenum type, const char *src, const char *who, const char *what, char *err,
                      size_t errlen)
{
    GLuint sh = f->glCreateShader(type);
    f->glShaderSource(sh, 1, &src, NULL);
    f->glCompileShader(sh);
    GLint ok = 0;
    f->glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        f->glGetShaderInfoLog(sh, sizeof log, NULL, log);
        snprintf(err, errlen, "%s: the %s shader does not compile: %s", who, what, log);
        f->glDeleteShader(sh);
        return 0;
    }
    return sh;
}

GLuint gls_glprog_build(gls_glctx *ctx, const char *vs_src, const char *fs_src, const char *who, char *err,
                        size_t errlen)
{
    prog_fns f;
#define PROG_X_LOAD(type, name)                                                                    \
    f.name = (type)(uintptr_t)gls_glctx_proc(ctx, #name);                                          \
    if (!f.name) {                                                                                 \
        snprintf(err, errlen, "%s: %s: GL function %s is missing", who, gls_glctx_backend(ctx), #name); \
        return 0;                                                                                  \
    }
    PROG_GLFUNCS(PROG_X_LOAD)
#undef PROG_X_LOAD
    GLuint prog = 0;
    GLuint vs = compile(&f, GL_VERTEX_SHADER, vs_src, who, "vertex", err, errlen);
    GLuint fs = vs ? compile(&f, GL_FRAGMENT_SHADER, fs_src, who, "fragment", err, errlen) : 0;
    if (fs) {
        prog = f.glCreateProgram();
        f.glAttachShader(prog, vs);
        f.glAttachShader(prog, fs);
        f.glLinkProgram(prog);
        GLint ok = 0;
        f.glGetProgramiv(prog, GL_LINK_STATUS, &ok);
        if (!ok) {
            char log[512] = "";
            f.glGetProgramInfoLog(prog, sizeof log, NULL, log);
            snprintf(err, errlen, "%s: the shaders do not link: %s", who, log);
            f.glDeleteProgram(prog);
            prog = 0;
        }
    }
    /* the program keeps them; deleting now frees them with it */
    if (vs)
        f.glDeleteShader(vs);
    if (fs)
        f.glDeleteShader(fs);
    return prog;
}
