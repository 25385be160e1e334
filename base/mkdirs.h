/* mkdir -p, shared by every tool that creates output directories (glsc -o,
 * glsplay -o, glsroad -o, the scene library's generators). */
#ifndef GLS_MKDIRS_H
#define GLS_MKDIRS_H

/* Create the directory path and any missing parents (mode 0777, less the
 * umask).  An existing directory is fine.  Returns 0, or -1 with errno
 * set; ENOTDIR when path or one of its parents exists and is not a
 * directory. */
int gls_mkdir_p(const char *path);

/* Create the directories above the file path (everything before its last
 * '/'; nothing for a bare file name).  Returns as gls_mkdir_p. */
int gls_mkdir_parents(const char *path);
#endif
