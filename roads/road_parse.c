/* Parser of the road description (spec/road.md): one `key value...` per
 * line, `#` comments.  Every error is "file:line:col: error: message", then
 * the offending line and a caret under the column. */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "buf.h"
#include "numfmt.h"
#include "road.h"
#include "srcline.h"
#include "suggest.h"
#include "textfile.h"

#define MAXTOK 64

typedef struct {
    const char *file;
    int line;
    char *err;
    size_t errlen;
    const char *text;    /* the whole description, for the source excerpt */
    size_t len;
    const char *linebuf; /* the current line's copy, which tokens point into */
    int col;             /* column of the key of the current line           */
} pctx;

/* Point the next error at token tok of the current line. */
static void at(pctx *c, const char *tok)
{
    if (c->linebuf && tok >= c->linebuf && tok <= c->linebuf + GLS_TEXT_MAX_LINE)
        c->col = (int)(tok - c->linebuf) + 1;
}

static int fail(pctx *c, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    gls_text_error(c->err, c->errlen, c->text, c->len, c->file, (unsigned)c->line, (unsigned)(c->col > 0 ? c->col : 1),
                   "%s", msg);
    return -1;
}

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
    unsigned col = 1;
    while (i < d->len && (d->text[i] == ' ' || d->text[i] == '\t'))
        i++, col++;
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(err, errlen, "%s:%d:%u: error: %s", d->file, line, col, msg);
    if (d->text)
        gls_append_source_line(err, errlen, d->text, d->len, (unsigned)line, col);
    return -1;
}

static int num(pctx *c, const char *tok, const char *what, double *out)
{
    const char *why = gls_parse_finite(tok, out); /* underflow to 0 is harmless */
    if (why) {
        at(c, tok);
        return fail(c, "%s: '%s' %s", what, tok, why);
    }
    return 0;
}

static int pos(pctx *c, const char *tok, const char *what, double *out)
{
    if (num(c, tok, what, out))
        return -1;
    if (!(*out > 0))
        return fail(c, "%s must be positive, got %s", what, tok);
    return 0;
}

static int nonneg(pctx *c, const char *tok, const char *what, double *out)
{
    if (num(c, tok, what, out))
        return -1;
    if (*out < 0)
        return fail(c, "%s must not be negative, got %s", what, tok);
    return 0;
}

static int whole(pctx *c, const char *tok, const char *what, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(tok, &end, 10);
    if (end == tok || *end || errno || v < lo || v > hi)
        return fail(c, "%s must be a whole number %ld..%ld, got '%s'", what, lo, hi, tok);
    *out = v;
    return 0;
}

static int grow(void **p, int *cap, int need, size_t elem)
{
    size_t c = (size_t)*cap;
    if (gls_grow(p, &c, (size_t)need, elem) || c > INT_MAX)
        return -1;
    *cap = (int)c;
    return 0;
}

