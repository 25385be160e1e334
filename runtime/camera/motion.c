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

int gls_motion_read(const char *path, FILE *notes, gls_motion *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    FILE *f = gls_text_open(path, "motion file", err, errlen);
    if (!f)
        return -2;
    m->path = malloc(strlen(path) + 1);
    if (m->path)
        strcpy(m->path, path);
    char buf[GLS_TEXT_MAX_LINE + 1];
    size_t n, cap = 0, fcap = 0;
    unsigned line = 0;
    int fmt = FMT_UNKNOWN, noted = 0, rc = -1;
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
        if (line == 1 && strncmp(buf, "# glsroad motion 1", 18) == 0 && strspn(buf + 18, " \t\r\n") == n - 18) {
            fmt = FMT_GLSROAD;
            continue;
        }
        char *tok[15];
        int nt = gls_text_split(buf, "#", " \t\r\n\f\v", tok, 15);
        if (nt == 0)
            continue;
        if (fmt == FMT_UNKNOWN)
            fmt = nt == 12 ? FMT_KITTI : nt == 8 ? FMT_TUM : FMT_UNKNOWN;
        int want = fmt == FMT_GLSROAD ? 14 : fmt == FMT_KITTI ? 12 : fmt == FMT_TUM ? 8 : 0;
        if (!want) {
            fail(err, errlen, path, line,
                 "%d values: not a motion row (\"# glsroad motion 1\" then 14 values, KITTI's 12 or TUM's 8)", nt);
            goto out;
        }
        if (nt != want) {
            fail(err, errlen, path, line, "expected %d values like the first row, got %s%d", want,
                 nt == 15 ? "more than " : "", nt == 15 ? 14 : nt);
            goto out;
        }
        double v[14];
        for (int i = 0; i < nt; i++) {
            const char *why = gls_parse_double(tok[i], &v[i]);
            if (why) {
                fail(err, errlen, path, line, "value %d ('%s') %s", i + 1, tok[i], why);
                goto out;
            }
        }
        uint64_t frame = m->n;
        double RT[12];
        if (fmt == FMT_GLSROAD) {
            if (!(v[0] >= 0 && v[0] <= 0x1p53 && v[0] == floor(v[0]))) {
                fail(err, errlen, path, line, "frame '%s' is not a whole number", tok[0]);
                goto out;
            }
            frame = (uint64_t)v[0];
            memcpy(RT, v + 2, 9 * sizeof *v);
            memcpy(RT + 9, v + 11, 3 * sizeof *v);
        } else if (fmt == FMT_KITTI) {
            for (int r = 0; r < 3; r++) {
                memcpy(RT + 3 * r, v + 4 * r, 3 * sizeof *v);
                RT[9 + r] = v[4 * r + 3];
            }
        } else {
            memcpy(RT + 9, v + 1, 3 * sizeof *v);
            if (gls_rotation_quat(v[4], v[5], v[6], v[7], RT)) {
                fail(err, errlen, path, line, "quaternion (%s %s %s %s) is not of unit length", tok[4], tok[5],
                     tok[6], tok[7]);
                goto out;
            }
        }
        if (m->n && !(frame > m->frame[m->n - 1])) {
            fail(err, errlen, path, line, "frame %llu does not follow frame %llu: frames must increase",
                 (unsigned long long)frame, (unsigned long long)m->frame[m->n - 1]);
            goto out;
        }
        char why[300];
        int rot = gls_rotation_check(RT, why, sizeof why);
        if (rot < 0) {
            fail(err, errlen, path, line, "%s", why);
            goto out;
        }
        if (rot > 0 && notes && !noted++)
            fprintf(notes, "%s:%u: note: %s (and on every later line where needed, without a note)\n", path, line,
                    why);
        if (gls_grow(&m->RT, &cap, m->n + 1, sizeof *m->RT) || gls_grow(&m->frame, &fcap, m->n + 1, sizeof *m->frame)) {
            snprintf(err, errlen, "%s: error: out of memory", path);
            goto out;
        }
        memcpy(m->RT[m->n], RT, sizeof RT);
        m->frame[m->n++] = frame;
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
