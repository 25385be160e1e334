/* The ground-truth pass (gt_pass.h).
 *
 * Why ftransform() and no geometry shader: GLSL guarantees that
 * ftransform() computes the position exactly as fixed-function vertex
 * processing does, so the depth of this pass is the colour pass's depth bit
 * for bit and a pixel's id is the id of the surface the image shows there
 * (tests/unit/test_gt_pass.c checks both).  llvmpipe runs a program with a
 * geometry shader through another vertex path whose depths differ in the
 * last bit at some pixels, so there is none.
 *
 * Why normals from a table, not cross(dFdx(eye), dFdy(eye)): the screen
 * derivatives are differences of points one pixel apart, so the rounding of
 * float eye coordinates (2^-24 of the distance) is divided by the pixel's
 * footprint: about f times 2^-24, 1e-5 at f = 300.  Instead each triangle's
 * unit normal is formed once in double from the scene's exact vertex
 * positions (in its proto's frame) into a texture buffer, looked up with
 * gl_PrimitiveID (the triangle's index in its draw call) plus the chunk's
 * first triangle, and turned into the camera frame by a per-item matrix
 * formed in double: F R cof(W), cof(W) the cofactor matrix of the
 * instance's world transform (normals of scaled and mirrored instances).
 * The error is then float rounding, ~1e-7.  Built on the first pass that
 * asks for normals; ids alone need no table.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glcalls.h"
#include "glprog.h"
#include "gt_pass.h"

typedef struct {
    const gls_glext *gl;     /* the renderer's GL beyond 1.1 (glcalls.h) */
    GLuint prog, fbo, rb[3]; /* ids, normals, depth */
    GLuint nbuf, ntex;       /* per triangle unit normal (proto frame), 0 before any */
    GLint u_id, u_tex, u_alpha_test, u_sampler, u_normals, u_tri0, u_nmat, u_want_normal;
    const gls_camera *cam;   /* of the pass being drawn (for u_nmat) */
    int want_normal;
    uint32_t width, height;  /* of the renderbuffers, 0 before any */
    int alpha_test;          /* the scene's GLS_FEAT_ALPHA_TEST */
} gt_state;

/* Position exactly as fixed function (ftransform), the eye-space position
 * (which side of the surface the camera is on), and what the alpha test
 * needs. */
static const char vs_src[] =
    "#version 330 compatibility\n"
    "out vec3 v_eye;\n"
    "out vec2 v_st;\n"
    "out float v_alpha;\n"
    "void main() {\n"
    "    gl_Position = ftransform();\n"
    "    v_eye = (gl_ModelViewMatrix * gl_Vertex).xyz;\n"
    "    v_st = gl_MultiTexCoord0.st;\n"
    "    v_alpha = gl_Color.a;\n"
    "}\n";

/* u_tex: 0 untextured, 1 GL_REPLACE, 2 GL_MODULATE (the draw key's mode);
 * the fragment's alpha as the texture environment forms it, discarded
 * where glAlphaFunc(GL_GEQUAL, 0.5) would reject it.  The normal: the
 * triangle's (u_normals at u_tri0 + gl_PrimitiveID) by u_nmat into OpenCV
 * camera axes, turned to face the camera (the eye frame is GL's, F =
 * diag(1, -1, -1) from OpenCV's; every point of a plane gives n . p the
 * same sign). */
