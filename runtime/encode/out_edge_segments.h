/* The encoder of edge_segments_F.csv (spec/outputs.md "Edge segments"):
 * exact coverage's visible edges (exact.h, --aa exact) as text. */
#ifndef GLS_OUT_EDGE_SEGMENTS_H
#define GLS_OUT_EDGE_SEGMENTS_H

#include <stddef.h>
#include "buf.h"
#include "exact.h"

/* the header line, then one line a segment: x0,y0,x1,y1,left_id,right_id.
 * 0, or -1 when out of memory. */
int gls_encode_edge_segments_csv(const gls_exact_seg *s, size_t n, gls_buf *buf);

#endif
