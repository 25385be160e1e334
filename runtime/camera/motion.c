/* Reading motion files (motion.h). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "motion.h"
#include "numfmt.h"
#include "rotation.h"
#include "textfile.h"

enum { FMT_UNKNOWN, FMT_GLSROAD, FMT_KITTI, FMT_TUM };

static int fail(char *err, size_t errlen, const char *path, unsigned line, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(err, errlen, "%s:%u: error: %s", path, line, msg);
    return -1;
}

/* A motion file being read: the format its first line or row chose, and
 * whether the note of a nearly orthonormal rotation was given. */
typedef struct {
    const char *path;
    FILE *notes;
    int fmt, noted;
    size_t cap, fcap; /* of m->RT and m->frame */
} reader;

/* Row values v (words tok) as a frame and a pose RT (R row-major, then
 * T), as the format lays them out; a row without a frame number is the
 * next one, *frame as given. */
static int row_pose(const reader *rd, unsigned line, const double *v, char *const *tok, uint64_t *frame,
                    double RT[12], char *err, size_t errlen)
{
    if (rd->fmt == FMT_GLSROAD) {
        if (!(v[0] >= 0 && v[0] <= 0x1p53 && v[0] == floor(v[0])))
            return fail(err, errlen, rd->path, line, "frame '%s' is not a whole number", tok[0]);
        *frame = (uint64_t)v[0];
        memcpy(RT, v + 2, 9 * sizeof *v);
        memcpy(RT + 9, v + 11, 3 * sizeof *v);
    } else if (rd->fmt == FMT_KITTI) {
        for (int r = 0; r < 3; r++) {
            memcpy(RT + 3 * r, v + 4 * r, 3 * sizeof *v);
            RT[9 + r] = v[4 * r + 3];
        }
    } else {
        memcpy(RT + 9, v + 1, 3 * sizeof *v);
        if (gls_rotation_quat(v[4], v[5], v[6], v[7], RT))
            return fail(err, errlen, rd->path, line, "quaternion (%s %s %s %s) is not of unit length", tok[4], tok[5],
                        tok[6], tok[7]);
    }
    return 0;
}

/* One line (buf, n bytes): nothing, the glsroad header, or a row, checked
 * and appended to m. */
static int read_line(reader *rd, gls_motion *m, char *buf, size_t n, unsigned line, char *err, size_t errlen)
{
    const char *path = rd->path;
    if (line == 1 && strncmp(buf, "# glsroad motion 1", 18) == 0 && strspn(buf + 18, " \t\r\n") == n - 18) {
        rd->fmt = FMT_GLSROAD;
        return 0;
    }
    char *tok[15];
    int nt = gls_text_split(buf, "#", " \t\r\n\f\v", tok, 15);
    if (nt == 0)
        return 0;
    if (rd->fmt == FMT_UNKNOWN)
        rd->fmt = nt == 12 ? FMT_KITTI : nt == 8 ? FMT_TUM : FMT_UNKNOWN;
    int want = rd->fmt == FMT_GLSROAD ? 14 : rd->fmt == FMT_KITTI ? 12 : rd->fmt == FMT_TUM ? 8 : 0;
    if (!want)
        return fail(err, errlen, path, line,
                    "%d values: not a motion row (\"# glsroad motion 1\" then 14 values, KITTI's 12 or TUM's 8)", nt);
    if (nt != want)
        return fail(err, errlen, path, line, "expected %d values like the first row, got %s%d", want,
                    nt == 15 ? "more than " : "", nt == 15 ? 14 : nt);
    double v[14];
    for (int i = 0; i < nt; i++) {
        const char *why = gls_parse_double(tok[i], &v[i]);
        if (why)
            return fail(err, errlen, path, line, "value %d ('%s') %s", i + 1, tok[i], why);
    }
    uint64_t frame = m->n;
    double RT[12];
    if (row_pose(rd, line, v, tok, &frame, RT, err, errlen))
        return -1;
    if (m->n && !(frame > m->frame[m->n - 1]))
        return fail(err, errlen, path, line, "frame %llu does not follow frame %llu: frames must increase",
                    (unsigned long long)frame, (unsigned long long)m->frame[m->n - 1]);
    char why[300];
    int rot = gls_rotation_check(RT, why, sizeof why);
    if (rot < 0)
        return fail(err, errlen, path, line, "%s", why);
    if (rot > 0 && rd->notes && !rd->noted++)
        fprintf(rd->notes, "%s:%u: note: %s (and on every later line where needed, without a note)\n", path, line,
                why);
    if (gls_grow(&m->RT, &rd->cap, m->n + 1, sizeof *m->RT) ||
        gls_grow(&m->frame, &rd->fcap, m->n + 1, sizeof *m->frame)) {
        snprintf(err, errlen, "%s: error: out of memory", path);
        return -1;
    }
    memcpy(m->RT[m->n], RT, sizeof RT);
    m->frame[m->n++] = frame;
    return 0;
}

int gls_motion_read(const char *path, FILE *notes, gls_motion *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    FILE *f = gls_text_open(path, "motion file", err, errlen);
    if (!f)
        return -2;
    m->path = malloc(strlen(path) + 1);
    if (m->path)
        strcpy(m->path, path);
    reader rd = {path, notes, FMT_UNKNOWN, 0, 0, 0};
    char buf[GLS_TEXT_MAX_LINE + 1];
    size_t n;
    unsigned line = 0;
    int rc = -1;
    for (;;) {
        int got = gls_text_getline(f, buf, &n);
        if (got == 0)
            break;
        line++;
        if (got == -2) {
            fail(err, errlen, path, line, "read error: %s", strerror(errno ? errno : EIO));
            goto out;
        }
        if (got < 0 || memchr(buf, 0, n)) {
            fail(err, errlen, path, line, got < 0 ? "line longer than %u bytes" : "NUL byte in the line",
                 GLS_TEXT_MAX_LINE);
            goto out;
        }
        if (read_line(&rd, m, buf, n, line, err, errlen))
            goto out;
    }
    if (m->n == 0) {
        fail(err, errlen, path, line ? line : 1, "no frames in the motion file");
        goto out;
    }
    rc = 0;
out:
    fclose(f);
    if (rc)
        gls_motion_free(m);
    return rc;
}

int gls_motion_pose(const gls_motion *m, uint64_t k, double R[9], double T[3])
{
    uint64_t lo = 0, hi = m->n;
    while (lo < hi) { /* binary search: frames increase */
        uint64_t mid = lo + (hi - lo) / 2;
        if (m->frame[mid] < k)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo >= m->n || m->frame[lo] != k)
        return -1;
    memcpy(R, m->RT[lo], 9 * sizeof *R);
    memcpy(T, m->RT[lo] + 9, 3 * sizeof *T);
    return 0;
}

void gls_motion_free(gls_motion *m)
{
    free(m->path);
    free(m->frame);
    free(m->RT);
    memset(m, 0, sizeof *m);
}