static const char fs_src[] =
    "#version 330 compatibility\n"
    "in vec3 v_eye;\n"
    "in vec2 v_st;\n"
    "in float v_alpha;\n"
    "uniform uint u_id;\n"
    "uniform int u_tex;\n"
    "uniform int u_alpha_test;\n"
    "uniform int u_want_normal;\n"
    "uniform int u_tri0;\n"
    "uniform mat3 u_nmat;\n"
    "uniform sampler2D u_sampler;\n"
    "uniform samplerBuffer u_normals;\n"
    "layout(location = 0) out uint o_id;\n"
    "layout(location = 1) out vec4 o_normal;\n"
    "void main() {\n"
    "    float a = v_alpha;\n"
    "    if (u_tex != 0) {\n"
    "        float t = texture(u_sampler, v_st).a;\n"
    "        a = u_tex == 1 ? t : t * a;\n"
    "    }\n"
    "    if (u_alpha_test != 0 && !(a >= 0.5)) discard;\n"
    "    o_id = u_id;\n"
    "    vec3 n = vec3(0.0);\n"
    "    if (u_want_normal != 0) {\n"
    "        n = u_nmat * texelFetch(u_normals, u_tri0 + gl_PrimitiveID).xyz;\n"
    "        float l = length(n);\n"
    "        n = l > 0.0 ? n / l : vec3(0.0);\n"
    "        if (dot(n, v_eye * vec3(1.0, -1.0, -1.0)) > 0.0) n = -n;\n"
    "    }\n"
    "    o_normal = vec4(n, 0.0);\n"
    "}\n";

static void gt_free(void *p)
{
    gt_state *g = p;
    if (!g)
        return;
    if (g->prog)
        g->gl->glDeleteProgram(g->prog);
    if (g->ntex)
        glDeleteTextures(1, &g->ntex);
    if (g->nbuf)
        g->gl->glDeleteBuffers(1, &g->nbuf);
    if (g->fbo) {
        g->gl->glDeleteFramebuffers(1, &g->fbo);
        g->gl->glDeleteRenderbuffers(3, g->rb);
    }
    free(g);
}

static gt_state *gt_create(gls_renderer *r, const gls_scene *s, char *err, size_t errlen)
{
    gt_state *g = calloc(1, sizeof *g);
    if (!g) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    g->gl = gls_renderer_gl(r);
    g->prog = gls_glprog_build(g->gl, vs_src, fs_src, "ground truth", err, errlen);
    if (!g->prog) {
        gt_free(g);
        return NULL;
    }
    g->u_id = g->gl->glGetUniformLocation(g->prog, "u_id");
    g->u_tex = g->gl->glGetUniformLocation(g->prog, "u_tex");
    g->u_alpha_test = g->gl->glGetUniformLocation(g->prog, "u_alpha_test");
    g->u_sampler = g->gl->glGetUniformLocation(g->prog, "u_sampler");
    g->u_normals = g->gl->glGetUniformLocation(g->prog, "u_normals");
    g->u_tri0 = g->gl->glGetUniformLocation(g->prog, "u_tri0");
    g->u_nmat = g->gl->glGetUniformLocation(g->prog, "u_nmat");
    g->u_want_normal = g->gl->glGetUniformLocation(g->prog, "u_want_normal");
    g->alpha_test = (s->features & GLS_FEAT_ALPHA_TEST) != 0;
    return g;
}

/* The framebuffer for w x h images (again when the size changes). */
static int gt_size(gt_state *g, uint32_t w, uint32_t h, char *err, size_t errlen)
{
    if (g->fbo && g->width == w && g->height == h)
        return 0;
    if (!g->fbo) {
        g->gl->glGenFramebuffers(1, &g->fbo);
        g->gl->glGenRenderbuffers(3, g->rb);
    }
    static const GLenum fmt[3] = {GL_R32UI, GL_RGBA32F, GL_DEPTH_COMPONENT32F};
    static const GLenum at[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_DEPTH_ATTACHMENT};
    g->gl->glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
    for (int i = 0; i < 3; i++) {
        g->gl->glBindRenderbuffer(GL_RENDERBUFFER, g->rb[i]);
        g->gl->glRenderbufferStorage(GL_RENDERBUFFER, fmt[i], (GLsizei)w, (GLsizei)h);
        g->gl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, at[i], GL_RENDERBUFFER, g->rb[i]);
    }
    static const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    g->gl->glDrawBuffers(2, bufs);
    if (g->gl->glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        while (glGetError() != GL_NO_ERROR)
            ;
        g->width = g->height = 0;
        /* 24 bytes a pixel: id, RGBA float normal, float depth */
        snprintf(err, errlen, "ground truth: cannot allocate a %ux%u framebuffer (%.1f MiB)", w, h,
                 (double)w * h * 24 / 1048576.0);
        return -1;
    }
    g->width = w, g->height = h;
    return 0;
}

