/* Durations and memory sizes as people read them, for the player's
 * messages (progress, time estimates, memory errors). */
#ifndef GLS_UNITS_H
#define GLS_UNITS_H

#include <stddef.h>
#include <stdint.h>

/* "850 us", "40.0 ms", "1.25 s", "42 s", "3 min 05 s", "7 h 12 min". */
void gls_fmt_duration(char *buf, size_t len, double seconds);

/* "900 bytes", "12.0 KiB", "512 MiB", "1.1 GiB" (binary units). */
void gls_fmt_bytes(char *buf, size_t len, uint64_t bytes);

#endif
