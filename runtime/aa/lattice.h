/* Rank-1 lattice sample patterns (spec/antialiasing.md "The lattice").
 *
 * M points in the unit pixel square, point i at
 *     ((i + 1/2) / M, ((i*a mod M) + g_h/2) / M),   g_h = gcd(a, M),
 * for a generator a in 0..M-1: one point centred in each 1/M strip in x;
 * in y the values i*a mod M are the multiples of g_h, each taken g_h
 * times, and the offset g_h/2 centres them, so that the points' mean is
 * the pixel centre (no systematic edge shift, lattice.c).  The pattern
 * repeats from pixel to pixel, so the samples of a whole image form one
 * 2D lattice; a reduced basis of it gives an integer map A from image
 * pixels to a "fine" framebuffer whose pixel centres are exactly the
 * sample points (the one-pass renderer, aa_onepass.h).
 *
 * Everything here is exact integer arithmetic: positions are integers in
 * units of 1/q of a pixel (q = 2 M), so mapping a point to the fine
 * framebuffer never rounds.  No GL. */
#ifndef GLS_LATTICE_H
#define GLS_LATTICE_H

#include <stdint.h>

/* Positions are in units of 1/(GLS_LATTICE_UNIT M) px. */
#define GLS_LATTICE_UNIT 2
/* Largest M: 4096^2. */
#define GLS_LATTICE_MAX_M (4096ull * 4096ull)

typedef struct {
    int64_t x, y;
} gls_iv2;

/* Lagrange-Gauss reduction: on return b1, b2 span the same lattice,
 * |b1| <= |b2| <= |b2 +- b1| (b1 a shortest nonzero vector). */
void gls_lattice_reduce(gls_iv2 *b1, gls_iv2 *b2);

typedef struct {
    uint64_t m, a;       /* points per pixel, generator                  */
    uint64_t q;          /* position unit: 1/q px, q = 2 m               */
    gls_iv2 e1, e2;      /* reduced basis, units 1/m px, det(e1, e2) = m  */
    int64_t len2;        /* |e1|^2, units 1/m^2: the criterion's first key */
    double mindist;      /* |e1| / m: shortest distance between points, px */
    uint64_t g0, g45, g135; /* gcd(a, m), gcd(a - 1, m), gcd(a + 1, m):
                            the points a position across 0, 45 and 135
                            degree edges (positions g/m px apart); 90
                            degree edges always see m positions          */
    double axis_diag;    /* max(g0, g45, g135) / (m sqrt 12): the worst
                            RMS edge error at 0, 45, 90, 135 degrees, px */
} gls_lattice;

/* The pattern for m points (1 <= m <= GLS_LATTICE_MAX_M): the generator
 * by the documented criterion (lattice.c).  Deterministic. */
int gls_lattice_choose(uint64_t m, gls_lattice *l);

/* The lattice for a given generator a (any a, reduced mod m; m = 1 has
 * a = 0); for tests and the K-pass split. */
int gls_lattice_make(uint64_t m, uint64_t a, gls_lattice *l);

/* Point i (0 <= i < m) in units of 1/q px, in [0, q)^2: (2 i + 1,
 * 2 (i a mod m) + g0). */
void gls_lattice_point(const gls_lattice *l, uint64_t i, int64_t *x, int64_t *y);

#endif
