/* CUDA backend, stage 4 for wide chunks on tensor cores (cfg.bwd_gather = 2; sm_80 and later,
 * chunks of 32, 40, 48 and 64 channels): the product kernel of rasterize_bwd_mm.cu with both of a
 * stage's D-wide sums as matrix products on tensor cores.
 *
 * Per stage of NB = 32 Gaussians over a tile's 256 pixels:
 *  (b) S[t][p] = colour_t . v_image_p, the colour term of dL/dalpha, is a [NB x CH] x [CH x 256]
 *      product formed BEFORE the walk (it depends on no transmittance): warp w forms the columns
 *      of its own 32 pixels, so only __syncwarp separates it from the walk that reads them, and
 *      skips the 16-row halves of the stage none of its pixels can still keep. The walk
 *      (stage_walk, bwd_common.cuh) reads S[t][p] where the pixel keeps t and writes the
 *      blending weight fac[t][p] over it, in place: one [NB][LDF] buffer for both.
 *  (a) v_colors[t][c] = sum_p fac[t][p] v_image[p][c], a [NB x 256] x [256 x CHP] product after
 *      the walk: 2 x CHP/16 output tiles of 16 x 16 over the 8 warps (at 32 channels two warps
 *      per tile, each half of the pixels, summed through shared memory), skipping the 32-pixel
 *      rows no pixel of which kept one of the tile's Gaussians; one atomic per Gaussian, channel
 *      and tile, as the product kernel.
 * Both are WMMA m16n16k8 TF32 with fp32 accumulation in the "3xTF32" split: each operand
 * a = hi + lo (hi = tf32(a), lo = tf32(a - hi)) and acc += lo*hi + hi*lo + hi*hi, which keeps
 * about 21 bits of each product (the dropped lo*lo is below 2^-21 relative), so the result stays
 * within float-level error of the CUDA-core sums. Everything else (geometry sums, alpha,
 * transmittance) is the product kernel's.
 *
 * Not measured on a GPU yet (see docs/DESIGN.md). WMMA rules followed: every tile pointer is
 * 256-bit aligned (buffers start at multiples of 32 bytes; tile offsets are multiples of 8
 * floats in columns and 16 rows), every leading dimension a multiple of 4 floats. The leading
 * dimensions are padded by 4 floats (260 for fac, CHP + 4 for v_image and colours) so the rows
 * of a fragment fall in different shared-memory banks. */
#include "bwd_common.cuh"

#include <mma.h>

#if !defined(__CUDA_ARCH__) || __CUDA_ARCH__ >= 800
#define TC_HAVE_MMA 1
#endif

