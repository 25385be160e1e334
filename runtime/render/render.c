/* The GL renderer (render.h).
 *
 * Fixed-function GL (compatibility profile) rather than shaders: the
 * bundle's drawing model is exactly the fixed-function one (per-vertex
 * colour, texture env REPLACE/MODULATE, alpha test), llvmpipe compiles the
 * fixed-function state into the same LLVM code a GLSL shader would give,
 * and there is no shader source to embed, compile and diagnose.  Matrices
 * go in with glLoadMatrixf after being formed in double on the CPU.  (The
 * ground-truth pass, gt_pass.c, draws the same items through
 * gls_render_hooked with a small GLSL program of its own, and a lit
 * scene's colour passes use lighting.c's, with shadows.c's maps drawn
 * through gls_render_depth_only; an unlit scene never meets either.)
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
#include "lighting.h"
#include "occlusion.h"
#include "render.h"
#include "shadows.h"
#include "scene_cull.h"
#include "units.h"
#include "vec.h"

#ifndef GL_TEXTURE_MAX_ANISOTROPY
#define GL_TEXTURE_MAX_ANISOTROPY 0x84FE
#define GL_MAX_TEXTURE_MAX_ANISOTROPY 0x84FF
#endif

struct gls_renderer {
    gls_glext gl;          /* GL beyond 1.1, shared with its passes (glcalls.h) */
    const gls_scene *scene;
    gls_glctx *ctx;
    GLuint vbo, fbo, rb_color, rb_depth;
    GLuint near_vbo;       /* per-pass vertices of re-anchored chunks */
    uint8_t *near_buf;
    size_t near_cap;       /* vertices */
    uint32_t *near_list;   /* item indices drawn from near_vbo */
    uint8_t *ivis, *vis;   /* culling: per instance, per item           */
    gls_cull_stats cull;   /* of the last plain pass                    */
    GLuint *tex;           /* per bundle texture: GL name or 0 if unused */
    uint32_t ntex;
    uint32_t width, height; /* one image (tile) */
    uint32_t kx, ky;        /* mosaic: kx x ky tiles in the framebuffer */
    int aniso;
    float zc_a, zc_b;      /* projection [2][2], [2][3] as GL got them */
    uint32_t nnear;        /* near chunks prepared by gls_render_prepare */
    float *dbuf;           /* depth read-back scratch */
    char gl_name[128], gl_version[128];
    gls_render_item_hook hook; /* called before each item's draw: the  */
    void *hook_ud;             /* ground-truth pass (gls_render_hooked) */
    gls_lighting *light;       /* lit scenes only: the shading program  */
    gls_shadows *shadows;      /* scenes with shadows: the maps         */
    int depth_only;            /* drawing a shadow map (no program)     */
    double pass_C[3];          /* the colour pass's camera centre and   */
    uint32_t pass_nnear;       /* near items, for the shadow maps' draw */
    void *ext;                 /* gls_renderer_set_ext: freed with r    */
    void (*ext_free)(void *);
    gls_occlusion_mode occ_mode; /* occlusion culling (occlusion.h)     */
    gls_occlusion occ;         /* its plan, reused from pass to pass   */
    GLuint occ_vbo;            /* the tested boxes                      */
    GLuint *occ_q;             /* one query per tested box              */
    uint32_t occ_nq;
    uint32_t *near_at;         /* per item: its first vertex in near_vbo,
                                  UINT32_MAX if drawn from vbo          */
    uint32_t occluded;         /* items the last colour pass skipped    */
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
        const char *e = (const char *)r->gl.glGetStringi(GL_EXTENSIONS, (GLuint)i);
        if (e && strcmp(e, name) == 0)
            return 1;
    }
    return 0;
}

/* Attribute pointers into the currently bound GL_ARRAY_BUFFER; a lit
 * scene's normal and specular state (texture unit 1's coordinates, read
 * only by the lighting program). */
