#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include "fileio.h"

char *gls_read_file(const char *path, size_t limit, size_t *len, char *why, size_t whylen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(why, whylen, "cannot open %s: %s", path, strerror(errno));
        return NULL;
    }
    struct stat st;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(why, whylen, "%s is not a regular file", path);
        fclose(f);
        return NULL;
    }
    if ((unsigned long long)st.st_size > limit) {
        snprintf(why, whylen, "%s is %llu bytes, more than the limit of %zu", path, (unsigned long long)st.st_size, limit);
        fclose(f);
        return NULL;
    }
    size_t n = (size_t)st.st_size;
    char *buf = malloc(n + 1);
    if (!buf) {
        snprintf(why, whylen, "out of memory reading %s", path);
        fclose(f);
        return NULL;
    }
    size_t got = fread(buf, 1, n, f);
    if (got != n || ferror(f)) {
        snprintf(why, whylen, "cannot read %s: %s", path, ferror(f) ? strerror(errno) : "file changed while reading");
        free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    buf[n] = 0;
    *len = n;
    return buf;
}

int gls_is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

int gls_is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

char *gls_load_source(const char *path, size_t limit, size_t *len, size_t *mapped, char *why, size_t whylen)
{
    *mapped = 0;
    int fd = open(path, O_RDONLY);
    struct stat st;
    if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 &&
        (unsigned long long)st.st_size <= limit) {
        long page = sysconf(_SC_PAGESIZE);
        size_t n = (size_t)st.st_size;
        if (page > 0 && n % (size_t)page != 0) {
            /* the rest of the last page reads as zeros: the sentinel */
            void *p = mmap(NULL, n + 1, PROT_READ, MAP_PRIVATE, fd, 0);
            if (p != MAP_FAILED) {
                close(fd);
                *len = n;
                *mapped = n + 1;
                return p;
            }
        }
    }
    if (fd >= 0)
        close(fd);
    return gls_read_file(path, limit, len, why, whylen);
}

void gls_release_file(const char *buf, size_t mapped)
{
    if (mapped)
        munmap((void *)buf, mapped);
    else
        free((void *)buf);
}
