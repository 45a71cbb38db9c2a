/* The blocked SGEMM (src/compat/sgemm_blocked.c, the stand-in for a BLAS) against a naive
 * double-precision product: every transpose combination, ragged sizes around the tile edges,
 * leading dimensions wider than the rows, alpha/beta, beta = 0 over NaN (never read), K = 0, and
 * the same bits with and without a thread pool. */
#include <stdlib.h>

#include "compat/sgemm_blocked.h"
#include "test.h"

static test_rng rng = {2024};

static double ref_at(const float *X, int ld, int trans, int i, int j)
{
    return trans ? X[(size_t)j * ld + i] : X[(size_t)i * ld + j];
}

static void one(sp_pool *pool, int ta, int tb, int M, int N, int K, float alpha, float beta)
{
    int lda = (ta ? M : K) + 3, ldb = (tb ? K : N) + 1, ldc = N + 2;
    size_t na = (size_t)(ta ? K : M) * lda + 1, nb = (size_t)(tb ? N : K) * ldb + 1, nc = (size_t)M * ldc;
    float *A = malloc(sizeof(float) * na), *B = malloc(sizeof(float) * nb);
    float *C = malloc(sizeof(float) * nc), *C1 = malloc(sizeof(float) * nc), *C0 = malloc(sizeof(float) * nc);
    for (size_t i = 0; i < na; i++) A[i] = (float)test_range(&rng, -1, 1);
    for (size_t i = 0; i < nb; i++) B[i] = (float)test_range(&rng, -1, 1);
    for (size_t i = 0; i < nc; i++) C0[i] = beta == 0 ? NAN : (float)test_range(&rng, -1, 1);
    memcpy(C, C0, sizeof(float) * nc);
    memcpy(C1, C0, sizeof(float) * nc);
    CHECK(sp_sgemm_blocked(pool, ta, tb, M, N, K, alpha, A, lda, B, ldb, beta, C, ldc) == 0);
    CHECK(sp_sgemm_blocked(NULL, ta, tb, M, N, K, alpha, A, lda, B, ldb, beta, C1, ldc) == 0);
    double worst = 0;
    int same = 1;
    for (int i = 0; i < M; i++)
        for (int j = 0; j < N; j++) {
            double s = 0;
            for (int k = 0; k < K; k++) s += ref_at(A, lda, ta, i, k) * ref_at(B, ldb, tb, k, j);
            double want = alpha * s + (beta == 0 ? 0 : beta * (double)C0[(size_t)i * ldc + j]);
            float got = C[(size_t)i * ldc + j];
            worst = isfinite(got) ? fmax(worst, fabs(got - want) / (1 + fabs(want))) : 1e9;
            same &= memcmp(&got, &C1[(size_t)i * ldc + j], sizeof got) == 0;
        }
    /* the padding columns past N are never touched */
    for (int i = 0; i < M; i++)
        for (int j = N; j < ldc; j++) {
            float a = C[(size_t)i * ldc + j], b = C0[(size_t)i * ldc + j];
            same &= memcmp(&a, &b, sizeof a) == 0;
        }
    CHECK_MSG(worst < 2e-6 * sqrt(K + 1.0) + 1e-6, "sgemm %dx%dx%d ta=%d tb=%d: rel err %g", M, N, K, ta, tb, worst);
    CHECK_MSG(same, "sgemm %dx%dx%d ta=%d tb=%d: pool and serial differ, or padding written", M, N, K, ta, tb);
    free(A); free(B); free(C); free(C1); free(C0);
}

static void test_shapes(void)
{
    sp_pool *pool = NULL;
    sp_error err = {0};
    CHECK_OK(sp_pool_create(&pool, 3, &err), &err);
    const int sizes[][3] = {{1, 1, 1}, {1, 9, 1}, {7, 1, 13}, {4, 8, 256}, {5, 9, 257},
                            {67, 259, 300}, {130, 70, 513}, {64, 256, 256}, {3, 300, 0}};
    for (int s = 0; s < 9; s++)
        for (int t = 0; t < 4; t++) {
            int M = sizes[s][0], N = sizes[s][1], K = sizes[s][2];
            one(pool, t & 1, t >> 1, M, N, K, 1.0f, 0.0f);
            one(pool, t & 1, t >> 1, M, N, K, -0.5f, 1.0f);
            if (s == 5) one(pool, t & 1, t >> 1, M, N, K, 2.0f, 0.25f);
        }
    /* a large one with the pool doing the work: the PCA's shape, C = X^T X */
    one(pool, 1, 0, 96, 96, 3000, 1.0f, 1.0f);
    sp_pool_free(pool);
}

int main(void)
{
    RUN(test_shapes);
    return TEST_EXIT();
}
