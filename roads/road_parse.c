/* Parser of the road description (spec/road.md): one `key value...` per
 * line, `#` comments.  What each key takes comes from the table in
 * road_keys.c; from it this file checks the count of values, their types
 * and ranges, keys given twice or together with a key they exclude, and
 * words every message the same way for every key.  Every error is
 * "file:line:col: error: message", then the offending line and a caret:
 * under the value at fault, else under the key. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "numfmt.h"
#include "road_keys.h"
#include "srcline.h"
#include "suggest.h"
#include "textfile.h"

struct road_pctx {
    const char *file;
    int line;
    char *err;
    size_t errlen;
    const char *text;    /* the whole description, for the source excerpt */
    size_t len;
    const char *linebuf; /* the current line's copy, which tokens point into */
    int keycol;          /* column of the key of the current line           */
    int first[ROAD_KEYS_MAX]; /* the line each key was first given on, or 0 */
};

/* The located error: "FILE:LINE:COL: error: " and the message, then the
   excerpt, through base's one writer of located errors. */
static int verror(char *err, size_t errlen, const char *text, size_t len, const char *file, int line, int col,
                  const char *fmt, va_list ap)
{
    char msg[512];
    vsnprintf(msg, sizeof msg, fmt, ap);
    gls_text_error(err, errlen, text, len, file, (unsigned)line, (unsigned)(col > 0 ? col : 1), "%s", msg);
    return -1;
}

int road_fail(road_pctx *c, const char *tok, const char *fmt, ...)
{
    int col = c->keycol;
    if (tok && c->linebuf && tok >= c->linebuf && tok <= c->linebuf + GLS_TEXT_MAX_LINE)
        col = (int)(tok - c->linebuf) + 1;
    va_list ap;
    va_start(ap, fmt);
    verror(c->err, c->errlen, c->text, c->len, c->file, c->line, col, fmt, ap);
    va_end(ap);
    return -1;
}

int road_line(const road_pctx *c) { return c->line; }

int road_error_at(const road_desc *d, int line, char *err, size_t errlen, const char *fmt, ...)
{
    /* the line's start, and its key: the first word */
    size_t i = 0;
    int at_line = 1;
    if (line <= 0) { /* nothing to point at: the last line */
        line = 1;
        for (size_t k = 0; k + 1 < d->len; k++)
            line += d->text[k] == '\n';
    }
    while (at_line < line && i < d->len)
        at_line += d->text[i++] == '\n';
    int col = 1;
    while (i < d->len && (d->text[i] == ' ' || d->text[i] == '\t'))
        i++, col++;
    va_list ap;
    va_start(ap, fmt);
    verror(err, errlen, d->text, d->len, d->file, line, col, fmt, ap);
    va_end(ap);
    return -1;
}

int road_twice(road_pctx *c, const char *what, int first)
{
    return road_fail(c, NULL, "'%s' given twice (first on line %d)", what, first);
}

int road_profile_add(road_pctx *c, road_profile *p, double x, double v)
{
    if (p->n && !(x > p->x[p->n - 1]))
        return road_fail(c, NULL, "profile points must have increasing %s (%g after %g)",
                         p->by_time ? "times" : "distances", x, p->x[p->n - 1]);
    if (p->n == 0 && x != 0)
        return road_fail(c, NULL, "the first point of a profile must be at %s 0", p->by_time ? "time" : "distance");
    if (p->n == ROAD_MAX_PROFILE_POINTS)
        return road_fail(c, NULL, "a profile has at most %d points", ROAD_MAX_PROFILE_POINTS);
    if ((size_t)p->n == p->cap) {
        size_t cap = p->cap;
        if (gls_grow(&p->x, &cap, (size_t)p->n + 1, sizeof(double)))
            return road_fail(c, NULL, "out of memory");
        double *nv = gls_resize(p->v, cap, sizeof(double)); /* v as long as x */
        if (!nv)
            return road_fail(c, NULL, "out of memory");
        p->v = nv;
        p->cap = cap;
    }
    if (p->n == 0)
        p->line = c->line;
    p->x[p->n] = x;
    p->v[p->n] = v;
    p->n++;
    return 0;
}

/* ---- values ------------------------------------------------------------- */

/* words (or options) as a message lists them: "a, b, c" */
static void word_list(char *out, size_t n, const char *const *words, const road_opt *opts)
{
    size_t k = 0;
    out[0] = 0;
    for (int i = 0; words ? words[i] != NULL : opts[i].word != NULL; i++) {
        const char *w = words ? words[i] : opts[i].word, *arg = words ? NULL : opts[i].arg;
        int m = snprintf(out + k, n - k, "%s%s%s%s", i ? ", " : "", w, arg ? " " : "", arg ? arg : "");
        if (m < 0 || (size_t)m >= n - k)
            return;
        k += (size_t)m;
    }
}

