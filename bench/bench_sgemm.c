/* The blocked SGEMM that stands in for a BLAS (src/compat/sgemm_blocked.c) on the shapes the
 * feature folders use: the PCA covariance (X^T X over 50,000 samples of 512), a map projection
 * (19,200 cells x 512 -> 32) and a square 1024 product; against the plain row loop that was the
 * fallback before (kept here as the baseline). GFLOP/s, median of --reps.
 *   bench_sgemm [--threads N] [--reps N] [--quick] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compat/sgemm_blocked.h"
#include "semsplat/core.h"

/* the previous fallback: C row by row, k outer, j inner (no packing, one thread) */
static void rowloop(int ta, int M, int N, int K, const float *A, int lda, const float *B, int ldb, float *C, int ldc)
{
    for (int i = 0; i < M; i++) {
        float *c = C + (size_t)i * ldc;
        memset(c, 0, sizeof(float) * N);
        for (int k = 0; k < K; k++) {
            float a = ta ? A[(size_t)k * lda + i] : A[(size_t)i * lda + k];
            const float *b = B + (size_t)k * ldb;
            for (int j = 0; j < N; j++) c[j] += a * b[j];
        }
    }
}

static double median(double *t, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && t[j] < t[j - 1]; j--) {
            double x = t[j]; t[j] = t[j - 1]; t[j - 1] = x;
        }
    return t[n / 2];
}

int main(int argc, char **argv)
{
    int threads = 2, reps = 3, quick = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--quick")) quick = 1;
        else {
            fprintf(stderr, "usage: bench_sgemm [--threads N] [--reps N] [--quick]\n");
            return 2;
        }
    }
    if (reps < 1 || reps > 32) reps = 3;
    sp_pool *pool = NULL;
    sp_error err = {0};
    if (sp_pool_create(&pool, threads, &err)) {
        fprintf(stderr, "bench_sgemm: %s\n", err.msg);
        return 1;
    }
    struct { const char *name; int ta, M, N, K; } shapes[] = {
        {"pca_cov", 1, 512, 512, quick ? 5000 : 50000}, {"map_proj", 0, 19200, 32, 512}, {"square", 0, 1024, 1024, 1024}};
    for (int s = 0; s < 3; s++) {
        int ta = shapes[s].ta, M = shapes[s].M, N = shapes[s].N, K = shapes[s].K, lda = ta ? M : K;
        float *A = malloc(sizeof(float) * (size_t)M * K), *B = malloc(sizeof(float) * (size_t)K * N);
        float *C = malloc(sizeof(float) * (size_t)M * N);
        for (size_t i = 0; i < (size_t)M * K; i++) A[i] = (float)((i * 7919) % 1000) / 1000.f - 0.5f;
        for (size_t i = 0; i < (size_t)K * N; i++) B[i] = (float)((i * 104729) % 1000) / 1000.f - 0.5f;
        double t[32], flop = 2.0 * M * N * K;
        for (int mode = 0; mode < 3; mode++) {
            for (int r = 0; r < reps; r++) {
                double t0 = sp_time_now();
                if (mode == 2) rowloop(ta, M, N, K, A, lda, B, N, C, N);
                else sp_sgemm_blocked(mode ? NULL : pool, ta, 0, M, N, K, 1.f, A, lda, B, N, 0.f, C, N);
                t[r] = sp_time_now() - t0;
            }
            const char *what = mode == 0 ? "blocked_pool" : mode == 1 ? "blocked_1thread" : "rowloop_1thread";
            printf("sgemm_%s_%s  %.2f  GFLOP/s  (%d x %d x %d%s, %d threads in the pool)\n", shapes[s].name, what,
                   flop / median(t, reps) / 1e9, M, N, K, ta ? ", A transposed" : "", sp_pool_size(pool));
        }
        free(A); free(B); free(C);
    }
    sp_pool_free(pool);
    return 0;
}
