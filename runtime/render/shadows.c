/* Shadow maps (shadows.h).  The fitting and the matrices are plain
 * double arithmetic; the GL part is one depth texture and framebuffer per
 * directional light, drawn through the renderer's own item loop
 * (gls_render_depth_only), so instances, near re-anchoring and the alpha
 * test of holey textures (a tree's leaves) are those of the colour pass. */
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glcalls.h"
#include "lighting.h"
#include "render.h"
#include "shadows.h"
#include "shadows_cube.h"
#include "vec.h"

struct gls_shadows {
    const gls_glext *gl; /* the renderer's GL beyond 1.1 (glcalls.h) */
    uint32_t n, res;
    GLuint fbo[GLS_MAX_LIGHTS], tex[GLS_MAX_LIGHTS];
    float S[16 * GLS_MAX_LIGHTS], bias[GLS_MAX_LIGHTS];
    uint8_t cube[GLS_MAX_LIGHTS]; /* slot i is a point light's cube map */
    float cnear[GLS_MAX_LIGHTS];  /* its near distance (shadows_cube.h)  */
    uint32_t ncube;
};

/* The directional or point light of slot i (gls_lights_eye's order). */
static const gls_light *slot_light(const gls_scene *s, uint32_t slot)
{
    for (uint32_t i = 0, n = 0; i < s->nlights; i++)
        if (s->lights[i].kind != GLS_LIGHT_AMBIENT && n++ == slot)
            return &s->lights[i];
    return NULL;
}

uint32_t gls_shadows_points(const gls_scene *s)
{
    uint32_t n = 0, slots = 0;
    for (uint32_t i = 0; i < s->nlights && slots < GLS_MAX_LIGHTS; i++)
        if (s->lights[i].kind != GLS_LIGHT_AMBIENT)
            slots++, n += s->lights[i].kind == GLS_LIGHT_POINT;
    return n;
}

int gls_shadow_fit(const gls_scene *s, const double L[3], const uint8_t *vis, uint32_t res, gls_shadow_view *v)
{
    if (!s->nitems)
        return -1;
    /* the frame: +Z down the light's direction (-L), X and Y across it */
    rv3 z = rv_unit(rv(-L[0], -L[1], -L[2]));
    rv3 a = fabs(z.y) < 0.9 ? rv(0, 1, 0) : rv(1, 0, 0);
    rv3 x = rv_unit(rv_cross(a, z)), y = rv_cross(z, x);
    double R[9] = {x.x, x.y, x.z, y.x, y.y, y.z, z.x, z.y, z.z};
    /* origin at the centre of every item's box: light coordinates small */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t i = 0; i < s->nitems; i++)
        for (int j = 0; j < 3; j++)
            lo[j] = fmin(lo[j], s->items[i].lo[j]), hi[j] = fmax(hi[j], s->items[i].hi[j]);
    rv3 c = rv(0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]));
    rv3 t = rm_apply(R, c);
    memcpy(v->R, R, sizeof R);
    v->T[0] = -t.x, v->T[1] = -t.y, v->T[2] = -t.z;
    double b[6] = {INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY}; /* receivers' x, y */
    double zr[2] = {INFINITY, -INFINITY};                                           /* every item's z   */
    for (int pass = 0; pass < 2; pass++) /* receivers seen; if none, every item */
        for (uint32_t i = 0; i < s->nitems && !(pass == 1 && b[0] <= b[1]); i++) {
            const gls_item *it = &s->items[i];
            int recv = pass == 1 || !vis || vis[i];
            for (int k = 0; k < 8; k++) {
                rv3 p = rm_apply(R, rv_sub(rv(k & 1 ? it->hi[0] : it->lo[0], k & 2 ? it->hi[1] : it->lo[1],
                                              k & 4 ? it->hi[2] : it->lo[2]), c));
                if (pass == 0)
                    zr[0] = fmin(zr[0], p.z), zr[1] = fmax(zr[1], p.z);
                if (recv)
                    b[0] = fmin(b[0], p.x), b[1] = fmax(b[1], p.x), b[2] = fmin(b[2], p.y), b[3] = fmax(b[3], p.y);
            }
        }
    /* a margin of a few texels, and a depth range never empty */
    double w = fmax(fmax(b[1] - b[0], b[3] - b[2]), 1e-9);
    double m = 2.0 * w / res;
    v->x0 = b[0] - m, v->x1 = b[1] + m, v->y0 = b[2] - m, v->y1 = b[3] + m;
    double dz = fmax(zr[1] - zr[0], 1e-9);
    v->z0 = zr[0] - 0.01 * dz, v->z1 = zr[1] + 0.01 * dz;
    v->texel = fmax(v->x1 - v->x0, v->y1 - v->y0) / res;
    return 0;
}

