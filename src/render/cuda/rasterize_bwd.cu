/* CUDA backend, stage 4: backward compositing, and sp_cuda_raster_backward.
 *
 * One 16x16 block per tile and channel chunk walks the tile's list back to front from the last
 * Gaussian any of its pixels used, recovering each pixel's transmittance by division (T_final
 * was saved by the forward). Why it stays fast for wide D:
 *  - the colour term of dL/dalpha is carried as ONE scalar per pixel, G = sum_{j behind} w_j
 *    (v_out . c_j) + T_final (v_out . bg), instead of a D-wide "colour behind" buffer, so a
 *    thread holds only the chunk's v_out and its colour-gradient partials;
 *  - channels beyond 64 are split into chunks (blockIdx.z, plus one narrower launch for the
 *    rest); dL/dalpha is linear in the channels, so each chunk adds its share of the geometry
 *    gradients independently (measured: one 64-wide pass beats two 32-wide ones, since every
 *    chunk repeats the per-pixel alpha work and the geometry reduction);
 *  - warp sums use a reduce-scatter (each shuffle round halves the values every lane carries),
 *    about CH shuffles instead of 5 CH, and the atomics that follow are spread over lanes and hit
 *    consecutive addresses;
 *  - warps where no pixel kept the Gaussian skip it (ballot);
 *  - chunks of up to 8 channels reduce geometry and colours in one reduce-scatter;
 *  - optional colour gradients by gather (cfg.bwd_gather = 1; off by default, measured slower):
 *    the pixels' v_image rows are staged in shared memory once, and per Gaussian lane l sums
 *    fac * v_image over only the lanes that kept it (ballot) for channels l, l + 32, ..: a
 *    shuffle and NPL fused multiply-adds per kept lane, and no D-wide register array, instead
 *    of D products and about D shuffles per lane. (Block sums in shared memory with one global
 *    atomic per Gaussian and value were measured slower on an H200 and removed.)
 *  - chunks of 32 channels and more go to rasterize_bwd_mm.cu (colour gradients as a product in
 *    shared memory over the tile's pixels) unless cfg.bwd_gather asks otherwise: on an H200 at 1M
 *    Gaussians 1080p it cut the backward from 18.3 to 12.5 ms at D=64, 16.4 to 11.9 at D=48 and
 *    9.0 to 8.2 at D=32. cfg.bwd_gather = 2 takes rasterize_bwd_tc.cu instead where it fits
 *    (the same product and the per-pixel colour dot on tensor cores, 3xTF32; not yet measured).
 * Gradients into v_colors are atomically ADDED (render.h's contract); geometry sums go to a
 * per-Gaussian scratch that project.cu turns into parameter gradients. */
#include "bwd_common.cuh"

/* 1: k_raster_bwd's warps own 8 x 4 boxes of the tile (sp_cu_box_x), 0: two rows */
#ifndef SP_RS_BOX
#define SP_RS_BOX 1
#endif

/* The staged Gaussians 32 wd .. 32 wd + 31 this warp walks (the warp owns rows rh warp ..
 * rh warp + rh - 1 of its tile: sp_cu_band_bits; with BOX its 8 x 4 box, rh unused), from slot
 * t_first on (the ones behind every pixel of the warp's list ends are skipped). */
template <int BOX = 0>
__device__ __forceinline__ unsigned walk_bits(const float4 *s_conic, const float2 *s_xy,
                                              const float *s_cut, int wd, int t_first, int cnt,
                                              int cull, int rh, int W, int H, int tid)
{
    const int warp = tid >> 5;
    int x0, x1, y0, y1; /* BOX 1: sp_cu_box_rect, 2: sp_cu_px2_rect */
    if (BOX == 2) sp_cu_px2_rect(blockIdx.x, blockIdx.y, warp, W, H, &x0, &x1, &y0, &y1);
    else sp_cu_box_rect(blockIdx.x, blockIdx.y, warp, W, H, &x0, &x1, &y0, &y1);
    unsigned m = BOX ? sp_cu_rect_bits(s_conic, s_xy, s_cut, 32 * wd, cnt, cull, x0, x1, y0, y1, tid & 31)
                     : sp_cu_band_bits(s_conic, s_xy, s_cut, 32 * wd, cnt, cull, blockIdx.x, blockIdx.y,
                                       warp, rh, W, H, tid & 31);
    return wd == t_first >> 5 ? m & (~0u << (t_first & 31)) : m;
}

