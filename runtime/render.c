/* The GL renderer (render.h).
 *
 * Fixed-function GL (compatibility profile) rather than shaders: the
 * bundle's drawing model is exactly the fixed-function one (per-vertex
 * colour, texture env REPLACE/MODULATE, alpha test), llvmpipe compiles the
 * fixed-function state into the same LLVM code a GLSL shader would give,
 * and there is no shader source to embed, compile and diagnose.  Matrices
 * go in with glLoadMatrixf after being formed in double on the CPU.
 *
 * Over 500 lines because it is the one file that speaks GL (the context
 * aside, glctx_*.c): textures, framebuffers, state per draw key, the
 * near-chunk re-anchoring and the read-backs all share the renderer's GL
 * objects, and keeping GL here keeps the rest of the runtime free of it.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glcalls.h"
#include "render.h"
#include "units.h"

#ifndef GL_TEXTURE_MAX_ANISOTROPY
#define GL_TEXTURE_MAX_ANISOTROPY 0x84FE
#define GL_MAX_TEXTURE_MAX_ANISOTROPY 0x84FF
#endif

/* GL entry points beyond GL 1.1 come through the backend's proc lookup,
 * so the renderer does not depend on what a library happens to export. */
#define GLS_GLFUNCS(X)                                                    \
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
    X(PFNGLGETSTRINGIPROC, glGetStringi)

struct gls_renderer {
#define GLS_X_FN(type, name) type name;
    GLS_GLFUNCS(GLS_X_FN)
#undef GLS_X_FN
    const gls_scene *scene;
    GLuint vbo, fbo, rb_color, rb_depth;
    GLuint near_vbo;       /* per-pass vertices of re-anchored chunks */
    uint8_t *near_buf;
    size_t near_cap;       /* vertices */
    uint32_t *near_list;   /* chunk indices drawn from near_vbo */
    GLuint *tex;           /* per bundle texture: GL name or 0 if unused */
    uint32_t ntex;
    uint32_t width, height; /* one image (tile) */
    uint32_t kx, ky;        /* mosaic: kx x ky tiles in the framebuffer */
    int aniso;
    float zc_a, zc_b;      /* projection [2][2], [2][3] as GL got them */
    uint32_t nnear;        /* near chunks prepared by gls_render_prepare */
    float *dbuf;           /* depth read-back scratch */
    char gl_name[128], gl_version[128];
};

void gls_mat_to_gl(const double rm[16], float cm[16])
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            cm[4 * j + i] = (float)rm[4 * i + j];
}

static int has_extension(gls_renderer *r, const char *name)
{
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; i++) {
        const char *e = (const char *)r->glGetStringi(GL_EXTENSIONS, (GLuint)i);
        if (e && strcmp(e, name) == 0)
            return 1;
    }
    return 0;
}

/* Attribute pointers into the currently bound GL_ARRAY_BUFFER. */
static void set_pointers(const gls_scene *s)
{
    GLsizei stride = (GLsizei)s->stride;
    glVertexPointer(3, GL_FLOAT, stride, (const void *)0);
    if (s->has_color)
        glColorPointer(4, GL_UNSIGNED_BYTE, stride, (const void *)(uintptr_t)s->color_offset);
    if (s->has_texcoord)
        glTexCoordPointer(2, GL_FLOAT, stride, (const void *)(uintptr_t)s->texcoord_offset);
}

static int upload_textures(gls_renderer *r, const gls_bundle *b, char *err, size_t errlen)
{
    const gls_scene *s = r->scene;
    r->ntex = b->ntextures;
    r->tex = calloc(b->ntextures ? b->ntextures : 1, sizeof *r->tex);
    if (!r->tex) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    if (!(s->features & GLS_FEAT_TEXTURES))
        return 0;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (uint32_t i = 0; i < s->nchunks; i++) {
        uint32_t t = s->chunks[i].key.texture;
        if (t == GLS_NONE || r->tex[t])
            continue;
        const gls_texture *tx = &b->textures[t];
        glGenTextures(1, &r->tex[t]);
        glBindTexture(GL_TEXTURE_2D, r->tex[t]);
        /* The bundle stores the image top row first; the language puts
         * t = 0 at the image's bottom edge (OpenGL's convention, which the
         * original system got by uploading bottom-up TGA files as they
         * are).  GL's first row is t = 0, so upload bottom row first. */
        size_t row = (size_t)tx->width * 4;
        uint8_t *flipped = malloc(row * tx->height);
        if (!flipped) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        for (uint32_t y = 0; y < tx->height; y++)
            memcpy(flipped + row * y, tx->rgba + row * (tx->height - 1 - y), row);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, (GLsizei)tx->width, (GLsizei)tx->height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, flipped);
        free(flipped);
        r->glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        /* anisotropic filtering stays off (GL's default, 1) unless asked
         * for: gls_renderer_set_anisotropy */
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "GL error %#x while uploading textures", e);
        return -1;
    }
    return 0;
}

