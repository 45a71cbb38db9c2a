/* CUDA backend, stage 3: forward compositing, and sp_cuda_raster_forward (the whole pipeline).
 *
 * One 16x16 thread block per tile and channel chunk: each thread owns a pixel, the block walks
 * the tile's depth-sorted list in batches of 256 Gaussians staged in shared memory (position,
 * conic, opacity, depth, the chunk's colour values), and composites front to back with the 3DGS
 * bounds. Kernels are specialised on the chunk width CH in SP_CHANNEL_WIDTHS (device.h: 1, 2, 3,
 * 4, 8, 12, 16, 24, 32, 40, 48, 64; the in-between widths keep RGB + 32 features = 35 from paying
 * for 64); a channel count that
 * is not one of those is padded up to the next (padded channels read as zero and are never
 * written), and wider ones run as several chunks (blockIdx.z), each recomputing the cheap
 * per-pixel alpha so registers hold only CH accumulators. The first chunk also writes
 * depth, alpha, the final transmittance and the per-pixel end of the list for backward. */
#include "common.cuh"

#include <stdlib.h>

#define BLOCK (SP_TILE_SIZE * SP_TILE_SIZE)

/* 1: above 8 channels each warp's pixels are an 8 x 4 box of the tile (sp_cu_box_x) and its band
 * test takes the Gaussian's columns too; 0: two rows */
#ifndef SP_FWD_BOX
#define SP_FWD_BOX 1
#endif

/* What compositing one tile of a view reads and writes (a kernel argument: by value for one
 * view, an array on the device for a batch). */
typedef struct fwd_view {
    int W, H, tiles_x;
    const int2 *ranges;
    const uint32_t *ids;
    const float2 *means2d;
    const float4 *conic_op;
    const float *depths;
    float *image, *depth_out, *alpha_out;
    float *t_final;    /* NULL: not kept (batches have no backward) */
    int32_t *last_idx; /* with t_final */
    int cull;          /* warp culling (sp_cu_band_bits) */
} fwd_view;

/* A tile's batch in shared memory: NT Gaussians' position, conic, opacity cut, depth, id and
 * the chunk's CH colour values each, laid out from the dynamic shared memory. */
typedef struct fwd_shared {
    float4 *conic;
    float2 *xy;
    float2 *yr; /* rows it can touch (sp_cu_y_extent), for the wide chunks' band test */
    float2 *xr; /* columns it can touch (the same, x and y swapped), for the box test */
    float *z, *cut;
    int *id;
    float *col;     /* [NT][CH] */
    unsigned *bits; /* [NT / 32 warps][NT / 32 words]: each warp's band bits (fwd_band_bits) */
} fwd_shared;

template <int NT, int CH>
__device__ __forceinline__ fwd_shared fwd_shared_at(float4 *base)
{
    fwd_shared s;
    s.conic = base;
    s.xy = (float2 *)(s.conic + NT);
    s.yr = s.xy + NT;
    s.xr = s.yr + NT;
    s.z = (float *)(s.xr + NT);
    s.cut = s.z + NT;
    s.id = (int *)(s.cut + NT);
    s.col = (float *)(s.id + NT);
    s.bits = (unsigned *)(s.col + NT * CH);
    return s;
}

/* Stages list entries b0 .. b0 + cnt (cnt <= NT threads: one Gaussian each, then the colours,
 * neighbouring threads reading neighbouring channels of one Gaussian); ends on a barrier. */
template <int CH, int NT, bool YR>
__device__ __forceinline__ void fwd_stage(const fwd_view &v, const fwd_shared &s, int b0, int cnt,
                                          int tid, const float *__restrict__ colors, int D, int c0)
{
    if (tid < cnt) {
        int g = (int)v.ids[b0 + tid];
        s.id[tid] = g;
        const float2 xy = v.means2d[g];
        s.xy[tid] = xy;
        const float4 co = v.conic_op[g];
        s.conic[tid] = co;
        const float cut = sp_cu_sigma_cut(co.w);
        s.cut[tid] = cut;
        s.z[tid] = v.depths[g];
        if (YR) s.yr[tid] = sp_cu_y_extent(co, cut, xy.y);
        if (YR && SP_FWD_BOX) s.xr[tid] = sp_cu_y_extent(make_float4(co.z, co.y, co.x, co.w), cut, xy.x);
    }
    __syncthreads();
    for (int k = tid; k < cnt * CH; k += NT) {
        int j = k / CH, c = k - j * CH;
        s.col[k] = (c0 + c < D) ? colors[(size_t)s.id[j] * D + c0 + c] : 0.f;
    }
    __syncthreads();
}

