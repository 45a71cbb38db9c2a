/* CUDA backend: a batch of views of one set of Gaussians (sp_render_views), with one wait for the
 * GPU per batch instead of one per view. Every view is projected into its own slice of one
 * projection buffer ([views][n]); one scan over all the slices' tile counts gives every pair its
 * place in one pair buffer, so one copy of the views' totals (the only wait) sizes every
 * sort; then each view's pairs are emitted, sorted and composited with the single-view kernels,
 * unchanged, on pointers into its slices, all queued on the device's stream. The per-pixel
 * forward state (final transmittance, list ends) is shared: nothing differentiates a batch. */
#include "common.cuh"

#include <cub/cub.cuh>
#include <stdlib.h>

typedef struct {
    sp_cuda_view v;
    size_t tile_base; /* first entry in the batch's tile ranges */
    size_t pair_base; /* first pair in the batch's pair buffers */
} batch_view;

static void slice_proj(const sp_cuda_proj *all, size_t at, sp_cuda_proj *p)
{
    p->means2d = all->means2d + at;
    p->conic_op = all->conic_op + at;
    p->depths = all->depths + at;
    p->radii = all->radii + at;
    p->rect = all->rect + at;
    p->ntiles = all->ntiles + at;
}

/* Buffers whose size is known before any work is queued (growing one later would free it while
 * kernels may still use it). */
static int reserve_upfront(sp_cuda_raster *r, const sp_raster_view *views, size_t nv, size_t n,
                           size_t total_tiles, size_t max_npix, sp_cuda_proj *all, sp_error *err)
{
    int max_d = 1, rc;
    for (size_t i = 0; i < nv; i++)
        for (int k = 0; k < views[i].n_pass; k++)
            if (views[i].pass[k].D > max_d) max_d = views[i].pass[k].D;
    if ((rc = sp_cu_reserve(r, &r->s_tfinal, max_npix * sizeof(float), err)) ||
        (rc = sp_cu_reserve(r, &r->s_last, max_npix * sizeof(int32_t), err)) ||
        (rc = sp_cu_reserve(r, &r->s_bg, (size_t)max_d * sizeof(float), err)) ||
        (rc = sp_cu_reserve(r, &r->s_tile_ranges, total_tiles * sizeof(int2), err)) ||
        (rc = sp_cu_reserve(r, &r->s_offsets, (nv * n ? nv * n : 1) * sizeof(unsigned long long), err)) ||
        (rc = sp_cu_reserve(r, &r->s_counts, nv * sizeof(unsigned long long), err)))
        return rc;
    return sp_cuda_reserve_proj(r, nv * n, all, err);
}

/* ends[v] = offsets[(v + 1) n - 1]: where view v's pairs end in the batch's pair buffers. */
__global__ void k_view_ends(const unsigned long long *__restrict__ offsets, size_t n, size_t nv,
                            unsigned long long *__restrict__ ends)
{
    size_t v = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (v < nv) ends[v] = offsets[(v + 1) * n - 1];
}

/* Projections, the scan of all tile counts and the one wait for the views' pair totals. */
static int project_and_count(sp_cuda_raster *r, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                             batch_view *bv, size_t nv, unsigned long long *ends, sp_error *err)
{
    size_t n = geom->n, count = nv * n;
    for (size_t i = 0; i < nv; i++) {
        int rc = sp_cuda_project(r, &bv[i].v, cfg, geom, err);
        if (rc) return sp_error_prefix(err, "view %zu: ", i);
    }
    unsigned long long *offsets = (unsigned long long *)r->s_offsets.ptr;
    const uint32_t *ntiles = bv[0].v.proj.ntiles; /* slice 0 starts the whole buffer */
    size_t tmp = 0;
    SP_CUDA_CHECK(cub::DeviceScan::InclusiveSum(NULL, tmp, ntiles, offsets, (int64_t)count), err,
                  "scan size query");
    int rc = sp_cu_reserve(r, &r->s_cub, tmp, err);
    if (rc) return rc;
    SP_CUDA_CHECK(cub::DeviceScan::InclusiveSum(r->s_cub.ptr, tmp, ntiles, offsets, (int64_t)count,
                                                r->stream),
                  err, "tile-count scan");
    /* view i's pairs end at offsets[(i + 1) n - 1]: gathered, then one copy of nv values */
    unsigned long long *d_ends = (unsigned long long *)r->s_counts.ptr;
    k_view_ends<<<sp_div_up(nv, 256), 256, 0, r->stream>>>(offsets, n, nv, d_ends);
    SP_CUDA_LAUNCHED(err, "gathering the views' pair counts");
    SP_CUDA_CHECK(cudaMemcpyAsync(ends, d_ends, nv * sizeof *ends, cudaMemcpyDeviceToHost, r->stream),
                  err, "reading the views' pair counts");
    SP_CUDA_CHECK(cudaStreamSynchronize(r->stream), err,
                  "reading the views' pair counts (an earlier kernel may have failed)");
    return 0;
}