gls_renderer *gls_renderer_create(gls_glctx *ctx, const gls_bundle *b, const gls_scene *scene, char *err,
                                  size_t errlen)
{
    gls_renderer *r = calloc(1, sizeof *r);
    if (!r) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    r->scene = scene;
#define GLS_X_LOAD(type, name)                                                    \
    r->name = (type)(uintptr_t)gls_glctx_proc(ctx, #name);                        \
    if (!r->name) {                                                               \
        snprintf(err, errlen, "%s: GL function %s is missing", gls_glctx_backend(ctx), #name); \
        free(r);                                                                  \
        return NULL;                                                              \
    }
    GLS_GLFUNCS(GLS_X_LOAD)
#undef GLS_X_LOAD
    snprintf(r->gl_name, sizeof r->gl_name, "%s", (const char *)glGetString(GL_RENDERER));
    snprintf(r->gl_version, sizeof r->gl_version, "%s", (const char *)glGetString(GL_VERSION));
    r->aniso = has_extension(r, "GL_EXT_texture_filter_anisotropic") ||
               has_extension(r, "GL_ARB_texture_filter_anisotropic");

    /* reversed Z: z_ndc in [0, 1], 1 at near; see spec/camera.md */
    r->glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glClearDepth(0.0);
    glDepthFunc(GL_GREATER);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_DITHER);
    glDisable(GL_CULL_FACE);
    glDisable(GL_LIGHTING);
    glClearColor(0, 0, 0, 1);
    if (scene->features & GLS_FEAT_ALPHA_TEST) {
        glEnable(GL_ALPHA_TEST);
        glAlphaFunc(GL_GEQUAL, 0.5f);
    }

    r->glGenBuffers(1, &r->vbo);
    r->glBindBuffer(GL_ARRAY_BUFFER, r->vbo);
    r->glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)scene->nverts * scene->stride), scene->verts,
                    GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    if (scene->has_color)
        glEnableClientState(GL_COLOR_ARRAY);
    if (scene->has_texcoord)
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    else
        glTexCoord2f(0, 0); /* texcoords absent: (0, 0) */
    set_pointers(scene);
    r->glGenBuffers(1, &r->near_vbo);
    r->near_list = malloc((scene->nchunks ? scene->nchunks : 1) * sizeof *r->near_list);
    if (!r->near_list) {
        snprintf(err, errlen, "out of memory");
        gls_renderer_destroy(r);
        return NULL;
    }
    if (upload_textures(r, b, err, errlen)) {
        gls_renderer_destroy(r);
        return NULL;
    }
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "GL error %#x while setting up the renderer", e);
        gls_renderer_destroy(r);
        return NULL;
    }
    return r;
}

int gls_renderer_set_size(gls_renderer *r, uint32_t w, uint32_t h, char *err, size_t errlen)
{
    return gls_renderer_set_mosaic(r, w, h, 1, 1, err, errlen);
}

uint32_t gls_renderer_max_dim(const gls_renderer *r)
{
    (void)r;
    GLint maxrb = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxrb);
    return maxrb > 0 ? (uint32_t)maxrb : 0;
}

uint64_t gls_renderer_bytes(uint32_t w, uint32_t h, uint32_t kx, uint32_t ky)
{
    /* RGBA8 colour and float depth per framebuffer pixel, and the float
     * depth read-back of one image */
    return (uint64_t)w * kx * h * ky * 8 + (uint64_t)w * h * 4;
}

/* The framebuffer could not be had: say which, and how much it needs.
 * The renderer is left without a valid size, so the next call
 * allocates again. */