static void set_pointers(gls_renderer *r, const gls_scene *s)
{
    GLsizei stride = (GLsizei)s->stride;
    glVertexPointer(3, GL_FLOAT, stride, (const void *)0);
    if (s->has_color)
        glColorPointer(4, GL_UNSIGNED_BYTE, stride, (const void *)(uintptr_t)s->color_offset);
    if (s->has_texcoord)
        glTexCoordPointer(2, GL_FLOAT, stride, (const void *)(uintptr_t)s->texcoord_offset);
    if (s->lit) {
        glNormalPointer(GL_FLOAT, stride, (const void *)(uintptr_t)s->normal_offset);
        r->gl.glClientActiveTexture(GL_TEXTURE1);
        glTexCoordPointer(4, GL_FLOAT, stride, (const void *)(uintptr_t)s->specular_offset);
        r->gl.glClientActiveTexture(GL_TEXTURE0);
    }
}

/* The lit scene's arrays on (or, unlit, off: a context may outlive an
 * earlier lit renderer, and fixed function must not fetch through its
 * stale pointers), and its program.  0, or -1 with a message. */
static int setup_lighting(gls_renderer *r, const gls_scene *scene, char *err, size_t errlen)
{
    r->gl.glClientActiveTexture(GL_TEXTURE1);
    if (scene->lit)
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    else
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    r->gl.glClientActiveTexture(GL_TEXTURE0);
    if (!scene->lit) {
        glDisableClientState(GL_NORMAL_ARRAY);
        return 0;
    }
    glEnableClientState(GL_NORMAL_ARRAY);
    if (scene->shadow_res && !(r->shadows = gls_shadows_create(&r->gl, scene, err, errlen)))
        return -1;
    r->light = gls_lighting_create(&r->gl, scene, err, errlen);
    return r->light ? 0 : -1;
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
        r->gl.glGenerateMipmap(GL_TEXTURE_2D);
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
    r->ctx = ctx;
    if (gls_glext_load(ctx, &r->gl, err, errlen)) {
        free(r);
        return NULL;
    }
    snprintf(r->gl_name, sizeof r->gl_name, "%s", (const char *)glGetString(GL_RENDERER));
    snprintf(r->gl_version, sizeof r->gl_version, "%s", (const char *)glGetString(GL_VERSION));
    r->aniso = has_extension(r, "GL_EXT_texture_filter_anisotropic") ||
               has_extension(r, "GL_ARB_texture_filter_anisotropic");

    /* reversed Z: z_ndc in [0, 1], 1 at near; see spec/camera.md */
    r->gl.glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
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
    } else {
        glDisable(GL_ALPHA_TEST); /* a context may outlive an earlier renderer */
    }

    r->gl.glGenBuffers(1, &r->vbo);
    r->gl.glBindBuffer(GL_ARRAY_BUFFER, r->vbo);
    r->gl.glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)scene->nverts * scene->stride), scene->verts,
                    GL_STATIC_DRAW);
    /* arrays the scene lacks are disabled, not just left alone: an
     * earlier renderer of the same context may have enabled them, and a
     * shader reading every attribute (gt_pass.c) would fetch through
     * its stale pointers */
    glEnableClientState(GL_VERTEX_ARRAY);
    if (scene->has_color)
        glEnableClientState(GL_COLOR_ARRAY);
    else
        glDisableClientState(GL_COLOR_ARRAY);
    if (scene->has_texcoord) {
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    } else {
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoord2f(0, 0); /* texcoords absent: (0, 0) */
    }
    if (setup_lighting(r, scene, err, errlen)) {
        gls_renderer_destroy(r);
        return NULL;
    }
    set_pointers(r, scene);
    r->gl.glGenBuffers(1, &r->near_vbo);
    r->gl.glGenBuffers(1, &r->occ_vbo);
    r->near_list = malloc((scene->nitems ? scene->nitems : 1) * sizeof *r->near_list);
    r->ivis = malloc(scene->ninst ? scene->ninst : 1);
    r->vis = malloc(scene->nitems ? scene->nitems : 1);
    r->near_at = malloc((scene->nitems ? scene->nitems : 1) * sizeof *r->near_at);
    r->occ_mode = GLS_OCCLUSION_AUTO;
    if (!r->near_list || !r->ivis || !r->vis || !r->near_at) {
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
        r->gl.glGenFramebuffers(1, &r->fbo);
        r->gl.glGenRenderbuffers(1, &r->rb_color);
        r->gl.glGenRenderbuffers(1, &r->rb_depth);
    }
    GLsizei fw = (GLsizei)(w * kx), fh = (GLsizei)(h * ky);
    r->gl.glBindFramebuffer(GL_FRAMEBUFFER, r->fbo);
    r->gl.glBindRenderbuffer(GL_RENDERBUFFER, r->rb_color);
    r->gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, fw, fh);
    r->gl.glBindRenderbuffer(GL_RENDERBUFFER, r->rb_depth);
    r->gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, fw, fh);
    r->gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r->rb_color);
    r->gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r->rb_depth);
    GLenum st = r->gl.glCheckFramebufferStatus(GL_FRAMEBUFFER);
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
    if (r->light && !r->hook && !r->depth_only)
        gls_lighting_key(r->light, k);
}

