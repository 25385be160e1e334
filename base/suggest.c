#include <ctype.h>
#include <string.h>
#include <strings.h>
#include "suggest.h"

unsigned gls_edit_distance(const char *a, size_t alen, const char *b)
{
    size_t blen = strlen(b);
    if (alen > 64 || blen > 64)
        return 1000;
    unsigned d[65][65];
    for (size_t i = 0; i <= alen; i++)
        d[i][0] = (unsigned)i;
    for (size_t j = 0; j <= blen; j++)
        d[0][j] = (unsigned)j;
    for (size_t i = 1; i <= alen; i++)
        for (size_t j = 1; j <= blen; j++) {
            int ai = tolower((unsigned char)a[i - 1]), bj = tolower((unsigned char)b[j - 1]);
            unsigned best = d[i - 1][j - 1] + (ai != bj);
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && ai == tolower((unsigned char)b[j - 2]) &&
                tolower((unsigned char)a[i - 2]) == bj && d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[alen][blen];
}

/* A likely typo is at distance 1 for words of up to 3 letters, else at
 * most 2: the distance must be strictly below this. */
static unsigned typo_limit(size_t len)
{
    return len <= 3 ? 2 : 3;
}

const char *gls_suggest(const char *word, size_t len, const char *const *cands, size_t n)
{
    const char *best = NULL;
    unsigned bestd = typo_limit(len);
    for (size_t i = 0; i < n && cands[i]; i++) {
        unsigned dd = gls_edit_distance(word, len, cands[i]);
        if (dd < bestd) {
            bestd = dd;
            best = cands[i];
        }
    }
    return best;
}

/* s[0..n) is an OpenGL type suffix: an optional component count 1-4, an
 * optional type (f d i s b ub us ui), an optional v (vector form). */
static int gl_suffix(const char *s, size_t n)
{
    static const char *const types[] = {"ub", "us", "ui", "f", "d", "i", "s", "b"};
    size_t p = 0;
    if (p < n && s[p] >= '1' && s[p] <= '4')
        p++;
    for (size_t t = 0; t < sizeof types / sizeof types[0]; t++) {
        size_t tl = strlen(types[t]);
        if (n - p >= tl && strncmp(s + p, types[t], tl) == 0) {
            p += tl;
            break;
        }
    }
    if (p < n && s[p] == 'v')
        p++;
    return p == n;
}

/* word[0..len) is name, without regard to case, or its OpenGL spelling:
 * a function (glName + type suffix) or an enum (GL_NAME). */
static int names(const char *word, size_t len, const char *name)
{
    size_t n = strlen(name);
    if (len == n && strncasecmp(word, name, n) == 0)
        return 1;
    if (len == n + 3 && strncasecmp(word, "gl_", 3) == 0 && strncasecmp(word + 3, name, n) == 0)
        return 1;
    return len > n + 2 && strncasecmp(word, "gl", 2) == 0 && strncasecmp(word + 2, name, n) == 0 &&
           gl_suffix(word + 2 + n, len - 2 - n);
}

static int is_candidate(const char *w, const char *const *cands, size_t n)
{
    for (size_t i = 0; i < n && cands[i]; i++)
        if (strcmp(cands[i], w) == 0)
            return 1;
    return 0;
}

const char *gls_suggest_alias(const char *word, size_t len, const char *const *cands, size_t n,
                              const gls_alias *aliases, size_t naliases)
{
    for (size_t i = 0; i < n && cands[i]; i++)
        if (names(word, len, cands[i]))
            return cands[i];
    for (size_t i = 0; i < naliases; i++)
        if (is_candidate(aliases[i].word, cands, n) && names(word, len, aliases[i].alias))
            return aliases[i].word;
    /* a typo of a candidate, else of an alias (candidates win ties) */
    const char *best = gls_suggest(word, len, cands, n);
    if (best)
        return best;
    unsigned bestd = typo_limit(len);
    for (size_t i = 0; i < naliases; i++) {
        if (!is_candidate(aliases[i].word, cands, n))
            continue;
        unsigned dd = gls_edit_distance(word, len, aliases[i].alias);
        if (dd < bestd) {
            bestd = dd;
            best = aliases[i].word;
        }
    }
    return best;
}
