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

/* the same, not transposed (K rows as the B operand of Q K^T); x2: matrices 0 and 1 only */
__device__ __forceinline__ void ldmatrix_x4(uint32_t r[4], const __half *p)
{
    unsigned a = (unsigned)__cvta_generic_to_shared(p);
    asm volatile("ldmatrix.sync.aligned.m8n8.x4.shared.b16 {%0,%1,%2,%3}, [%4];\n"
                 : "=r"(r[0]), "=r"(r[1]), "=r"(r[2]), "=r"(r[3])
                 : "r"(a));
}
__device__ __forceinline__ void ldmatrix_x2(uint32_t r[2], const __half *p)
{
    unsigned a = (unsigned)__cvta_generic_to_shared(p);
    asm volatile("ldmatrix.sync.aligned.m8n8.x2.shared.b16 {%0,%1}, [%2];\n" : "=r"(r[0]), "=r"(r[1]) : "r"(a));
}

/* 16 bytes global -> shared without a register round trip; src_bytes 0 writes zeros */
__device__ __forceinline__ void cp_async16(__half *dst, const __half *src, int src_bytes)
{
    unsigned a = (unsigned)__cvta_generic_to_shared(dst);
    asm volatile("cp.async.cg.shared.global [%0], [%1], 16, %2;\n" ::"r"(a), "l"(src), "r"(src_bytes));
}
__device__ __forceinline__ void cp_async_commit() { asm volatile("cp.async.commit_group;\n" ::); }
template <int N> __device__ __forceinline__ void cp_async_wait() { asm volatile("cp.async.wait_group %0;\n" ::"n"(N)); }
/* wait until at most n of this thread's groups are in flight (fewer when n > 3: still correct) */
__device__ __forceinline__ void cp_async_wait_upto(int n)
{
    if (n <= 0) cp_async_wait<0>();
    else if (n == 1) cp_async_wait<1>();
    else if (n == 2) cp_async_wait<2>();
    else cp_async_wait<3>();
}

/* 2^x on the MUFU alone: exp2f without fast math adds the denormal fix-up around it, and these
 * are probabilities headed for fp16 (ex2(-inf) = 0 still) */
__device__ __forceinline__ float ex2(float x)
{
    float y;
    asm("ex2.approx.ftz.f32 %0, %1;" : "=f"(y) : "f"(x));
    return y;
}

__device__ __forceinline__ uint32_t pack_half2(float lo, float hi)
{
    __half2 h = __floats2half2_rn(lo, hi);
    return *(uint32_t *)&h;
}

__device__ __forceinline__ uint32_t ld32(const __half *p) { return *(const uint32_t *)p; }

/* Per-warp state: 16 query rows as A fragments, the output accumulators, running max and sum of
 * rows g and g + 8 (of the lane's quad). */
template <int D> struct warp_rows {
    uint32_t qa[D / 16][4];
    float o[D / 8][4];
    float m0, m1, l0, l1;
    int ra, rb; /* the lane's two query rows */
};

/* rows r0 .. r0+15 of q (rows past T read as zero), accumulators cleared */
template <int D>
__device__ __forceinline__ void rows_begin(warp_rows<D> &w, const __half *qb, size_t ld, int r0, int T, int g, int t,
                                           bool load_q = true)
{
    w.ra = r0 + g;
    w.rb = r0 + g + 8;
#pragma unroll
    for (int kk = 0; kk < D / 16; kk++) {
        if (!load_q) break; /* the caller fills qa (rows_q_smem) */
        int c = 16 * kk + 2 * t;
        w.qa[kk][0] = w.ra < T ? ld32(qb + w.ra * ld + c) : 0u;
        w.qa[kk][1] = w.rb < T ? ld32(qb + w.rb * ld + c) : 0u;
        w.qa[kk][2] = w.ra < T ? ld32(qb + w.ra * ld + c + 8) : 0u;
        w.qa[kk][3] = w.rb < T ? ld32(qb + w.rb * ld + c + 8) : 0u;
    }
#pragma unroll
    for (int j = 0; j < D / 8; j++) w.o[j][0] = w.o[j][1] = w.o[j][2] = w.o[j][3] = 0.f;
    w.m0 = w.m1 = -INFINITY;
    w.l0 = w.l1 = 0.f;
}

