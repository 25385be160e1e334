/* Counter-based random numbers for the sensor noise (sensor_rng.h). */
#include <math.h>
#include "sensor_rng.h"

#define GOLDEN 0x9e3779b97f4a7c15ull

uint64_t gls_rng_mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

uint64_t gls_rng_key(uint64_t key, uint64_t v)
{
    return gls_rng_mix(gls_rng_mix(key) ^ (v + GOLDEN));
}

gls_rng gls_rng_stream(uint64_t key)
{
    gls_rng r = {key};
    return r;
}

uint64_t gls_rng_next(gls_rng *r)
{
    r->state += GOLDEN;
    return gls_rng_mix(r->state);
}

double gls_rng_uniform(gls_rng *r)
{
    return ((double)(gls_rng_next(r) >> 11) + 0.5) * 0x1p-53;
}

double gls_rng_normal(gls_rng *r)
{
    double u1 = gls_rng_uniform(r), u2 = gls_rng_uniform(r);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
}

/* Below this mean, the multiplication method: about lambda + 1 uniforms,
 * and exp(-lambda) is far from underflow. */
#define PTRS_FROM 10.0

/* log Gamma(x) for x >= 1 by Stirling's series (the one NumPy's
 * generator uses), a pure function: libm's lgamma writes the global
 * signgam, which the noise threads would race on. */
static double log_gamma(double x)
{
    static const double a[10] = {8.333333333333333e-02, -2.777777777777778e-03, 7.936507936507937e-04,
                                 -5.952380952380952e-04, 8.417508417508418e-04, -1.917526917526918e-03,
                                 6.410256410256410e-03, -2.955065359477124e-02, 1.796443723688307e-01,
                                 -1.39243221690590e+00};
    if (x == 1.0 || x == 2.0)
        return 0.0;
    int n = x < 7.0 ? (int)(7 - x) : 0;
    double x0 = x + n, x2 = (1.0 / x0) * (1.0 / x0), gl0 = a[9];
    for (int k = 8; k >= 0; k--)
        gl0 = gl0 * x2 + a[k];
    double gl = gl0 / x0 + 0.5 * 1.8378770664093453 + (x0 - 0.5) * log(x0) - x0; /* log(2 pi) */
    for (int k = 1; k <= n; k++) {
        gl -= log(x0 - 1.0);
        x0 -= 1.0;
    }
    return gl;
}

void gls_poisson_setup(gls_poisson *p, double lambda)
{
    p->lambda = lambda > 0 ? lambda : 0;
    if (p->lambda < PTRS_FROM) {
        p->limit = exp(-p->lambda);
        return;
    }
    /* PTRS (W. Hormann, "The transformed rejection method for generating
     * Poisson random variables", 1993), constants as published */
    p->slam = sqrt(lambda);
    p->loglam = log(lambda);
    p->b = 0.931 + 2.53 * p->slam;
    p->a = -0.059 + 0.02483 * p->b;
    p->invalpha = 1.1239 + 1.1328 / (p->b - 3.4);
    p->vr = 0.9277 - 3.6224 / (p->b - 2);
    p->lgia = log(p->invalpha);
}

double gls_rng_poisson(gls_rng *r, const gls_poisson *p)
{
    double lambda = p->lambda;
    if (lambda == 0)
        return 0;
    if (lambda < PTRS_FROM) {
        /* the number of uniforms whose running product stays above
         * exp(-lambda) */
        double prod = gls_rng_uniform(r), k = 0;
        while (prod > p->limit) {
            k++;
            prod *= gls_rng_uniform(r);
        }
        return k;
    }
    double a = p->a, b = p->b;
    for (;;) {
        double U = gls_rng_uniform(r) - 0.5, V = gls_rng_uniform(r);
        double us = 0.5 - fabs(U);
        double k = floor((2 * a / us + b) * U + lambda + 0.43);
        if (us >= 0.07 && V <= p->vr)
            return k;
        if (k < 0 || (us < 0.013 && V > us))
            continue;
        if (log(V) + p->lgia - log(a / (us * us) + b) <= -lambda + k * p->loglam - log_gamma(k + 1))
            return k;
    }
}