static int valid_name(const char *tok, size_t max)
{
    size_t n = strlen(tok);
    int ok = n > 0 && n < max;
    for (size_t i = 0; ok && i < n; i++)
        ok = isalnum((unsigned char)tok[i]) || tok[i] == '_' || tok[i] == '.';
    return ok && tok[0] != '.' && tok[n - 1] != '.' && !isdigit((unsigned char)tok[0]) && !strstr(tok, "..");
}

/* The range of a number, for its message: "positive", "0..0.5". */
static int in_range(const road_val *v, double x, char *why, size_t n)
{
    const char *note = v->why ? v->why : "";
    const char *l = v->why ? " (" : "", *r = v->why ? ")" : "";
    switch (v->range) {
    case RR_POS:
        snprintf(why, n, "must be positive%s%s%s", l, note, r);
        return x > 0;
    case RR_NONNEG:
        snprintf(why, n, "must not be negative%s%s%s", l, note, r);
        return x >= 0;
    case RR_RANGE:
        snprintf(why, n, "must be %g..%g%s%s%s", v->lo, v->hi, l, note, r);
        return x >= v->lo && x <= v->hi;
    case RR_MIN:
        snprintf(why, n, "must be at least %g%s%s%s", v->lo, l, note, r);
        return x >= v->lo;
    case RR_ANY:
        break;
    }
    return 1;
}

int road_value_parse(road_pctx *c, const char *key, const road_val *v, const char *tok, road_value *out)
{
    switch (v->type) {
    case RV_RAW:
        out->tok = tok;
        return 0;
    case RV_NUM: {
        const char *why = gls_parse_finite(tok, &out->num); /* underflow to 0 is harmless */
        if (why)
            return road_fail(c, tok, "%s: '%s' %s", v->what, tok, why);
        char range[160];
        if (!in_range(v, out->num, range, sizeof range))
            return road_fail(c, tok, "%s %s, got %s", v->what, range, tok);
        return 0;
    }
    case RV_WHOLE: {
        char *end;
        errno = 0;
        long w = strtol(tok, &end, 10);
        if (end == tok || *end || errno || w < (long)v->lo || w > (long)v->hi)
            return road_fail(c, tok, "%s must be a whole number %ld..%ld, got '%s'", v->what, (long)v->lo,
                             (long)v->hi, tok);
        out->whole = w;
        return 0;
    }
    case RV_NAME:
        if (!valid_name(tok, v->size))
            return road_fail(c, tok, "'%s' is not a valid %s name (dotted identifiers, like demo.Tree)", tok,
                             v->what);
        out->tok = tok;
        return 0;
    case RV_IDENT:
        if (strlen(tok) >= v->size || !(isalpha((unsigned char)tok[0]) || tok[0] == '_'))
            return road_fail(c, tok, "%s '%s': use an identifier of at most %zu characters", v->what, tok,
                             v->size - 1);
        for (const char *p = tok; *p; p++)
            if (!isalnum((unsigned char)*p) && *p != '_')
                return road_fail(c, tok, "%s '%s': use letters, digits and '_'", v->what, tok);
        out->tok = tok;
        return 0;
    case RV_WORD:
        for (int i = 0; v->words[i]; i++)
            if (!strcmp(tok, v->words[i])) {
                out->word = i;
                return 0;
            }
        char list[256];
        word_list(list, sizeof list, v->words, NULL);
        return road_fail(c, tok, "'%s': unexpected '%s' (options: %s)", key, tok, list);
    case RV_FLAG:
        out->word = (int)v->lo;
        return 0;
    }
    return 0;
}

/* Store a parsed value at its destination from base. */
static void store(void *base, const road_val *v, const road_value *x)
{
    char *p = (char *)base + v->off;
    if (v->size == 0)
        return;
    switch (v->type) {
    case RV_NUM:
        memcpy(p, &x->num, sizeof x->num);
        break;
    case RV_WHOLE:
        if (v->size == sizeof(int)) {
            int i = (int)x->whole;
            memcpy(p, &i, sizeof i);
        } else {
            memcpy(p, &x->whole, sizeof x->whole); /* a long, or an unsigned long >= 0 */
        }
        break;
    case RV_NAME:
    case RV_IDENT:
        snprintf(p, v->size, "%s", x->tok);
        break;
    case RV_WORD:
    case RV_FLAG:
        memcpy(p, &x->word, sizeof x->word);
        break;
    case RV_RAW:
        break;
    }
}

/* ---- lines -------------------------------------------------------------- */

