/* glsroad's output directory as a whole: check, write aside, swap in
 * (road_outdir.h).  Only names glsroad writes are ever removed. */
#define _GNU_SOURCE /* renameat2 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "atomic_write.h"
#include "mkdirs.h"
#include "road_outdir.h"

/* malloc'd "a/b" (b NULL: a copy of a); NULL when out of memory */
static char *join(const char *a, const char *b)
{
    size_t n = strlen(a) + (b ? strlen(b) + 1 : 0) + 1;
    char *p = malloc(n);
    if (p && b)
        snprintf(p, n, "%s/%s", a, b);
    else if (p)
        snprintf(p, n, "%s", a);
    return p;
}

static int fail(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = snprintf(err, errlen, "glsroad: error: ");
    if (k > 0 && (size_t)k < errlen)
        vsnprintf(err + k, errlen - (size_t)k, fmt, ap);
    va_end(ap);
    return -1;
}

/* glsroad writes one file per vehicle in this directory: a previous output
   may have other vehicles, so each NAME.txt in it is glsroad's. */
#define MOTION_DIR "motion"

static int is_motion_file(const char *name)
{
    size_t n = strlen(name);
    return n > 4 && strcmp(name + n - 4, ".txt") == 0;
}

/* Does the set write entry `name` of DIR (sub NULL) or of DIR/sub?  *is_dir:
   it is the directory of some names. */
static int listed(const road_out_file *f, int n, const char *sub, const char *name, int *is_dir)
{
    if (!sub && !strcmp(name, MOTION_DIR))
        return *is_dir = 1, 1;
    if (sub && !strcmp(sub, MOTION_DIR) && is_motion_file(name))
        return *is_dir = 0, 1;
    for (int i = 0; i < n; i++) {
        const char *slash = strchr(f[i].name, '/');
        size_t pre = slash ? (size_t)(slash - f[i].name) : 0;
        if (!sub && !slash && !strcmp(f[i].name, name))
            return *is_dir = 0, 1;
        if (!sub && slash && strlen(name) == pre && !strncmp(f[i].name, name, pre))
            return *is_dir = 1, 1;
        if (sub && slash && strlen(sub) == pre && !strncmp(f[i].name, sub, pre) && !strcmp(slash + 1, name))
            return *is_dir = 0, 1;
    }
    return 0;
}

/* 1 and the first entry of path (DIR, or DIR/sub) the set does not write
   in bad; 0 if there is none; -1 (errno) if path cannot be read. */
static int stranger(const char *path, const char *sub, const road_out_file *f, int n, char *bad, size_t badlen)
{
    DIR *dp = opendir(path);
    if (!dp)
        return -1;
    int r = 0;
    for (struct dirent *e; r == 0 && (e = readdir(dp)) != NULL;) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        int is_dir = 0;
        char *full = join(path, e->d_name);
        struct stat st;
        if (!full) {
            errno = ENOMEM;
            r = -1;
        } else if (!listed(f, n, sub, e->d_name, &is_dir) || lstat(full, &st) != 0 ||
                   !(is_dir ? S_ISDIR(st.st_mode) : S_ISREG(st.st_mode))) {
            snprintf(bad, badlen, "%s%s%s", sub ? sub : "", sub ? "/" : "", e->d_name);
            r = 1;
        } else if (is_dir) {
            r = stranger(full, e->d_name, f, n, bad, badlen);
        }
        free(full);
    }
    int e = errno;
    closedir(dp);
    errno = e;
    return r;
}

int road_outdir_check(const char *dir, const road_out_file *files, int n, char *err, size_t errlen)
{
    struct stat st;
    if (lstat(dir, &st) != 0)
        return errno == ENOENT ? 0 : fail(err, errlen, "cannot use %s: %s", dir, strerror(errno));
    if (S_ISLNK(st.st_mode))
        return fail(err, errlen, "%s is a symbolic link; give the directory itself", dir);
    if (!S_ISDIR(st.st_mode))
        return fail(err, errlen, "%s exists and is not a directory", dir);
    char bad[512];
    int r = stranger(dir, NULL, files, n, bad, sizeof bad);
    if (r < 0)
        return fail(err, errlen, "cannot read directory %s: %s", dir, strerror(errno));
    if (r > 0)
        return fail(err, errlen,
                    "%s is not a glsroad output directory: it holds '%s', which glsroad does not write; give a new "
                    "or an empty directory",
                    dir, bad);
    return 0;
}

/* Remove the motion files of path/motion/ (any previous output's, checked
   by road_outdir_check to be nothing else), then the directory. */
static int remove_motion(const char *path)
{
    char *m = join(path, MOTION_DIR);
    if (!m)
        return -1;
    DIR *dp = opendir(m);
    int r = 0;
    for (struct dirent *e; dp && (e = readdir(dp)) != NULL;) {
        if (!is_motion_file(e->d_name))
            continue;
        char *p = join(m, e->d_name);
        if (!p || (unlink(p) != 0 && errno != ENOENT))
            r = -1;
        free(p);
    }
    if (dp)
        closedir(dp);
    if (rmdir(m) != 0 && errno != ENOENT)
        r = -1;
    free(m);
    return r;
}

