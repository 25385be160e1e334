/* The triangles of bench/play_scene.h's height field in a random order
 * (the hard case for a renderer that draws triangles in the order it is
 * given them: no two consecutive triangles are near each other), for
 * bench/instances_bench.c and bench/play_floor.c --random.  Deterministic
 * (a fixed splitmix64 seed and Fisher-Yates). */
#ifndef GLS_RANDOM_ORDER_H
#define GLS_RANDOM_ORDER_H
#include <stdint.h>
#include <stdlib.h>
#include "play_scene.h"

#define RO_NTRI (2u * PS_N * PS_N)

/* Corner q (0..2) of triangle t: quad t / 2 = (i, j) of the grid, split
 * along its diagonal as play_floor.c splits it. */
static inline void ro_corner(uint32_t t, int q, int *i, int *j)
{
    static const int corner[2][3][2] = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
    uint32_t quad = t / 2;
    *i = (int)(quad / PS_N) + corner[t % 2][q][0];
    *j = (int)(quad % PS_N) + corner[t % 2][q][1];
}

static inline uint64_t ro_splitmix(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* RO_NTRI triangle numbers in random order (malloc'd; NULL if out of memory). */
static inline uint32_t *ro_order(void)
{
    uint32_t *o = malloc(RO_NTRI * sizeof *o);
    uint64_t s = 14;
    for (uint32_t k = 0; o && k < RO_NTRI; k++)
        o[k] = k;
    for (uint32_t k = RO_NTRI - 1; o && k > 0; k--) {
        uint32_t r = (uint32_t)(ro_splitmix(&s) % (k + 1)), x = o[k];
        o[k] = o[r], o[r] = x;
    }
    return o;
}
#endif