/* The 16 query rows as A fragments from a warp's shared copy (row stride LD), by ldmatrix: lane
 * 8 i + r gives row r + 8 (i & 1), columns 8 (i >> 1).. of each 16-column k-step. */
template <int D, int LD> __device__ __forceinline__ void rows_q_smem(warp_rows<D> &w, const __half *Qw, int lane)
{
    const __half *p = Qw + ((lane & 7) + 8 * ((lane >> 3) & 1)) * LD + 8 * (lane >> 4);
#pragma unroll
    for (int kk = 0; kk < D / 16; kk++) ldmatrix_x4(w.qa[kk], p + 16 * kk);
}

/* One tile of FK keys starting at key k0, its rows in shared memory at Ks / Vs (row stride LD):
 * scores, mask, online softmax, O += P V. Keys past T must read as zero rows. */
template <int D, int LD, int KW>
__device__ __forceinline__ void tile_step_k(warp_rows<D> &w, const __half *Ks, const __half *Vs, int k0, int T,
                                            int causal, float scale_log2, int lane)
{
    const int g = lane >> 2, t = lane & 3;
    const int valid = T - k0 < FK ? T - k0 : FK; /* keys of this tile that exist */
    /* KW (16, 32, 48 or 64): the step covers KW key rows, a compile-time bound, so the unrolled
     * loops have no branches and ptxas can interleave the fragment loads, products and
     * exponentials of all n-tiles (one basic block); rows past T are masked. */
    const int nj = KW / 8, nk = KW / 16;
    float s[FK / 8][4];
#pragma unroll
    for (int j = 0; j < FK / 8; j++) {
        s[j][0] = s[j][1] = s[j][2] = s[j][3] = 0.f;
        if (j < nj) {
            /* lane 8 i + r: key row 8 j + r, dims 8 i.. of a 32-dim pair of k-steps */
            const __half *kr = Ks + (8 * j + (lane & 7)) * LD + 8 * (D == 16 ? (lane >> 3) & 1 : lane >> 3);
            if (D == 16) {
                uint32_t kf[2];
                ldmatrix_x2(kf, kr);
                mma16816(s[j], w.qa[0], kf[0], kf[1]);
            } else {
#pragma unroll
                for (int kp = 0; kp < D / 32; kp++) {
                    uint32_t kf[4];
                    ldmatrix_x4(kf, kr + 32 * kp);
                    mma16816(s[j], w.qa[2 * kp], kf[0], kf[1]);
                    mma16816(s[j], w.qa[2 * kp + 1], kf[2], kf[3]);
                }
            }
        }
    }
    /* mask (only where the tile is partial or the attention causal), running max per row */
    float mx0 = -INFINITY, mx1 = -INFINITY;
    const bool masked = valid < FK || (causal && k0 + FK - 1 > w.ra - g);
    if (masked) /* one branch around the whole mask (uniform: skipped in whole non-causal tiles) */
#pragma unroll
        for (int j = 0; j < nj; j++)
#pragma unroll
            for (int e = 0; e < 4; e++) {
                int key = k0 + 8 * j + 2 * t + (e & 1), q = e < 2 ? w.ra : w.rb;
                if (key >= T || (causal && key > q)) s[j][e] = -INFINITY;
            }
#pragma unroll
    for (int j = 0; j < nj; j++) { /* columns past nj: never in the max, probability 0 below */
        mx0 = fmaxf(mx0, fmaxf(s[j][0], s[j][1]));
        mx1 = fmaxf(mx1, fmaxf(s[j][2], s[j][3]));
    }
#pragma unroll
    for (int d = 1; d <= 2; d <<= 1) {
        mx0 = fmaxf(mx0, __shfl_xor_sync(0xffffffffu, mx0, d));
        mx1 = fmaxf(mx1, __shfl_xor_sync(0xffffffffu, mx1, d));
    }
    float n0 = fmaxf(w.m0, mx0), n1 = fmaxf(w.m1, mx1);
    /* a row with nothing unmasked yet keeps 0 as its reference (no inf - inf) */
    float u0 = n0 == -INFINITY ? 0.f : n0 * scale_log2, u1 = n1 == -INFINITY ? 0.f : n1 * scale_log2;
    float al0 = ex2(fmaf(w.m0, scale_log2, -u0)), al1 = ex2(fmaf(w.m1, scale_log2, -u1));
    w.m0 = n0;
    w.m1 = n1;
    w.l0 *= al0;
    w.l1 *= al1;
#pragma unroll
    for (int j = 0; j < D / 8; j++) {
        w.o[j][0] *= al0;
        w.o[j][1] *= al0;
        w.o[j][2] *= al1;
        w.o[j][3] *= al1;
    }
#pragma unroll
    for (int j = 0; j < FK / 8; j++) {
        if (j < nj) { /* past the last key: probability 0, no exp (the MUFU is a bottleneck) */
            s[j][0] = ex2(fmaf(s[j][0], scale_log2, -u0));
            s[j][1] = ex2(fmaf(s[j][1], scale_log2, -u0));
            s[j][2] = ex2(fmaf(s[j][2], scale_log2, -u1));
            s[j][3] = ex2(fmaf(s[j][3], scale_log2, -u1));
            w.l0 += s[j][0] + s[j][1];
            w.l1 += s[j][2] + s[j][3];
        } else {
            s[j][0] = s[j][1] = s[j][2] = s[j][3] = 0.f;
        }
    }
    /* O += P V, 16 keys per k-step; V fragments by transposed ldmatrix */
    const int mi = lane >> 3, rr = lane & 7;
#pragma unroll
    for (int kk = 0; kk < FK / 16; kk++) {
        if (kk < nk) {
            uint32_t pa[4] = {pack_half2(s[2 * kk][0], s[2 * kk][1]), pack_half2(s[2 * kk][2], s[2 * kk][3]),
                              pack_half2(s[2 * kk + 1][0], s[2 * kk + 1][1]),
                              pack_half2(s[2 * kk + 1][2], s[2 * kk + 1][3])};
#pragma unroll
            for (int jp = 0; jp < D / 16; jp++) {
                uint32_t vf[4];
                ldmatrix_x4_trans(vf, Vs + (16 * kk + (mi & 1) * 8 + rr) * LD + 16 * jp + (mi >> 1) * 8);
                mma16816(w.o[2 * jp], pa, vf[0], vf[1]);
                mma16816(w.o[2 * jp + 1], pa, vf[2], vf[3]);
            }
        }
    }
}

