/* Atomic file output: write a temporary file beside the target, flush it,
 * then rename() it into place.  A reader never sees a half-written file,
 * and an interrupted writer leaves at most a ".tmp" file, never a
 * truncated output under the real name. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "atomic_write.h"
#include "readfile.h"

/* Write everything to fd; 0 or -1 with errno set. */
static int write_all(int fd, const void *data, size_t len)
{
    const char *p = data;
    while (len) {
        ssize_t w = write(fd, p, len);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        p += w;
        len -= (size_t)w;
    }
    return 0;
}

/* What an existing non-regular file is, for messages; NULL for a regular
 * file or none. */
static const char *special_kind(const char *path)
{
    struct stat st;
    return stat(path, &st) != 0 ? NULL : gls_file_kind(st.st_mode);
}

const char *gls_write_error(const char *path, int err)
{
    const char *kind = special_kind(path);
    return kind ? kind : strerror(err);
}

int gls_atomic_begin(gls_atomic_file *f, const char *path)
{
    /* An existing target that is not a regular file is refused without
       being opened: renaming over it would replace a FIFO or a device node
       with a plain file, and writing into it could block for ever (a FIFO
       nobody reads) or send the bytes nowhere. */
    f->fd = -1;
    f->tmp = NULL;
    f->path = path;
    if (special_kind(path)) {
        errno = EEXIST;
        return -1;
    }
    size_t n = strlen(path);
    char *tmp = malloc(n + 32);
    if (!tmp)
        return -1;
    snprintf(tmp, n + 32, "%s.tmp%ld", path, (long)getpid());
    int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) {
        int e = errno;
        free(tmp);
        errno = e;
        return -1;
    }
    f->fd = fd;
    f->tmp = tmp;
    return 0;
}

void gls_atomic_abort(gls_atomic_file *f)
{
    int e = errno;
    if (f->fd >= 0)
        close(f->fd);
    if (f->tmp)
        unlink(f->tmp);
    free(f->tmp);
    f->fd = -1;
    f->tmp = NULL;
    errno = e;
}

int gls_atomic_commit(gls_atomic_file *f)
{
    if (fsync(f->fd) != 0 && errno != EINVAL)
        goto fail;
    int fd = f->fd;
    f->fd = -1;
    if (close(fd) != 0 || rename(f->tmp, f->path) != 0)
        goto fail;
    free(f->tmp);
    f->tmp = NULL;
    return 0;
fail:
    gls_atomic_abort(f);
    return -1;
}

int gls_write_file_atomic(const char *path, const void *data, size_t len)
{
    gls_atomic_file f;
    if (gls_atomic_begin(&f, path))
        return -1;
    if (write_all(f.fd, data, len)) {
        gls_atomic_abort(&f);
        return -1;
    }
    return gls_atomic_commit(&f);
}
