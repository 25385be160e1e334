/* --progress json lines (progress_json.h). */
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "progress_json.h"

/* The line in b, written with one fwrite so that it is never split by
 * another thread's message. */
static void put_line(FILE *f, gls_buf *b)
{
    if (b->data) {
        fwrite(b->data, 1, b->len, f);
        fflush(f);
    }
    free(b->data);
}

static void put(gls_buf *b, const char *s)
{
    gls_buf_put(b, s, strlen(s));
}

void gls_progress_json_frame(gls_progress_json *p, uint32_t frame, const char *camera, double now)
{
    if (!p || !p->f)
        return;
    p->done++;
    double el = now - p->t0, rate = el > 0 ? (double)p->done / el : 0;
    double eta = rate > 0 ? (double)(p->total - p->done) / rate : 0;
    char s[256];
    gls_buf b = {0};
    snprintf(s, sizeof s, "{\"event\": \"frame\", \"frame\": %u, \"camera\": ", frame);
    put(&b, s);
    gls_buf_quoted(&b, camera, 1);
    snprintf(s, sizeof s,
             ", \"done\": %llu, \"total\": %llu, \"elapsed_s\": %.3f, \"rate_fps\": %.3f, \"eta_s\": %.3f}\n",
             (unsigned long long)p->done, (unsigned long long)p->total, el, rate, eta);
    put(&b, s);
    put_line(p->f, &b);
}

void gls_progress_json_end(gls_progress_json *p, int ok, double now)
{
    if (!p || !p->f)
        return;
    double el = now - p->t0, rate = el > 0 ? (double)p->done / el : 0;
    char s[320];
    gls_buf b = {0};
    snprintf(s, sizeof s,
             "{\"event\": \"end\", \"status\": \"%s\", \"done\": %llu, \"total\": %llu, \"frames\": %llu, "
             "\"skipped\": %llu, \"elapsed_s\": %.3f, \"rate_fps\": %.3f}\n",
             ok ? "ok" : "error", (unsigned long long)p->done, (unsigned long long)p->total,
             (unsigned long long)(p->cameras ? p->done / p->cameras : 0), (unsigned long long)p->skipped, el, rate);
    put(&b, s);
    put_line(p->f, &b);
}
