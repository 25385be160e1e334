/* Clamped NURBS curves: evaluation (Piegl & Tiller) and arc length.
 * See nurbs.h. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "nurbs.h"

const char *nurbs_check(int p, int npts, const double *w, int nknots, const double *U)
{
    if (p < 1 || p > NURBS_MAX_DEGREE)
        return "degree must be 1..9";
    if (npts < p + 1)
        return "a curve of degree p needs at least p + 1 control points";
    for (int i = 0; i < npts; i++)
        if (!(w[i] > 0) || !isfinite(w[i]))
            return "weights must be positive and finite";
    if (nknots != npts + p + 1)
        return "the knot vector must have (number of points) + degree + 1 values";
    for (int i = 0; i < nknots; i++)
        if (!isfinite(U[i]))
            return "knots must be finite";
    for (int i = 1; i < nknots; i++)
        if (U[i] < U[i - 1])
            return "knots must be non-decreasing";
    for (int i = 1; i <= p; i++)
        if (U[i] != U[0] || U[nknots - 1 - i] != U[nknots - 1])
            return "the knot vector must be clamped: its first and last degree + 1 knots equal";
    if (!(U[nknots - 1] > U[0]))
        return "the knot vector spans an empty range";
    /* Interior multiplicity <= p keeps the curve continuous and every
       basis function well defined; p + 1 would split it into two curves. */
    int run = 1;
    for (int i = p + 1; i < nknots - p - 1; i++) {
        run = (U[i] == U[i - 1] && i > p + 1) ? run + 1 : 1;
        if (U[i] == U[p])
            return "an interior knot equals the first knot (the curve would be split)";
        if (U[i] == U[nknots - 1])
            return "an interior knot equals the last knot (the curve would be split)";
        if (run > p)
            return "an interior knot repeats more than degree times (the curve would be split)";
    }
    return NULL;
}

void nurbs_uniform_knots(int p, int npts, double *U)
{
    int m = npts + p; /* last index */
    int nint = npts - p - 1;
    for (int i = 0; i <= p; i++) {
        U[i] = 0;
        U[m - i] = 1;
    }
    for (int j = 1; j <= nint; j++)
        U[p + j] = (double)j / (nint + 1);
}

/* A2.1.  Binary search; the end of the range belongs to the last span so
   that C(U[m]) is the last control point of a clamped curve. */
int nurbs_find_span(int n, int p, double u, const double *U)
{
    if (u >= U[n + 1])
        return n;
    if (u <= U[p])
        return p;
    int low = p, high = n + 1, mid = (low + high) / 2;
    while (u < U[mid] || u >= U[mid + 1]) {
        if (u < U[mid])
            high = mid;
        else
            low = mid;
        mid = (low + high) / 2;
    }
    return mid;
}

/* A2.2 */
void nurbs_basis(int i, double u, int p, const double *U, double *N)
{
    double left[NURBS_MAX_DEGREE + 1], right[NURBS_MAX_DEGREE + 1];
    N[0] = 1.0;
    for (int j = 1; j <= p; j++) {
        left[j] = u - U[i + 1 - j];
        right[j] = U[i + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; r++) {
            double temp = N[r] / (right[r + 1] + left[j - r]);
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
    }
}

/* A2.3.  The denominators ndu[p-k+1][..] and ndu[pk+1][rk] are sums of
   knot differences that include the span [U[i], U[i+1]], which FindSpan
   guarantees is non-empty, so they are never zero, also with repeated
   interior knots. */
void nurbs_ders_basis(int i, double u, int p, int nd, const double *U, double *ders)
{
    enum { P1 = NURBS_MAX_DEGREE + 1 };
    double ndu[P1][P1], a[2][P1], left[P1], right[P1];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; j++) {
        left[j] = u - U[i + 1 - j];
        right[j] = U[i + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; r++) {
            ndu[j][r] = right[r + 1] + left[j - r]; /* lower triangle */
            double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp; /* upper triangle */
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= p; j++)
        ders[j] = ndu[j][p];
    for (int r = 0; r <= p; r++) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= nd; k++) {
            double d = 0.0;
            int rk = r - k, pk = p - k;
            if (k > p) {
                ders[k * (p + 1) + r] = 0;
                continue;
            }
            if (r >= k) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d = a[s2][0] * ndu[rk][pk];
            }
            int j1 = rk >= -1 ? 1 : -rk;
            int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; j++) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k * (p + 1) + r] = d;
            int t = s1;
            s1 = s2;
            s2 = t;
        }
    }
    int r = p;
    for (int k = 1; k <= nd && k <= p; k++) {
        for (int j = 0; j <= p; j++)
            ders[k * (p + 1) + j] *= r;
        r *= p - k;
    }
}

double nurbs_umin(const nurbs *c) { return c->U[c->p]; }
double nurbs_umax(const nurbs *c) { return c->U[c->n + 1]; }