/* Does item it need re-anchoring at the camera centre C?  Its float
 * offsets err by up to 2^-24 * maxoff in the proto's frame, scale times
 * that in the world; every visible vertex is at least max(distance from
 * C to the item's box, near) from the camera.  Keep the static offsets
 * only while that error is within 4 * 2^-24 of the distance, i.e. no
 * more than twice the float rounding GL adds anyway. */
static int needs_reanchor(const gls_scene *s, const gls_item *it, const double C[3], double near)
{
    double d2 = 0;
    for (int j = 0; j < 3; j++) {
        double e = C[j] < it->lo[j] ? it->lo[j] - C[j] : C[j] > it->hi[j] ? C[j] - it->hi[j] : 0;
        d2 += e * e;
    }
    double dist = sqrt(d2);
    if (dist < near)
        dist = near;
    return s->chunks[it->chunk].maxoff * s->inst[it->inst].scale > 4 * dist;
}

/* Modelview of geometry at offsets from a in the frame of world transform
 * W: camera-relative in double (W a first, then R (W a) + T, where the
 * large terms cancel), the rotation R A.  For W = I every product is
 * exact, so an instance at the identity draws exactly as flattened. */
static void item_modelview(const gls_camera *c, const double W[16], const double a[3], double MV[16])
{
    double p[3];
    for (int i = 0; i < 3; i++)
        p[i] = W[4 * i] * a[0] + W[4 * i + 1] * a[1] + W[4 * i + 2] * a[2] + W[4 * i + 3];
    gls_camera_modelview(c, p, MV);
    for (int i = 0; i < 3; i++) {
        double sg = i == 0 ? 1.0 : -1.0; /* the flip diag(1, -1, -1) */
        for (int j = 0; j < 3; j++)
            MV[4 * i + j] =
                sg * (c->R[3 * i] * W[j] + c->R[3 * i + 1] * W[4 + j] + c->R[3 * i + 2] * W[8 + j]);
    }
}

/* Draw item it: from the static buffer (near = 0: offsets from its
 * chunk's anchor in its instance's frame) or the near buffer (offsets
 * from the camera centre C in the world). */
