/* CLIP towers on the GPU: cuBLAS for every matrix product (fused QKV projection, strided-batched
 * attention products per head), our kernels for LayerNorm, bias + activation, softmax, layout
 * permutes and gathers. One templated path serves fp32 and fp16 (weights and activations in
 * half, LayerNorm/softmax statistics and GEMM accumulation in fp32). Mirrors src/clip/cpu.c. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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

/* The stream and cuBLAS handle are the device's (device/cuda/device_cuda.h); weights and scratch
 * are device allocations, so they count in sp_device_peak_bytes. */
struct sp_clip_gpu {
    sp_device *dev;
    cublasHandle_t blas;
    cudaStream_t stream;
    float *w32;      /* blob + fused QKV weights, fp32 */
    __half *w16;     /* the same in fp16 (made on first fp16 use) */
    size_t n_floats; /* elements in w32 */
    gpu_layer *text, *vision;
    void *arena;
    size_t arena_cap, arena_used;
};

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

/* ---- element access for both precisions ----------------------------------------------------- */

__device__ __forceinline__ float ld(const float *p) { return *p; }
__device__ __forceinline__ float ld(const __half *p) { return __half2float(*p); }
__device__ __forceinline__ void st(float *p, float v) { *p = v; }
__device__ __forceinline__ void st(__half *p, float v) { *p = __float2half(v); }

template <typename T> struct dtype_of;
template <> struct dtype_of<float> { static const cudaDataType_t v = CUDA_R_32F; };
template <> struct dtype_of<__half> { static const cudaDataType_t v = CUDA_R_16F; };

/* ---- kernels ---------------------------------------------------------------------------------- */

__device__ float block_sum(float v, float *sh)
{
    for (int o = 16; o > 0; o >>= 1) v += __shfl_xor_sync(0xffffffffu, v, o);
    int lane = threadIdx.x & 31, wid = threadIdx.x >> 5;
    __syncthreads();
    if (lane == 0) sh[wid] = v;
    __syncthreads();
    float s = 0;
    for (int i = 0; i < (int)(blockDim.x >> 5); i++) s += sh[i];
    return s;
}

__device__ float block_max(float v, float *sh)
{
    for (int o = 16; o > 0; o >>= 1) v = fmaxf(v, __shfl_xor_sync(0xffffffffu, v, o));
    int lane = threadIdx.x & 31, wid = threadIdx.x >> 5;
    __syncthreads();
    if (lane == 0) sh[wid] = v;
    __syncthreads();
    float s = sh[0];
    for (int i = 1; i < (int)(blockDim.x >> 5); i++) s = fmaxf(s, sh[i]);
    return s;
}

/* One block per row; in-place allowed (every thread reads its elements before writing). */
template <typename T>
__global__ void k_layernorm(const T *x, T *y, int n, const T *g, const T *b, float eps)
{
    __shared__ float sh[32];
    const T *xr = x + (size_t)blockIdx.x * n;
    T *yr = y + (size_t)blockIdx.x * n;
    float s = 0;
    for (int i = threadIdx.x; i < n; i += blockDim.x) s += ld(xr + i);
    float mean = block_sum(s, sh) / n;
    float s2 = 0;
    for (int i = threadIdx.x; i < n; i += blockDim.x) {
        float d = ld(xr + i) - mean;
        s2 += d * d;
    }
    float inv = rsqrtf(block_sum(s2, sh) / n + eps);
    for (int i = threadIdx.x; i < n; i += blockDim.x)
        st(yr + i, (ld(xr + i) - mean) * inv * ld(g + i) + ld(b + i));
}

/* y[r][j] += b[j], then the activation (0 none, 1 quick_gelu, 2 erf GELU). */
template <typename T>
__global__ void k_bias_act(T *y, long total, int n, const T *b, int act)
{
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x) {
        float v = ld(y + i) + ld(b + i % n);
        if (act == 1) v = v / (1.f + expf(-1.702f * v));
        else if (act == 2) v = 0.5f * v * (1.f + erff(v * 0.70710678f));
        st(y + i, v);
    }
}

