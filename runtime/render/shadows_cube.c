/* Point lights' cube-map geometry (shadows_cube.h). */
#include <math.h>
#include <string.h>
#include "shadows_cube.h"

/* Rows of each face's R (world to the face camera's x, y, z): x_c = s_c,
 * y_c = -t_c, z_c = the major axis m_a of table 8.19; all six are proper
 * rotations. */
static const double face_R[6][9] = {
    {0, 0, -1, 0, 1, 0, 1, 0, 0},  /* +X: s_c = -r_z, t_c = -r_y */
    {0, 0, 1, 0, 1, 0, -1, 0, 0},  /* -X: s_c = +r_z, t_c = -r_y */
    {1, 0, 0, 0, 0, -1, 0, 1, 0},  /* +Y: s_c = +r_x, t_c = +r_z */
    {1, 0, 0, 0, 0, 1, 0, -1, 0},  /* -Y: s_c = +r_x, t_c = -r_z */
    {1, 0, 0, 0, 1, 0, 0, 0, 1},   /* +Z: s_c = +r_x, t_c = -r_y */
    {-1, 0, 0, 0, 1, 0, 0, 0, -1}, /* -Z: s_c = -r_x, t_c = -r_y */
};

void gls_cube_face_camera(const double X[3], int f, double near, gls_camera *c)
{
    memset(c, 0, sizeof *c);
    memcpy(c->R, face_R[f], sizeof c->R);
    for (int i = 0; i < 3; i++) /* T = -R X: entries 0 and +-1, exact */
        c->T[i] = -(c->R[3 * i] * X[0] + c->R[3 * i + 1] * X[1] + c->R[3 * i + 2] * X[2]);
    c->fx = c->fy = 1, c->near = near, c->far = INFINITY;
}

void gls_cube_projection(double near, double P[16])
{
    /* eye (xe, ye, ze) = (x_c, -y_c, -z_c): x_ndc = x_c / z_c = s_c / m_a,
     * y_ndc = -y_c / z_c = t_c / m_a; z_clip = near, w_clip = z_c */
    memset(P, 0, 16 * sizeof *P);
    P[0] = 1, P[5] = 1, P[11] = near, P[14] = -1;
}

double gls_cube_near(const gls_scene *s, const double X[3])
{
    double far2 = 0;
    for (uint32_t i = 0; i < s->nitems; i++)
        for (int k = 0; k < 8; k++) {
            const gls_item *it = &s->items[i];
            double d2 = 0;
            for (int j = 0; j < 3; j++) {
                double e = ((k >> j) & 1 ? it->hi[j] : it->lo[j]) - X[j];
                d2 += e * e;
            }
            far2 = fmax(far2, d2);
        }
    double n = GLS_CUBE_NEAR_FRACTION * sqrt(far2);
    return n > 0 ? n : 1e-9;
}
