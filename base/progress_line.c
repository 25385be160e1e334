/* The clock and a long job's progress line (progress_line.h). */
#include <time.h>
#include "progress_line.h"

double gls_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void gls_progress_steps(FILE *f, const char *label, const char *units, uint64_t done, uint64_t total, double t0,
                        double *last, int final)
{
    if (!f)
        return;
    double t = gls_now();
    if (!final && t - *last < 0.5)
        return;
    *last = t;
    double el = t - t0, left = done ? el * (double)(total - done) / (double)done : 0;
    fprintf(f, "\rglsplay: %s: %llu/%llu %s (%.0f%%), %.0f s %s   ", label ? label : "", (unsigned long long)done,
            (unsigned long long)total, units, 100.0 * (double)done / (double)total, final ? el : left,
            final ? "taken" : "left");
    if (final)
        fputc('\n', f);
    fflush(f);
}
