/* The player's writer thread and its bounded queue (frame_writer.h). */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "frame_writer.h"

struct gls_writer {
    unsigned threads;
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t work;    /* a job was queued, or stop was set        */
    pthread_cond_t changed; /* a job finished (pending went down)       */
    gls_write_job *head, *tail;
    size_t pending; /* queued and running                               */
    int stop, failed;
    char msg[1024]; /* the first failure's message                      */
};

static void copy_msg(const gls_writer *w, char *err, size_t errlen)
{
    if (errlen)
        snprintf(err, errlen, "%s", w->msg);
}

/* Run a job (or free it unrun after a failure); the caller does not hold
 * the lock.  Returns the job's result, 0 when skipped. */
static int run_job(gls_write_job *job, int skip, char *msg, size_t msglen)
{
    int r = skip ? 0 : job->run(job, msg, msglen);
    job->destroy(job);
    return r;
}

static void *writer_main(void *arg)
{
    gls_writer *w = arg;
    char msg[sizeof w->msg];
    pthread_mutex_lock(&w->lock);
    for (;;) {
        while (!w->head && !w->stop)
            pthread_cond_wait(&w->work, &w->lock);
        if (!w->head)
            break; /* stop, and nothing left */
        gls_write_job *job = w->head;
        w->head = job->next;
        if (!w->head)
            w->tail = NULL;
        int skip = w->failed;
        pthread_mutex_unlock(&w->lock);
        msg[0] = 0;
        int r = run_job(job, skip, msg, sizeof msg);
        pthread_mutex_lock(&w->lock);
        if (r && !w->failed) {
            w->failed = 1;
            memcpy(w->msg, msg, sizeof msg);
        }
        w->pending--;
        pthread_cond_broadcast(&w->changed);
    }
    pthread_mutex_unlock(&w->lock);
    return NULL;
}

gls_writer *gls_writer_create(unsigned threads, char *err, size_t errlen)
{
    gls_writer *w = calloc(1, sizeof *w);
    if (!w) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    w->threads = threads ? 1 : 0;
    if (!w->threads)
        return w;
    pthread_mutex_init(&w->lock, NULL);
    pthread_cond_init(&w->work, NULL);
    pthread_cond_init(&w->changed, NULL);
    int e = pthread_create(&w->thread, NULL, writer_main, w);
    if (e) {
        snprintf(err, errlen, "cannot start the writer thread: %s (--writer-threads 0 writes without one)",
                 strerror(e));
        pthread_cond_destroy(&w->changed);
        pthread_cond_destroy(&w->work);
        pthread_mutex_destroy(&w->lock);
        free(w);
        return NULL;
    }
    return w;
}

int gls_writer_submit(gls_writer *w, gls_write_job *job, char *err, size_t errlen)
{
    if (!w->threads) {
        if (w->failed)
            job->destroy(job);
        else if (run_job(job, 0, w->msg, sizeof w->msg))
            w->failed = 1;
        else
            return 0;
        copy_msg(w, err, errlen);
        return -1;
    }
    pthread_mutex_lock(&w->lock);
    while (w->pending >= GLS_WRITER_DEPTH && !w->failed)
        pthread_cond_wait(&w->changed, &w->lock);
    if (w->failed) {
        copy_msg(w, err, errlen);
        pthread_mutex_unlock(&w->lock);
        job->destroy(job);
        return -1;
    }
    job->next = NULL;
    if (w->tail)
        w->tail->next = job;
    else
        w->head = job;
    w->tail = job;
    w->pending++;
    pthread_cond_signal(&w->work);
    pthread_mutex_unlock(&w->lock);
    return 0;
}

int gls_writer_finish(gls_writer *w, char *err, size_t errlen)
{
    if (!w->threads) {
        if (w->failed)
            copy_msg(w, err, errlen);
        return w->failed ? -1 : 0;
    }
    pthread_mutex_lock(&w->lock);
    while (w->pending > 0)
        pthread_cond_wait(&w->changed, &w->lock);
    int failed = w->failed;
    if (failed)
        copy_msg(w, err, errlen);
    pthread_mutex_unlock(&w->lock);
    return failed ? -1 : 0;
}

void gls_writer_destroy(gls_writer *w)
{
    if (!w)
        return;
    if (w->threads) {
        pthread_mutex_lock(&w->lock);
        w->stop = 1;
        pthread_cond_signal(&w->work);
        pthread_mutex_unlock(&w->lock);
        pthread_join(w->thread, NULL);
        pthread_cond_destroy(&w->changed);
        pthread_cond_destroy(&w->work);
        pthread_mutex_destroy(&w->lock);
    }
    free(w);
}