/* Emits and sorts every view's pairs into its segment of the pair buffers. */
static int sort_views(sp_cuda_raster *r, batch_view *bv, size_t nv, size_t n,
                      const unsigned long long *ends, sp_error *err)
{
    size_t total = (size_t)ends[nv - 1], tmp_max = 0;
    for (size_t i = 0; i < nv; i++) {
        bv[i].pair_base = i ? (size_t)ends[i - 1] : 0;
        unsigned long long m = ends[i] - (i ? ends[i - 1] : 0);
        if (m > 0x7fffffffull)
            return sp_error_set(err, SP_E_NOMEM, "view %zu: %llu (Gaussian, tile) pairs exceed the "
                                "2^31 the rasterizer indexes", i, m);
        bv[i].v.n_pairs = (size_t)m;
        size_t b = 0;
        int rc = sp_cuda_sort_temp_bytes(&bv[i].v, (size_t)m, &b, err);
        if (rc) return rc;
        if (b > tmp_max) tmp_max = b;
    }
    if (total == 0) return 0;
    int rc;
    for (int k = 0; k < 2; k++)
        if ((rc = sp_cu_reserve(r, &r->s_keys[k], total * sizeof(unsigned long long), err)) ||
            (rc = sp_cu_reserve(r, &r->s_vals[k], total * sizeof(uint32_t), err)))
            return rc;
    if ((rc = sp_cu_reserve(r, &r->s_cub, tmp_max, err))) return rc;
    unsigned long long *k0 = (unsigned long long *)r->s_keys[0].ptr;
    unsigned long long *k1 = (unsigned long long *)r->s_keys[1].ptr;
    uint32_t *v0 = (uint32_t *)r->s_vals[0].ptr, *v1 = (uint32_t *)r->s_vals[1].ptr;
    const unsigned long long *offsets = (const unsigned long long *)r->s_offsets.ptr;
    for (size_t i = 0; i < nv && !rc; i++) {
        if (bv[i].v.n_pairs == 0) continue;
        size_t at = bv[i].pair_base;
        rc = sp_cuda_emit_pairs(r, &bv[i].v, n, offsets + i * n, k0, v0, err);
        if (!rc)
            rc = sp_cuda_sort_pairs(r, &bv[i].v, k0 + at, k1 + at, v0 + at, v1 + at,
                                    (int2 *)r->s_tile_ranges.ptr + bv[i].tile_base, err);
    }
    return rc;
}

