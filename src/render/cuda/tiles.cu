/* CUDA backend, stage 2: tile binning, in two sorts (the CPU backend's order, tiles.c):
 *
 *  1. the Gaussians are sorted once by camera depth (cub radix sort of n 32-bit keys, the float
 *     bits of a positive depth ordering like its value; culled ones get the largest key and go
 *     last); the sort is stable, so equal depths keep index order;
 *  2. in that order each Gaussian counts, then emits, one (tile, id) pair per tile of its pixel
 *     box that its alpha >= 1/255 ellipse reaches (sp_gm_tile_hit: exact ellipse-vs-tile culling;
 *     the box's every tile when cfg.box_tiles); a stable radix sort over the tile bits only
 *     (16-bit keys when the image has at most 65536 tiles) then groups the pairs by tile, each
 *     tile's list staying front to back, ordered by (depth, index).
 * Against one sort of 64-bit (tile << 32 | depth) keys this sorts 13 to 16 bits per pair instead
 * of 45 (two radix passes instead of six) and keeps 12 bytes per pair instead of 24. Memory is
 * O(visible pairs), never image x Gaussians. */
#include "common.cuh"

#include <cub/cub.cuh>

/* ---- depth order --------------------------------------------------------------------------- */

__global__ void k_depth_keys(size_t n, const int32_t *__restrict__ radii,
                             const float *__restrict__ depths, uint32_t *__restrict__ keys,
                             uint32_t *__restrict__ ids)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    keys[i] = radii[i] > 0 ? __float_as_uint(depths[i]) : 0xffffffffu;
    ids[i] = (uint32_t)i;
}

int sp_cuda_depth_order(sp_cuda_raster *r, const sp_cuda_view *v, size_t n, uint32_t *ids,
                        uint32_t *tmp, sp_error *err)
{
    uint32_t *k0 = tmp, *k1 = tmp + n, *ids1 = tmp + 2 * n;
    k_depth_keys<<<sp_div_up(n, 256), 256, 0, r->stream>>>(n, v->proj.radii, v->proj.depths, k0,
                                                           ids);
    SP_CUDA_LAUNCHED(err, "depth keys");
    cub::DoubleBuffer<uint32_t> dk(k0, k1), dv(ids, ids1);
    size_t bytes = r->s_cub.cap;
    SP_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(r->s_cub.ptr, bytes, dk, dv, (int64_t)n, 0, 32,
                                                  r->stream),
                  err, "depth sort");
    if (dv.Current() != ids)
        SP_CUDA_CHECK(cudaMemcpyAsync(ids, dv.Current(), n * sizeof(uint32_t),
                                      cudaMemcpyDeviceToDevice, r->stream),
                      err, "copying the depth order");
    return 0;
}

/* ---- counting and emitting pairs ------------------------------------------------------------- */

/* Whether the Gaussian with pixel box b, mean xy and conic/opacity co keeps tile (tx, ty). */
__device__ __forceinline__ bool tile_kept(short4 b, float2 xy, float4 co, float cut, int tx,
                                          int ty, int box_tiles)
{
    /* a box within one tile keeps it (as the CPU's tile_kept) */
    if (box_tiles || (b.x / SP_TILE_SIZE == b.z / SP_TILE_SIZE && b.y / SP_TILE_SIZE == b.w / SP_TILE_SIZE))
        return true;
    const int x0 = tx * SP_TILE_SIZE, y0 = ty * SP_TILE_SIZE;
    const float con[3] = {co.x, co.y, co.z};
    return sp_gm_tile_hit(con, cut, xy.x, xy.y, max(x0, (int)b.x), min(x0 + SP_TILE_SIZE - 1, (int)b.z),
                          max(y0, (int)b.y), min(y0 + SP_TILE_SIZE - 1, (int)b.w));
}

/* Calls f(tx, ty) for each tile Gaussian g keeps, row by row: the one walk both the counting and
 * the emitting kernel make, so they agree on every tile. */
