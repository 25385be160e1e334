/* The player's writer: encoding and writing the files of one camera frame
 * while the next is rendered (spec/camera.md "Outputs").
 *
 * A job is run by one writer thread, in the order submitted, so files and
 * frame records are written in the same order as without the thread and
 * hold the same bytes.  At most GLS_WRITER_DEPTH jobs wait or run: submit
 * blocks while that many are pending, so memory stays bounded (the
 * buffers of two frames besides the one being rendered).  After a job
 * fails, no later job runs (each is freed unrun) and every later submit
 * and finish returns that job's message, so the run stops at the same
 * frame, with the same message and the same files on disk, as without the
 * thread.  With no thread, submit runs the job at once. */
#ifndef GLS_FRAME_WRITER_H
#define GLS_FRAME_WRITER_H

#include <stddef.h>

#define GLS_WRITER_DEPTH 2

/* A job: run() does the work and returns 0, or -1 with a message (the
 * whole line, without the newline) in err; destroy() frees the job, run
 * or not.  The writer owns a job from submit on. */
typedef struct gls_write_job gls_write_job;
struct gls_write_job {
    int (*run)(gls_write_job *job, char *err, size_t errlen);
    void (*destroy)(gls_write_job *job);
    gls_write_job *next; /* the writer's queue */
};

typedef struct gls_writer gls_writer;

/* threads: 0 (run jobs in submit) or 1.  NULL when out of memory or no
 * thread could be started, with the reason in err. */
gls_writer *gls_writer_create(unsigned threads, char *err, size_t errlen);

/* Hand job over.  0, or -1 when this job or an earlier one failed: err
 * holds the first failure's message, and job has been freed. */
int gls_writer_submit(gls_writer *w, gls_write_job *job, char *err, size_t errlen);

/* Wait until every submitted job has run.  0, or -1 with the first
 * failure's message in err. */
int gls_writer_finish(gls_writer *w, char *err, size_t errlen);

/* Wait for the jobs, stop the thread, free everything.  NULL is fine. */
void gls_writer_destroy(gls_writer *w);

#endif