static int alloc_failed(gls_renderer *r, uint32_t w, uint32_t h, uint32_t kx, uint32_t ky, char *err, size_t errlen)
{
    char need[32], tiles[96] = "";
    gls_fmt_bytes(need, sizeof need, gls_renderer_bytes(w, h, kx, ky));
    if (kx * ky > 1)
        snprintf(tiles, sizeof tiles, ", %ux%u tiles of %ux%u images", kx, ky, w, h);
    snprintf(err, errlen, "cannot allocate a %ux%u framebuffer%s (%s of memory)", w * kx, h * ky, tiles, need);
    r->kx = r->ky = 0;
    return -1;
}

int gls_renderer_set_mosaic(gls_renderer *r, uint32_t w, uint32_t h, uint32_t kx, uint32_t ky, char *err,
                            size_t errlen)
{
    if (r->fbo && r->width == w && r->height == h && r->kx == kx && r->ky == ky) {
        /* same framebuffer; a fine-framebuffer pass may have left its
         * viewport and scissor */
        glViewport(0, 0, (GLsizei)w, (GLsizei)h);
        if (kx * ky > 1)
            glEnable(GL_SCISSOR_TEST);
        else
            glDisable(GL_SCISSOR_TEST);
        return 0;
    }
    uint32_t maxrb = gls_renderer_max_dim(r);
    if (kx < 1 || ky < 1 || w > maxrb / kx || h > maxrb / ky) {
        snprintf(err, errlen, "image size %ux%u (mosaic %ux%u) exceeds the GL limit %u", w, h, kx, ky, maxrb);
        return -1;
    }
    float *d = realloc(r->dbuf, (size_t)w * h * sizeof *d);
    if (!d)
        return alloc_failed(r, w, h, kx, ky, err, errlen);
    r->dbuf = d;
    if (!r->fbo) {
        r->glGenFramebuffers(1, &r->fbo);
        r->glGenRenderbuffers(1, &r->rb_color);
        r->glGenRenderbuffers(1, &r->rb_depth);
    }
    GLsizei fw = (GLsizei)(w * kx), fh = (GLsizei)(h * ky);
    r->glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    r->glBindRenderbuffer(GL_RENDERBUFFER, r->rb_color);
    r->glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, fw, fh);
    r->glBindRenderbuffer(GL_RENDERBUFFER, r->rb_depth);
    r->glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, fw, fh);
    r->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r->rb_color);
    r->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r->rb_depth);
    GLenum st = r->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (st != GL_FRAMEBUFFER_COMPLETE) {
        /* llvmpipe's renderbuffers are plain memory: incomplete means
         * GL could not allocate them (GL_OUT_OF_MEMORY) */
        while (glGetError() != GL_NO_ERROR)
            ;
        return alloc_failed(r, w, h, kx, ky, err, errlen);
    }
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    /* Tiles of a mosaic must not draw into each other: the clip volume
     * keeps triangles inside their viewport in theory, but rasterisers
     * with a guard band (llvmpipe) rely on a scissor for that. */
    if (kx * ky > 1)
        glEnable(GL_SCISSOR_TEST);
    else
        glDisable(GL_SCISSOR_TEST);
    r->width = w;
    r->height = h;
    r->kx = kx;
    r->ky = ky;
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "GL error %#x while creating a %ux%u framebuffer", e, fw, fh);
        return -1;
    }
    return 0;
}

static void apply_key(gls_renderer *r, const gls_drawkey *k)
{
    if (k->texture == GLS_NONE) {
        glDisable(GL_TEXTURE_2D);
    } else {
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, r->tex[k->texture]);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, k->mode == GLS_MODE_REPLACE ? GL_REPLACE : GL_MODULATE);
    }
    if (!r->scene->has_color)
        glColor4ub(k->rgba[0], k->rgba[1], k->rgba[2], k->rgba[3]);
}

/* Does chunk ch need re-anchoring at the camera centre C?  Its float
 * offsets err by up to 2^-24 * maxoff; every visible vertex is at least
 * max(distance from C to the chunk's box, near) from the camera.  Keep the
 * static offsets only while that error is within 4 * 2^-24 of the
 * distance, i.e. no more than twice the float rounding GL adds anyway. */
