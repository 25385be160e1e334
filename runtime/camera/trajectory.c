/* Reader of trajectory files (spec/road.md), used by glsplay
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
    gls_traj_text own;        /* gls_traj_open's text (data NULL otherwise) */
    const gls_traj_text *tx;  /* the text read, own or the caller's         */
    gls_text_lines it;
    FILE *notes;
    int noted; /* the note on a re-orthonormalised R was given */
    int fmt;        /* values a line: 14 glsroad, 12 KITTI, 8 TUM; 0 before the first */
    uint64_t rows;  /* data lines read (KITTI and TUM number frames by row) */
    int have_prev;
    uint64_t prev_frame;
    double prev_time;
    char buf[GLS_TEXT_MAX_LINE + 1]; /* one line at a time */
};

static int fail(const gls_traj *t, char *err, size_t errlen, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(err, errlen, "%s:%u: error: %s", t->tx->path, t->it.line, msg);
    return -1;
}

/* The bytes of fd, up to GLS_TRAJ_MAX_FILE, stopping at the first line
 * longer than GLS_TEXT_MAX_LINE (an endless line, /dev/zero, costs a
 * line's memory, not the limit's).  0, or -1 with the message in err. */
static int read_text(int fd, gls_traj_text *tx, char *err, size_t errlen)
{
    size_t cap = 0, run = 0; /* run: bytes since the last newline */
    unsigned line = 1;
    for (;;) {
        if (tx->len + 65536 + 1 > cap) {
            size_t ncap = cap ? 2 * cap : 65536 + 1;
            char *p = realloc(tx->data, ncap);
            if (!p) {
                snprintf(err, errlen, "%s: error: out of memory", tx->path);
                return -1;
            }
            tx->data = p, cap = ncap;
        }
        ssize_t r = read(fd, tx->data + tx->len, 65536);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            snprintf(err, errlen, "%s: error: cannot read: %s", tx->path, strerror(errno));
            return -1;
        }
        if (r == 0)
            break;
        for (size_t i = tx->len; i < tx->len + (size_t)r; i++) {
            if (tx->data[i] == '\n') {
                run = 0, line++;
            } else if (++run > GLS_TEXT_MAX_LINE) {
                snprintf(err, errlen, "%s:%u: error: line longer than %u bytes", tx->path, line, GLS_TEXT_MAX_LINE);
                return -1;
            }
        }
        tx->len += (size_t)r;
        if (tx->len > GLS_TRAJ_MAX_FILE) {
            snprintf(err, errlen, "%s: error: trajectory file larger than %u MiB", tx->path,
                     (unsigned)(GLS_TRAJ_MAX_FILE >> 20));
            return -1;
        }
    }
    tx->data[tx->len] = 0;
    return 0;
}

int gls_traj_load(const char *path, gls_traj_text *tx, char *err, size_t errlen)
{
    memset(tx, 0, sizeof *tx);
    if (!(tx->path = strdup(path))) {
        snprintf(err, errlen, "%s: error: out of memory", path);
        return -1;
    }
    /* every input is a regular file (readfile.h): a FIFO or a device is
     * refused before anything is read, so none blocks the run */
    char why[300];
    FILE *f = gls_text_open(path, "trajectory file", why, sizeof why);
    if (!f) {
        snprintf(err, errlen, "%s: error: %s", path, why);
        gls_traj_text_free(tx);
        return -1;
    }
    int rc = read_text(fileno(f), tx, err, errlen);
    fclose(f);
    if (rc)
        gls_traj_text_free(tx);
    return rc;
}

void gls_traj_text_free(gls_traj_text *tx)
{
    free(tx->path);
    free(tx->data);
    memset(tx, 0, sizeof *tx);
}

gls_traj *gls_traj_open_text(const gls_traj_text *tx, FILE *notes)
{
    gls_traj *t = calloc(1, sizeof *t);
    if (!t)
        return NULL;
    t->tx = tx;
    t->it.text = tx->data;
    t->it.len = tx->len;
    t->notes = notes;
    return t;
}

