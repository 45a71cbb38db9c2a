/* Private to src/clip/cuda: the GPU model (weights in fp32 and fp16, a scratch arena, the
 * cuBLASLt handle and its cached matmul plans) and the pieces the towers are built from:
 * linear layers with fused bias (+ residual) epilogues, fused attention, LayerNorm and the
 * elementwise kernels. One templated path serves fp32 (T = float) and fp16 (T = __half). */
#ifndef SP_CLIP_GPU_CUH
#define SP_CLIP_GPU_CUH

#include <stddef.h>
#include <stdint.h>

#include <cublasLt.h>
#include <cublas_v2.h>
#include <cuda_fp16.h>
#include <cuda_runtime.h>

#include "device/cuda/device_cuda.h"
extern "C" {
#include "../clip_internal.h"
}

struct gpu_layer {
    size_t ln1_w, ln1_b, qkv_w, qkv_b, o_w, o_b, ln2_w, ln2_b, fc1_w, fc1_b, fc2_w, fc2_b;
};

/* One cached cuBLASLt matmul (descriptors + the heuristic's algorithm) per shape. */
struct lt_plan {
    int used, bad; /* bad: no algorithm; the plain cuBLAS path runs instead */
    int M, N, K, ldx, ldy, half, epi, acc, align;
    cublasLtMatmulDesc_t op;
    cublasLtMatrixLayout_t a, b, c;
    cublasLtMatmulAlgo_t algo;
};
enum { LT_PLANS = 48, PROF_EVENTS = 512, MLP_SLAB_ROWS = 4096, BLOCK_SLAB_ROWS = 6400 };

/* Host pinned staging for uploads: two slots so the copy of one overlaps filling the other. */
struct pin_stage {
    char *buf[2];
    size_t cap;
    cudaEvent_t done[2];
};

/* The stream and cuBLAS handle are the device's (device/cuda/device_cuda.h); weights and scratch
 * are device allocations, so they count in sp_device_peak_bytes. */
struct sp_clip_gpu {
    sp_device *dev;
    cublasHandle_t blas;
    cublasLtHandle_t lt;
    cudaStream_t stream;
    float *w32;      /* blob + fused QKV weights, fp32 */
    __half *w16;     /* the same in fp16 (made on first fp16 use) */
    size_t n_floats; /* elements in w32 */
    gpu_layer *text, *vision;
    void *arena;
    size_t arena_cap;
    void *lt_ws;
    size_t lt_ws_size;
    lt_plan plans[LT_PLANS];
    int plan_next;
    pin_stage pin;
    sp_device_scratch io_in, io_out; /* the host entry points' inputs and outputs on the device */
    sp_device_scratch pos;           /* position embeddings of the last grid size (pos_gh x pos_gw) */
    int pos_gh, pos_gw;
    int io_half;                     /* io_in holds fp16 pixels (the last vision call was fp16) */
    sp_device_scratch dense[8];      /* the dense pipeline's buffers (dense_cuda.cu) */
    int flags; /* CLIP_GPU_* (clip_internal.h) */
    struct {   /* CLIP_GPU_PROFILE: ev[0] at the start, ev[i] after a stage of kind stage[i] */
        cudaEvent_t ev[PROF_EVENTS];
        int stage[PROF_EVENTS], n, made, forwards;
        double ms[CLIP_STAGES];
    } prof;
};

/* stage timing (CLIP_GPU_PROFILE): clip_prof_begin before a forward, clip_prof_mark after each
 * stage, clip_prof_collect after the stream has synchronised */
void clip_prof_begin(sp_clip_gpu *g);
void clip_prof_mark(sp_clip_gpu *g, int stage);
void clip_prof_collect(sp_clip_gpu *g);

#define CK(call, what)                                                                          \
    do {                                                                                        \
        cudaError_t e_ = (call);                                                                \
        if (e_ != cudaSuccess)                                                                  \
            return sp_error_set(err, SP_E_DEVICE, "CLIP GPU: %s: %s", what, cudaGetErrorString(e_)); \
    } while (0)
#define CB(call, what)                                                                          \
    do {                                                                                        \
        cublasStatus_t s_ = (call);                                                             \
        if (s_ != CUBLAS_STATUS_SUCCESS)                                                        \
            return sp_error_set(err, SP_E_DEVICE, "CLIP GPU: cuBLAS %s failed (%d)", what, (int)s_); \
    } while (0)

template <typename T> struct dtype_of;
template <> struct dtype_of<float> { static const cudaDataType_t v = CUDA_R_32F; };
template <> struct dtype_of<__half> { static const cudaDataType_t v = CUDA_R_16F; };

/* ---- scratch ---------------------------------------------------------------------------------- */

/* A bump allocator over the arena, grown (and the call retried) when too small. */
struct arena {
    sp_clip_gpu *g;
    size_t need;
    int fits;
};

template <typename T> static inline T *take(arena *a, size_t count)
{
    size_t bytes = (count * sizeof(T) + 255) & ~(size_t)255, at = a->need;
    a->need += bytes;
    if (a->need > a->g->arena_cap) {
        a->fits = 0;
        return NULL;
    }
    return (T *)((char *)a->g->arena + at);
}

