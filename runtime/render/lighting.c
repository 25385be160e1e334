/* Per-pixel lighting (lighting.h).
 *
 * Why per pixel and in GLSL: fixed-function lighting is per vertex
 * (Gouraud), so a highlight or a point light's fall-off inside a large
 * triangle would be wrong by a closed form's measure; the program computes
 * Lambert (max(0, n.l) times the surface colour) plus Phong
 * (max(0, r.v)^e times the specular colour) at every fragment from the
 * interpolated normal.  Colours are linear and written as they are: no
 * gamma is applied, and a sum above 1 saturates at 255.
 *
 * The position goes through ftransform(), so the depth (and so which
 * surface a pixel shows, and the depth output) is the fixed-function
 * path's bit for bit (as in gt_pass.c).
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glcalls.h"
#include "glprog.h"
#include "lighting.h"
#include "shadows.h"

struct gls_lighting {
    const gls_glext *gl; /* the renderer's GL beyond 1.1 (glcalls.h) */
    GLuint prog;
    GLint u_n, u_pos, u_col, u_ambient, u_tex, u_sampler;
    GLint u_shadows, u_smat, u_sbias, u_smap;
    int cubes;                  /* built with GLS_POINT_SHADOWS */
    GLint u_cube, u_cnear, u_ctexel, u_e2w, u_cmap;
};

/* gl_Normal: unit for a given normal, length 2 for a flat one (scene.h),
 * which is turned towards the camera; gl_MultiTexCoord1: the specular
 * colour and exponent.  The normal goes to the eye by gl_NormalMatrix
 * kept at its length, as render.c's normals_to_world carries the normals
 * of items re-anchored near the camera: under a non-uniform scale the
 * lengths would differ from vertex to vertex and weigh the interpolation,
 * so that an item's shading would depend on whether it was re-anchored. */
static const char vs_src[] =
    "#version 400 compatibility\n"
    "out vec3 v_eye;\n"
    "out vec3 v_n;\n"
    "out vec4 v_col;\n"
    "out vec2 v_st;\n"
    "out vec4 v_spec;\n"
    "flat out int v_flat;\n"
    "void main() {\n"
    "    gl_Position = ftransform();\n"
    "    v_eye = (gl_ModelViewMatrix * gl_Vertex).xyz;\n"
    "    vec3 m = gl_NormalMatrix * gl_Normal;\n"
    "    float lm = length(m);\n"
    "    v_n = lm > 0.0 ? m * (length(gl_Normal) / lm) : m;\n"
    "    v_flat = dot(gl_Normal, gl_Normal) > 2.0 ? 1 : 0;\n"
    "    v_col = gl_Color;\n"
    "    v_st = gl_MultiTexCoord0.st;\n"
    "    v_spec = gl_MultiTexCoord1;\n"
    "}\n";

/* u_tex as gt_pass.c: 0 untextured, 1 replace, 2 modulate.  A normal of
 * length 0 (a degenerate triangle) faces the camera.  The alpha goes out
 * as the texture environment forms it, for the alpha test.  Shadows
 * (u_shadows != 0, every light directional with map i): the point's map
 * coordinates by u_smat[i], its depth plus the slope-scaled bias
 * (shadows.h) compared with the map, 2x2 bilinear (GLSL 4.00: sampler
 * arrays indexed by the loop's uniform index). */