/* qkv [B*T][3w] (q | k | v) -> out [3][B][H][T][d] */
template <typename T>
__global__ void k_split_heads(const T *qkv, T *out, int B, int Tn, int H, int d)
{
    long w = (long)H * d, total = 3L * B * Tn * w;
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x) {
        int c = (int)(i % d);
        long r = i / d;
        int t = (int)(r % Tn);
        r /= Tn;
        int h = (int)(r % H);
        r /= H;
        int b = (int)(r % B);
        int which = (int)(r / B);
        out[i] = qkv[((long)b * Tn + t) * 3 * w + which * w + (long)h * d + c];
    }
}

/* o [B][H][T][d] -> y [B*T][w] */
template <typename T>
__global__ void k_merge_heads(const T *o, T *y, int B, int Tn, int H, int d)
{
    long w = (long)H * d, total = (long)B * Tn * w;
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x) {
        int col = (int)(i % w);
        long row = i / w;
        int t = (int)(row % Tn), b = (int)(row / Tn), h = col / d, c = col % d;
        y[i] = o[(((long)b * H + h) * Tn + t) * d + c];
    }
}

/* Softmax of each row of s [rows][T] after scaling; causal rows mask keys after the query. */
template <typename T>
__global__ void k_softmax(T *s, int Tn, float scale, int causal)
{
    __shared__ float sh[32];
    T *r = s + (size_t)blockIdx.x * Tn;
    int q = blockIdx.x % Tn, n = causal ? q + 1 : Tn;
    float m = -INFINITY;
    for (int i = threadIdx.x; i < n; i += blockDim.x) m = fmaxf(m, ld(r + i) * scale);
    m = block_max(m, sh);
    float sum = 0;
    for (int i = threadIdx.x; i < n; i += blockDim.x) sum += expf(ld(r + i) * scale - m);
    float inv = 1.f / block_sum(sum, sh);
    for (int i = threadIdx.x; i < Tn; i += blockDim.x)
        st(r + i, i < n ? expf(ld(r + i) * scale - m) * inv : 0.f);
}

template <typename T>
__global__ void k_embed_text(const int32_t *ids, const T *tok, const T *pos, T *x, int L, int w, long total)
{
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x) {
        int c = (int)(i % w);
        long row = i / w;
        int t = (int)(row % L);
        st(x + i, ld(tok + (long)ids[row] * w + c) + ld(pos + (long)t * w + c));
    }
}

/* pixels [B][3][H][W] fp32 -> cols [B*np][3*p*p] in (channel, ky, kx) order */
template <typename T>
__global__ void k_im2col(const float *px, T *cols, int H, int W, int p, int gw, int np, long total)
{
    int K = 3 * p * p;
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x) {
        int k = (int)(i % K);
        long r = i / K;
        int b = (int)(r / np), pi = (int)(r % np), ch = k / (p * p), ky = (k / p) % p, kx = k % p;
        int y = (pi / gw) * p + ky, x = (pi % gw) * p + kx;
        st(cols + i, px[(((long)b * 3 + ch) * H + y) * W + x]);
    }
}

/* x [B][T][w]: row 0 = cls + pos[0], rows 1.. = patch embeddings + pos */
template <typename T>
__global__ void k_assemble(const T *pe, const T *cls, const float *pos, T *x, int Tn, int w, long total)
{
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x) {
        int c = (int)(i % w);
        long row = i / w;
        int t = (int)(row % Tn), b = (int)(row / Tn);
        float v = t == 0 ? ld(cls + c) : ld(pe + ((long)b * (Tn - 1) + t - 1) * w + c);
        st(x + i, v + pos[(long)t * w + c]);
    }
}

/* dst[i] = src[rows[i]] for rows of width w */
template <typename T>
__global__ void k_gather(const T *src, const int32_t *rows, T *dst, int w, long total)
{
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x)
        dst[i] = src[(long)rows[i / w] * w + i % w];
}

