/* Fused multi-head attention on the tensor cores (FlashAttention-2 style, fp16 in, fp32
 * accumulation): one block of 4 warps takes 64 queries of one head; key/value tiles of 64 rows go
 * through shared memory; each warp keeps its 16 query rows' scores, running max and sum and the
 * output in registers (mma.sync m16n8k16), so the attention matrix never exists in memory. The
 * probabilities go from the score accumulators straight into the A operand of the P V product
 * (the accumulator layout of two n-tiles is the A layout of one k-step). Reads q, k, v straight
 * from the fused projection [B*T][3w] and writes [B*T][w]: no head split or merge passes.
 *
 * Fragment layouts (PTX ISA, mma.m16n8k16 .f16): lane = 4 g + t; A (16x16, row): a0 = (g, 2t..),
 * a1 = (g+8, 2t..), a2 = (g, 2t+8..), a3 = (g+8, 2t+8..); B (16x8, col): b0 = (k 2t.., n g),
 * b1 = (k 2t+8.., n g); C (16x8): c0,c1 = (g, 2t..), c2,c3 = (g+8, 2t..). */
#include <math.h>

#include "clip_gpu.cuh"

enum { FQ = 64, FK = 64, FWARPS = 4 };

__device__ __forceinline__ void mma16816(float c[4], const uint32_t a[4], uint32_t b0, uint32_t b1)
{
    asm volatile("mma.sync.aligned.m16n8k16.row.col.f32.f16.f16.f32 {%0,%1,%2,%3}, {%4,%5,%6,%7}, {%8,%9}, "
                 "{%0,%1,%2,%3};\n"
                 : "+f"(c[0]), "+f"(c[1]), "+f"(c[2]), "+f"(c[3])
                 : "r"(a[0]), "r"(a[1]), "r"(a[2]), "r"(a[3]), "r"(b0), "r"(b1));
}

/* four 8x8 b16 matrices, transposed: lane 8 i + r gives the address of row r of matrix i */
__device__ __forceinline__ void ldmatrix_x4_trans(uint32_t r[4], const __half *p)
{
    unsigned a = (unsigned)__cvta_generic_to_shared(p);
    asm volatile("ldmatrix.sync.aligned.m8n8.x4.trans.shared.b16 {%0,%1,%2,%3}, [%4];\n"
                 : "=r"(r[0]), "=r"(r[1]), "=r"(r[2]), "=r"(r[3])
                 : "r"(a));
}

__device__ __forceinline__ uint32_t pack_half2(float lo, float hi)
{
    __half2 h = __floats2half2_rn(lo, hi);
    return *(uint32_t *)&h;
}

__device__ __forceinline__ uint32_t ld32(const __half *p) { return *(const uint32_t *)p; }

