/* CLIP's matrix products. Linear layers go through cuBLASLt with the bias (and, with beta = 1
 * into the residual stream, the residual add) fused into the GEMM's epilogue; the matmul
 * descriptors and the heuristic's algorithm are cached per shape, since asking for them costs
 * more host time than a small product takes on the GPU. Where cuBLASLt offers no algorithm (or
 * CLIP_GPU_NO_LT is set, for comparisons) the plain cuBLAS product runs, followed by a bias
 * kernel. Accumulation is fp32 in both precisions (CUBLAS_COMPUTE_32F: no TF32 for fp32). */
#include <string.h>

#include "clip_gpu.cuh"

static unsigned align_of(const void *p)
{
    uintptr_t a = (uintptr_t)p;
    unsigned al = 256;
    while (al > 1 && a % al) al >>= 1;
    return al;
}

static void plan_destroy(lt_plan *p)
{
    if (p->op) cublasLtMatmulDescDestroy(p->op);
    if (p->a) cublasLtMatrixLayoutDestroy(p->a);
    if (p->b) cublasLtMatrixLayoutDestroy(p->b);
    if (p->c) cublasLtMatrixLayoutDestroy(p->c);
    memset(p, 0, sizeof *p);
}

void clip_lt_free(sp_clip_gpu *g)
{
    for (int i = 0; i < LT_PLANS; i++)
        if (g->plans[i].used) plan_destroy(&g->plans[i]);
    if (g->lt) cublasLtDestroy(g->lt);
    g->lt = NULL;
}

/* Row-major Y[M][N] = X[M][K] W[N][K]^T is the column-major Y^T (N x M) = op_T(W) X^T: A = W
 * (K x N, ld K, transposed), B = X (K x M, ld ldx), C = D = Y (N x M, ld N); the bias runs along
 * D's rows (N), as cuBLASLt broadcasts it. */
static int plan_make(sp_clip_gpu *g, lt_plan *p, int half, int M, int N, int K, int ldx, int epi, int acc,
                     unsigned align)
{
    cudaDataType_t dt = half ? CUDA_R_16F : CUDA_R_32F;
    cublasOperation_t ta = CUBLAS_OP_T, tb = CUBLAS_OP_N;
    cublasLtEpilogue_t e = epi ? CUBLASLT_EPILOGUE_BIAS : CUBLASLT_EPILOGUE_DEFAULT;
    memset(p, 0, sizeof *p);
    p->used = 1;
    p->M = M; p->N = N; p->K = K; p->ldx = ldx; p->half = half; p->epi = epi; p->acc = acc; p->align = (int)align;
    cublasLtMatmulPreference_t pref = NULL;
    cublasLtMatmulHeuristicResult_t res;
    int n_res = 0;
    uint64_t ws = g->lt_ws_size;
    uint32_t al = align;
    if (cublasLtMatmulDescCreate(&p->op, CUBLAS_COMPUTE_32F, CUDA_R_32F) ||
        cublasLtMatmulDescSetAttribute(p->op, CUBLASLT_MATMUL_DESC_TRANSA, &ta, sizeof ta) ||
        cublasLtMatmulDescSetAttribute(p->op, CUBLASLT_MATMUL_DESC_TRANSB, &tb, sizeof tb) ||
        cublasLtMatmulDescSetAttribute(p->op, CUBLASLT_MATMUL_DESC_EPILOGUE, &e, sizeof e) ||
        cublasLtMatrixLayoutCreate(&p->a, dt, K, N, K) || cublasLtMatrixLayoutCreate(&p->b, dt, K, M, ldx) ||
        cublasLtMatrixLayoutCreate(&p->c, dt, N, M, N) || cublasLtMatmulPreferenceCreate(&pref) ||
        cublasLtMatmulPreferenceSetAttribute(pref, CUBLASLT_MATMUL_PREF_MAX_WORKSPACE_BYTES, &ws, sizeof ws) ||
        cublasLtMatmulPreferenceSetAttribute(pref, CUBLASLT_MATMUL_PREF_MIN_ALIGNMENT_A_BYTES, &al, sizeof al) ||
        cublasLtMatmulPreferenceSetAttribute(pref, CUBLASLT_MATMUL_PREF_MIN_ALIGNMENT_B_BYTES, &al, sizeof al) ||
        cublasLtMatmulPreferenceSetAttribute(pref, CUBLASLT_MATMUL_PREF_MIN_ALIGNMENT_C_BYTES, &al, sizeof al) ||
        cublasLtMatmulPreferenceSetAttribute(pref, CUBLASLT_MATMUL_PREF_MIN_ALIGNMENT_D_BYTES, &al, sizeof al) ||
        cublasLtMatmulAlgoGetHeuristic(g->lt, p->op, p->a, p->b, p->c, p->c, pref, 1, &res, &n_res) || n_res < 1) {
        p->bad = 1;
    } else {
        p->algo = res.algo;
    }
    if (pref) cublasLtMatmulPreferenceDestroy(pref);
    return p->bad ? -1 : 0;
}

