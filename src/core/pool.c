/* A fixed thread pool with one operation: a parallel for over [0, n) with dynamic hand-out.
 * One job runs at a time: a caller that finds the pool busy (another thread's job, or a nested
 * call from inside a job) runs its loop itself, serially, so concurrent callers can never
 * overwrite each other's job and a nested call cannot deadlock. */
#include "semsplat/core.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

struct sp_pool {
    int n_threads; /* workers, not counting the caller */
    pthread_t *threads;
    pthread_mutex_t mu;
    pthread_mutex_t job_mu; /* held by the caller whose job the workers run */
    pthread_cond_t cv_work, cv_done;
    /* current job */
    void (*fn)(void *, long, int);
    void *ctx;
    long n, next;
    int active;       /* workers still inside the job */
    unsigned long gen; /* job generation, so workers wake once per job */
    int quit;
};

typedef struct { sp_pool *pool; int id; } worker_arg;

static void run_items(sp_pool *p, int tid)
{
    for (;;) {
        long i = __atomic_fetch_add(&p->next, 1, __ATOMIC_RELAXED);
        if (i >= p->n) break;
        p->fn(p->ctx, i, tid);
    }
}

static void *worker(void *arg)
{
    worker_arg *wa = arg;
    sp_pool *p = wa->pool;
    int id = wa->id;
    free(wa);
    unsigned long seen = 0;
    pthread_mutex_lock(&p->mu);
    for (;;) {
        while (!p->quit && p->gen == seen) pthread_cond_wait(&p->cv_work, &p->mu);
        if (p->quit) break;
        seen = p->gen;
        pthread_mutex_unlock(&p->mu);
        run_items(p, id);
        pthread_mutex_lock(&p->mu);
        if (--p->active == 0) pthread_cond_signal(&p->cv_done);
    }
    pthread_mutex_unlock(&p->mu);
    return NULL;
}

int sp_pool_create(sp_pool **out, int n_threads, sp_error *err)
{
    *out = NULL;
    if (n_threads < 0 || n_threads > SP_MAX_THREADS)
        return sp_error_set(err, SP_E_ARG, "threads %d: expected 0 (all cores) to %d", n_threads, SP_MAX_THREADS);
    if (n_threads == 0) {
        long c = sysconf(_SC_NPROCESSORS_ONLN);
        n_threads = c > 0 ? (int)c : 1;
    }
    sp_pool *p = calloc(1, sizeof *p);
    if (!p) return sp_error_set(err, SP_E_NOMEM, "thread pool: out of memory");
    p->n_threads = n_threads - 1;
    pthread_mutex_init(&p->mu, NULL);
    pthread_mutex_init(&p->job_mu, NULL);
    pthread_cond_init(&p->cv_work, NULL);
    pthread_cond_init(&p->cv_done, NULL);
    if (p->n_threads > 0) {
        p->threads = calloc((size_t)p->n_threads, sizeof *p->threads);
        if (!p->threads) {
            free(p);
            return sp_error_set(err, SP_E_NOMEM, "thread pool: out of memory");
        }
    }
    for (int i = 0; i < p->n_threads; i++) {
        worker_arg *wa = malloc(sizeof *wa);
        if (wa) {
            wa->pool = p;
            wa->id = i + 1;
        }
        if (!wa || pthread_create(&p->threads[i], NULL, worker, wa) != 0) {
            free(wa);
            p->n_threads = i;
            sp_pool_free(p);
            return sp_error_set(err, SP_E_NOMEM, "thread pool: cannot start thread %d", i);
        }
    }
    *out = p;
    return SP_OK;
}

void sp_pool_free(sp_pool *p)
{
    if (!p) return;
    pthread_mutex_lock(&p->mu);
    p->quit = 1;
    pthread_cond_broadcast(&p->cv_work);
    pthread_mutex_unlock(&p->mu);
    for (int i = 0; i < p->n_threads; i++) pthread_join(p->threads[i], NULL);
    pthread_mutex_destroy(&p->mu);
    pthread_mutex_destroy(&p->job_mu);
    pthread_cond_destroy(&p->cv_work);
    pthread_cond_destroy(&p->cv_done);
    free(p->threads);
    free(p);
}

int sp_pool_size(const sp_pool *p) { return p ? p->n_threads + 1 : 1; }

void sp_pool_for(sp_pool *p, long n, void (*fn)(void *ctx, long i, int thread_id), void *ctx)
{
    if (n <= 0) return;
    /* Busy (another caller's job, or called from inside one): run here, serially. */
    if (!p || p->n_threads == 0 || n == 1 || pthread_mutex_trylock(&p->job_mu) != 0) {
        for (long i = 0; i < n; i++) fn(ctx, i, 0);
        return;
    }
    pthread_mutex_lock(&p->mu);
    p->fn = fn;
    p->ctx = ctx;
    p->n = n;
    p->next = 0;
    p->active = p->n_threads;
    p->gen++;
    pthread_cond_broadcast(&p->cv_work);
    pthread_mutex_unlock(&p->mu);
    run_items(p, 0);
    pthread_mutex_lock(&p->mu);
    while (p->active > 0) pthread_cond_wait(&p->cv_done, &p->mu);
    pthread_mutex_unlock(&p->mu);
    pthread_mutex_unlock(&p->job_mu);
}