template <int CH, bool GV>
__global__ void __launch_bounds__(BLOCK)
k_raster_bwd(int W, int H, int tiles_x, const int2 *__restrict__ ranges,
             const uint32_t *__restrict__ ids, const float2 *__restrict__ means2d,
             const float4 *__restrict__ conic_op, const float *__restrict__ depths,
             const float *__restrict__ colors, int D, int c_base, const float *__restrict__ bg,
             const float *__restrict__ t_final, const int32_t *__restrict__ last_idx,
             const float *__restrict__ v_image, const float *__restrict__ v_depth,
             const float *__restrict__ v_alpha_out, int aux, int cull, float *__restrict__ v_colors,
             float *__restrict__ vgeo)
{
    extern __shared__ float4 smem_f4[];
    float4 *s_conic = smem_f4;                        /* [BLOCK] */
    float2 *s_xy = (float2 *)(s_conic + BLOCK);       /* [BLOCK] */
    float *s_z = (float *)(s_xy + BLOCK);             /* [BLOCK] */
    float *s_cut = s_z + BLOCK;                       /* [BLOCK] */
    float2 *s_frame = (float2 *)(s_cut + BLOCK);      /* [BLOCK] conic frame (cs, sn) */
    int *s_id = (int *)(s_frame + BLOCK);             /* [BLOCK] */
    float *s_col = (float *)(s_id + BLOCK);           /* [BLOCK][CH] */
    float *s_vout = s_col + BLOCK * CH;               /* GV: [BLOCK][CH] pixels' v_image */
    __shared__ int s_block_last;

    const int c0 = c_base + blockIdx.z * CH;
    const bool do_aux = aux && blockIdx.z == 0; /* depth and alpha terms in one chunk only */
    const int tid = threadIdx.y * SP_TILE_SIZE + threadIdx.x;
    const int lane = tid & 31;
    const int px_i = blockIdx.x * SP_TILE_SIZE + (SP_RS_BOX ? sp_cu_box_x(tid) : (int)threadIdx.x);
    const int py_i = blockIdx.y * SP_TILE_SIZE + (SP_RS_BOX ? sp_cu_box_y(tid) : (int)threadIdx.y);
    const bool inside = px_i < W && py_i < H;
    const float px = px_i + 0.5f, py = py_i + 0.5f;
    const int2 range = ranges[blockIdx.y * tiles_x + blockIdx.x];
    const size_t pix = inside ? (size_t)py_i * W + px_i : 0;

    const float Tf = inside ? t_final[pix] : 1.f;
    const int last = inside ? last_idx[pix] : range.x;
    float vout[CH];
    float G = 0.f;
#pragma unroll
    for (int c = 0; c < CH; c++) {
        vout[c] = (inside && c0 + c < D) ? v_image[pix * D + c0 + c] : 0.f;
        if (bg && c0 + c < D) G += vout[c] * bg[c0 + c];
    }
    G *= Tf;
    if (GV) /* read back only by this thread's warp, after the __syncthreads below */
#pragma unroll
        for (int c = 0; c < CH; c++) s_vout[tid * CH + c] = vout[c];
    const float vd = (do_aux && inside && v_depth) ? v_depth[pix] : 0.f;
    const float va = (do_aux && inside && v_alpha_out) ? v_alpha_out[pix] : 0.f;
    float Gd = 0.f, T = Tf;

    if (tid == 0) s_block_last = range.x;
    __syncthreads();
    atomicMax(&s_block_last, last);
    const int warp_last = __reduce_max_sync(FULL_MASK, last);
    __syncthreads();
    const int block_last = s_block_last;

    for (int b_end = block_last; b_end > range.x; b_end -= BLOCK) {
        const int cnt = min(BLOCK, b_end - range.x);
        __syncthreads();
        if (tid < cnt) {
            int g = (int)ids[b_end - 1 - tid];
            s_id[tid] = g;
            s_xy[tid] = means2d[g];
            const float4 co = conic_op[g];
            s_conic[tid] = co;
            s_cut[tid] = sp_cu_sigma_cut(co.w);
            const float con[3] = {co.x, co.y, co.z};
            float fcs, fsn;
            sp_gm_conic_frame(con, &fcs, &fsn);
            s_frame[tid] = make_float2(fcs, fsn);
            s_z[tid] = depths[g];
        }
        __syncthreads();
        for (int k = tid; k < cnt * CH; k += BLOCK) {
            int j = k / CH, c = k - j * CH;
            s_col[k] = (c0 + c < D) ? colors[(size_t)s_id[j] * D + c0 + c] : 0.f;
        }
        __syncthreads();
        const int t_first = max(0, b_end - warp_last);
        for (int wd = t_first >> 5; 32 * wd < cnt; wd++) {
            unsigned m = walk_bits<SP_RS_BOX ? 1 : 0>(s_conic, s_xy, s_cut, wd, t_first, cnt, cull, 2, W, H, tid);
            for (; m; m &= m - 1) {
                const int t = 32 * wd + __ffs(m) - 1;
                const int idx = b_end - 1 - t;
                const float4 co = s_conic[t];
                const float2 xy = s_xy[t];
                const float dx = px - xy.x, dy = py - xy.y;
                float vis = 0.f, alpha = 0.f;
                if (inside && idx < last) alpha = sp_cu_alpha(co, s_cut[t], dx, dy, &vis);
                const bool valid = alpha > 0.f;
                if (!__any_sync(FULL_MASK, valid)) continue;

                constexpr int VC = GV ? 1 : CH; /* the reduce-scatter's values (unused with GV) */
                float vcol[VC];
                float geo[7], fac = 0.f;
    #pragma unroll
                for (int c = 0; c < VC; c++) vcol[c] = 0.f;
    #pragma unroll
                for (int k = 0; k < 7; k++) geo[k] = 0.f;
                if (valid) {
                    /* IEEE 1/x (fast math would approximate it), as the CPU's division: the T recovered
                     * front to back then matches the CPU's bit for bit */
                    const float ra = __frcp_rn(1.f - alpha);
                    T *= ra;
                    fac = alpha * T;
                    const float *col = s_col + t * CH;
                    float p = 0.f;
    #pragma unroll
                    for (int c = 0; c < CH; c++) {
                        p += col[c] * vout[c];
                        if (!GV) vcol[c < VC ? c : 0] = fac * vout[c];
                    }
                    const float v_alpha = sp_cu_bwd_alpha_grad(p, T, ra, fac, do_aux, s_z + t, vd, va, Tf, &G,
                                                               &Gd, geo);
                    sp_cu_bwd_geo(co, s_frame[t], vis, v_alpha, dx, dy, geo);
                }
                const int g = s_id[t];
                if (v_colors && GV) {
                    /* sum over the lanes that kept the Gaussian of fac * v_image: lane l gathers
                     * channels l, l + 32, .. from the warp's staged v_image rows */
                    constexpr int NPL = (CH + 31) / 32;
                    float acc[NPL];
    #pragma unroll
                    for (int i = 0; i < NPL; i++) acc[i] = 0.f;
                    const float *sv = s_vout + (tid & ~31) * CH;
                    for (unsigned m = __ballot_sync(FULL_MASK, valid); m; m &= m - 1) {
                        const int l = __ffs(m) - 1;
                        const float f = __shfl_sync(FULL_MASK, fac, l);
    #pragma unroll
                        for (int i = 0; i < NPL; i++)
                            if (lane + 32 * i < CH) acc[i] += f * sv[l * CH + lane + 32 * i];
                    }
    #pragma unroll
                    for (int i = 0; i < NPL; i++) {
                        const int c = lane + 32 * i;
                        if (c < CH && c0 + c < D && acc[i] != 0.f)
                            atomicAdd(v_colors + (size_t)g * D + c0 + c, acc[i]);
                    }
                } else if (v_colors && CH <= 8) {
                    /* narrow chunks: geometry and colours in ONE reduce-scatter (fewer shuffle
                     * rounds than two); slot k < 7 is geometry, 7 + c colour c */
                    constexpr int NV = 7 + VC;
                    float all[NV];
    #pragma unroll
                    for (int k = 0; k < 7; k++) all[k] = geo[k];
    #pragma unroll
                    for (int c = 0; c < VC; c++) all[7 + c] = vcol[c];
                    const int base = warp_reduce_scatter<NV>(all, lane);
                    if (lane % RS_GROUP(NV) == 0) {
    #pragma unroll
                        for (int i = 0; i < RS_LIVE(NV); i++) {
                            const int k = base + i;
                            if (k >= NV || all[i] == 0.f) continue;
                            if (k < 7) atomicAdd(vgeo + (size_t)g * SP_VGEO_STRIDE + k, all[i]);
                            else if (k - 7 < CH && c0 + k - 7 < D)
                                atomicAdd(v_colors + (size_t)g * D + c0 + k - 7, all[i]);
                        }
                    }
                    continue;
                } else if (v_colors) {
                    const int cb = warp_reduce_scatter<VC>(vcol, lane);
                    constexpr int LIVE = RS_LIVE(VC), GROUP = RS_GROUP(VC);
                    if (lane % GROUP == 0) {
    #pragma unroll
                        for (int i = 0; i < LIVE; i++) {
                            const int c = cb + i;
                            if (c < CH && c0 + c < D && vcol[i] != 0.f)
                                atomicAdd(v_colors + (size_t)g * D + c0 + c, vcol[i]);
                        }
                    }
                }
                const int slot = warp_reduce_scatter<7>(geo, lane);
                if (lane % RS_GROUP(7) == 0 && slot < 7 && geo[0] != 0.f)
                    atomicAdd(vgeo + (size_t)g * SP_VGEO_STRIDE + slot, geo[0]);
            }
        }
    }
}