static lt_plan *plan_find(sp_clip_gpu *g, int half, int M, int N, int K, int ldx, int epi, int acc, unsigned align)
{
    for (int i = 0; i < LT_PLANS; i++) {
        lt_plan *p = &g->plans[i];
        if (p->used && p->M == M && p->N == N && p->K == K && p->ldx == ldx && p->half == half && p->epi == epi &&
            p->acc == acc && p->align == (int)align)
            return p;
    }
    lt_plan *p = &g->plans[g->plan_next];
    g->plan_next = (g->plan_next + 1) % LT_PLANS;
    if (p->used) plan_destroy(p);
    plan_make(g, p, half, M, N, K, ldx, epi, acc, align);
    return p;
}

/* 0 when cuBLASLt ran the product, 1 when the caller must fall back */
static int lt_run(sp_clip_gpu *g, int half, const void *X, int ldx, int M, int K, const void *W, int N,
                  const void *bias, void *Y, int acc)
{
    if (!g->lt || (g->flags & CLIP_GPU_NO_LT)) return 1;
    unsigned al = align_of(X);
    unsigned a2 = align_of(W), a3 = align_of(Y);
    if (a2 < al) al = a2;
    if (a3 < al) al = a3;
    lt_plan *p = plan_find(g, half, M, N, K, ldx, bias != NULL, acc, al);
    if (p->bad) return 1;
    if (bias && cublasLtMatmulDescSetAttribute(p->op, CUBLASLT_MATMUL_DESC_BIAS_POINTER, &bias, sizeof bias))
        return 1;
    float one = 1.f, beta = acc ? 1.f : 0.f;
    cublasStatus_t s = cublasLtMatmul(g->lt, p->op, &one, W, p->a, X, p->b, &beta, Y, p->c, Y, p->c, &p->algo,
                                      g->lt_ws, g->lt_ws_size, g->stream);
    if (s != CUBLAS_STATUS_SUCCESS) {
        p->bad = 1; /* not again for this shape */
        return 1;
    }
    return 0;
}

template <typename T>
int lin(ctx<T> &x, const T *X, int ldx, int M, int K, const T *W, int N, const T *bias, T *Y, int accumulate)
{
    sp_error *err = x.err;
    if (M <= 0) return 0;
    if (!lt_run(x.g, sizeof(T) == 2, X, ldx, M, K, W, N, bias, Y, accumulate)) return 0;
    float one = 1.f, beta = accumulate ? 1.f : 0.f;
    CB(cublasGemmEx(x.g->blas, CUBLAS_OP_T, CUBLAS_OP_N, N, M, K, &one, W, dtype_of<T>::v, K, X, dtype_of<T>::v,
                    ldx, &beta, Y, dtype_of<T>::v, N, CUBLAS_COMPUTE_32F, CUBLAS_GEMM_DEFAULT),
       "gemm");
    if (bias) launch_bias_act<T>(Y, M, N, bias, 0, x.g->stream);
    return 0;
}

template int lin<float>(ctx<float> &, const float *, int, int, int, const float *, int, const float *, float *, int);
template int lin<__half>(ctx<__half> &, const __half *, int, int, int, const __half *, int, const __half *, __half *,
                         int);

/* ---- attention -------------------------------------------------------------------------------------- */

size_t attention_ptr_count(int B, int H) { return 5 * (size_t)B * H; }

/* fused: 1 when the flash kernel will run (no score buffer needed) */
size_t attention_score_count(int B, int H, int Tn, int fused) { return fused ? 1 : (size_t)B * H * Tn * Tn; }

