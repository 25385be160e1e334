/* glsplay --explain: the rendering plan, derived from the bundle's
 * feature bits (which the reader has checked against the content). */
#include "player.h"

/* The GL effect each feature switches on, by feature bit; the asserts keep
 * the indices in step with bundle.h. */
_Static_assert(GLS_FEAT_TEXTURES == 1u << 0 && GLS_FEAT_ALPHA_TEST == 1u << 1 &&
                   GLS_FEAT_VERTEX_COLOR == 1u << 2 && GLS_FEAT_TEXCOORDS == 1u << 3 &&
                   GLS_FEAT_HOMOGENEOUS == 1u << 4 && GLS_FEAT_MODULATE == 1u << 5 &&
                   GLS_FEAT_REPLACE == 1u << 6 && GLS_FEAT_TRANSLUCENT == 1u << 7,
               "feature bits moved: update effect[]");
static const char *const effect[32] = {
    [0] = "GL_TEXTURE_2D, RGBA8 textures with mipmaps (GL_LINEAR_MIPMAP_LINEAR)",
    [1] = "GL_ALPHA_TEST, glAlphaFunc(GL_GEQUAL, 0.5): texels with alpha 0 are holes",
    [2] = "GL_COLOR_ARRAY (RGBA8 per vertex); otherwise one glColor per batch",
    [3] = "GL_TEXTURE_COORD_ARRAY (float s, t); otherwise texcoord (0, 0)",
    [4] = "none: positions are divided by w in double at load",
    [5] = "glTexEnv GL_MODULATE (texture times colour)",
    [6] = "glTexEnv GL_REPLACE (texture colour only)",
    [7] = "none: alpha is not blended, surfaces are drawn opaque (outputs are RGB)",
};

void gls_explain(FILE *out, const char *bundle_path, const gls_bundle *b, const gls_scene *s,
                 const gls_camera *cams, const char *const *names, size_t n, unsigned outputs)
{
    fprintf(out, "plan for %s: top object '%s', %u objects, %u textures, %u positions\n", bundle_path,
            b->objects[b->top].name, b->nobjects, b->ntextures, b->npos);
    fprintf(out, "geometry: %u triangles in %u chunks (cells of %g units, double anchors), %u state batches",
            s->nverts / 3, s->nchunks, GLS_SCENE_CELL, s->nbatches);
    if (s->dropped)
        fprintf(out, ", %llu triangles dropped (vertex at infinity)", (unsigned long long)s->dropped);
    fprintf(out, "\n");
    fprintf(out, "always on: reversed-Z depth test (GL_DEPTH_COMPONENT32F, cleared to 0, GL_GREATER, "
                 "glClipControl GL_ZERO_TO_ONE); FBO with RGBA8 colour; clear colour black\n");
    fprintf(out, "features (bundle bits %#x):\n", b->features);
    for (unsigned bit = 0; bit < 32; bit++) {
        if (!gls_feature_name[bit])
            continue;
        int on = (b->features >> bit) & 1u;
        fprintf(out, "  %-14s %-3s %s\n", gls_feature_name[bit], on ? "on" : "off",
                on ? gls_feature_why[bit] : "not used by this bundle");
        if (on && effect[bit])
            fprintf(out, "  %-14s     GL: %s\n", "", effect[bit]);
    }
    fprintf(out, "passes: 1 per camera and frame (no anti-aliasing), jitter (0, 0)\n");
    if (!n) {
        fprintf(out, "cameras: none given\n");
        return;
    }
    for (size_t i = 0; i < n; i++) {
        const gls_camera *c = &cams[i];
        fprintf(out, "camera %s: %ux%u fx %g fy %g cx %g cy %g skew %g near %g far %g\n", names[i], c->width,
                c->height, c->fx, c->fy, c->cx, c->cy, c->skew, c->near, c->far);
        fprintf(out, "  reads back: %s%s%s\n",
                outputs & (GLS_OUT_IMAGE | GLS_OUT_POINTS) ? "colour (RGBA8) " : "",
                outputs & (GLS_OUT_DEPTH | GLS_OUT_POINTS) ? "depth (float32) " : "",
                outputs ? "" : "nothing");
        fprintf(out, "  writes:%s%s%s\n", outputs & GLS_OUT_IMAGE ? " image (PNG)" : "",
                outputs & GLS_OUT_DEPTH ? " depth (PFM, Zc)" : "",
                outputs & GLS_OUT_POINTS ? " points (PLY, world, double)" : "");
    }
}