/* PX pixels per thread for narrow chunks (cfg.bwd_px = 2 or 4, CH <= 8): 256 / PX threads per
 * 16x16 tile, thread (x, y) of a (16 / PX) x 16 block owning pixels (x + q 16 / PX, y), q < PX,
 * so a warp covers a 16 x 2 PX patch. The per-Gaussian costs of a warp (the shared-memory loads,
 * the ballot, the loop, and above all the reduce-scatter and its atomics) are paid once per
 * 32 PX pixels instead of 32: the pixels' gradients are summed in registers (fused into their
 * products) before the one reduce-scatter. A thread's pixels share a row, so they share the
 * alpha rule's row terms (sp_gm_alpha_row: the same operations as sp_gm_alpha_g, bit for bit);
 * each pixel's gradient block runs only where some lane kept the Gaussian at that pixel, so a
 * Gaussian costs per pixel what it did with one pixel per thread. Per pixel everything is as
 * in k_raster_bwd: the T recovery by IEEE reciprocal, G, Gd, and the kept test idx < last (a
 * pixel outside the image has last = range.x, which no index reaches, so it needs no test of
 * its own). */
/* Two pixels per thread (the D=3 default) bounded for 8 blocks per SM, 64 registers (8 bytes of
 * spills): the warp culling loop took it to 72 and 7 blocks; H200, 1M 1080p D=3, same call:
 * backward 2.77-2.79 ms bounded against 2.84-2.86 unbounded. */