/* After fwd_stage: this warp's band bits for the batch (a warp of a block of NT threads covers
 * 32 / (NT / 16) rows), word c for Gaussians 32 c .. 32 c + 31, read back only by the warp
 * itself. TEST 1: the exact test, sp_cu_band_bits. TEST 2, for chunks wider than 8 channels:
 * only the rows the Gaussian can touch (sp_cu_y_extent, staged by fwd_stage), a few
 * instructions and registers, where the exact test's temporaries beside CH accumulators cost a
 * block per SM (H200, D=32: 78 registers against 64, 3 blocks instead of 4; forward 2.96 ms
 * culled against 2.81 unculled). Both are conservative: a cleared bit is a Gaussian no pixel of
 * the band keeps, so images stay the same bits. TEST 0: every staged Gaussian's bit. */
template <int NT, int TEST>
__device__ __forceinline__ const unsigned *fwd_band_bits(const fwd_view &v, const fwd_shared &s,
                                                         int cnt, int tid, int tx, int ty)
{
    constexpr int NW = NT / 32, RH = SP_TILE_SIZE / NW;
    const int warp = tid >> 5, lane = tid & 31;
    unsigned *bits = s.bits + warp * NW;
    if (TEST == 1 && SP_PX_BOX && NT == BLOCK / 2) { /* fwd_tile_px<CH, 2>: 8 x 8 boxes */
        int x0, x1, y0, y1;
        sp_cu_px2_rect(tx, ty, warp, v.W, v.H, &x0, &x1, &y0, &y1);
#pragma unroll 1
        for (int c = 0; c < NW; c++) {
            const unsigned b = sp_cu_rect_bits(s.conic, s.xy, s.cut, 32 * c, cnt, v.cull, x0, x1, y0, y1, lane);
            if (lane == 0) bits[c] = b;
        }
    } else if (TEST == 1) {
#pragma unroll 1
        for (int c = 0; c < NW; c++) {
            const unsigned b = sp_cu_band_bits(s.conic, s.xy, s.cut, 32 * c, cnt, v.cull, tx, ty, warp,
                                               RH, v.W, v.H, lane);
            if (lane == 0) bits[c] = b;
        }
    } else if (TEST == 2 && SP_FWD_BOX && NT == BLOCK) {
        /* the warp's 8 x 4 box (sp_cu_box_x): its pixel-centre rows and columns, clipped */
        int x0, x1, y0, y1;
        sp_cu_box_rect(tx, ty, warp, v.W, v.H, &x0, &x1, &y0, &y1);
        const float cx0 = x0 + 0.5f, cx1 = x1 + 0.5f, cy0 = y0 + 0.5f, cy1 = y1 + 0.5f;
#pragma unroll 1
        for (int c = 0; c < NW; c++) {
            const int j = 32 * c + lane;
            bool hit = j < cnt;
            if (hit && v.cull) {
                const float2 yr = s.yr[j], xr = s.xr[j];
                hit = y0 <= y1 && x0 <= x1 && yr.x <= cy1 && yr.y >= cy0 && xr.x <= cx1 && xr.y >= cx0;
            }
            const unsigned b = __ballot_sync(0xffffffffu, hit);
            if (lane == 0) bits[c] = b;
        }
    } else {
        /* the band's first and last pixel-centre rows, clipped to the image */
        const int y0 = ty * SP_TILE_SIZE + warp * RH, y1 = min(y0 + RH - 1, v.H - 1);
        const float cy0 = y0 + 0.5f, cy1 = y1 + 0.5f;
#pragma unroll 1
        for (int c = 0; c < NW; c++) {
            const int j = 32 * c + lane;
            bool hit = j < cnt;
            if (TEST == 2 && hit && v.cull) {
                const float2 yr = s.yr[j];
                hit = y0 <= y1 && yr.x <= cy1 && yr.y >= cy0;
            }
            const unsigned b = __ballot_sync(0xffffffffu, hit);
            if (lane == 0) bits[c] = b;
        }
    }
    __syncwarp();
    return bits;
}