void gls_shadow_camera(const gls_shadow_view *v, gls_camera *c)
{
    memset(c, 0, sizeof *c);
    memcpy(c->R, v->R, sizeof c->R);
    memcpy(c->T, v->T, sizeof c->T);
    c->fx = c->fy = 1, c->near = v->z0, c->far = v->z1;
}

void gls_shadow_projection(const gls_shadow_view *v, double P[16])
{
    /* GL eye (xe, ye, ze) = (x, -y, -z) of the light frame */
    memset(P, 0, 16 * sizeof *P);
    P[0] = 2 / (v->x1 - v->x0), P[3] = -(v->x0 + v->x1) / (v->x1 - v->x0);
    P[5] = 2 / (v->y1 - v->y0), P[7] = (v->y0 + v->y1) / (v->y1 - v->y0);
    P[10] = 1 / (v->z1 - v->z0), P[11] = v->z1 / (v->z1 - v->z0); /* z0 -> 1, z1 -> 0 */
    P[15] = 1;
}

void gls_shadow_matrix(const gls_shadow_view *v, const gls_camera *c, double S[16])
{
    /* GL eye of c -> world: X = R_c^T (F e - T_c); world -> light GL eye:
     * F (R_l X + T_l).  Together F R_l R_c^T F e + F R_l (C - centre):
     * the translation is formed from the camera's centre, small terms. */
    double C[3], A[16] = {0}, P[16], M[16];
    gls_camera_centre(c, C);
    for (int i = 0; i < 3; i++) {
        double fi = i == 0 ? 1.0 : -1.0;
        for (int j = 0; j < 3; j++) {
            double fj = j == 0 ? 1.0 : -1.0, sum = 0;
            for (int k = 0; k < 3; k++)
                sum += v->R[3 * i + k] * c->R[3 * j + k];
            A[4 * i + j] = fi * sum * fj;
        }
        A[4 * i + 3] = fi * (v->R[3 * i] * C[0] + v->R[3 * i + 1] * C[1] + v->R[3 * i + 2] * C[2] + v->T[i]);
    }
    A[15] = 1;
    gls_shadow_projection(v, P);
    m4_mul(P, A, M);
    /* x, y from -1..1 to texture coordinates 0..1; depth as it is */
    for (int j = 0; j < 4; j++) {
        S[j] = 0.5 * M[j] + 0.5 * M[12 + j];
        S[4 + j] = 0.5 * M[4 + j] + 0.5 * M[12 + j];
        S[8 + j] = M[8 + j];
        S[12 + j] = M[12 + j];
    }
}

uint64_t gls_shadows_bytes(const gls_scene *s)
{
    uint64_t points = gls_shadows_points(s);
    return ((uint64_t)gls_lights_count(s) + 5 * points) * s->shadow_res * s->shadow_res * 4;
}

void gls_shadows_explain(FILE *out, const gls_scene *s)
{
    uint32_t n = 0, points = 0;
    if (!s->lit) {
        fprintf(out, "  %-14s     none drawn: the scene declares no light\n", "");
        return;
    }
    for (uint32_t i = 0; i < s->nlights; i++)
        n += s->lights[i].kind == GLS_LIGHT_DIRECTIONAL, points += s->lights[i].kind == GLS_LIGHT_POINT;
    double face = (double)s->shadow_res * s->shadow_res * 4 / 1048576.0;
    if (n || !points) {
        fprintf(out, "  %-14s     maps: %u of %ux%u (GL_DEPTH_COMPONENT32F, %.1f MiB), one per directional light, "
                     "fitted to the items the camera sees\n",
                "", n, s->shadow_res, s->shadow_res, n * face);
        fprintf(out, "  %-14s     cost: %u extra depth pass%s of every item per colour pass; bias t * (%g + %g "
                     "tan(theta), tan at most %g), t a map texel; 2x2 bilinear PCF\n",
                "", n, n == 1 ? "" : "es", GLS_SHADOW_BIAS_CONST, GLS_SHADOW_BIAS_SLOPE, GLS_SHADOW_BIAS_TAN_MAX);
    }
    if (!points)
        return;
    /* point lights: one cube map each (the lights past the 8 shaded are refused by lighting.c) */
    points = gls_shadows_points(s);
    for (uint32_t i = 0, k = 0; i < s->nlights && k < GLS_MAX_LIGHTS; i++) {
        const gls_light *l = &s->lights[i];
        if (l->kind == GLS_LIGHT_AMBIENT)
            continue;
        k++;
        if (l->kind != GLS_LIGHT_POINT)
            continue;
        double X[3];
        gls_light_world(s, l, X);
        fprintf(out, "  %-14s     light %u: cube map of 6 x %ux%u (%.1f MiB) at (%.6g, %.6g, %.6g), near %.3g: 6 "
                     "depth passes of every item at %ux%u\n",
                "", i + 1, s->shadow_res, s->shadow_res, 6 * face, X[0], X[1], X[2], gls_cube_near(s, X),
                s->shadow_res, s->shadow_res);
    }
    fprintf(out, "  %-14s     cost: %u extra depth passes (6 per point light) of every item per colour pass; bias "
                 "t * (%g + %g tan(theta), tan at most %g) along the face's axis, t = 2 z / %u the texel at the "
                 "point's depth z; 2x2 bilinear PCF across the faces (seamless)\n",
            "", 6 * points, GLS_SHADOW_BIAS_CONST, GLS_SHADOW_BIAS_SLOPE, GLS_SHADOW_BIAS_TAN_MAX, s->shadow_res);
}