static void draw_item(gls_renderer *r, const gls_camera *c, const gls_item *it, int near, const double C[3],
                      uint32_t first, const gls_drawkey **prev)
{
    static const double I[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const gls_chunk *ch = &r->scene->chunks[it->chunk];
    double MV[16];
    float f[16];
    if (!*prev || memcmp(*prev, &ch->key, sizeof **prev)) {
        apply_key(r, &ch->key);
        *prev = &ch->key;
    }
    if (near)
        item_modelview(c, I, C, MV);
    else
        item_modelview(c, r->scene->inst[it->inst].world, ch->anchor, MV);
    gls_mat_to_gl(MV, f);
    glLoadMatrixf(f);
    if (r->hook)
        r->hook(r->hook_ud, r->scene, it);
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

/* The normals of n vertices (float x 3 at v, stride bytes apart) from an
 * instance's frame into the world by W's normal matrix, in double, each
 * kept at its length: 1 for a given normal, 2 for a flat one (turned
 * towards the camera by the shader), 0 for a degenerate triangle's. */
static void normals_to_world(uint8_t *v, uint32_t n, size_t stride, const double W[16])
{
    double N[9];
    m4_normal_matrix(W, N);
    for (uint32_t k = 0; k < n; k++, v += stride) {
        float f[3];
        memcpy(f, v, sizeof f);
        rv3 a = rv(f[0], f[1], f[2]), m = rm_apply(N, a);
        double len = rv_len(a), ml = rv_len(m);
        if (!(len > 0) || !(ml > 0))
            continue;
        m = rv_mul(m, len / ml);
        f[0] = (float)m.x, f[1] = (float)m.y, f[2] = (float)m.z;
        memcpy(v, f, sizeof f);
    }
}

/* Items near the camera: offsets from the camera centre, formed in
 * double in the world, so their float error is relative to their
 * distance.  Uploaded once per camera position; returns how many items
 * are in the list. */
static uint32_t prepare_near(gls_renderer *r, const gls_camera *c, const double C[3])
{
    const gls_scene *s = r->scene;
    uint32_t nnear = 0;
    size_t nv = 0;
    for (uint32_t i = 0; i < s->nitems; i++) {
        r->near_at[i] = UINT32_MAX;
        if (needs_reanchor(s, &s->items[i], C, c->near)) {
            r->near_list[nnear++] = i;
            nv += s->chunks[s->items[i].chunk].count;
        }
    }
    if (!nnear)
        return 0;
    if (nv > r->near_cap) {
        uint8_t *nb = realloc(r->near_buf, nv * s->stride);
        if (!nb) {
            for (uint32_t k = 0; k < nnear; k++)
                r->near_at[r->near_list[k]] = UINT32_MAX;
            return 0; /* out of memory: drawn from the static buffer */
        }
        r->near_buf = nb;
        r->near_cap = nv;
    }
    size_t at = 0;
    for (uint32_t k = 0; k < nnear; k++) {
        const gls_item *it = &s->items[r->near_list[k]];
        const gls_chunk *ch = &s->chunks[it->chunk];
        const double *W = s->inst[it->inst].world;
        r->near_at[r->near_list[k]] = (uint32_t)at;
        memcpy(r->near_buf + at * s->stride, s->verts + (size_t)ch->first * s->stride, (size_t)ch->count * s->stride);
        for (uint32_t v = 0; v < ch->count; v++) {
            const double *q = s->exact + 3 * ((size_t)ch->first + v);
            float off[3];
            for (int i = 0; i < 3; i++)
                off[i] = (float)(W[4 * i] * q[0] + W[4 * i + 1] * q[1] + W[4 * i + 2] * q[2] + W[4 * i + 3] - C[i]);
            memcpy(r->near_buf + (at + v) * s->stride, off, sizeof off);
        }
        if (s->lit) /* normals too, into the world, at their lengths (scene.h) */
            normals_to_world(r->near_buf + at * s->stride + s->normal_offset, ch->count, s->stride, W);
        at += ch->count;
    }
    r->gl.glBindBuffer(GL_ARRAY_BUFFER, r->near_vbo);
    r->gl.glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nv * s->stride), r->near_buf, GL_STREAM_DRAW);
    return nnear;
}

/* Draw every item (those with vis[i] != 0; NULL: all) with the current
 * projection and viewport. */
static void draw_all(gls_renderer *r, const gls_camera *c, const double C[3], uint32_t nnear, const uint8_t *vis)
{
    const gls_scene *s = r->scene;
    const gls_drawkey *prev = NULL;
    uint32_t k = 0;
    /* a colour pass (the hooked one has its own program, a shadow map none) */
    int lit = r->light && !r->hook && !r->depth_only;
    if (lit)
        gls_lighting_begin(r->light, s, c, r->shadows);
    r->gl.glBindBuffer(GL_ARRAY_BUFFER, r->vbo);
    set_pointers(r, s);
    for (uint32_t i = 0; i < s->nitems; i++) {
        const gls_item *it = &s->items[i];
        if (k < nnear && r->near_list[k] == i) {
            k++;
            continue;
        }
        if (!vis || vis[i])
            draw_item(r, c, it, 0, C, s->chunks[it->chunk].first, &prev);
    }
    if (nnear) {
        r->gl.glBindBuffer(GL_ARRAY_BUFFER, r->near_vbo);
        set_pointers(r, s);
        size_t at = 0;
        for (k = 0; k < nnear; k++) {
            const gls_item *it = &s->items[r->near_list[k]];
            if (!vis || vis[r->near_list[k]])
                draw_item(r, c, it, 1, C, (uint32_t)at, &prev);
            at += s->chunks[it->chunk].count;
        }
    }
    if (lit)
        gls_lighting_end(r->light);
}

