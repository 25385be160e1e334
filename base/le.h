/* Little-endian load/store helpers: the only place byte order is handled
 * (the bundle's encoding, the player's PFM and PLY files). */
#ifndef GLS_LE_H
#define GLS_LE_H
#include <stdint.h>
#include <string.h>

static inline void gls_le_put_u32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}
static inline void gls_le_put_u64(uint8_t *p, uint64_t v)
{
    gls_le_put_u32(p, (uint32_t)v);
    gls_le_put_u32(p + 4, (uint32_t)(v >> 32));
}
static inline uint32_t gls_le_get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static inline uint64_t gls_le_get_u64(const uint8_t *p)
{
    return (uint64_t)gls_le_get_u32(p) | (uint64_t)gls_le_get_u32(p + 4) << 32;
}
static inline void gls_le_put_f32(uint8_t *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, 4);
    gls_le_put_u32(p, v);
}
static inline void gls_le_put_f64(uint8_t *p, double d)
{
    uint64_t v;
    memcpy(&v, &d, 8);
    gls_le_put_u64(p, v);
}
static inline double gls_le_get_f64(const uint8_t *p)
{
    uint64_t v = gls_le_get_u64(p);
    double d;
    memcpy(&d, &v, 8);
    return d;
}
#endif