/* The bound depth texture of slot i (target: 2D or cube map): bilinear,
 * wrap as given, compared (a reference at least the map's depth is lit),
 * and attached (image attach: the 2D map or the cube's face +X) to the
 * slot's framebuffer, which is left bound.  0, or 1 when the framebuffer
 * is incomplete. */
static int depth_target(gls_shadows *sh, uint32_t i, GLenum target, GLint wrap, GLenum attach)
{
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    sh->gl->glBindFramebuffer(GL_FRAMEBUFFER, sh->fbo[i]);
    sh->gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, attach, sh->tex[i], 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    return sh->gl->glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE;
}

/* Slot i's cube map: six res x res float depth faces, compared like the
 * directional maps; its framebuffer checked with face +X attached (the
 * draw attaches each face in turn).  0, or 1 when incomplete. */
static int cube_create(gls_shadows *sh, uint32_t i)
{
    glBindTexture(GL_TEXTURE_CUBE_MAP, sh->tex[i]);
    for (int f = 0; f < 6; f++)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_DEPTH_COMPONENT32F, (GLsizei)sh->res,
                     (GLsizei)sh->res, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    int bad = depth_target(sh, i, GL_TEXTURE_CUBE_MAP, GL_CLAMP_TO_EDGE, GL_TEXTURE_CUBE_MAP_POSITIVE_X);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return bad;
}

/* Slot n's cube map: the six faces from the light at X (world). */
static void cube_render(gls_shadows *sh, struct gls_renderer *r, const gls_scene *s, uint32_t n, const double X[3])
{
    double P[16];
    double near = gls_cube_near(s, X);
    gls_cube_projection(near, P);
    sh->gl->glBindFramebuffer(GL_FRAMEBUFFER, sh->fbo[n]);
    glViewport(0, 0, (GLsizei)sh->res, (GLsizei)sh->res);
    for (int f = 0; f < 6; f++) {
        gls_camera fc;
        sh->gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f,
                                   sh->tex[n], 0);
        glClear(GL_DEPTH_BUFFER_BIT);
        gls_cube_face_camera(X, f, near, &fc);
        gls_render_depth_only(r, &fc, P);
    }
    memset(sh->S + 16 * n, 0, 16 * sizeof *sh->S);
    sh->bias[n] = 0;
    sh->cnear[n] = (float)near;
}

gls_shadows *gls_shadows_create(const gls_glext *gl, const gls_scene *s, char *err, size_t errlen)
{
    gls_shadows *sh = calloc(1, sizeof *sh);
    if (!sh) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    sh->gl = gl;
    sh->n = gls_lights_count(s);
    if (sh->n > GLS_MAX_LIGHTS)
        sh->n = GLS_MAX_LIGHTS; /* refused by gls_lighting_create */
    sh->res = s->shadow_res;
    for (uint32_t i = 0; i < sh->n; i++) {
        sh->cube[i] = slot_light(s, i)->kind == GLS_LIGHT_POINT;
        sh->ncube += sh->cube[i];
    }
    if (sh->ncube) {
        /* the cube maps go on units 9..16 (a sampler type per unit) */
        GLint units = 0;
        glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
        if (units < 1 + 2 * GLS_MAX_LIGHTS) {
            snprintf(err, errlen, "shadows: point lights' cube maps need %d texture units, GL has %d",
                     1 + 2 * GLS_MAX_LIGHTS, units);
            free(sh);
            return NULL;
        }
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS); /* PCF across the faces' edges */
    }
    glGenTextures((GLsizei)sh->n, sh->tex);
    sh->gl->glGenFramebuffers((GLsizei)sh->n, sh->fbo);
    GLint prev = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &prev);
    int bad = 0;
    for (uint32_t i = 0; i < sh->n && !bad; i++) {
        if (sh->cube[i]) {
            bad = cube_create(sh, i);
            continue;
        }
        glBindTexture(GL_TEXTURE_2D, sh->tex[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, (GLsizei)sh->res, (GLsizei)sh->res, 0,
                     GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
        /* bilinear PCF; outside the map (border depth 0, the far end): lit */
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        bad = depth_target(sh, i, GL_TEXTURE_2D, GL_CLAMP_TO_BORDER, GL_TEXTURE_2D);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    sh->gl->glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)prev);
    if (bad || glGetError() != GL_NO_ERROR) {
        while (glGetError() != GL_NO_ERROR)
            ;
        snprintf(err, errlen, "shadows: cannot allocate %u shadow maps of %ux%u (%.1f MiB)",
                 sh->n + 5 * sh->ncube, sh->res, sh->res, (double)gls_shadows_bytes(s) / 1048576.0);
        gls_shadows_destroy(sh);
        return NULL;
    }
    return sh;
}

