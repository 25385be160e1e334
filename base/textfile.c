/* Bounded reading of text inputs (textfile.h). */
#include <errno.h>
#include <string.h>
#include <unistd.h>
#include "readfile.h"
#include "textfile.h"

/* "1 MiB" for whole mebibytes, else "N bytes". */
static void fmt_size(char *buf, size_t n, size_t bytes)
{
    if (bytes && bytes % (1u << 20) == 0)
        snprintf(buf, n, "%zu MiB", bytes >> 20);
    else
        snprintf(buf, n, "%zu bytes", bytes);
}

/* Why a text input could not be opened or read, without its path: the
 * one wording of every text input's file errors. */
static void why_not(const gls_read_error *e, const char *what, size_t limit, char *why, size_t n)
{
    char lim[32];
    fmt_size(lim, sizeof lim, limit);
    switch (e->status) {
    case GLS_READ_OPEN: snprintf(why, n, "cannot open: %s", strerror(e->err)); break;
    case GLS_READ_DIR: snprintf(why, n, "is a directory, not a %s", what); break;
    case GLS_READ_NOT_REGULAR: snprintf(why, n, "cannot read: %s", gls_file_kind(e->mode)); break;
    case GLS_READ_TOO_LARGE: snprintf(why, n, "%s larger than %s (%llu bytes)", what, lim, e->size); break;
    case GLS_READ_STAT:
    case GLS_READ_IO: snprintf(why, n, "cannot read: %s", strerror(e->err)); break;
    case GLS_READ_SHORT: snprintf(why, n, "cannot read: the file shrank while it was read"); break;
    default: snprintf(why, n, "out of memory"); break;
    }
}

char *gls_text_read(const char *path, size_t limit, const char *what, size_t *len, char *err, size_t errlen)
{
    gls_read_error e;
    char *buf = gls_file_read(path, limit, len, &e);
    if (buf)
        return buf;
    char why[300];
    why_not(&e, what, limit, why, sizeof why);
    snprintf(err, errlen, "%s: error: %s", path, why);
    return NULL;
}

FILE *gls_text_open(const char *path, const char *what, char *why, size_t whylen)
{
    struct stat st;
    gls_read_error e;
    int fd = gls_file_open(path, &st, &e);
    if (fd < 0) {
        why_not(&e, what, 0, why, whylen);
        return NULL;
    }
    FILE *f = fdopen(fd, "r");
    if (!f) {
        snprintf(why, whylen, "cannot open: %s", strerror(errno));
        close(fd);
    }
    return f;
}

int gls_text_next_line(gls_text_lines *it, char buf[GLS_TEXT_MAX_LINE + 1], size_t *n)
{
    if (it->pos >= it->len)
        return 0;
    const char *p = it->text + it->pos;
    size_t left = it->len - it->pos;
    const char *nl = memchr(p, '\n', left);
    size_t k = nl ? (size_t)(nl - p) : left;
    it->line++;
    it->pos += k + (nl != NULL);
    if (k > GLS_TEXT_MAX_LINE)
        return -1;
    memcpy(buf, p, k);
    buf[k] = 0;
    *n = k;
    return 1;
}

int gls_text_split(char *line, const char *cut, const char *seps, char **tok, int max)
{
    line[strcspn(line, cut)] = 0;
    int n = 0;
    char *save;
    for (char *w = strtok_r(line, seps, &save); w && n < max; w = strtok_r(NULL, seps, &save))
        tok[n++] = w;
    return n;
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
