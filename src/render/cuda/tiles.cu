/* CUDA backend, stage 2: tile binning and the device radix sort.
 *
 * Every visible Gaussian emits one (key, id) pair per 16x16 tile its rectangle touches, key =
 * tile << 32 | float bits of its camera depth (positive floats order like their bit patterns).
 * cub's radix sort over the low 32 + ceil(log2(tiles)) bits then orders pairs by tile, and
 * within a tile front to back; the sort is stable, so equal depths keep Gaussian-index order,
 * as the CPU backend's per-tile sort does. Memory is O(visible pairs), never image x Gaussians. */
#include "common.cuh"

#include <cub/cub.cuh>

__global__ void k_emit_pairs(size_t n, const int4 *__restrict__ rect,
                             const uint32_t *__restrict__ ntiles,
                             const unsigned long long *__restrict__ offsets,
                             const float *__restrict__ depths, int tiles_x,
                             unsigned long long *__restrict__ keys, uint32_t *__restrict__ vals)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n || ntiles[i] == 0) return;
    unsigned long long o = offsets[i] - ntiles[i]; /* offsets are inclusive sums */
    int4 b = rect[i];
    unsigned long long dbits = (unsigned long long)__float_as_uint(depths[i]);
    for (int ty = b.y; ty < b.w; ty++)
        for (int tx = b.x; tx < b.z; tx++) {
            unsigned long long tile = (unsigned long long)(ty * tiles_x + tx);
            keys[o] = (tile << 32) | dbits;
            vals[o] = (uint32_t)i;
            o++;
        }
}

__global__ void k_tile_ranges(size_t m, const unsigned long long *__restrict__ keys,
                              int2 *__restrict__ ranges)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= m) return;
    uint32_t t = (uint32_t)(keys[i] >> 32);
    if (i == 0 || (uint32_t)(keys[i - 1] >> 32) != t) ranges[t].x = (int)i;
    if (i == m - 1 || (uint32_t)(keys[i + 1] >> 32) != t) ranges[t].y = (int)(i + 1);
}

int sp_cuda_emit_pairs(sp_cuda_raster *r, const sp_cuda_view *v, size_t n,
                       const unsigned long long *offsets, unsigned long long *keys,
                       uint32_t *vals, sp_error *err)
{
    k_emit_pairs<<<sp_div_up(n, 256), 256, 0, r->stream>>>(n, v->proj.rect, v->proj.ntiles,
                                                           offsets, v->proj.depths, v->tiles_x,
                                                           keys, vals);
    SP_CUDA_LAUNCHED(err, "emitting tile pairs");
    return 0;
}

/* Bits the radix sort looks at: depth (32) and the tile index. */
static int sort_bits(const sp_cuda_view *v)
{
    int n_tiles = v->tiles_x * v->tiles_y, tile_bits = 1;
    while ((1 << tile_bits) < n_tiles) tile_bits++;
    return 32 + tile_bits;
}

/* cub's temporary storage for sorting m pairs of view v (a host-side size query). */
static int sort_temp_bytes(const sp_cuda_view *v, size_t m, size_t *bytes, sp_error *err)
{
    cub::DoubleBuffer<unsigned long long> dk(NULL, NULL);
    cub::DoubleBuffer<uint32_t> dv(NULL, NULL);
    *bytes = 0;
    SP_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(NULL, *bytes, dk, dv, (int64_t)m, 0, sort_bits(v)),
                  err, "sort size query");
    return 0;
}

int sp_cuda_sort_pairs(sp_cuda_raster *r, sp_cuda_view *v, unsigned long long *k0,
                       unsigned long long *k1, uint32_t *v0, uint32_t *v1, int2 *ranges,
                       sp_error *err)
{
    size_t m = v->n_pairs, tmp_sort = 0;
    int rc = sort_temp_bytes(v, m, &tmp_sort, err);
    if (rc || (rc = sp_cu_reserve(r, &r->s_cub, tmp_sort, err))) return rc;
    cub::DoubleBuffer<unsigned long long> dk(k0, k1);
    cub::DoubleBuffer<uint32_t> dv(v0, v1);
    SP_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(r->s_cub.ptr, tmp_sort, dk, dv, (int64_t)m, 0,
                                                  sort_bits(v), r->stream),
                  err, "radix sort of (tile, depth) keys");
    k_tile_ranges<<<sp_div_up(m, 256), 256, 0, r->stream>>>(m, dk.Current(), ranges);
    SP_CUDA_LAUNCHED(err, "tile ranges");
    v->sorted_ids = dv.Current();
    return 0;
}

int sp_cuda_sort_temp_bytes(const sp_cuda_view *v, size_t m, size_t *bytes, sp_error *err)
{
    return sort_temp_bytes(v, m, bytes, err);
}

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
    if (n == 0) return 0;

    /* inclusive scan of per-Gaussian tile counts, in 64 bits so no count can wrap */
    if ((rc = sp_cu_reserve(r, &r->s_offsets, n * sizeof(unsigned long long), err))) return rc;
    unsigned long long *offsets = (unsigned long long *)r->s_offsets.ptr;
    size_t tmp_scan = 0;
    SP_CUDA_CHECK(cub::DeviceScan::InclusiveSum(NULL, tmp_scan, v->proj.ntiles, offsets, (int64_t)n),
                  err, "scan size query");
    if ((rc = sp_cu_reserve(r, &r->s_cub, tmp_scan, err))) return rc;
    SP_CUDA_CHECK(cub::DeviceScan::InclusiveSum(r->s_cub.ptr, tmp_scan, v->proj.ntiles, offsets,
                                                (int64_t)n, r->stream),
                  err, "tile-count scan");
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

    size_t m = (size_t)total;
    for (int k = 0; k < 2; k++) {
        if ((rc = sp_cu_reserve(r, &r->s_keys[k], m * sizeof(unsigned long long), err))) return rc;
        if ((rc = sp_cu_reserve(r, &r->s_vals[k], m * sizeof(uint32_t), err))) return rc;
    }
    unsigned long long *k0 = (unsigned long long *)r->s_keys[0].ptr;
    unsigned long long *k1 = (unsigned long long *)r->s_keys[1].ptr;
    uint32_t *v0 = (uint32_t *)r->s_vals[0].ptr, *v1 = (uint32_t *)r->s_vals[1].ptr;
    if ((rc = sp_cuda_emit_pairs(r, v, n, offsets, k0, v0, err))) return rc;
    return sp_cuda_sort_pairs(r, v, k0, k1, v0, v1, (int2 *)r->s_tile_ranges.ptr, err);
}