/* a tile by the specialisation of its width (whole tiles 64; the last one 16, 32, 48 or 64) */
template <int D, int LD>
__device__ __forceinline__ void tile_step(warp_rows<D> &w, const __half *Ks, const __half *Vs, int k0, int T,
                                          int causal, float scale_log2, int lane)
{
    /* the last tile's width rounded up to 16 rows: no row past the resident kernel's Tp */
    int kw = T - k0 >= FK ? FK : (T - k0 + 15) & ~15;
    if (kw == 64) tile_step_k<D, LD, 64>(w, Ks, Vs, k0, T, causal, scale_log2, lane);
    else if (kw == 48) tile_step_k<D, LD, 48>(w, Ks, Vs, k0, T, causal, scale_log2, lane);
    else if (kw == 32) tile_step_k<D, LD, 32>(w, Ks, Vs, k0, T, causal, scale_log2, lane);
    else tile_step_k<D, LD, 16>(w, Ks, Vs, k0, T, causal, scale_log2, lane);
}

/* the finished rows (past T not written) into out rows of width w at column offset ob */
template <int D>
__device__ __forceinline__ void rows_end(warp_rows<D> &w, __half *ob, int wd, int T, int t)
{
#pragma unroll
    for (int d = 1; d <= 2; d <<= 1) {
        w.l0 += __shfl_xor_sync(0xffffffffu, w.l0, d);
        w.l1 += __shfl_xor_sync(0xffffffffu, w.l1, d);
    }
    float i0 = w.l0 > 0 ? 1.f / w.l0 : 0.f, i1 = w.l1 > 0 ? 1.f / w.l1 : 0.f;
#pragma unroll
    for (int j = 0; j < D / 8; j++) {
        int c = 8 * j + 2 * t;
        if (w.ra < T) *(__half2 *)(ob + (size_t)w.ra * wd + c) = __floats2half2_rn(w.o[j][0] * i0, w.o[j][1] * i0);
        if (w.rb < T) *(__half2 *)(ob + (size_t)w.rb * wd + c) = __floats2half2_rn(w.o[j][2] * i1, w.o[j][3] * i1);
    }
}