void gls_shadows_render(gls_shadows *sh, struct gls_renderer *r, const gls_scene *s, const gls_camera *c,
                        const uint8_t *vis)
{
    GLint prev = 0, vp[4], scissor = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &prev);
    glGetIntegerv(GL_VIEWPORT, vp);
    glGetIntegerv(GL_SCISSOR_TEST, &scissor);
    glDisable(GL_SCISSOR_TEST);
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->nlights && n < sh->n; i++) {
        const gls_light *l = &s->lights[i];
        if (l->kind == GLS_LIGHT_AMBIENT)
            continue;
        if (l->kind == GLS_LIGHT_POINT) {
            double X[3];
            gls_light_world(s, l, X);
            cube_render(sh, r, s, n++, X);
            continue;
        }
        double L[3], P[16], S[16];
        gls_light_world(s, l, L);
        double len = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
        gls_shadow_view v;
        sh->gl->glBindFramebuffer(GL_FRAMEBUFFER, sh->fbo[n]);
        glViewport(0, 0, (GLsizei)sh->res, (GLsizei)sh->res);
        glClear(GL_DEPTH_BUFFER_BIT);
        if (len > 0 && (L[0] /= len, L[1] /= len, L[2] /= len, gls_shadow_fit(s, L, vis, sh->res, &v) == 0)) {
            gls_camera lc;
            gls_shadow_camera(&v, &lc);
            gls_shadow_projection(&v, P);
            gls_render_depth_only(r, &lc, P);
            gls_shadow_matrix(&v, c, S);
            for (int a = 0; a < 4; a++) /* column-major for glUniformMatrix4fv */
                for (int b = 0; b < 4; b++)
                    sh->S[16 * n + 4 * b + a] = (float)S[4 * a + b];
            sh->bias[n] = (float)(v.texel / (v.z1 - v.z0));
        } else { /* nothing to shadow: the cleared map lights everything */
            memset(sh->S + 16 * n, 0, 16 * sizeof *sh->S);
            sh->bias[n] = 0;
        }
        n++;
    }
    sh->gl->glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)prev);
    glViewport(vp[0], vp[1], vp[2], vp[3]);
    if (scissor)
        glEnable(GL_SCISSOR_TEST);
}

uint32_t gls_shadows_uniforms(const gls_shadows *sh, float *S, float *bias)
{
    memcpy(S, sh->S, 16 * sh->n * sizeof *S);
    memcpy(bias, sh->bias, sh->n * sizeof *bias);
    return sh->n;
}

uint32_t gls_shadows_cube_uniforms(const gls_shadows *sh, int *cube, float *near, float *texel)
{
    *texel = 2.0f / (float)sh->res; /* a face texel's size at z = 1 */
    for (uint32_t i = 0; i < sh->n; i++)
        cube[i] = sh->cube[i], near[i] = sh->cnear[i];
    return sh->n;
}

void gls_shadows_bind(const gls_shadows *sh)
{
    for (uint32_t i = 0; i < sh->n; i++) {
        if (sh->cube[i]) {
            sh->gl->glActiveTexture(GL_TEXTURE1 + GLS_MAX_LIGHTS + i);
            glBindTexture(GL_TEXTURE_CUBE_MAP, sh->tex[i]);
            continue;
        }
        sh->gl->glActiveTexture(GL_TEXTURE1 + i);
        glBindTexture(GL_TEXTURE_2D, sh->tex[i]);
    }
    sh->gl->glActiveTexture(GL_TEXTURE0);
}

void gls_shadows_destroy(gls_shadows *sh)
{
    if (!sh)
        return;
    if (sh->n) {
        sh->gl->glDeleteFramebuffers((GLsizei)sh->n, sh->fbo);
        glDeleteTextures((GLsizei)sh->n, sh->tex);
    }
    free(sh);
}
