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
/* The reason for "cannot write PATH: REASON" after gls_write_file_atomic
 * failed with errno err: what the special file is ("it is a FIFO (named
 * pipe), not a regular file"), or strerror(err). */
const char *gls_write_error(const char *path, int err);
#endif