template <int CH, int PX>
__global__ void __launch_bounds__(BLOCK / PX, PX == 2 ? 8 : 1)
k_raster_bwd_px(int W, int H, int tiles_x, const int2 *__restrict__ ranges,
                const uint32_t *__restrict__ ids, const float2 *__restrict__ means2d,
                const float4 *__restrict__ conic_op, const float *__restrict__ depths,
                const float *__restrict__ colors, int D, int c_base, const float *__restrict__ bg,
                const float *__restrict__ t_final, const int32_t *__restrict__ last_idx,
                const float *__restrict__ v_image, const float *__restrict__ v_depth,
                const float *__restrict__ v_alpha_out, int aux, int cull, float *__restrict__ v_colors,
                float *__restrict__ vgeo)
{
    static_assert(CH <= 8, "several pixels per thread: narrow chunks only");
    constexpr int NT = BLOCK / PX;          /* threads, and Gaussians per batch */
    constexpr int BX = SP_TILE_SIZE / PX;   /* threads per tile row */
    extern __shared__ float4 smem_f4[];
    float4 *s_conic = smem_f4;                   /* [NT] */
    float2 *s_xy = (float2 *)(s_conic + NT);     /* [NT] */
    float *s_z = (float *)(s_xy + NT);           /* [NT] */
    float *s_cut = s_z + NT;                     /* [NT] */
    float2 *s_frame = (float2 *)(s_cut + NT);    /* [NT] conic frame (cs, sn) */
    int *s_id = (int *)(s_frame + NT);           /* [NT] */
    float *s_col = (float *)(s_id + NT);         /* [NT][CH] */
    __shared__ int s_block_last;

    const int c0 = c_base + blockIdx.z * CH;
    const bool do_aux = aux && blockIdx.z == 0; /* depth and alpha terms in one chunk only */
    const int tid = threadIdx.y * BX + threadIdx.x;
    const int lane = tid & 31;
    constexpr bool PBOX = SP_PX_BOX && PX == 2; /* 8 x 8 warp boxes (sp_cu_px2_pixel) */
    int ox = threadIdx.x, oy = threadIdx.y, step = BX;
    if (PBOX) sp_cu_px2_pixel(tid, &ox, &oy, &step);
    const int py_i = blockIdx.y * SP_TILE_SIZE + oy;
    const float py = py_i + 0.5f;
    const int2 range = ranges[blockIdx.y * tiles_x + blockIdx.x];

    float px[PX], Tf[PX], T[PX], G[PX], Gd[PX], vd[PX], va[PX], vout[PX][CH];
    int last[PX];
    int my_last = range.x;
#pragma unroll
    for (int q = 0; q < PX; q++) {
        const int px_i = blockIdx.x * SP_TILE_SIZE + ox + q * step;
        const bool inside = px_i < W && py_i < H;
        const size_t pix = inside ? (size_t)py_i * W + px_i : 0;
        px[q] = px_i + 0.5f;
        Tf[q] = inside ? t_final[pix] : 1.f;
        last[q] = inside ? last_idx[pix] : range.x;
        my_last = max(my_last, last[q]);
        G[q] = 0.f;
#pragma unroll
        for (int c = 0; c < CH; c++) {
            vout[q][c] = (inside && c0 + c < D) ? v_image[pix * D + c0 + c] : 0.f;
            if (bg && c0 + c < D) G[q] += vout[q][c] * bg[c0 + c];
        }
        G[q] *= Tf[q];
        vd[q] = (do_aux && inside && v_depth) ? v_depth[pix] : 0.f;
        va[q] = (do_aux && inside && v_alpha_out) ? v_alpha_out[pix] : 0.f;
        Gd[q] = 0.f;
        T[q] = Tf[q];
    }

    if (tid == 0) s_block_last = range.x;
    __syncthreads();
    atomicMax(&s_block_last, my_last);
    const int warp_last = __reduce_max_sync(FULL_MASK, my_last);
    __syncthreads();
    const int block_last = s_block_last;

    for (int b_end = block_last; b_end > range.x; b_end -= NT) {
        const int cnt = min(NT, b_end - range.x);
        __syncthreads();
        if (tid < cnt) {
            int g = (int)ids[b_end - 1 - tid];
            s_id[tid] = g;
            s_xy[tid] = means2d[g];
            const float4 co = conic_op[g];
            s_conic[tid] = co;
            s_cut[tid] = sp_cu_sigma_cut(co.w);
            const float con[3] = {co.x, co.y, co.z};
            float fcs, fsn;
            sp_gm_conic_frame(con, &fcs, &fsn);
            s_frame[tid] = make_float2(fcs, fsn);
            s_z[tid] = depths[g];
        }
        __syncthreads();
        for (int k = tid; k < cnt * CH; k += NT) {
            int j = k / CH, c = k - j * CH;
            s_col[k] = (c0 + c < D) ? colors[(size_t)s_id[j] * D + c0 + c] : 0.f;
        }
        __syncthreads();
        const int t_first = max(0, b_end - warp_last);
        for (int wd = t_first >> 5; 32 * wd < cnt; wd++) {
            unsigned m = walk_bits<PBOX ? 2 : 0>(s_conic, s_xy, s_cut, wd, t_first, cnt, cull, 2 * PX, W, H, tid);
            for (; m; m &= m - 1) {
                const int t = 32 * wd + __ffs(m) - 1;
                const int idx = b_end - 1 - t;
                const float4 co = s_conic[t];
                const float2 xy = s_xy[t];
                const float cut = s_cut[t];
                const float dy = py - xy.y;
                float by, hy;
                const float con[3] = {co.x, co.y, co.z};
                sp_gm_row_terms(con, dy, &by, &hy);
                const float half_a = 0.5f * co.x;
                float dx[PX], vis[PX], alpha[PX];
                bool any = false;
    #pragma unroll
                for (int q = 0; q < PX; q++) {
                    dx[q] = px[q] - xy.x;
                    vis[q] = 0.f;
                    alpha[q] = idx < last[q]
                                   ? sp_gm_alpha_row(half_a, by, hy, co.w, cut, dx[q], &vis[q])
                                   : 0.f;
                    any = any || alpha[q] > 0.f;
                }
                if (!__any_sync(FULL_MASK, any)) continue;

                /* the Gaussian's terms every pixel's block reads, loaded once */
                float col[CH];
    #pragma unroll
                for (int c = 0; c < CH; c++) col[c] = s_col[t * CH + c];
                const float2 fr = s_frame[t];
                const float z = s_z[t];
                /* slot k < 7 geometry, 7 + c colour c, summed over the thread's pixels */
                constexpr int NV = 7 + CH;
                float all[NV];
    #pragma unroll
                for (int k = 0; k < NV; k++) all[k] = 0.f;
    #pragma unroll
                for (int q = 0; q < PX; q++) {
                    if (!(alpha[q] > 0.f)) continue;
                    /* IEEE 1/x, as the CPU's division (see k_raster_bwd) */
                    const float ra = __frcp_rn(1.f - alpha[q]);
                    T[q] *= ra;
                    const float fac = alpha[q] * T[q];
                    float p = 0.f;
    #pragma unroll
                    for (int c = 0; c < CH; c++) {
                        p += col[c] * vout[q][c];
                        all[7 + c] += fac * vout[q][c];
                    }
                    const float v_alpha = sp_cu_bwd_alpha_grad<true>(
                        p, T[q], ra, fac, do_aux, &z, vd[q], va[q], Tf[q], &G[q], &Gd[q], all);
                    sp_cu_bwd_geo<true>(co, fr, vis[q], v_alpha, dx[q], dy, all);
                }
                const int g = s_id[t];
                const int base = warp_reduce_scatter<NV>(all, lane);
                if (lane % RS_GROUP(NV) == 0) {
    #pragma unroll
                    for (int i = 0; i < RS_LIVE(NV); i++) {
                        const int k = base + i;
                        if (k >= NV || all[i] == 0.f) continue;
                        if (k < 7) atomicAdd(vgeo + (size_t)g * SP_VGEO_STRIDE + k, all[i]);
                        else if (v_colors && c0 + k - 7 < D)
                            atomicAdd(v_colors + (size_t)g * D + c0 + k - 7, all[i]);
                    }
                }
            }
        }
    }
}

