/* CLIP's memory-bound kernels: LayerNorm (one warp per row, the row in registers, 16-byte loads),
 * bias + activation (QuickGELU, GELU) in place, softmax for the unfused attention path, and the
 * embedding / patch / layout kernels that run once per forward. Statistics in fp32 for both
 * precisions. The per-layer kernels index with 32-bit integers (64-bit division per element
 * cost more than the arithmetic). */
#include <math.h>

#include "clip_gpu.cuh"

__device__ __forceinline__ float ld1(const float *p) { return *p; }
__device__ __forceinline__ float ld1(const __half *p) { return __half2float(*p); }
__device__ __forceinline__ void st1(float *p, float v) { *p = v; }
__device__ __forceinline__ void st1(__half *p, float v) { *p = __float2half(v); }

/* eight consecutive elements, 16-byte aligned (fp16: one uint4, fp32: two float4) */
__device__ __forceinline__ void ld8(const float *p, float v[8])
{
    float4 a = *(const float4 *)p, b = *(const float4 *)(p + 4);
    v[0] = a.x; v[1] = a.y; v[2] = a.z; v[3] = a.w; v[4] = b.x; v[5] = b.y; v[6] = b.z; v[7] = b.w;
}
__device__ __forceinline__ void ld8(const __half *p, float v[8])
{
    uint4 u = *(const uint4 *)p;
    const __half2 *h = (const __half2 *)&u;
#pragma unroll
    for (int i = 0; i < 4; i++) {
        float2 f = __half22float2(h[i]);
        v[2 * i] = f.x;
        v[2 * i + 1] = f.y;
    }
}
__device__ __forceinline__ void st8(float *p, const float v[8])
{
    *(float4 *)p = make_float4(v[0], v[1], v[2], v[3]);
    *(float4 *)(p + 4) = make_float4(v[4], v[5], v[6], v[7]);
}
__device__ __forceinline__ void st8(__half *p, const float v[8])
{
    uint4 u;
    __half2 *h = (__half2 *)&u;
#pragma unroll
    for (int i = 0; i < 4; i++) h[i] = __floats2half2_rn(v[2 * i], v[2 * i + 1]);
    *(uint4 *)p = u;
}

__device__ __forceinline__ float warp_sum(float v)
{
#pragma unroll
    for (int o = 16; o > 0; o >>= 1) v += __shfl_xor_sync(0xffffffffu, v, o);
    return v;
}
__device__ __forceinline__ float warp_max(float v)
{
#pragma unroll
    for (int o = 16; o > 0; o >>= 1) v = fmaxf(v, __shfl_xor_sync(0xffffffffu, v, o));
    return v;
}

__device__ __forceinline__ int ln_src_row(const ln_rows &m, int r)
{
    return m.rows ? m.rows[r] : (r / m.group) * m.stride + m.offset + r % m.group;
}

__device__ __forceinline__ float act_of(float v, int act)
{
    if (act == 1) return v / (1.f + __expf(-1.702f * v));
    if (act == 2) return 0.5f * v * (1.f + erff(v * 0.70710678f));
    return v;
}

/* ---- LayerNorm ------------------------------------------------------------------------------- */

/* One warp per row of w = 8 * chunks elements, at most 32 * CH chunks (lane l holds chunks l,
 * l + 32, ...). Two passes over the registers (mean, then the centred variance), as the CPU. */
