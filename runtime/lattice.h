/* Rank-1 lattice sample patterns (spec/antialiasing.md "The lattice").
 *
 * M points in the unit pixel square, point i at
 *     frac(t + (i, i*a mod M) / M)
 * with a generator a coprime to M and a shift t.  The pattern repeats
 * from pixel to pixel, so the samples of a whole image form one 2D
 * lattice; a reduced basis of it gives an integer map A from image
 * pixels to a "fine" framebuffer whose pixel centres are exactly the
 * sample points (the one-pass renderer, aa_onepass.h).
 *
 * Everything here is exact integer arithmetic: positions are integers in
 * units of 1/Q of a pixel (Q = GLS_LATTICE_SHIFT_DEN * M), so wrapping a
 * point into the pixel and mapping it to the fine framebuffer never
 * rounds.  No GL. */
#ifndef GLS_LATTICE_H
#define GLS_LATTICE_H

#include <stdint.h>

/* The shift t is a multiple of 1/GLS_LATTICE_SHIFT_DEN of the reduced
 * basis vectors (the search grid of the shift). */
#define GLS_LATTICE_SHIFT_DEN 24
/* Largest M: 4096^2. */
#define GLS_LATTICE_MAX_M (4096ull * 4096ull)
/* Generators whose shortest vector is within this factor of the best are
 * candidates (and at most GLS_LATTICE_CANDIDATES of them). */
#define GLS_LATTICE_MINDIST_TOL 0.95
#define GLS_LATTICE_CANDIDATES 64

typedef struct {
    int64_t x, y;
} gls_iv2;

/* Lagrange-Gauss reduction: on return b1, b2 span the same lattice,
 * |b1| <= |b2| <= |b2 +- b1| (b1 a shortest nonzero vector). */
void gls_lattice_reduce(gls_iv2 *b1, gls_iv2 *b2);

typedef struct {
    uint64_t m, a;       /* points per pixel, generator                  */
    uint64_t q;          /* position unit: 1/q px, q = 24 m              */
    gls_iv2 e1, e2;      /* reduced basis, units 1/m px, det(e1, e2) = m  */
    gls_iv2 t;           /* shift, units 1/q px, in [0, q)^2             */
    uint32_t alpha, beta;/* t = (alpha e1 + beta e2) / 24, before wrapping */
    double mindist;      /* |e1| / m: shortest distance between points, px */
    double worst;        /* the criterion's value: worst RMS edge error over
                            the short-vector directions, px (see .c)      */
} gls_lattice;

/* The pattern for m points (1 <= m <= GLS_LATTICE_MAX_M): generator and
 * shift by the documented criterion (lattice.c).  Deterministic. */
int gls_lattice_choose(uint64_t m, gls_lattice *l);

/* The lattice for a given generator (gcd(a, m) = 1) and shift index
 * (alpha, beta in 0..23); for tests and the K-pass split. */
int gls_lattice_make(uint64_t m, uint64_t a, uint32_t alpha, uint32_t beta, gls_lattice *l);

/* Point i (0 <= i < m) in units of 1/q px, in [0, q)^2. */
void gls_lattice_point(const gls_lattice *l, uint64_t i, int64_t *x, int64_t *y);

/* The worst-direction criterion for generator a and shift (alpha, beta)
 * (exposed for tests and the bench). */
double gls_lattice_criterion(uint64_t m, gls_iv2 e1, gls_iv2 e2, uint32_t alpha, uint32_t beta);

#endif