static int needs_reanchor(const gls_chunk *ch, const double C[3], double near)
{
    double d2 = 0;
    for (int j = 0; j < 3; j++) {
        double e = C[j] < ch->lo[j] ? ch->lo[j] - C[j] : C[j] > ch->hi[j] ? C[j] - ch->hi[j] : 0;
        d2 += e * e;
    }
    double dist = sqrt(d2);
    if (dist < near)
        dist = near;
    return ch->maxoff > 4 * dist;
}

static void draw_chunk(gls_renderer *r, const gls_camera *c, const gls_chunk *ch, const double anchor[3],
                       uint32_t first, const gls_drawkey **prev)
{
    double MV[16];
    float f[16];
    if (!*prev || memcmp(*prev, &ch->key, sizeof **prev)) {
        apply_key(r, &ch->key);
        *prev = &ch->key;
    }
    gls_camera_modelview(c, anchor, MV);
    gls_mat_to_gl(MV, f);
    glLoadMatrixf(f);
    glDrawArrays(GL_TRIANGLES, (GLint)first, (GLsizei)ch->count);
}

/* Load the projection of jitter (du, dv) and remember its depth terms. */
static void load_projection(gls_renderer *r, const gls_camera *c, double du, double dv)
{
    double P[16];
    float f[16];
    gls_camera_projection(c, du, dv, P);
    gls_mat_to_gl(P, f);
    r->zc_a = f[10]; /* row 2: z_clip = a * ze + b */
    r->zc_b = f[14];
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(f);
    glMatrixMode(GL_MODELVIEW);
}

/* Chunks near the camera: offsets from the camera centre, formed in
 * double, so their float error is relative to their distance.  Uploaded
 * once per camera position; returns how many chunks are in the list. */
static uint32_t prepare_near(gls_renderer *r, const gls_camera *c, const double C[3])
{
    const gls_scene *s = r->scene;
    uint32_t nnear = 0;
    size_t nv = 0;
    for (uint32_t i = 0; i < s->nchunks; i++)
        if (needs_reanchor(&s->chunks[i], C, c->near)) {
            r->near_list[nnear++] = i;
            nv += s->chunks[i].count;
        }
    if (!nnear)
        return 0;
    if (nv > r->near_cap) {
        uint8_t *nb = realloc(r->near_buf, nv * s->stride);
        if (!nb)
            return 0; /* out of memory: those chunks are not drawn */
        r->near_buf = nb;
        r->near_cap = nv;
    }
    size_t at = 0;
    for (uint32_t k = 0; k < nnear; k++) {
        const gls_chunk *ch = &s->chunks[r->near_list[k]];
        memcpy(r->near_buf + at * s->stride, s->verts + (size_t)ch->first * s->stride, (size_t)ch->count * s->stride);
        for (uint32_t v = 0; v < ch->count; v++) {
            const double *p = s->world + 3 * ((size_t)ch->first + v);
            float off[3] = {(float)(p[0] - C[0]), (float)(p[1] - C[1]), (float)(p[2] - C[2])};
            memcpy(r->near_buf + (at + v) * s->stride, off, sizeof off);
        }
        at += ch->count;
    }
    r->glBindBuffer(GL_ARRAY_BUFFER, r->near_vbo);
    r->glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nv * s->stride), r->near_buf, GL_STREAM_DRAW);
    return nnear;
}

/* Draw every chunk (those with vis[i] != 0; NULL: all) with the current
 * projection and viewport. */
static void draw_all(gls_renderer *r, const gls_camera *c, const double C[3], uint32_t nnear, const uint8_t *vis)
{
    const gls_scene *s = r->scene;
    const gls_drawkey *prev = NULL;
    uint32_t k = 0;
    r->glBindBuffer(GL_ARRAY_BUFFER, r->vbo);
    set_pointers(s);
    for (uint32_t i = 0; i < s->nchunks; i++) {
        const gls_chunk *ch = &s->chunks[i];
        if (k < nnear && r->near_list[k] == i) {
            k++;
            continue;
        }
        if (!vis || vis[i])
            draw_chunk(r, c, ch, ch->anchor, ch->first, &prev);
    }
    if (!nnear)
        return;
    r->glBindBuffer(GL_ARRAY_BUFFER, r->near_vbo);
    set_pointers(s);
    size_t at = 0;
    for (k = 0; k < nnear; k++) {
        const gls_chunk *ch = &s->chunks[r->near_list[k]];
        if (!vis || vis[r->near_list[k]])
            draw_chunk(r, c, ch, C, (uint32_t)at, &prev);
        at += ch->count;
    }
}