/* grid (ceil(T / 64), H, B), 128 threads. D: head width (16, 32 or 64). */
template <int D>
__global__ void __launch_bounds__(FWARPS * 32) k_flash(const __half *__restrict__ qkv, __half *__restrict__ out,
                                                      int T, int w, float scale_log2, int causal, int qq)
{
    constexpr int KS = D / 16; /* k-steps of the q k^T product */
    constexpr int ND = D / 8;  /* n-tiles of the output */
    constexpr int LD = D + 8;  /* padded smem rows: conflict-free fragment reads and ldmatrix */
    __shared__ __align__(16) __half Ks[FK][LD];
    __shared__ __align__(16) __half Vs[FK][LD];
    const int lane = threadIdx.x & 31, warp = threadIdx.x >> 5, g = lane >> 2, t = lane & 3;
    const int h = blockIdx.y, b = blockIdx.z, q0 = blockIdx.x * FQ, r0 = q0 + warp * 16;
    const size_t ld = 3 * (size_t)w;
    const __half *base = qkv + (size_t)b * T * ld + (size_t)h * D;
    const __half *kb = base + (qq ? 0 : w), *vb = base + 2 * (size_t)w;
    const bool active = r0 < T;

    /* this warp's 16 query rows as A fragments (rows past T read as zero) */
    uint32_t qa[KS][4];
    {
        int ra = r0 + g, rb = r0 + g + 8;
#pragma unroll
        for (int kk = 0; kk < KS; kk++) {
            int c = 16 * kk + 2 * t;
            qa[kk][0] = ra < T ? ld32(base + ra * ld + c) : 0u;
            qa[kk][1] = rb < T ? ld32(base + rb * ld + c) : 0u;
            qa[kk][2] = ra < T ? ld32(base + ra * ld + c + 8) : 0u;
            qa[kk][3] = rb < T ? ld32(base + rb * ld + c + 8) : 0u;
        }
    }
    float o[ND][4];
#pragma unroll
    for (int j = 0; j < ND; j++) o[j][0] = o[j][1] = o[j][2] = o[j][3] = 0.f;
    float m0 = -INFINITY, m1 = -INFINITY, l0 = 0.f, l1 = 0.f;
    const int qa_row = r0 + g, qb_row = r0 + g + 8;

    int n_tiles = (T + FK - 1) / FK;
    if (causal) {
        int last = (q0 + FQ - 1) / FK + 1; /* keys beyond the block's last query are masked */
        if (last < n_tiles) n_tiles = last;
    }
    for (int kt = 0; kt < n_tiles; kt++) {
        const int k0 = kt * FK;
        /* K and V tiles: 16-byte chunks, rows past T zero (never garbage: 0 * NaN is NaN) */
        for (int i = threadIdx.x; i < FK * D / 8; i += FWARPS * 32) {
            int row = i / (D / 8), c8 = (i % (D / 8)) * 8, key = k0 + row;
            uint4 kv = make_uint4(0, 0, 0, 0), vv = make_uint4(0, 0, 0, 0);
            if (key < T) {
                kv = *(const uint4 *)(kb + key * ld + c8);
                vv = *(const uint4 *)(vb + key * ld + c8);
            }
            *(uint4 *)&Ks[row][c8] = kv;
            *(uint4 *)&Vs[row][c8] = vv;
        }
        __syncthreads();
        const int valid = T - k0 < FK ? T - k0 : FK;   /* keys of this tile that exist */
        const int nj = (valid + 7) / 8, nk = (valid + 15) / 16;
        if (active) {
            float s[FK / 8][4];
#pragma unroll
            for (int j = 0; j < FK / 8; j++) {
                s[j][0] = s[j][1] = s[j][2] = s[j][3] = 0.f;
                if (j < nj) {
#pragma unroll
                    for (int kk = 0; kk < KS; kk++) {
                        uint32_t b0 = ld32(&Ks[8 * j + g][16 * kk + 2 * t]);
                        uint32_t b1 = ld32(&Ks[8 * j + g][16 * kk + 2 * t + 8]);
                        mma16816(s[j], qa[kk], b0, b1);
                    }
                }
            }
            /* mask, running max per row (the 4 lanes of a quad share a row) */
            float mx0 = -INFINITY, mx1 = -INFINITY;
#pragma unroll
            for (int j = 0; j < FK / 8; j++)
#pragma unroll
                for (int e = 0; e < 4; e++) {
                    int key = k0 + 8 * j + 2 * t + (e & 1), q = e < 2 ? qa_row : qb_row;
                    bool off = key >= T || (causal && key > q);
                    s[j][e] = off ? -INFINITY : s[j][e];
                    if (e < 2) mx0 = fmaxf(mx0, s[j][e]);
                    else mx1 = fmaxf(mx1, s[j][e]);
                }
#pragma unroll
            for (int d = 1; d <= 2; d <<= 1) {
                mx0 = fmaxf(mx0, __shfl_xor_sync(0xffffffffu, mx0, d));
                mx1 = fmaxf(mx1, __shfl_xor_sync(0xffffffffu, mx1, d));
            }
            float n0 = fmaxf(m0, mx0), n1 = fmaxf(m1, mx1);
            /* a row with nothing unmasked yet keeps 0 as its reference (no inf - inf) */
            float u0 = n0 == -INFINITY ? 0.f : n0, u1 = n1 == -INFINITY ? 0.f : n1;
            float al0 = exp2f((m0 - u0) * scale_log2), al1 = exp2f((m1 - u1) * scale_log2);
            m0 = n0;
            m1 = n1;
            l0 *= al0;
            l1 *= al1;
#pragma unroll
            for (int j = 0; j < ND; j++) {
                o[j][0] *= al0;
                o[j][1] *= al0;
                o[j][2] *= al1;
                o[j][3] *= al1;
            }
#pragma unroll
            for (int j = 0; j < FK / 8; j++) {
                s[j][0] = exp2f((s[j][0] - u0) * scale_log2);
                s[j][1] = exp2f((s[j][1] - u0) * scale_log2);
                s[j][2] = exp2f((s[j][2] - u1) * scale_log2);
                s[j][3] = exp2f((s[j][3] - u1) * scale_log2);
                l0 += s[j][0] + s[j][1];
                l1 += s[j][2] + s[j][3];
            }
            /* O += P V, 16 keys per k-step; V fragments by transposed ldmatrix */
#pragma unroll
            for (int kk = 0; kk < FK / 16; kk++) {
                if (kk < nk) {
                    uint32_t pa[4] = {pack_half2(s[2 * kk][0], s[2 * kk][1]), pack_half2(s[2 * kk][2], s[2 * kk][3]),
                                      pack_half2(s[2 * kk + 1][0], s[2 * kk + 1][1]),
                                      pack_half2(s[2 * kk + 1][2], s[2 * kk + 1][3])};
                    const int mi = lane >> 3, rr = lane & 7;
#pragma unroll
                    for (int jp = 0; jp < D / 16; jp++) {
                        uint32_t vf[4];
                        ldmatrix_x4_trans(vf, &Vs[16 * kk + (mi & 1) * 8 + rr][16 * jp + (mi >> 1) * 8]);
                        mma16816(o[2 * jp], pa, vf[0], vf[1]);
                        mma16816(o[2 * jp + 1], pa, vf[2], vf[3]);
                    }
                }
            }
        }
        __syncthreads();
    }
    if (!active) return;
#pragma unroll
    for (int d = 1; d <= 2; d <<= 1) {
        l0 += __shfl_xor_sync(0xffffffffu, l0, d);
        l1 += __shfl_xor_sync(0xffffffffu, l1, d);
    }
    float i0 = l0 > 0 ? 1.f / l0 : 0.f, i1 = l1 > 0 ? 1.f / l1 : 0.f;
    __half *ob = out + (size_t)b * T * w + (size_t)h * D;
#pragma unroll
    for (int j = 0; j < ND; j++) {
        int c = 8 * j + 2 * t;
        if (qa_row < T) *(__half2 *)(ob + (size_t)qa_row * w + c) = __floats2half2_rn(o[j][0] * i0, o[j][1] * i0);
        if (qb_row < T) *(__half2 *)(ob + (size_t)qb_row * w + c) = __floats2half2_rn(o[j][2] * i1, o[j][3] * i1);
    }
}