/* The unfused path: per (sequence, head) pointers into qkv, the scores and the output, one
 * batched product for the scores, a softmax, one for the values. */
template <typename T>
static int attention_batched(ctx<T> &x, const T *qkv, int B, int Tn, int H, int w, int causal, int qq, T *out,
                             T *s, void **ptrs)
{
    sp_error *err = x.err;
    int d = w / H, n = B * H;
    size_t ld = 3 * (size_t)w;
    void **hp = (void **)malloc(attention_ptr_count(B, H) * sizeof(void *));
    if (!hp) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (int b = 0; b < B; b++)
        for (int h = 0; h < H; h++) {
            int i = b * H + h;
            const T *q = qkv + (size_t)b * Tn * ld + (size_t)h * d;
            hp[i] = (void *)(qq ? q : q + w);             /* keys */
            hp[n + i] = (void *)q;                         /* queries */
            hp[2 * n + i] = (void *)(s + (size_t)i * Tn * Tn); /* scores [query][key] */
            hp[3 * n + i] = (void *)(q + 2 * (size_t)w);   /* values */
            hp[4 * n + i] = (void *)(out + (size_t)b * Tn * w + (size_t)h * d);
        }
    cudaError_t ce = cudaMemcpyAsync(ptrs, hp, attention_ptr_count(B, H) * sizeof(void *), cudaMemcpyHostToDevice,
                                     x.g->stream);
    free(hp); /* a pageable copy has left the buffer when the call returns */
    CK(ce, "attention pointers");
    float one = 1.f, zero = 0.f;
    cudaDataType_t dt = dtype_of<T>::v;
    /* column-major: S^T (keys x queries) = K^T Q, then O^T (d x queries) = V P^T */
    CB(cublasGemmBatchedEx(x.g->blas, CUBLAS_OP_T, CUBLAS_OP_N, Tn, Tn, d, &one, (const void *const *)ptrs, dt, (int)ld,
                           (const void *const *)(ptrs + n), dt, (int)ld, &zero, ptrs + 2 * n, dt, Tn, n,
                           CUBLAS_COMPUTE_32F, CUBLAS_GEMM_DEFAULT),
       "attention scores");
    launch_softmax<T>(s, (long)n * Tn, Tn, 1.f / sqrtf((float)d), causal, x.g->stream);
    CB(cublasGemmBatchedEx(x.g->blas, CUBLAS_OP_N, CUBLAS_OP_N, d, Tn, Tn, &one, (const void *const *)(ptrs + 3 * n), dt,
                           (int)ld, (const void *const *)(ptrs + 2 * n), dt, Tn, &zero, ptrs + 4 * n, dt, w, n,
                           CUBLAS_COMPUTE_32F, CUBLAS_GEMM_DEFAULT),
       "attention values");
    return 0;
}

int attention_fused_ok(const sp_clip_gpu *g, int half, int B, int w, int H)
{
    int d = H > 0 && w % H == 0 ? w / H : 0;
    return half && !(g->flags & CLIP_GPU_NO_FLASH) && (d == 16 || d == 32 || d == 64) && w % 8 == 0 && B >= 1 &&
           B <= 65535;
}

template <typename T>
int attention(ctx<T> &x, const T *qkv, int B, int Tn, int H, int w, int causal, int qq, T *out, T *s, void **ptrs)
{
    /* the same decision sized the scratch (attention_score_count): the fused kernel or the
     * batched products, never a fall-back onto a score buffer that was not reserved */
    if (attention_fused_ok(x.g, sizeof(T) == 2, B, w, H)) {
        if (flash_attention((const __half *)qkv, B, Tn, H, w, causal, qq, (__half *)out,
                            (x.g->flags & CLIP_GPU_FLASH_V1) != 0, x.g->stream)) {
            sp_error *err = x.err;
            return sp_error_set(err, SP_E_DEVICE, "CLIP GPU: fused attention refused %d x %d heads", B, H);
        }
        return 0;
    }
    return attention_batched(x, qkv, B, Tn, H, w, causal, qq, out, s, ptrs);
}

template int attention<float>(ctx<float> &, const float *, int, int, int, int, int, int, float *, float *, void **);
template int attention<__half>(ctx<__half> &, const __half *, int, int, int, int, int, int, __half *, __half *,
                               void **);
