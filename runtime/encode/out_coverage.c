/* coverage_F.csv (out_coverage.h, spec/outputs.md "Coverage").  Areas are
 * written with 9 significant digits, which read back as the float32 the
 * engine stored; the background's rest is 1 minus their double sum, so a
 * pixel's lines add up to 1 to within float32 rounding. */
#include "out_coverage.h"

int gls_encode_coverage_csv(const gls_exact_cover *cover, uint32_t w, uint32_t h, gls_buf *buf)
{
    if (gls_buf_printf(buf, "x,y,id,area\n"))
        return -1;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            const gls_exact_cover *c = cover + ((size_t)y * w + x) * GLS_EXACT_COVER_K;
            double sum = 0;
            for (int k = 0; k < GLS_EXACT_COVER_K && c[k].id; k++) {
                if (gls_buf_printf(buf, "%u,%u,%u,%.9g\n", x, y, c[k].id, (double)c[k].area))
                    return -1;
                sum += c[k].area;
            }
            if (sum > 0 && 1 - sum > 1e-6 && gls_buf_printf(buf, "%u,%u,0,%.9g\n", x, y, 1 - sum))
                return -1;
        }
    return 0;
}