#define STR_(x) #x
#define STR(x) STR_(x)
#define TAN_MAX STR(GLS_SHADOW_BIAS_TAN_MAX)
#define BIAS_CONST STR(GLS_SHADOW_BIAS_CONST)
#define BIAS_SLOPE STR(GLS_SHADOW_BIAS_SLOPE)
static const char fs_version[] = "#version 400 compatibility\n";
static const char fs_src[] =
    "in vec3 v_eye;\n"
    "in vec3 v_n;\n"
    "in vec4 v_col;\n"
    "in vec2 v_st;\n"
    "in vec4 v_spec;\n"
    "flat in int v_flat;\n"
    "uniform int u_n;\n"
    "uniform vec4 u_pos[8];\n"
    "uniform vec4 u_col[8];\n"
    "uniform vec3 u_ambient;\n"
    "uniform int u_tex;\n"
    "uniform sampler2D u_sampler;\n"
    "uniform int u_shadows;\n"
    "uniform mat4 u_smat[8];\n"
    "uniform float u_sbias[8];\n"
    "uniform sampler2DShadow u_smap[8];\n"
    "#ifdef GLS_POINT_SHADOWS\n"
    "uniform int u_cube[8];\n"
    "uniform float u_cnear[8];\n"
    "uniform float u_ctexel;\n"
    "uniform mat3 u_e2w;\n"
    "uniform samplerCubeShadow u_cmap[8];\n"
    "#endif\n"
    "void main() {\n"
    "    vec4 albedo = v_col;\n"
    "    if (u_tex == 1) albedo = texture(u_sampler, v_st);\n"
    "    else if (u_tex == 2) albedo = texture(u_sampler, v_st) * v_col;\n"
    "    vec3 V = normalize(-v_eye);\n"
    "    float ln = length(v_n);\n"
    "    vec3 n = ln > 0.0 ? v_n / ln : V;\n"
    "    if (v_flat != 0 && dot(n, V) < 0.0) n = -n;\n"
    "    vec3 c = u_ambient * albedo.rgb;\n"
    "    bool shiny = v_spec.r + v_spec.g + v_spec.b > 0.0;\n"
    "    for (int i = 0; i < u_n; i++) {\n"
    "        vec3 L = u_pos[i].xyz;\n"
    "        float att = 1.0;\n"
    "        if (u_pos[i].w != 0.0) {\n"
    "            vec3 d = u_pos[i].xyz - v_eye;\n"
    "            float d2 = dot(d, d);\n"
    "            L = d * inversesqrt(d2);\n"
    "            att = 1.0 / (1.0 + u_col[i].w * d2);\n"
    "        }\n"
    "        float nl = dot(n, L);\n"
    "        if (nl <= 0.0) continue;\n"
    "        vec3 e = u_col[i].rgb * att;\n"
    "        if (u_shadows != 0) {\n"
    "#ifdef GLS_POINT_SHADOWS\n"
    "          if (u_cube[i] != 0) {\n"
    "            vec3 d = u_e2w * (v_eye - u_pos[i].xyz);\n"
    "            vec3 a = abs(d);\n"
    "            float z = max(a.x, max(a.y, a.z));\n"
    "            float tn = min(sqrt(max(1.0 - nl * nl, 0.0)) / nl, " TAN_MAX ");\n"
    "            float zb = z * (1.0 - u_ctexel * (" BIAS_CONST " + " BIAS_SLOPE " * tn));\n"
    "            float ref = zb > u_cnear[i] ? u_cnear[i] / zb : 1.0;\n"
    "            e *= texture(u_cmap[i], vec4(d, ref));\n"
    "          } else\n"
    "#endif\n"
    "          {\n"
    "            vec4 sc = u_smat[i] * vec4(v_eye, 1.0);\n"
    "            float tn = min(sqrt(max(1.0 - nl * nl, 0.0)) / nl, " TAN_MAX ");\n"
    "            float ref = sc.z + u_sbias[i] * (" BIAS_CONST " + " BIAS_SLOPE " * tn);\n"
    "            e *= texture(u_smap[i], vec3(sc.xy, ref));\n"
    "          }\n"
    "        }\n"
    "        c += e * nl * albedo.rgb;\n"
    "        if (shiny) {\n"
    "            float rv = max(dot(reflect(-L, n), V), 0.0);\n"
    "            c += e * v_spec.rgb * (rv > 0.0 ? pow(rv, v_spec.a) : 0.0);\n"
    "        }\n"
    "    }\n"
    "    gl_FragColor = vec4(c, albedo.a);\n"
    "}\n";
_Static_assert(GLS_MAX_LIGHTS == 8, "the shader's arrays hold GLS_MAX_LIGHTS lights");

void gls_light_world(const gls_scene *s, const gls_light *l, double X[3])
{
    const double *W = s->inst[l->inst].world;
    for (int r = 0; r < 3; r++)
        X[r] = W[4 * r] * l->p[0] + W[4 * r + 1] * l->p[1] + W[4 * r + 2] * l->p[2] + W[4 * r + 3] * l->p[3];
}

uint32_t gls_lights_count(const gls_scene *s)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < s->nlights; i++)
        n += s->lights[i].kind != GLS_LIGHT_AMBIENT;
    return n;
}