/* Draw unit u of the plan's drawing order: its items in turn, each from
 * the static buffer or, re-anchored, the near one (*bound: which buffer
 * the pointers read, -1 none). */
static void draw_unit(gls_renderer *r, const gls_camera *c, const double C[3], uint32_t u, int *bound,
                      const gls_drawkey **prev)
{
    const gls_scene *s = r->scene;
    const gls_occlusion *o = &r->occ;
    for (uint32_t j = 0; j < o->unit_n[u]; j++) {
        uint32_t i = o->items[o->unit_first[u] + j];
        int near = r->near_at[i] != UINT32_MAX;
        if (*bound != near) {
            r->gl.glBindBuffer(GL_ARRAY_BUFFER, near ? r->near_vbo : r->vbo);
            set_pointers(r, s);
            *bound = near;
        }
        draw_item(r, c, &s->items[i], near, C, near ? r->near_at[i] : s->chunks[s->items[i].chunk].first, prev);
    }
}

/* Test tested units t0 .. t1-1 of the plan (their boxes in occlusion
 * queries against the depth drawn so far, depth and colour writes off)
 * and mark those no sample of whose boxes passed hidden (utested 2);
 * how many. */
static uint32_t test_units(gls_renderer *r, const gls_camera *c, const double C[3], uint32_t t0, uint32_t t1)
{
    static const double I[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const gls_scene *s = r->scene;
    gls_occlusion *o = &r->occ;
    double MV[16];
    float f[16];
    item_modelview(c, I, C, MV); /* the boxes are relative to C */
    gls_mat_to_gl(MV, f);
    glLoadMatrixf(f);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glDisable(GL_TEXTURE_2D);
    if (!s->has_color)
        glColor4ub(255, 255, 255, 255); /* alpha 1: the alpha test passes */
    r->gl.glBindBuffer(GL_ARRAY_BUFFER, r->occ_vbo);
    set_pointers(r, s);
    for (uint32_t k = t0; k < t1; k++) {
        uint32_t u = o->tested[k];
        r->gl.glBeginQuery(GL_ANY_SAMPLES_PASSED, r->occ_q[k]);
        glDrawArrays(GL_TRIANGLES, (GLint)o->box_first[u], (GLsizei)o->box_n[u]);
        r->gl.glEndQuery(GL_ANY_SAMPLES_PASSED);
    }
    uint32_t hidden = 0;
    for (uint32_t k = t0; k < t1; k++) {
        GLuint any = 1;
        r->gl.glGetQueryObjectuiv(r->occ_q[k], GL_QUERY_RESULT, &any);
        if (!any) {
            o->utested[o->tested[k]] = 2;
            r->occluded += o->unit_n[o->tested[k]];
            hidden++;
        }
    }
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return hidden;
}

/* The drawing order of camera c's passes over the items vis keeps, and
 * with occlude (colour passes) the occlusion plan, its queries and its
 * boxes uploaded: gls_occlusion_plan's result.  The plan depends on the
 * camera centre and vis, not on a pass's jitter, so the tiles of a mosaic
 * share it. */
static int plan_passes(gls_renderer *r, const gls_camera *c, const double C[3], const uint8_t *vis, int occlude)
{
    const gls_scene *s = r->scene;
    gls_occlusion *o = &r->occ;
    int plan = gls_occlusion_plan(o, occlude ? r->occ_mode : GLS_OCCLUSION_OFF, s, c, C, vis);
    if (plan > 0 && o->ntested > r->occ_nq) {
        GLuint *q = realloc(r->occ_q, o->ntested * sizeof *q);
        if (!q) {
            plan = 0;
        } else {
            r->occ_q = q;
            r->gl.glGenQueries((GLsizei)(o->ntested - r->occ_nq), q + r->occ_nq);
            r->occ_nq = o->ntested;
        }
    }
    if (plan > 0) {
        r->gl.glBindBuffer(GL_ARRAY_BUFFER, r->occ_vbo);
        r->gl.glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)o->box_verts * s->stride), o->boxes,
                           GL_STREAM_DRAW);
    }
    return plan;
}

