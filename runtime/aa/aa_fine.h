/* The fine framebuffer of a lattice plan (spec/antialiasing.md "One
 * pass"): the samples of all pixels form a lattice S in the image plane;
 * an integer matrix A maps it onto the integer grid, so that a framebuffer
 * with one pixel per sample ("fine" pixels) holds pixel (u, v)'s sample j
 * at fine pixel
 *     u * A[.][0] + v * A[.][1] + c_j      (c_j integer),
 * and the gather is index arithmetic.  More samples than one pass should
 * hold are split into K passes of L = M / K samples each, shifted copies
 * of one smaller lattice (same A, same c_j, another shift).
 *
 * The grid pattern (box) is the case A = N I; the rank-1 lattice is
 * A = adj(E) for the reduced basis E of the pass lattice (lattice.h),
 * turned by 90 degrees where that makes image rows run along fine rows
 * (aa_fine.c).
 * No GL here: aa_onepass.c renders. */
#ifndef GLS_AA_FINE_H
#define GLS_AA_FINE_H

#include "aa.h"

typedef struct {
    uint64_t k;          /* passes                                        */
    uint64_t l;          /* samples per pixel and pass                    */
    int64_t a[2][2];     /* fine = a * image; det = l                     */
    uint64_t q;          /* positions in units of 1/q px                  */
    const gls_aa_plan *p;
    gls_iv2 e1, e2;      /* lattice: reduced basis of the pass lattice (l
                            points, generator a mod l), units 1/l         */
    uint64_t gk;         /* grid: K = gk^2 passes of N/gk x N/gk          */
} gls_aa_fine;

/* Does plan p render through the fine framebuffer?  Lattice (box and
 * Gaussian) and grid with the box filter; stratified jitter is not a
 * lattice, and the grid Gaussian spreads its N x N over the window. */
int gls_aa_fine_ok(const gls_aa_plan *p);

/* Split plan p (which must outlive f) into passes of at most max_l
 * samples per pixel: the fewest passes K (K divides M; for the grid
 * K = k^2, k divides N) with L = M / K <= max_l; but if that K is more
 * than 4 times ceil(M / max_l) (M has no divisor near), the largest
 * divisor K below ceil(M / max_l) instead when that keeps L within
 * 16 max_l (tiles still bound the memory).  So a prime M far above max_l
 * is M passes of one sample each.  -1 if p is not a fine-framebuffer
 * plan. */
int gls_aa_fine_init(gls_aa_fine *f, const gls_aa_plan *p, uint64_t max_l);

/* Pass r (0 <= r < K): its shift (units 1/q px: the position in the
 * pixel square of the pass lattice's point 0, the plan's point r), and for
 * each of its l samples j the position in the pixel square (units 1/q,
 * in [0, q)^2) and the fine offset c_j.  Sample j of pass r is sample
 * r + j K of the plan (lattice) or grid sample (rx + k i, ry + k j). */
void gls_aa_fine_pass(const gls_aa_fine *f, uint64_t r, int64_t shift[2], int64_t (*pos)[2], int64_t (*c)[2]);

/* The image -> fine window map of pass r: window = m[0..2] . (u, v, 1),
 * m[3..5] . (u, v, 1), such that fine pixel centre (X + 1/2, Y + 1/2) is
 * a sample, (X, Y) relative to the origin (ox, oy). */
void gls_aa_fine_map(const gls_aa_fine *f, const int64_t shift[2], int64_t ox, int64_t oy, double m[6]);

#endif
