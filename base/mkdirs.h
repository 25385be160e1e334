/* mkdir -p, shared by every tool that creates output directories (glsc -o,
 * glsplay -o, glsroad -o, the scene library's generators). */
#ifndef GLS_MKDIRS_H
#define GLS_MKDIRS_H
#include <stddef.h>

/* Create the directory path and any missing parents (mode 0777, less the
 * umask).  An existing directory is fine.  Returns 0, or -1 with errno
 * set; ENOTDIR when path or one of its parents exists and is not a
 * directory. */
int gls_mkdir_p(const char *path);

/* gls_mkdir_p that says what it made: *made is the length of the
 * shortest prefix of path that it created (every directory of path below
 * that one it created too), 0 when path was there already. */
int gls_mkdir_p_made(const char *path, size_t *made);

/* Undo gls_mkdir_p_made where nothing went since: remove path's
 * directories from path itself up to its prefix of length made, deepest
 * first, each only if empty (rmdir; stop at the first that is not).  A
 * directory that was there before, or holds a file, stays.  Nothing when
 * made is 0. */
void gls_rmdir_made(const char *path, size_t made);

/* Create the directories above the file path (everything before its last
 * '/'; nothing for a bare file name).  Returns as gls_mkdir_p. */
int gls_mkdir_parents(const char *path);
#endif