/* Draw the items vis keeps (NULL: all) in the drawing order of
 * occlusion.h (nearest instances first) as planned by plan_passes (its
 * result: plan), with the current projection, viewport and scissor.  With
 * a plan (a colour pass), units are tested before they are drawn
 * (spec/bundle.md 9.3): the nearest units are drawn first, untested;
 * then, a round at a time, the next tested units' boxes are drawn in
 * occlusion queries against the depth drawn so far, and the round's units
 * are drawn in order, less those no sample of whose boxes passed.  Every
 * unit that is drawn is drawn once, in the same order as without culling,
 * so exact depth ties resolve alike with it and without. */
static void draw_planned(gls_renderer *r, const gls_camera *c, const double C[3], uint32_t nnear, const uint8_t *vis,
                         int plan)
{
    const gls_scene *s = r->scene;
    gls_occlusion *o = &r->occ;
    r->occluded = 0;
    if (plan < 0) { /* out of memory: no order, the scene's own */
        draw_all(r, c, C, nnear, vis);
        return;
    }
    for (uint32_t k = 0; plan > 0 && k < o->ntested; k++)
        o->utested[o->tested[k]] = 1; /* an earlier tile's hidden units: tested afresh */
    /* a colour pass (the hooked one has its own program, a shadow map none) */
    int lit = r->light && !r->hook && !r->depth_only, bound = -1;
    if (lit)
        gls_lighting_begin(r->light, s, c, r->shadows);
    const gls_drawkey *prev = NULL;
    /* GLS_OCCLUSION_ROUNDS rounds (of at least 16 units): units tested in
     * one round do not hide each other, so fewer rounds hide less; each
     * round waits for its queries */
    uint32_t round = plan > 0 ? o->ntested / GLS_OCCLUSION_ROUNDS + 1 : 0, t = 0, hidden = 0;
    if (round < 16)
        round = 16;
    int testing = plan > 0;
    for (uint32_t u = 0; u < o->nunits;) {
        if (!testing || !o->utested[u]) {
            draw_unit(r, c, C, u++, &bound, &prev);
            continue;
        }
        /* a round: the next tested units, and with them the untested
         * ones (reaching the near plane) up to the next round's first */
        uint32_t t1 = t + round < o->ntested ? t + round : o->ntested;
        uint32_t v = t1 < o->ntested ? o->tested[t1] : o->nunits;
        if (lit)
            gls_lighting_end(r->light);
        hidden += test_units(r, c, C, t, t1);
        if (lit)
            gls_lighting_begin(r->light, s, c, r->shadows);
        bound = -1, prev = NULL; /* the tests changed the buffer, texture and colour */
        for (; u < v; u++)
            if (o->utested[u] != 2)
                draw_unit(r, c, C, u, &bound, &prev);
        t = t1;
        /* a sixteenth tested and almost nothing hidden: the view overlaps
         * without hiding (sparse geometry in big boxes); the rest is drawn
         * untested rather than tested for nothing */
        if (t >= o->ntested / GLS_OCCLUSION_PROBE && GLS_OCCLUSION_STOP * hidden < t)
            testing = 0;
    }
    if (lit)
        gls_lighting_end(r->light);
}

