/* The lexical text encoder's start-up and query times: opening WordNet (sp_lexicon_open),
 * preparing a vocabulary (the house's 25 class names, or the bookstore's 20), and matching the
 * phrasing table's queries (tests/semantic/phrases_<world>.json), one thread, then two threads
 * sharing one vocabulary. Targets (issue 17): start-up under 0.5 s, a query under 20 ms.
 * Usage: bench_lexical [house|bookstore] [repeats] */
#include <cjson/cJSON.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "semsplat/io.h"
#include "semsplat/semantic.h"

#ifndef SP_SOURCE_DIR
#define SP_SOURCE_DIR "."
#endif

typedef struct {
    const sp_lex_vocab *v;
    const char *const *texts;
    int n, repeats, failed;
    double max_ms, max_cpu_ms;
    double *wall_ms; /* [n * repeats] or NULL */
} worker;

static double thread_cpu_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void *run(void *arg)
{
    worker *w = arg;
    sp_lex_result *res = malloc(sizeof *res);
    sp_error err = {0};
    for (int r = 0; r < w->repeats && res; r++)
        for (int i = 0; i < w->n; i++) {
            double t0 = sp_time_now(), c0 = thread_cpu_s();
            if (sp_lex_match(w->v, w->texts[i], res, &err)) w->failed++;
            double ms = (sp_time_now() - t0) * 1e3, cpu = (thread_cpu_s() - c0) * 1e3;
            if (ms > w->max_ms) w->max_ms = ms;
            if (cpu > w->max_cpu_ms) w->max_cpu_ms = cpu;
            if (w->wall_ms) w->wall_ms[r * w->n + i] = ms;
        }
    free(res);
    return NULL;
}

int main(int argc, char **argv)
{
    const char *world = argc > 1 ? argv[1] : "house";
    int repeats = argc > 2 ? atoi(argv[2]) : 5;
    if (repeats < 1) repeats = 1;
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/semantic/phrases_%s.json", SP_SOURCE_DIR, world);
    sp_error err = {0};
    cJSON *js = NULL;
    if (sp_json_read_file(path, &js, &err)) {
        fprintf(stderr, "bench_lexical: %s\n", err.msg);
        return 1;
    }
    const char *classes[SP_LEX_MAX_CLASSES], *texts[512];
    int nc = 0, nt = 0;
    const cJSON *it;
    cJSON_ArrayForEach(it, cJSON_GetObjectItem(js, "classes")) classes[nc++] = it->valuestring;
    cJSON_ArrayForEach(it, cJSON_GetObjectItem(js, "phrases"))
        if (nt < 512) texts[nt++] = cJSON_GetObjectItem(it, "text")->valuestring;

    double t0 = sp_time_now();
    sp_lexicon *lx = NULL;
    if (sp_lexicon_open(&lx, NULL, &err)) {
        fprintf(stderr, "bench_lexical: %s\n", err.msg);
        return 1;
    }
    double t1 = sp_time_now();
    sp_lex_vocab *v = NULL;
    if (sp_lex_vocab_create(&v, lx, classes, nc, NULL, &err)) {
        fprintf(stderr, "bench_lexical: %s\n", err.msg);
        return 1;
    }
    double t2 = sp_time_now();
    printf("lexical_open      %8.2f ms  (WordNet 3.0 at %s)\n", (t1 - t0) * 1e3, SP_LEX_DEFAULT_WORDNET);
    printf("lexical_vocab     %8.2f ms  (%d class names of %s)\n", (t2 - t1) * 1e3, nc, world);
    printf("lexical_startup   %8.2f ms  (open + vocabulary; target < 500)\n", (t2 - t0) * 1e3);

    worker one = {v, texts, nt, repeats, 0, 0, 0, calloc((size_t)nt * repeats, sizeof(double))};
    double t3 = sp_time_now();
    run(&one);
    double t4 = sp_time_now();
    double per = (t4 - t3) * 1e3 / (nt * repeats);
    printf("lexical_query     %8.3f ms  (mean of %d queries x %d, 1 thread; target < 20)\n", per, nt, repeats);
    if (one.wall_ms) {
        size_t m = (size_t)nt * repeats;
        qsort(one.wall_ms, m, sizeof(double), cmp_double);
        printf("lexical_query_p50 %8.3f ms  (median)\n", one.wall_ms[m / 2]);
        printf("lexical_query_p99 %8.3f ms  (99th percentile)\n", one.wall_ms[(size_t)(0.99 * (double)(m - 1))]);
    }
    printf("lexical_query_max %8.3f ms  (slowest single query, wall: includes waits for the CPU)\n", one.max_ms);
    printf("lexical_query_cpu_max %4.3f ms  (slowest single query, its thread's CPU time)\n", one.max_cpu_ms);
    free(one.wall_ms);

    worker two[2] = {{v, texts, nt, repeats, 0, 0, 0, NULL}, {v, texts, nt, repeats, 0, 0, 0, NULL}};
    pthread_t th[2];
    double t5 = sp_time_now();
    for (int i = 0; i < 2; i++) pthread_create(&th[i], NULL, run, &two[i]);
    for (int i = 0; i < 2; i++) pthread_join(th[i], NULL);
    double t6 = sp_time_now();
    printf("lexical_query_2t  %8.3f ms  (wall per query, 2 threads sharing one vocabulary)\n",
           (t6 - t5) * 1e3 / (2.0 * nt * repeats));
    int failed = one.failed + two[0].failed + two[1].failed;
    sp_lex_vocab_free(v);
    sp_lexicon_free(lx);
    cJSON_Delete(js);
    if (failed) fprintf(stderr, "bench_lexical: %d queries failed\n", failed);
    return failed ? 1 : 0;
}
