/* Minimal test harness shared by the unit tests.  Each test program prints
 * one line per check group: "ok NAME" or "FAIL NAME: why (file:line)".
 * tests/run.sh counts those lines across all programs and prints the
 * closing "N passed, N failed" line. */
#ifndef GLS_CHECK_H
#define GLS_CHECK_H
#include <math.h>
#include <stdio.h>
#include <string.h>

static int check_failed_ = 0;   /* failures in the current TEST */
static int check_total_fail_ = 0;

#define CHECK(cond)                                                                   \
    do {                                                                              \
        if (!(cond)) {                                                                \
            printf("  check failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__);        \
            check_failed_++;                                                          \
        }                                                                             \
    } while (0)

#define CHECK_MSG(cond, ...)                                                          \
    do {                                                                              \
        if (!(cond)) {                                                                \
            printf("  check failed: %s (%s:%d): ", #cond, __FILE__, __LINE__);        \
            printf(__VA_ARGS__);                                                      \
            printf("\n");                                                             \
            check_failed_++;                                                          \
        }                                                                             \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                         \
    do {                                                                              \
        double a_ = (a), b_ = (b);                                                    \
        if (!(fabs(a_ - b_) <= (tol))) {                                              \
            printf("  check failed: |%s - %s| = %.9g > %g (%s:%d)\n", #a, #b,         \
                   fabs(a_ - b_), (double)(tol), __FILE__, __LINE__);                 \
            check_failed_++;                                                          \
        }                                                                             \
    } while (0)

#define CHECK_STR(a, b)                                                               \
    do {                                                                              \
        const char *a_ = (a), *b_ = (b);                                              \
        if (!a_ || !b_ || strcmp(a_, b_) != 0) {                                      \
            printf("  check failed: %s == %s\n    got:      %s\n    expected: %s (%s:%d)\n", \
                   #a, #b, a_ ? a_ : "(null)", b_ ? b_ : "(null)", __FILE__, __LINE__); \
            check_failed_++;                                                          \
        }                                                                             \
    } while (0)

/* Run one test function and report it. */
#define RUN(fn)                                                                       \
    do {                                                                              \
        check_failed_ = 0;                                                            \
        fn();                                                                         \
        if (check_failed_) {                                                          \
            printf("FAIL %s\n", #fn);                                                 \
            check_total_fail_++;                                                      \
        } else {                                                                      \
            printf("ok %s\n", #fn);                                                   \
        }                                                                             \
        fflush(stdout);                                                               \
    } while (0)

#define CHECK_EXIT() return check_total_fail_ ? 1 : 0
#endif