/* fwd_tile's walk over a batch's set bits above 32 channels: two Gaussians at a time, their
 * alphas first and branch-free (sp_cu_alpha_flat) so the exps interleave, then the same
 * compositing in the same order, so the same bits. H200, 1M 1080p, D=64: forward 5.17 ms
 * against 5.36 one at a time; at 16 and 32 channels it costs (1.96 against 1.87, 2.79 against
 * 2.65 ms: the 64-register bound), so those walk one at a time. */
template <int CH>
__device__ __forceinline__ void fwd_walk_pairs(const fwd_shared &s, const unsigned *bits, int b0,
                                               float px, float py, float (&acc)[CH], float *acc_z,
                                               float *T, int *last, bool *done)
{
#pragma unroll 1
    for (int wd = 0; wd < BLOCK / 32 && !*done; wd++)
    for (unsigned m = bits[wd]; m && !*done;) {
        int j2[2];
        j2[0] = 32 * wd + __ffs(m) - 1;
        m &= m - 1;
        const bool two = m != 0;
        j2[1] = two ? 32 * wd + __ffs(m) - 1 : j2[0];
        if (two) m &= m - 1;
        float alpha[2];
#pragma unroll
        for (int h = 0; h < 2; h++) {
            const float4 co = s.conic[j2[h]];
            const float2 xy = s.xy[j2[h]];
            float vis;
            alpha[h] = sp_cu_alpha_flat(co, s.cut[j2[h]], px - xy.x, py - xy.y, &vis);
        }
        if (!two) alpha[1] = 0.f;
#pragma unroll
        for (int h = 0; h < 2; h++) {
            if (alpha[h] == 0.f) continue;
            const int j = j2[h];
            const float next_T = *T * (1.f - alpha[h]);
            if (next_T < SP_TRANSMITTANCE_MIN) {
                *done = true;
                break;
            }
            const float w = alpha[h] * *T;
            const float *col = s.col + j * CH;
#pragma unroll
            for (int c = 0; c < CH; c++) acc[c] += col[c] * w;
            *acc_z += s.z[j] * w;
            *T = next_T;
            *last = b0 + j + 1;
        }
    }
}

/* Composites tile (tx, ty) of view v, channels c0 .. c0 + CH; aux: also depth, alpha and the
 * per-pixel state for backward. */
