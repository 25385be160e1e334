/* --shard I/N and --shard slurm (runtime/play/shard.c): parsing, the messages
 * of bad values and variables, and that the shards split a range. */
#include <stdlib.h>
#include "check.h"
#include "shard.h"

/* A fake environment for --shard slurm: NAME=VALUE strings. */
static const char *const *env_now;
static char *fake_env(const char *name)
{
    size_t n = strlen(name);
    for (const char *const *e = env_now; e && *e; e++)
        if (strncmp(*e, name, n) == 0 && (*e)[n] == '=')
            return (char *)*e + n + 1;
    return NULL;
}

static int parse(const char *arg, const char *const *env, gls_shard *s, char *msg)
{
    env_now = env;
    msg[0] = 0;
    return gls_shard_parse(arg, fake_env, s, msg, 512);
}

static void test_parse_i_n(void)
{
    gls_shard s;
    char msg[512];
    CHECK(parse("0/1", NULL, &s, msg) == 0 && s.index == 0 && s.count == 1);
    CHECK(parse("2/3", NULL, &s, msg) == 0 && s.index == 2 && s.count == 3);
    CHECK(parse("4294967294/4294967295", NULL, &s, msg) == 0 && s.count == 4294967295ull);
    static const char *const bad[] = {"3/3", "1/0", "0/0", "x", "", "/3", "1/", "-1/3", "+1/3", "1/-3",
                                      " 1/3", "1/3 ", "1/3/4", "1/4294967296", "99999999999999999999/3"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        CHECK_MSG(parse(bad[i], NULL, &s, msg) == -1, "'%s' accepted", bad[i]);
    }
    parse("3/3", NULL, &s, msg);
    CHECK_STR(msg, "--shard needs I/N with 0 <= I < N (or slurm), got '3/3'");
}

static void test_parse_slurm(void)
{
    gls_shard s;
    char msg[512];
    static const char *const plain[] = {"SLURM_ARRAY_TASK_ID=2", "SLURM_ARRAY_TASK_COUNT=5", NULL};
    CHECK(parse("slurm", plain, &s, msg) == 0 && s.index == 2 && s.count == 5);
    /* --array=1-5: MIN 1, task 3 is shard 2 */
    static const char *const from1[] = {"SLURM_ARRAY_TASK_ID=3", "SLURM_ARRAY_TASK_COUNT=5",
                                        "SLURM_ARRAY_TASK_MIN=1", NULL};
    CHECK(parse("slurm", from1, &s, msg) == 0 && s.index == 2 && s.count == 5);
    /* --array=10-18:4: tasks 10, 14, 18 */
    static const char *const step[] = {"SLURM_ARRAY_TASK_ID=18", "SLURM_ARRAY_TASK_COUNT=3",
                                       "SLURM_ARRAY_TASK_MIN=10", "SLURM_ARRAY_TASK_STEP=4", NULL};
    CHECK(parse("slurm", step, &s, msg) == 0 && s.index == 2 && s.count == 3);

    static const char *const none[] = {NULL};
    CHECK(parse("slurm", none, &s, msg) == -1);
    CHECK_STR(msg, "--shard slurm: SLURM_ARRAY_TASK_ID is not set (run glsplay as a task of a Slurm job array, "
                   "sbatch --array, or give --shard I/N)");
    static const char *const nocount[] = {"SLURM_ARRAY_TASK_ID=0", NULL};
    CHECK(parse("slurm", nocount, &s, msg) == -1);
    CHECK_STR(msg, "--shard slurm: SLURM_ARRAY_TASK_COUNT is not set (run glsplay as a task of a Slurm job array, "
                   "sbatch --array, or give --shard I/N)");
    static const char *const garbled[] = {"SLURM_ARRAY_TASK_ID=1", "SLURM_ARRAY_TASK_COUNT=4x", NULL};
    CHECK(parse("slurm", garbled, &s, msg) == -1);
    CHECK_STR(msg, "--shard slurm: SLURM_ARRAY_TASK_COUNT is '4x', not a whole number");
    static const char *const badmin[] = {"SLURM_ARRAY_TASK_ID=1", "SLURM_ARRAY_TASK_COUNT=4",
                                         "SLURM_ARRAY_TASK_MIN=", NULL};
    CHECK(parse("slurm", badmin, &s, msg) == -1);
    CHECK_STR(msg, "--shard slurm: SLURM_ARRAY_TASK_MIN is '', not a whole number");
    static const char *const zero[] = {"SLURM_ARRAY_TASK_ID=0", "SLURM_ARRAY_TASK_COUNT=0", NULL};
    CHECK(parse("slurm", zero, &s, msg) == -1);
    CHECK_STR(msg, "--shard slurm: SLURM_ARRAY_TASK_COUNT is 0");
    /* --array=1,4,9: task 9 of 3 is no shard number */
    static const char *const list[] = {"SLURM_ARRAY_TASK_ID=9", "SLURM_ARRAY_TASK_COUNT=3",
                                       "SLURM_ARRAY_TASK_MIN=1", NULL};
    CHECK(parse("slurm", list, &s, msg) == -1);
    CHECK_STR(msg, "--shard slurm: SLURM_ARRAY_TASK_ID 9 is not task 0..2 of an array from SLURM_ARRAY_TASK_MIN 1 "
                   "in steps of 1 (give --shard I/N for other arrays)");
    static const char *const below[] = {"SLURM_ARRAY_TASK_ID=0", "SLURM_ARRAY_TASK_COUNT=3",
                                        "SLURM_ARRAY_TASK_MIN=1", NULL};
    CHECK(parse("slurm", below, &s, msg) == -1);
}

/* Every frame of a range, gaps or not, falls to exactly one shard, and
 * shard I takes first + I, first + I + N, ... */
static void test_partition(void)
{
    for (uint64_t n = 1; n <= 7; n++)
        for (uint64_t first = 0; first < 5; first++)
            for (uint64_t f = first; f < first + 40; f++) {
                int owners = 0;
                for (uint64_t i = 0; i < n; i++) {
                    gls_shard s = {i, n};
                    owners += gls_shard_has(&s, first, f);
                    if (gls_shard_has(&s, first, f))
                        CHECK((f - first) % n == i);
                }
                CHECK_MSG(owners == 1, "frame %llu of N %llu has %d shards", (unsigned long long)f,
                          (unsigned long long)n, owners);
            }
    gls_shard all = {0, 0};
    CHECK(gls_shard_has(&all, 3, 3) && gls_shard_has(&all, 3, 1000));
    gls_shard s = {1, 3};
    CHECK(!gls_shard_has(&s, 2, 2) && gls_shard_has(&s, 2, 3) && !gls_shard_has(&s, 2, 5) && gls_shard_has(&s, 2, 6));
}

int main(void)
{
    RUN(test_parse_i_n);
    RUN(test_parse_slurm);
    RUN(test_partition);
    CHECK_EXIT();
}