/* key rows [k0, k0 + n) of K and V into shared rows of stride LD, 16-byte chunks by all threads
 * (rows past T zero: never garbage, 0 * NaN is NaN) */
template <int D, int LD>
__device__ __forceinline__ void load_kv(__half *Ks, __half *Vs, const __half *kb, const __half *vb, size_t ld, int k0,
                                        int n, int T)
{
    for (int i = threadIdx.x; i < n * (D / 8); i += blockDim.x) {
        int row = i / (D / 8), c8 = (i % (D / 8)) * 8, key = k0 + row;
        uint4 kv = make_uint4(0, 0, 0, 0), vv = make_uint4(0, 0, 0, 0);
        if (key < T) {
            kv = *(const uint4 *)(kb + key * ld + c8);
            vv = *(const uint4 *)(vb + key * ld + c8);
        }
        *(uint4 *)(Ks + row * LD + c8) = kv;
        *(uint4 *)(Vs + row * LD + c8) = vv;
    }
}

/* v1, any length: grid (ceil(T / 64), H, B), 4 warps of 16 queries, key/value tiles streamed
 * through shared memory. */
template <int D>
__global__ void __launch_bounds__(FWARPS * 32, 3) k_flash(const __half *__restrict__ qkv, __half *__restrict__ out,
                                                      int T, int w, float scale_log2, int causal, int qq)
{
    constexpr int LD = D + 8; /* padded smem rows: conflict-free fragment reads and ldmatrix */
    __shared__ __align__(16) __half Ks[FK * LD];
    __shared__ __align__(16) __half Vs[FK * LD];
    const int lane = threadIdx.x & 31, warp = threadIdx.x >> 5;
    const int h = blockIdx.y, b = blockIdx.z, q0 = blockIdx.x * FQ, r0 = q0 + warp * 16;
    const size_t ld = 3 * (size_t)w;
    const __half *base = qkv + (size_t)b * T * ld + (size_t)h * D;
    const __half *kb = base + (qq ? 0 : w), *vb = base + 2 * (size_t)w;
    const bool active = r0 < T;
    warp_rows<D> wr;
    rows_begin(wr, base, ld, r0, T, lane >> 2, lane & 3);
    int n_tiles = (T + FK - 1) / FK;
    if (causal) {
        int last = (q0 + FQ - 1) / FK + 1; /* keys beyond the block's last query are masked */
        if (last < n_tiles) n_tiles = last;
    }
    for (int kt = 0; kt < n_tiles; kt++) {
        load_kv<D, LD>(Ks, Vs, kb, vb, ld, kt * FK, FK, T);
        __syncthreads();
        if (active) tile_step<D, LD>(wr, Ks, Vs, kt * FK, T, causal, scale_log2, lane);
        __syncthreads();
    }
    if (active) rows_end(wr, out + (size_t)b * T * w + (size_t)h * D, w, T, lane & 3);
}