/* Remove a set written by road_outdir_write (only the names it writes, and
   motion files), then the directory; 0, or -1 (errno) if something else is
   left. */
static int remove_set(const char *path, const road_out_file *f, int n)
{
    int r = remove_motion(path);
    for (int i = 0; i < n; i++) {
        char *p = join(path, f[i].name);
        if (!p || (unlink(p) != 0 && errno != ENOENT))
            r = -1;
        free(p);
    }
    for (int i = 0; i < n; i++) {
        const char *slash = strchr(f[i].name, '/');
        if (!slash)
            continue;
        char *p = join(path, f[i].name);
        if (p)
            p[strlen(path) + 1 + (size_t)(slash - f[i].name)] = 0;
        if (!p || (rmdir(p) != 0 && errno != ENOENT))
            r = -1;
        free(p);
    }
    if (rmdir(path) != 0)
        r = -1;
    return r;
}

/* Write the set into the new directory tmp; DIR is named in messages (tmp
   is only where it is put together). */
static int write_set(const char *tmp, const char *dir, const road_out_file *f, int n, char *err, size_t errlen)
{
    for (int i = 0; i < n; i++) {
        const char *slash = strchr(f[i].name, '/');
        char *p = join(tmp, f[i].name);
        if (!p)
            return fail(err, errlen, "out of memory");
        if (slash && gls_mkdir_parents(p) != 0) { /* roadobj/ */
            int e = errno;
            free(p);
            return fail(err, errlen, "cannot create directory %s/%.*s: %s", dir, (int)(slash - f[i].name),
                        f[i].name, strerror(e));
        }
        int r = gls_write_file_atomic(p, f[i].data, f[i].len);
        int e = errno;
        free(p);
        if (r)
            return fail(err, errlen, "cannot write %s/%s: %s", dir, f[i].name, strerror(e));
    }
    return 0;
}

int road_outdir_write(const char *dir_arg, const road_out_file *files, int n, char *err, size_t errlen)
{
    /* "out/" and "out" are the same directory; the temporary one is its
       sibling, never inside it */
    char *dir = join(dir_arg, NULL);
    if (!dir)
        return fail(err, errlen, "out of memory");
    for (size_t k = strlen(dir); k > 1 && dir[k - 1] == '/'; k--)
        dir[k - 1] = 0;
    char *tmp = NULL, *old = NULL;
    int rc = -1;
    if (road_outdir_check(dir, files, n, err, errlen))
        goto out;
    struct stat st;
    int exists = lstat(dir, &st) == 0;
    size_t tn = strlen(dir) + 48;
    if (!(tmp = malloc(tn)) || !(old = malloc(tn))) {
        fail(err, errlen, "out of memory");
        goto out;
    }
    /* like glsc -o and glsplay -o, -o creates the missing parents */
    if (!exists && gls_mkdir_parents(dir)) {
        fail(err, errlen, "cannot create the parent directories of %s: %s", dir, strerror(errno));
        goto out;
    }
    int made = 0;
    for (int k = 0; k < 100 && !made; k++) { /* a name a dead run may have left: the next one */
        if (k)
            snprintf(tmp, tn, "%s.tmp%ld.%d", dir, (long)getpid(), k);
        else
            snprintf(tmp, tn, "%s.tmp%ld", dir, (long)getpid());
        made = mkdir(tmp, 0777) == 0;
        if (!made && errno != EEXIST)
            break;
    }
    if (!made) {
        fail(err, errlen, "cannot create directory %s: %s", dir, strerror(errno));
        goto out;
    }
    if (write_set(tmp, dir, files, n, err, errlen)) {
        remove_set(tmp, files, n);
        goto out;
    }
    if (!exists) {
        if (rename(tmp, dir) != 0) {
            fail(err, errlen, "cannot create directory %s: %s", dir, strerror(errno));
            remove_set(tmp, files, n);
            goto out;
        }
        rc = 0;
        goto out;
    }
    /* swap the new set and the old in one step; the old is then at tmp */
    if (renameat2(AT_FDCWD, tmp, AT_FDCWD, dir, RENAME_EXCHANGE) == 0) {
        snprintf(old, tn, "%s", tmp);
    } else if (errno == EINVAL || errno == ENOSYS) {
        /* no atomic exchange on this file system: move the old set aside,
           then the new one in (DIR is briefly absent, never mixed) */
        snprintf(old, tn, "%s.old%ld", dir, (long)getpid());
        if (rename(dir, old) != 0) {
            fail(err, errlen, "cannot replace %s: %s", dir, strerror(errno));
            remove_set(tmp, files, n);
            goto out;
        }
        if (rename(tmp, dir) != 0) {
            fail(err, errlen, "cannot replace %s: %s", dir, strerror(errno));
            rename(old, dir);
            remove_set(tmp, files, n);
            goto out;
        }
    } else {
        fail(err, errlen, "cannot replace %s: %s", dir, strerror(errno));
        remove_set(tmp, files, n);
        goto out;
    }
    if (remove_set(old, files, n) != 0)
        fprintf(stderr, "glsroad: warning: the previous output is left in %s: %s\n", old, strerror(errno));
    rc = 0;
out:
    free(dir);
    free(tmp);
    free(old);
    return rc;
}
