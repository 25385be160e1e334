/* bench-play, player side: the bench scene as a bundle (one qstrip per
 * grid column, per-vertex colours), flattened and drawn by the runtime
 * with the colour and depth read-backs of every frame (the player's
 * gls_render_read_z also converts depth to Zc).  Prints "player FPS". */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "player_scene.h"
#include "play_bundle.h"

int main(void)
{
    char err[256];
    gls_glctx *ctx = gls_glctx_create(1, 1, err, sizeof err);
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
