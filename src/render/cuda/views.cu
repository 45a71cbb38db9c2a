/* CUDA backend: a batch of views of one set of Gaussians (sp_render_views), with one wait for the
 * GPU per batch instead of one per view. Every view is projected into its own slice of one
 * projection buffer ([views][n]), put in depth order and its tile pairs counted into its slice of
 * one count buffer; one scan over all the slices' counts gives every pair its place in one pair
 * buffer, so one copy of the views' totals (the only wait) sizes every tile sort; then each view's
 * pairs are emitted and sorted with the single-view kernels on pointers into its slices, and
 * when the views' passes share colours and background every pass composites all views in ONE
 * launch (else view by view), all queued on the device's stream. The per-pixel
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
    p->box = all->box + at;
}

/* The batch's work area (s_work): offsets [views][n] (64-bit), depth orders [views][n], counts
 * [views][n], then the depth sorts' temporaries [3n] (reused view after view). */
typedef struct {
    unsigned long long *offsets;
    uint32_t *ids, *counts, *tmp;
} batch_work;

static size_t batch_work_bytes(size_t nv, size_t n) { return nv * n * 16 + 3 * n * 4 + 256; }

static batch_work carve_work(void *base, size_t nv, size_t n)
{
    batch_work w;
    w.offsets = (unsigned long long *)base;
    w.ids = (uint32_t *)(w.offsets + nv * n);
    w.counts = w.ids + nv * n;
    w.tmp = w.counts + nv * n;
    return w;
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
        (rc = sp_cu_reserve(r, &r->s_work, batch_work_bytes(nv, n), err)) ||
        (rc = sp_cu_reserve(r, &r->s_counts, nv * sizeof(unsigned long long), err)))
        return rc;
    size_t tmp = 0;
    if (n > 0 && ((rc = sp_cuda_prep_temp_bytes(n, nv * n, &tmp, err)) ||
                  (rc = sp_cu_reserve(r, &r->s_cub, tmp, err))))
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

/* Projections, depth orders and tile counts, the scan of all counts and the one wait for the
 * views' pair totals. */
static int project_and_count(sp_cuda_raster *r, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                             batch_view *bv, size_t nv, unsigned long long *ends, sp_error *err)
{
    size_t n = geom->n, count = nv * n;
    batch_work w = carve_work(r->s_work.ptr, nv, n);
    for (size_t i = 0; i < nv; i++) {
        sp_cuda_view *v = &bv[i].v;
        uint32_t *ids = w.ids + i * n;
        int rc = sp_cuda_project(r, v, cfg, geom, err);
        if (!rc) rc = sp_cuda_depth_order(r, v, n, ids, w.tmp, err);
        if (!rc) rc = sp_cuda_count_pairs(r, v, n, ids, w.counts + i * n, err);
        if (rc) return sp_error_prefix(err, "view %zu: ", i);
    }
    unsigned long long *offsets = w.offsets;
    int rc = sp_cuda_scan_counts(r, w.counts, offsets, count, err);
    if (rc) return rc;
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
    size_t kb = 2; /* one key width for the batch: the widest view's */
    for (size_t i = 0; i < nv; i++)
        if ((size_t)sp_cuda_key_bytes(&bv[i].v) > kb) kb = (size_t)sp_cuda_key_bytes(&bv[i].v);
    for (int k = 0; k < 2; k++)
        if ((rc = sp_cu_reserve(r, &r->s_keys[k], total * kb, err)) ||
            (rc = sp_cu_reserve(r, &r->s_vals[k], total * sizeof(uint32_t), err)))
            return rc;
    if ((rc = sp_cu_reserve(r, &r->s_cub, tmp_max, err))) return rc;
    char *k0 = (char *)r->s_keys[0].ptr, *k1 = (char *)r->s_keys[1].ptr;
    uint32_t *v0 = (uint32_t *)r->s_vals[0].ptr, *v1 = (uint32_t *)r->s_vals[1].ptr;
    batch_work w = carve_work(r->s_work.ptr, nv, n);
    for (size_t i = 0; i < nv && !rc; i++) {
        if (bv[i].v.n_pairs == 0) continue;
        size_t at = bv[i].pair_base, kv = (size_t)sp_cuda_key_bytes(&bv[i].v);
        /* the view's offsets count from the batch's first pair: its keys are addressed from a
         * base moved back by pair_base keys of its own width, so its segment starts at k0 + at kb */
        char *kbase = k0 + at * kb - at * kv;
        rc = sp_cuda_emit_pairs(r, &bv[i].v, n, w.ids + i * n, w.offsets + i * n, at, kbase, v0,
                                err);
        if (!rc)
            rc = sp_cuda_sort_pairs(r, &bv[i].v, k0 + at * kb, k1 + at * kb, v0 + at, v1 + at,
                                    (int2 *)r->s_tile_ranges.ptr + bv[i].tile_base, err);
    }
    return rc;
}

