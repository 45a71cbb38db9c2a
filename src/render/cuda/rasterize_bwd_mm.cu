/* CUDA backend, stage 4 for wide chunks (32 channels and more): backward compositing with the
 * colour gradients as a product in shared memory.
 *
 * The colour gradient of Gaussian t in a tile is v_colors[t][c] = sum_p fac[t][p] v_image[p][c]
 * over the tile's 256 pixels (fac = alpha T, the pixel's blending weight). The reduce-scatter
 * kernel (rasterize_bwd.cu) forms that sum per warp with about CH shuffles and selects per
 * Gaussian and adds each warp's share atomically; Nsight Compute on an H200 (1M Gaussians, 1080p,
 * D=32) showed that kernel issue-bound, two thirds of its instructions in those shuffles and
 * selects, at 25 % occupancy (116 registers). Here the block walks its list in stages of NB = 32
 * Gaussians: each pixel stores its fac for the stage's Gaussians in shared memory (zero where
 * it did not keep one) and keeps the geometry sums by warp reduce-scatter as before, walking
 * only the Gaussians its warp's band can keep, two at a time (stage_walk_pairs, bwd_common.cuh);
 * then every warp forms the product for GPW = 4 of the stage's Gaussians, lane l for
 * channels l, l + 32 (four pixels per step: four broadcast float4 reads of fac, one read of
 * v_image per pixel and channel, 16 multiply-adds), over only the 32-pixel rows of the warps
 * that kept one of its Gaussians, and adds one atomic per Gaussian, channel and tile (not one
 * per warp). The transmittance recursion, the alpha rule and the geometry terms are the
 * reduce-scatter kernel's, so both agree with the CPU up to float summation order. */
#include "bwd_common.cuh"

#define GPW (NB / NWARPS)        /* Gaussians per warp in the product */

/* 1: each warp's pixels are an 8 x 4 box of the tile (sp_cu_box_x), 0: two rows */
#ifndef SP_MM_BOX
#define SP_MM_BOX 1
#endif

/* blocks per SM the registers are bounded for: 3 for 32 channels (its shared memory allows 3),
 * else 2 */
#define MM_MIN_BLOCKS(CH) ((CH) <= 32 ? 3 : 2)

