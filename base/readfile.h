/* Reading a file whole, with a size limit: the one reader of every input
 * that is read whole (scene sources and images, camera files, road
 * descriptions, bundles, the player's frame records) and the one place
 * where an input is opened and looked at (is it a directory? a FIFO?).
 * What went wrong comes back as a status with its errno and size; each
 * caller words its own message, so the messages stay those of its tool. */
#ifndef GLS_READFILE_H
#define GLS_READFILE_H
#include <stddef.h>
#include <sys/stat.h>

typedef enum {
    GLS_READ_OK,
    GLS_READ_OPEN,        /* open failed (err)                                   */
    GLS_READ_STAT,        /* fstat failed (err); only with GLS_READ_REGULAR       */
    GLS_READ_DIR,         /* a directory                                          */
    GLS_READ_NOT_REGULAR, /* with GLS_READ_REGULAR: a FIFO, device or socket (mode) */
    GLS_READ_TOO_LARGE,   /* over the limit: a regular file of size bytes, or a
                             stream (size 0) that gave more than limit bytes      */
    GLS_READ_NOMEM,       /* no memory for the bytes                              */
    GLS_READ_IO,          /* read failed (err)                                    */
    GLS_READ_SHORT        /* with GLS_READ_REGULAR: the file ended before its size */
} gls_read_status;

typedef struct {
    gls_read_status status;
    int err;                 /* errno of OPEN, STAT and IO                    */
    unsigned long long size; /* the file's size at open (regular files)       */
    mode_t mode;             /* the file's type at open                       */
} gls_read_error;

enum {
    GLS_READ_REGULAR = 1, /* only a regular file, read as long as it was at open */
    GLS_READ_NONBLOCK = 2 /* open without waiting (a FIFO with no writer)    */
};

/* Open path for reading and look at it.  Returns the descriptor, with *st
 * filled, or -1 with e set: OPEN, DIR, and with GLS_READ_REGULAR also STAT
 * and NOT_REGULAR (without it, a file fstat cannot look at is read as a
 * stream). */
int gls_file_open(const char *path, unsigned flags, struct stat *st, gls_read_error *e);

/* All of n bytes from fd at its offset: 0, or -1 with errno set (0 for a
 * file that ended early). */
int gls_read_full(int fd, void *p, size_t n);

/* Read path whole: a malloc'd buffer of *len bytes and a NUL after them, or
 * NULL with e set.  At most limit bytes: a regular file larger than limit
 * is refused before any of it is read; a pipe or a device is read as the
 * data comes, up to limit + 1 bytes, so that a wrong path (/dev/zero)
 * costs bounded memory and time.  With GLS_READ_REGULAR only a regular
 * file is read, exactly as many bytes as it had at open. */
char *gls_file_read(const char *path, size_t limit, unsigned flags, size_t *len, gls_read_error *e);

/* Does path name a directory / a regular file (following links)? */
int gls_is_dir(const char *path);
int gls_is_file(const char *path);
#endif