/* patch rows of x [B][T][w] -> [B*(T-1)][w] */
template <typename T>
__global__ void k_drop_cls(const T *x, T *y, int Tn, int w, long total)
{
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < total; i += (long)gridDim.x * blockDim.x) {
        long row = i / w;
        long b = row / (Tn - 1), t = row % (Tn - 1) + 1;
        y[i] = x[(b * Tn + t) * w + i % w];
    }
}

template <typename T>
__global__ void k_to_float(const T *x, float *y, long n)
{
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < n; i += (long)gridDim.x * blockDim.x) y[i] = ld(x + i);
}

__global__ void k_f32_to_f16(const float *x, __half *y, long n)
{
    for (long i = blockIdx.x * (long)blockDim.x + threadIdx.x; i < n; i += (long)gridDim.x * blockDim.x) y[i] = __float2half(x[i]);
}

static int grid_for(long n)
{
    long g = (n + 255) / 256;
    return (int)(g > 65535 ? 65535 : g < 1 ? 1 : g);
}

/* ---- host side -------------------------------------------------------------------------------- */

static size_t off_of(const sp_clip *c, const float *p) { return (size_t)(p - c->blob); }

/* count bytes of device memory into *p (accounted to the device) */
static int dev_alloc(sp_clip_gpu *g, void **p, size_t bytes, const char *what, sp_error *err)
{
    *p = sp_device_alloc_scratch(g->dev, bytes, err);
    return *p ? 0 : sp_error_prefix(err, "CLIP GPU: %s: ", what);
}

extern "C" int clip_gpu_init(sp_clip *c, sp_error *err)
{
    sp_clip_gpu *g = (sp_clip_gpu *)calloc(1, sizeof *g);
    if (!g) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    c->gpu = g;
    g->dev = c->dev;
    g->stream = sp_cuda_stream(c->dev);
    if (!(g->blas = sp_cuda_blas(c->dev, err))) return sp_error_prefix(err, "CLIP GPU: ");
    g->text = (gpu_layer *)calloc((size_t)c->cfg.text.layers, sizeof(gpu_layer));
    g->vision = (gpu_layer *)calloc((size_t)c->cfg.vision.layers, sizeof(gpu_layer));
    if (!g->text || !g->vision) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    cudaStream_t st = g->stream;
    /* the blob, then a fused [3w][w] QKV weight and [3w] bias per layer */
    size_t extra = 0;
    int tw = c->cfg.text.width, vw = c->cfg.vision.width;
    extra += (size_t)c->cfg.text.layers * (3 * (size_t)tw * tw + 3 * tw);
    extra += (size_t)c->cfg.vision.layers * (3 * (size_t)vw * vw + 3 * vw);
    g->n_floats = c->blob_floats + extra;
    int rc = dev_alloc(g, (void **)&g->w32, g->n_floats * sizeof(float), "weights", err);
    if (rc) return rc;
    CK(cudaMemcpyAsync(g->w32, c->blob, c->blob_floats * sizeof(float), cudaMemcpyHostToDevice, st),
       "weights upload");
    size_t at = c->blob_floats;
    for (int tower = 0; tower < 2; tower++) {
        const clip_tower *tw_ = tower ? &c->vision : &c->text;
        gpu_layer *gl = tower ? g->vision : g->text;
        size_t w = (size_t)tw_->cfg.width;
        for (int l = 0; l < tw_->cfg.layers; l++) {
            const clip_layer *L = &tw_->layers[l];
            gpu_layer *o = &gl[l];
            o->ln1_w = off_of(c, L->ln1_w); o->ln1_b = off_of(c, L->ln1_b);
            o->o_w = off_of(c, L->o_w); o->o_b = off_of(c, L->o_b);
            o->ln2_w = off_of(c, L->ln2_w); o->ln2_b = off_of(c, L->ln2_b);
            o->fc1_w = off_of(c, L->fc1_w); o->fc1_b = off_of(c, L->fc1_b);
            o->fc2_w = off_of(c, L->fc2_w); o->fc2_b = off_of(c, L->fc2_b);
            o->qkv_w = at;
            o->qkv_b = at + 3 * w * w;
            const float *src_w[3] = {L->q_w, L->k_w, L->v_w}, *src_b[3] = {L->q_b, L->k_b, L->v_b};
            for (int k = 0; k < 3; k++) {
                CK(cudaMemcpyAsync(g->w32 + o->qkv_w + k * w * w, g->w32 + off_of(c, src_w[k]),
                                   w * w * sizeof(float), cudaMemcpyDeviceToDevice, st), "qkv weights");
                CK(cudaMemcpyAsync(g->w32 + o->qkv_b + k * w, g->w32 + off_of(c, src_b[k]),
                                   w * sizeof(float), cudaMemcpyDeviceToDevice, st), "qkv bias");
            }
            at += 3 * w * w + 3 * w;
        }
    }
    CK(cudaStreamSynchronize(st), "weights upload");
    return 0;
}

