/* sp_pool_for under concurrent callers: two threads (the query engine and a navigation planner,
 * say) sharing one pool each get every item of their own job run exactly once with their own
 * context, and a job may call sp_pool_for again from inside an item without deadlocking. */
#include <pthread.h>

#include "semsplat/core.h"
#include "test.h"

enum { N_ITEMS = 2000, ROUNDS = 300 };

typedef struct {
    int tag;
    int *slots; /* [N_ITEMS] */
} job;

static void mark(void *ctx, long i, int tid)
{
    job *j = ctx;
    (void)tid;
    j->slots[i] += j->tag; /* each item exactly once: the slot ends at tag */
}

typedef struct {
    sp_pool *pool;
    int tag;
    int bad_rounds;
} caller;

static void *hammer(void *arg)
{
    caller *c = arg;
    int *slots = calloc(N_ITEMS, sizeof *slots);
    for (int r = 0; r < ROUNDS && slots; r++) {
        memset(slots, 0, N_ITEMS * sizeof *slots);
        job j = {c->tag, slots};
        sp_pool_for(c->pool, N_ITEMS, mark, &j);
        int ok = 1;
        for (int i = 0; i < N_ITEMS; i++) ok &= slots[i] == c->tag;
        c->bad_rounds += !ok;
    }
    free(slots);
    return NULL;
}

static void test_two_callers(void)
{
    sp_error err = {0};
    sp_pool *pool = NULL;
    CHECK_OK(sp_pool_create(&pool, 3, &err), &err);
    caller a = {pool, 1, 0}, b = {pool, 1000, 0};
    pthread_t ta, tb;
    CHECK(pthread_create(&ta, NULL, hammer, &a) == 0);
    CHECK(pthread_create(&tb, NULL, hammer, &b) == 0);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    CHECK_MSG(a.bad_rounds == 0, "caller a: %d of %d rounds wrong", a.bad_rounds, ROUNDS);
    CHECK_MSG(b.bad_rounds == 0, "caller b: %d of %d rounds wrong", b.bad_rounds, ROUNDS);
    sp_pool_free(pool);
}

typedef struct {
    sp_pool *pool;
    long sums[64];
} nested;

static void add_one(void *ctx, long i, int tid)
{
    (void)tid;
    __atomic_fetch_add((long *)ctx, i + 1, __ATOMIC_RELAXED);
}

static void outer(void *ctx, long i, int tid)
{
    (void)tid;
    nested *n = ctx;
    sp_pool_for(n->pool, 100, add_one, &n->sums[i]); /* runs serially: the pool is busy */
}

static void test_nested_call(void)
{
    sp_error err = {0};
    sp_pool *pool = NULL;
    CHECK_OK(sp_pool_create(&pool, 2, &err), &err);
    nested n = {pool, {0}};
    sp_pool_for(pool, 64, outer, &n);
    for (int i = 0; i < 64; i++) CHECK_MSG(n.sums[i] == 5050, "item %d: %ld", i, n.sums[i]);
    sp_pool_free(pool);
}

int main(void)
{
    RUN(test_two_callers);
    RUN(test_nested_call);
    return TEST_EXIT();
}