void gls_renderer_set_background(gls_renderer *r, const float rgb[3])
{
    (void)r; /* state of the current context, which r owns */
    glClearColor(rgb[0], rgb[1], rgb[2], 1);
}

void gls_render_pass(gls_renderer *r, const gls_camera *c, double du, double dv)
{
    gls_render_tiles(r, c, 1, &du, &dv);
}

void gls_render_tiles(gls_renderer *r, const gls_camera *c, uint32_t n, const double *du, const double *dv)
{
    double C[3];
    gls_camera_centre(c, C);
    if (r->kx * r->ky > 1) {
        /* one clear for the whole mosaic */
        glViewport(0, 0, (GLsizei)(r->width * r->kx), (GLsizei)(r->height * r->ky));
        glScissor(0, 0, (GLsizei)(r->width * r->kx), (GLsizei)(r->height * r->ky));
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    uint32_t nnear = prepare_near(r, c, C);
    for (uint32_t t = 0; t < n && t < r->kx * r->ky; t++) {
        if (r->kx * r->ky > 1) {
            GLint x = (GLint)(r->width * (t % r->kx)), y = (GLint)(r->height * (t / r->kx));
            glViewport(x, y, (GLsizei)r->width, (GLsizei)r->height);
            glScissor(x, y, (GLsizei)r->width, (GLsizei)r->height);
        }
        load_projection(r, c, du[t], dv[t]);
        draw_all(r, c, C, nnear, NULL);
    }
}

uint32_t gls_renderer_nchunks(const gls_renderer *r) { return r->scene->nchunks; }

uint32_t gls_render_chunk_bounds(const gls_renderer *r, const gls_camera *c, double (*b)[4])
{
    const gls_scene *s = r->scene;
    for (uint32_t i = 0; i < s->nchunks; i++) {
        const gls_chunk *ch = &s->chunks[i];
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        int nearer = 0, beyond = 0;
        for (int k = 0; k < 8; k++) {
            double P[3] = {k & 1 ? ch->hi[0] : ch->lo[0], k & 2 ? ch->hi[1] : ch->lo[1], k & 4 ? ch->hi[2] : ch->lo[2]};
            double u, v, z = gls_camera_project(c, P, &u, &v);
            if (!(z >= c->near)) {
                nearer++;
                continue;
            }
            beyond += z > c->far;
            lo[0] = fmin(lo[0], u), lo[1] = fmin(lo[1], v);
            hi[0] = fmax(hi[0], u), hi[1] = fmax(hi[1], v);
        }
        if (nearer == 8 || beyond == 8) { /* wholly clipped: nowhere */
            b[i][0] = b[i][1] = INFINITY;
            b[i][2] = b[i][3] = -INFINITY;
        } else if (nearer || !isfinite(lo[0] + lo[1] + hi[0] + hi[1])) { /* crosses the near plane */
            b[i][0] = b[i][1] = -INFINITY;
            b[i][2] = b[i][3] = INFINITY;
        } else {
            /* corners in front of the camera: the box projects inside their
             * convex hull; a pixel of margin for rounding */
            b[i][0] = lo[0] - 1, b[i][1] = lo[1] - 1;
            b[i][2] = hi[0] + 1, b[i][3] = hi[1] + 1;
        }
    }
    return s->nchunks;
}

void gls_render_prepare(gls_renderer *r, const gls_camera *c)
{
    double C[3];
    gls_camera_centre(c, C);
    r->nnear = prepare_near(r, c, C);
}

void gls_render_mapped(gls_renderer *r, const gls_camera *c, const double m[6], uint32_t vw, uint32_t vh,
                       const uint32_t sc[4], const uint8_t *vis)
{
    double C[3], P[16];
    float f[16];
    gls_camera_centre(c, C);
    glViewport(0, 0, (GLsizei)vw, (GLsizei)vh);
    glEnable(GL_SCISSOR_TEST);
    glScissor((GLint)sc[0], (GLint)sc[1], (GLsizei)sc[2], (GLsizei)sc[3]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gls_camera_projection_map(c, m, vw, vh, P);
    gls_mat_to_gl(P, f);
    r->zc_a = f[10];
    r->zc_b = f[14];
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(f);
    glMatrixMode(GL_MODELVIEW);
    draw_all(r, c, C, r->nnear, vis);
}

void gls_render_read_rect(gls_renderer *r, uint32_t width, const uint32_t sc[4], uint8_t *rgba)
{
    (void)r;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, (GLint)width);
    glReadPixels((GLint)sc[0], (GLint)sc[1], (GLsizei)sc[2], (GLsizei)sc[3], GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba + ((size_t)sc[1] * width + sc[0]) * 4);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
}

void gls_render_flush(gls_renderer *r)
{
    (void)r;
    glFlush();
}

void gls_render_finish(gls_renderer *r)
{
    (void)r;
    glFinish();
}

void gls_render_read_mosaic(gls_renderer *r, uint32_t rows, uint8_t *rgba)
{
    if (rows > r->ky)
        rows = r->ky;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, (GLsizei)(r->width * r->kx), (GLsizei)(r->height * rows), GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

void gls_render_read_rgba(gls_renderer *r, uint8_t *rgba)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, (GLsizei)r->width, (GLsizei)r->height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
}

void gls_render_read_z(gls_renderer *r, float *z)
{
    size_t n = (size_t)r->width * r->height;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, (GLsizei)r->width, (GLsizei)r->height, GL_DEPTH_COMPONENT, GL_FLOAT, r->dbuf);
    /* z_ndc = d = (a*ze + b) / -ze with ze = -Zc  =>  Zc = b / (d + a).
     * a = n/(f-n) and b = n f/(f-n) exactly as the floats GL used, so the
     * inversion adds no error of its own.  d == 0 is the clear value. */
    double a = r->zc_a, b = r->zc_b;
    for (size_t i = 0; i < n; i++) {
        double d = r->dbuf[i];
        z[i] = d > 0 ? (float)(b / (d + a)) : INFINITY;
    }
}