/* v2, short sequences (the whole K and V of one head fit in shared memory): nq blocks per
 * (head, sequence) (grid (nq, H, B); nq = 1 in the towers: K and V read once) each load all of K
 * and V, then warp i of block q takes the 16-query chunks c = q * warps + i + k * nq * warps. Keys
 * are padded to Tp = T rounded up to 16 (zeros; tile_step reads no row past that). The loads go
 * out at once as cp.async groups of 64 keys, so each warp computes its first chunk's tile kt while
 * the later tiles are still arriving (every warp, with a chunk or not, passes the first round's
 * barriers); after the first round no barrier. Warps per block in the towers: the fewest that
 * keep the rounds (ceil(chunks / warps)) minimal, so no warp idles in the last round, e.g. 7 for
 * ViT-B/16's 197 tokens (13 chunks, 2 rounds). Dynamic shared memory 2 * Tp * (D + 8) halves. */
enum { SEQ_WARPS = 7 }; /* the most warps a block may have (forced modes); 144 registers a thread */
/* QSM: each warp's query rows also go through shared memory by cp.async (16 rows of D + 8 halves
 * per warp after K and V), the first chunk's ahead of the K/V groups and the next chunk's while
 * the current one computes, then by ldmatrix into the A fragments. */
/* __maxnreg__ instead of __launch_bounds__ (which cannot go together): 144 registers, 3 blocks of
 * 4 warps per SM; at 128 the branch-free full-tile step spills */
template <int D, bool QSM>
__global__ void __maxnreg__(144) k_flash_seq(const __half *__restrict__ qkv,
                                                                 __half *__restrict__ out, int T, int w,
                                                                 float scale_log2, int causal, int qq)
{
    constexpr int LD = D + 8, C8 = D / 8; /* 16-byte chunks per row */
    extern __shared__ __align__(16) __half kv_smem[];
    const int Tp = (T + 15) & ~15, nt = (Tp + FK - 1) / FK, nwarps = blockDim.x >> 5;
    __half *Ks = kv_smem, *Vs = kv_smem + (size_t)Tp * LD;
    const int lane = threadIdx.x & 31, warp = threadIdx.x >> 5;
    __half *Qw = kv_smem + (size_t)2 * Tp * LD + (size_t)warp * 16 * LD; /* QSM only */
    const int h = blockIdx.y, b = blockIdx.z, stride = (int)gridDim.x * nwarps * 16;
    const size_t ld = 3 * (size_t)w;
    const __half *base = qkv + (size_t)b * T * ld + (size_t)h * D;
    const __half *kb = base + (qq ? 0 : w), *vb = base + 2 * (size_t)w;
    /* this warp's 16 query rows from r0 into Qw, one cp.async group */
    auto q_copy = [&](int r0) {
        for (int i = lane; i < 16 * C8; i += 32) {
            int row = i / C8, c8 = (i % C8) * 8, q = r0 + row;
            cp_async16(Qw + row * LD + c8, base + (size_t)(q < T ? q : 0) * ld + c8, q < T ? 16 : 0);
        }
        cp_async_commit();
    };
    int r0 = ((int)blockIdx.x * nwarps + warp) * 16;
    if (QSM) q_copy(r0);
    for (int kt = 0; kt < nt; kt++) {
        int end = (kt + 1) * FK < Tp ? (kt + 1) * FK : Tp;
        for (int i = kt * FK * C8 + threadIdx.x; i < end * C8; i += blockDim.x) {
            int row = i / C8, c8 = (i % C8) * 8, ok = row < T ? 16 : 0, src = row < T ? row : 0;
            cp_async16(Ks + row * LD + c8, kb + src * ld + c8, ok);
            cp_async16(Vs + row * LD + c8, vb + src * ld + c8, ok);
        }
        cp_async_commit();
    }
    __half *ob = out + (size_t)b * T * w + (size_t)h * D;
    /* one copy of the loop (one inlined tile_step keeps the registers down) */
    for (int first = 1; first || r0 < T; r0 += stride, first = 0) {
        const bool active = r0 < T;
        warp_rows<D> wr;
        rows_begin(wr, base, ld, r0, T, lane >> 2, lane & 3, !QSM); /* global loads in flight with the copies */
        int ahead = 0; /* QSM: the next chunk's query copy is in flight (the newest group) */
        if (QSM && !first) {
            cp_async_wait<0>(); /* only this chunk's query copy was pending */
            __syncwarp();
            rows_q_smem<D, LD>(wr, Qw, lane);
            __syncwarp(); /* read before the next copy overwrites it */
            if (r0 + stride < T) q_copy(r0 + stride);
        }
        int n_tiles = causal && r0 / FK + 1 < nt ? r0 / FK + 1 : nt; /* keys past row r0 + 15 are masked */
        int steps = first ? nt : n_tiles;
        for (int kt = 0; kt < steps; kt++) {
            if (first) {
                /* groups: [query,] tiles 0 .. nt - 1[, next query]: tile kt (and what came before) landed */
                cp_async_wait_upto(nt - 1 - kt + ahead);
                __syncthreads(); /* every thread's part of tile kt has landed */
                if (QSM && kt == 0) {
                    rows_q_smem<D, LD>(wr, Qw, lane);
                    __syncwarp();
                    if (r0 + stride < T) {
                        q_copy(r0 + stride);
                        ahead = 1;
                    }
                }
            }
            if (active && kt < n_tiles)
                tile_step<D, LD>(wr, Ks + (size_t)kt * FK * LD, Vs + (size_t)kt * FK * LD, kt * FK, T, causal,
                                 scale_log2, lane);
        }
        if (active) rows_end(wr, ob, w, T, lane & 3);
    }
}

