/* Reading a file whole, with a size limit: the one reader of every input
 * of every tool (scene sources and images, camera files, trajectories,
 * motion files, road descriptions, bundles, the player's frame records)
 * and the one place where an input is opened and looked at.  The rule,
 * once, for all of them (spec/camera.md "Input files are regular files"):
 * an input is a regular file.  A directory, a FIFO (named pipe, also the
 * /dev/fd/N of a shell's <(...)), a device or a socket is refused when
 * opened, with what it is: a FIFO with no writer would block for ever, a
 * device such as /dev/zero never ends, and neither can be read a second
 * time (glsplay reads its trajectory twice and digests its inputs for
 * --resume).  Opening never waits (O_NONBLOCK).  What went wrong comes
 * back as a status with its errno, size and file type; each caller words
 * its own message around gls_file_kind, so the messages stay those of its
 * tool. */
#ifndef GLS_READFILE_H
#define GLS_READFILE_H
#include <stddef.h>
#include <sys/stat.h>

typedef enum {
    GLS_READ_OK,
    GLS_READ_OPEN,        /* open failed (err)                                   */
    GLS_READ_STAT,        /* fstat failed (err)                                   */
    GLS_READ_DIR,         /* a directory                                          */
    GLS_READ_NOT_REGULAR, /* a FIFO, device or socket (mode)                      */
    GLS_READ_TOO_LARGE,   /* a file of size bytes, over the limit                 */
    GLS_READ_NOMEM,       /* no memory for the bytes                              */
    GLS_READ_IO,          /* read failed (err)                                    */
    GLS_READ_SHORT        /* the file ended before its size at open               */
} gls_read_status;

typedef struct {
    gls_read_status status;
    int err;                 /* errno of OPEN, STAT and IO                    */
    unsigned long long size; /* the file's size at open (regular files)       */
    mode_t mode;             /* the file's type at open                       */
} gls_read_error;

/* Open path for reading (without waiting) and look at it.  Returns the
 * descriptor of a regular file, with *st filled, or -1 with e set: OPEN,
 * STAT, DIR or NOT_REGULAR. */
int gls_file_open(const char *path, struct stat *st, gls_read_error *e);

/* What a file that is not a regular one is, for "cannot read PATH: ..."
 * and "cannot write PATH: ...": "it is a directory", "it is a FIFO (named
 * pipe), not a regular file", "it is a character device, not a regular
 * file", ...; NULL for a regular file.  The one wording of every tool. */
const char *gls_file_kind(mode_t mode);

/* All of n bytes from fd at its offset: 0, or -1 with errno set (0 for a
 * file that ended early). */
int gls_read_full(int fd, void *p, size_t n);

/* Read the regular file at path whole: a malloc'd buffer of *len bytes
 * (as many as it had at open) and a NUL after them, or NULL with e set.
 * A file larger than limit is refused before any of it is read. */
char *gls_file_read(const char *path, size_t limit, size_t *len, gls_read_error *e);

/* Does path name a directory?  Does it name something else (a regular
 * file, or a FIFO, device or socket that gls_file_open then refuses with
 * what it is, rather than "no such file")?  Links are followed. */
int gls_is_dir(const char *path);
int gls_is_file(const char *path);
#endif