template <typename F>
__device__ __forceinline__ void for_kept_tiles(uint32_t g, const short4 *__restrict__ box,
                                               const float2 *__restrict__ means2d,
                                               const float4 *__restrict__ conic_op, int box_tiles,
                                               F f)
{
    const short4 b = box[g];
    const float2 xy = means2d[g];
    const float4 co = conic_op[g];
    const float cut = sp_cu_sigma_cut(co.w);
    for (int ty = b.y / SP_TILE_SIZE; ty <= b.w / SP_TILE_SIZE; ty++)
        for (int tx = b.x / SP_TILE_SIZE; tx <= b.z / SP_TILE_SIZE; tx++)
            if (tile_kept(b, xy, co, cut, tx, ty, box_tiles)) f(tx, ty);
}

__global__ void k_count_pairs(size_t n, const uint32_t *__restrict__ ids,
                              const int32_t *__restrict__ radii, const short4 *__restrict__ box,
                              const float2 *__restrict__ means2d,
                              const float4 *__restrict__ conic_op, int box_tiles,
                              uint32_t *__restrict__ counts)
{
    size_t k = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (k >= n) return;
    const uint32_t g = ids[k];
    uint32_t cnt = 0;
    if (radii[g] > 0) for_kept_tiles(g, box, means2d, conic_op, box_tiles, [&](int, int) { cnt++; });
    counts[k] = cnt;
}

int sp_cuda_count_pairs(sp_cuda_raster *r, const sp_cuda_view *v, size_t n, const uint32_t *ids,
                        uint32_t *counts, sp_error *err)
{
    const sp_cuda_proj *p = &v->proj;
    k_count_pairs<<<sp_div_up(n, 256), 256, 0, r->stream>>>(n, ids, p->radii, p->box, p->means2d,
                                                            p->conic_op, v->box_tiles, counts);
    SP_CUDA_LAUNCHED(err, "counting tile pairs");
    return 0;
}

/* The same walk as k_count_pairs (same tests, so the same count), writing the pairs; never past
 * the Gaussian's end offset whatever happens. */
template <typename K>
__global__ void k_emit_pairs(size_t n, const uint32_t *__restrict__ ids,
                             const unsigned long long *__restrict__ offsets,
                             unsigned long long first, const short4 *__restrict__ box, const float2 *__restrict__ means2d,
                             const float4 *__restrict__ conic_op, int tiles_x, int box_tiles,
                             K *__restrict__ keys, uint32_t *__restrict__ vals)
{
    size_t k = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (k >= n) return;
    unsigned long long o = k ? offsets[k - 1] : first, end = offsets[k];
    if (o == end) return;
    const uint32_t g = ids[k];
    for_kept_tiles(g, box, means2d, conic_op, box_tiles, [&](int tx, int ty) {
        if (o >= end) return;
        keys[o] = (K)(ty * tiles_x + tx);
        vals[o] = g;
        o++;
    });
}

int sp_cuda_emit_pairs(sp_cuda_raster *r, const sp_cuda_view *v, size_t n, const uint32_t *ids,
                       const unsigned long long *offsets, unsigned long long first, void *keys,
                       uint32_t *vals, sp_error *err)
{
    const sp_cuda_proj *p = &v->proj;
    if (sp_cuda_key_bytes(v) == 2)
        k_emit_pairs<uint16_t><<<sp_div_up(n, 256), 256, 0, r->stream>>>(
            n, ids, offsets, first, p->box, p->means2d, p->conic_op, v->tiles_x, v->box_tiles,
            (uint16_t *)keys, vals);
    else
        k_emit_pairs<uint32_t><<<sp_div_up(n, 256), 256, 0, r->stream>>>(
            n, ids, offsets, first, p->box, p->means2d, p->conic_op, v->tiles_x, v->box_tiles,
            (uint32_t *)keys, vals);
    SP_CUDA_LAUNCHED(err, "emitting tile pairs");
    return 0;
}

/* ---- the tile sort ----------------------------------------------------------------------------- */

