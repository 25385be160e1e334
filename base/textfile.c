/* Bounded reading of text inputs (textfile.h). */
#include <string.h>
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

char *gls_text_read(const char *path, size_t limit, const char *what, size_t *len, char *err, size_t errlen)
{
    gls_read_error e;
    char *buf = gls_file_read(path, limit, 0, len, &e);
    if (buf)
        return buf;
    char lim[32];
    fmt_size(lim, sizeof lim, limit);
    switch (e.status) {
    case GLS_READ_OPEN: snprintf(err, errlen, "%s: error: cannot open: %s", path, strerror(e.err)); break;
    case GLS_READ_DIR: snprintf(err, errlen, "%s: error: is a directory, not a %s", path, what); break;
    case GLS_READ_TOO_LARGE:
        if (e.size)
            snprintf(err, errlen, "%s: error: %s larger than %s (%llu bytes)", path, what, lim, e.size);
        else
            snprintf(err, errlen, "%s: error: %s larger than %s", path, what, lim);
        break;
    case GLS_READ_IO: snprintf(err, errlen, "%s: error: cannot read: %s", path, strerror(e.err)); break;
    default: snprintf(err, errlen, "%s: error: out of memory", path); break;
    }
    return NULL;
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