/* Whether pass k of every view shares colours, D and background: then the views composite in
 * one launch (rasterize_fwd.cu). */
static int same_pass(const sp_raster_view *views, size_t nv, int k)
{
    for (size_t i = 0; i < nv; i++) {
        const sp_raster_pass *a = &views[0].pass[k], *b = &views[i].pass[k];
        if (views[i].n_pass <= k || a->colors != b->colors || a->D != b->D ||
            a->background != b->background)
            return 0;
    }
    return 1;
}

/* Pass k of every view in one launch (same_pass holds). */
static int composite_pass_batched(sp_cuda_raster *r, const sp_raster_view *views, batch_view *bv,
                                  size_t nv, int k, int max_ch, int px, sp_error *err)
{
    const sp_raster_pass *p0 = &views[0].pass[k];
    float *bg = NULL;
    int rc = sp_cuda_upload_background(r, p0->background, p0->D, &bg, err);
    const sp_cuda_view **vs = (const sp_cuda_view **)malloc(nv * sizeof *vs);
    sp_cuda_pass *ps = (sp_cuda_pass *)malloc(nv * sizeof *ps);
    if (!rc && (!vs || !ps)) rc = sp_error_set(err, SP_E_NOMEM, "sp_render_views: out of host memory");
    for (size_t i = 0; i < nv && !rc; i++) {
        const sp_raster_view *w = &views[i];
        vs[i] = &bv[i].v;
        ps[i] = (sp_cuda_pass){p0->colors, p0->D, bg, w->pass[k].image, k ? NULL : w->depth,
                               k ? NULL : w->alpha};
    }
    if (!rc) rc = sp_cuda_rasterize_fwd_views(r, vs, ps, nv, max_ch, px, k == 0, err);
    free(vs), free(ps);
    return rc;
}

static int composite_views(sp_cuda_raster *r, const sp_raster_cfg *cfg, const sp_raster_view *views,
                           batch_view *bv, size_t nv, sp_error *err)
{
    int max_ch = cfg->chunk_fwd ? cfg->chunk_fwd : SP_CHANNEL_CHUNK_MAX;
    int batched = nv > 1 && views[0].n_pass > 0;
    for (int k = 0; batched && k < views[0].n_pass; k++) batched = same_pass(views, nv, k);
    for (size_t i = 0; batched && i < nv; i++) batched = views[i].n_pass == views[0].n_pass;
    if (batched)
        for (int k = 0; k < views[0].n_pass; k++) {
            int rc = composite_pass_batched(r, views, bv, nv, k, max_ch, sp_cuda_fwd_px(cfg), err);
            if (rc) return rc;
        }
    for (size_t i = 0; i < nv; i++) {
        const sp_raster_view *w = &views[i];
        for (int k = 0; !batched && k < w->n_pass; k++) {
            const sp_raster_pass *p = &w->pass[k];
            float *bg = NULL;
            /* the one background buffer is rewritten per pass: the stream orders each copy after
             * the kernel that read the previous one */
            int rc = sp_cuda_upload_background(r, p->background, p->D, &bg, err);
            /* depth, alpha and the per-pixel state come from the first pass */
            sp_cuda_pass cp = {p->colors, p->D, bg, p->image, k ? NULL : w->depth, k ? NULL : w->alpha};
            if (!rc) rc = sp_cuda_rasterize_fwd(r, &bv[i].v, &cp, max_ch, sp_cuda_fwd_px(cfg), k == 0, err);
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
    r->profiling = r->prof_fwd = r->prof_bwd = 0; /* batches are not profiled */
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
        v->box_tiles = cfg->box_tiles;
        v->warp_cull = cfg->warp_cull >= 0;
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