static size_t bwd_px_smem(int ch, int px)
{
    return (size_t)(BLOCK / px) * (sizeof(float4) + 2 * sizeof(float2) + 2 * sizeof(float) +
                                   sizeof(int) + sizeof(float) * ch);
}

template <int CH, int PX>
static int launch_bwd_px(const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                         float *vgeo, int c_base, int n_chunks, int aux, sp_error *err)
{
    size_t smem = bwd_px_smem(CH, PX);
    const sp_cuda_view *v = &r->view;
    dim3 grid(v->tiles_x, v->tiles_y, n_chunks), block(SP_TILE_SIZE / PX, SP_TILE_SIZE, 1);
    k_raster_bwd_px<CH, PX><<<grid, block, smem, r->stream>>>(
        v->cam.width, v->cam.height, v->tiles_x, v->tile_ranges, v->sorted_ids, v->proj.means2d,
        v->proj.conic_op, v->proj.depths, r->in.colors, r->in.D, c_base, r->bg_dev, v->t_final,
        v->last_idx, gin->v_image, gin->v_depth, gin->v_alpha, aux, v->warp_cull, v_colors, vgeo);
    SP_CUDA_LAUNCHED(err, "backward rasterization (several pixels per thread)");
    return 0;
}

static size_t bwd_smem(int ch, bool gv)
{
    return (size_t)BLOCK * (sizeof(float4) + 2 * sizeof(float2) + 2 * sizeof(float) + sizeof(int) +
                            sizeof(float) * ch * (gv ? 2 : 1));
}