template <int CH>
__device__ __forceinline__ void fwd_tile(const fwd_view &v, int tx, int ty,
                                         const float *__restrict__ colors, int D, int c0,
                                         const float *__restrict__ bg, bool aux)
{
    extern __shared__ float4 smem_f4[];
    const fwd_shared sh = fwd_shared_at<BLOCK, CH>(smem_f4);
    const float4 *s_conic = sh.conic;
    const float2 *s_xy = sh.xy;
    const float *s_z = sh.z, *s_cut = sh.cut, *s_col = sh.col;

    const int tid = threadIdx.y * SP_TILE_SIZE + threadIdx.x;
    constexpr bool BOXED = SP_FWD_BOX && CH > 8; /* the box test's pixels (sp_cu_box_x) */
    const int px_i = tx * SP_TILE_SIZE + (BOXED ? sp_cu_box_x(tid) : (int)threadIdx.x);
    const int py_i = ty * SP_TILE_SIZE + (BOXED ? sp_cu_box_y(tid) : (int)threadIdx.y);
    const bool inside = px_i < v.W && py_i < v.H;
    const float px = px_i + 0.5f, py = py_i + 0.5f;
    const int2 range = v.ranges[ty * v.tiles_x + tx];

    constexpr bool PAIR = CH > 32;
    float acc[CH];
#pragma unroll
    for (int c = 0; c < CH; c++) acc[c] = 0.f;
    float acc_z = 0.f, T = 1.f;
    int last = range.x;
    bool done = !inside;

    for (int b0 = range.x; b0 < range.y; b0 += BLOCK) {
        if (__syncthreads_count(done) == BLOCK) break;
        const int cnt = min(BLOCK, range.y - b0);
        fwd_stage<CH, BLOCK, (CH > 8)>(v, sh, b0, cnt, tid, colors, D, c0);
        const unsigned *bits = fwd_band_bits<BLOCK, (CH <= 8 ? 1 : 2)>(v, sh, cnt, tid, tx, ty);
        if (PAIR) {
            fwd_walk_pairs<CH>(sh, bits, b0, px, py, acc, &acc_z, &T, &last, &done);
        } else {
#pragma unroll 1
        for (int wd = 0; wd < BLOCK / 32 && !done; wd++)
        for (unsigned m = bits[wd]; m && !done; m &= m - 1) {
            const int j = 32 * wd + __ffs(m) - 1;
            const float4 co = s_conic[j];
            const float2 xy = s_xy[j];
            const float dx = px - xy.x, dy = py - xy.y;
            float vis;
            const float alpha = sp_cu_alpha(co, s_cut[j], dx, dy, &vis);
            if (alpha == 0.f) continue;
            const float next_T = T * (1.f - alpha);
            if (next_T < SP_TRANSMITTANCE_MIN) {
                done = true;
                break;
            }
            const float w = alpha * T;
            const float *col = s_col + j * CH;
#pragma unroll
            for (int c = 0; c < CH; c++) acc[c] += col[c] * w;
            acc_z += s_z[j] * w;
            T = next_T;
            last = b0 + j + 1;
        }
        }
    }
    if (!inside) return;
    const size_t pix = (size_t)py_i * v.W + px_i;
#pragma unroll
    for (int c = 0; c < CH; c++)
        if (c0 + c < D) v.image[pix * D + c0 + c] = acc[c] + T * (bg ? bg[c0 + c] : 0.f);
    if (aux) {
        if (v.t_final) v.t_final[pix] = T, v.last_idx[pix] = last;
        if (v.depth_out) v.depth_out[pix] = acc_z;
        if (v.alpha_out) v.alpha_out[pix] = 1.f - T;
    }
}

/* PX pixels per thread for narrow chunks (cfg.fwd_px, CH <= 8), as the backward's
 * k_raster_bwd_px: a (16 / PX) x 16 block per tile, thread (x, y) owning pixels (x + q 16 / PX, y),
 * q < PX, batches of 256 / PX Gaussians. A Gaussian's shared-memory loads, its row terms
 * (sp_gm_row_terms) and the loop's overhead serve PX pixels; per pixel every operation is
 * fwd_tile's in the same order (sp_gm_alpha_row is sp_gm_alpha_g's arithmetic), so images,
 * depth, alpha, the final transmittance and the list ends are the same bit for bit (tested). */
