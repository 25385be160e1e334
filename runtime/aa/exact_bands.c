/* Exact coverage: the bands of rows on worker threads and handed out in
 * order, or by the workers themselves in any order (exact.h
 * gls_exact_visit, gls_exact_visit_threads, gls_exact_visit_any_thread;
 * exact_int.h exact_visit_cands).  Each band is computed by exact_pixels.c's
 * exact_band_compute. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "exact_int.h"

/* Band lists (exact_int.h band_lists) of the triangles ok[] marks: 0, or -1 when out of memory */
static int exact_band_lists_make(const exact_prep *p, const unsigned char *ok, size_t n, int nbands, band_lists *l)
{
    l->start = calloc((size_t)nbands + 1, sizeof *l->start);
    if (!l->start)
        return -1;
    for (size_t t = 0; t < n; t++)
        if (ok[t])
            for (int b = p[t].j0 / EXACT_BAND; b <= p[t].j1 / EXACT_BAND; b++)
                l->start[b + 1]++;
    for (int b = 0; b < nbands; b++)
        l->start[b + 1] += l->start[b];
    if (!(l->idx = malloc((l->start[nbands] ? l->start[nbands] : 1) * sizeof *l->idx)))
        return -1;
    for (size_t t = 0; t < n; t++)
        if (ok[t])
            for (int b = p[t].j0 / EXACT_BAND; b <= p[t].j1 / EXACT_BAND; b++)
                l->idx[l->start[b]++] = t;
    for (int b = nbands; b > 0; b--)
        l->start[b] = l->start[b - 1];
    l->start[0] = 0;
    return 0;
}

/* Hand band j0's results out, pixel by pixel in order: to fn, or to the
 * walk's candidate callback. */
static int band_emit(const exact_work *wk, int w, int h, int j0, band_slot *b, gls_exact_pixel_fn fn, void *user)
{
    int j1 = j0 + EXACT_BAND - 1 < h - 1 ? j0 + EXACT_BAND - 1 : h - 1;
    for (int j = j0; j <= j1; j++)
        for (int i = 0; i < w; i++) {
            size_t px = (size_t)(j - j0) * w + i;
            if (wk->cands) {
                /* the visible candidates, first in the pixel's (fstart:
                 * their count, exact_band_compute) */
                if (wk->cands(wk->cuser, wk->prep, b->sorted + b->start[px], b->fstart[px], i, j))
                    return -1;
            } else
                fn(user, i, j, b->frags + b->fstart[px], b->fstart[px + 1] - b->fstart[px]);
        }
    return 0;
}

static void band_free(band_slot *b)
{
    free(b->fmin), free(b->start), free(b->fstart), free(b->c), free(b->sorted), free(b->frags);
}

/* Bands on worker threads: each takes the next band whose slot is free
 * (slot b % nslot, free once band b - nslot is handed out) and computes
 * it with its own scratch; the calling thread hands the bands out in
 * order.  A pixel's result depends on its band's candidates only, never
 * on the thread or the order, so the output is the same for any number
 * of threads (test_exact's test_exact_threads). */
#define EXACT_MAX_THREADS 64
typedef struct {
    const exact_work *proto;
    const band_lists *bl;
    gls_exact_pixel_fn fn; /* any_thread: the worker hands its band to fn  */
    void *user;
    int any_thread;
    int w, h, nbands, nslot;
    band_slot *slot;
    int *ready;         /* per slot: the band done in it + 1, 0: none      */
    int *rc;            /* per slot: that band's exact_band_compute              */
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int next, emitted, stop;
} sched;

static void *band_worker(void *arg)
{
    sched *s = arg;
    exact_work wk = {0};
    wk.prep = s->proto->prep, wk.tris = s->proto->tris, wk.cands = s->proto->cands, wk.cuser = s->proto->cuser;
    wk.dense = s->proto->dense;
    /* a worker that hands its bands out itself keeps one slot's buffers
     * for all of them: half the memory first touched (page faults were a
     * tenth of the road frame's CPU) */
    band_slot own = {0};
    pthread_mutex_lock(&s->mu);
    for (;;) {
        while (!s->stop && s->next < s->nbands && s->next >= s->emitted + s->nslot)
            pthread_cond_wait(&s->cv, &s->mu);
        if (s->stop || s->next >= s->nbands)
            break;
        int b = s->next++, k = b % s->nslot;
        pthread_mutex_unlock(&s->mu);
        band_slot *slot = s->any_thread ? &own : &s->slot[k];
        int rc = exact_band_compute(&wk, s->bl, s->w, s->h, b * EXACT_BAND, slot);
        if (rc == 0 && s->any_thread)
            rc = band_emit(&wk, s->w, s->h, b * EXACT_BAND, slot, s->fn, s->user);
        pthread_mutex_lock(&s->mu);
        s->rc[k] = rc, s->ready[k] = b + 1;
        pthread_cond_broadcast(&s->cv);
    }
    pthread_mutex_unlock(&s->mu);
    band_free(&own);
    exact_work_free(&wk);
    return NULL;
}

