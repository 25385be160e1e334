/* The player's writer queue (runtime/write/frame_writer.h) with jobs whose
 * timing the test controls: jobs run in order; at most GLS_WRITER_DEPTH
 * are pending (submit blocks); after a failure no later job runs, every
 * later submit and finish return that failure's message and every job is
 * freed; without a thread, submit runs the job at once. */
#include <pthread.h>
#include <semaphore.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "check.h"
#include "frame_writer.h"

typedef struct {
    gls_write_job job;
    int id, fail;
    sem_t *gate; /* waited on before running, when set */
} fake_job;

static int ran[16], nran, destroyed;

static int fake_run(gls_write_job *j, char *err, size_t errlen)
{
    fake_job *f = (fake_job *)j;
    if (f->gate)
        sem_wait(f->gate);
    ran[nran++] = f->id;
    if (f->fail)
        snprintf(err, errlen, "job %d failed", f->id);
    return f->fail ? -1 : 0;
}

static void fake_destroy(gls_write_job *j)
{
    destroyed++;
    free(j);
}

static gls_write_job *fake(int id, int fail, sem_t *gate)
{
    fake_job *f = calloc(1, sizeof *f);
    f->job.run = fake_run;
    f->job.destroy = fake_destroy;
    f->id = id, f->fail = fail, f->gate = gate;
    return &f->job;
}

static void reset(void)
{
    nran = destroyed = 0;
}

static void sleep_ms(long ms)
{
    struct timespec t = {0, ms * 1000000L};
    nanosleep(&t, NULL);
}

/* job 1 fails while job 2 waits behind it: job 2 never runs, later
 * submits are refused with job 1's message */
static void test_failure_stops_later_jobs(void)
{
    reset();
    char err[256] = "";
    sem_t gate;
    sem_init(&gate, 0, 0);
    gls_writer *w = gls_writer_create(1, err, sizeof err);
    CHECK(w != NULL);
    if (!w)
        return;
    CHECK(gls_writer_submit(w, fake(1, 1, &gate), err, sizeof err) == 0);
    CHECK(gls_writer_submit(w, fake(2, 0, NULL), err, sizeof err) == 0);
    sem_post(&gate);
    CHECK(gls_writer_finish(w, err, sizeof err) == -1);
    CHECK_STR(err, "job 1 failed");
    err[0] = 0;
    CHECK(gls_writer_submit(w, fake(3, 0, NULL), err, sizeof err) == -1);
    CHECK_STR(err, "job 1 failed");
    gls_writer_destroy(w);
    CHECK(nran == 1 && ran[0] == 1);
    CHECK(destroyed == 3);
    sem_destroy(&gate);
}

typedef struct {
    gls_writer *w;
    volatile int returned;
} submitter;

static void *submit_third(void *arg)
{
    submitter *s = arg;
    char err[64];
    gls_writer_submit(s->w, fake(3, 0, NULL), err, sizeof err);
    s->returned = 1;
    return NULL;
}

/* two pending jobs: a third submit waits until one has run; all run in
 * order */
static void test_bounded_and_ordered(void)
{
    reset();
    char err[256];
    sem_t gate;
    sem_init(&gate, 0, 0);
    gls_writer *w = gls_writer_create(1, err, sizeof err);
    CHECK(w != NULL);
    if (!w)
        return;
    CHECK(GLS_WRITER_DEPTH == 2);
    CHECK(gls_writer_submit(w, fake(1, 0, &gate), err, sizeof err) == 0);
    CHECK(gls_writer_submit(w, fake(2, 0, NULL), err, sizeof err) == 0);
    submitter s = {w, 0};
    pthread_t t;
    pthread_create(&t, NULL, submit_third, &s);
    sleep_ms(100);
    CHECK(s.returned == 0); /* blocked: two pending */
    sem_post(&gate);
    pthread_join(t, NULL);
    CHECK(s.returned == 1);
    CHECK(gls_writer_finish(w, err, sizeof err) == 0);
    CHECK(nran == 3 && ran[0] == 1 && ran[1] == 2 && ran[2] == 3);
    gls_writer_destroy(w);
    CHECK(destroyed == 3);
    sem_destroy(&gate);
}

/* no thread: each job runs inside submit; the same failure rules */
static void test_without_thread(void)
{
    reset();
    char err[256] = "";
    gls_writer *w = gls_writer_create(0, err, sizeof err);
    CHECK(w != NULL);
    if (!w)
        return;
    CHECK(gls_writer_submit(w, fake(1, 0, NULL), err, sizeof err) == 0);
    CHECK(nran == 1 && destroyed == 1);
    CHECK(gls_writer_submit(w, fake(2, 1, NULL), err, sizeof err) == -1);
    CHECK_STR(err, "job 2 failed");
    err[0] = 0;
    CHECK(gls_writer_submit(w, fake(3, 0, NULL), err, sizeof err) == -1);
    CHECK_STR(err, "job 2 failed");
    CHECK(gls_writer_finish(w, err, sizeof err) == -1);
    gls_writer_destroy(w);
    CHECK(nran == 2 && destroyed == 3);
}

int main(void)
{
    RUN(test_failure_stops_later_jobs);
    RUN(test_bounded_and_ordered);
    RUN(test_without_thread);
    CHECK_EXIT();
}
