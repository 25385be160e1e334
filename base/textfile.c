/* Bounded reading of text inputs (textfile.h). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "textfile.h"

/* "1 MiB" for whole mebibytes, else "N bytes". */
static void fmt_size(char *buf, size_t n, size_t bytes)
{
    if (bytes && bytes % (1u << 20) == 0)
        snprintf(buf, n, "%zu MiB", bytes >> 20);
    else
        snprintf(buf, n, "%zu bytes", bytes);
}

char *gls_text_read(const char *path, size_t limit, const char *what, size_t *len, char *err, size_t errlen)
{
    char lim[32];
    fmt_size(lim, sizeof lim, limit);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: error: cannot open: %s", path, strerror(errno));
        return NULL;
    }
    struct stat st;
    if (fstat(fileno(f), &st) == 0) {
        if (S_ISDIR(st.st_mode)) {
            snprintf(err, errlen, "%s: error: is a directory, not a %s", path, what);
            fclose(f);
            return NULL;
        }
        /* a regular file tells its size: refuse before reading any of it */
        if (S_ISREG(st.st_mode) && (unsigned long long)st.st_size > limit) {
            snprintf(err, errlen, "%s: error: %s larger than %s (%llu bytes)", path, what, lim,
                     (unsigned long long)st.st_size);
            fclose(f);
            return NULL;
        }
    }
    /* Pipes and devices do not: read at most limit + 1 bytes, growing the
     * buffer as the data comes, so a short pipe costs little memory. */
    size_t cap = limit < 65536 ? limit + 1 : 65536, n = 0;
    char *buf = malloc(cap + 1);
    while (buf) {
        size_t r = fread(buf + n, 1, cap - n, f);
        n += r;
        if (n < cap || n > limit)
            break;
        size_t ncap = cap > limit / 2 ? limit + 1 : 2 * cap;
        char *nb = realloc(buf, ncap + 1);
        if (!nb) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = nb;
        cap = ncap;
    }
    int bad = ferror(f);
    int e = errno;
    fclose(f);
    if (!buf || bad || n > limit) {
        if (!buf)
            snprintf(err, errlen, "%s: error: out of memory", path);
        else if (bad)
            snprintf(err, errlen, "%s: error: cannot read: %s", path, strerror(e));
        else
            snprintf(err, errlen, "%s: error: %s larger than %s", path, what, lim);
        free(buf);
        return NULL;
    }
    buf[n] = 0;
    *len = n;
    return buf;
}

int gls_text_next_line(gls_text_lines *it, const char **start, size_t *n)
{
    if (it->pos >= it->len)
        return 0;
    const char *p = it->text + it->pos;
    size_t left = it->len - it->pos;
    const char *nl = memchr(p, '\n', left);
    size_t k = nl ? (size_t)(nl - p) : left;
    it->line++;
    *start = p;
    *n = k;
    it->pos += k + (nl != NULL);
    return k > GLS_TEXT_MAX_LINE ? -1 : 1;
}

int gls_text_getline(FILE *f, char buf[GLS_TEXT_MAX_LINE + 1], size_t *n)
{
    size_t k = 0;
    int c;
    while ((c = getc(f)) != EOF && c != '\n') {
        if (k == GLS_TEXT_MAX_LINE) {
            buf[k] = 0;
            *n = k;
            return -1;
        }
        buf[k++] = (char)c;
    }
    buf[k] = 0;
    *n = k;
    if (c == EOF) {
        if (ferror(f))
            return -2;
        if (k == 0)
            return 0;
    }
    return 1;
}