static size_t seq_smem(int T, int D) { return (size_t)2 * ((T + 15) / 16 * 16) * (D + 8) * sizeof(__half); }
static size_t seq_q_smem(int warps, int D) { return (size_t)warps * 16 * (D + 8) * sizeof(__half); }
enum { SEQ_SMEM_MAX = 200 * 1024 }; /* Hopper gives a block up to 227 KB; leave room */

/* warps of the resident kernel for T tokens: as many rounds as AUTO_WARPS warps need, with the
 * fewest warps. 4, not 7: registers are split per SM quarter (16K each, one warp scheduler), so
 * blocks of 7 warps at 144 registers fit once per SM (2 + 2 + 2 + 1 warps; Nsight Compute: block
 * limit registers 1, 10.9% occupancy) while blocks of 4 fit three times. Round 2 on the H200:
 * 89.6 us a layer at ViT-B/16 batch 128 (4 warps) against 123.2 (7); 34.3 us for the text batch
 * 256 (3 warps) against 42.5 (5). */
enum { AUTO_WARPS = 4 };
static int seq_warps(int T)
{
    int chunks = (T + 15) / 16, rounds = (chunks + AUTO_WARPS - 1) / AUTO_WARPS;
    return (chunks + rounds - 1) / rounds;
}

template <int D, bool QSM> static int launch_seq(const __half *qkv, int B, int Tn, int H, int w, int causal, int qq,
                                                __half *out, int warps, int nq, float sl2, cudaStream_t st)
{
    size_t smem = seq_smem(Tn, D) + (QSM ? seq_q_smem(warps, D) : 0);
    if (smem > SEQ_SMEM_MAX) return 1;
    /* past 48 KB a block's dynamic shared memory needs the kernel's limit raised (cheap); the
     * carveout all shared memory, so that two blocks of ~60 KB fit beside each other */
    if (smem > 48 * 1024 &&
        cudaFuncSetAttribute(k_flash_seq<D, QSM>, cudaFuncAttributeMaxDynamicSharedMemorySize, (int)smem) != cudaSuccess)
        return 1;
    cudaFuncSetAttribute(k_flash_seq<D, QSM>, cudaFuncAttributePreferredSharedMemoryCarveout,
                         (int)cudaSharedmemCarveoutMaxShared); /* a hint: refused is harmless */
    k_flash_seq<D, QSM><<<dim3(nq, H, B), warps * 32, smem, st>>>(qkv, out, Tn, w, sl2, causal, qq);
    return 0;
}

