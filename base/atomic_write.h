/* Atomic file output, shared by every tool that writes files (glsc's
 * bundles, glsplay's images, glsroad's outputs): a temporary file beside
 * the target, flushed, then renamed into place. */
#ifndef GLS_ATOMIC_WRITE_H
#define GLS_ATOMIC_WRITE_H
#include <stddef.h>

/* Write bytes to path atomically: a temporary file in the same directory,
 * fsync'd, then renamed over path.  On failure nothing is left behind.  An
 * existing path that is not a regular file (a directory, FIFO, device or
 * socket) is refused and never opened.  Returns 0, or -1 with errno set
 * (EEXIST for such a file). */
int gls_write_file_atomic(const char *path, const void *data, size_t len);

/* The same in steps, which gls_write_file_atomic is made of (and which
 * tests/unit/test_base.c watches between): gls_atomic_begin opens the
 * temporary beside path (tmp, in path's directory, so that the rename
 * stays within one file system) and leaves path as it was; the caller
 * writes to fd; gls_atomic_commit flushes, closes and renames it over
 * path; gls_atomic_abort closes and removes it, leaving path as it was.
 * begin and commit return 0, or -1 with errno set; a failed begin holds
 * nothing, a failed commit has removed the temporary. */
typedef struct {
    int fd;
    char *tmp;        /* the temporary's name (malloc'd) */
    const char *path; /* the target, as given to begin */
} gls_atomic_file;
int gls_atomic_begin(gls_atomic_file *f, const char *path);
int gls_atomic_commit(gls_atomic_file *f);
void gls_atomic_abort(gls_atomic_file *f);

/* The reason for "cannot write PATH: REASON" after gls_write_file_atomic
 * failed with errno err: what the special file is ("it is a FIFO (named
 * pipe), not a regular file"), or strerror(err). */
const char *gls_write_error(const char *path, int err);
#endif
