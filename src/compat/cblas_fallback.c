/* cblas_sgemm for builds without OpenBLAS: the blocked SGEMM of sgemm_blocked.c, on a pool of
 * all cores for products large enough to pay for starting one (the BLAS interface carries no
 * pool; a temporary one is safe even when the caller is itself a pool task). */
#include "cblas.h"

#include "sgemm_blocked.h"

void cblas_sgemm(enum CBLAS_ORDER order, enum CBLAS_TRANSPOSE ta, enum CBLAS_TRANSPOSE tb, int M,
                 int N, int K, float alpha, const float *A, int lda, const float *B, int ldb,
                 float beta, float *C, int ldc)
{
    if (order == CblasColMajor) {
        /* C^T = op(B)^T op(A)^T: the same product on the transposed (row-major) views. */
        cblas_sgemm(CblasRowMajor, tb, ta, N, M, K, alpha, B, ldb, A, lda, beta, C, ldc);
        return;
    }
    sp_pool *pool = NULL;
    sp_error err = {0};
    if ((double)M * N * K >= 5e7 && sp_pool_create(&pool, 0, &err)) pool = NULL;
    if (sp_sgemm_blocked(pool, ta != CblasNoTrans, tb != CblasNoTrans, M, N, K, alpha, A, lda, B, ldb, beta, C,
                         ldc) && pool)
        /* no memory for every thread's packing buffers (C untouched): one thread needs one */
        sp_sgemm_blocked(NULL, ta != CblasNoTrans, tb != CblasNoTrans, M, N, K, alpha, A, lda, B, ldb, beta, C, ldc);
    sp_pool_free(pool);
}
