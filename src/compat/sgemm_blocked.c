/* A cache-blocked, pool-parallel SGEMM (row-major) for builds without a BLAS: C is cut into
 * MC x NC tiles, one pool task each; a task walks K in KC slabs, packs its slab of op(A) into
 * MR-row strips and of op(B) into NR-column strips (contiguous, so the micro-kernel streams
 * both), and an MR x NR micro-kernel keeps its block of C in registers over the slab. Each element
 * of C is summed by one task in one fixed order, so results do not depend on the thread count. */
#include "sgemm_blocked.h"

#include <stdlib.h>
#include <string.h>

enum { MR = 4, NR = 8, MC = 64, NC = 256, KC = 256 };

typedef struct gemm_job {
    int ta, tb, M, N, K, lda, ldb, ldc, tiles_n;
    float alpha, beta;
    const float *A, *B;
    float *C;
    float *pack; /* per pool thread: packed op(A) slab, then packed op(B) slab */
} gemm_job;

enum { PACK_FLOATS = (MC + MR) * KC + (NC + NR) * KC };

/* op(A) rows [i0, i0+mc) x k [k0, k0+kc) -> strips of MR rows, k-major inside a strip, zero-padded */
static void pack_a(const gemm_job *j, int i0, int mc, int k0, int kc, float *ap)
{
    for (int s = 0; s < mc; s += MR)
        for (int k = 0; k < kc; k++)
            for (int r = 0; r < MR; r++) {
                int i = i0 + s + r;
                float v = 0;
                if (s + r < mc)
                    v = j->ta ? j->A[(size_t)(k0 + k) * j->lda + i] : j->A[(size_t)i * j->lda + k0 + k];
                *ap++ = v;
            }
}

/* op(B) k [k0, k0+kc) x cols [j0, j0+nc) -> strips of NR columns, k-major inside a strip */
static void pack_b(const gemm_job *j, int k0, int kc, int j0, int nc, float *bp)
{
    for (int s = 0; s < nc; s += NR)
        for (int k = 0; k < kc; k++) {
            if (!j->tb && s + NR <= nc) {
                memcpy(bp, j->B + (size_t)(k0 + k) * j->ldb + j0 + s, NR * sizeof(float));
                bp += NR;
                continue;
            }
            for (int c = 0; c < NR; c++) {
                int col = j0 + s + c;
                float v = 0;
                if (s + c < nc) v = j->tb ? j->B[(size_t)col * j->ldb + k0 + k] : j->B[(size_t)(k0 + k) * j->ldb + col];
                *bp++ = v;
            }
        }
}

/* acc[MR][NR] = sum over kc of a strip times b strip; C block += alpha * acc (mr x nr valid) */
static void micro(int kc, const float *ap, const float *bp, float alpha, float *c, int ldc, int mr, int nr)
{
    float acc[MR][NR];
    memset(acc, 0, sizeof acc);
    for (int k = 0; k < kc; k++) {
        const float *a = ap + (size_t)k * MR, *b = bp + (size_t)k * NR;
        for (int r = 0; r < MR; r++)
            for (int q = 0; q < NR; q++) acc[r][q] += a[r] * b[q];
    }
    for (int r = 0; r < mr; r++)
        for (int q = 0; q < nr; q++) c[(size_t)r * ldc + q] += alpha * acc[r][q];
}

static void tile_task(void *ctx, long t, int thread_id)
{
    gemm_job *j = ctx;
    int i0 = (int)(t / j->tiles_n) * MC, j0 = (int)(t % j->tiles_n) * NC;
    int mc = j->M - i0 < MC ? j->M - i0 : MC, nc = j->N - j0 < NC ? j->N - j0 : NC;
    for (int i = 0; i < mc; i++) { /* BLAS: beta == 0 writes C without reading it (NaN-safe) */
        float *c = j->C + (size_t)(i0 + i) * j->ldc + j0;
        for (int q = 0; q < nc; q++) c[q] = j->beta == 0.0f ? 0.0f : j->beta * c[q];
    }
    if (j->K <= 0 || j->alpha == 0.0f) return;
    float *ap = j->pack + (size_t)thread_id * PACK_FLOATS, *bp = ap + (MC + MR) * KC;
    for (int k0 = 0; k0 < j->K; k0 += KC) {
        int kc = j->K - k0 < KC ? j->K - k0 : KC;
        pack_a(j, i0, mc, k0, kc, ap);
        pack_b(j, k0, kc, j0, nc, bp);
        for (int s = 0; s < mc; s += MR)
            for (int q = 0; q < nc; q += NR)
                micro(kc, ap + (size_t)s * kc, bp + (size_t)q * kc, j->alpha, j->C + (size_t)(i0 + s) * j->ldc + j0 + q,
                      j->ldc, mc - s < MR ? mc - s : MR, nc - q < NR ? nc - q : NR);
    }
}

int sp_sgemm_blocked(sp_pool *pool, int trans_a, int trans_b, int M, int N, int K, float alpha, const float *A,
                     int lda, const float *B, int ldb, float beta, float *C, int ldc)
{
    if (M <= 0 || N <= 0) return 0;
    if ((double)M * N * K <= 4e6) pool = NULL; /* small products are not worth waking the pool */
    gemm_job j = {trans_a, trans_b, M, N, K, lda, ldb, ldc, (N + NC - 1) / NC, alpha, beta, A, B, C, NULL};
    /* every buffer before any write to C: a failure leaves C as it was */
    j.pack = malloc(sizeof(float) * PACK_FLOATS * (size_t)sp_pool_size(pool));
    if (!j.pack) return -1;
    long tiles = (long)((M + MC - 1) / MC) * j.tiles_n;
    sp_pool_for(pool, tiles, tile_task, &j);
    free(j.pack);
    return 0;
}