static void draw_ordered(gls_renderer *r, const gls_camera *c, const double C[3], uint32_t nnear, const uint8_t *vis,
                         int occlude)
{
    draw_planned(r, c, C, nnear, vis, plan_passes(r, c, C, vis, occlude));
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

void gls_render_pass_rows(gls_renderer *r, const gls_camera *c, uint32_t y0, uint32_t rows)
{
    static const double zero = 0.0;
    gls_render_tiles_rows(r, c, 1, &zero, &zero, y0, rows);
}

/* The shadow maps for camera c (centre C, nnear near items prepared),
 * before a colour pass that draws the items vis marks. */
static void draw_shadow_maps(gls_renderer *r, const gls_camera *c, const double C[3], uint32_t nnear,
                             const uint8_t *vis)
{
    if (!r->shadows)
        return;
    memcpy(r->pass_C, C, sizeof r->pass_C);
    r->pass_nnear = nnear;
    gls_shadows_render(r->shadows, r, r->scene, c, vis);
}

void gls_render_depth_only(gls_renderer *r, const gls_camera *view, const double P[16])
{
    float f[16];
    gls_mat_to_gl(P, f);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(f);
    glMatrixMode(GL_MODELVIEW);
    r->depth_only = 1;
    draw_all(r, view, r->pass_C, r->pass_nnear, NULL);
    r->depth_only = 0;
}

void gls_render_tiles(gls_renderer *r, const gls_camera *c, uint32_t n, const double *du, const double *dv)
{
    gls_render_tiles_rows(r, c, n, du, dv, 0, r->height);
}

void gls_render_tiles_rows(gls_renderer *r, const gls_camera *c, uint32_t n, const double *du, const double *dv,
                           uint32_t y0, uint32_t rows)
{
    double C[3];
    gls_camera_centre(c, C);
    int mosaic = r->kx * r->ky > 1, part = y0 > 0 || rows < r->height;
    if (mosaic) {
        /* one clear for the whole mosaic */
        glViewport(0, 0, (GLsizei)(r->width * r->kx), (GLsizei)(r->height * r->ky));
        glScissor(0, 0, (GLsizei)(r->width * r->kx), (GLsizei)(r->height * r->ky));
    } else if (part) {
        /* a plain framebuffer has the scissor off (gls_renderer_set_mosaic):
           on for these rows only; the clear and the fragments obey it */
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, (GLint)y0, (GLsizei)r->width, (GLsizei)rows);
    }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    uint32_t nnear = prepare_near(r, c, C);
    gls_scene_cull(r->scene, c, r->ivis, r->vis, &r->cull);
    draw_shadow_maps(r, c, C, nnear, r->vis);
    int plan = plan_passes(r, c, C, r->vis, 1); /* one for every tile */
    for (uint32_t t = 0; t < n && t < r->kx * r->ky; t++) {
        if (mosaic) {
            GLint x = (GLint)(r->width * (t % r->kx)), y = (GLint)(r->height * (t / r->kx));
            glViewport(x, y, (GLsizei)r->width, (GLsizei)r->height);
            glScissor(x, y + (GLint)y0, (GLsizei)r->width, (GLsizei)rows);
        }
        load_projection(r, c, du[t], dv[t]);
        draw_planned(r, c, C, nnear, r->vis, plan);
    }
    if (!mosaic && part)
        glDisable(GL_SCISSOR_TEST);
}

void gls_render_hooked(gls_renderer *r, const gls_camera *c, gls_render_item_hook hook, void *ud)
{
    double C[3];
    gls_camera_centre(c, C);
    uint32_t nnear = prepare_near(r, c, C);
    gls_scene_cull(r->scene, c, r->ivis, r->vis, &r->cull);
    load_projection(r, c, 0.0, 0.0);
    r->hook = hook, r->hook_ud = ud;
    draw_ordered(r, c, C, nnear, r->vis, 0);
    r->hook = NULL, r->hook_ud = NULL;
}

const gls_glext *gls_renderer_gl(const gls_renderer *r) { return &r->gl; }
const gls_scene *gls_renderer_scene(const gls_renderer *r) { return r->scene; }
void *gls_renderer_ext(const gls_renderer *r) { return r->ext; }

void gls_renderer_set_ext(gls_renderer *r, void *ext, void (*ext_free)(void *))
{
    if (r->ext && r->ext_free)
        r->ext_free(r->ext);
    r->ext = ext, r->ext_free = ext_free;
}

uint32_t gls_renderer_nchunks(const gls_renderer *r) { return r->scene->nitems; }

gls_cull_stats gls_render_cull_stats(const gls_renderer *r) { return r->cull; }

uint32_t gls_render_chunk_bounds(gls_renderer *r, const gls_camera *c, double (*b)[4])
{
    const gls_scene *s = r->scene;
    gls_scene_cull(s, c, r->ivis, r->vis, &r->cull);
    for (uint32_t i = 0; i < s->nitems; i++) {
        if (r->vis[i]) /* the frustum's instances first, then each item's box */
            gls_box_image_bounds(c, s->items[i].lo, s->items[i].hi, b[i]);
        else
            b[i][0] = b[i][1] = INFINITY, b[i][2] = b[i][3] = -INFINITY;
    }
    return s->nitems;
}

