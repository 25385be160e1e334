/* A GLSL program from a vertex and a fragment shader's source, compiled
 * and linked in the context current now: what the ground-truth pass
 * (gt_pass.c) and the lighting (lighting.c) share. */
#ifndef GLS_GLPROG_H
#define GLS_GLPROG_H

#include <GL/gl.h>
#include <stddef.h>

/* The program, built with gl's entry points (glcalls.h), or 0 with "WHO:
 * the vertex shader does not compile: LOG" (or fragment, or "WHO: the
 * shaders do not link: LOG") in err.  The shaders are deleted (the
 * program keeps them). */
typedef struct gls_glext gls_glext;
GLuint gls_glprog_build(const gls_glext *gl, const char *vs_src, const char *fs_src, const char *who, char *err,
                        size_t errlen);

#endif