static int composite_views(sp_cuda_raster *r, const sp_raster_cfg *cfg, const sp_raster_view *views,
                           batch_view *bv, size_t nv, sp_error *err)
{
    int max_ch = cfg->chunk_fwd ? cfg->chunk_fwd : SP_CHANNEL_CHUNK_MAX;
    for (size_t i = 0; i < nv; i++) {
        const sp_raster_view *w = &views[i];
        for (int k = 0; k < w->n_pass; k++) {
            const sp_raster_pass *p = &w->pass[k];
            float *bg = NULL;
            /* the one background buffer is rewritten per pass: the stream orders each copy after
             * the kernel that read the previous one */
            int rc = sp_cuda_upload_background(r, p->background, p->D, &bg, err);
            /* depth, alpha and the per-pixel state come from the first pass */
            sp_cuda_pass cp = {p->colors, p->D, bg, p->image, k ? NULL : w->depth, k ? NULL : w->alpha};
            if (!rc) rc = sp_cuda_rasterize_fwd(r, &bv[i].v, &cp, max_ch, k == 0, err);
            if (rc) return sp_error_prefix(err, "view %zu: ", i);
        }
        if (w->surface_depth) {
            int rc = sp_cuda_rasterize_surface(r, &bv[i].v, w->surface_alpha, w->surface_depth, err);
            if (rc) return sp_error_prefix(err, "view %zu: ", i);
        }
    }
    return 0;
}

int sp_cuda_views(void *state, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                             const sp_raster_view *views, size_t nv, sp_error *err)
{
    sp_cuda_raster *r = (sp_cuda_raster *)state;
    r->have_forward = 0;
    if (nv == 0) return 0;
    size_t n = geom->n, total_tiles = 0, max_npix = 0;
    batch_view *bv = (batch_view *)calloc(nv, sizeof *bv);
    unsigned long long *ends = (unsigned long long *)calloc(nv, sizeof *ends);
    if (!bv || !ends) {
        free(bv), free(ends);
        return sp_error_set(err, SP_E_NOMEM, "sp_render_views: out of host memory");
    }
    for (size_t i = 0; i < nv; i++) {
        sp_cuda_view *v = &bv[i].v;
        v->cam = views[i].cam;
        v->tiles_x = (v->cam.width + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
        v->tiles_y = (v->cam.height + SP_TILE_SIZE - 1) / SP_TILE_SIZE;
        bv[i].tile_base = total_tiles;
        total_tiles += (size_t)v->tiles_x * v->tiles_y;
        size_t np = (size_t)v->cam.width * v->cam.height;
        if (np > max_npix) max_npix = np;
    }
    sp_cuda_proj all;
    int rc = reserve_upfront(r, views, nv, n, total_tiles, max_npix, &all, err);
    for (size_t i = 0; i < nv && !rc; i++) {
        sp_cuda_view *v = &bv[i].v;
        slice_proj(&all, i * n, &v->proj);
        v->tile_ranges = (const int2 *)r->s_tile_ranges.ptr + bv[i].tile_base;
        v->t_final = (float *)r->s_tfinal.ptr;
        v->last_idx = (int32_t *)r->s_last.ptr;
    }
    if (!rc)
        rc = cudaMemsetAsync(r->s_tile_ranges.ptr, 0, total_tiles * sizeof(int2), r->stream) == cudaSuccess
                 ? 0 : sp_error_set(err, SP_E_DEVICE, "CUDA: clearing tile ranges failed");
    if (!rc && n > 0) rc = project_and_count(r, cfg, geom, bv, nv, ends, err);
    if (!rc && n > 0) rc = sort_views(r, bv, nv, n, ends, err);
    if (!rc) rc = composite_views(r, cfg, views, bv, nv, err);
    free(bv);
    free(ends);
    return rc;
}

/* Expected depth of outputs left on the device: sum w z / sum w, IEEE division (__fdiv_rn, not
 * fast math) so it equals the host's division of the downloaded buffers. */
__global__ void k_depth_normalize(float *__restrict__ depth, const float *__restrict__ alpha, size_t npix)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i < npix) depth[i] = alpha[i] >= 1e-6f ? __fdiv_rn(depth[i], alpha[i]) : 0.f;
}

int sp_cuda_depth_normalize(sp_device *dev, float *depth, const float *alpha, size_t npix, sp_error *err)
{
    if (npix == 0) return 0;
    k_depth_normalize<<<sp_div_up(npix, 256), 256, 0, sp_cuda_stream(dev)>>>(depth, alpha, npix);
    SP_CUDA_LAUNCHED(err, "normalizing expected depth");
    return 0;
}
