/* The floor for bench-play: the bench scene's triangles in one vertex
 * buffer, world coordinates as float, one draw call per frame, through the
 * same OSMesa context, the same FBO (RGBA8 + 32F depth, reversed Z) and
 * the same read-backs (colour and depth) as the player.  Nothing a real
 * player could skip, in the order that draws fastest.  Prints "floor FPS".
 * With --random, the same triangles in bench/random_order.h's order (what
 * a floor that draws triangles as given makes of instances_bench's
 * random-order scene).
 * With --cloud N DIR: issue 30's floor for a whole process: issue 30's
 * scattered scene (cloud_scene.h) in one vertex buffer, cameras 0..N-1
 * each drawn once, its colour read back and written as
 * DIR/image_K.png (the player's PNG encoder, rows top first); make
 * bench-play times the whole process. */
#include <GL/gl.h>
#include <GL/glext.h>
#include "glcalls.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "glctx.h"
#include "cloud_scene.h"
#include "outputs.h"
#include "play_scene.h"
#include "random_order.h"
#include "render.h"

#define LOAD(type, name) type name = (type)(uintptr_t)gls_glctx_proc(ctx, #name)

typedef struct {
    float p[3];
    uint8_t c[4];
} vert;

/* *v = grid vertex (i, j) as a float position and an RGBA8 colour. */
static void put_vertex(vert *v, int i, int j)
{
    double p[3];
    float c[4];
    ps_vertex(i, j, p, c);
    for (int a = 0; a < 3; a++) {
        v->p[a] = (float)p[a];
        v->c[a] = (uint8_t)lrint(c[a] * 255.0);
    }
    v->c[3] = 255;
}

/* The cloud's triangles as float vertices in v (3 * CL_NTRI). */
static int cloud_vertices(vert *v)
{
    double *p = malloc(9 * sizeof *p * CL_NTRI);
    float *rgb = malloc(9 * sizeof *rgb * CL_NTRI);
    if (!p || !rgb)
        return -1;
    cl_triangles(p, rgb);
    for (size_t k = 0; k < 3 * (size_t)CL_NTRI; k++) {
        for (int a = 0; a < 3; a++) {
            v[k].p[a] = (float)p[3 * k + a];
            v[k].c[a] = (uint8_t)lrint(rgb[3 * k + a] * 255.0);
        }
        v[k].c[3] = 255;
    }
    free(p), free(rgb);
    return 0;
}

/* Draw camera c's view of the nv vertices bound, read its colour back into
 * rgba (rows top first) and write it as PNG to path. */
static int cloud_frame(const gls_camera *c, size_t nv, uint8_t *rgba, uint8_t *row, const char *path)
{
    double P[16], MV[16], zero[3] = {0, 0, 0};
    float m[16];
    gls_camera_projection(c, 0, 0, P);
    gls_mat_to_gl(P, m);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(m);
    gls_camera_modelview(c, zero, MV);
    gls_mat_to_gl(MV, m);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(m);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, (GLsizei)nv);
    glReadPixels(0, 0, CL_W, CL_H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    size_t rb = 4 * (size_t)CL_W;
    for (int y = 0; y < CL_H / 2; y++) {
        memcpy(row, rgba + y * rb, rb);
        memcpy(rgba + y * rb, rgba + (CL_H - 1 - y) * rb, rb);
        memcpy(rgba + (CL_H - 1 - y) * rb, row, rb);
    }
    gls_buf png = {0};
    FILE *f = NULL;
    int bad = gls_encode_png(rgba, CL_W, CL_H, &png) || !(f = fopen(path, "wb")) ||
              fwrite(png.data, 1, png.len, f) != png.len;
    if (f && fclose(f))
        bad = 1;
    free(png.data);
    return bad ? -1 : 0;
}

