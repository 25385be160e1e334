/* Reading input files whole, with a size limit and a NUL sentinel. */
#ifndef GLS_FILEIO_H
#define GLS_FILEIO_H
#include <stddef.h>

#define GLS_MAX_INPUT_BYTES ((size_t)1 << 30)   /* 1 GiB per source or image */

/* Returns a malloc'd buffer of *len bytes plus a NUL, or NULL with a
 * one-line reason in why. */
char *gls_read_file(const char *path, size_t limit, size_t *len, char *why, size_t whylen);
int gls_is_dir(const char *path);
int gls_is_file(const char *path);
#endif