extern "C" void clip_gpu_free(sp_clip *c)
{
    sp_clip_gpu *g = c->gpu;
    if (!g) return;
    sp_device_release(g->dev, g->w32);
    sp_device_release(g->dev, g->w16);
    sp_device_release(g->dev, g->arena);
    free(g->text);
    free(g->vision);
    free(g);
    c->gpu = NULL;
}

extern "C" int clip_gpu_set_fp16(sp_clip *c, int on, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    if (on && !g->w16) {
        int rc = dev_alloc(g, (void **)&g->w16, g->n_floats * sizeof(__half), "fp16 weights", err);
        if (rc) return rc;
        k_f32_to_f16<<<grid_for((long)g->n_floats), 256, 0, g->stream>>>(g->w32, g->w16, (long)g->n_floats);
        CK(cudaStreamSynchronize(g->stream), "fp16 conversion");
    }
    c->fp16 = on;
    return 0;
}

/* A bump allocator over one device buffer, grown (and the call retried) when too small. */
struct arena {
    sp_clip_gpu *g;
    size_t need;
    int fits;
};

template <typename T> static T *take(arena *a, size_t count)
{
    size_t bytes = (count * sizeof(T) + 255) & ~(size_t)255, at = a->need;
    a->need += bytes;
    if (a->need > a->g->arena_cap) {
        a->fits = 0;
        return NULL;
    }
    return (T *)((char *)a->g->arena + at);
}

static int arena_grow(sp_clip_gpu *g, size_t need, sp_error *err)
{
    sp_device_release(g->dev, g->arena);
    g->arena = NULL;
    g->arena_cap = 0;
    int rc = dev_alloc(g, &g->arena, need, "scratch", err);
    if (!rc) g->arena_cap = need;
    return rc;
}

template <typename T> struct ctx {
    sp_clip *c;
    sp_clip_gpu *g;
    const T *W; /* weights in this precision */
    float one, zero;
    sp_error *err;
};

/* Y[M][N] = X[M][K] W^T (+ beta Y): row-major, as a column-major Y^T = W X^T */
template <typename T>
static int gemm(ctx<T> &x, const T *X, int M, int K, const T *W, int N, T *Y, float beta)
{
    sp_error *err = x.err;
    CB(cublasGemmEx(x.g->blas, CUBLAS_OP_T, CUBLAS_OP_N, N, M, K, &x.one, W, dtype_of<T>::v, K, X,
                    dtype_of<T>::v, K, &beta, Y, dtype_of<T>::v, N, CUBLAS_COMPUTE_32F,
                    CUBLAS_GEMM_DEFAULT), "gemm");
    return 0;
}

/* Attention for B sequences of Tn tokens: qkvh [3][B][H][Tn][d]; a = q, b = k (or q for
 * ClearCLIP), v; writes heads output to oh [B][H][Tn][d]. */