static int key_index(const char *k)
{
    for (size_t i = 0; i < road_nkeys; i++)
        if (!strcmp(road_keys[i].key, k))
            return (int)i;
    return -1;
}

static int unknown_key(road_pctx *c, const char *k)
{
    const char *names[ROAD_KEYS_MAX];
    for (size_t i = 0; i < road_nkeys; i++)
        names[i] = road_keys[i].key;
    const char *best = gls_suggest(k, strlen(k), names, road_nkeys);
    if (best)
        return road_fail(c, NULL, "unknown key '%s'; did you mean '%s'?", k, best);
    return road_fail(c, NULL, "unknown key '%s'", k);
}

/* "1 value", "3 to 4 values", "at least 2 values" */
static void count_text(const road_key *k, char *out, size_t n)
{
    if (k->max < 0)
        snprintf(out, n, "at least %d value%s", k->min, k->min == 1 ? "" : "s");
    else if (k->min == k->max)
        snprintf(out, n, "%d value%s", k->min, k->min == 1 ? "" : "s");
    else
        snprintf(out, n, "%d to %d values", k->min, k->max);
}

static int parse_line(road_pctx *c, road_desc *d, char **tok, int ntok)
{
    int ki = key_index(tok[0]);
    if (ki < 0)
        return unknown_key(c, tok[0]);
    const road_key *k = &road_keys[ki];
    char **a = tok + 1;
    int na = ntok - 1;
    if (na < k->min || (k->max >= 0 && na > k->max)) {
        char count[64];
        count_text(k, count, sizeof count);
        return road_fail(c, NULL, "'%s' takes %s (%s), got %d", k->key, count, k->values, na);
    }
    if (k->repeat == RK_ONCE && c->first[ki])
        return road_twice(c, k->key, c->first[ki]);
    int xi = k->excludes ? key_index(k->excludes) : -1;
    if (xi >= 0 && c->first[xi]) {
        int lo = ki < xi ? ki : xi, hi = ki < xi ? xi : ki;
        return road_fail(c, NULL, "give either '%s' or '%s', not both ('%s' is on line %d)", road_keys[lo].key,
                         road_keys[hi].key, road_keys[xi].key, c->first[xi]);
    }
    if (!c->first[ki])
        c->first[ki] = c->line;
    if (k->line_off)
        memcpy((char *)d + k->line_off, &c->line, sizeof c->line);
    void *base = k->prepare ? k->prepare(c, d, a, na) : d;
    if (!base)
        return -1;
    int nval = 0;
    while (nval < (int)(sizeof k->val / sizeof k->val[0]) && k->val[nval].what)
        nval++;
    road_value v[ROAD_MAX_WORDS];
    int i = 0;
    for (; i < na && (i < nval || !k->opts); i++) {
        const road_val *val = &k->val[i < nval ? i : nval - 1];
        if (road_value_parse(c, k->key, val, a[i], &v[i]))
            return -1;
        store(base, val, &v[i]);
    }
    for (; i < na; i++) { /* options */
        const road_opt *o = k->opts;
        while (o->word && (strcmp(o->word, a[i]) || (o->arg && i + 1 >= na)))
            o++;
        if (!o->word) {
            char list[256];
            word_list(list, sizeof list, NULL, k->opts);
            return road_fail(c, a[i], "'%s': unexpected '%s' (options: %s)", k->key, a[i], list);
        }
        road_value x;
        if (o->arg)
            i++;
        if (road_value_parse(c, k->key, &o->val, a[i], &x))
            return -1;
        store(base, &o->val, &x);
    }
    return k->finish ? k->finish(c, d, base, a, na, v) : 0;
}

/* The defaults of the values the table stores into the description. */
static void defaults(road_desc *d)
{
    for (size_t i = 0; i < road_nkeys; i++) {
        const road_key *k = &road_keys[i];
        for (int j = 0; !k->prepare && j < (int)(sizeof k->val / sizeof k->val[0]) && k->val[j].what; j++) {
            const road_val *v = &k->val[j];
            road_value x;
            if (v->type == RV_NUM)
                x.num = v->def;
            else if (v->type == RV_WHOLE)
                x.whole = (long)v->def;
            else
                continue;
            store(d, v, &x);
        }
    }
}

/* Checks across lines, once all are read; each reported at the line that
   can fix it, or at the last line (last) when something is missing. */
