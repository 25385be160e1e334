/* The benchmark scene of bench/play_scene.h as a bundle (one quad strip
 * per grid row, per-vertex colours), for bench/play_bench.c and
 * bench/aa_bench.c.  Needs tests/unit/player_scene.h (the tb builder). */
#ifndef GLS_PLAY_BUNDLE_H
#define GLS_PLAY_BUNDLE_H
#include <stdlib.h>
#include "play_scene.h"

static gls_bundle *ps_bundle(void)
{
    tb t;
    tb_init(&t);
    tb_object(&t, "terrain", 1);
    gls_vec4 *p = malloc(2 * (PS_N + 1) * sizeof *p);
    gls_rgba *c = malloc(2 * (PS_N + 1) * sizeof *c);
    for (int i = 0; i < PS_N; i++) {
        for (int j = 0; j <= PS_N; j++)
            for (int s = 0; s < 2; s++) {
                double q[3];
                float col[4];
                ps_vertex(i + s, j, q, col);
                p[2 * j + s] = (gls_vec4){q[0], q[1], q[2], 1};
                c[2 * j + s] = (gls_rgba){col[0], col[1], col[2], col[3]};
            }
        tb_prim4(&t, GLS_PRIM_QSTRIP, 2 * (PS_N + 1), p, c, NULL);
    }
    free(p), free(c);
    return tb_finish(&t);
}
#endif
