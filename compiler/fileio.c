/* The compiler's inputs read whole (fileio.h), through base/readfile.h,
 * with the compiler's wording of what went wrong. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>
#include "fileio.h"
#include "readfile.h"

char *gls_read_file(const char *path, size_t limit, size_t *len, char *why, size_t whylen)
{
    gls_read_error e;
    char *buf = gls_file_read(path, limit, len, &e);
    if (buf)
        return buf;
    switch (e.status) {
    case GLS_READ_OPEN: snprintf(why, whylen, "cannot open %s: %s", path, strerror(e.err)); break;
    case GLS_READ_STAT: snprintf(why, whylen, "cannot read %s: %s", path, strerror(e.err)); break;
    case GLS_READ_DIR:
    case GLS_READ_NOT_REGULAR: snprintf(why, whylen, "cannot read %s: %s", path, gls_file_kind(e.mode)); break;
    case GLS_READ_TOO_LARGE:
        snprintf(why, whylen, "%s is %llu bytes, more than the limit of %zu", path, e.size, limit);
        break;
    case GLS_READ_NOMEM: snprintf(why, whylen, "out of memory reading %s", path); break;
    default:
        snprintf(why, whylen, "cannot read %s: %s", path,
                 e.status == GLS_READ_IO ? strerror(e.err) : "file changed while reading");
        break;
    }
    return NULL;
}

char *gls_load_source(const char *path, size_t limit, size_t *len, size_t *mapped, char *why, size_t whylen)
{
    *mapped = 0;
    struct stat st;
    gls_read_error e;
    int fd = gls_file_open(path, &st, &e);
    if (fd >= 0 && st.st_size > 0 && (unsigned long long)st.st_size <= limit) {
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
