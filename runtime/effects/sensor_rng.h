/* The random numbers of the sensor noise (spec/camera.md "Sensor
 * effects"): a counter-based generator, so that every draw is a pure
 * function of its key and its index and the noise of a pixel depends on
 * nothing but (seed, camera, frame, pixel, channel), not on the order the
 * pixels are done in or on threads.
 *
 * A stream is splitmix64 (Steele, Lea and Flood, 2014) started at a key:
 * draw j of the stream with key k is mix64(k + (j + 1) * golden), mix64
 * being splitmix64's finaliser (a bijection of 64-bit words).  Keys are
 * chained with mix64 too (gls_rng_key). */
#ifndef GLS_SENSOR_RNG_H
#define GLS_SENSOR_RNG_H

#include <stdint.h>

typedef struct {
    uint64_t state; /* key + j * golden after j draws */
} gls_rng;

/* splitmix64's finaliser. */
uint64_t gls_rng_mix(uint64_t z);

/* The key of a sub-stream: mix(mix(key) ^ (v + golden)); different v
 * give unrelated keys. */
uint64_t gls_rng_key(uint64_t key, uint64_t v);

/* A stream starting at key. */
gls_rng gls_rng_stream(uint64_t key);

/* The next 64 random bits. */
uint64_t gls_rng_next(gls_rng *r);

/* Uniform in (0, 1), never 0 or 1: (53 bits + 1/2) / 2^53. */
double gls_rng_uniform(gls_rng *r);

/* Standard normal: Box-Muller, cos branch, two uniforms a draw. */
double gls_rng_normal(gls_rng *r);

/* Poisson with mean lambda >= 0, exact: the multiplication method
 * (Knuth) below mean 10, Hormann's transformed rejection with squeeze
 * (PTRS, 1993) from 10 up, as NumPy's generator does.  The constants of a
 * mean are set up once (gls_poisson_setup) and kept while the mean
 * repeats, as it does over a surface of one colour. */
typedef struct {
    double lambda, limit;                            /* limit: exp(-lambda), below 10 */
    double slam, loglam, a, b, invalpha, vr, lgia;   /* PTRS                          */
} gls_poisson;
void gls_poisson_setup(gls_poisson *p, double lambda);
double gls_rng_poisson(gls_rng *r, const gls_poisson *p);

#endif
