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
                                &r->s_rect, &r->s_ntiles, &r->s_offsets, &r->s_keys[0],
                                &r->s_keys[1], &r->s_vals[0], &r->s_vals[1], &r->s_tile_ranges,
                                &r->s_cub, &r->s_tfinal, &r->s_last, &r->s_bg,
                                &r->s_vgeo, &r->s_counts};
    for (size_t i = 0; i < sizeof(all) / sizeof(all[0]); i++) sp_device_scratch_release(r->dev, all[i]);
    free(r);
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
    sp_cuda_sh_to_rgb_backward};

extern "C" const sp_render_backend *sp_render_cuda_backend(void) { return &cuda_backend; }