template <int D> static int launch_flash(const __half *qkv, int B, int Tn, int H, int w, int causal, int qq,
                                         __half *out, int mode, cudaStream_t st)
{
    float sl2 = 1.4426950408889634f / sqrtf((float)D);
    if (mode != FLASH_TILED) {
        /* the towers: queries through shared memory too (round 1 on the H200: 156 against 168 us
         * a layer at ViT-B/16 batch 128, 46 against 48 for the text batch 256) */
        int warps = seq_warps(Tn), nq = 1, chunks = (Tn + 15) / 16, qsm = 1;
        if (mode >= FLASH_RESIDENT && mode % 100 >= 1 && mode % 100 <= SEQ_WARPS) { /* forced */
            qsm = mode >= FLASH_QSMEM;
            warps = mode % 100 < chunks ? mode % 100 : chunks;
            nq = mode % FLASH_QSMEM / 100;
            if (nq < 1) nq = 1;
            if (nq > (chunks + warps - 1) / warps) nq = (chunks + warps - 1) / warps;
        }
        if (!(qsm ? launch_seq<D, true> : launch_seq<D, false>)(qkv, B, Tn, H, w, causal, qq, out, warps, nq, sl2, st))
            return 0;
    }
    k_flash<D><<<dim3((Tn + FQ - 1) / FQ, H, B), FWARPS * 32, 0, st>>>(qkv, out, Tn, w, sl2, causal, qq);
    return 0;
}

int flash_attention(const __half *qkv, int B, int Tn, int H, int w, int causal, int qq, __half *out, int mode,
                    cudaStream_t st)
{
    int D = w / H;
    /* 16-byte rows of K/V need the fused row (3w halves) and each head to start on 8 halves */
    if (w % H || (D != 16 && D != 32 && D != 64) || w % 8 || B < 1 || Tn < 1 || B > 65535) return 1;
    if (D == 64) return launch_flash<64>(qkv, B, Tn, H, w, causal, qq, out, mode, st);
    if (D == 32) return launch_flash<32>(qkv, B, Tn, H, w, causal, qq, out, mode, st);
    return launch_flash<16>(qkv, B, Tn, H, w, causal, qq, out, mode, st);
}

/* ---- test hook: the kernel alone on host data -------------------------------------------------- */

__global__ void k_half_to_float(const __half *x, float *y, size_t n)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < n; i += (size_t)gridDim.x * blockDim.x)
        y[i] = __half2float(x[i]);
}

