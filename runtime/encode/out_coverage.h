/* The encoder of coverage_F.csv (spec/outputs.md "Coverage"): exact
 * coverage's areas per instance (exact.h, --aa exact) as text. */
#ifndef GLS_OUT_COVERAGE_H
#define GLS_OUT_COVERAGE_H

#include <stdint.h>
#include "buf.h"
#include "exact.h"

/* "x,y,id,area" a line after a header, for every pixel a surface covers
 * part of: its instances largest first, then id 0 with the uncovered
 * rest when there is one.  0, or -1 when out of memory. */
int gls_encode_coverage_csv(const gls_exact_cover *cover, uint32_t w, uint32_t h, gls_buf *buf);

#endif