template <typename K>
__global__ void k_tile_ranges(size_t m, const K *__restrict__ keys, int2 *__restrict__ ranges)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= m) return;
    uint32_t t = keys[i];
    if (i == 0 || (uint32_t)keys[i - 1] != t) ranges[t].x = (int)i;
    if (i == m - 1 || (uint32_t)keys[i + 1] != t) ranges[t].y = (int)(i + 1);
}

int sp_cuda_key_bytes(const sp_cuda_view *v)
{
    return (size_t)v->tiles_x * v->tiles_y <= 65536 ? 2 : 4;
}

/* Bits the tile sort looks at. */
static int tile_bits(const sp_cuda_view *v)
{
    int n_tiles = v->tiles_x * v->tiles_y, bits = 1;
    while ((1 << bits) < n_tiles) bits++;
    return bits;
}

template <typename K>
static int sort_typed(sp_cuda_raster *r, sp_cuda_view *v, void *k0, void *k1, uint32_t *v0,
                      uint32_t *v1, int2 *ranges, void *tmp, size_t *bytes, sp_error *err)
{
    size_t m = v->n_pairs;
    cub::DoubleBuffer<K> dk((K *)k0, (K *)k1);
    cub::DoubleBuffer<uint32_t> dv(v0, v1);
    SP_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(tmp, *bytes, dk, dv, (int64_t)m, 0, tile_bits(v),
                                                  r ? r->stream : 0),
                  err, "radix sort of tile keys");
    if (!tmp) return 0; /* a size query */
    k_tile_ranges<K><<<sp_div_up(m, 256), 256, 0, r->stream>>>(m, dk.Current(), ranges);
    SP_CUDA_LAUNCHED(err, "tile ranges");
    v->sorted_ids = dv.Current();
    return 0;
}

static int sort_dispatch(sp_cuda_raster *r, sp_cuda_view *v, void *k0, void *k1, uint32_t *v0,
                         uint32_t *v1, int2 *ranges, void *tmp, size_t *bytes, sp_error *err)
{
    return sp_cuda_key_bytes(v) == 2
               ? sort_typed<uint16_t>(r, v, k0, k1, v0, v1, ranges, tmp, bytes, err)
               : sort_typed<uint32_t>(r, v, k0, k1, v0, v1, ranges, tmp, bytes, err);
}

int sp_cuda_sort_temp_bytes(const sp_cuda_view *v, size_t m, size_t *bytes, sp_error *err)
{
    sp_cuda_view q = *v;
    q.n_pairs = m;
    *bytes = 0;
    return sort_dispatch(NULL, &q, NULL, NULL, NULL, NULL, NULL, NULL, bytes, err);
}

int sp_cuda_sort_pairs(sp_cuda_raster *r, sp_cuda_view *v, void *k0, void *k1, uint32_t *v0,
                       uint32_t *v1, int2 *ranges, sp_error *err)
{
    size_t bytes = 0;
    int rc = sp_cuda_sort_temp_bytes(v, v->n_pairs, &bytes, err);
    if (rc || (rc = sp_cu_reserve(r, &r->s_cub, bytes, err))) return rc;
    bytes = r->s_cub.cap;
    return sort_dispatch(r, v, k0, k1, v0, v1, ranges, r->s_cub.ptr, &bytes, err);
}

/* cub's temporary bytes for the depth sort of n keys and the scan of m counts. */
int sp_cuda_prep_temp_bytes(size_t n, size_t m, size_t *bytes, sp_error *err)
{
    cub::DoubleBuffer<uint32_t> dk(NULL, NULL), dv(NULL, NULL);
    size_t a = 0, b = 0;
    SP_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(NULL, a, dk, dv, (int64_t)n, 0, 32), err,
                  "depth sort size query");
    SP_CUDA_CHECK(cub::DeviceScan::InclusiveSum(NULL, b, (const uint32_t *)NULL,
                                                (unsigned long long *)NULL, (int64_t)m),
                  err, "scan size query");
    *bytes = a > b ? a : b;
    return 0;
}

