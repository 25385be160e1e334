/* A 64-bit digest of bytes and of files' contents (FNV-1a), to notice
 * that an input changed between two runs (the player's frame records,
 * --resume).  Not a defence against someone who wants a collision. */
#ifndef GLS_DIGEST_H
#define GLS_DIGEST_H
#include <stddef.h>
#include <stdint.h>

#define GLS_DIGEST_INIT 0xcbf29ce484222325ull /* FNV-1a's offset basis */

/* h extended by n bytes at p. */
uint64_t gls_digest_bytes(uint64_t h, const void *p, size_t n);

/* h extended by the length n (8 bytes, little-endian) and the n bytes at
 * p: what gls_digest_file gives for a file of those bytes, for an input
 * read into memory once (a trajectory, which may be a pipe). */
uint64_t gls_digest_sized(uint64_t h, const void *p, size_t n);

/* *h extended by the length and the bytes of the regular file at path
 * (read in blocks, any size).  0, or -1 (and *h unchanged) when path is
 * not a regular file or cannot be read whole: a pipe or a device cannot
 * be read a second time, so it has no digest. */
int gls_digest_file(uint64_t *h, const char *path);
#endif
