/* mkdir -p (mkdirs.h). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "mkdirs.h"

/* mkdir path[0..n), tolerating one that exists as a directory. */
static int make_one(char *path)
{
    if (mkdir(path, 0777) == 0)
        return 0;
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
    }
    int e = errno;
    free(tmp);
    errno = e;
    return rc;
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
