/* gls_fmt_duration, gls_fmt_bytes (units.h). */
#include <math.h>
#include <stdio.h>
#include "units.h"

void gls_fmt_duration(char *buf, size_t len, double s)
{
    if (!(s >= 0) || s > 1e9) {
        snprintf(buf, len, "?");
    } else if (s < 1e-3) {
        snprintf(buf, len, "%.0f us", s * 1e6);
    } else if (s < 1) {
        snprintf(buf, len, "%.*f ms", s < 0.1 ? 1 : 0, s * 1e3);
    } else if (s < 10) {
        snprintf(buf, len, "%.2f s", s);
    } else if (s < 59.5) {
        snprintf(buf, len, "%.0f s", s);
    } else if (s < 3599.5) {
        long t = lround(s);
        snprintf(buf, len, "%ld min %02ld s", t / 60, t % 60);
    } else {
        long m = lround(s / 60);
        snprintf(buf, len, "%ld h %02ld min", m / 60, m % 60);
    }
}

void gls_fmt_bytes(char *buf, size_t len, uint64_t b)
{
    static const char *const unit[] = {"KiB", "MiB", "GiB", "TiB"};
    if (b < 1024) {
        snprintf(buf, len, "%llu bytes", (unsigned long long)b);
        return;
    }
    double v = (double)b / 1024;
    int u = 0;
    while (v >= 1024 && u < 3)
        v /= 1024, u++;
    snprintf(buf, len, v < 100 ? "%.1f %s" : "%.0f %s", v, unit[u]);
}
