/* Small double-precision vector and matrix helpers, the generic ones every
 * layer uses (the road geometry, the camera model, rotation checks, the
 * scene's transform stack): rv3 is a 3-vector; rm_ functions take
 * row-major 3x3 matrices, double[9] with m[3*r + c]; m4_ functions
 * row-major 4x4 matrices, double[16].  Sums are formed left to right, the
 * order every caller has always used, so results are bit-identical. */
#ifndef GLS_VEC_H
#define GLS_VEC_H
#include <math.h>

typedef struct {
    double x, y, z;
} rv3;

static inline rv3 rv(double x, double y, double z)
{
    rv3 v = {x, y, z};
    return v;
}
static inline rv3 rv_add(rv3 a, rv3 b) { return rv(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline rv3 rv_sub(rv3 a, rv3 b) { return rv(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline rv3 rv_mul(rv3 a, double k) { return rv(a.x * k, a.y * k, a.z * k); }
static inline rv3 rv_madd(rv3 a, rv3 b, double k) { return rv(a.x + b.x * k, a.y + b.y * k, a.z + b.z * k); }
static inline double rv_dot(rv3 a, rv3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline rv3 rv_cross(rv3 a, rv3 b)
{
    return rv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double rv_len(rv3 a) { return sqrt(rv_dot(a, a)); }
static inline rv3 rv_unit(rv3 a)
{
    double l = rv_len(a);
    return l > 0 ? rv_mul(a, 1 / l) : a;
}

/* Distance from p to the segment [a, b]. */
static inline double rv_seg_dist(rv3 p, rv3 a, rv3 b)
{
    rv3 ab = rv_sub(b, a), ap = rv_sub(p, a);
    double L2 = rv_dot(ab, ab);
    double t = L2 > 0 ? rv_dot(ap, ab) / L2 : 0;
    if (t < 0)
        t = 0;
    if (t > 1)
        t = 1;
    return rv_len(rv_sub(ap, rv_mul(ab, t)));
}

/* C = A * B (3x3, row-major). */
static inline void rm_mul(const double A[9], const double B[9], double C[9])
{
    double t[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            t[3 * r + c] = A[3 * r] * B[c] + A[3 * r + 1] * B[3 + c] + A[3 * r + 2] * B[6 + c];
    for (int i = 0; i < 9; i++)
        C[i] = t[i];
}
static inline void rm_transpose(const double A[9], double B[9])
{
    double t[9] = {A[0], A[3], A[6], A[1], A[4], A[7], A[2], A[5], A[8]};
    for (int i = 0; i < 9; i++)
        B[i] = t[i];
}
static inline rv3 rm_apply(const double A[9], rv3 v)
{
    return rv(A[0] * v.x + A[1] * v.y + A[2] * v.z, A[3] * v.x + A[4] * v.y + A[5] * v.z,
              A[6] * v.x + A[7] * v.y + A[8] * v.z);
}
/* A^T v */
static inline rv3 rm_apply_t(const double A[9], rv3 v)
{
    return rv(A[0] * v.x + A[3] * v.y + A[6] * v.z, A[1] * v.x + A[4] * v.y + A[7] * v.z,
              A[2] * v.x + A[5] * v.y + A[8] * v.z);
}
static inline double rm_det(const double A[9])
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}
/* The matrix whose columns are a, b, c. */
static inline void rm_cols(rv3 a, rv3 b, rv3 c, double M[9])
{
    M[0] = a.x, M[1] = b.x, M[2] = c.x;
    M[3] = a.y, M[4] = b.y, M[5] = c.y;
    M[6] = a.z, M[7] = b.z, M[8] = c.z;
}

/* C = A * B (4x4, row-major); C may be A or B. */
static inline void m4_mul(const double A[16], const double B[16], double C[16])
{
    double t[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            t[4 * i + j] = A[4 * i] * B[j] + A[4 * i + 1] * B[4 + j] + A[4 * i + 2] * B[8 + j] + A[4 * i + 3] * B[12 + j];
    for (int i = 0; i < 16; i++)
        C[i] = t[i];
}
/* N: the direction of M^-T for the upper 3x3 of the 4x4 row-major A,
 * which carries normals: the cofactor matrix times the sign of the
 * determinant (no division, so a tiny scale loses nothing; the caller
 * normalises). */
static inline void m4_normal_matrix(const double A[16], double N[9])
{
    double d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            N[3 * i + j] = A[4 * i1 + j1] * A[4 * i2 + j2] - A[4 * i1 + j2] * A[4 * i2 + j1];
        }
    for (int j = 0; j < 3; j++)
        d += A[j] * N[j];
    if (d < 0)
        for (int i = 0; i < 9; i++)
            N[i] = -N[i];
}
/* r = A v for a homogeneous 4-vector (x, y, z, w). */
static inline void m4_apply(const double A[16], double x, double y, double z, double w, double r[4])
{
    for (int i = 0; i < 4; i++)
        r[i] = A[4 * i] * x + A[4 * i + 1] * y + A[4 * i + 2] * z + A[4 * i + 3] * w;
}
#endif