gls_traj *gls_traj_open(const char *path, FILE *notes, char *err, size_t errlen)
{
    gls_traj_text tx;
    if (gls_traj_load(path, &tx, err, errlen))
        return NULL;
    gls_traj *t = calloc(1, sizeof *t);
    if (!t) {
        snprintf(err, errlen, "%s: error: out of memory", path);
        gls_traj_text_free(&tx);
        return NULL;
    }
    t->own = tx;
    t->tx = &t->own;
    t->it.text = t->own.data;
    t->it.len = t->own.len;
    t->notes = notes;
    return t;
}

void gls_traj_close(gls_traj *t)
{
    if (!t)
        return;
    gls_traj_text_free(&t->own);
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

/* R a rotation (gls_rotation_check, replaced in place by the nearest one
 * within 1e-4): 0, or -1 with the error in err. */
static int check_rotation(gls_traj *t, double R[9], char *err, size_t errlen)
{
    char why[300];
    int rot = gls_rotation_check(R, why, sizeof why);
    if (rot < 0)
        return fail(t, err, errlen, "%s", why);
    /* one note per file: a trajectory printed with few decimals would
       repeat it on every line */
    if (rot > 0 && t->notes && !t->noted++)
        fprintf(t->notes, "%s:%u: note: %s (and on every later line where needed, without a note)\n", t->tx->path,
                t->it.line, why);
    return 0;
}

int gls_traj_next(gls_traj *t, gls_traj_pose *p, char *err, size_t errlen)
{
    for (;;) {
        size_t n;
        int got = gls_text_next_line(&t->it, t->buf, &n);
        if (got == 0) {
            if (!t->have_prev) {
                t->it.line = t->it.line ? t->it.line : 1;
                return fail(t, err, errlen, "no frames in the trajectory");
            }
            return 0;
        }
        if (got < 0) /* refused by gls_traj_load already; a caller's text may hold one */
            return fail(t, err, errlen, "line longer than %u bytes", GLS_TEXT_MAX_LINE);
        if (memchr(t->buf, 0, n))
            return fail(t, err, errlen, "NUL byte in the line");
        char *tok[15];
        int nt = gls_text_split(t->buf, "#", " \t\r\n\f\v", tok, 15);
        if (nt == 0)
            continue;
        /* the first line's count tells the format (trajectory.h) */
        if (!t->fmt && (nt == 14 || nt == 12 || nt == 8))
            t->fmt = nt;
        if (!t->fmt)
            return fail(t, err, errlen,
                        "expected 14 values (frame time R[9] T[3]), 12 (KITTI: [R|t] row-major) or 8 (TUM: time tx ty "
                        "tz qx qy qz qw), got %s%d",
                        nt == 15 ? "more than " : "", nt == 15 ? 14 : nt);
        if (nt != t->fmt)
            return fail(t, err, errlen, "expected %d values (%s), got %s%d", t->fmt,
                        t->fmt == 14 ? "frame time R[9] T[3]"
                        : t->fmt == 12 ? "KITTI, like the first line: [R|t] row-major"
                                       : "TUM, like the first line: time tx ty tz qx qy qz qw",
                        nt == 15 ? "more than " : "", nt == 15 ? 14 : nt);
        int first_value = t->fmt == 14 ? 1 : 0;
        if (t->fmt == 14 && parse_u64(tok[0], &p->frame))
            return fail(t, err, errlen, "frame '%s' is not a whole number", tok[0]);
        double v[13];
        for (int i = first_value; i < nt; i++) {
            const char *why = gls_parse_double(tok[i], &v[i - first_value]);
            if (why)
                return fail(t, err, errlen, "value %d ('%s') %s", i + 1, tok[i], why);
        }
        if (t->fmt == 14) {
            p->time = v[0];
            memcpy(p->R, v + 1, sizeof p->R);
            memcpy(p->T, v + 10, sizeof p->T);
        } else {
            /* KITTI and TUM give the camera's pose in the world,
             * P_world = Rw P_cam + c: frame = row, and the world -> rig
             * pose is R = Rw^T, T = -Rw^T c (after Rw is checked) */
            double Rw[9], c[3];
            p->frame = t->rows;
            if (t->fmt == 12) {
                p->time = (double)t->rows; /* KITTI poses carry no time */
                for (int r = 0; r < 3; r++) {
                    memcpy(Rw + 3 * r, v + 4 * r, 3 * sizeof *v);
                    c[r] = v[4 * r + 3];
                }
            } else {
                p->time = v[0];
                memcpy(c, v + 1, sizeof c);
                if (gls_rotation_quat(v[4], v[5], v[6], v[7], Rw))
                    return fail(t, err, errlen, "quaternion (%s %s %s %s) is not of unit length", tok[4], tok[5],
                                tok[6], tok[7]);
            }
            if (check_rotation(t, Rw, err, errlen))
                return -1;
            rm_transpose(Rw, p->R);
            rv3 T = rm_apply(p->R, rv(c[0], c[1], c[2]));
            p->T[0] = -T.x, p->T[1] = -T.y, p->T[2] = -T.z;
        }
        t->rows++;
        p->line = t->it.line;
        if (t->have_prev && !(p->frame > t->prev_frame))
            return fail(t, err, errlen, "frame %llu does not follow frame %llu: frames must increase",
                        (unsigned long long)p->frame, (unsigned long long)t->prev_frame);
        if (t->have_prev && !(p->time > t->prev_time))
            return fail(t, err, errlen, "time %.17g is not after the previous frame's %.17g", p->time, t->prev_time);
        if (t->fmt == 14 && check_rotation(t, p->R, err, errlen))
            return -1;
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

void gls_traj_gaps_init(gls_traj_gaps *g, uint64_t first)
{
    memset(g, 0, sizeof *g);
    g->next = first;
}

/* frames next..upto-1 are missing */
static void gap_to(gls_traj_gaps *g, uint64_t upto)
{
    if (upto <= g->next)
        return;
    if (g->runs < GLS_TRAJ_GAPS_SHOWN)
        g->a[g->runs] = g->next, g->b[g->runs] = upto - 1;
    g->runs++;
    g->frames += upto - g->next;
}

void gls_traj_gaps_row(gls_traj_gaps *g, uint64_t frame)
{
    gap_to(g, frame);
    g->next = frame + 1;
}

void gls_traj_gaps_end(gls_traj_gaps *g, uint64_t end)
{
    if (end != UINT64_MAX)
        gap_to(g, end);
}

int gls_traj_gaps_message(const gls_traj_gaps *g, const char *path, char *buf, size_t len)
{
    if (!g->frames)
        return 0;
    char list[256] = "";
    size_t k = 0, shown = g->runs < GLS_TRAJ_GAPS_SHOWN ? (size_t)g->runs : GLS_TRAJ_GAPS_SHOWN;
    for (size_t i = 0; i < shown && k < sizeof list; i++) {
        const char *sep = i == 0 ? "" : i + 1 == shown && shown == g->runs ? " and " : ", ";
        int n = g->a[i] == g->b[i] ? snprintf(list + k, sizeof list - k, "%s%llu", sep, (unsigned long long)g->a[i])
                                   : snprintf(list + k, sizeof list - k, "%s%llu-%llu", sep,
                                              (unsigned long long)g->a[i], (unsigned long long)g->b[i]);
        k += n > 0 ? (size_t)n : 0;
    }
    if (g->runs > shown && k < sizeof list)
        snprintf(list + k, sizeof list - k, ", ... (%llu frames in %llu runs)", (unsigned long long)g->frames,
                 (unsigned long long)g->runs);
    snprintf(buf, len, "frame%s %s asked for by --frames %s no row in the trajectory %s", g->frames == 1 ? "" : "s",
             list, g->frames == 1 ? "has" : "have", path);
    return 1;
}
