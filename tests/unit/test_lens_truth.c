/* Flow and boxes through a lens at the model's fold (runtime/truth/lens_truth.c,
 * spec/outputs.md "Through a lens"), against closed forms: a Brown lens
 * k1 = -0.3 has r (1 + k1 r^2) rising up to r^2 = 1 / (3 |k1|) = 10/9 and
 * folding back beyond, where OpenCV's formula would bring a point far off
 * axis back into the image.  Such a point has no flow (mask out) and a
 * box there counts as wholly outside the image. */
#include <math.h>
#include <string.h>
#include "check.h"
#include "distort.h"
#include "lens_truth.h"

/* 80 x 80, fx = fy = 100, centred, identity pose, k1 = -0.3: the image's
 * corners have rays well inside the fold (distorted radius 0.57 < 0.70) */
static gls_camera lens_camera(void)
{
    gls_camera c;
    memset(&c, 0, sizeof c);
    c.width = c.height = 80;
    c.fx = c.fy = 100;
    c.cx = c.cy = 39.5;
    c.R[0] = c.R[4] = c.R[8] = 1;
    c.near = 0.1, c.far = 100;
    c.dist.model = GLS_LENS_BROWN;
    c.dist.n = 4;
    c.dist.k[0] = -0.3;
    gls_distort_setup(&c.dist);
    return c;
}

static void test_fold_found(void)
{
    gls_camera c = lens_camera();
    CHECK_NEAR(c.dist.max_r2, 10.0 / 9.0, 1e-9);
    char why[300];
    CHECK(gls_distort_check(&c, 0, why, sizeof why) == 0);
}

/* one pixel's flow: its ray (0, 0) at depth 1, the camera at t+1 turned
 * so that the point lies at undistorted x = tan(a) */
static void flow_at(double a, float uv[2], uint8_t *mask)
{
    gls_camera c0 = lens_camera(), c1 = c0;
    c0.width = c0.height = c1.width = c1.height = 1;
    c0.cx = c0.cy = c1.cx = c1.cy = 0;
    /* rotation about y by -a: (0, 0, 1) -> (sin a, 0, cos a) */
    memset(c1.R, 0, sizeof c1.R);
    c1.R[0] = cos(a), c1.R[2] = sin(a), c1.R[4] = 1, c1.R[6] = -sin(a), c1.R[8] = cos(a);
    gls_distort_frame f;
    memset(&f, 0, sizeof f);
    double ray[2] = {0, 0};
    f.ray = ray;
    f.lay.mag = 4;
    uint32_t inst = 1;
    float z = 1, z1 = INFINITY;
    gls_flow_moves m;
    memset(&m, 0, sizeof m);
    gls_flow_compute_lens(&c0, &c1, &f, &inst, &z, &z1, &m, uv, mask);
}

static void test_flow_fold(void)
{
    float uv[2];
    uint8_t mask;
    /* x = tan(a) = 0.5 (r^2 0.25, inside): u = fx x (1 + k1 x^2) */
    flow_at(atan(0.5), uv, &mask);
    CHECK_NEAR(uv[0], 100 * 0.5 * (1 - 0.3 * 0.25), 1e-4);
    CHECK_NEAR(uv[1], 0, 1e-6);
    CHECK(mask == GLS_FLOW_OUT); /* in the lens's model but off the 1 x 1 image */
    /* x = 2 (r^2 4, past the fold): OpenCV's formula gives u = 2 (1 -
     * 1.2) fx = -40, a place in front; there is no image position */
    flow_at(atan(2.0), uv, &mask);
    CHECK(uv[0] == GLS_FLOW_UNKNOWN && uv[1] == GLS_FLOW_UNKNOWN);
    CHECK(mask == GLS_FLOW_OUT);
}

/* a box [x0, x0 + 0.2] x [-0.1, 0.1] x [1, 1.2] in the camera frame */
static double box_truncation(double x0)
{
    gls_camera c = lens_camera();
    double k[8][3];
    for (int i = 0; i < 8; i++) {
        k[i][0] = i & 1 ? x0 + 0.2 : x0;
        k[i][1] = i & 2 ? 0.1 : -0.1;
        k[i][2] = i & 4 ? 1.2 : 1.0;
    }
    return gls_lens_box_truncation(&c, (const double(*)[3])k);
}

static void test_box_fold(void)
{
    /* on the axis, small: wholly inside */
    CHECK(box_truncation(-0.1) == 0);
    /* x from 2 / 1.2 to 2.2: every point past the fold, where OpenCV's
     * formula lands at u = 39.5 + 100 x (1 - 0.3 x^2) in -24..4, inside the
     * image; taken at the fold it is at u = 39.5 + 100 sqrt(10/9) (2/3) =
     * 109.8 or beyond: outside */
    CHECK(box_truncation(2.0) == 1);
    /* x 0.1 to 0.3 at z 1: u up to 39.5 + 100 0.3 (1 - 0.027) = 68.7,
     * inside; x 0.3 to 0.5: up to 39.5 + 100 0.5 (1 - 0.075) = 85.75,
     * across the right edge (79.5): partly truncated */
    CHECK(box_truncation(0.1) == 0);
    double t = box_truncation(0.3);
    CHECK_MSG(t > 0 && t < 1, "truncation %g", t);
    /* behind the near plane entirely: 1 */
    gls_camera c = lens_camera();
    double k[8][3];
    for (int i = 0; i < 8; i++)
        k[i][0] = i & 1 ? 0.1 : 0, k[i][1] = i & 2 ? 0.1 : 0, k[i][2] = i & 4 ? 0.05 : -1;
    CHECK(gls_lens_box_truncation(&c, (const double(*)[3])k) == 1);
}

int main(void)
{
    RUN(test_fold_found);
    RUN(test_flow_fold);
    RUN(test_box_fold);
    CHECK_EXIT();
}
