/* bench-play, player side: the bench scene as a bundle (one qstrip per
 * grid column, per-vertex colours), flattened and drawn by the runtime
 * with the colour and depth read-backs of every frame (the player's
 * gls_render_read_z also converts depth to Zc).  Prints "player FPS".
 *
 * usage: play_bench [--backend B]   render PS_FRAMES frames through GL
 *                                   backend B (default auto)
 *        play_bench --write DIR     write the scene for glsplay instead:
 *                                   DIR/terrain.glsb, DIR/rig.cam (pose rig,
 *                                   the identity) and DIR/trajectory.txt (the
 *                                   camera path), for make bench-backends
 *        play_bench --write-cloud DIR  write issue 30's scattered scene
 *                                   (cloud_scene.h): DIR/cloud.glsb and
 *                                   DIR/cam_00.cam .. cam_19.cam, and
 *                                   DIR/cloud.pov (POV-Ray, camera 0) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "player_scene.h"
#include "play_bundle.h"
#include "cloud_scene.h"

/* The same triangles for POV-Ray 3.7 (make bench-play's comparison):
 * DIR/cloud.pov, seen by camera 0.  The vertices are taken into that
 * camera's frame (x right, y down, z forward) and y is turned up, which
 * is POV-Ray's left-handed camera at the origin looking along +z: up 1 is
 * the image's height, right W/H its width, direction fy/H.  One mesh2,
 * POV-Ray's fastest form, and each triangle one flat colour (its first
 * corner's; glsplay interpolates three): the cheaper case for POV-Ray. */
static int write_cloud_pov(const char *dir, const double *p, const float *rgb)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/cloud.pov", dir);
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    gls_camera c = cl_camera(0);
    fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\nbackground { rgb 0 }\n");
    fprintf(f, "camera { perspective location <0, 0, 0> up <0, 1, 0> right <%.17g, 0, 0> direction <0, 0, %.17g> }\n",
            (double)c.width / c.height, c.fy / c.height);
    fprintf(f, "mesh2 {\n vertex_vectors { %d", 3 * CL_NTRI);
    for (int k = 0; k < 3 * CL_NTRI; k++) {
        const double *x = p + 3 * k;
        double q[3];
        for (int i = 0; i < 3; i++)
            q[i] = c.R[3 * i] * x[0] + c.R[3 * i + 1] * x[1] + c.R[3 * i + 2] * x[2] + c.T[i];
        fprintf(f, ",\n<%.9g, %.9g, %.9g>", q[0], -q[1], q[2]);
    }
    fprintf(f, " }\n texture_list { %d", CL_NTRI);
    for (int k = 0; k < CL_NTRI; k++)
        fprintf(f, ",\ntexture { pigment { rgb <%.6g, %.6g, %.6g> } finish { emission 1 diffuse 0 } }", rgb[9 * k],
                rgb[9 * k + 1], rgb[9 * k + 2]);
    fprintf(f, " }\n face_indices { %d", CL_NTRI);
    for (int k = 0; k < CL_NTRI; k++)
        fprintf(f, ",\n<%d, %d, %d>, %d", 3 * k, 3 * k + 1, 3 * k + 2, k);
    fprintf(f, " }\n}\n");
    return fclose(f) ? -1 : 0;
}

/* Issue 30's scattered scene (cloud_scene.h) as glsplay's inputs:
 * DIR/cloud.glsb and DIR/cam_K.cam for each of its cameras. */
static int write_cloud(const char *dir)
{
    char path[4096];
    double *p = malloc(9 * sizeof *p * CL_NTRI);
    float *rgb = malloc(9 * sizeof *rgb * CL_NTRI);
    if (!p || !rgb)
        return -1;
    cl_triangles(p, rgb);
    tb t;
    tb_init(&t);
    tb_object(&t, "cloud", 1);
    for (int k = 0; k < CL_NTRI; k++) {
        gls_vec4 v[3];
        gls_rgba c[3];
        for (int q = 0; q < 3; q++) {
            const double *x = p + 9 * k + 3 * q;
            const float *f = rgb + 9 * k + 3 * q;
            v[q] = (gls_vec4){x[0], x[1], x[2], 1};
            c[q] = (gls_rgba){f[0], f[1], f[2], 1};
        }
        tb_prim4(&t, GLS_PRIM_POLY, 3, v, c, NULL);
    }
    int pov = write_cloud_pov(dir, p, rgb);
    free(p), free(rgb);
    gls_bundle *b = tb_finish(&t);
    snprintf(path, sizeof path, "%s/cloud.glsb", dir);
    int bad = tb_write(b, path);
    gls_bundle_free(b);
    for (int k = 0; k < CL_NCAM && !bad; k++) {
        gls_camera c = cl_camera(k);
        snprintf(path, sizeof path, "%s/cam_%02d.cam", dir, k);
        bad = tb_write_camera(&c, path);
    }
    return bad || pov ? -1 : 0;
}

