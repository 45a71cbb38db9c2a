/* The blocked SGEMM that stands in for a BLAS (src/compat/cblas_fallback.c), and that the tests
 * and benchmarks call directly on any build. Row-major: C[M][N] = alpha op(A) op(B) + beta C,
 * op(A) = A [M][K] (lda) or, trans_a, A^T of A [K][M]; likewise B. beta == 0 never reads C.
 * pool: NULL runs on the calling thread (never call it from a task of the same pool). Returns 0,
 * or -1 when the packing buffers could not be allocated (C is then untouched). */
#ifndef SP_COMPAT_SGEMM_BLOCKED_H
#define SP_COMPAT_SGEMM_BLOCKED_H

#include "semsplat/core.h"

int sp_sgemm_blocked(sp_pool *pool, int trans_a, int trans_b, int M, int N, int K, float alpha, const float *A,
                     int lda, const float *B, int ldb, float beta, float *C, int ldc);

#endif