uint32_t gls_lights_eye(const gls_scene *s, const gls_camera *c, double pos[4 * GLS_MAX_LIGHTS],
                        double col[4 * GLS_MAX_LIGHTS], double ambient[3])
{
    uint32_t n = 0;
    ambient[0] = ambient[1] = ambient[2] = 0;
    for (uint32_t i = 0; i < s->nlights; i++) {
        const gls_light *l = &s->lights[i];
        if (l->kind == GLS_LIGHT_AMBIENT) {
            for (int k = 0; k < 3; k++)
                ambient[k] += l->rgb[k];
            continue;
        }
        if (n == GLS_MAX_LIGHTS)
            break;
        /* world: the instance's transform (motion included); camera:
         * R X + T for a point, R d for a direction; then GL's eye axes */
        double X[3], P[3];
        gls_light_world(s, l, X);
        for (int r = 0; r < 3; r++)
            P[r] = c->R[3 * r] * X[0] + c->R[3 * r + 1] * X[1] + c->R[3 * r + 2] * X[2] + (l->p[3] ? c->T[r] : 0);
        double len = l->p[3] ? 1.0 : sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2]);
        if (!(len > 0))
            len = 1.0; /* a direction scaled to nothing lights nothing */
        pos[4 * n] = P[0] / len, pos[4 * n + 1] = -P[1] / len, pos[4 * n + 2] = -P[2] / len;
        pos[4 * n + 3] = l->p[3] ? 1.0 : 0.0;
        for (int k = 0; k < 3; k++)
            col[4 * n + k] = l->rgb[k];
        col[4 * n + 3] = l->atten;
        n++;
    }
    return n;
}

void gls_lighting_explain(FILE *out, const gls_bundle *b, const gls_scene *s)
{
    static const char *const what[] = {"directional, towards", "point at", "ambient"};
    uint32_t n = gls_lights_count(s);
    for (uint32_t i = 0; i < s->nlights; i++) {
        const gls_light *l = &s->lights[i];
        double X[3];
        gls_light_world(s, l, X);
        fprintf(out, "  %-14s     light %u: %s", "", i + 1, what[l->kind]);
        if (l->kind != GLS_LIGHT_AMBIENT)
            fprintf(out, " (%.6g, %.6g, %.6g) in the world", X[0], X[1], X[2]);
        fprintf(out, ", colour (%.6g, %.6g, %.6g)", l->rgb[0], l->rgb[1], l->rgb[2]);
        if (l->kind == GLS_LIGHT_POINT)
            fprintf(out, ", attenuation 1/(1 + %.6g d^2)", l->atten);
        fprintf(out, " (light instruction of %s)\n", b->objects[s->inst[l->inst].object].name);
    }
    fprintf(out, "  %-14s     cost: per-pixel shading of every covered fragment of each colour pass, %u "
                 "directional/point light%s (at most %u); +28 bytes per vertex; no extra pass\n",
            "", n, n == 1 ? "" : "s", GLS_MAX_LIGHTS);
}

gls_lighting *gls_lighting_create(const gls_glext *gl, const gls_scene *s, char *err, size_t errlen)
{
    uint32_t n = gls_lights_count(s);
    if (n > GLS_MAX_LIGHTS) {
        snprintf(err, errlen,
                 "the scene has %u directional and point lights (counting every call path); the player shades "
                 "with at most %u",
                 n, GLS_MAX_LIGHTS);
        return NULL;
    }
    gls_lighting *l = calloc(1, sizeof *l);
    if (!l) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    l->gl = gl;
    /* the point lights' cube-map lookups are compiled in only when a
     * point light casts shadows: every other scene's program is the
     * source it was before they existed, token for token */
    static const char cube_define[] = "#define GLS_POINT_SHADOWS\n";
    l->cubes = s->shadow_res && gls_shadows_points(s);
    char fs[sizeof fs_version + sizeof cube_define + sizeof fs_src];
    snprintf(fs, sizeof fs, "%s%s%s", fs_version, l->cubes ? cube_define : "", fs_src);
    l->prog = gls_glprog_build(gl, vs_src, fs, "lighting", err, errlen);
    if (!l->prog) {
        free(l);
        return NULL;
    }
    l->u_n = l->gl->glGetUniformLocation(l->prog, "u_n");
    l->u_pos = l->gl->glGetUniformLocation(l->prog, "u_pos");
    l->u_col = l->gl->glGetUniformLocation(l->prog, "u_col");
    l->u_ambient = l->gl->glGetUniformLocation(l->prog, "u_ambient");
    l->u_tex = l->gl->glGetUniformLocation(l->prog, "u_tex");
    l->u_sampler = l->gl->glGetUniformLocation(l->prog, "u_sampler");
    l->u_shadows = l->gl->glGetUniformLocation(l->prog, "u_shadows");
    l->u_smat = l->gl->glGetUniformLocation(l->prog, "u_smat");
    l->u_sbias = l->gl->glGetUniformLocation(l->prog, "u_sbias");
    l->u_smap = l->gl->glGetUniformLocation(l->prog, "u_smap");
    /* the maps on texture units 1..8 (gls_shadows_bind), set once */
    static const GLint units[GLS_MAX_LIGHTS] = {1, 2, 3, 4, 5, 6, 7, 8};
    l->gl->glUseProgram(l->prog);
    l->gl->glUniform1iv(l->u_smap, GLS_MAX_LIGHTS, units);
    if (l->cubes) { /* the cube maps on units 9..16 */
        static const GLint cunits[GLS_MAX_LIGHTS] = {9, 10, 11, 12, 13, 14, 15, 16};
        l->u_cube = l->gl->glGetUniformLocation(l->prog, "u_cube");
        l->u_cnear = l->gl->glGetUniformLocation(l->prog, "u_cnear");
        l->u_ctexel = l->gl->glGetUniformLocation(l->prog, "u_ctexel");
        l->u_e2w = l->gl->glGetUniformLocation(l->prog, "u_e2w");
        l->u_cmap = l->gl->glGetUniformLocation(l->prog, "u_cmap");
        l->gl->glUniform1iv(l->u_cmap, GLS_MAX_LIGHTS, cunits);
    }
    l->gl->glUseProgram(0);
    return l;
}