/* The scene, a rig camera and the camera path as glsplay's inputs. */
static int write_inputs(const char *dir)
{
    char path[4096];
    gls_bundle *b = ps_bundle();
    snprintf(path, sizeof path, "%s/terrain.glsb", dir);
    int bad = tb_write(b, path);
    gls_bundle_free(b);
    gls_camera c = ps_camera(0);
    static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    memcpy(c.R, I, sizeof c.R);
    c.T[0] = c.T[1] = c.T[2] = 0;
    snprintf(path, sizeof path, "%s/rig.cam", dir);
    FILE *f = NULL;
    bad = bad || tb_write_camera(&c, path) || !(f = fopen(path, "a")) || fprintf(f, "pose rig\n") < 0;
    if (f && fclose(f))
        bad = 1;
    snprintf(path, sizeof path, "%s/trajectory.txt", dir);
    f = bad ? NULL : fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "# glsroad trajectory 1\n");
    for (int k = 0; k < PS_FRAMES; k++) {
        gls_camera ck = ps_camera(k);
        fprintf(f, "%d %.17g", k, k / 25.0);
        for (int i = 0; i < 9; i++)
            fprintf(f, " %.17g", ck.R[i]);
        fprintf(f, " %.17g %.17g %.17g\n", ck.T[0], ck.T[1], ck.T[2]);
    }
    return fclose(f);
}

int main(int argc, char **argv)
{
    char err[256];
    gls_backend backend = GLS_BACKEND_AUTO;
    if (argc == 3 && strcmp(argv[1], "--write-cloud") == 0) {
        if (write_cloud(argv[2])) {
            fprintf(stderr, "play_bench: cannot write to %s\n", argv[2]);
            return 1;
        }
        return 0;
    }
    if (argc == 3 && strcmp(argv[1], "--write") == 0) {
        if (write_inputs(argv[2])) {
            fprintf(stderr, "play_bench: cannot write to %s\n", argv[2]);
            return 1;
        }
        return 0;
    }
    if (argc == 3 && strcmp(argv[1], "--backend") == 0 && gls_backend_parse(argv[2], &backend) == 0)
        argc -= 2;
    if (argc != 1) {
        fprintf(stderr, "usage: play_bench [--backend B] | --write DIR | --write-cloud DIR\n");
        return 2;
    }
    gls_glctx *ctx = gls_glctx_create(backend, err, sizeof err);
    if (!ctx) {
        fprintf(stderr, "play_bench: %s\n", err);
        return 1;
    }
    gls_bundle *b = ps_bundle();
    gls_scene sc;
    if (gls_scene_flatten(b, &sc, err, sizeof err)) {
        fprintf(stderr, "play_bench: %s\n", err);
        return 1;
    }
    gls_renderer *r = gls_renderer_create(ctx, b, &sc, err, sizeof err);
    if (!r || gls_renderer_set_size(r, PS_W, PS_H, err, sizeof err)) {
        fprintf(stderr, "play_bench: %s\n", err);
        return 1;
    }
    uint8_t *rgba = malloc((size_t)PS_W * PS_H * 4);
    float *z = malloc((size_t)PS_W * PS_H * 4);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (int f = 0; f < PS_FRAMES; f++) {
        gls_camera cam = ps_camera(f);
        gls_render_pass(r, &cam, 0, 0);
        gls_render_read_rgba(r, rgba);
        gls_render_read_z(r, z);
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    ps_dump(rgba);
    double s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    printf("player %.2f triangles %u chunks %u renderer %s\n", PS_FRAMES / s, sc.nverts / 3, sc.nchunks,
           gls_renderer_gl_name(r));
    free(rgba), free(z);
    gls_renderer_destroy(r);
    gls_scene_free(&sc);
    gls_bundle_free(b);
    gls_glctx_destroy(ctx);
    return 0;
}
