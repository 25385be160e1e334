/* glsplay --times (play_times.h). */
#include "play_times.h"

void gls_play_times_print(FILE *out, const gls_play_times *t)
{
    /* each stage from the previous mark that happened */
    const char *name[] = {"load", "build", "context", "upload", "plan", "first draw", "write"};
    const double mark[] = {t->load, t->build, t->context, t->upload, t->plan, t->draw, t->write};
    double prev = t->start, last = t->start;
    fprintf(out, "glsplay: times:");
    for (int k = 0; k < 7; k++) {
        if (!(mark[k] > 0))
            continue;
        fprintf(out, "%s %s %.3f s", k ? "," : "", name[k], mark[k] - prev);
        if (k == 1)
            fprintf(out, " (pack %.3f s)", t->pack);
        prev = last = mark[k];
    }
    fprintf(out, "; total %.3f s\n", last - t->start);
}
