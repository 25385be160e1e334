/* The functions and the constant of constant expressions (spec/language.md
 * 5.2): sqrt, sin, cos, tan, asin, acos, atan, atan2, abs, min, max, floor,
 * ceil, round, mod, pow, and pi.  Angles are in degrees, in and out. */
#ifndef GLS_MATHFN_H
#define GLS_MATHFN_H
#include <stddef.h>

#define GLS_MAX_FN_ARGS 16

/* The function named s[0..n), or -1. */
int gls_fn_find(const char *s, size_t n);
/* Its name, and how many arguments it takes (max is GLS_MAX_FN_ARGS for
 * min and max). */
const char *gls_fn_name(int fn);
unsigned gls_fn_min_args(int fn);
unsigned gls_fn_max_args(int fn);
/* Every function name, then NULL (for "did you mean"). */
extern const char *const gls_fn_names[];

/* Apply fn to x[0..n) (n within its argument count, every x finite):
 * NULL and *out (finite), or what is wrong, worded as a whole message
 * ("sqrt of a negative number (-1)"), in why. */
const char *gls_fn_eval(int fn, const double *x, unsigned n, double *out, char *why, size_t whylen);

/* The built-in constant named s[0..n) ("pi"): 1 and *v, or 0. */
int gls_builtin_const(const char *s, size_t n, double *v);

/* Sine and cosine of an angle in degrees, reduced exactly (sin(180) is 0,
 * sin(30) is 0.5); also used by tests. */
double gls_sin_deg(double deg);
double gls_cos_deg(double deg);
#endif
