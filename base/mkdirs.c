/* mkdir -p (mkdirs.h). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "mkdirs.h"

/* mkdir path, tolerating one that exists as a directory: 1 made, 0
 * there, -1 with errno. */
static int make_one(char *path)
{
    if (mkdir(path, 0777) == 0)
        return 1;
    int e = errno;
    struct stat st;
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode))
            return 0;
        errno = ENOTDIR;
        return -1;
    }
    errno = e;
    return -1;
}

int gls_mkdir_p(const char *path)
{
    size_t made;
    return gls_mkdir_p_made(path, &made);
}

int gls_mkdir_p_made(const char *path, size_t *made)
{
    *made = 0;
    size_t n = strlen(path);
    if (n == 0) {
        errno = ENOENT;
        return -1;
    }
    char *tmp = malloc(n + 1);
    if (!tmp)
        return -1;
    memcpy(tmp, path, n + 1);
    int rc = 0;
    /* each prefix ending before a '/' (not the root's own '/'), then path */
    for (size_t i = 1; i <= n && rc == 0; i++) {
        if (tmp[i] != '/' && tmp[i] != 0)
            continue;
        if (tmp[i - 1] == '/')
            continue; /* "a//b": the empty component adds nothing */
        char save = tmp[i];
        tmp[i] = 0;
        rc = make_one(tmp);
        tmp[i] = save;
        if (rc == 1 && !*made)
            *made = i;
        rc = rc < 0 ? -1 : 0;
    }
    int e = errno;
    free(tmp);
    errno = e;
    return rc;
}

void gls_rmdir_made(const char *path, size_t made)
{
    size_t n = strlen(path);
    char *tmp = made ? malloc(n + 1) : NULL;
    if (!tmp)
        return; /* nothing made, or no memory: the directories stay */
    memcpy(tmp, path, n + 1);
    /* path, then each parent whose prefix is at least made long */
    for (size_t i = n; i >= made; i--) {
        if (i < n && tmp[i] != '/')
            continue;
        if (i < n && tmp[i - 1] == '/')
            continue; /* "a//b" */
        tmp[i] = 0;
        if (rmdir(tmp) != 0)
            break; /* not empty (or gone): its parents are not either */
    }
    free(tmp);
}

int gls_mkdir_parents(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash || slash == path)
        return 0; /* in the current directory, or in / */
    size_t n = (size_t)(slash - path);
    char *dir = strndup(path, n);
    if (!dir)
        return -1;
    int rc = gls_mkdir_p(dir);
    int e = errno;
    free(dir);
    errno = e;
    return rc;
}