int flash_attention(const __half *qkv, int B, int Tn, int H, int w, int causal, int qq, __half *out, cudaStream_t st)
{
    int D = w / H;
    /* 16-byte rows of K/V need the fused row (3w halves) and each head to start on 8 halves */
    if (w % H || (D != 16 && D != 32 && D != 64) || w % 8 || B < 1 || Tn < 1 || B > 65535) return 1;
    float sl2 = 1.4426950408889634f / sqrtf((float)D);
    dim3 grid((Tn + FQ - 1) / FQ, H, B);
    if (D == 64) k_flash<64><<<grid, FWARPS * 32, 0, st>>>(qkv, out, Tn, w, sl2, causal, qq);
    else if (D == 32) k_flash<32><<<grid, FWARPS * 32, 0, st>>>(qkv, out, Tn, w, sl2, causal, qq);
    else k_flash<16><<<grid, FWARPS * 32, 0, st>>>(qkv, out, Tn, w, sl2, causal, qq);
    return 0;
}

/* ---- test hook: the kernel alone on host data -------------------------------------------------- */

__global__ void k_half_to_float(const __half *x, float *y, size_t n)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < n; i += (size_t)gridDim.x * blockDim.x)
        y[i] = __half2float(x[i]);
}

extern "C" int clip_gpu_attention_check(sp_device *dev, const float *qkv, int B, int T, int H, int w, int causal,
                                        int qq, float *out, sp_error *err)
{
    size_t nin = (size_t)B * T * 3 * w, nout = (size_t)B * T * w;
    int d = H > 0 && w % H == 0 ? w / H : 0;
    if ((d != 16 && d != 32 && d != 64) || w % 8 || B < 1 || T < 1)
        return sp_error_set(err, SP_E_UNSUPPORTED, "fused attention: width %d with %d heads", w, H);
    cudaStream_t st = sp_cuda_stream(dev);
    float *f = (float *)sp_device_alloc_scratch(dev, (nin + nout) * sizeof(float), err);
    __half *h = (__half *)sp_device_alloc_scratch(dev, (nin + nout) * sizeof(__half), err);
    int rc = 0;
    if (!f || !h) rc = sp_error_prefix(err, "fused attention check: ");
    else if (cudaMemcpyAsync(f, qkv, nin * sizeof(float), cudaMemcpyHostToDevice, st) != cudaSuccess)
        rc = sp_error_set(err, SP_E_DEVICE, "fused attention check: upload failed");
    if (!rc) {
        launch_f32_to_f16(f, h, (long)nin, st);
        /* poison the output: every element must be written */
        cudaMemsetAsync(h + nin, 0xff, nout * sizeof(__half), st);
        flash_attention(h, B, T, H, w, causal, qq, h + nin, st);
        k_half_to_float<<<256, 256, 0, st>>>(h + nin, f + nin, nout);
        if (cudaMemcpyAsync(out, f + nin, nout * sizeof(float), cudaMemcpyDeviceToHost, st) != cudaSuccess ||
            cudaStreamSynchronize(st) != cudaSuccess)
            rc = sp_error_set(err, SP_E_DEVICE, "fused attention check: %s", cudaGetErrorString(cudaGetLastError()));
    }
    sp_device_release(dev, f);
    sp_device_release(dev, h);
    return rc;
}
