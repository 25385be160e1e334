/* The camera file's sensor keys (sensor_keys.h).  Messages follow
 * camera.c's: the same wording for a count, a comma, a number, a key
 * given twice, located at the word at fault. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"
#include "sensor_keys.h"
#include "srcline.h"
#include "suggest.h"

enum { S_GAIN, S_READ, S_SHOT, S_SEED, S_VIGNETTING, S_BAYER };
const char *const gls_sensor_key_names[GLS_SENSOR_NKEYS] = {"gain",       "read_noise", "shot_noise",
                                                            "noise_seed", "vignetting", "bayer"};
static const char *const bayer_names[] = {"RGGB", "BGGR", "GRBG", "GBRG"};

void gls_sensor_keys_init(gls_sensor_keys *k)
{
    memset(k, 0, sizeof *k);
    k->s = gls_sensor_none();
}

int gls_sensor_key(const char *word)
{
    for (int i = 0; i < GLS_SENSOR_NKEYS; i++)
        if (strcmp(word, gls_sensor_key_names[i]) == 0)
            return i;
    return -1;
}

/* The line being read: where a message points. */
typedef struct {
    const char *line; /* the words point into it */
    unsigned lineno;
    const char *text, *fname;
    size_t len;
    char *err;
    size_t errlen;
} where;

/* The located error at word t of the line. */
#define FAIL(t, ...)                                                                                                \
    do {                                                                                                            \
        gls_text_error(w->err, w->errlen, w->text, w->len, w->fname, w->lineno, (unsigned)((t) - w->line) + 1,     \
                       __VA_ARGS__);                                                                                \
        return -1;                                                                                                  \
    } while (0)

/* tok[i] as a double, or -1 after the message camera.c gives. */
static int number(const where *w, char *const *tok, int i, const char *key, double *v)
{
    char *comma = strchr(tok[i], ',');
    if (comma)
        FAIL(comma, "key '%s': a comma in '%s': separate numbers with spaces and write decimals with '.'", key,
             tok[i]);
    const char *why = gls_parse_double(tok[i], v);
    if (why)
        FAIL(tok[i], "key '%s': '%s' %s", key, tok[i], why);
    return 0;
}

/* gain, read_noise, shot_noise: one number each */
static int level_key(const where *w, gls_sensor *s, int key, char *const *tok, int nv, int more)
{
    const char *name = gls_sensor_key_names[key];
    char num[40];
    double v;
    if (nv != 1)
        FAIL(tok[0], "key '%s' takes 1 number, got %s%d", name, more ? "more than " : "", nv);
    if (number(w, tok, 1, name, &v))
        return -1;
    gls_fmt_double(num, sizeof num, v);
    if (key == S_GAIN) {
        if (!(v > 0))
            FAIL(tok[1], "gain %s must be > 0 (a factor on the linear intensity; 1 = no gain)", num);
        s->gain = v;
        if (v != 1)
            s->on |= GLS_SENSOR_GAIN;
    } else if (key == S_READ) {
        if (!(v >= 0))
            FAIL(tok[1], "read_noise %s must be >= 0 (a standard deviation in units of full scale: white "
                         "is 1, one 8-bit level 1/255)", num);
        s->read_sigma = v;
        if (v > 0)
            s->on |= GLS_SENSOR_READ;
    } else {
        if (!(v > 0) || v > GLS_SENSOR_MAX_K)
            FAIL(tok[1], "shot_noise %s must be > 0 and at most 1e12 (electrons collected at intensity 1, "
                         "the full-well scale)", num);
        s->shot_k = v;
        s->on |= GLS_SENSOR_SHOT;
    }
    return 0;
}

static int seed_key(const where *w, gls_sensor *s, char *const *tok, int nv, int more)
{
    if (nv != 1)
        FAIL(tok[0], "key 'noise_seed' takes 1 number, got %s%d", more ? "more than " : "", nv);
    const char *p = tok[1];
    char *end;
    errno = 0;
    unsigned long long seed = strtoull(p, &end, 10);
    if (*p < '0' || *p > '9' || *end || errno)
        FAIL(tok[1], "noise_seed '%s' must be a whole number in 0..18446744073709551615", tok[1]);
    s->seed = seed;
    return 0;
}