static unsigned auto_threads(unsigned threads, int nbands)
{
    if (!threads) {
        long cpus = sysconf(_SC_NPROCESSORS_ONLN);
        threads = cpus > 0 ? (unsigned)cpus : 1;
    }
    if (threads > EXACT_MAX_THREADS)
        threads = EXACT_MAX_THREADS;
    if (threads > (unsigned)nbands)
        threads = (unsigned)nbands;
    return threads;
}

static int run_bands(exact_work *wk, const band_lists *bl, int w, int h, gls_exact_pixel_fn fn, void *user,
                     unsigned threads, int any_thread)
{
    int nbands = (h + EXACT_BAND - 1) / EXACT_BAND, rc = 0;
    threads = auto_threads(threads, nbands);
    if (threads <= 1) { /* here, band by band */
        band_slot b = {0};
        for (int k = 0; k < nbands && rc == 0; k++)
            if ((rc = exact_band_compute(wk, bl, w, h, k * EXACT_BAND, &b)) == 0)
                rc = band_emit(wk, w, h, k * EXACT_BAND, &b, fn, user);
        band_free(&b);
        return rc;
    }
    /* fn on the workers only for pixels' values (never the walk's
     * candidates, which exact_edges.c takes in order) */
    any_thread = any_thread && fn && !wk->cands;
    sched s = {wk, bl, fn, user, any_thread, w, h, nbands, 2 * (int)threads, NULL, NULL, NULL,
               PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, 0, 0, 0};
    pthread_t th[EXACT_MAX_THREADS];
    unsigned started = 0;
    s.slot = calloc((size_t)s.nslot, sizeof *s.slot);
    s.ready = calloc((size_t)s.nslot, sizeof *s.ready);
    s.rc = calloc((size_t)s.nslot, sizeof *s.rc);
    if (s.slot && s.ready && s.rc)
        while (started < threads && pthread_create(&th[started], NULL, band_worker, &s) == 0)
            started++;
    if (!started) { /* no threads to be had: here */
        free(s.slot), free(s.ready), free(s.rc);
        return run_bands(wk, bl, w, h, fn, user, 1, 0);
    }
    for (int b = 0; b < nbands && rc == 0; b++) {
        int k = b % s.nslot;
        pthread_mutex_lock(&s.mu);
        while (s.ready[k] != b + 1)
            pthread_cond_wait(&s.cv, &s.mu);
        pthread_mutex_unlock(&s.mu);
        rc = s.rc[k] ? s.rc[k] : any_thread ? 0 : band_emit(wk, w, h, b * EXACT_BAND, &s.slot[k], fn, user);
        pthread_mutex_lock(&s.mu);
        s.ready[k] = 0, s.emitted = b + 1, s.stop = rc != 0;
        pthread_cond_broadcast(&s.cv);
        pthread_mutex_unlock(&s.mu);
    }
    pthread_mutex_lock(&s.mu);
    s.stop = 1;
    pthread_cond_broadcast(&s.cv);
    pthread_mutex_unlock(&s.mu);
    for (unsigned k = 0; k < started; k++)
        pthread_join(th[k], NULL);
    for (int k = 0; k < s.nslot; k++)
        band_free(&s.slot[k]);
    free(s.slot), free(s.ready), free(s.rc);
    return rc;
}

static int visit(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user,
                 exact_cand_fn cands, unsigned threads, int any_thread, size_t dense)
{
    if (w <= 0 || h <= 0)
        return 0;
    /* exact_cand's fields: a triangle index in 32 bits, a band's pixel in 31 */
    if (n > UINT32_MAX || (size_t)w > ((size_t)1 << 31) / EXACT_BAND - 1)
        return -1;
    exact_prep *p = malloc((n ? n : 1) * sizeof *p);
    unsigned char *ok = malloc(n ? n : 1);
    exact_work wk = {0};
    int rc = -1;
    if (p && ok) {
        for (size_t k = 0; k < n; k++)
            ok[k] = (unsigned char)exact_prep_tri(&t[k], w, h, &p[k]);
        wk.prep = p, wk.tris = t, wk.cands = cands, wk.cuser = user, wk.dense = dense;
        band_lists bl = {0};
        rc = exact_band_lists_make(p, ok, n, (h + EXACT_BAND - 1) / EXACT_BAND, &bl);
        if (rc == 0)
            rc = run_bands(&wk, &bl, w, h, fn, user, threads, any_thread);
        free(bl.start), free(bl.idx);
    }
    exact_work_free(&wk);
    free(p), free(ok);
    return rc;
}

int gls_exact_visit(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user)
{
    return visit(t, n, w, h, fn, user, NULL, 0, 0, 0);
}

int exact_visit_dense(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user, size_t dense)
{
    return visit(t, n, w, h, fn, user, NULL, 0, 1, dense);
}

int gls_exact_visit_any_thread(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user)
{
    return visit(t, n, w, h, fn, user, NULL, 0, 1, 0);
}

int gls_exact_visit_threads(const gls_exact_tri *t, size_t n, int w, int h, gls_exact_pixel_fn fn, void *user,
                            unsigned threads)
{
    return visit(t, n, w, h, fn, user, NULL, threads, 0, 0);
}

int exact_visit_cands(const gls_exact_tri *t, size_t n, int w, int h, exact_cand_fn fn, void *user)
{
    return visit(t, n, w, h, NULL, user, fn, 0, 0, 0);
}
