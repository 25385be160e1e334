/* FNV-1a digests of bytes and files (digest.h). */
#include "digest.h"
#include <unistd.h>
#include "readfile.h"

uint64_t gls_digest_bytes(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ c[i]) * 0x100000001b3ull; /* FNV-1a's 64-bit prime */
    return h;
}

/* the length first, so that two inputs' bytes cannot run together */
static uint64_t digest_length(uint64_t h, uint64_t size)
{
    unsigned char le[8]; /* little-endian: the same digest on every machine of a cluster */
    for (int i = 0; i < 8; i++)
        le[i] = (unsigned char)(size >> (8 * i));
    return gls_digest_bytes(h, le, sizeof le);
}

uint64_t gls_digest_sized(uint64_t h, const void *p, size_t n)
{
    return gls_digest_bytes(digest_length(h, (uint64_t)n), p, n);
}

int gls_digest_file(uint64_t *h, const char *path)
{
    struct stat st;
    gls_read_error e;
    int fd = gls_file_open(path, &st, &e);
    if (fd < 0)
        return -1;
    uint64_t size = (uint64_t)st.st_size;
    uint64_t d = digest_length(*h, size);
    unsigned char block[65536];
    uint64_t left = size;
    while (left) {
        size_t n = left < sizeof block ? (size_t)left : sizeof block;
        if (gls_read_full(fd, block, n)) {
            close(fd);
            return -1;
        }
        d = gls_digest_bytes(d, block, n);
        left -= n;
    }
    close(fd);
    *h = d;
    return 0;
}
