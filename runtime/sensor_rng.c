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

double gls_rng_poisson(gls_rng *r, double lambda)
{
    if (!(lambda > 0))
        return 0;
    if (lambda < PTRS_FROM) {
        /* the number of uniforms whose running product stays above
         * exp(-lambda) */
        double limit = exp(-lambda), prod = gls_rng_uniform(r), k = 0;
        while (prod > limit) {
            k++;
            prod *= gls_rng_uniform(r);
        }
        return k;
    }
    /* PTRS (W. Hormann, "The transformed rejection method for generating
     * Poisson random variables", 1993), constants as published */
    double slam = sqrt(lambda), loglam = log(lambda);
    double b = 0.931 + 2.53 * slam, a = -0.059 + 0.02483 * b;
    double invalpha = 1.1239 + 1.1328 / (b - 3.4), vr = 0.9277 - 3.6224 / (b - 2);
    for (;;) {
        double U = gls_rng_uniform(r) - 0.5, V = gls_rng_uniform(r);
        double us = 0.5 - fabs(U);
        double k = floor((2 * a / us + b) * U + lambda + 0.43);
        if (us >= 0.07 && V <= vr)
            return k;
        if (k < 0 || (us < 0.013 && V > us))
            continue;
        if (log(V) + log(invalpha) - log(a / (us * us) + b) <= -lambda + k * loglam - lgamma(k + 1))
            return k;
    }
}