const char *gls_renderer_gl_name(const gls_renderer *r) { return r->gl_name; }
const char *gls_renderer_gl_version(const gls_renderer *r) { return r->gl_version; }
int gls_renderer_anisotropic(const gls_renderer *r) { return r->aniso; }

int gls_renderer_set_anisotropy(gls_renderer *r, uint32_t n, char *err, size_t errlen)
{
    if (n <= 1 && !r->aniso)
        return 0; /* off, and GL without the extension is off already */
    if (!r->aniso) {
        snprintf(err, errlen, "anisotropic texture filtering is not available in %s", r->gl_name);
        return -1;
    }
    GLfloat maxaniso = 1;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &maxaniso);
    GLfloat a = n < 1 ? 1.0f : (GLfloat)n;
    if (a > maxaniso)
        a = maxaniso;
    for (uint32_t i = 0; i < r->ntex; i++)
        if (r->tex[i]) {
            glBindTexture(GL_TEXTURE_2D, r->tex[i]);
            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, a);
        }
    glBindTexture(GL_TEXTURE_2D, 0);
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "GL error %#x while setting anisotropic filtering", e);
        return -1;
    }
    return 0;
}

void gls_renderer_destroy(gls_renderer *r)
{
    if (!r)
        return;
    if (r->tex) {
        for (uint32_t i = 0; i < r->ntex; i++)
            if (r->tex[i])
                glDeleteTextures(1, &r->tex[i]);
        free(r->tex);
    }
    if (r->vbo)
        r->glDeleteBuffers(1, &r->vbo);
    if (r->near_vbo)
        r->glDeleteBuffers(1, &r->near_vbo);
    free(r->near_buf);
    free(r->near_list);
    if (r->fbo) {
        r->glBindFramebuffer(GL_FRAMEBUFFER, 0);
        r->glDeleteFramebuffers(1, &r->fbo);
        r->glDeleteRenderbuffers(1, &r->rb_color);
        r->glDeleteRenderbuffers(1, &r->rb_depth);
    }
    free(r->dbuf);
    free(r);
}
