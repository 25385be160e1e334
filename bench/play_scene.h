/* The benchmark scene shared by bench/play_bench.c and bench/play_floor.c:
 * a 224 x 224 quad height field (100352 triangles, per-vertex colours)
 * spanning 200 x 200 units, and a camera path over it.  Deterministic. */
#ifndef GLS_PLAY_SCENE_H
#define GLS_PLAY_SCENE_H
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "camera.h"

#define PS_N 224
#define PS_SIZE 200.0
#define PS_W 640
#define PS_H 480
#define PS_FRAMES 200

static double ps_height(int i, int j)
{
    return 2.0 * sin(i * 0.11) * cos(j * 0.07) + 0.5 * sin(i * 0.9 + j * 1.3);
}

/* Grid vertex (i, j): world position and colour. */
static void ps_vertex(int i, int j, double p[3], float c[4])
{
    p[0] = -PS_SIZE / 2 + PS_SIZE * i / PS_N;
    p[1] = ps_height(i, j);
    p[2] = 5 + PS_SIZE * j / PS_N;
    c[0] = (float)(0.3 + 0.3 * sin(i * 0.2));
    c[1] = (float)(0.5 + 0.4 * cos(j * 0.15));
    c[2] = (float)(0.2 + 0.2 * sin((i + j) * 0.1));
    c[3] = 1;
}

/* Camera of frame k: 6 units above the ground (world y is up) looking
 * along world +z, pitched down, drifting sideways; OpenCV camera frame:
 * x right (= world -x here), y down, z forward. */
static gls_camera ps_camera(int k)
{
    gls_camera c;
    memset(&c, 0, sizeof c);
    c.width = PS_W, c.height = PS_H;
    c.fx = c.fy = 500, c.cx = 319.5, c.cy = 239.5;
    double t = 0.25; /* pitch down */
    /* world y is up: camera y (down) = -world y */
    double R[9] = {-1, 0, 0, 0, -cos(t), -sin(t), 0, -sin(t), cos(t)};
    memcpy(c.R, R, sizeof R);
    double C[3] = {-20 + 0.2 * k, 6, -10};
    for (int i = 0; i < 3; i++)
        c.T[i] = -(R[3 * i] * C[0] + R[3 * i + 1] * C[1] + R[3 * i + 2] * C[2]);
    c.near = 0.1, c.far = 1000;
    return c;
}

/* BENCH_DUMP=FILE: the last frame as raw RGBA, for comparing the player's
 * image with the floor's. */
static inline void ps_dump(const uint8_t *rgba)
{
    const char *path = getenv("BENCH_DUMP");
    FILE *df = path ? fopen(path, "wb") : NULL;
    if (df) {
        fwrite(rgba, 4, (size_t)PS_W * PS_H, df);
        fclose(df);
    }
}
#endif