template <int CH, int PX>
__device__ __forceinline__ void fwd_tile_px(const fwd_view &v, int tx, int ty,
                                            const float *__restrict__ colors, int D, int c0,
                                            const float *__restrict__ bg, bool aux)
{
    constexpr int NT = BLOCK / PX;        /* threads, and Gaussians per batch */
    constexpr int BX = SP_TILE_SIZE / PX; /* threads per tile row */
    extern __shared__ float4 smem_f4[];
    const fwd_shared sh = fwd_shared_at<NT, CH>(smem_f4);
    const float4 *s_conic = sh.conic;
    const float2 *s_xy = sh.xy;
    const float *s_z = sh.z, *s_cut = sh.cut, *s_col = sh.col;

    const int tid = threadIdx.y * BX + threadIdx.x;
    constexpr bool PBOX = SP_PX_BOX && PX == 2; /* 8 x 8 warp boxes (sp_cu_px2_pixel) */
    int ox = threadIdx.x, oy = threadIdx.y, step = BX;
    if (PBOX) sp_cu_px2_pixel(tid, &ox, &oy, &step);
    const int py_i = ty * SP_TILE_SIZE + oy;
    const float py = py_i + 0.5f;
    const int2 range = v.ranges[ty * v.tiles_x + tx];

    float px[PX], acc[PX][CH], acc_z[PX], T[PX];
    int last[PX];
    bool done[PX], all_done = true;
#pragma unroll
    for (int q = 0; q < PX; q++) {
        const int px_i = tx * SP_TILE_SIZE + ox + q * step;
        px[q] = px_i + 0.5f;
        done[q] = !(px_i < v.W && py_i < v.H);
        all_done = all_done && done[q];
#pragma unroll
        for (int c = 0; c < CH; c++) acc[q][c] = 0.f;
        acc_z[q] = 0.f, T[q] = 1.f, last[q] = range.x;
    }

    for (int b0 = range.x; b0 < range.y; b0 += NT) {
        if (__syncthreads_count(all_done) == NT) break;
        const int cnt = min(NT, range.y - b0);
        fwd_stage<CH, NT, false>(v, sh, b0, cnt, tid, colors, D, c0);
        const unsigned *bits = fwd_band_bits<NT, 1>(v, sh, cnt, tid, tx, ty);
#pragma unroll 1
        for (int wd = 0; wd < NT / 32 && !all_done; wd++)
        for (unsigned m = bits[wd]; m && !all_done; m &= m - 1) {
            const int j = 32 * wd + __ffs(m) - 1;
            const float4 co = s_conic[j];
            const float2 xy = s_xy[j];
            const float cut = s_cut[j];
            float by, hy;
            const float con[3] = {co.x, co.y, co.z};
            sp_gm_row_terms(con, py - xy.y, &by, &hy);
            const float half_a = 0.5f * co.x;
            all_done = true;
#pragma unroll
            for (int q = 0; q < PX; q++) {
                if (!done[q]) {
                    float vis;
                    const float alpha = sp_gm_alpha_row(half_a, by, hy, co.w, cut, px[q] - xy.x, &vis);
                    if (alpha != 0.f) {
                        const float next_T = T[q] * (1.f - alpha);
                        if (next_T < SP_TRANSMITTANCE_MIN) {
                            done[q] = true;
                        } else {
                            const float w = alpha * T[q];
                            const float *col = s_col + j * CH;
#pragma unroll
                            for (int c = 0; c < CH; c++) acc[q][c] += col[c] * w;
                            acc_z[q] += s_z[j] * w;
                            T[q] = next_T;
                            last[q] = b0 + j + 1;
                        }
                    }
                }
                all_done = all_done && done[q];
            }
        }
    }
#pragma unroll
    for (int q = 0; q < PX; q++) {
        const int px_i = tx * SP_TILE_SIZE + ox + q * step;
        if (!(px_i < v.W && py_i < v.H)) continue;
        const size_t pix = (size_t)py_i * v.W + px_i;
#pragma unroll
        for (int c = 0; c < CH; c++)
            if (c0 + c < D) v.image[pix * D + c0 + c] = acc[q][c] + T[q] * (bg ? bg[c0 + c] : 0.f);
        if (aux) {
            if (v.t_final) v.t_final[pix] = T[q], v.last_idx[pix] = last[q];
            if (v.depth_out) v.depth_out[pix] = acc_z[q];
            if (v.alpha_out) v.alpha_out[pix] = 1.f - T[q];
        }
    }
}

/* One tile with PX pixels per thread (1: fwd_tile). */
template <int CH, int PX>
__device__ __forceinline__ void fwd_tile_as(const fwd_view &v, int tx, int ty,
                                            const float *__restrict__ colors, int D, int c0,
                                            const float *__restrict__ bg, bool aux)
{
    if (PX == 1) fwd_tile<CH>(v, tx, ty, colors, D, c0, bg, aux);
    else fwd_tile_px<CH, PX>(v, tx, ty, colors, D, c0, bg, aux);
}

/* blocks per SM the one-pixel kernel's registers are bounded for above 8 channels: 4 (64
 * registers) up to 32 channels, else 2 (128); the band test's few temporaries would otherwise
 * take a 32-channel chunk to 73 registers (3 blocks) and a 64-channel one to 142 (1 block) */
#define FWD_MIN_BLOCKS(CH, PX) ((PX) != 1 || (CH) <= 8 ? 0 : (CH) <= 32 ? 4 : 2)

