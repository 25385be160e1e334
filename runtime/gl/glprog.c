/* glprog.h: compile two shaders and link them. */
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include "glcalls.h"
#include "glprog.h"

static GLuint compile(const gls_glext *f, GLenum type, const char *src, const char *who, const char *what, char *err,
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

GLuint gls_glprog_build(const gls_glext *f, const char *vs_src, const char *fs_src, const char *who, char *err,
                        size_t errlen)
{
    GLuint prog = 0;
    GLuint vs = compile(f, GL_VERTEX_SHADER, vs_src, who, "vertex", err, errlen);
    GLuint fs = vs ? compile(f, GL_FRAGMENT_SHADER, fs_src, who, "fragment", err, errlen) : 0;
    if (fs) {
        prog = f->glCreateProgram();
        f->glAttachShader(prog, vs);
        f->glAttachShader(prog, fs);
        f->glLinkProgram(prog);
        GLint ok = 0;
        f->glGetProgramiv(prog, GL_LINK_STATUS, &ok);
        if (!ok) {
            char log[512] = "";
            f->glGetProgramInfoLog(prog, sizeof log, NULL, log);
            snprintf(err, errlen, "%s: the shaders do not link: %s", who, log);
            f->glDeleteProgram(prog);
            prog = 0;
        }
    }
    /* the program keeps them; deleting now frees them with it */
    if (vs)
        f->glDeleteShader(vs);
    if (fs)
        f->glDeleteShader(fs);
    return prog;
}
