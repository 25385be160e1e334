/* Streaming reader of trajectory files (spec/road.md), used by glsplay
 * --trajectory and by glsroad --camera-at; see trajectory.h. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "numfmt.h"
#include "readfile.h"
#include "rotation.h"
#include "textfile.h"
#include "trajectory.h"
#include "vec.h"

struct gls_traj {
    FILE *f;
    char *path;
    unsigned line;
    FILE *notes;
    int noted; /* the note on a re-orthonormalised R was given */
    int have_prev;
    uint64_t prev_frame;
    double prev_time;
    char buf[GLS_TEXT_MAX_LINE + 1]; /* one line: memory stays bounded */
};

static int fail(const gls_traj *t, char *err, size_t errlen, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(err, errlen, "%s:%u: error: %s", t->path, t->line, msg);
    return -1;
}

gls_traj *gls_traj_open(const char *path, FILE *notes, char *err, size_t errlen)
{
    gls_traj *t = calloc(1, sizeof *t);
    if (!t || !(t->path = strdup(path))) {
        free(t);
        snprintf(err, errlen, "%s: error: out of memory", path);
        return NULL;
    }
    t->notes = notes;
    struct stat st;
    gls_read_error e;
    int fd = gls_file_open(path, 0, &st, &e);
    if (fd < 0 || !(t->f = fdopen(fd, "r"))) {
        if (fd < 0 && e.status == GLS_READ_DIR)
            snprintf(err, errlen, "%s: error: is a directory, not a trajectory file", path);
        else
            snprintf(err, errlen, "%s: error: cannot open: %s", path, strerror(fd < 0 ? e.err : errno));
        if (fd >= 0)
            close(fd);
        gls_traj_close(t);
        return NULL;
    }
    return t;
}

void gls_traj_close(gls_traj *t)
{
    if (!t)
        return;
    if (t->f)
        fclose(t->f);
    free(t->path);
    free(t);
}

/* A whole number token: digits only, no sign, fits in 64 bits. */
static int parse_u64(const char *s, uint64_t *out)
{
    if (!*s)
        return -1;
    uint64_t v = 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9')
            return -1;
        unsigned d = (unsigned)(*s - '0');
        if (v > (UINT64_MAX - d) / 10)
            return -1;
        v = v * 10 + d;
    }
    *out = v;
    return 0;
}

int gls_traj_next(gls_traj *t, gls_traj_pose *p, char *err, size_t errlen)
{
    for (;;) {
        size_t n;
        int got = gls_text_getline(t->f, t->buf, &n);
        if (got == -2) {
            int e = errno ? errno : EIO;
            t->line++;
            return fail(t, err, errlen, "read error: %s", strerror(e));
        }
        if (got == 0) {
            if (!t->have_prev) {
                t->line = t->line ? t->line : 1;
                return fail(t, err, errlen, "no frames in the trajectory");
            }
            return 0;
        }
        t->line++;
        if (got < 0)
            return fail(t, err, errlen, "line longer than %u bytes", GLS_TEXT_MAX_LINE);
        if (memchr(t->buf, 0, n))
            return fail(t, err, errlen, "NUL byte in the line");
        char *tok[15];
        int nt = gls_text_split(t->buf, "#", " \t\r\n\f\v", tok, 15);
        if (nt == 0)
            continue;
        if (nt != 14)
            return fail(t, err, errlen, "expected 14 values (frame time R[9] T[3]), got %s%d", nt == 15 ? "more than " : "",
                        nt == 15 ? 14 : nt);
        if (parse_u64(tok[0], &p->frame))
            return fail(t, err, errlen, "frame '%s' is not a whole number", tok[0]);
        double v[13];
        for (int i = 0; i < 13; i++) {
            const char *why = gls_parse_double(tok[i + 1], &v[i]);
            if (why)
                return fail(t, err, errlen, "value %d ('%s') %s", i + 2, tok[i + 1], why);
        }
        p->time = v[0];
        memcpy(p->R, v + 1, sizeof p->R);
        memcpy(p->T, v + 10, sizeof p->T);
        p->line = t->line;
        if (t->have_prev && !(p->frame > t->prev_frame))
            return fail(t, err, errlen, "frame %llu does not follow frame %llu: frames must increase",
                        (unsigned long long)p->frame, (unsigned long long)t->prev_frame);
        if (t->have_prev && !(p->time > t->prev_time))
            return fail(t, err, errlen, "time %.17g is not after the previous frame's %.17g", p->time, t->prev_time);
        char why[300];
        int rot = gls_rotation_check(p->R, why, sizeof why);
        if (rot < 0)
            return fail(t, err, errlen, "%s", why);
        /* one note per file: a trajectory printed with few decimals would
           repeat it on every line */
        if (rot > 0 && t->notes && !t->noted++)
            fprintf(t->notes, "%s:%u: note: %s (and on every later line where needed, without a note)\n", t->path,
                    t->line, why);
        t->have_prev = 1;
        t->prev_frame = p->frame;
        t->prev_time = p->time;
        return 1;
    }
}

void gls_traj_compose(const double Rc[9], const double Tc[3], const double Rr[9], const double Tr[3], double R[9],
                      double T[3])
{
    rm_mul(Rc, Rr, R);
    rv3 t = rm_apply(Rc, rv(Tr[0], Tr[1], Tr[2]));
    T[0] = t.x + Tc[0];
    T[1] = t.y + Tc[1];
    T[2] = t.z + Tc[2];
}

int gls_traj_range(const char *s, uint64_t *first, uint64_t *end, char *err, size_t errlen)
{
    const char *colon = strchr(s, ':');
    char a[32] = "", b[32] = "";
    size_t la = colon ? (size_t)(colon - s) : strlen(s);
    size_t lb = colon ? strlen(colon + 1) : 0;
    if (la >= sizeof a || lb >= sizeof b)
        goto bad;
    memcpy(a, s, la);
    memcpy(b, colon ? colon + 1 : "", lb + 1);
    *first = 0;
    *end = UINT64_MAX;
    if (!colon) {
        if (parse_u64(a, first) || *first == UINT64_MAX)
            goto bad;
        *end = *first + 1;
        return 0;
    }
    if (!la && !lb)
        goto bad;
    if (la && parse_u64(a, first))
        goto bad;
    if (lb && parse_u64(b, end))
        goto bad;
    if (*end <= *first) {
        snprintf(err, errlen, "--frames: '%s' is empty (A:B means frames A to B-1)", s);
        return -1;
    }
    return 0;
bad:
    snprintf(err, errlen, "--frames: '%s' is not a frame range (A:B for frames A to B-1, A:, :B, or A)", s);
    return -1;
}
