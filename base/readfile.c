/* Whole-file reading (readfile.h). */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "readfile.h"

static void set(gls_read_error *e, gls_read_status s, int err)
{
    e->status = s;
    e->err = err;
}

int gls_file_open(const char *path, unsigned flags, struct stat *st, gls_read_error *e)
{
    memset(e, 0, sizeof *e);
    int fd = open(path, O_RDONLY | O_CLOEXEC | (flags & GLS_READ_NONBLOCK ? O_NONBLOCK : 0));
    if (fd < 0) {
        set(e, GLS_READ_OPEN, errno);
        return -1;
    }
    if (fstat(fd, st) != 0) {
        if (flags & GLS_READ_REGULAR) {
            set(e, GLS_READ_STAT, errno);
            close(fd);
            return -1;
        }
        memset(st, 0, sizeof *st); /* unknown: read as a stream */
        return fd;
    }
    e->mode = st->st_mode;
    e->size = S_ISREG(st->st_mode) ? (unsigned long long)st->st_size : 0;
    if (S_ISDIR(st->st_mode) || ((flags & GLS_READ_REGULAR) && !S_ISREG(st->st_mode))) {
        set(e, S_ISDIR(st->st_mode) ? GLS_READ_DIR : GLS_READ_NOT_REGULAR, 0);
        close(fd);
        return -1;
    }
    return fd;
}

int gls_read_full(int fd, void *p, size_t n)
{
    char *q = p;
    while (n) {
        ssize_t r = read(fd, q, n > (1u << 30) ? (1u << 30) : n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0) {
            if (r == 0)
                errno = 0;
            return -1;
        }
        q += r;
        n -= (size_t)r;
    }
    return 0;
}

/* A regular file whole, as long as it was at open. */
static char *read_regular(int fd, size_t n, gls_read_error *e)
{
    char *buf = malloc(n + 1);
    if (!buf) {
        set(e, GLS_READ_NOMEM, 0);
        return NULL;
    }
    if (gls_read_full(fd, buf, n)) {
        set(e, errno ? GLS_READ_IO : GLS_READ_SHORT, errno);
        free(buf);
        return NULL;
    }
    buf[n] = 0;
    return buf;
}

/* Whatever fd gives until its end, at most limit + 1 bytes, the buffer
 * growing as the data comes (from cap bytes) so that a short pipe costs
 * little memory. */
static char *read_stream(int fd, size_t limit, size_t cap, size_t *len, gls_read_error *e)
{
    size_t n = 0;
    char *buf = malloc(cap + 1);
    while (buf) {
        ssize_t r = read(fd, buf + n, cap - n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            set(e, GLS_READ_IO, errno);
            free(buf);
            return NULL;
        }
        n += (size_t)r;
        if (r == 0 || n > limit)
            break;
        if (n < cap)
            continue;
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
    if (!buf) {
        set(e, GLS_READ_NOMEM, 0);
        return NULL;
    }
    if (n > limit) {
        set(e, GLS_READ_TOO_LARGE, 0);
        e->size = 0;
        free(buf);
        return NULL;
    }
    buf[n] = 0;
    *len = n;
    return buf;
}

char *gls_file_read(const char *path, size_t limit, unsigned flags, size_t *len, gls_read_error *e)
{
    struct stat st;
    int fd = gls_file_open(path, flags, &st, e);
    if (fd < 0)
        return NULL;
    char *buf = NULL;
    int regular = S_ISREG(st.st_mode);
    /* a regular file tells its size: refuse before reading any of it */
    if (regular && e->size > limit)
        set(e, GLS_READ_TOO_LARGE, 0);
    else if (flags & GLS_READ_REGULAR) {
        buf = read_regular(fd, (size_t)e->size, e);
        *len = (size_t)e->size;
    } else {
        /* the size of a regular file is only a hint: it may grow */
        size_t cap = regular ? (size_t)e->size + 1 : limit < 65536 ? limit + 1 : 65536;
        buf = read_stream(fd, limit, cap, len, e);
    }
    close(fd);
    return buf;
}

int gls_is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

int gls_is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}