/* cfg.bwd_gather: 1 on (when the block's shared memory fits this GPU), else off. Measured on an
 * H200, fwd+bwd at 1M Gaussians 1080p: D=32 14.24 ms on vs 12.34 off, D=64 27.98 vs 25.20, so
 * off is the default. */
static bool use_gather(int mode, int ch)
{
    if (mode != 1) return false;
    int dev = 0, max_smem = 0;
    if (cudaGetDevice(&dev) != cudaSuccess ||
        cudaDeviceGetAttribute(&max_smem, cudaDevAttrMaxSharedMemoryPerBlockOptin, dev) != cudaSuccess)
        return false;
    return bwd_smem(ch, true) + 64 <= (size_t)max_smem;
}

template <int CH, bool GV>
static int launch_bwd_as(const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                         float *vgeo, int c_base, int n_chunks, int aux, sp_error *err)
{
    size_t smem = bwd_smem(CH, GV);
    SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_bwd<CH, GV>,
                                       cudaFuncAttributeMaxDynamicSharedMemorySize, (int)smem),
                  err, "backward shared memory");
    const sp_cuda_view *v = &r->view;
    dim3 grid(v->tiles_x, v->tiles_y, n_chunks), block(SP_TILE_SIZE, SP_TILE_SIZE, 1);
    k_raster_bwd<CH, GV><<<grid, block, smem, r->stream>>>(
        v->cam.width, v->cam.height, v->tiles_x, v->tile_ranges, v->sorted_ids, v->proj.means2d,
        v->proj.conic_op, v->proj.depths, r->in.colors, r->in.D, c_base, r->bg_dev, v->t_final,
        v->last_idx, gin->v_image, gin->v_depth, gin->v_alpha, aux, v->warp_cull, v_colors, vgeo);
    SP_CUDA_LAUNCHED(err, "backward rasterization");
    return 0;
}