template <typename T, int CH>
__global__ void k_ln_warp(const T *x, T *y, int n_rows, int w, const T *g, const T *b, float eps, ln_rows map)
{
    int r = (int)((blockIdx.x * blockDim.x + threadIdx.x) >> 5), lane = threadIdx.x & 31;
    if (r >= n_rows) return;
    const T *xr = x + (size_t)ln_src_row(map, r) * w;
    T *yr = y + (size_t)r * w;
    int nch = w >> 3;
    float v[CH][8], s = 0;
#pragma unroll
    for (int j = 0; j < CH; j++) {
        int c = lane + 32 * j;
        if (c < nch) {
            ld8(xr + 8 * c, v[j]);
#pragma unroll
            for (int e = 0; e < 8; e++) s += v[j][e];
        }
    }
    float mean = warp_sum(s) / w, s2 = 0;
#pragma unroll
    for (int j = 0; j < CH; j++)
        if (lane + 32 * j < nch)
#pragma unroll
            for (int e = 0; e < 8; e++) {
                float d = v[j][e] - mean;
                s2 += d * d;
            }
    float inv = rsqrtf(warp_sum(s2) / w + eps);
#pragma unroll
    for (int j = 0; j < CH; j++) {
        int c = lane + 32 * j;
        if (c < nch) {
            float gg[8], bb[8], o[8];
            ld8(g + 8 * c, gg);
            ld8(b + 8 * c, bb);
#pragma unroll
            for (int e = 0; e < 8; e++) o[e] = (v[j][e] - mean) * inv * gg[e] + bb[e];
            st8(yr + 8 * c, o);
        }
    }
}

/* Any width: one block per row, three passes over memory. */
template <typename T>
__global__ void k_ln_block(const T *x, T *y, int w, const T *g, const T *b, float eps, ln_rows map)
{
    __shared__ float sh[32];
    const T *xr = x + (size_t)ln_src_row(map, blockIdx.x) * w;
    T *yr = y + (size_t)blockIdx.x * w;
    int lane = threadIdx.x & 31, wid = threadIdx.x >> 5, nw = blockDim.x >> 5;
    float s = 0;
    for (int i = threadIdx.x; i < w; i += blockDim.x) s += ld1(xr + i);
    s = warp_sum(s);
    if (lane == 0) sh[wid] = s;
    __syncthreads();
    float mean = 0;
    for (int i = 0; i < nw; i++) mean += sh[i];
    mean /= w;
    __syncthreads();
    float s2 = 0;
    for (int i = threadIdx.x; i < w; i += blockDim.x) {
        float d = ld1(xr + i) - mean;
        s2 += d * d;
    }
    s2 = warp_sum(s2);
    if (lane == 0) sh[wid] = s2;
    __syncthreads();
    float var = 0;
    for (int i = 0; i < nw; i++) var += sh[i];
    float inv = rsqrtf(var / w + eps);
    /* every thread has read its elements above: in place is safe (same thread, same elements) */
    for (int i = threadIdx.x; i < w; i += blockDim.x) st1(yr + i, (ld1(xr + i) - mean) * inv * ld1(g + i) + ld1(b + i));
}

template <typename T>
void launch_layernorm(const T *x, T *y, int n_rows, int w, const T *g, const T *b, float eps, ln_rows map,
                      cudaStream_t st)
{
    if (n_rows <= 0) return;
    int nch = w / 8, grid = (n_rows + 7) / 8;
    if (w % 8 || nch > 128) {
        k_ln_block<T><<<n_rows, 256, 0, st>>>(x, y, w, g, b, eps, map);
    } else if (nch <= 32) {
        k_ln_warp<T, 1><<<grid, 256, 0, st>>>(x, y, n_rows, w, g, b, eps, map);
    } else if (nch <= 64) {
        k_ln_warp<T, 2><<<grid, 256, 0, st>>>(x, y, n_rows, w, g, b, eps, map);
    } else if (nch <= 96) {
        k_ln_warp<T, 3><<<grid, 256, 0, st>>>(x, y, n_rows, w, g, b, eps, map);
    } else {
        k_ln_warp<T, 4><<<grid, 256, 0, st>>>(x, y, n_rows, w, g, b, eps, map);
    }
}

/* ---- bias + activation --------------------------------------------------------------------------- */

static int blocks_for(size_t n, int per_block)
{
    size_t g = (n + per_block - 1) / per_block;
    return (int)(g > 131072 ? 131072 : g < 1 ? 1 : g);
}

/* chunks of 8 along rows of n (n % 8 == 0); chunk i is at column (i % (n / 8)) * 8 */
template <typename T>
__global__ void k_bias_act8(T *y, unsigned n_chunks, unsigned row_chunks, const T *bias, int act)
{
    for (unsigned i = blockIdx.x * blockDim.x + threadIdx.x; i < n_chunks; i += gridDim.x * blockDim.x) {
        float v[8];
        T *p = y + (size_t)i * 8;
        ld8(p, v);
        if (bias) {
            float bb[8];
            ld8(bias + (i % row_chunks) * 8, bb);
#pragma unroll
            for (int e = 0; e < 8; e++) v[e] += bb[e];
        }
#pragma unroll
        for (int e = 0; e < 8; e++) v[e] = act_of(v[e], act);
        st8(p, v);
    }
}

