/* --shard I/N and --shard slurm (shard.h). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "shard.h"

/* A whole decimal number, no sign, within 0..GLS_SHARD_MAX. */
static int whole(const char *s, uint64_t *v)
{
    char *e;
    if (!s || !s[0] || s[0] < '0' || s[0] > '9')
        return -1;
    errno = 0;
    unsigned long long x = strtoull(s, &e, 10);
    if (*e || errno || x > GLS_SHARD_MAX)
        return -1;
    *v = x;
    return 0;
}

/* One SLURM_ARRAY_TASK_* variable: 0, 1 when unset and optional, -1
 * with the message. */
static int slurm_var(char *(*env)(const char *), const char *name, int optional, uint64_t *v, char *msg, size_t len)
{
    const char *s = env(name);
    if (!s) {
        if (optional)
            return 1;
        snprintf(msg, len, "--shard slurm: %s is not set (run glsplay as a task of a Slurm job array, "
                           "sbatch --array, or give --shard I/N)", name);
        return -1;
    }
    if (whole(s, v)) {
        snprintf(msg, len, "--shard slurm: %s is '%.64s', not a whole number", name, s);
        return -1;
    }
    return 0;
}

static int parse_slurm(char *(*env)(const char *), gls_shard *s, char *msg, size_t len)
{
    uint64_t id, count, min = 0, step = 1;
    int r;
    if (slurm_var(env, "SLURM_ARRAY_TASK_ID", 0, &id, msg, len) ||
        slurm_var(env, "SLURM_ARRAY_TASK_COUNT", 0, &count, msg, len) ||
        (r = slurm_var(env, "SLURM_ARRAY_TASK_MIN", 1, &min, msg, len)) < 0 ||
        (r = slurm_var(env, "SLURM_ARRAY_TASK_STEP", 1, &step, msg, len)) < 0)
        return -1;
    if (count == 0 || step == 0) {
        snprintf(msg, len, "--shard slurm: %s is 0", count == 0 ? "SLURM_ARRAY_TASK_COUNT" : "SLURM_ARRAY_TASK_STEP");
        return -1;
    }
    /* an array MIN, MIN+STEP, ..., one task per shard: any other array
       (a list such as --array=1,4,9) does not number its tasks 0..N-1 */
    if (id < min || (id - min) % step || (id - min) / step >= count) {
        snprintf(msg, len, "--shard slurm: SLURM_ARRAY_TASK_ID %llu is not task 0..%llu of an array from "
                           "SLURM_ARRAY_TASK_MIN %llu in steps of %llu (give --shard I/N for other arrays)",
                 (unsigned long long)id, (unsigned long long)(count - 1), (unsigned long long)min,
                 (unsigned long long)step);
        return -1;
    }
    s->index = (id - min) / step;
    s->count = count;
    return 0;
}

int gls_shard_parse(const char *arg, char *(*env)(const char *), gls_shard *s, char *msg, size_t len)
{
    if (strcmp(arg, "slurm") == 0)
        return parse_slurm(env, s, msg, len);
    const char *slash = strchr(arg, '/');
    char i[32];
    uint64_t vi, vn;
    if (!slash || (size_t)(slash - arg) >= sizeof i)
        goto bad;
    memcpy(i, arg, (size_t)(slash - arg));
    i[slash - arg] = 0;
    if (whole(i, &vi) || whole(slash + 1, &vn) || vn == 0 || vi >= vn)
        goto bad;
    s->index = vi;
    s->count = vn;
    return 0;
bad:
    snprintf(msg, len, "--shard needs I/N with 0 <= I < N (or slurm), got '%.64s'", arg);
    return -1;
}

int gls_shard_has(const gls_shard *s, uint64_t first, uint64_t f)
{
    return s->count <= 1 || (f - first) % s->count == s->index;
}

void gls_shard_explain(FILE *out, const gls_shard *s, int sequence, uint64_t first, uint64_t mine,
                       uint64_t inrange)
{
    if (s->count == 0)
        return;
    if (sequence)
        fprintf(out,
                "shard %llu/%llu: the frames f with (f - %llu) mod %llu = %llu: %llu of the %llu frame%s in range\n",
                (unsigned long long)s->index, (unsigned long long)s->count, (unsigned long long)first,
                (unsigned long long)s->count, (unsigned long long)s->index, (unsigned long long)mine,
                (unsigned long long)inrange, inrange == 1 ? "" : "s");
    else
        fprintf(out, "shard %llu/%llu: a single render (no --trajectory) is shard 0's: %llu of 1 frame\n",
                (unsigned long long)s->index, (unsigned long long)s->count, (unsigned long long)mine);
}