/* A3.2 on the homogeneous points, then A4.2:
   CK[k] = (A(k) - sum_{i=1..k} bin(k,i) w(i) CK[k-i]) / w(0). */
void nurbs_derivs(const nurbs *c, double u, int d, rv3 *CK)
{
    int p = c->p;
    double ders[(NURBS_MAX_DERIV + 1) * (NURBS_MAX_DEGREE + 1)];
    if (d > NURBS_MAX_DERIV)
        d = NURBS_MAX_DERIV;
    if (u < nurbs_umin(c))
        u = nurbs_umin(c);
    if (u > nurbs_umax(c))
        u = nurbs_umax(c);
    int span = nurbs_find_span(c->n, p, u, c->U);
    nurbs_ders_basis(span, u, p, d, c->U, ders);
    double A[NURBS_MAX_DERIV + 1][4];
    for (int k = 0; k <= d; k++) {
        A[k][0] = A[k][1] = A[k][2] = A[k][3] = 0;
        for (int j = 0; j <= p; j++) {
            const double *P = c->Pw + 4 * (span - p + j);
            double N = ders[k * (p + 1) + j];
            for (int q = 0; q < 4; q++)
                A[k][q] += N * P[q];
        }
    }
    static const double bin[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    for (int k = 0; k <= d; k++) {
        rv3 v = rv(A[k][0], A[k][1], A[k][2]);
        for (int i = 1; i <= k; i++)
            v = rv_madd(v, CK[k - i], -bin[k][i] * A[i][3]);
        CK[k] = rv_mul(v, 1.0 / A[0][3]);
    }
}

rv3 nurbs_point(const nurbs *c, double u)
{
    rv3 CK[1];
    nurbs_derivs(c, u, 0, CK);
    return CK[0];
}

static double speed_at(const nurbs *c, double u)
{
    rv3 CK[2];
    nurbs_derivs(c, u, 1, CK);
    return rv_len(CK[1]);
}

/* ---- Gauss-Legendre quadrature ------------------------------------------ */

#define GL_N 12
static double gl_x[GL_N], gl_w[GL_N];
static int gl_ready;

/* Nodes and weights computed by Newton's method on P_n (no hand-typed
   constants to get wrong); accurate to the last bit or two. */
static void gl_init(void)
{
    if (gl_ready)
        return;
    for (int i = 0; i < GL_N; i++) {
        double x = cos(M_PI * (i + 0.75) / (GL_N + 0.5)), dp = 1;
        for (int it = 0; it < 100; it++) {
            double p0 = 1, p1 = x;
            for (int k = 2; k <= GL_N; k++) {
                double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = GL_N * (x * p1 - p0) / (x * x - 1);
            double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-17)
                break;
        }
        gl_x[i] = x;
        gl_w[i] = 2 / ((1 - x * x) * dp * dp);
    }
    gl_ready = 1;
}

static double gl_arc(const nurbs *c, double a, double b)
{
    double h = (b - a) / 2, m = (a + b) / 2, s = 0;
    for (int i = 0; i < GL_N; i++)
        s += gl_w[i] * speed_at(c, m + h * gl_x[i]);
    return s * h;
}

double nurbs_arc(const nurbs *c, double u0, double u1)
{
    gl_init();
    /* integrate span by span: the speed is smooth only inside a span */
    if (u1 < u0) {
        double t = u0;
        u0 = u1;
        u1 = t;
    }
    double s = 0;
    int i0 = nurbs_find_span(c->n, c->p, u0, c->U), i1 = nurbs_find_span(c->n, c->p, u1, c->U);
    for (int i = i0; i <= i1; i++) {
        double a = i == i0 ? u0 : c->U[i], b = i == i1 ? u1 : c->U[i + 1];
        if (b > a)
            s += gl_arc(c, a, b);
    }
    return s;
}

/* ---- arc-length table --------------------------------------------------- */

typedef struct {
    double *u, *s;
    int n, cap;
} table;

static int tab_push(table *t, double u, double s)
{
    if (t->n == t->cap) {
        /* two arrays of one capacity */
        size_t cap = gls_grow_cap((size_t)t->cap, (size_t)t->n + 1, sizeof(double));
        double *nu = cap && cap <= INT_MAX ? gls_resize(t->u, cap, sizeof(double)) : NULL, *ns;
        if (!nu)
            return -1;
        t->u = nu;
        ns = gls_resize(t->s, cap, sizeof(double));
        if (!ns)
            return -1;
        t->s = ns;
        t->cap = (int)cap;
    }
    t->u[t->n] = u;
    t->s[t->n] = s;
    t->n++;
    return 0;
}

/* Split [a, b] until the 12-point rule on it agrees with the sum over its
   halves to 1e-13 relative, or to 1e-15 of the whole span (floor): with
   weights far from 1 the speed |C'| itself carries rounding noise well
   above 1e-16 (A4.2 subtracts nearly equal terms), and a purely relative
   test would split forever.  Both halves then go into the table (they are
   at least as accurate as the whole that was verified). */
static int build(const nurbs *c, table *t, double a, double b, double whole, double span, int depth)
{
    double m = 0.5 * (a + b);
    double l = gl_arc(c, a, m), r = gl_arc(c, m, b);
    double d = fabs(l + r - whole);
    if (depth >= 40 || d <= 1e-13 * (l + r) || d <= 1e-15 * span || m <= a || m >= b) {
        double s0 = t->s[t->n - 1];
        if (tab_push(t, m, s0 + l) || tab_push(t, b, s0 + l + r))
            return -1;
        return 0;
    }
    if (build(c, t, a, m, l, span, depth + 1))
        return -1;
    return build(c, t, m, b, r, span, depth + 1);
}

int nurbs_init(nurbs *c, int p, int npts, const double *pts, const double *w, const double *U, char *err,
               size_t errlen)
{
    memset(c, 0, sizeof *c);
    const char *why = nurbs_check(p, npts, w, npts + p + 1, U);
    if (why) {
        snprintf(err, errlen, "%s", why);
        return -1;
    }
    gl_init();
    c->p = p;
    c->n = npts - 1;
    c->Pw = malloc(sizeof(double) * 4 * npts);
    c->U = malloc(sizeof(double) * (npts + p + 1));
    if (!c->Pw || !c->U) {
        snprintf(err, errlen, "out of memory");
        nurbs_free(c);
        return -1;
    }
    for (int i = 0; i < npts; i++) {
        c->Pw[4 * i + 0] = pts[3 * i + 0] * w[i];
        c->Pw[4 * i + 1] = pts[3 * i + 1] * w[i];
        c->Pw[4 * i + 2] = pts[3 * i + 2] * w[i];
        c->Pw[4 * i + 3] = w[i];
    }
    memcpy(c->U, U, sizeof(double) * (npts + p + 1));
    table t = {0};
    if (tab_push(&t, nurbs_umin(c), 0))
        goto oom;
    for (int i = p; i <= c->n; i++) {
        double a = c->U[i], b = c->U[i + 1];
        if (!(b > a))
            continue;
        /* A zero tangent (a cusp, or coincident control points) has no
           direction for the road to follow; look for one at the span's
           ends and quadrature nodes. */
        for (int k = 0; k <= GL_N + 1; k++) {
            double u = a + (b - a) * k / (GL_N + 1);
            double v = speed_at(c, u);
            if (!(v > 0) || !isfinite(v)) {
                snprintf(err, errlen, "the curve has a zero or undefined tangent near u = %.9g (coincident control points?)", u);
                free(t.u);
                free(t.s);
                nurbs_free(c);
                return -1;
            }
        }
        double whole = gl_arc(c, a, b);
        if (build(c, &t, a, b, whole, whole, 0))
            goto oom;
    }
    c->tu = t.u;
    c->ts = t.s;
    c->ntab = t.n - 1;
    c->length = t.s[t.n - 1];
    return 0;
oom:
    free(t.u);
    free(t.s);
    nurbs_free(c);
    snprintf(err, errlen, "out of memory");
    return -1;
}

void nurbs_free(nurbs *c)
{
    free(c->Pw);
    free(c->U);
    free(c->tu);
    free(c->ts);
    memset(c, 0, sizeof *c);
}

/* Index i of the table interval [t[i], t[i+1]] holding x: the last entry
   of t[0..n) at or below x (t increasing: the table's tu or ts). */
static int tab_find(const double *t, int n, double x)
{
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (t[mid] <= x)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

double nurbs_s_of_u(const nurbs *c, double u)
{
    if (u <= nurbs_umin(c))
        return 0;
    if (u >= nurbs_umax(c))
        return c->length;
    int i = tab_find(c->tu, c->ntab, u);
    /* table intervals never straddle a knot, so one rule suffices */
    return c->ts[i] + gl_arc(c, c->tu[i], u);
}

double nurbs_u_of_s(const nurbs *c, double s)
{
    if (s <= 0)
        return nurbs_umin(c);
    if (s >= c->length)
        return nurbs_umax(c);
    int lo = tab_find(c->ts, c->ntab, s);
    double ua = c->tu[lo], ub = c->tu[lo + 1], sa = c->ts[lo], sb = c->ts[lo + 1];
    double a = ua, b = ub;
    double u = sb > sa ? ua + (ub - ua) * (s - sa) / (sb - sa) : ua;
    /* Newton on f(u) = s(u) - s with f' = |C'(u)|, kept inside the bracket
       [a, b] by bisection when a step would leave it. */
    for (int it = 0; it < 100; it++) {
        double f = sa + gl_arc(c, ua, u) - s;
        if (f == 0)
            break;
        if (f > 0)
            b = u;
        else
            a = u;
        double un = u - f / speed_at(c, u);
        if (!(un > a && un < b))
            un = 0.5 * (a + b);
        if (fabs(un - u) <= 2e-16 * fabs(u) + 1e-300 || un == u) {
            u = un;
            break;
        }
        u = un;
    }
    return u;
}