static int check_whole(road_pctx *c, road_desc *d, int last)
{
    char *err = c->err;
    size_t errlen = c->errlen;
    if (d->npts == 0)
        return road_error_at(d, last, err, errlen,
                             "no control points: give the centre line as 'point X Y Z [WEIGHT]' lines");
    if (d->npts < d->degree + 1)
        return road_error_at(d, d->line_points, err, errlen,
                             "a curve of degree %d needs at least %d control points; there are %d", d->degree,
                             d->degree + 1, d->npts);
    if (d->knots) {
        const char *why = nurbs_check(d->degree, d->npts, d->w, d->nknots, d->knots);
        if (why && d->nknots != d->npts + d->degree + 1)
            return road_error_at(d, d->line_knots, err, errlen, "%d knots given; %d points of degree %d need %d",
                                 d->nknots, d->npts, d->degree, d->npts + d->degree + 1);
        if (why)
            return road_error_at(d, d->line_knots, err, errlen, "%s", why);
    }
    if (d->lane_width.n == 0) { /* the constant width: a profile of one point */
        c->line = d->line_lane_width;
        c->keycol = 1;
        if (road_profile_add(c, &d->lane_width, 0, d->lane_width_const))
            return -1;
    }
    for (int b = 0; b <= ROAD_MAX_LANES; b++) {
        if (d->marking_set[b] && b > d->lanes)
            return road_error_at(d, d->marking_set[b], err, errlen,
                                 "boundary %d does not exist: %d lanes have boundaries 0..%d (0 is the leftmost)", b,
                                 d->lanes, d->lanes);
        if (!d->marking_set[b])
            d->marking[b] = (b == 0 || b == d->lanes) ? MARK_SOLID : MARK_DASHED;
    }
    if (d->frames == -2) {
        /* the product is checked before it is rounded to a count */
        double n = d->duration * d->fps;
        if (!(n < ROAD_MAX_FRAMES + 0.5))
            return road_error_at(d, d->line_frames, err, errlen,
                                 "duration %g s at %g fps is %.6g frames, more than the %ld allowed", d->duration,
                                 d->fps, n, ROAD_MAX_FRAMES);
        d->frames = lround(n);
    }
    if (d->frames == 0)
        return road_error_at(d, d->line_frames, err, errlen, "duration %g s at %g fps is no frame at all",
                             d->duration, d->fps);
    if (d->speed.n == 0)
        return road_error_at(d, last, err, errlen,
                             "no speed profile: give at least one 'speed_at distance 0 SPEED' (m/s)");
    for (int v = 0; v < d->nveh; v++)
        if (d->veh[v].speed.n == 0)
            return road_error_at(d, d->veh[v].line, err, errlen,
                                 "vehicle '%s' has no speed: add 'vehicle_speed %s distance 0 SPEED'", d->veh[v].name,
                                 d->veh[v].name);
    return 0;
}

int road_parse(const char *text, size_t len, const char *fname, road_desc *d, char *err, size_t errlen)
{
    memset(d, 0, sizeof *d);
    d->file = fname;
    d->text = text;
    d->len = len;
    defaults(d);
    road_pctx c = {.file = fname, .err = err, .errlen = errlen, .text = text, .len = len, .keycol = 1};
    gls_text_lines it = {text, len, 0, 0};
    size_t n;
    int got;
    char line[GLS_TEXT_MAX_LINE + 1];
    while ((got = gls_text_next_line(&it, line, &n)) != 0) {
        c.line = (int)it.line;
        c.keycol = 1;
        c.linebuf = NULL;
        if (got < 0) {
            c.keycol = GLS_TEXT_MAX_LINE + 1;
            road_fail(&c, NULL, "line longer than %u bytes", GLS_TEXT_MAX_LINE);
            goto bad;
        }
        if (memchr(line, 0, n)) {
            road_fail(&c, NULL, "NUL byte in the description");
            goto bad;
        }
        char *tok[ROAD_MAX_WORDS + 1];
        int ntok = gls_text_split(line, "#", " \t\r\f\v", tok, ROAD_MAX_WORDS + 1);
        if (ntok > ROAD_MAX_WORDS) {
            road_fail(&c, NULL, "more than %d words on one line", ROAD_MAX_WORDS);
            goto bad;
        }
        if (ntok == 0)
            continue;
        c.linebuf = line;
        c.keycol = (int)(tok[0] - line) + 1;
        if (parse_line(&c, d, tok, ntok))
            goto bad;
    }
    c.linebuf = NULL;
    if (check_whole(&c, d, c.line ? c.line : 1) == 0)
        return 0;
bad:
    road_desc_free(d);
    return -1;
}

static void profile_free(road_profile *p)
{
    free(p->x);
    free(p->v);
}

void road_desc_free(road_desc *d)
{
    free(d->pts);
    free(d->w);
    free(d->knots);
    profile_free(&d->lane_width);
    profile_free(&d->speed);
    for (int v = 0; v < d->nveh; v++)
        profile_free(&d->veh[v].speed);
    free(d->veh);
    const char *f = d->file;
    memset(d, 0, sizeof *d);
    d->file = f;
}
