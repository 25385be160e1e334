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

int gls_file_open(const char *path, struct stat *st, gls_read_error *e)
{
    memset(e, 0, sizeof *e);
    /* O_NONBLOCK: opening a FIFO must not wait for a writer (it is refused
       below); for a regular file the flag changes nothing */
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        set(e, GLS_READ_OPEN, errno);
        return -1;
    }
    if (fstat(fd, st) != 0) {
        set(e, GLS_READ_STAT, errno);
        close(fd);
        return -1;
    }
    e->mode = st->st_mode;
    if (!S_ISREG(st->st_mode)) {
        set(e, S_ISDIR(st->st_mode) ? GLS_READ_DIR : GLS_READ_NOT_REGULAR, 0);
        close(fd);
        return -1;
    }
    e->size = (unsigned long long)st->st_size;
    return fd;
}

const char *gls_file_kind(mode_t m)
{
    if (S_ISREG(m))
        return NULL;
    if (S_ISDIR(m))
        return "it is a directory";
    if (S_ISFIFO(m))
        return "it is a FIFO (named pipe), not a regular file";
    if (S_ISCHR(m))
        return "it is a character device, not a regular file";
    if (S_ISBLK(m))
        return "it is a block device, not a regular file";
    if (S_ISSOCK(m))
        return "it is a socket, not a regular file";
    return "it is not a regular file";
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

char *gls_file_read(const char *path, size_t limit, size_t *len, gls_read_error *e)
{
    struct stat st;
    int fd = gls_file_open(path, &st, e);
    if (fd < 0)
        return NULL;
    char *buf = NULL;
    /* the file tells its size: refuse before reading any of it */
    if (e->size > limit)
        set(e, GLS_READ_TOO_LARGE, 0);
    else {
        buf = read_regular(fd, (size_t)e->size, e);
        *len = (size_t)e->size;
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
    return stat(path, &st) == 0 && !S_ISDIR(st.st_mode);
}