static int profile_add(pctx *c, road_profile *p, double x, double v)
{
    if (p->n && !(x > p->x[p->n - 1]))
        return fail(c, "profile points must have increasing %s (%g after %g)", p->by_time ? "times" : "distances",
                    x, p->x[p->n - 1]);
    if (p->n == 0 && x != 0)
        return fail(c, "the first point of a profile must be at %s 0", p->by_time ? "time" : "distance");
    if (p->n == ROAD_MAX_PROFILE_POINTS)
        return fail(c, "a profile has at most %d points", ROAD_MAX_PROFILE_POINTS);
    if (p->n == p->cap) {
        int cap = p->cap ? 2 * p->cap : 8;
        double *nx = realloc(p->x, sizeof(double) * cap);
        if (!nx)
            return fail(c, "out of memory");
        p->x = nx;
        double *nv = realloc(p->v, sizeof(double) * cap);
        if (!nv)
            return fail(c, "out of memory");
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

/* A speed point "distance|time X V" into profile p. */
static int speed_point(pctx *c, road_profile *p, char **tok, int ntok)
{
    if (ntok != 3)
        return fail(c, "expected 'distance X SPEED' or 'time T SPEED'");
    int by_time;
    if (!strcmp(tok[0], "distance"))
        by_time = 0;
    else if (!strcmp(tok[0], "time"))
        by_time = 1;
    else
        return fail(c, "'%s': the speed is given at a 'distance' or a 'time'", tok[0]);
    if (p->n && p->by_time != by_time)
        return fail(c, "a speed profile is given either by distance or by time, not both");
    p->by_time = by_time;
    double x, v;
    if (nonneg(c, tok[1], by_time ? "time" : "distance", &x))
        return -1;
    if (by_time ? nonneg(c, tok[2], "speed", &v) : pos(c, tok[2], "speed (by distance it must be > 0: the vehicle could never pass a point of speed 0)", &v))
        return -1;
    return profile_add(c, p, x, v);
}

static int colour(pctx *c, char **tok, int ntok, double out[3])
{
    if (ntok != 3)
        return fail(c, "a colour is three numbers r g b in 0..1");
    for (int i = 0; i < 3; i++) {
        if (num(c, tok[i], "colour component", &out[i]))
            return -1;
        if (out[i] < 0 || out[i] > 1)
            return fail(c, "colour component %s is outside 0..1", tok[i]);
    }
    return 0;
}

static int name_arg(pctx *c, const char *tok, char *out, const char *what)
{
    size_t n = strlen(tok);
    int ok = n > 0 && n < ROAD_NAME_MAX;
    for (size_t i = 0; ok && i < n; i++)
        ok = isalnum((unsigned char)tok[i]) || tok[i] == '_' || tok[i] == '.';
    if (!ok || tok[0] == '.' || tok[n - 1] == '.' || isdigit((unsigned char)tok[0]) || strstr(tok, ".."))
        return fail(c, "'%s' is not a valid %s name (dotted identifiers, like demo.Tree)", tok, what);
    memcpy(out, tok, n + 1);
    return 0;
}

static const char *const KEYS[] = {
    "degree", "point", "knots", "lanes", "lane_width", "lane_width_at", "shoulder", "verge", "marking",
    "marking_width", "dash", "double_gap", "marking_height", "bank_max", "bank_speed", "tolerance",
    "max_segment", "road_color", "marking_color", "verge_color", "road_texture", "verge_texture", "trees", "fps",
    "frames", "duration", "start", "speed_at", "vehicle_lateral", "rig_height", "rig_lateral", "rig_forward",
    "rig_pitch", "rig_yaw", "rig_roll", "body_freq", "body_damping", "accel_pitch", "roughness", "wheelbase", "seed",
    "vehicle", "vehicle_speed", NULL};

static road_vehicle *find_vehicle(road_desc *d, const char *name)
{
    for (int i = 0; i < d->nveh; i++)
        if (!strcmp(d->veh[i].name, name))
            return &d->veh[i];
    return NULL;
}

static int parse_line(pctx *c, road_desc *d, char **tok, int ntok, int *seen_degree)
{
    const char *k = tok[0];
    char **a = tok + 1;
    int na = ntok - 1;
    long lv;
#define NARGS(want)                                                                              \
    if (na != (want))                                                                            \
    return fail(c, "'%s' takes %d value%s, got %d", k, (want), (want) == 1 ? "" : "s", na)
    if (!strcmp(k, "degree")) {
        NARGS(1);
        if (*seen_degree)
            return fail(c, "'degree' given twice");
        if (whole(c, a[0], "degree", 1, NURBS_MAX_DEGREE, &lv))
            return -1;
        d->degree = (int)lv;
        *seen_degree = 1;
    } else if (!strcmp(k, "point")) {
        if (na != 3 && na != 4)
            return fail(c, "'point' takes x y z [weight], got %d values", na);
        if (d->npts == ROAD_MAX_POINTS)
            return fail(c, "at most %d control points", ROAD_MAX_POINTS);
        if (grow((void **)&d->pts, &d->ncap, d->npts + 1, 3 * sizeof(double)))
            return fail(c, "out of memory");
        double *w = realloc(d->w, sizeof(double) * d->ncap);
        if (!w)
            return fail(c, "out of memory");
        d->w = w;
        for (int i = 0; i < 3; i++)
            if (num(c, a[i], "coordinate", &d->pts[3 * d->npts + i]))
                return -1;
        d->w[d->npts] = 1;
        if (na == 4 && pos(c, a[3], "weight", &d->w[d->npts]))
            return -1;
        if (d->npts == 0)
            d->line_points = c->line;
        d->npts++;
    } else if (!strcmp(k, "knots")) {
        if (d->knots)
            return fail(c, "'knots' given twice");
        if (na < 2)
            return fail(c, "'knots' needs the whole knot vector");
        d->knots = malloc(sizeof(double) * na);
        if (!d->knots)
            return fail(c, "out of memory");
        for (int i = 0; i < na; i++)
            if (num(c, a[i], "knot", &d->knots[i]))
                return -1;
        d->nknots = na;
        d->line_knots = c->line;
    } else if (!strcmp(k, "lanes")) {
        NARGS(1);
        if (whole(c, a[0], "lanes", 1, ROAD_MAX_LANES, &lv))
            return -1;
        d->lanes = (int)lv;
    } else if (!strcmp(k, "lane_width")) {
        NARGS(1);
        if (d->line_lane_width)
            return fail(c, "'lane_width' given twice");
        d->line_lane_width = c->line;
        return pos(c, a[0], "lane width", &d->lane_width_const);
    } else if (!strcmp(k, "lane_width_at")) {
        NARGS(2);
        double s, w;
        if (nonneg(c, a[0], "distance", &s) || pos(c, a[1], "lane width", &w))
            return -1;
        return profile_add(c, &d->lane_width, s, w);
    } else if (!strcmp(k, "shoulder")) {
        NARGS(1);
        return nonneg(c, a[0], "shoulder", &d->shoulder);
    } else if (!strcmp(k, "verge")) {
        NARGS(1);
        return nonneg(c, a[0], "verge", &d->verge);
    } else if (!strcmp(k, "marking")) {
        NARGS(2);
        if (whole(c, a[0], "boundary index", 0, ROAD_MAX_LANES, &lv))
            return -1;
        static const char *const st[] = {"none", "solid", "dashed", "double"};
        int s = -1;
        for (int i = 0; i < 4; i++)
            if (!strcmp(a[1], st[i]))
                s = i;
        if (s < 0)
            return fail(c, "unknown marking '%s' (the styles are solid, dashed, double, none)", a[1]);
        d->marking[lv] = s;
        d->marking_set[lv] = c->line;
    } else if (!strcmp(k, "marking_width")) {
        NARGS(1);
        return pos(c, a[0], "marking width", &d->marking_width);
    } else if (!strcmp(k, "dash")) {
        NARGS(2);
        d->line_dash = c->line;
        return pos(c, a[0], "dash length", &d->dash) || pos(c, a[1], "gap length", &d->gap) ? -1 : 0;
    } else if (!strcmp(k, "double_gap")) {
        NARGS(1);
        return pos(c, a[0], "double_gap", &d->double_gap);
    } else if (!strcmp(k, "marking_height")) {
        NARGS(1);
        return nonneg(c, a[0], "marking height", &d->marking_height);
    } else if (!strcmp(k, "bank_max")) {
        NARGS(1);
        if (nonneg(c, a[0], "bank_max", &d->bank_max))
            return -1;
        if (d->bank_max > 0.5)
            return fail(c, "bank_max is a cross slope (rise over run), at most 0.5; got %s", a[0]);
    } else if (!strcmp(k, "bank_speed")) {
        NARGS(1);
        return pos(c, a[0], "bank_speed", &d->bank_speed);
    } else if (!strcmp(k, "tolerance")) {
        NARGS(1);
        d->line_tolerance = c->line;
        if (pos(c, a[0], "tolerance", &d->tolerance))
            return -1;
        if (d->tolerance < 1e-6)
            return fail(c, "tolerance below a micrometre (%s) is beyond what the tessellation can meet", a[0]);
    } else if (!strcmp(k, "max_segment")) {
        NARGS(1);
        d->line_max_segment = c->line;
        return pos(c, a[0], "max_segment", &d->max_segment);
    } else if (!strcmp(k, "road_color")) {
        return colour(c, a, na, d->road_color);
    } else if (!strcmp(k, "marking_color")) {
        return colour(c, a, na, d->marking_color);
    } else if (!strcmp(k, "verge_color")) {
        return colour(c, a, na, d->verge_color);
    } else if (!strcmp(k, "road_texture") || !strcmp(k, "verge_texture")) {
        NARGS(2);
        int r = k[0] == 'r';
        if (name_arg(c, a[0], r ? d->road_texture : d->verge_texture, "texture"))
            return -1;
        return pos(c, a[1], "texture tile size", r ? &d->road_tile : &d->verge_tile);
    } else if (!strcmp(k, "trees")) {
        /* trees EVERY OFFSET [left|right|both] [start S] [object NAME] */
        if (na < 2)
            return fail(c, "'trees' takes EVERY OFFSET [left|right|both] [start S] [object NAME]");
        if (d->ntrees == 16)
            return fail(c, "at most 16 'trees' lines");
        road_trees *t = &d->trees[d->ntrees];
        memset(t, 0, sizeof *t);
        t->sides = 3;
        t->line = c->line;
        if (pos(c, a[0], "tree spacing", &t->every) || nonneg(c, a[1], "tree offset from the road edge", &t->offset))
            return -1;
        for (int i = 2; i < na; i++) {
            if (!strcmp(a[i], "left"))
                t->sides = 1;
            else if (!strcmp(a[i], "right"))
                t->sides = 2;
            else if (!strcmp(a[i], "both"))
                t->sides = 3;
            else if (!strcmp(a[i], "start") && i + 1 < na) {
                if (nonneg(c, a[++i], "start", &t->start))
                    return -1;
            } else if (!strcmp(a[i], "object") && i + 1 < na) {
                if (name_arg(c, a[++i], t->object, "object"))
                    return -1;
            } else
                return fail(c, "'trees': unexpected '%s' (options: left, right, both, start S, object NAME)", a[i]);
        }
        d->ntrees++;
    } else if (!strcmp(k, "fps")) {
        NARGS(1);
        d->line_fps = c->line;
        return pos(c, a[0], "fps", &d->fps);
    } else if (!strcmp(k, "frames") || !strcmp(k, "duration")) {
        NARGS(1);
        if (d->line_frames)
            return fail(c, "'frames' or 'duration' given twice");
        d->line_frames = c->line;
        if (k[0] == 'f') {
            if (whole(c, a[0], "frames", 1, ROAD_MAX_FRAMES, &lv))
                return -1;
            d->frames = lv;
        } else {
            /* frames = round(duration * fps), resolved once fps is known */
            if (nonneg(c, a[0], "duration", &d->duration))
                return -1;
            d->frames = -2;
        }
    } else if (!strcmp(k, "start")) {
        NARGS(1);
        return nonneg(c, a[0], "start", &d->start);
    } else if (!strcmp(k, "speed_at")) {
        return speed_point(c, &d->speed, a, na);
    } else if (!strcmp(k, "vehicle_lateral")) {
        NARGS(1);
        return num(c, a[0], "vehicle_lateral", &d->vehicle_lateral);
    } else if (!strcmp(k, "rig_height") || !strcmp(k, "rig_lateral") || !strcmp(k, "rig_forward")) {
        NARGS(1);
        double *dst = k[4] == 'h' ? &d->rig_height : k[4] == 'l' ? &d->rig_lateral : &d->rig_forward;
        return num(c, a[0], k, dst);
    } else if (!strcmp(k, "rig_pitch") || !strcmp(k, "rig_yaw") || !strcmp(k, "rig_roll")) {
        NARGS(1);
        double *dst = k[4] == 'p' ? &d->rig_pitch : k[4] == 'y' ? &d->rig_yaw : &d->rig_roll;
        if (num(c, a[0], k, dst))
            return -1;
        if (fabs(*dst) > 180)
            return fail(c, "%s is in degrees, -180..180; got %s", k, a[0]);
    } else if (!strcmp(k, "body_freq")) {
        NARGS(1);
        return pos(c, a[0], "body_freq (Hz)", &d->body_freq);
    } else if (!strcmp(k, "body_damping")) {
        NARGS(1);
        return nonneg(c, a[0], "body_damping (damping ratio)", &d->body_damping);
    } else if (!strcmp(k, "accel_pitch")) {
        NARGS(1);
        return num(c, a[0], "accel_pitch (degrees per m/s^2)", &d->accel_pitch);
    } else if (!strcmp(k, "roughness")) {
        NARGS(1);
        return nonneg(c, a[0], "roughness (m rms)", &d->roughness);
    } else if (!strcmp(k, "wheelbase")) {
        NARGS(1);
        return pos(c, a[0], "wheelbase", &d->wheelbase);
    } else if (!strcmp(k, "seed")) {
        NARGS(1);
        if (whole(c, a[0], "seed", 0, 2147483647L, &lv))
            return -1;
        d->seed = (unsigned long)lv;
    } else if (!strcmp(k, "vehicle")) {
        /* vehicle NAME lateral L start S [oncoming] [object OBJ] */
        if (na < 1)
            return fail(c, "'vehicle' takes NAME [lateral L] [start S] [oncoming] [object OBJ]");
        if (strlen(a[0]) >= 64 || !(isalpha((unsigned char)a[0][0]) || a[0][0] == '_'))
            return fail(c, "vehicle name '%s': use an identifier of at most 63 characters", a[0]);
        for (const char *p = a[0]; *p; p++)
            if (!isalnum((unsigned char)*p) && *p != '_')
                return fail(c, "vehicle name '%s': use letters, digits and '_'", a[0]);
        if (find_vehicle(d, a[0]))
            return fail(c, "vehicle '%s' is already defined", a[0]);
        if (d->nveh == ROAD_MAX_VEHICLES)
            return fail(c, "at most %d 'vehicle' lines", ROAD_MAX_VEHICLES);
        if (grow((void **)&d->veh, &d->vcap, d->nveh + 1, sizeof(road_vehicle)))
            return fail(c, "out of memory");
        road_vehicle *v = &d->veh[d->nveh];
        memset(v, 0, sizeof *v);
        snprintf(v->name, sizeof v->name, "%s", a[0]);
        v->line = c->line;
        for (int i = 1; i < na; i++) {
            if (!strcmp(a[i], "lateral") && i + 1 < na) {
                if (num(c, a[++i], "lateral", &v->lateral))
                    return -1;
            } else if (!strcmp(a[i], "start") && i + 1 < na) {
                if (nonneg(c, a[++i], "start", &v->start))
                    return -1;
            } else if (!strcmp(a[i], "oncoming")) {
                v->oncoming = 1;
            } else if (!strcmp(a[i], "object") && i + 1 < na) {
                if (name_arg(c, a[++i], v->object, "object"))
                    return -1;
            } else
                return fail(c, "'vehicle': unexpected '%s' (options: lateral L, start S, oncoming, object NAME)", a[i]);
        }
        d->nveh++;
    } else if (!strcmp(k, "vehicle_speed")) {
        if (na < 1)
            return fail(c, "'vehicle_speed' takes NAME distance|time X SPEED");
        road_vehicle *v = find_vehicle(d, a[0]);
        if (!v)
            return fail(c, "unknown vehicle '%s' (define it with a 'vehicle' line first)", a[0]);
        return speed_point(c, &v->speed, a + 1, na - 1);
    } else {
        const char *best = gls_suggest(k, strlen(k), KEYS, (size_t)-1);
        if (best)
            return fail(c, "unknown key '%s'; did you mean '%s'?", k, best);
        return fail(c, "unknown key '%s'", k);
    }
    return 0;
#undef NARGS
}

static void defaults(road_desc *d)
{
    d->degree = 3;
    d->tolerance = 0.001;
    d->max_segment = 10;
    d->lanes = 2;
    d->lane_width_const = 3.5;
    d->shoulder = 0.5;
    d->marking_width = 0.12;
    d->dash = 3;
    d->gap = 9;
    d->double_gap = 0.12;
    d->marking_height = 0.01;
    d->bank_speed = 25;
    double rc[3] = {0.32, 0.32, 0.34}, mc[3] = {0.95, 0.95, 0.9}, vc[3] = {0.25, 0.45, 0.2};
    memcpy(d->road_color, rc, sizeof rc);
    memcpy(d->marking_color, mc, sizeof mc);
    memcpy(d->verge_color, vc, sizeof vc);
    d->fps = 25;
    d->frames = -1;
    d->rig_height = 1.5;
    d->body_freq = 1.2;
    d->body_damping = 0.3;
    d->wheelbase = 2.7;
    d->seed = 1;
}

int road_parse(const char *text, size_t len, const char *fname, road_desc *d, char *err, size_t errlen)
{
    memset(d, 0, sizeof *d);
    d->file = fname;
    d->text = text;
    d->len = len;
    defaults(d);
    pctx c = {fname, 0, err, errlen, text, len, NULL, 1};
    int seen_degree = 0;
    gls_text_lines it = {text, len, 0, 0};
    size_t n;
    int got;
    char line[GLS_TEXT_MAX_LINE + 1];
    while ((got = gls_text_next_line(&it, line, &n)) != 0) {
        c.line = (int)it.line;
        c.col = 1;
        c.linebuf = NULL;
        if (got < 0) {
            c.col = GLS_TEXT_MAX_LINE + 1;
            fail(&c, "line longer than %u bytes", GLS_TEXT_MAX_LINE);
            goto bad;
        }
        if (memchr(line, 0, n)) {
            fail(&c, "NUL byte in the description");
            goto bad;
        }
        char *tok[MAXTOK + 1];
        int ntok = gls_text_split(line, "#", " \t\r\f\v", tok, MAXTOK + 1);
        if (ntok > MAXTOK) {
            fail(&c, "more than %d words on one line", MAXTOK);
            goto bad;
        }
        if (ntok == 0)
            continue;
        c.linebuf = line;
        at(&c, tok[0]);
        if (parse_line(&c, d, tok, ntok, &seen_degree))
            goto bad;
    }
    /* checks across lines; reported at the line that can be fixed, or at
       the last line when something is missing */
    int last = c.line ? c.line : 1;
    c.linebuf = NULL;
    c.col = 1;
    if (d->npts == 0) {
        c.line = last;
        fail(&c, "no control points: give the centre line as 'point X Y Z [WEIGHT]' lines");
        goto bad;
    }
    if (d->npts < d->degree + 1) {
        c.line = d->line_points;
        fail(&c, "a curve of degree %d needs at least %d control points; there are %d", d->degree, d->degree + 1,
             d->npts);
        goto bad;
    }
    if (d->knots) {
        const char *why = nurbs_check(d->degree, d->npts, d->w, d->nknots, d->knots);
        if (why) {
            c.line = d->line_knots;
            if (d->nknots != d->npts + d->degree + 1)
                fail(&c, "%d knots given; %d points of degree %d need %d", d->nknots, d->npts, d->degree,
                     d->npts + d->degree + 1);
            else
                fail(&c, "%s", why);
            goto bad;
        }
    }
    if (d->lane_width.n && d->line_lane_width) {
        c.line = d->lane_width.line;
        fail(&c, "give either 'lane_width' or 'lane_width_at' lines, not both");
        goto bad;
    }
    if (d->lane_width.n == 0) {
        c.line = d->line_lane_width;
        if (profile_add(&c, &d->lane_width, 0, d->lane_width_const))
            goto bad;
    }
    for (int b = 0; b <= ROAD_MAX_LANES; b++) {
        if (d->marking_set[b] && b > d->lanes) {
            c.line = d->marking_set[b];
            fail(&c, "boundary %d does not exist: %d lanes have boundaries 0..%d (0 is the leftmost)", b, d->lanes,
                 d->lanes);
            goto bad;
        }
        if (!d->marking_set[b])
            d->marking[b] = (b == 0 || b == d->lanes) ? MARK_SOLID : MARK_DASHED;
    }
    if (d->frames == -2) {
        /* the product is checked before it is rounded to a count */
        double n = d->duration * d->fps;
        if (!(n < ROAD_MAX_FRAMES + 0.5)) {
            road_error_at(d, d->line_frames, err, errlen,
                          "duration %g s at %g fps is %.6g frames, more than the %ld allowed", d->duration, d->fps,
                          n, ROAD_MAX_FRAMES);
            goto bad;
        }
        d->frames = lround(n);
    }
    if (d->frames == 0) {
        c.line = d->line_frames;
        fail(&c, "duration %g s at %g fps is no frame at all", d->duration, d->fps);
        goto bad;
    }
    if (d->speed.n == 0) {
        c.line = last;
        fail(&c, "no speed profile: give at least one 'speed_at distance 0 SPEED' (m/s)");
        goto bad;
    }
    for (int v = 0; v < d->nveh; v++)
        if (d->veh[v].speed.n == 0) {
            c.line = d->veh[v].line;
            fail(&c, "vehicle '%s' has no speed: add 'vehicle_speed %s distance 0 SPEED'", d->veh[v].name,
                 d->veh[v].name);
            goto bad;
        }
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