template <int CH, int PX>
__global__ void __launch_bounds__(BLOCK / PX, FWD_MIN_BLOCKS(CH, PX))
k_raster_fwd(fwd_view v, const float *__restrict__ colors, int D, int c_base,
             const float *__restrict__ bg, int aux)
{
    fwd_tile_as<CH, PX>(v, blockIdx.x, blockIdx.y, colors, D, c_base + blockIdx.z * CH, bg,
                 aux && blockIdx.z == 0);
}

/* A batch's views in one launch: block x is tile x of the batch, in view order (tile_base[i] is
 * view i's first), so the small grids of small views fill the GPU together instead of one
 * after another (a 320x240 view is 300 blocks: about one wave of an H200, its time that of its
 * slowest tile). */
template <int CH, int PX>
__global__ void __launch_bounds__(BLOCK / PX)
k_raster_fwd_views(const fwd_view *__restrict__ views, const int *__restrict__ tile_base, int nv,
                   const float *__restrict__ colors, int D, int c_base, const float *__restrict__ bg,
                   int aux)
{
    const int t = blockIdx.x;
    int lo = 0, hi = nv - 1; /* the last view whose first tile is <= t */
    while (lo < hi) {
        const int mid = (lo + hi + 1) >> 1;
        if (tile_base[mid] <= t) lo = mid;
        else hi = mid - 1;
    }
    const fwd_view v = views[lo];
    const int local = t - tile_base[lo];
    fwd_tile_as<CH, PX>(v, local % v.tiles_x, local / v.tiles_x, colors, D, c_base + blockIdx.z * CH, bg,
                 aux && blockIdx.z == 0);
}

static fwd_view fwd_view_of(const sp_cuda_view *v, const sp_cuda_pass *p, int state)
{
    fwd_view f = {v->cam.width, v->cam.height, v->tiles_x, v->tile_ranges, v->sorted_ids,
                  v->proj.means2d, v->proj.conic_op, v->proj.depths, p->image, p->depth, p->alpha,
                  state ? v->t_final : NULL, state ? v->last_idx : NULL, v->warp_cull};
    return f;
}

static size_t fwd_smem(int ch, int px)
{
    const size_t nt = BLOCK / px;
    return nt * (sizeof(float4) + 3 * sizeof(float2) + 2 * sizeof(float) + sizeof(int) +
                 sizeof(float) * ch) +
           (nt / 32) * (nt / 32) * sizeof(unsigned);
}

/* One launch of width CH: a single view (views NULL: v) or a batch of nv views (views and
 * tile_base on the device, total_tiles blocks). */
typedef struct fwd_launch {
    const sp_cuda_view *v;
    const sp_cuda_pass *p;
    const fwd_view *views;
    const int *tile_base;
    int nv, total_tiles;
    int px; /* pixels per thread for narrow chunks: 1, 2 or 4 (sp_cuda_fwd_px) */
} fwd_launch;

template <int CH, int PX>
static int launch_fwd(const sp_cuda_raster *r, const fwd_launch *L, int c_base, int n_chunks,
                      int aux, sp_error *err)
{
    size_t smem = fwd_smem(CH, PX);
    const sp_cuda_pass *p = L->p;
    dim3 block(SP_TILE_SIZE / PX, SP_TILE_SIZE, 1);
    if (L->views) {
        SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_fwd_views<CH, PX>,
                                           cudaFuncAttributeMaxDynamicSharedMemorySize, (int)smem),
                      err, "forward shared memory");
        dim3 grid(L->total_tiles, 1, n_chunks);
        k_raster_fwd_views<CH, PX><<<grid, block, smem, r->stream>>>(L->views, L->tile_base, L->nv,
                                                                 p->colors, p->D, c_base,
                                                                 p->bg_dev, aux);
    } else {
        SP_CUDA_CHECK(cudaFuncSetAttribute(k_raster_fwd<CH, PX>,
                                           cudaFuncAttributeMaxDynamicSharedMemorySize, (int)smem),
                      err, "forward shared memory");
        const sp_cuda_view *v = L->v;
        dim3 grid(v->tiles_x, v->tiles_y, n_chunks);
        k_raster_fwd<CH, PX><<<grid, block, smem, r->stream>>>(fwd_view_of(v, p, 1), p->colors, p->D,
                                                           c_base, p->bg_dev, aux);
    }
    SP_CUDA_LAUNCHED(err, "forward rasterization");
    return 0;
}