template <int CH>
__global__ void __launch_bounds__(BLOCK, MM_MIN_BLOCKS(CH))
k_raster_bwd_mm(int W, int H, int tiles_x, const int2 *__restrict__ ranges,
                const uint32_t *__restrict__ ids, const float2 *__restrict__ means2d,
                const float4 *__restrict__ conic_op, const float *__restrict__ depths,
                const float *__restrict__ colors, int D, int c_base, const float *__restrict__ bg,
                const float *__restrict__ t_final, const int32_t *__restrict__ last_idx,
                const float *__restrict__ v_image, const float *__restrict__ v_depth,
                const float *__restrict__ v_alpha_out, int aux, int cull, float *__restrict__ v_colors,
                float *__restrict__ vgeo)
{
    constexpr int NPL = (CH + 31) / 32; /* channels per lane in the product */
    extern __shared__ float4 smem_f4[];
    stage_smem st;
    st.conic = smem_f4;                                          /* [NB] */
    st.flag = (unsigned long long *)(st.conic + NB);             /* [NB] */
    float *s_fac = (float *)(st.flag + NB);                      /* [NB][BLOCK] */
    float *s_vout = s_fac + NB * BLOCK;                          /* [BLOCK][CH] pixels' v_image */
    st.col = s_vout + BLOCK * CH;                                /* [NB][CH] */
    st.xy = (float2 *)(st.col + NB * CH);                        /* [NB] */
    st.frame = st.xy + NB;                                       /* [NB] */
    st.z = (float *)(st.frame + NB);                             /* [NB] */
    st.cut = st.z + NB;                                          /* [NB] */
    st.id = (int *)(st.cut + NB);                                /* [NB] */
    /* ids and flags (the only stage data the product reads) alternate between two buffers, so
     * the next stage is stored while this one's product runs */
    int *const id_buf[2] = {st.id, st.id + NB};                                      /* [NB] */
    unsigned long long *const flag_buf[2] = {st.flag, (unsigned long long *)(st.id + 2 * NB)}; /* [NB] */
    __shared__ int s_block_last;

    const int c0 = c_base + blockIdx.z * CH;
    const int tid = threadIdx.y * SP_TILE_SIZE + threadIdx.x;
    const int lane = tid & 31, warp = tid >> 5;
    const int bx = blockIdx.x * SP_TILE_SIZE, by = blockIdx.y * SP_TILE_SIZE;
    const int px_i = bx + (SP_MM_BOX ? sp_cu_box_x(tid) : (int)threadIdx.x);
    const int py_i = by + (SP_MM_BOX ? sp_cu_box_y(tid) : (int)threadIdx.y);
    walk_px q;
    q.aux = aux && blockIdx.z == 0; /* depth and alpha terms in one chunk only */
    q.inside = px_i < W && py_i < H;
    q.px = px_i + 0.5f, q.py = py_i + 0.5f;
    const int2 range = ranges[blockIdx.y * tiles_x + blockIdx.x];
    const size_t pix = q.inside ? (size_t)py_i * W + px_i : 0;

    load_vout<CH, CH, CH, SP_MM_BOX>(s_vout, v_image, W, H, D, c0, bx, by, tid);
    q.Tf = q.inside ? t_final[pix] : 1.f;
    q.last = q.inside ? last_idx[pix] : range.x;
    if (tid == 0) s_block_last = range.x;
    __syncthreads();
    atomicMax(&s_block_last, q.last);
    float vout[CH];
    q.G = 0.f;
#pragma unroll
    for (int c = 0; c < CH; c++) {
        vout[c] = s_vout[tid * CH + c];
        if (bg && c0 + c < D) q.G += vout[c] * bg[c0 + c];
    }
    q.G *= q.Tf;
    q.vd = (q.aux && q.inside && v_depth) ? v_depth[pix] : 0.f;
    q.va = (q.aux && q.inside && v_alpha_out) ? v_alpha_out[pix] : 0.f;
    q.Gd = 0.f, q.T = q.Tf;
    q.warp_last = __reduce_max_sync(FULL_MASK, q.last);
    __syncthreads();
    const int block_last = s_block_last;
    int box_x0, box_x1, box_y0, box_y1;
    sp_cu_box_rect(blockIdx.x, blockIdx.y, warp, W, H, &box_x0, &box_x1, &box_y0, &box_y1);

    /* Stages are double-buffered through registers: the next stage's geometry and colours are
     * loaded while this one is composited, and stored while this one's product runs (after the
     * barrier that ends the walk: only the walk reads the geometry and colours, and the product
     * reads the ids and flags, which alternate between two buffers). Two barriers a stage. */
    constexpr int CPT = (NB * CH + BLOCK - 1) / BLOCK; /* colour values per thread and stage */
    stage_regs<CPT> nx;
    if (block_last > range.x) {
        stage_load<CH, CPT>(&nx, ids, means2d, conic_op, depths, colors, D, c0, block_last,
                            min(NB, block_last - range.x), tid);
        stage_store<CH, CH, CPT>(st, nx, min(NB, block_last - range.x), tid); /* buffer 0 */
        if (block_last - NB > range.x)
            stage_load<CH, CPT>(&nx, ids, means2d, conic_op, depths, colors, D, c0, block_last - NB,
                                min(NB, block_last - NB - range.x), tid);
    }
    __syncthreads();
    for (int b_end = block_last, cb = 0; b_end > range.x; b_end -= NB, cb ^= 1) {
        const int cnt = min(NB, b_end - range.x);
        st.id = id_buf[cb], st.flag = flag_buf[cb];
        /* warp culling: the warp's box (8 x 4) or band (2 rows) */
        const unsigned bits =
            SP_MM_BOX ? sp_cu_rect_bits(st.conic, st.xy, st.cut, 0, cnt, cull, box_x0, box_x1, box_y0, box_y1, lane)
                      : sp_cu_band_bits(st.conic, st.xy, st.cut, 0, cnt, cull, blockIdx.x, blockIdx.y,
                                        warp, 2, W, H, lane);
        stage_walk_pairs(st, q, b_end, bits, s_fac, BLOCK,
                   [&](int t) {
                       /* four independent chains, so the sum waits on 8 multiply-adds, not 32 */
                       const float *col = st.col + t * CH;
                       float p[4] = {0.f, 0.f, 0.f, 0.f};
#pragma unroll
                       for (int c = 0; c < CH; c++) p[c & 3] = fmaf(col[c], vout[c], p[c & 3]);
                       return (p[0] + p[1]) + (p[2] + p[3]);
                   },
                   vgeo, tid);
        __syncthreads(); /* every warp's walk is done: s_fac is complete, the geometry free */
        if (b_end - NB > range.x) { /* the next stage, into the other buffer */
            stage_smem sn = st;
            sn.id = id_buf[cb ^ 1], sn.flag = flag_buf[cb ^ 1];
            stage_store<CH, CH, CPT>(sn, nx, min(NB, b_end - NB - range.x), tid);
            if (b_end - 2 * NB > range.x)
                stage_load<CH, CPT>(&nx, ids, means2d, conic_op, depths, colors, D, c0, b_end - 2 * NB,
                                    min(NB, b_end - 2 * NB - range.x), tid);
        }
        const int t0 = warp * GPW;
        if (v_colors && t0 < cnt) { /* warp-uniform */
            unsigned long long rows = 0;
#pragma unroll
            for (int j = 0; j < GPW; j++) rows |= st.flag[t0 + j];
            float acc[GPW][NPL];
#pragma unroll
            for (int j = 0; j < GPW; j++)
#pragma unroll
                for (int i = 0; i < NPL; i++) acc[j][i] = 0.f;
            for (int w = 0; w < NWARPS; w++) {
                if (!((rows >> (8 * w)) & 0xffu)) continue; /* no pixel of warp w kept any of them */
                for (int p = 32 * w; p < 32 * w + 32; p += 4) {
                    float4 f[GPW];
#pragma unroll
                    for (int j = 0; j < GPW; j++) f[j] = *(const float4 *)(s_fac + (t0 + j) * BLOCK + p);
#pragma unroll
                    for (int i = 0; i < NPL; i++) {
                        const int c = lane + 32 * i;
                        if (CH % 32 != 0 && c >= CH) continue;
                        const float *sv = s_vout + (size_t)p * CH + c;
                        const float v0 = sv[0], v1 = sv[CH], v2 = sv[2 * CH], v3 = sv[3 * CH];
                        /* one chain of fused multiply-adds per accumulator */
#pragma unroll
                        for (int j = 0; j < GPW; j++) {
                            acc[j][i] = fmaf(f[j].x, v0, acc[j][i]);
                            acc[j][i] = fmaf(f[j].y, v1, acc[j][i]);
                            acc[j][i] = fmaf(f[j].z, v2, acc[j][i]);
                            acc[j][i] = fmaf(f[j].w, v3, acc[j][i]);
                        }
                    }
                }
            }
#pragma unroll
            for (int j = 0; j < GPW; j++) {
                if (t0 + j >= cnt) break;
                const size_t g = (size_t)st.id[t0 + j];
#pragma unroll
                for (int i = 0; i < NPL; i++) {
                    const int c = lane + 32 * i;
                    if (c < CH && c0 + c < D && acc[j][i] != 0.f)
                        atomicAdd(v_colors + g * D + c0 + c, acc[j][i]);
                }
            }
        }
        __syncthreads(); /* the product is done with s_fac; the next stage is stored */
    }
}

