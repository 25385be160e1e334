/* The functions of constant expressions (mathfn.h, spec/language.md 5.2).
 *
 * Angles are degrees.  An angle is reduced exactly before any conversion
 * to radians (fmod is exact, and so are the subtractions below by
 * Sterbenz's lemma), so multiples of 90 degrees give exact results and 30,
 * 45 and 60 degrees the correctly rounded ones: sin(180) is 0, not
 * 1.2e-16, and sin(30) is 0.5.  Other angles go through the C library's
 * sin and cos of the reduced angle (0..45 degrees) in radians.  A zero
 * result is always +0. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "mathfn.h"
#include "numfmt.h"

/* The doubles nearest pi/180, 180/pi, sqrt(1/2) and sqrt(3)/2. */
#define RAD_PER_DEG 0.017453292519943295
#define DEG_PER_RAD 57.29577951308232
#define SQRT_HALF 0.7071067811865476
#define SQRT3_HALF 0.8660254037844386

/* sin and cos of r degrees, 0 <= r <= 90. */
static double sin_q(double r)
{
    if (r == 0)
        return 0;
    if (r == 30)
        return 0.5;
    if (r == 45)
        return SQRT_HALF;
    if (r == 60)
        return SQRT3_HALF;
    if (r == 90)
        return 1;
    return r < 45 ? sin(r * RAD_PER_DEG) : cos((90 - r) * RAD_PER_DEG);
}

static double cos_q(double r)
{
    if (r == 0)
        return 1;
    if (r == 30)
        return SQRT3_HALF;
    if (r == 45)
        return SQRT_HALF;
    if (r == 60)
        return 0.5;
    if (r == 90)
        return 0;
    return r < 45 ? cos(r * RAD_PER_DEG) : sin((90 - r) * RAD_PER_DEG);
}

static double plus_zero(double v)
{
    return v == 0 ? 0 : v;
}

double gls_sin_deg(double deg)
{
    int neg = deg < 0;
    double r = fmod(fabs(deg), 360); /* 0 <= r < 360, exact */
    if (r >= 180) {
        r -= 180;
        neg = !neg;
    }
    if (r > 90)
        r = 180 - r;
    double v = sin_q(r);
    return plus_zero(neg ? -v : v);
}

double gls_cos_deg(double deg)
{
    double r = fmod(fabs(deg), 360);
    if (r > 180)
        r = 360 - r;
    int neg = r > 90;
    if (neg)
        r = 180 - r;
    double v = cos_q(r);
    return plus_zero(neg ? -v : v);
}

static double asin_deg(double x)
{
    if (x == 1 || x == -1)
        return 90 * x;
    if (x == 0.5 || x == -0.5)
        return 60 * x;
    return asin(x) * DEG_PER_RAD;
}

static double acos_deg(double x)
{
    if (x == 1)
        return 0;
    if (x == -1)
        return 180;
    if (x == 0)
        return 90;
    if (x == 0.5)
        return 60;
    if (x == -0.5)
        return 120;
    return acos(x) * DEG_PER_RAD;
}

static double atan_deg(double x)
{
    if (x == 1 || x == -1)
        return 45 * x;
    return atan(x) * DEG_PER_RAD;
}

/* In (-180, 180]; the signs of zeros do not matter: atan2(0, x) is 0 for
 * x >= 0 and 180 for x < 0. */
static double atan2_deg(double y, double x)
{
    if (y == 0)
        return x < 0 ? 180 : 0;
    if (x == 0)
        return y > 0 ? 90 : -90;
    if (fabs(y) == fabs(x))
        return (x > 0 ? 45 : 135) * (y > 0 ? 1 : -1);
    return atan2(y, x) * DEG_PER_RAD;
}

/* x rounded to digits decimals as printf("%.*f") rounds the exact value
 * (a tie to the even digit), read back as the nearest double. */
static double round_to(double x, int digits)
{
    char buf[400]; /* a double has at most 309 integer digits */
    snprintf(buf, sizeof buf, "%.*f", digits, x);
    return strtod(buf, NULL);
}

enum {
    F_SQRT, F_SIN, F_COS, F_TAN, F_ASIN, F_ACOS, F_ATAN, F_ATAN2, F_ABS, F_MIN, F_MAX,
    F_FLOOR, F_CEIL, F_ROUND, F_MOD, F_POW, F_COUNT
};

