/* Internals shared by the CUDA backend's stages (src/render/cuda/*.cu). Not a public header.
 *
 * Memory: every device buffer goes through sp_cuda_malloc/sp_cuda_free (device.cu), which count
 * live and peak bytes so sp_cuda_peak_bytes reports what semsplat itself holds. The rasterizer's
 * scratch buffers are grow-only (scratch_reserve) so a training loop allocates nothing after
 * its first few steps. */
#ifndef SP_RENDER_CUDA_COMMON_CUH
#define SP_RENDER_CUDA_COMMON_CUH

#include <cuda_runtime.h>
#include <stdint.h>

#include "render/cuda_api.h"
#include "render/gauss_math.h"

#define SP_CUDA_CHECK(call, err, what)                                                        \
    do {                                                                                      \
        cudaError_t sp_e_ = (call);                                                           \
        if (sp_e_ != cudaSuccess)                                                             \
            return sp_error_set((err), SP_E_DEVICE, "CUDA %s: %s (%s)", (what),              \
                                cudaGetErrorString(sp_e_), cudaGetErrorName(sp_e_));         \
    } while (0)

/* Checks the last kernel launch (configuration errors show up here, faults at the next sync). */
#define SP_CUDA_LAUNCHED(err, what) SP_CUDA_CHECK(cudaGetLastError(), err, what)

/* A grow-only device buffer. */
typedef struct sp_cu_scratch {
    void *ptr;
    size_t cap;
} sp_cu_scratch;

/* Ensures s holds at least `bytes` (contents are NOT kept when it grows). Grows by 1.25x so a
 * slowly growing Gaussian count does not reallocate every step. */
int sp_cu_scratch_reserve(sp_cu_scratch *s, size_t bytes, sp_error *err);
void sp_cu_scratch_release(sp_cu_scratch *s);

/* Projected Gaussians of one view, written by project.cu and read by every later stage. */
typedef struct sp_cuda_proj {
    float2 *means2d;   /* [n] pixels */
    float4 *conic_op;  /* [n] (conic a, b, c, opacity after sigmoid and AA compensation) */
    float *depths;     /* [n] camera z */
    int32_t *radii;    /* [n] 0 = culled */
    int4 *rect;        /* [n] tile rectangle x0, y0, x1, y1 (half-open) */
    uint32_t *ntiles;  /* [n] tiles touched */
} sp_cuda_proj;

/* The backend's per-view state (defined here so the stage files share it). */
struct sp_cuda_raster {
    /* the last forward's arguments, kept for backward */
    sp_camera cam;
    sp_raster_cfg cfg;
    sp_raster_in in;
    int have_forward;
    int tiles_x, tiles_y;
    size_t n_pairs;
    float *bg_dev; /* [D] background on the device (inside s_bg) */

    sp_cu_scratch s_means2d, s_conic_op, s_depths, s_radii, s_rect, s_ntiles, s_offsets;
    sp_cu_scratch s_keys[2], s_vals[2], s_tile_ranges, s_cub;
    sp_cu_scratch s_tfinal, s_last, s_bg;
    /* backward: per-Gaussian sums (v_mean2d 2, v_conic 3 in the conic's frame, v_opacity,
     * v_depth, pad) */
    sp_cu_scratch s_vgeo;
    sp_cuda_proj proj;
    const uint32_t *sorted_ids; /* [n_pairs] Gaussian index per sorted pair */
    const int2 *tile_ranges;    /* [tiles] [start, end) in the sorted list */
    float *t_final;             /* [H*W] */
    int32_t *last_idx;          /* [H*W] one past the last pair index used by the pixel */
};

/* Stages (each returns 0 or a negative SP_E_*). */
int sp_cuda_project(sp_cuda_raster *r, sp_error *err);
int sp_cuda_bin_and_sort(sp_cuda_raster *r, sp_error *err);
int sp_cuda_rasterize_fwd(sp_cuda_raster *r, sp_raster_out *out, sp_error *err);
int sp_cuda_rasterize_bwd(sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                          float *vgeo, sp_error *err);
int sp_cuda_project_bwd(sp_cuda_raster *r, sp_raster_grads *grads, const float *vgeo,
                        sp_error *err);

/* Chunk width for d remaining channels: the smallest specialised width >= d, capped at max_ch. */
int sp_cuda_chunk_width(int d, int max_ch);
/* Widest chunk from environment variable `name` (8, 16, 32 or 64; for tuning), else dflt. */
int sp_cuda_env_chunk(const char *name, int dflt);

/* alpha of a Gaussian at offset (dx, dy) from a pixel centre: sp_gm_alpha_g (gauss_math.h), the
 * rule the CPU backend runs bit for bit (unfused multiplies and adds, the shared polynomial exp),
 * so both backends keep and skip the same contributions; forward and backward kernels both call
 * this. co = (conic a, b, c, opacity). Returns 0 when skipped; *vis gets exp(-sigma). `cut` is
 * sp_cu_sigma_cut(opacity): beyond it alpha is surely below 1/255, so the exp is skipped for the
 * many pixels outside the ellipse without changing any decision (the 1e-3 margin is far above
 * the fast log's error). */
__device__ __forceinline__ float sp_cu_sigma_cut(float opacity)
{
    return __logf(opacity * 255.f) + 1e-3f;
}
__device__ __forceinline__ float sp_cu_alpha(float4 co, float cut, float dx, float dy, float *vis)
{
    const float conic[3] = {co.x, co.y, co.z};
    return sp_gm_alpha_g(conic, co.w, cut, dx, dy, vis);
}

static inline unsigned sp_div_up(size_t a, size_t b) { return (unsigned)((a + b - 1) / b); }

#endif