/* Before each item's draw: its instance's id and its texture's rule. */
static void gt_item(void *ud, const gls_scene *s, const gls_item *it)
{
    gt_state *g = ud;
    const gls_drawkey *k = &s->chunks[it->chunk].key;
    g->gl->glUniform1ui(g->u_id, it->inst + 1);
    g->gl->glUniform1i(g->u_tex, k->texture == GLS_NONE ? 0 : k->mode == GLS_MODE_REPLACE ? 1 : 2);
    if (!g->want_normal)
        return;
    /* near (re-anchored) items draw copies of the chunk's vertices in
     * the same order, so the chunk's triangles are theirs too */
    g->gl->glUniform1i(g->u_tri0, (GLint)(s->chunks[it->chunk].first / 3));
    const double *W = s->inst[it->inst].world, *R = g->cam->R;
    double cof[9], M[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            cof[3 * i + j] = W[4 * i1 + j1] * W[4 * i2 + j2] - W[4 * i1 + j2] * W[4 * i2 + j1];
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            M[3 * i + j] = R[3 * i] * cof[j] + R[3 * i + 1] * cof[3 + j] + R[3 * i + 2] * cof[6 + j];
    float f[9];
    for (int i = 0; i < 9; i++)
        f[i] = (float)M[i];
    g->gl->glUniformMatrix3fv(g->u_nmat, 1, GL_TRUE, f); /* row-major */
}

/* The table of unit normals, one per triangle of the scene, in its
 * proto's frame, formed in double from the exact positions. */
static int gt_normals(gt_state *g, const gls_scene *s, char *err, size_t errlen)
{
    if (g->ntex)
        return 0;
    size_t ntri = s->nverts / 3;
    GLint max = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max);
    if (ntri > (size_t)max) {
        snprintf(err, errlen, "ground truth: normals of %zu triangles exceed GL's texture buffer limit (%d)", ntri,
                 max);
        return -1;
    }
    float *nf = malloc((ntri ? ntri : 1) * 3 * sizeof *nf);
    if (!nf) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (size_t t = 0; t < ntri; t++) {
        const double *p0 = s->exact + 9 * t, *p1 = p0 + 3, *p2 = p0 + 6;
        double a[3], b[3], n[3];
        for (int i = 0; i < 3; i++)
            a[i] = p1[i] - p0[i], b[i] = p2[i] - p0[i];
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int i = 0; i < 3; i++)
            nf[3 * t + i] = l > 0 ? (float)(n[i] / l) : 0.0f;
    }
    g->gl->glGenBuffers(1, &g->nbuf);
    g->gl->glBindBuffer(GL_TEXTURE_BUFFER, g->nbuf);
    g->gl->glBufferData(GL_TEXTURE_BUFFER, (GLsizeiptr)((ntri ? ntri : 1) * 3 * sizeof *nf), nf, GL_STATIC_DRAW);
    g->gl->glBindBuffer(GL_TEXTURE_BUFFER, 0);
    free(nf);
    glGenTextures(1, &g->ntex);
    g->gl->glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_BUFFER, g->ntex);
    g->gl->glTexBuffer(GL_TEXTURE_BUFFER, GL_RGB32F, g->nbuf);
    g->gl->glActiveTexture(GL_TEXTURE0);
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "ground truth: GL error %#x while uploading %zu triangle normals", e, ntri);
        return -1;
    }
    return 0;
}

int gls_gt_render(gls_renderer *r, const gls_camera *c, uint32_t *inst, float *normal, float *z, char *err,
                  size_t errlen)
{
    return gls_gt_render_rows(r, c, 0, c->height, inst, normal, z, err, errlen);
}