/* Which kernel sums a chunk of width ch's colour gradients, from cfg.bwd_gather (render.h): 2 the
 * tensor-core one where it fits (else as 0), 0 the product kernel where it fits, 1 gather, else
 * (and -1) reduce-scatter; that one, for ch <= 8, with 2 pixels per thread by default (cfg.bwd_px
 * 0 or 2; H200, 1M 1080p D=3: backward 2.96 against 3.80 ms), 4 with bwd_px 4, one with bwd_px 1. */
enum bwd_kind { BWD_REDUCE_SCATTER, BWD_GATHER, BWD_PRODUCT, BWD_TENSOR_CORE, BWD_RS_PX2, BWD_RS_PX4 };
static const char *const bwd_kind_name[] = {"reduce-scatter", "gather", "product", "tensor-core",
                                            "reduce-scatter-2px", "reduce-scatter-4px"};

static bwd_kind bwd_choose(const sp_raster_cfg *cfg, int ch)
{
    const int mode = cfg->bwd_gather;
    if (mode == 2 && sp_cuda_bwd_tc_fits(ch)) return BWD_TENSOR_CORE;
    if ((mode == 0 || mode == 2) && sp_cuda_bwd_mm_fits(ch)) return BWD_PRODUCT;
    if (use_gather(mode, ch)) return BWD_GATHER;
    if (ch <= 8 && (cfg->bwd_px == 0 || cfg->bwd_px == 2)) return BWD_RS_PX2; /* the default */
    if (ch <= 8 && cfg->bwd_px == 4) return BWD_RS_PX4;
    return BWD_REDUCE_SCATTER;
}

