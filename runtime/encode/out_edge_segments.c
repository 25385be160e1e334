/* edge_segments_F.csv (out_edge_segments.h, spec/outputs.md "Edge
 * segments").  Coordinates are written with 17 significant digits, which
 * read back as the double the engine computed: the file is as exact as
 * the engine. */
#include "out_edge_segments.h"

int gls_encode_edge_segments_csv(const gls_exact_seg *s, size_t n, gls_buf *buf)
{
    if (gls_buf_printf(buf, "x0,y0,x1,y1,left_id,right_id\n"))
        return -1;
    for (size_t k = 0; k < n; k++)
        if (gls_buf_printf(buf, "%.17g,%.17g,%.17g,%.17g,%u,%u\n", s[k].x0, s[k].y0, s[k].x1, s[k].y1, s[k].left,
                           s[k].right))
            return -1;
    return 0;
}