int sp_cuda_scan_counts(sp_cuda_raster *r, const uint32_t *counts, unsigned long long *offsets,
                        size_t m, sp_error *err)
{
    size_t bytes = r->s_cub.cap;
    SP_CUDA_CHECK(cub::DeviceScan::InclusiveSum(r->s_cub.ptr, bytes, counts, offsets, (int64_t)m,
                                                r->stream),
                  err, "tile-count scan");
    return 0;
}

/* ---- one view ------------------------------------------------------------------------------------ */

int sp_cuda_bin_and_sort(sp_cuda_raster *r, sp_cuda_view *v, size_t n, sp_error *err)
{
    int n_tiles = v->tiles_x * v->tiles_y;
    int rc;
    if ((rc = sp_cu_reserve(r, &r->s_tile_ranges, (size_t)n_tiles * sizeof(int2), err))) return rc;
    SP_CUDA_CHECK(cudaMemsetAsync(r->s_tile_ranges.ptr, 0, (size_t)n_tiles * sizeof(int2), r->stream),
                  err, "clearing tile ranges");
    v->tile_ranges = (const int2 *)r->s_tile_ranges.ptr;
    v->sorted_ids = NULL;
    v->n_pairs = 0;
    if (n == 0) {
        sp_cu_mark(r, SP_EV_COUNTED);
        return 0;
    }

    /* work area: offsets [n] (64 bits, so no count can wrap), depth order [n], counts [n],
     * sort temporaries [3n]; the backward reuses it for its per-Gaussian sums */
    size_t tmp = 0;
    if ((rc = sp_cu_reserve(r, &r->s_work, sp_cuda_work_bytes(n), err)) ||
        (rc = sp_cuda_prep_temp_bytes(n, n, &tmp, err)) ||
        (rc = sp_cu_reserve(r, &r->s_cub, tmp, err)))
        return rc;
    unsigned long long *offsets = (unsigned long long *)r->s_work.ptr;
    uint32_t *ids = (uint32_t *)(offsets + n), *counts = ids + n, *sort_tmp = counts + n;
    if ((rc = sp_cuda_depth_order(r, v, n, ids, sort_tmp, err)) ||
        (rc = sp_cuda_count_pairs(r, v, n, ids, counts, err)) ||
        (rc = sp_cuda_scan_counts(r, counts, offsets, n, err)))
        return rc;
    sp_cu_mark(r, SP_EV_COUNTED);
    /* the one wait of a view: the sort needs the pair count on the host */
    unsigned long long total = 0;
    SP_CUDA_CHECK(cudaMemcpyAsync(&total, offsets + n - 1, sizeof(total), cudaMemcpyDeviceToHost,
                                  r->stream),
                  err, "reading the pair count");
    SP_CUDA_CHECK(cudaStreamSynchronize(r->stream), err,
                  "reading the pair count (an earlier kernel may have failed)");
    if (total > 0x7fffffffull)
        return sp_error_set(err, SP_E_NOMEM,
                            "%llu (Gaussian, tile) pairs exceed the 2^31 the rasterizer indexes",
                            total);
    v->n_pairs = (size_t)total;
    if (total == 0) return 0;

    size_t m = (size_t)total, kb = (size_t)sp_cuda_key_bytes(v);
    for (int k = 0; k < 2; k++) {
        if ((rc = sp_cu_reserve(r, &r->s_keys[k], m * kb, err))) return rc;
        if ((rc = sp_cu_reserve(r, &r->s_vals[k], m * sizeof(uint32_t), err))) return rc;
    }
    uint32_t *v0 = (uint32_t *)r->s_vals[0].ptr, *v1 = (uint32_t *)r->s_vals[1].ptr;
    if ((rc = sp_cuda_emit_pairs(r, v, n, ids, offsets, 0, r->s_keys[0].ptr, v0, err))) return rc;
    return sp_cuda_sort_pairs(r, v, r->s_keys[0].ptr, r->s_keys[1].ptr, v0, v1,
                              (int2 *)r->s_tile_ranges.ptr, err);
}