int gls_gt_render_rows(gls_renderer *r, const gls_camera *c, uint32_t y0, uint32_t rows, uint32_t *inst,
                       float *normal, float *z, char *err, size_t errlen)
{
    gt_state *g = gls_renderer_ext(r);
    if (!g) {
        g = gt_create(r, gls_renderer_scene(r), err, errlen);
        if (!g)
            return -1;
        gls_renderer_set_ext(r, g, gt_free);
    }
    uint32_t w = c->width, h = c->height;
    /* what the colour pass set up, restored afterwards */
    GLint fbo = 0, vp[4], scissor = 0, box[4], alpha = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &fbo);
    glGetIntegerv(GL_VIEWPORT, vp);
    glGetIntegerv(GL_SCISSOR_TEST, &scissor);
    glGetIntegerv(GL_SCISSOR_BOX, box);
    glGetIntegerv(GL_ALPHA_TEST, &alpha);
    int rc = gt_size(g, w, h, err, errlen);
    if (rc == 0 && normal)
        rc = gt_normals(g, gls_renderer_scene(r), err, errlen);
    if (rc == 0) {
        static const GLuint id0[4] = {0, 0, 0, 0};
        g->gl->glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
        static const GLfloat n0[4] = {0, 0, 0, 0}, d0 = 0; /* reversed Z: far is 0 */
        int part = y0 > 0 || rows < h;
        if (part) { /* the rows asked for: clears and fragments obey the scissor */
            glEnable(GL_SCISSOR_TEST);
            glScissor(0, (GLint)y0, (GLsizei)w, (GLsizei)rows);
        } else {
            glDisable(GL_SCISSOR_TEST);
        }
        glDisable(GL_ALPHA_TEST); /* the shader discards instead */
        glViewport(0, 0, (GLsizei)w, (GLsizei)h);
        g->gl->glClearBufferuiv(GL_COLOR, 0, id0);
        g->gl->glClearBufferfv(GL_COLOR, 1, n0);
        g->gl->glClearBufferfv(GL_DEPTH, 0, &d0);
        g->gl->glUseProgram(g->prog);
        g->gl->glUniform1i(g->u_sampler, 0);
        g->gl->glUniform1i(g->u_alpha_test, g->alpha_test);
        g->gl->glUniform1i(g->u_normals, 1);
        g->gl->glUniform1i(g->u_want_normal, normal != NULL);
        g->want_normal = normal != NULL;
        g->cam = c;
        if (normal) { /* texture unit 1; the draw keys bind theirs on unit 0 */
            g->gl->glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_BUFFER, g->ntex);
            g->gl->glActiveTexture(GL_TEXTURE0);
        }
        gls_render_hooked(r, c, gt_item, g);
        g->gl->glUseProgram(0);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        size_t at = (size_t)y0 * w; /* rows y0.. at their place */
        if (inst) {
            glReadBuffer(GL_COLOR_ATTACHMENT0);
            glReadPixels(0, (GLint)y0, (GLsizei)w, (GLsizei)rows, GL_RED_INTEGER, GL_UNSIGNED_INT, inst + at);
        }
        if (normal) {
            glReadBuffer(GL_COLOR_ATTACHMENT1);
            glReadPixels(0, (GLint)y0, (GLsizei)w, (GLsizei)rows, GL_RGB, GL_FLOAT, normal + 3 * at);
        }
        if (z)
            gls_render_read_z_rows(r, y0, rows, z); /* from the bound (ground-truth) framebuffer */
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        GLenum e = glGetError();
        if (e != GL_NO_ERROR) {
            snprintf(err, errlen, "ground truth: GL error %#x in the pass", e);
            rc = -1;
        }
    }
    g->gl->glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)fbo);
    glViewport(vp[0], vp[1], vp[2], vp[3]);
    glScissor(box[0], box[1], box[2], box[3]);
    if (scissor)
        glEnable(GL_SCISSOR_TEST);
    else
        glDisable(GL_SCISSOR_TEST);
    if (alpha)
        glEnable(GL_ALPHA_TEST);
    return rc;
}