/* The several-pixel kernels exist for CH <= 8 only (bwd_choose picks them only there). */
template <int CH, int PX, bool NARROW = (CH <= 8)>
struct px_launch {
    static int go(const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors, float *vgeo,
                  int c_base, int n_chunks, int aux, sp_error *err)
    {
        return launch_bwd_as<CH, false>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    }
};
template <int CH, int PX>
struct px_launch<CH, PX, true> {
    static int go(const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors, float *vgeo,
                  int c_base, int n_chunks, int aux, sp_error *err)
    {
        return launch_bwd_px<CH, PX>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    }
};

template <int CH>
static int launch_bwd(const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                      float *vgeo, int c_base, int n_chunks, int aux, sp_error *err)
{
    switch (bwd_choose(&r->cfg, CH)) {
    case BWD_TENSOR_CORE: return sp_cuda_bwd_tc(CH, r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case BWD_PRODUCT: return sp_cuda_bwd_mm(CH, r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case BWD_GATHER: return launch_bwd_as<CH, true>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case BWD_RS_PX2: return px_launch<CH, 2>::go(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    case BWD_RS_PX4: return px_launch<CH, 4>::go(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    default: return launch_bwd_as<CH, false>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    }
}

/* Launches the kernel specialised for width `ch` (one of SP_CHANNEL_WIDTHS). */
static int dispatch_bwd(int ch, const sp_cuda_raster *r, const sp_raster_grad_in *gin,
                        float *v_colors, float *vgeo, int c_base, int n_chunks, int aux,
                        sp_error *err)
{
    switch (ch) {
#define SP_WIDTH_CASE(w) case w: return launch_bwd<w>(r, gin, v_colors, vgeo, c_base, n_chunks, aux, err);
    SP_CHANNEL_WIDTHS(SP_WIDTH_CASE)
#undef SP_WIDTH_CASE
    default: return sp_error_set(err, SP_E_ARG, "no backward kernel for chunk width %d", ch);
    }
}

int sp_cuda_rasterize_bwd(sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                          float *vgeo, sp_error *err)
{
    if (r->view.n_pairs == 0) return 0;
    int D = r->in.D, rc;
    int max_ch = r->cfg.chunk_bwd ? r->cfg.chunk_bwd : SP_CHANNEL_CHUNK_MAX;
    int full = D / max_ch, rem = D % max_ch;
    /* the widest chunk's kernel, for sp_raster_last_stages */
    r->bwd_kernel = bwd_kind_name[bwd_choose(&r->cfg, full > 0 ? max_ch : sp_channel_width(rem, max_ch))];
    if (full > 0 && (rc = dispatch_bwd(max_ch, r, gin, v_colors, vgeo, 0, full, 1, err))) return rc;
    if (rem > 0 && (rc = dispatch_bwd(sp_channel_width(rem, max_ch), r, gin, v_colors, vgeo,
                                      full * max_ch, 1, full == 0, err)))
        return rc;
    return 0;
}

int sp_cuda_raster_backward(void *state, const sp_raster_grad_in *gin,
                                       sp_raster_grads *grads, sp_error *err)
{
    sp_cuda_raster *r = (sp_cuda_raster *)state;
    if (!r->have_forward)
        return sp_error_set(err, SP_E_ARG, "sp_raster_backward: no forward to differentiate "
                                           "(call sp_raster_forward first)");
    size_t n = r->in.n;
    if (n == 0) return 0;
    int rc;
    /* the binning's temporaries are dead now: their space holds the per-Gaussian sums */
    if ((rc = sp_cu_reserve(r, &r->s_work, sp_cuda_work_bytes(n), err))) return rc;
    float *vgeo = (float *)r->s_work.ptr;
    sp_cu_mark(r, SP_EV_BWD_START);
    SP_CUDA_CHECK(cudaMemsetAsync(vgeo, 0, n * SP_VGEO_STRIDE * sizeof(float), r->stream), err,
                  "clearing gradients");
    if ((rc = sp_cuda_rasterize_bwd(r, gin, grads->v_colors, vgeo, err))) return rc;
    sp_cu_mark(r, SP_EV_BWD_RASTER);
    if ((rc = sp_cuda_project_bwd(r, grads, vgeo, err))) return rc;
    sp_cu_mark(r, SP_EV_BWD_DONE);
    r->prof_bwd = r->profiling;
    return 0;
}
