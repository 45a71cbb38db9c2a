/* A plain blocked SGEMM for builds without OpenBLAS. Correct, cache-blocked, single-threaded:
 * enough for PCA and for the CPU CLIP path on machines where the GPU does the heavy work. */
#include "cblas.h"

#include <stdlib.h>

/* Element (i, j) of op(X) for a row-major X with leading dimension ld. */
static inline float at(const float *X, int ld, int trans, int i, int j)
{
    return trans ? X[(size_t)j * ld + i] : X[(size_t)i * ld + j];
}

void cblas_sgemm(enum CBLAS_ORDER order, enum CBLAS_TRANSPOSE ta, enum CBLAS_TRANSPOSE tb, int M,
                 int N, int K, float alpha, const float *A, int lda, const float *B, int ldb,
                 float beta, float *C, int ldc)
{
    if (order == CblasColMajor) {
        /* C^T = op(B)^T op(A)^T: the same product on the transposed (row-major) views. */
        cblas_sgemm(CblasRowMajor, tb, ta, N, M, K, alpha, B, ldb, A, lda, beta, C, ldc);
        return;
    }
    int tA = ta != CblasNoTrans, tB = tb != CblasNoTrans;
    /* BLAS semantics: with beta == 0, C is written without being read (it may hold NaN). */
    for (int i = 0; i < M; i++)
        for (int j = 0; j < N; j++)
            C[(size_t)i * ldc + j] = beta == 0.0f ? 0.0f : beta * C[(size_t)i * ldc + j];
    enum { BK = 64, BJ = 256 };
    float *row = malloc(sizeof(float) * BJ);
    if (!row) return;
    for (int k0 = 0; k0 < K; k0 += BK) {
        int k1 = k0 + BK < K ? k0 + BK : K;
        for (int j0 = 0; j0 < N; j0 += BJ) {
            int j1 = j0 + BJ < N ? j0 + BJ : N;
            for (int i = 0; i < M; i++) {
                for (int j = j0; j < j1; j++) row[j - j0] = 0;
                for (int k = k0; k < k1; k++) {
                    float a = alpha * at(A, lda, tA, i, k);
                    if (a == 0) continue;
                    if (!tB) {
                        const float *b = B + (size_t)k * ldb;
                        for (int j = j0; j < j1; j++) row[j - j0] += a * b[j];
                    } else {
                        for (int j = j0; j < j1; j++) row[j - j0] += a * B[(size_t)j * ldb + k];
                    }
                }
                float *c = C + (size_t)i * ldc;
                for (int j = j0; j < j1; j++) c[j] += row[j - j0];
            }
        }
    }
    free(row);
}
