/* Issue 30's scattered scene, shared by bench/play_bench.c (which writes
 * it as a bundle for glsplay) and bench/play_floor.c (which draws the same
 * triangles in one vertex buffer): 100,000 triangles of random colours,
 * their corners within 40 units of a centre drawn uniformly in a cube of
 * 5,400 units, so that nearly every 64-unit cell holds one triangle (the
 * issue: 92,433 chunks); CL_NCAM cameras around it, 640x480.
 * Deterministic. */
#ifndef GLS_CLOUD_SCENE_H
#define GLS_CLOUD_SCENE_H
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "camera.h"

#define CL_NTRI 100000
#define CL_SIDE 5400.0
#define CL_NCAM 20
#define CL_W 640
#define CL_H 480

static uint64_t cl_state;
static double cl_rand(void) /* 0 <= x < 1 */
{
    cl_state = cl_state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(cl_state >> 11) / 9007199254740992.0;
}

/* Every triangle in order: p[9 * k ..] its corners, rgb[9 * k ..] their
 * colours (0..1). */
static void cl_triangles(double *p, float *rgb)
{
    cl_state = 20261128;
    for (int k = 0; k < CL_NTRI; k++) {
        double m[3];
        for (int j = 0; j < 3; j++)
            m[j] = (cl_rand() - 0.5) * CL_SIDE;
        for (int v = 0; v < 3; v++)
            for (int j = 0; j < 3; j++) {
                p[9 * k + 3 * v + j] = m[j] + (cl_rand() - 0.5) * 80;
                rgb[9 * k + 3 * v + j] = (float)cl_rand();
            }
    }
}

/* Camera k of CL_NCAM: 6,000 units from the cube's centre, level, turned
 * k / CL_NCAM of a circle about the vertical, looking at the centre. */
static gls_camera cl_camera(int k)
{
    gls_camera c;
    memset(&c, 0, sizeof c);
    c.width = CL_W, c.height = CL_H;
    c.fx = c.fy = 500, c.cx = 319.5, c.cy = 239.5;
    double a = 2 * M_PI * k / CL_NCAM, s = sin(a), co = cos(a);
    /* camera rows: x = (cos a, 0, sin a), y = (0, -1, 0) (world y up),
     * z = x cross y = (sin a, 0, -cos a), the way it looks; its centre
     * 6,000 units back from the cube's centre along it */
    double R[9] = {co, 0, s, 0, -1, 0, s, 0, -co};
    double C[3] = {-6000 * s, 0, 6000 * co};
    memcpy(c.R, R, sizeof R);
    for (int i = 0; i < 3; i++)
        c.T[i] = -(R[3 * i] * C[0] + R[3 * i + 1] * C[1] + R[3 * i + 2] * C[2]);
    c.near = 1, c.far = 20000;
    return c;
}
#endif