static size_t mm_smem(int ch)
{
    return (size_t)NB * (sizeof(float4) + sizeof(unsigned long long) + BLOCK * sizeof(float) +
                         ch * sizeof(float) + 2 * sizeof(float2) + 2 * sizeof(float) + 2 * sizeof(int) +
                         sizeof(unsigned long long)) +
           (size_t)BLOCK * ch * sizeof(float);
}

/* Whether this kernel takes chunks of width ch on this GPU: 32 channels and more (narrower ones
 * reduce-scatter cheaply, and 256 pixels x ch floats of v_image must fit beside the stage). */
bool sp_cuda_bwd_mm_fits(int ch)
{
    if (ch != 32 && ch != 40 && ch != 48 && ch != 64) return false;
    int dev = 0, max_smem = 0;
    if (cudaGetDevice(&dev) != cudaSuccess ||
        cudaDeviceGetAttribute(&max_smem, cudaDevAttrMaxSharedMemoryPerBlockOptin, dev) != cudaSuccess)
        return false;
    return mm_smem(ch) + 64 <= (size_t)max_smem;
}

template <int CH>
static int launch_mm(const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                     float *vgeo, int c_base, int n_chunks, int aux, sp_error *err)
{
    size_t smem = mm_smem(CH);
    SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_bwd_mm<CH>, cudaFuncAttributeMaxDynamicSharedMemorySize,
                                       (int)smem),
                  err, "backward shared memory");
    const sp_cuda_view *v = &r->view;
    dim3 grid(v->tiles_x, v->tiles_y, n_chunks), block(SP_TILE_SIZE, SP_TILE_SIZE, 1);
    k_raster_bwd_mm<CH><<<grid, block, smem, r->stream>>>(
        v->cam.width, v->cam.height, v->tiles_x, v->tile_ranges, v->sorted_ids, v->proj.means2d,
        v->proj.conic_op, v->proj.depths, r->in.colors, r->in.D, c_base, r->bg_dev, v->t_final,
        v->last_idx, gin->v_image, gin->v_depth, gin->v_alpha, aux, v->warp_cull, v_colors, vgeo);
    SP_CUDA_LAUNCHED(err, "backward rasterization");
    return 0;
}

int sp_cuda_bwd_mm(int ch, const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                   float *vgeo, int c_base, int n_chunks, int aux, sp_error *err)
{
    switch (ch) {
    case 32: return launch_mm<32>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case 40: return launch_mm<40>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case 48: return launch_mm<48>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case 64: return launch_mm<64>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    default: return sp_error_set(err, SP_E_ARG, "no product backward kernel for chunk width %d", ch);
    }
}