namespace {

namespace wm = nvcuda::wmma;

#define LDF (BLOCK + 4) /* row stride of the [NB] x 256 S / fac buffer */

/* shapes of one width's products */
template <int CH>
struct tc_dims {
    static constexpr int CHP = (CH + 15) / 16 * 16; /* channels of product (a), padded to tiles */
    static constexpr int LDV = CHP + 4;             /* row stride of v_image and colours */
    static constexpr int NTN = CHP / 16;            /* column tiles of v_colors */
    static constexpr int NT = 2 * NTN;              /* output tiles of v_colors ([NB] = 2 rows) */
    static constexpr int KS = NT == 4 ? 2 : 1;      /* warps per output tile (pixel halves) */
    static_assert(CH % 8 == 0, "product (b) runs over k steps of 8 channels");
    static_assert(NT * KS <= NWARPS, "one warp per output tile and pixel part");
};

#ifdef TC_HAVE_MMA
typedef wm::fragment<wm::accumulator, 16, 16, 8, float> acc_t;

/* Splits a loaded fragment into its TF32 high part (in place) and the TF32 rounding of the rest.
 * The mask makes hi exactly a TF32 value whatever cvt leaves in the low 13 bits, so x - hi is
 * exact. */
template <class Frag>
__device__ __forceinline__ void tf32_split(Frag &hi, Frag &lo)
{
#pragma unroll
    for (int i = 0; i < hi.num_elements; i++) {
        const float x = hi.x[i];
        const float h = __uint_as_float(__float_as_uint(wm::__float_to_tf32(x)) & 0xffffe000u);
        hi.x[i] = h;
        lo.x[i] = wm::__float_to_tf32(x - h);
    }
}

/* acc += a b in 3xTF32 (the small terms first) */
template <class FA, class FB>
__device__ __forceinline__ void mma3(acc_t &acc, const FA &ah, const FA &al, const FB &bh, const FB &bl)
{
    wm::mma_sync(acc, al, bh, acc);
    wm::mma_sync(acc, ah, bl, acc);
    wm::mma_sync(acc, ah, bh, acc);
}

/* Product (b) for warp `warp`: S[t][p] = sum_c col[t][c] v[p][c] for the row tiles m in
 * [m_lo, m_hi) (t in [16 m, 16 m + 16)) and this warp's pixels p in [32 warp, 32 warp + 32),
 * into s_s[t * LDF + p]. v[p][c] at s_vout[p * LDV + c] is the column-major [CH x 256] operand. */
template <int CH>
__device__ __forceinline__ void tc_scores(const float *s_col, const float *s_vout, float *s_s, int m_lo,
                                          int m_hi, int warp)
{
    constexpr int LDV = tc_dims<CH>::LDV;
    typedef wm::fragment<wm::matrix_a, 16, 16, 8, wm::precision::tf32, wm::row_major> fa_t;
    typedef wm::fragment<wm::matrix_b, 16, 16, 8, wm::precision::tf32, wm::col_major> fb_t;
    for (int m = m_lo; m < m_hi; m++) {
#pragma unroll 1
        for (int n = 0; n < 2; n++) { /* one accumulator at a time: registers for 3 blocks/SM */
            acc_t acc;
            wm::fill_fragment(acc, 0.f);
#pragma unroll 4
            for (int k = 0; k < CH / 8; k++) {
                fa_t ah, al;
                wm::load_matrix_sync(ah, s_col + 16 * m * LDV + 8 * k, LDV);
                tf32_split(ah, al);
                fb_t bh, bl;
                wm::load_matrix_sync(bh, s_vout + (32 * warp + 16 * n) * LDV + 8 * k, LDV);
                tf32_split(bh, bl);
                mma3(acc, ah, al, bh, bl);
            }
            wm::store_matrix_sync(s_s + 16 * m * LDF + 32 * warp + 16 * n, acc, LDF, wm::mem_row_major);
        }
    }
}

/* Product (a), one output tile's part: acc = sum over the pixels of warps' rows [w_lo, w_hi) of
 * fac[t][p] v[p][c] for t in [16 m, 16 m + 16), c in [16 n, 16 n + 16); rows whose byte of
 * `rows` is zero (no pixel there kept any of the tile's Gaussians: fac is 0) are skipped. */
template <int CH>
__device__ __forceinline__ void tc_colors(acc_t &acc, const float *s_fac, const float *s_vout,
                                          unsigned long long rows, int m, int n, int w_lo, int w_hi)
{
    constexpr int LDV = tc_dims<CH>::LDV;
    typedef wm::fragment<wm::matrix_a, 16, 16, 8, wm::precision::tf32, wm::row_major> fa_t;
    typedef wm::fragment<wm::matrix_b, 16, 16, 8, wm::precision::tf32, wm::row_major> fb_t;
    for (int w = w_lo; w < w_hi; w++) {
        if (!((rows >> (8 * w)) & 0xffu)) continue;
#pragma unroll
        for (int kk = 0; kk < 4; kk++) {
            const int k = 4 * w + kk; /* pixels [8 k, 8 k + 8) */
            fa_t ah, al;
            wm::load_matrix_sync(ah, s_fac + 16 * m * LDF + 8 * k, LDF);
            tf32_split(ah, al);
            fb_t bh, bl;
            wm::load_matrix_sync(bh, s_vout + 8 * k * LDV + 16 * n, LDV);
            tf32_split(bh, bl);
            mma3(acc, ah, al, bh, bl);
        }
    }
}
#endif

/* blocks per SM the registers are bounded for: 3 for 32 channels (its shared memory allows 3),
 * else 2 */
#define TC_MIN_BLOCKS(CH) ((CH) <= 32 ? 3 : 2)

template <int CH>
__global__ void __launch_bounds__(BLOCK, TC_MIN_BLOCKS(CH))
k_raster_bwd_tc(int W, int H, int tiles_x, const int2 *__restrict__ ranges,
                const uint32_t *__restrict__ ids, const float2 *__restrict__ means2d,
                const float4 *__restrict__ conic_op, const float *__restrict__ depths,
                const float *__restrict__ colors, int D, int c_base, const float *__restrict__ bg,
                const float *__restrict__ t_final, const int32_t *__restrict__ last_idx,
                const float *__restrict__ v_image, const float *__restrict__ v_depth,
                const float *__restrict__ v_alpha_out, int aux, float *__restrict__ v_colors,
                float *__restrict__ vgeo)
{
#ifdef TC_HAVE_MMA
    typedef tc_dims<CH> dm;
    constexpr int CHP = dm::CHP, LDV = dm::LDV;
    /* the WMMA operands first, each at a multiple of 32 bytes */
    extern __shared__ __align__(32) float smem_tc[];
    float *s_fac = smem_tc;            /* [NB][LDF]: S of product (b), then fac (in place) */
    float *s_vout = s_fac + NB * LDF;  /* [BLOCK][LDV] pixels' v_image */
    stage_smem st;
    st.col = s_vout + BLOCK * LDV;     /* [NB][LDV]: colours, then product (a)'s sums */
    st.conic = (float4 *)(st.col + NB * LDV);            /* [NB] */
    st.flag = (unsigned long long *)(st.conic + NB);     /* [NB] */
    st.xy = (float2 *)(st.flag + NB);                    /* [NB] */
    st.frame = st.xy + NB;                               /* [NB] */
    st.z = (float *)(st.frame + NB);                     /* [NB] */
    st.cut = st.z + NB;                                  /* [NB] */
    st.id = (int *)(st.cut + NB);                        /* [NB] */
    __shared__ int s_block_last;

    const int c0 = c_base + blockIdx.z * CH;
    const int tid = threadIdx.y * SP_TILE_SIZE + threadIdx.x;
    const int lane = tid & 31, warp = tid >> 5;
    const int bx = blockIdx.x * SP_TILE_SIZE, by = blockIdx.y * SP_TILE_SIZE;
    const int px_i = bx + threadIdx.x, py_i = by + threadIdx.y;
    walk_px q;
    q.aux = aux && blockIdx.z == 0; /* depth and alpha terms in one chunk only */
    q.inside = px_i < W && py_i < H;
    q.px = px_i + 0.5f, q.py = py_i + 0.5f;
    const int2 range = ranges[blockIdx.y * tiles_x + blockIdx.x];
    const size_t pix = q.inside ? (size_t)py_i * W + px_i : 0;

    load_vout<CH, CHP, LDV>(s_vout, v_image, W, H, D, c0, bx, by, tid);
    q.Tf = q.inside ? t_final[pix] : 1.f;
    q.last = q.inside ? last_idx[pix] : range.x;
    if (tid == 0) s_block_last = range.x;
    __syncthreads();
    atomicMax(&s_block_last, q.last);
    q.G = 0.f;
#pragma unroll
    for (int c = 0; c < CH; c++)
        if (bg && c0 + c < D) q.G += s_vout[tid * LDV + c] * bg[c0 + c];
    q.G *= q.Tf;
    q.vd = (q.aux && q.inside && v_depth) ? v_depth[pix] : 0.f;
    q.va = (q.aux && q.inside && v_alpha_out) ? v_alpha_out[pix] : 0.f;
    q.Gd = 0.f, q.T = q.Tf;
    q.warp_last = __reduce_max_sync(FULL_MASK, q.last);
    __syncthreads();
    const int block_last = s_block_last;

    /* product (a)'s work: warp -> (output tile, pixel part) */
    const bool a_act = warp < dm::NT * dm::KS;
    const int a_tile = warp % dm::NT, a_part = warp / dm::NT;
    const int a_m = a_tile / dm::NTN, a_n = a_tile % dm::NTN;
    const int a_wlo = a_part * (NWARPS / dm::KS), a_whi = a_wlo + NWARPS / dm::KS;
    float *a_out = st.col + 16 * a_m * LDV + 16 * a_n; /* the tile's sums, over the colours */

    constexpr int CPT = (NB * CH + BLOCK - 1) / BLOCK; /* colour values per thread and stage */
    stage_regs<CPT> nx;
    stage_load<CH, CPT>(&nx, ids, means2d, conic_op, depths, colors, D, c0, block_last,
                        min(NB, block_last - range.x), tid);
    for (int b_end = block_last; b_end > range.x; b_end -= NB) {
        const int cnt = min(NB, b_end - range.x);
        __syncthreads(); /* the previous stage's product is done with s_fac, st.col, st.id */
        stage_store<CH, LDV, CPT>(st, nx, cnt, tid);
        if (b_end - NB > range.x)
            stage_load<CH, CPT>(&nx, ids, means2d, conic_op, depths, colors, D, c0, b_end - NB,
                                min(NB, b_end - NB - range.x), tid);
        __syncthreads();
        /* (b) for the rows t this warp's walk reads: t < cnt and b_end - 1 - t < warp_last */
        const int t_lo = max(0, b_end - q.warp_last);
        tc_scores<CH>(st.col, s_vout, s_fac, t_lo / 16, min(2, (cnt + 15) / 16), warp);
        __syncwarp();
        /* no warp culling here (an option kernel): every Gaussian of the stage */
        stage_walk<false>(st, q, b_end, cnt >= 32 ? ~0u : (1u << cnt) - 1u, s_fac, LDF, [&](int t) { return s_fac[t * LDF + tid]; }, vgeo,
                   tid);
        __syncthreads();
        if (!v_colors) continue; /* block-uniform */
        acc_t acc;
        wm::fill_fragment(acc, 0.f);
        const bool a_rows = a_act && 16 * a_m < cnt;
        if (a_rows) {
            unsigned long long rows = 0;
#pragma unroll
            for (int j = 0; j < 16; j++) rows |= st.flag[16 * a_m + j];
            tc_colors<CH>(acc, s_fac, s_vout, rows, a_m, a_n, a_wlo, a_whi);
        }
        if (dm::KS == 2) { /* the second pixel half's warps hand their sums to the first's */
            if (a_act && a_part == 1) wm::store_matrix_sync(a_out, acc, LDV, wm::mem_row_major);
            __syncthreads();
            if (a_rows && a_part == 0) {
                acc_t other;
                wm::load_matrix_sync(other, a_out, LDV, wm::mem_row_major);
#pragma unroll
                for (int i = 0; i < acc.num_elements; i++) acc.x[i] += other.x[i];
            }
        }
        if (!a_rows || a_part != 0) continue; /* warp-uniform */
        wm::store_matrix_sync(a_out, acc, LDV, wm::mem_row_major);
        __syncwarp();
        /* lane: column lane % 16 of rows lane / 16, + 2, ..: 16 consecutive channels a half-warp */
#pragma unroll
        for (int i = 0; i < 8; i++) {
            const int r = lane / 16 + 2 * i, cc = lane % 16;
            const int t = 16 * a_m + r, c = 16 * a_n + cc;
            const float v = a_out[r * LDV + cc];
            if (t < cnt && c < CH && c0 + c < D && v != 0.f)
                atomicAdd(v_colors + (size_t)st.id[t] * D + c0 + c, v);
        }
    }
#endif
}

size_t tc_smem(int ch)
{
    const int chp = (ch + 15) / 16 * 16, ldv = chp + 4;
    return sizeof(float) * ((size_t)NB * LDF + (size_t)BLOCK * ldv + (size_t)NB * ldv) +
           (size_t)NB * (sizeof(float4) + sizeof(unsigned long long) + 2 * sizeof(float2) +
                         2 * sizeof(float) + sizeof(int));
}

template <int CH>
int launch_tc(const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors, float *vgeo,
              int c_base, int n_chunks, int aux, sp_error *err)
{
    size_t smem = tc_smem(CH);
    SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_bwd_tc<CH>, cudaFuncAttributeMaxDynamicSharedMemorySize,
                                       (int)smem),
                  err, "backward shared memory");
    /* a hint only: as much shared memory as the SM has, for TC_MIN_BLOCKS blocks */
    SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_bwd_tc<CH>, cudaFuncAttributePreferredSharedMemoryCarveout,
                                       cudaSharedmemCarveoutMaxShared),
                  err, "backward shared memory carveout");
    const sp_cuda_view *v = &r->view;
    dim3 grid(v->tiles_x, v->tiles_y, n_chunks), block(SP_TILE_SIZE, SP_TILE_SIZE, 1);
    k_raster_bwd_tc<CH><<<grid, block, smem, r->stream>>>(
        v->cam.width, v->cam.height, v->tiles_x, v->tile_ranges, v->sorted_ids, v->proj.means2d,
        v->proj.conic_op, v->proj.depths, r->in.colors, r->in.D, c_base, r->bg_dev, v->t_final,
        v->last_idx, gin->v_image, gin->v_depth, gin->v_alpha, aux, v_colors, vgeo);
    SP_CUDA_LAUNCHED(err, "backward rasterization");
    return 0;
}

} // namespace

/* Whether this kernel takes chunks of width ch on this GPU: tensor cores with TF32 (compute
 * capability 8.0 and later), a width it is instantiated for, and its shared memory. */
bool sp_cuda_bwd_tc_fits(int ch)
{
    if (ch != 32 && ch != 40 && ch != 48 && ch != 64) return false;
    int dev = 0, major = 0, max_smem = 0;
    if (cudaGetDevice(&dev) != cudaSuccess ||
        cudaDeviceGetAttribute(&major, cudaDevAttrComputeCapabilityMajor, dev) != cudaSuccess ||
        cudaDeviceGetAttribute(&max_smem, cudaDevAttrMaxSharedMemoryPerBlockOptin, dev) != cudaSuccess)
        return false;
    return major >= 8 && tc_smem(ch) + 64 <= (size_t)max_smem;
}

int sp_cuda_bwd_tc(int ch, const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                   float *vgeo, int c_base, int n_chunks, int aux, sp_error *err)
{
    switch (ch) {
    case 32: return launch_tc<32>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case 40: return launch_tc<40>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case 48: return launch_tc<48>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case 64: return launch_tc<64>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    default: return sp_error_set(err, SP_E_ARG, "no tensor-core backward kernel for chunk width %d", ch);
    }
}