void gls_render_prepare(gls_renderer *r, const gls_camera *c)
{
    double C[3];
    gls_camera_centre(c, C);
    r->nnear = prepare_near(r, c, C);
    if (r->shadows) { /* once for all the mapped tiles: fitted to what the whole camera sees */
        gls_cull_stats st;
        gls_scene_cull(r->scene, c, r->ivis, r->vis, &st);
        draw_shadow_maps(r, c, C, r->nnear, r->vis);
    }
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
    draw_ordered(r, c, C, r->nnear, vis, 1);
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

void gls_render_read_mosaic_rows(gls_renderer *r, uint32_t rows, uint32_t y0, uint32_t n, uint8_t *rgba)
{
    if (rows > r->ky)
        rows = r->ky;
    if (y0 == 0 && n >= r->height) {
        gls_render_read_mosaic(r, rows, rgba); /* one read */
        return;
    }
    size_t stride = (size_t)r->width * r->kx * 4;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (uint32_t j = 0; j < rows; j++) {
        uint32_t y = j * r->height + y0;
        glReadPixels(0, (GLint)y, (GLsizei)(r->width * r->kx), (GLsizei)n, GL_RGBA, GL_UNSIGNED_BYTE,
                     rgba + stride * y);
    }
}

void gls_render_read_rgba(gls_renderer *r, uint8_t *rgba)
{
    gls_render_read_rgba_rows(r, 0, r->height, rgba);
}

void gls_render_read_rgba_rows(gls_renderer *r, uint32_t y0, uint32_t rows, uint8_t *rgba)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, (GLint)y0, (GLsizei)r->width, (GLsizei)rows, GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba + 4 * (size_t)y0 * r->width);
}

void gls_render_read_z(gls_renderer *r, float *z)
{
    gls_render_read_z_rows(r, 0, r->height, z);
}

void gls_render_read_z_rows(gls_renderer *r, uint32_t y0, uint32_t rows, float *z)
{
    size_t i0 = (size_t)y0 * r->width, i1 = i0 + (size_t)rows * r->width;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, (GLint)y0, (GLsizei)r->width, (GLsizei)rows, GL_DEPTH_COMPONENT, GL_FLOAT, r->dbuf + i0);
    /* z_ndc = d = (a*ze + b) / -ze with ze = -Zc  =>  Zc = b / (d + a).
     * a = n/(f-n) and b = n f/(f-n) exactly as the floats GL used, so the
     * inversion adds no error of its own.  d == 0 is the clear value. */
    double a = r->zc_a, b = r->zc_b;
    for (size_t i = i0; i < i1; i++) {
        double d = r->dbuf[i];
        z[i] = d > 0 ? (float)(b / (d + a)) : INFINITY;
    }
}

void gls_renderer_set_occlusion(gls_renderer *r, gls_occlusion_mode mode) { r->occ_mode = mode; }
uint32_t gls_render_occluded(const gls_renderer *r) { return r->occluded; }

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
    gls_renderer_set_ext(r, NULL, NULL); /* its GL objects, while the context is there */
    gls_lighting_destroy(r->light);
    gls_shadows_destroy(r->shadows);
    if (r->tex) {
        for (uint32_t i = 0; i < r->ntex; i++)
            if (r->tex[i])
                glDeleteTextures(1, &r->tex[i]);
        free(r->tex);
    }
    if (r->vbo)
        r->gl.glDeleteBuffers(1, &r->vbo);
    if (r->near_vbo)
        r->gl.glDeleteBuffers(1, &r->near_vbo);
    if (r->occ_vbo)
        r->gl.glDeleteBuffers(1, &r->occ_vbo);
    if (r->occ_nq)
        r->gl.glDeleteQueries((GLsizei)r->occ_nq, r->occ_q);
    free(r->occ_q);
    free(r->near_at);
    gls_occlusion_free(&r->occ);
    free(r->near_buf);
    free(r->near_list);
    free(r->ivis);
    free(r->vis);
    if (r->fbo) {
        r->gl.glBindFramebuffer(GL_FRAMEBUFFER, 0);
        r->gl.glDeleteFramebuffers(1, &r->fbo);
        r->gl.glDeleteRenderbuffers(1, &r->rb_color);
        r->gl.glDeleteRenderbuffers(1, &r->rb_depth);
    }
    free(r->dbuf);
    free(r);
}