static const struct {
    const char *name;
    unsigned min, max;
} fns[F_COUNT] = {
    [F_SQRT] = {"sqrt", 1, 1},   [F_SIN] = {"sin", 1, 1},     [F_COS] = {"cos", 1, 1},
    [F_TAN] = {"tan", 1, 1},     [F_ASIN] = {"asin", 1, 1},   [F_ACOS] = {"acos", 1, 1},
    [F_ATAN] = {"atan", 1, 1},   [F_ATAN2] = {"atan2", 2, 2}, [F_ABS] = {"abs", 1, 1},
    [F_MIN] = {"min", 2, GLS_MAX_FN_ARGS}, [F_MAX] = {"max", 2, GLS_MAX_FN_ARGS},
    [F_FLOOR] = {"floor", 1, 1}, [F_CEIL] = {"ceil", 1, 1},   [F_ROUND] = {"round", 1, 2},
    [F_MOD] = {"mod", 2, 2},     [F_POW] = {"pow", 2, 2},
};

const char *const gls_fn_names[] = {"sqrt", "sin",   "cos",  "tan",   "asin", "acos", "atan", "atan2", "abs",
                                    "min",  "max",   "floor", "ceil", "round", "mod", "pow",  NULL};

int gls_fn_find(const char *s, size_t n)
{
    for (int i = 0; i < F_COUNT; i++)
        if (strlen(fns[i].name) == n && memcmp(fns[i].name, s, n) == 0)
            return i;
    return -1;
}

const char *gls_fn_name(int fn) { return fns[fn].name; }
unsigned gls_fn_min_args(int fn) { return fns[fn].min; }
unsigned gls_fn_max_args(int fn) { return fns[fn].max; }

int gls_builtin_const(const char *s, size_t n, double *v)
{
    if (n == 2 && memcmp(s, "pi", 2) == 0) {
        *v = 3.141592653589793; /* the double nearest pi */
        return 1;
    }
    return 0;
}

#define WHY(...) (snprintf(why, whylen, __VA_ARGS__), why)

const char *gls_fn_eval(int fn, const double *x, unsigned n, double *out, char *why, size_t whylen)
{
    char a[40];
    gls_fmt_double(a, sizeof a, x[0]);
    double v = 0;
    switch (fn) {
    case F_SQRT:
        if (x[0] < 0)
            return WHY("sqrt of a negative number (%s)", a);
        v = sqrt(x[0]);
        break;
    case F_SIN: v = gls_sin_deg(x[0]); break;
    case F_COS: v = gls_cos_deg(x[0]); break;
    case F_TAN: {
        double c = gls_cos_deg(x[0]);
        if (c == 0)
            return WHY("tan of %s degrees is infinite", a);
        v = gls_sin_deg(x[0]) / c;
        break;
    }
    case F_ASIN:
    case F_ACOS:
        if (x[0] < -1 || x[0] > 1)
            return WHY("%s of %s is undefined: the argument must be in -1..1", fns[fn].name, a);
        v = fn == F_ASIN ? asin_deg(x[0]) : acos_deg(x[0]);
        break;
    case F_ATAN: v = atan_deg(x[0]); break;
    case F_ATAN2: v = atan2_deg(x[0], x[1]); break;
    case F_ABS: v = fabs(x[0]); break;
    case F_MIN:
    case F_MAX:
        v = x[0];
        for (unsigned i = 1; i < n; i++)
            if (fn == F_MIN ? x[i] < v : x[i] > v)
                v = x[i];
        break;
    case F_FLOOR: v = floor(x[0]); break;
    case F_CEIL: v = ceil(x[0]); break;
    case F_ROUND:
        if (n == 1) {
            v = round_to(x[0], 0);
            break;
        }
        if (!(x[1] >= 0 && x[1] <= 20 && x[1] == floor(x[1]))) {
            gls_fmt_double(a, sizeof a, x[1]);
            return WHY("the digits of 'round' must be a whole number from 0 to 20, not %s", a);
        }
        v = round_to(x[0], (int)x[1]);
        break;
    case F_MOD:
        if (x[1] == 0)
            return WHY("division by zero");
        v = fmod(x[0], x[1]);
        break;
    case F_POW:
        v = pow(x[0], x[1]);
        if (isnan(v))
            return WHY("pow of a negative number to a fractional power is not a real number");
        break;
    default: return WHY("internal error: function %d", fn);
    }
    if (!isfinite(v))
        return WHY("result of '%s' is not finite", fns[fn].name);
    *out = plus_zero(v);
    return NULL;
}
