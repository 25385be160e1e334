/* What glsroad's text outputs share (road_emit.h): numbers, vertices,
 * the streams into road_bufs, and the error of a tessellation over the
 * vertex limit. */
#include <stdio.h>
#include <string.h>
#include "numfmt.h"
#include "road_emit.h"

void road_num(FILE *f, double v)
{
    char b[64];
    gls_fmt_double(b, sizeof b, v);
    fputs(b, f);
}

void road_nums(FILE *f, const double *v, int n, const char *sep)
{
    for (int i = 0; i < n; i++) {
        if (i)
            fputs(sep, f);
        road_num(f, v[i]);
    }
}

void road_vert(FILE *f, rv3 P)
{
    double v[3] = {P.x, P.y, P.z};
    fputs("vert(", f);
    road_nums(f, v, 3, ", ");
    fputs(");", f);
}

int road_too_fine(const road_desc *d, char *err, size_t errlen, const char *what)
{
    return road_error_at(d, d->line_tolerance ? d->line_tolerance : d->line_max_segment ? d->line_max_segment
                                                                                        : d->line_points,
                         err, errlen,
                         "%s within tolerance %g m (max_segment %g m) need more than %ld vertices; raise the "
                         "tolerance or max_segment",
                         what, d->tolerance, d->max_segment, ROAD_MAX_VERTICES);
}

FILE *road_buf_open(road_buf *b, const char *file, char *err, size_t errlen)
{
    memset(b, 0, sizeof *b);
    FILE *f = open_memstream(&b->text, &b->len);
    if (!f)
        snprintf(err, errlen, "%s: error: out of memory", file);
    return f;
}

int road_buf_close(FILE *f, road_buf *b, const char *file, char *err, size_t errlen)
{
    if (fclose(f) != 0 || !b->text) {
        snprintf(err, errlen, "%s: error: out of memory", file);
        return -1;
    }
    return 0;
}
