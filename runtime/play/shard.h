/* glsplay --shard I/N: which frames of a sequence one process renders,
 * so that N processes (GNU Parallel, a Slurm job array) split a sequence
 * without a scheduler of their own (spec/road.md "Sharding").  Shard I of
 * N renders the frames f of the selected range A..B-1 (--frames; A is 0
 * without it) with (f - A) mod N = I; the shards 0..N-1 together render
 * every frame once.  A single render (no --trajectory) is shard 0's. */
#ifndef GLS_SHARD_H
#define GLS_SHARD_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* count 0: no --shard, every frame */
typedef struct {
    uint64_t index, count;
} gls_shard;

/* The largest N: frame numbers are 32-bit (spec/road.md). */
#define GLS_SHARD_MAX 4294967295ull

/* Read "I/N" (0 <= I < N <= GLS_SHARD_MAX) or "slurm": then
 * SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT, less
 * SLURM_ARRAY_TASK_MIN and divided by SLURM_ARRAY_TASK_STEP where those
 * are set, through env (getenv, or a test's table).  0, or -1 with the
 * message (no "glsplay: error: ") in msg. */
int gls_shard_parse(const char *arg, char *(*env)(const char *), gls_shard *s, char *msg, size_t len);

/* Does shard s render frame f of a range starting at first (f >= first)? */
int gls_shard_has(const gls_shard *s, uint64_t first, uint64_t f);

/* --explain's line: "shard I/N: ...: K of the M frames in range". */
void gls_shard_explain(FILE *out, const gls_shard *s, int sequence, uint64_t first, uint64_t mine,
                       uint64_t inrange);

#endif
