/* Reading the compiler's input files whole, with a size limit and a NUL
 * sentinel (base/readfile.h reads; this words the compiler's messages). */
#ifndef GLS_FILEIO_H
#define GLS_FILEIO_H
#include <stddef.h>
#include "readfile.h" /* and gls_is_dir, gls_is_file */

#define GLS_MAX_INPUT_BYTES ((size_t)1 << 30)   /* 1 GiB per source or image */

/* Returns a malloc'd buffer of *len bytes plus a NUL, or NULL with a
 * one-line reason in why. */
char *gls_read_file(const char *path, size_t limit, size_t *len, char *why, size_t whylen);
/* Like gls_read_file, but maps the file read-only when the page after its
 * end supplies the NUL sentinel for free (the common case); *mapped is set
 * to the mapping length (release with gls_release_file), or 0 when the
 * buffer was malloc'd.  Saves copying large sources (bench-compile). */
char *gls_load_source(const char *path, size_t limit, size_t *len, size_t *mapped, char *why, size_t whylen);
void gls_release_file(const char *buf, size_t mapped);
#endif