extern "C" int clip_gpu_attention_check(sp_device *dev, const float *qkv, int B, int T, int H, int w, int causal,
                                        int qq, int mode, float *out, sp_error *err)
{
    size_t nin = (size_t)B * T * 3 * w, nout = (size_t)B * T * w;
    int d = H > 0 && w % H == 0 ? w / H : 0;
    if ((d != 16 && d != 32 && d != 64) || w % 8 || B < 1 || T < 1)
        return sp_error_set(err, SP_E_UNSUPPORTED, "fused attention: width %d with %d heads", w, H);
    cudaStream_t st = sp_cuda_stream(dev);
    float *f = (float *)sp_device_alloc_scratch(dev, (nin + nout) * sizeof(float), err);
    __half *h = f ? (__half *)sp_device_alloc_scratch(dev, (nin + nout) * sizeof(__half), err) : NULL;
    int rc = 0;
    if (!f || !h) rc = sp_error_prefix(err, "fused attention check: ");
    else if (cudaMemcpyAsync(f, qkv, nin * sizeof(float), cudaMemcpyHostToDevice, st) != cudaSuccess)
        rc = sp_error_set(err, SP_E_DEVICE, "fused attention check: upload failed");
    if (!rc) {
        launch_f32_to_f16(f, h, (long)nin, st);
        /* poison the output: every element must be written */
        cudaMemsetAsync(h + nin, 0xff, nout * sizeof(__half), st);
        if (flash_attention(h, B, T, H, w, causal, qq, h + nin, mode, st))
            rc = sp_error_set(err, SP_E_DEVICE, "fused attention check: the kernel refused %d x %d", B, H);
    }
    if (!rc) {
        k_half_to_float<<<256, 256, 0, st>>>(h + nin, f + nin, nout);
        cudaError_t e = cudaGetLastError();
        if (e == cudaSuccess && cudaMemcpyAsync(out, f + nin, nout * sizeof(float), cudaMemcpyDeviceToHost, st) == cudaSuccess)
            e = cudaStreamSynchronize(st);
        else if (e == cudaSuccess)
            e = cudaErrorUnknown;
        if (e != cudaSuccess) rc = sp_error_set(err, SP_E_DEVICE, "fused attention check: %s", cudaGetErrorString(e));
    }
    sp_device_release(dev, f);
    sp_device_release(dev, h);
    return rc;
}

/* ---- benchmark hook: the kernel alone on random device data ---------------------------------------- */

__global__ void k_fill_random(__half *x, size_t n, uint32_t seed)
{
    for (size_t i = blockIdx.x * (size_t)blockDim.x + threadIdx.x; i < n; i += (size_t)gridDim.x * blockDim.x) {
        uint32_t h = (uint32_t)i * 2654435761u ^ seed;
        h ^= h >> 15;
        h *= 2246822519u;
        h ^= h >> 13;
        x[i] = __float2half(((float)(h & 0xffff) / 65535.f - 0.5f) * 3.f); /* [-1.5, 1.5] */
    }
}

extern "C" int clip_gpu_attention_bench(sp_device *dev, int B, int T, int H, int w, int causal, int mode, int reps,
                                        double *us, sp_error *err)
{
    size_t nin = (size_t)B * T * 3 * w, nout = (size_t)B * T * w;
    cudaStream_t st = sp_cuda_stream(dev);
    __half *h = (__half *)sp_device_alloc_scratch(dev, (nin + nout) * sizeof(__half), err);
    if (!h) return sp_error_prefix(err, "fused attention bench: ");
    cudaEvent_t e0 = NULL, e1 = NULL;
    int rc = 0;
    k_fill_random<<<1024, 256, 0, st>>>(h, nin, 12345u);
    if (cudaEventCreate(&e0) != cudaSuccess || cudaEventCreate(&e1) != cudaSuccess ||
        flash_attention(h, B, T, H, w, causal, 0, h + nin, mode, st)) /* warm-up; refusals show here */
        rc = sp_error_set(err, SP_E_UNSUPPORTED, "fused attention bench: %d x %d heads of width %d refused", B, H, w / H);
    if (!rc) {
        cudaEventRecord(e0, st);
        for (int r = 0; r < reps; r++) flash_attention(h, B, T, H, w, causal, 0, h + nin, mode, st);
        cudaEventRecord(e1, st);
        float ms = 0;
        cudaError_t e = cudaEventSynchronize(e1);
        if (e == cudaSuccess) e = cudaGetLastError();
        if (e == cudaSuccess) e = cudaEventElapsedTime(&ms, e0, e1);
        if (e != cudaSuccess) rc = sp_error_set(err, SP_E_DEVICE, "fused attention bench: %s", cudaGetErrorString(e));
        *us = 1000.0 * ms / (reps > 0 ? reps : 1);
    }
    if (e0) cudaEventDestroy(e0);
    if (e1) cudaEventDestroy(e1);
    sp_device_release(dev, h);
    return rc;
}