template <typename T>
static int attention(ctx<T> &x, const sp_clip_tower_config *cfg, const T *a, const T *b, const T *v,
                     T *s, T *oh, int B, int Tn, int causal)
{
    sp_error *err = x.err;
    int H = cfg->heads, d = cfg->width / H, batch = B * H;
    long long sd = (long long)Tn * d, ss = (long long)Tn * Tn;
    float zero = 0, one = 1;
    CB(cublasGemmStridedBatchedEx(x.g->blas, CUBLAS_OP_T, CUBLAS_OP_N, Tn, Tn, d, &one, b, dtype_of<T>::v, d, sd,
                                  a, dtype_of<T>::v, d, sd, &zero, s, dtype_of<T>::v, Tn, ss, batch,
                                  CUBLAS_COMPUTE_32F, CUBLAS_GEMM_DEFAULT), "scores");
    k_softmax<T><<<batch * Tn, 128, 0, x.g->stream>>>(s, Tn, 1.f / sqrtf((float)d), causal);
    CB(cublasGemmStridedBatchedEx(x.g->blas, CUBLAS_OP_N, CUBLAS_OP_N, d, Tn, Tn, &one, v, dtype_of<T>::v, d, sd,
                                  s, dtype_of<T>::v, Tn, ss, &zero, oh, dtype_of<T>::v, d, sd, batch,
                                  CUBLAS_COMPUTE_32F, CUBLAS_GEMM_DEFAULT), "attention values");
    return 0;
}

struct bufs_t {
    void *h, *qkv, *heads, *s, *oh, *o, *m;
};

template <typename T> static void take_bufs(arena *ar, bufs_t *b, size_t M, int w, int mlp, int B, int H, int Tn)
{
    b->h = take<T>(ar, M * w);
    b->qkv = take<T>(ar, M * 3 * w);
    b->heads = take<T>(ar, M * 3 * w);
    b->s = take<T>(ar, (size_t)B * H * Tn * Tn);
    b->oh = take<T>(ar, M * w);
    b->m = take<T>(ar, M * (size_t)mlp);
}

template <typename T>
static int block(ctx<T> &x, const sp_clip_tower_config *cfg, const gpu_layer *L, T *xb, int B, int Tn,
                 int causal, bufs_t *bf)
{
    int w = cfg->width, H = cfg->heads, d = w / H, M = B * Tn, rc;
    long Mw = (long)M * w;
    cudaStream_t st = x.g->stream;
    T *h = (T *)bf->h, *qkv = (T *)bf->qkv, *heads = (T *)bf->heads, *oh = (T *)bf->oh, *m = (T *)bf->m;
    k_layernorm<T><<<M, 256, 0, st>>>(xb, h, w, x.W + L->ln1_w, x.W + L->ln1_b, cfg->eps);
    if ((rc = gemm(x, h, M, w, x.W + L->qkv_w, 3 * w, qkv, 0.f))) return rc;
    k_bias_act<T><<<grid_for(3 * Mw), 256, 0, st>>>(qkv, 3 * Mw, 3 * w, x.W + L->qkv_b, 0);
    k_split_heads<T><<<grid_for(3 * Mw), 256, 0, st>>>(qkv, heads, B, Tn, H, d);
    if ((rc = attention(x, cfg, heads, heads + Mw, heads + 2 * Mw, (T *)bf->s, oh, B, Tn, causal))) return rc;
    k_merge_heads<T><<<grid_for(Mw), 256, 0, st>>>(oh, h, B, Tn, H, d);
    if ((rc = gemm(x, h, M, w, x.W + L->o_w, w, xb, 1.f))) return rc;
    k_bias_act<T><<<grid_for(Mw), 256, 0, st>>>(xb, Mw, w, x.W + L->o_b, 0);
    k_layernorm<T><<<M, 256, 0, st>>>(xb, h, w, x.W + L->ln2_w, x.W + L->ln2_b, cfg->eps);
    if ((rc = gemm(x, h, M, w, x.W + L->fc1_w, cfg->mlp, m, 0.f))) return rc;
    k_bias_act<T><<<grid_for((long)M * cfg->mlp), 256, 0, st>>>(m, (long)M * cfg->mlp, cfg->mlp, x.W + L->fc1_b,
                                                                 cfg->quick_gelu ? 1 : 2);
    if ((rc = gemm(x, m, M, cfg->mlp, x.W + L->fc2_w, w, xb, 1.f))) return rc;
    k_bias_act<T><<<grid_for(Mw), 256, 0, st>>>(xb, Mw, w, x.W + L->fc2_b, 0);
    return 0;
}