int clip_arena_grow(sp_clip_gpu *g, size_t need, sp_error *err);
/* Host -> device through the pinned staging (pool threads fill it, the copy engine drains it);
 * the _half one converts count floats to fp16 on the way. */
int clip_upload(sp_clip *c, void *dst, const void *src, size_t bytes, sp_error *err);
int clip_upload_half(sp_clip *c, __half *dst, const float *src, size_t count, sp_error *err);

/* ---- linear layers (gemm.cu) -------------------------------------------------------------------- */

template <typename T> struct ctx {
    sp_clip *c;
    sp_clip_gpu *g;
    const T *W; /* weights in this precision */
    sp_error *err;
};

/* Y[M][N] (contiguous rows) = X[M][K] (row stride ldx) W[N][K]^T + bias (NULL: none)
 * (+ Y when accumulate: the residual connection). */
template <typename T>
int lin(ctx<T> &x, const T *X, int ldx, int M, int K, const T *W, int N, const T *bias, T *Y, int accumulate);
void clip_lt_free(sp_clip_gpu *g);

/* ---- attention (attention.cu, flash.cu) --------------------------------------------------------- */

/* Multi-head attention of B sequences of Tn tokens read straight from the fused projection
 * qkv [B*Tn][3w] (q | k | v, biases added): out [B*Tn][w] = softmax(q k^T / sqrt(d)) v per head
 * (k = q when qq: ClearCLIP), causal masks keys after the query. Tensor-core flash attention
 * for fp16 and head widths 16/32/64; otherwise cuBLAS products around a softmax, with the
 * batch's pointer tables in ptrs (attention_ptr_count entries) and scores in s. */
template <typename T>
int attention(ctx<T> &x, const T *qkv, int B, int Tn, int H, int w, int causal, int qq, T *out, T *s,
              void **ptrs);
size_t attention_ptr_count(int B, int H);
/* 1 when the fused kernel takes this attention (then no score buffer is needed) */
int attention_fused_ok(const sp_clip_gpu *g, int half, int B, int w, int H);
size_t attention_score_count(int B, int H, int Tn, int fused);
/* The flash kernels alone (fp16, d in 16/32/64, w % 8 == 0, B <= 65535): one block per head and
 * sequence with K and V resident in shared memory when they fit, else (or mode FLASH_TILED)
 * 64-query blocks streaming K/V tiles; mode FLASH_RESIDENT * q + n (q >= 1, n = 1..8) forces the
 * resident kernel with q blocks of n warps per head (benchmarks, tests), FLASH_QSMEM + that with
 * the query rows staged through shared memory too; 0 when launched, 1 when it does not apply. */
enum { FLASH_AUTO = 0, FLASH_TILED = 1, FLASH_RESIDENT = 100, FLASH_QSMEM = 1000 };
int flash_attention(const __half *qkv, int B, int Tn, int H, int w, int causal, int qq, __half *out, int mode,
                    cudaStream_t st);

/* ---- elementwise (kernels.cu) --------------------------------------------------------------------- */

/* LayerNorm of rows: output row r reads input row (r / group) * stride + offset + r % group, or
 * rows[r] when rows is not NULL. In place allowed. */
struct ln_rows {
    const int32_t *rows;
    int group, stride, offset;
};
static inline ln_rows ln_plain(void) { return ln_rows{NULL, 1, 1, 0}; }

template <typename T>
void launch_layernorm(const T *x, T *y, int n_rows, int w, const T *g, const T *b, float eps, ln_rows map,
                      cudaStream_t st);
/* y = act(y + bias) over [rows][n] (bias NULL: none; act 0 none, 1 quick_gelu, 2 erf GELU). */
template <typename T> void launch_bias_act(T *y, long rows, int n, const T *bias, int act, cudaStream_t st);
template <typename T>
void launch_embed_text(const int32_t *ids, const T *tok, const T *pos, T *x, int rows, int L, int w, cudaStream_t st);
template <typename T>
void launch_im2col(const void *px, int px_half, T *cols, int n, int H, int W, int p, cudaStream_t st);
template <typename T>
void launch_assemble(const T *pe, const T *cls, const float *pos, T *x, int n, int Tn, int w, cudaStream_t st);
template <typename T> void launch_softmax(T *s, long rows, int Tn, float scale, int causal, cudaStream_t st);
template <typename T> void launch_to_float(const T *x, float *y, long n, cudaStream_t st);
void launch_f32_to_f16(const float *x, __half *y, long n, cudaStream_t st);

/* ---- towers (clip_cuda.cu), used by the dense pipeline ---------------------------------------------- */

/* The vision tower on device pixels [n][3][H][W] (fp32, or fp16 when px_half) -> device out
 * [n_out][P] float (not normalised; n_out = n for pooled, n * (H/p) * (W/p) for the dense heads);
 * its scratch is the arena. */
int clip_vision_device(sp_clip *c, const void *d_px, int px_half, int n, int H, int W, clip_out_kind kind,
                       float *d_out, sp_error *err);

#endif