template <typename T>
__global__ void k_bias_act1(T *y, size_t total, int n, const T *bias, int act)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < total; i += (size_t)gridDim.x * blockDim.x) {
        float v = ld1(y + i) + (bias ? ld1(bias + i % n) : 0.f);
        st1(y + i, act_of(v, act));
    }
}

template <typename T> void launch_bias_act(T *y, long rows, int n, const T *bias, int act, cudaStream_t st)
{
    size_t total = (size_t)rows * n;
    if (!total || (!bias && !act)) return;
    if (n % 8 == 0 && total / 8 < 0xffffffffu)
        k_bias_act8<T><<<blocks_for(total / 8, 256), 256, 0, st>>>(y, (unsigned)(total / 8), (unsigned)(n / 8), bias, act);
    else
        k_bias_act1<T><<<blocks_for(total, 256), 256, 0, st>>>(y, total, n, bias, act);
}

/* ---- softmax (unfused attention) ----------------------------------------------------------------- */

/* One warp per row of s [rows][Tn] after scaling; causal rows mask keys after the query. */
template <typename T>
__global__ void k_softmax(T *s, int rows, int Tn, float scale, int causal)
{
    int r = (int)((blockIdx.x * blockDim.x + threadIdx.x) >> 5), lane = threadIdx.x & 31;
    if (r >= rows) return;
    T *p = s + (size_t)r * Tn;
    int n = causal ? r % Tn + 1 : Tn;
    float m = -INFINITY;
    for (int i = lane; i < n; i += 32) m = fmaxf(m, ld1(p + i) * scale);
    m = warp_max(m);
    float sum = 0;
    for (int i = lane; i < n; i += 32) sum += __expf(ld1(p + i) * scale - m);
    float inv = 1.f / warp_sum(sum);
    for (int i = lane; i < Tn; i += 32) st1(p + i, i < n ? __expf(ld1(p + i) * scale - m) * inv : 0.f);
}

template <typename T> void launch_softmax(T *s, long rows, int Tn, float scale, int causal, cudaStream_t st)
{
    if (rows > 0) k_softmax<T><<<(int)((rows + 7) / 8), 256, 0, st>>>(s, (int)rows, Tn, scale, causal);
}

/* ---- once per forward -------------------------------------------------------------------------------- */

template <typename T>
__global__ void k_embed_text(const int32_t *ids, const T *tok, const T *pos, T *x, int L, int w, size_t total)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < total; i += (size_t)gridDim.x * blockDim.x) {
        int c = (int)(i % w);
        size_t row = i / w;
        int t = (int)(row % L);
        st1(x + i, ld1(tok + (size_t)ids[row] * w + c) + ld1(pos + (size_t)t * w + c));
    }
}

template <typename T>
void launch_embed_text(const int32_t *ids, const T *tok, const T *pos, T *x, int rows, int L, int w, cudaStream_t st)
{
    size_t total = (size_t)rows * w;
    k_embed_text<T><<<blocks_for(total, 256), 256, 0, st>>>(ids, tok, pos, x, L, w, total);
}

/* pixels [B][3][H][W] (fp32 or fp16) -> cols [B*np][3*p*p] in (channel, ky, kx) order. I: the
 * index type (32-bit where the sizes allow: 64-bit division per element dominated this kernel). */
template <typename T, typename PX, typename I>
__global__ void k_im2col(const PX *px, T *cols, I H, I W, I p, I gw, I np, I total)
{
    I K = 3 * p * p, pp = p * p;
    for (I i = blockIdx.x * (I)blockDim.x + threadIdx.x; i < total; i += (I)gridDim.x * blockDim.x) {
        I k = i % K, r = i / K;
        I b = r / np, pi = r % np, ch = k / pp, ky = (k / p) % p, kx = k % p;
        I y = (pi / gw) * p + ky, x = (pi % gw) * p + kx;
        st1(cols + i, ld1(px + ((b * 3 + ch) * H + y) * W + x));
    }
}