int main(int argc, char **argv)
{
    char err[256];
    int random = argc == 2 && strcmp(argv[1], "--random") == 0;
    int cloud = argc == 4 && strcmp(argv[1], "--cloud") == 0;
    int ncam = cloud ? atoi(argv[2]) : 0;
    if ((argc > 1 && !random && !cloud) || (cloud && (ncam < 1 || ncam > CL_NCAM))) {
        fprintf(stderr, "usage: play_floor [--random | --cloud N DIR]\n");
        return 2;
    }
    gls_glctx *ctx = gls_glctx_create(GLS_BACKEND_AUTO, err, sizeof err);
    if (!ctx) {
        fprintf(stderr, "play_floor: %s\n", err);
        return 1;
    }
    LOAD(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers);
    LOAD(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer);
    LOAD(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers);
    LOAD(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer);
    LOAD(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage);
    LOAD(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer);
    LOAD(PFNGLCLIPCONTROLPROC, glClipControl);
    LOAD(PFNGLGENBUFFERSPROC, glGenBuffers);
    LOAD(PFNGLBINDBUFFERPROC, glBindBuffer);
    LOAD(PFNGLBUFFERDATAPROC, glBufferData);
    size_t nv = cloud ? 3 * (size_t)CL_NTRI : (size_t)PS_N * PS_N * 6, k = 0;
    vert *v = malloc(nv * sizeof *v);
    if (!v || (cloud && cloud_vertices(v)))
        return 1;
    /* Quads in 32 x 32 blocks rather than row by row: llvmpipe bins
     * spatially coherent triangles faster (measured on this bench: row
     * order 52 fps, 32-blocks 63 fps), and a floor must be the fastest
     * plain way to draw these triangles, or the player could beat it by
     * ordering alone (its chunks are spatial cells). */
    const int blk = 32;
    uint32_t *order = random ? ro_order() : NULL;
    if (random && !order)
        return 1;
    for (uint32_t t = 0; random && t < RO_NTRI; t++)
        for (int q = 0; q < 3; q++) {
            int i, j;
            ro_corner(order[t], q, &i, &j);
            put_vertex(&v[k++], i, j);
        }
    free(order);
    for (int bi = 0; !random && !cloud && bi < PS_N; bi += blk)
    for (int bj = 0; bj < PS_N; bj += blk)
    for (int i = bi; i < bi + blk && i < PS_N; i++)
        for (int j = bj; j < bj + blk && j < PS_N; j++) {
            static const int corner[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
            for (int q = 0; q < 6; q++)
                put_vertex(&v[k++], i + corner[q][0], j + corner[q][1]);
        }
    GLuint fbo, rb[2], vbo;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, cloud ? CL_W : PS_W, cloud ? CL_H : PS_H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, cloud ? CL_W : PS_W, cloud ? CL_H : PS_H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    glViewport(0, 0, cloud ? CL_W : PS_W, cloud ? CL_H : PS_H);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glClearDepth(0);
    glDepthFunc(GL_GREATER);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0, 0, 0, 1);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nv * sizeof *v), v, GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof *v, (void *)0);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof *v, (void *)offsetof(vert, c));
    if (cloud) {
        uint8_t *img = malloc((size_t)CL_W * CL_H * 4), *row = malloc(4 * (size_t)CL_W);
        char path[4096];
        int bad = !img || !row;
        for (int c = 0; c < ncam && !bad; c++) {
            gls_camera cam = cl_camera(c);
            snprintf(path, sizeof path, "%s/image_%02d.png", argv[3], c);
            bad = cloud_frame(&cam, nv, img, row, path);
        }
        free(img), free(row), free(v);
        gls_glctx_destroy(ctx);
        if (bad)
            fprintf(stderr, "play_floor: cannot write to %s\n", argv[3]);
        return bad;
    }
    uint8_t *rgba = malloc((size_t)PS_W * PS_H * 4);
    float *depth = malloc((size_t)PS_W * PS_H * 4);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (int f = 0; f < PS_FRAMES; f++) {
        gls_camera c = ps_camera(f);
        double P[16], MV[16], zero[3] = {0, 0, 0};
        float m[16];
        gls_camera_projection(&c, 0, 0, P);
        gls_mat_to_gl(P, m);
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(m);
        gls_camera_modelview(&c, zero, MV);
        gls_mat_to_gl(MV, m);
        glMatrixMode(GL_MODELVIEW);
        glLoadMatrixf(m);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLES, 0, (GLsizei)nv);
        glReadPixels(0, 0, PS_W, PS_H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        glReadPixels(0, 0, PS_W, PS_H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    ps_dump(rgba);
    double s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    printf("floor %.2f\n", PS_FRAMES / s);
    free(v), free(rgba), free(depth);
    gls_glctx_destroy(ctx);
    return 0;
}
