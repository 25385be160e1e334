/* Frame progress and the render-time estimate (progress.h). */
#include "progress.h"
#include "units.h"

void gls_progress_frames(FILE *f, uint64_t done, uint64_t total, double elapsed, int final)
{
    char t[32];
    double rate = elapsed > 0 ? (double)done / elapsed : 0;
    if (final) {
        gls_fmt_duration(t, sizeof t, elapsed);
        fprintf(f, "\rglsplay: %llu frame%s in %s, %.2f frames/s          \n", (unsigned long long)done,
                done == 1 ? "" : "s", t, rate);
    } else {
        gls_fmt_duration(t, sizeof t, rate > 0 ? (double)(total - done) / rate : -1);
        fprintf(f, "\rglsplay: frame %llu/%llu (%.0f%%), %.2f frames/s, %s left   ", (unsigned long long)done,
                (unsigned long long)total, total ? 100.0 * (double)done / (double)total : 100.0, rate, t);
    }
    fflush(f);
}

double gls_estimate_total(double elapsed, uint64_t done, uint64_t per_view, uint64_t views)
{
    if (!done)
        return 0;
    return elapsed / (double)done * (double)per_view * (double)views;
}

int gls_estimate_report(FILE *f, double elapsed, uint64_t done, uint64_t per_view, uint64_t views)
{
    return gls_estimate_report_units(f, elapsed, done, per_view, views, "passes");
}

int gls_estimate_report_units(FILE *f, double elapsed, uint64_t done, uint64_t per_view, uint64_t views,
                              const char *units)
{
    double total = gls_estimate_total(elapsed, done, per_view, views);
    if (!(total > GLS_ESTIMATE_THRESHOLD_S))
        return 0;
    char tt[32], tu[32];
    gls_fmt_duration(tt, sizeof tt, total);
    gls_fmt_duration(tu, sizeof tu, elapsed / (double)done);
    if (per_view > 1)
        fprintf(f, "glsplay: note: estimated render time %s: %llu camera frame%s x %llu anti-aliasing %s x %s "
                   "(measured on the first %llu %s; --explain shows the plan)\n",
                tt, (unsigned long long)views, views == 1 ? "" : "s", (unsigned long long)per_view, units, tu,
                (unsigned long long)done, units);
    else
        fprintf(f, "glsplay: note: estimated render time %s: %llu camera frames x %s (measured on the first %llu)\n",
                tt, (unsigned long long)views, tu, (unsigned long long)done);
    fflush(f);
    return 1;
}