/* Pixels per thread a chunk of width ch takes: px where ch <= 8 (fwd_tile_px's kernels exist
 * only there), else one. */
static int fwd_px_for(int ch, int px) { return ch <= 8 ? px : 1; }

/* Launches the kernel specialised for width `ch` (one of SP_CHANNEL_WIDTHS) and
 * fwd_px_for(ch, L->px) pixels per thread. */
static int dispatch_fwd(int ch, const sp_cuda_raster *r, const fwd_launch *L, int c_base,
                        int n_chunks, int aux, sp_error *err)
{
    const int px = fwd_px_for(ch, L->px);
    switch (ch) {
#define SP_WIDTH_CASE(w)                                                                          \
    case w:                                                                                       \
        return px == 2   ? launch_fwd<w, (w <= 8 ? 2 : 1)>(r, L, c_base, n_chunks, aux, err)     \
               : px == 4 ? launch_fwd<w, (w <= 8 ? 4 : 1)>(r, L, c_base, n_chunks, aux, err)     \
                         : launch_fwd<w, 1>(r, L, c_base, n_chunks, aux, err);
    SP_CHANNEL_WIDTHS(SP_WIDTH_CASE)
#undef SP_WIDTH_CASE
    default: return sp_error_set(err, SP_E_ARG, "no forward kernel for chunk width %d", ch);
    }
}

/* D channels as full chunks of max_ch plus one narrower launch for the rest; aux: write depth,
 * alpha and (single views) the final transmittance and the list ends, once, from the first
 * chunk. Records the widest chunk's pixels per thread (sp_raster_stages.fwd_px). */
static int rasterize_chunks(sp_cuda_raster *r, const fwd_launch *L, int max_ch, int aux,
                            sp_error *err)
{
    int D = L->p->D, rc;
    int full = D / max_ch, rem = D % max_ch;
    r->fwd_px = fwd_px_for(full > 0 ? max_ch : sp_channel_width(rem, max_ch), L->px);
    if (full > 0 && (rc = dispatch_fwd(max_ch, r, L, 0, full, aux, err))) return rc;
    if (rem > 0 && (rc = dispatch_fwd(sp_channel_width(rem, max_ch), r, L, full * max_ch, 1,
                                      aux && full == 0, err)))
        return rc;
    return 0;
}

int sp_cuda_fwd_px(const sp_raster_cfg *cfg) { return cfg->fwd_px == 0 ? 2 : cfg->fwd_px; }

int sp_cuda_rasterize_fwd(sp_cuda_raster *r, const sp_cuda_view *v, const sp_cuda_pass *p,
                          int max_ch, int px, int aux, sp_error *err)
{
    fwd_launch L = {v, p, NULL, NULL, 1, v->tiles_x * v->tiles_y, px};
    return rasterize_chunks(r, &L, max_ch, aux, err);
}

int sp_cuda_rasterize_fwd_views(sp_cuda_raster *r, const sp_cuda_view *const *views,
                                const sp_cuda_pass *passes, size_t nv, int max_ch, int px,
                                int aux, sp_error *err)
{
    if (nv == 0) return 0;
    size_t vb = sizeof(fwd_view) * nv, bytes = vb + sizeof(int) * nv;
    fwd_view *hv = (fwd_view *)malloc(bytes);
    if (!hv) return sp_error_set(err, SP_E_NOMEM, "sp_render_views: out of host memory");
    int *hb = (int *)((char *)hv + vb);
    size_t total = 0;
    for (size_t i = 0; i < nv; i++) {
        hv[i] = fwd_view_of(views[i], &passes[i], 0);
        hb[i] = (int)total;
        total += (size_t)views[i]->tiles_x * views[i]->tiles_y;
    }
    int rc = total > 0x7fffffff ? sp_error_set(err, SP_E_ARG, "sp_render_views: %zu tiles in one "
                                               "batch exceed a grid", total)
                                : sp_cu_reserve(r, &r->s_batch, bytes, err);
    /* a pageable copy: the host buffer is staged before the call returns, so it can go */
    if (!rc && cudaMemcpyAsync(r->s_batch.ptr, hv, bytes, cudaMemcpyHostToDevice, r->stream) != cudaSuccess)
        rc = sp_error_set(err, SP_E_DEVICE, "CUDA: uploading the batch's views failed");
    free(hv);
    if (rc) return rc;
    /* every view's pass shares colours, D and background (the caller checked) */
    fwd_launch L = {views[0], &passes[0], (const fwd_view *)r->s_batch.ptr,
                    (const int *)((char *)r->s_batch.ptr + vb), (int)nv, (int)total, px};
    return rasterize_chunks(r, &L, max_ch, aux, err);
}