template <typename T>
static int text_forward(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    ctx<T> x = {c, g, (const T *)(sizeof(T) == 2 ? (void *)g->w16 : (void *)g->w32), 1.f, 0.f, err};
    const sp_clip_tower_config *cfg = &c->cfg.text;
    int w = cfg->width, P = c->cfg.projection_dim, ctxn = c->cfg.context, L = 1, rc;
    int32_t *rows = (int32_t *)malloc((size_t)n * sizeof *rows);
    if (!rows) return sp_error_set(err, SP_E_NOMEM, "out of memory");
    for (int i = 0; i < n; i++) {
        rows[i] = clip_eos_position(c, ids + (size_t)i * ctxn);
        if (rows[i] + 1 > L) L = rows[i] + 1;
    }
    /* sequences are cut to the longest EOS: causal attention never looks past a row */
    int32_t *hids = (int32_t *)malloc((size_t)n * L * sizeof *hids);
    if (!hids) { free(rows); return sp_error_set(err, SP_E_NOMEM, "out of memory"); }
    for (int i = 0; i < n; i++) {
        memcpy(hids + (size_t)i * L, ids + (size_t)i * ctxn, (size_t)L * sizeof *hids);
        rows[i] += i * L;
    }
    size_t M = (size_t)n * L;
    for (int attempt = 0; attempt < 2; attempt++) {
        arena ar = {g, 0, 1};
        int32_t *d_ids = take<int32_t>(&ar, M), *d_rows = take<int32_t>(&ar, (size_t)n);
        T *xb = take<T>(&ar, M * w), *fin = take<T>(&ar, (size_t)n * w), *po = take<T>(&ar, (size_t)n * P);
        float *o32 = take<float>(&ar, (size_t)n * P);
        bufs_t bf;
        take_bufs<T>(&ar, &bf, M, w, cfg->mlp, n, cfg->heads, L);
        if (!ar.fits) {
            if ((rc = arena_grow(g, ar.need, err))) break;
            continue;
        }
        cudaStream_t st = g->stream;
        rc = 0;
        if (cudaMemcpyAsync(d_ids, hids, M * sizeof *hids, cudaMemcpyHostToDevice, st) != cudaSuccess ||
            cudaMemcpyAsync(d_rows, rows, (size_t)n * sizeof *rows, cudaMemcpyHostToDevice, st) != cudaSuccess) {
            rc = sp_error_set(err, SP_E_DEVICE, "CLIP GPU: upload failed");
            break;
        }
        k_embed_text<T><<<grid_for((long)M * w), 256, 0, st>>>(d_ids, x.W + off_of(c, c->tok_emb),
                                                                 x.W + off_of(c, c->txt_pos), xb, L, w, (long)M * w);
        for (int l = 0; l < cfg->layers && !rc; l++) rc = block(x, cfg, &g->text[l], xb, n, L, 1, &bf);
        if (rc) break;
        k_gather<T><<<grid_for((long)n * w), 256, 0, st>>>(xb, d_rows, fin, w, (long)n * w);
        k_layernorm<T><<<n, 256, 0, st>>>(fin, fin, w, x.W + off_of(c, c->final_ln_w), x.W + off_of(c, c->final_ln_b), cfg->eps);
        if ((rc = gemm(x, fin, n, w, x.W + off_of(c, c->text_proj), P, po, 0.f))) break;
        k_to_float<T><<<grid_for((long)n * P), 256, 0, st>>>(po, o32, (long)n * P);
        if (cudaMemcpyAsync(out, o32, (size_t)n * P * sizeof(float), cudaMemcpyDeviceToHost, st) != cudaSuccess ||
            cudaStreamSynchronize(st) != cudaSuccess)
            rc = sp_error_set(err, SP_E_DEVICE, "CLIP GPU: text forward failed: %s", cudaGetErrorString(cudaGetLastError()));
        break;
    }
    free(rows);
    free(hids);
    return rc;
}

