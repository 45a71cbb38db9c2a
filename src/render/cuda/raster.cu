/* CUDA render backend: the raster object's lifetime and the backend table. The pipeline itself is
 * in project.cu, tiles.cu, rasterize_fwd.cu, rasterize_bwd.cu, rasterize_surface.cu, views.cu. */
#include "common.cuh"

#include <stdlib.h>

static int cu_create(void **state, sp_device *dev, sp_error *err)
{
    sp_cuda_raster *r = (sp_cuda_raster *)calloc(1, sizeof(*r));
    if (!r) return sp_error_set(err, SP_E_NOMEM, "sp_raster_create: out of host memory");
    r->dev = dev;
    r->stream = sp_cuda_stream(dev);
    *state = r;
    return 0;
}

static void cu_destroy(void *state)
{
    sp_cuda_raster *r = (sp_cuda_raster *)state;
    if (!r) return;
    sp_device_scratch *all[] = {&r->s_means2d, &r->s_conic_op, &r->s_depths, &r->s_radii,
                                &r->s_box, &r->s_keys[0], &r->s_keys[1], &r->s_vals[0],
                                &r->s_vals[1], &r->s_tile_ranges, &r->s_cub, &r->s_tfinal,
                                &r->s_last, &r->s_bg, &r->s_work, &r->s_counts, &r->s_batch};
    for (size_t i = 0; i < sizeof(all) / sizeof(all[0]); i++) sp_device_scratch_release(r->dev, all[i]);
    for (int k = 0; r->ev_made && k < SP_EV_COUNT; k++) cudaEventDestroy(r->ev[k]);
    free(r);
}

int sp_cuda_make_events(sp_cuda_raster *r, sp_error *err)
{
    for (; r->ev_made < SP_EV_COUNT; r->ev_made++)
        SP_CUDA_CHECK(cudaEventCreate(&r->ev[r->ev_made]), err, "making profiling events");
    return 0;
}

static int cu_stages(void *state, sp_raster_stages *o, sp_error *err)
{
    sp_cuda_raster *r = (sp_cuda_raster *)state;
    o->bwd_kernel = r->bwd_kernel;
    o->fwd_px = r->fwd_px;
    if (!r->prof_fwd) return 0;
    SP_CUDA_CHECK(cudaEventSynchronize(r->ev[r->prof_bwd ? SP_EV_BWD_DONE : SP_EV_FWD_DONE]), err,
                  "waiting for the profiled passes");
    const int from[6] = {SP_EV_START, SP_EV_PROJECTED, SP_EV_COUNTED, SP_EV_SORTED,
                         SP_EV_BWD_START, SP_EV_BWD_RASTER};
    double *to[6] = {&o->project, &o->bin, &o->sort, &o->raster_fwd, &o->raster_bwd, &o->project_bwd};
    for (int k = 0; k < (r->prof_bwd ? 6 : 4); k++) {
        float ms = 0.f;
        SP_CUDA_CHECK(cudaEventElapsedTime(&ms, r->ev[from[k]], r->ev[from[k] + 1]), err,
                      "reading profiling events");
        *to[k] = ms;
    }
    return 0;
}

static const int32_t *cu_radii(const void *state)
{
    const sp_cuda_raster *r = (const sp_cuda_raster *)state;
    return r->have_forward ? r->view.proj.radii : NULL;
}

static size_t cu_last_pairs(const void *state)
{
    const sp_cuda_raster *r = (const sp_cuda_raster *)state;
    return r->have_forward ? r->view.n_pairs : 0;
}

static const sp_render_backend cuda_backend = {
    "cuda", cu_create, cu_destroy, sp_cuda_raster_forward, sp_cuda_raster_backward, cu_radii,
    cu_last_pairs, sp_cuda_views, sp_cuda_depth_normalize, sp_cuda_sh_to_rgb,
    sp_cuda_sh_to_rgb_backward, cu_stages};

extern "C" const sp_render_backend *sp_render_cuda_backend(void) { return &cuda_backend; }