template <typename T, typename PX>
static void im2col_as(const PX *px, T *cols, int n, int H, int W, int p, cudaStream_t st)
{
    int gw = W / p, np = (H / p) * gw;
    size_t total = (size_t)n * np * 3 * p * p, in = (size_t)n * 3 * H * W;
    if (total < 0x7fffffffu && in < 0x7fffffffu)
        k_im2col<T, PX, unsigned><<<blocks_for(total, 256), 256, 0, st>>>(px, cols, H, W, p, gw, np, (unsigned)total);
    else
        k_im2col<T, PX, size_t><<<blocks_for(total, 256), 256, 0, st>>>(px, cols, H, W, p, gw, np, total);
}

template <typename T>
void launch_im2col(const void *px, int px_half, T *cols, int n, int H, int W, int p, cudaStream_t st)
{
    if (px_half) im2col_as<T, __half>((const __half *)px, cols, n, H, W, p, st);
    else im2col_as<T, float>((const float *)px, cols, n, H, W, p, st);
}

/* x [B][T][w]: row 0 = cls + pos[0], rows 1.. = patch embeddings + pos */
template <typename T, typename I>
__global__ void k_assemble(const T *pe, const T *cls, const float *pos, T *x, I Tn, I w, I total)
{
    for (I i = blockIdx.x * (I)blockDim.x + threadIdx.x; i < total; i += (I)gridDim.x * blockDim.x) {
        I c = i % w, row = i / w, t = row % Tn, b = row / Tn;
        float v = t == 0 ? ld1(cls + c) : ld1(pe + (b * (Tn - 1) + t - 1) * w + c);
        st1(x + i, v + pos[t * w + c]);
    }
}

template <typename T>
void launch_assemble(const T *pe, const T *cls, const float *pos, T *x, int n, int Tn, int w, cudaStream_t st)
{
    size_t total = (size_t)n * Tn * w;
    if (total < 0x7fffffffu)
        k_assemble<T, unsigned><<<blocks_for(total, 256), 256, 0, st>>>(pe, cls, pos, x, Tn, w, (unsigned)total);
    else
        k_assemble<T, size_t><<<blocks_for(total, 256), 256, 0, st>>>(pe, cls, pos, x, Tn, w, total);
}

template <typename T>
__global__ void k_to_float(const T *x, float *y, size_t n)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < n; i += (size_t)gridDim.x * blockDim.x) y[i] = ld1(x + i);
}

template <typename T> void launch_to_float(const T *x, float *y, long n, cudaStream_t st)
{
    if (n > 0) k_to_float<T><<<blocks_for((size_t)n, 256), 256, 0, st>>>(x, y, (size_t)n);
}

__global__ void k_f32_to_f16(const float *x, __half *y, size_t n)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < n; i += (size_t)gridDim.x * blockDim.x)
        y[i] = __float2half(x[i]);
}

void launch_f32_to_f16(const float *x, __half *y, long n, cudaStream_t st)
{
    if (n > 0) k_f32_to_f16<<<blocks_for((size_t)n, 256), 256, 0, st>>>(x, y, (size_t)n);
}

#define INSTANTIATE(T)                                                                                       \
    template void launch_layernorm<T>(const T *, T *, int, int, const T *, const T *, float, ln_rows, cudaStream_t); \
    template void launch_bias_act<T>(T *, long, int, const T *, int, cudaStream_t);                         \
    template void launch_embed_text<T>(const int32_t *, const T *, const T *, T *, int, int, int, cudaStream_t); \
    template void launch_im2col<T>(const void *, int, T *, int, int, int, int, cudaStream_t);              \
    template void launch_assemble<T>(const T *, const T *, const float *, T *, int, int, int, cudaStream_t); \
    template void launch_softmax<T>(T *, long, int, float, int, cudaStream_t);                              \
    template void launch_to_float<T>(const T *, float *, long, cudaStream_t);
INSTANTIATE(float)
INSTANTIATE(__half)