template <typename T>
static int vision_forward(sp_clip *c, const float *pixels, int n, int H, int W, clip_out_kind kind,
                          float *out, sp_error *err)
{
    sp_clip_gpu *g = c->gpu;
    ctx<T> x = {c, g, (const T *)(sizeof(T) == 2 ? (void *)g->w16 : (void *)g->w32), 1.f, 0.f, err};
    const sp_clip_tower_config *cfg = &c->cfg.vision;
    int w = cfg->width, P = c->cfg.projection_dim, p = c->cfg.patch_size, rc = 0;
    int gh = H / p, gw = W / p, np = gh * gw, Tn = np + 1, K = 3 * p * p;
    int dense = kind != CLIP_OUT_POOLED, layers = cfg->layers - (dense ? 1 : 0);
    size_t M = (size_t)n * Tn, n_out = dense ? (size_t)n * np : (size_t)n;
    float *pos = (float *)malloc((size_t)Tn * w * sizeof *pos);
    int32_t *rows = (int32_t *)malloc((size_t)n * sizeof *rows);
    if (!pos || !rows) { free(pos); free(rows); return sp_error_set(err, SP_E_NOMEM, "out of memory"); }
    clip_pos_embed(c, gh, gw, pos);
    for (int i = 0; i < n; i++) rows[i] = i * Tn;
    for (int attempt = 0; attempt < 2; attempt++) {
        arena ar = {g, 0, 1};
        float *d_px = take<float>(&ar, (size_t)n * 3 * H * W), *d_pos = take<float>(&ar, (size_t)Tn * w);
        int32_t *d_rows = take<int32_t>(&ar, (size_t)n);
        T *cols = take<T>(&ar, (size_t)n * np * K), *pe = take<T>(&ar, (size_t)n * np * w);
        T *xb = take<T>(&ar, M * w), *fin = take<T>(&ar, n_out * w), *po = take<T>(&ar, n_out * P);
        float *o32 = take<float>(&ar, n_out * P);
        bufs_t bf;
        take_bufs<T>(&ar, &bf, M, w, cfg->mlp, n, cfg->heads, Tn);
        if (!ar.fits) {
            if ((rc = arena_grow(g, ar.need, err))) break;
            continue;
        }
        cudaStream_t st = g->stream;
        if (cudaMemcpyAsync(d_px, pixels, (size_t)n * 3 * H * W * sizeof(float), cudaMemcpyHostToDevice, st) != cudaSuccess ||
            cudaMemcpyAsync(d_pos, pos, (size_t)Tn * w * sizeof(float), cudaMemcpyHostToDevice, st) != cudaSuccess ||
            cudaMemcpyAsync(d_rows, rows, (size_t)n * sizeof(int32_t), cudaMemcpyHostToDevice, st) != cudaSuccess) {
            rc = sp_error_set(err, SP_E_DEVICE, "CLIP GPU: upload failed");
            break;
        }
        long total = (long)n * np * K;
        k_im2col<T><<<grid_for(total), 256, 0, st>>>(d_px, cols, H, W, p, gw, np, total);
        if ((rc = gemm(x, cols, n * np, K, x.W + off_of(c, c->patch_w), w, pe, 0.f))) break;
        k_assemble<T><<<grid_for((long)M * w), 256, 0, st>>>(pe, x.W + off_of(c, c->cls), d_pos, xb, Tn, w, (long)M * w);
        k_layernorm<T><<<(int)M, 256, 0, st>>>(xb, xb, w, x.W + off_of(c, c->pre_ln_w), x.W + off_of(c, c->pre_ln_b), cfg->eps);
        for (int l = 0; l < layers && !rc; l++) rc = block(x, cfg, &g->vision[l], xb, n, Tn, 0, &bf);
        if (rc) break;
        if (!dense) {
            k_gather<T><<<grid_for((long)n * w), 256, 0, st>>>(xb, d_rows, fin, w, (long)n * w);
        } else {
            /* dense head: last block's value path (MaskCLIP) or q-q attention (ClearCLIP), no
             * residual or FFN, then the projection of every patch token */
            const gpu_layer *L = &g->vision[cfg->layers - 1];
            int Hh = cfg->heads, d = w / Hh;
            long Mw = (long)M * w;
            T *h = (T *)bf.h, *qkv = (T *)bf.qkv, *heads = (T *)bf.heads;
            k_layernorm<T><<<(int)M, 256, 0, st>>>(xb, h, w, x.W + L->ln1_w, x.W + L->ln1_b, cfg->eps);
            if ((rc = gemm(x, h, (int)M, w, x.W + L->qkv_w, 3 * w, qkv, 0.f))) break;
            k_bias_act<T><<<grid_for(3 * Mw), 256, 0, st>>>(qkv, 3 * Mw, 3 * w, x.W + L->qkv_b, 0);
            k_split_heads<T><<<grid_for(3 * Mw), 256, 0, st>>>(qkv, heads, n, Tn, Hh, d);
            const T *vals = heads + 2 * Mw;
            if (kind == CLIP_OUT_DENSE_CLEARCLIP) {
                if ((rc = attention(x, cfg, heads, heads, heads + 2 * Mw, (T *)bf.s, (T *)bf.oh, n, Tn, 0))) break;
                vals = (T *)bf.oh;
            }
            k_merge_heads<T><<<grid_for(Mw), 256, 0, st>>>(vals, h, n, Tn, Hh, d);
            if ((rc = gemm(x, h, (int)M, w, x.W + L->o_w, w, xb, 0.f))) break;
            k_bias_act<T><<<grid_for(Mw), 256, 0, st>>>(xb, Mw, w, x.W + L->o_b, 0);
            k_drop_cls<T><<<grid_for((long)n_out * w), 256, 0, st>>>(xb, fin, Tn, w, (long)n_out * w);
        }
        k_layernorm<T><<<(int)n_out, 256, 0, st>>>(fin, fin, w, x.W + off_of(c, c->post_ln_w), x.W + off_of(c, c->post_ln_b), cfg->eps);
        if ((rc = gemm(x, fin, (int)n_out, w, x.W + off_of(c, c->vis_proj), P, po, 0.f))) break;
        k_to_float<T><<<grid_for((long)n_out * P), 256, 0, st>>>(po, o32, (long)n_out * P);
        if (cudaMemcpyAsync(out, o32, n_out * P * sizeof(float), cudaMemcpyDeviceToHost, st) != cudaSuccess ||
            cudaStreamSynchronize(st) != cudaSuccess)
            rc = sp_error_set(err, SP_E_DEVICE, "CLIP GPU: vision forward failed: %s", cudaGetErrorString(cudaGetLastError()));
        break;
    }
    free(pos);
    free(rows);
    return rc;
}

extern "C" int clip_gpu_text(sp_clip *c, const int32_t *ids, int n, float *out, sp_error *err)
{
    return c->fp16 ? text_forward<__half>(c, ids, n, out, err) : text_forward<float>(c, ids, n, out, err);
}

extern "C" int clip_gpu_vision(sp_clip *c, const float *pixels, int n, int H, int W, clip_out_kind kind,
                               float *out, sp_error *err)
{
    return c->fp16 ? vision_forward<__half>(c, pixels, n, H, W, kind, out, err)
                   : vision_forward<float>(c, pixels, n, H, W, kind, out, err);
}