/* vignetting cos4, or vignetting poly a1 a2 a3 */
static int vignetting_key(const where *w, gls_sensor *s, char *const *tok, int nv, int more)
{
    if (nv < 1)
        FAIL(tok[0], "key 'vignetting' takes cos4, or poly and three numbers a1 a2 a3, got nothing");
    if (strcmp(tok[1], "cos4") == 0) {
        if (nv != 1)
            FAIL(tok[2], "key 'vignetting': cos4 takes no numbers, got %s%d", more ? "more than " : "", nv - 1);
        s->vignetting = GLS_VIGNETTING_COS4;
        s->on |= GLS_SENSOR_VIGNETTING;
        return 0;
    }
    if (strcmp(tok[1], "poly") == 0) {
        if (nv != 4)
            FAIL(tok[1], "key 'vignetting': poly takes three numbers a1 a2 a3 (1 + a1 r^2 + a2 r^4 + a3 r^6), "
                         "got %s%d", more ? "more than " : "", nv - 1);
        int any = 0;
        for (int i = 0; i < 3; i++) {
            if (number(w, tok, 2 + i, gls_sensor_key_names[S_VIGNETTING], &s->poly[i]))
                return -1;
            any |= s->poly[i] != 0;
        }
        if (any) { /* poly 0 0 0 is a factor of 1: none */
            s->vignetting = GLS_VIGNETTING_POLY;
            s->on |= GLS_SENSOR_VIGNETTING;
        }
        return 0;
    }
    static const char *const modes[] = {"cos4", "poly"};
    const char *sug = gls_suggest(tok[1], strlen(tok[1]), modes, 2);
    if (sug)
        FAIL(tok[1], "key 'vignetting': '%s' is neither cos4 nor poly (did you mean '%s'?)", tok[1], sug);
    FAIL(tok[1], "key 'vignetting': '%s' is neither cos4 nor poly", tok[1]);
}

static int bayer_key(const where *w, gls_sensor *s, char *const *tok, int nv, int more)
{
    if (nv != 1)
        FAIL(tok[0], "key 'bayer' takes one word, RGGB, BGGR, GRBG or GBRG, got %s%d", more ? "more than " : "", nv);
    for (int i = 0; i < 4; i++)
        if (strcmp(tok[1], bayer_names[i]) == 0) {
            memcpy(s->bayer, bayer_names[i], 5);
            s->on |= GLS_SENSOR_BAYER;
            return 0;
        }
    const char *sug = gls_suggest(tok[1], strlen(tok[1]), bayer_names, 4);
    if (sug)
        FAIL(tok[1], "key 'bayer': '%s' is not a Bayer pattern (did you mean '%s'?)", tok[1], sug);
    FAIL(tok[1], "key 'bayer': '%s' is not a Bayer pattern: RGGB, BGGR, GRBG or GBRG (the 2x2 block at "
                 "the top-left corner, row by row)", tok[1]);
}

int gls_sensor_key_parse(gls_sensor_keys *k, int key, char *const *tok, int nt, int more, const char *line,
                         unsigned lineno, const char *text, size_t len, const char *fname, char *err, size_t errlen)
{
    const where at = {line, lineno, text, fname, len, err, errlen}, *w = &at;
    int nv = nt - 1;
    if (k->seen[key])
        FAIL(tok[0], "key '%s' given twice (first on line %u)", gls_sensor_key_names[key], k->seen[key]);
    k->seen[key] = lineno;
    switch (key) {
    case S_GAIN:
    case S_READ:
    case S_SHOT:
        return level_key(w, &k->s, key, tok, nv, more);
    case S_SEED:
        return seed_key(w, &k->s, tok, nv, more);
    case S_VIGNETTING:
        return vignetting_key(w, &k->s, tok, nv, more);
    default: /* S_BAYER */
        return bayer_key(w, &k->s, tok, nv, more);
    }
}

gls_sensor gls_sensor_none(void)
{
    gls_sensor s;
    memset(&s, 0, sizeof s);
    s.gain = 1;
    return s;
}