/* Uploads a host background of D floats into the raster's scratch (NULL: none). */
int sp_cuda_upload_background(sp_cuda_raster *r, const float *bg, int D, float **out, sp_error *err)
{
    *out = NULL;
    if (!bg) return 0;
    int rc = sp_cu_reserve(r, &r->s_bg, (size_t)D * sizeof(float), err);
    if (rc) return rc;
    SP_CUDA_CHECK(cudaMemcpyAsync(r->s_bg.ptr, bg, (size_t)D * sizeof(float), cudaMemcpyHostToDevice,
                                  r->stream),
                  err, "uploading the background");
    *out = (float *)r->s_bg.ptr;
    return 0;
}

/* ---- the whole forward --------------------------------------------------------------------- */

int sp_cuda_raster_forward(void *state, const sp_camera *cam, const sp_raster_cfg *cfg,
                                      const sp_raster_in *in, sp_raster_out *out, sp_error *err)
{
    sp_cuda_raster *r = (sp_cuda_raster *)state;
    sp_cuda_view *v = &r->view;
    int rc;
    r->have_forward = 0;
    v->cam = *cam;
    r->cfg = *cfg;
    r->in = *in;
    r->in.background = NULL; /* host pointer; kept on the device in bg_dev */
    v->tiles_x = (cam->width + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
    v->tiles_y = (cam->height + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
    v->box_tiles = cfg->box_tiles;
    v->warp_cull = cfg->warp_cull >= 0;
    size_t npix = (size_t)cam->width * cam->height;

    if ((rc = sp_cuda_upload_background(r, in->background, in->D, &r->bg_dev, err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_tfinal, npix * sizeof(float), err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_last, npix * sizeof(int32_t), err))) return rc;
    v->t_final = (float *)r->s_tfinal.ptr;
    v->last_idx = (int32_t *)r->s_last.ptr;

    if ((rc = sp_cuda_reserve_proj(r, in->n, &v->proj, err))) return rc;
    r->prof_fwd = r->prof_bwd = 0;
    r->profiling = cfg->profile;
    if (r->profiling && (rc = sp_cuda_make_events(r, err))) return rc;
    sp_cu_mark(r, SP_EV_START);
    if ((rc = sp_cuda_project(r, v, cfg, in, err))) return rc;
    sp_cu_mark(r, SP_EV_PROJECTED);
    if ((rc = sp_cuda_bin_and_sort(r, v, in->n, err))) return rc;
    sp_cu_mark(r, SP_EV_SORTED);
    sp_cuda_pass pass = {in->colors, in->D, r->bg_dev, out->image, out->depth, out->alpha};
    int max_ch = cfg->chunk_fwd ? cfg->chunk_fwd : SP_CHANNEL_CHUNK_MAX;
    if ((rc = sp_cuda_rasterize_fwd(r, v, &pass, max_ch, sp_cuda_fwd_px(cfg), 1, err))) return rc;
    sp_cu_mark(r, SP_EV_FWD_DONE);
    r->prof_fwd = r->profiling;
    if (out->surface_depth &&
        (rc = sp_cuda_rasterize_surface(r, v, cfg->surface_alpha, out->surface_depth, err)))
        return rc;
    r->have_forward = 1;
    return 0;
}