/* The cube maps' uniforms: which lights have one, their near distances,
 * the texel at depth 1, and the rotation from camera c's GL eye frame to
 * the world axes the faces are aligned with (R^T F, F = diag(1, -1, -1)):
 * the lookup direction is formed from eye-frame offsets, small numbers. */
static void cube_uniforms(gls_lighting *l, const gls_camera *c, const struct gls_shadows *sh)
{
    int cube[GLS_MAX_LIGHTS];
    float near[GLS_MAX_LIGHTS], texel, M[9];
    uint32_t m = gls_shadows_cube_uniforms(sh, cube, near, &texel);
    for (int i = 0; i < 3; i++)     /* world row i */
        for (int j = 0; j < 3; j++) /* eye column j, column-major */
            M[3 * j + i] = (float)(c->R[3 * j + i] * (j == 0 ? 1.0 : -1.0));
    if (m) {
        l->gl->glUniform1iv(l->u_cube, (GLsizei)m, cube);
        l->gl->glUniform1fv(l->u_cnear, (GLsizei)m, near);
    }
    l->gl->glUniform1f(l->u_ctexel, texel);
    l->gl->glUniformMatrix3fv(l->u_e2w, 1, GL_FALSE, M);
}

void gls_lighting_begin(gls_lighting *l, const gls_scene *s, const gls_camera *c, const struct gls_shadows *sh)
{
    double pos[4 * GLS_MAX_LIGHTS], col[4 * GLS_MAX_LIGHTS], amb[3];
    float fp[4 * GLS_MAX_LIGHTS], fc[4 * GLS_MAX_LIGHTS];
    uint32_t n = gls_lights_eye(s, c, pos, col, amb);
    for (uint32_t i = 0; i < 4 * n; i++)
        fp[i] = (float)pos[i], fc[i] = (float)col[i];
    l->gl->glUseProgram(l->prog);
    l->gl->glUniform1i(l->u_n, (GLint)n);
    if (n) {
        l->gl->glUniform4fv(l->u_pos, (GLsizei)n, fp);
        l->gl->glUniform4fv(l->u_col, (GLsizei)n, fc);
    }
    l->gl->glUniform3f(l->u_ambient, (float)amb[0], (float)amb[1], (float)amb[2]);
    l->gl->glUniform1i(l->u_sampler, 0);
    l->gl->glUniform1i(l->u_tex, 0);
    l->gl->glUniform1i(l->u_shadows, sh != NULL);
    if (sh) {
        float S[16 * GLS_MAX_LIGHTS], bias[GLS_MAX_LIGHTS];
        uint32_t m = gls_shadows_uniforms(sh, S, bias);
        if (m) {
            l->gl->glUniformMatrix4fv(l->u_smat, (GLsizei)m, GL_FALSE, S);
            l->gl->glUniform1fv(l->u_sbias, (GLsizei)m, bias);
        }
        if (l->cubes)
            cube_uniforms(l, c, sh);
        gls_shadows_bind(sh);
    }
}

void gls_lighting_key(gls_lighting *l, const gls_drawkey *k)
{
    l->gl->glUniform1i(l->u_tex, k->texture == GLS_NONE ? 0 : k->mode == GLS_MODE_REPLACE ? 1 : 2);
}

void gls_lighting_end(gls_lighting *l) { l->gl->glUseProgram(0); }

void gls_lighting_destroy(gls_lighting *l)
{
    if (!l)
        return;
    if (l->prog)
        l->gl->glDeleteProgram(l->prog);
    free(l);
}
