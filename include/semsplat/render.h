/* semsplat render: the 3DGS/EWA Gaussian rasterizer, forward and backward, for any channel count,
 * with a CPU and a CUDA backend behind one interface (sp_device).
 *
 * Pipeline per view (one stage per file in src/render/, same split in src/render/cuda/):
 *   project (means, covariances -> 2D means, conics, depths, radii)
 *   -> tile binning (16x16 tiles) -> sort by (tile, depth) -> composite front to back.
 * Colours are whatever the caller passes per Gaussian ([n][D]: RGB from sp_sh_to_rgb, features,
 * or both concatenated); the rasterizer also gives expected depth and accumulated alpha.
 *
 * Memory: every buffer in sp_raster_in / sp_raster_out / sp_raster_grads lives on the device
 * the sp_raster was created for (host memory for the CPU backend, GPU memory for CUDA). Use
 * sp_device_alloc/upload/download to move data. An sp_raster keeps the forward pass's state
 * (projections, sorted lists, per-pixel final transmittance) for the backward of the same view.
 *
 * Conventions (same as gsplat / 3DGS): camera frame x right, y down, z forward; pixel (px, py)
 * has its centre at (px + 0.5, py + 0.5); covariance = R S S^T R^T with S = diag(exp(log_scales));
 * the 2D covariance gets eps2d (0.3 px^2) added to its diagonal; alpha = min(0.99, opacity *
 * exp(-0.5 d^T conic d)), skipped below 1/255; compositing stops when transmittance < 1e-4.
 * Gradients are ADDED to the output buffers (callers zero them), so several passes (RGB, then
 * features) can accumulate into one set. */
#ifndef SEMSPLAT_RENDER_H
#define SEMSPLAT_RENDER_H

#include "semsplat/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- devices ---------------------------------------------------------------------------------- */

typedef enum {
    SP_DEVICE_CPU = 0,
    SP_DEVICE_CUDA = 1,
    SP_DEVICE_AUTO = 2 /* CUDA when a GPU is usable, else CPU */
} sp_device_kind;

typedef struct sp_device sp_device;

/* n_threads: CPU worker threads (0: all cores; see sp_pool_create for the limits). CUDA: fails with SP_E_NODEVICE when the
 * backend is not built or no GPU is present. */
int sp_device_create(sp_device **out, sp_device_kind kind, int n_threads, sp_error *err);
void sp_device_free(sp_device *dev);
sp_device_kind sp_device_kind_of(const sp_device *dev);
const char *sp_device_name(const sp_device *dev); /* "CPU (2 threads)", "NVIDIA H100 ..." */
sp_pool *sp_device_pool(sp_device *dev);          /* CPU worker pool (also used by CUDA for host work) */
int sp_cuda_available(void);                       /* 1 when the CUDA backend is built and a GPU answers */

void *sp_device_alloc(sp_device *dev, size_t bytes, sp_error *err); /* zeroed; NULL on error */
void sp_device_release(sp_device *dev, void *ptr);
int sp_device_upload(sp_device *dev, void *dst, const void *src_host, size_t bytes, sp_error *err);
int sp_device_download(sp_device *dev, void *dst_host, const void *src, size_t bytes, sp_error *err);
int sp_device_copy(sp_device *dev, void *dst, const void *src, size_t bytes, sp_error *err);
int sp_device_zero(sp_device *dev, void *dst, size_t bytes, sp_error *err);
int sp_device_sync(sp_device *dev, sp_error *err);
/* Peak bytes allocated through sp_device_alloc plus the rasterizer's scratch, since creation. */
size_t sp_device_peak_bytes(const sp_device *dev);

/* ---- rasterization ---------------------------------------------------------------------------- */

#define SP_TILE_SIZE 16
#define SP_ALPHA_MAX 0.99f             /* 3DGS: cap per-Gaussian alpha */
#define SP_ALPHA_MIN (1.0f / 255.0f)   /* 3DGS: skip fainter contributions */
#define SP_TRANSMITTANCE_MIN 1e-4f     /* 3DGS: stop compositing below this */
#define SP_EPS2D 0.3f                  /* 3DGS/gsplat screen-space dilation, px^2 */

typedef struct sp_raster_cfg {
    float near_plane;   /* Gaussians with camera z below this are culled (default 0.01 m) */
    float far_plane;    /* and beyond this (default 1e10) */
    float eps2d;        /* default SP_EPS2D */
    int antialiased;    /* gsplat "antialiased" mode: opacity *= sqrt(det(S)/det(S + eps2d I)) */
} sp_raster_cfg;

sp_raster_cfg sp_raster_cfg_default(void);

typedef struct sp_raster_in {
    size_t n;
    const float *means;          /* [n][3] world */
    const float *quats;          /* [n][4] (w,x,y,z) unnormalised */
    const float *log_scales;     /* [n][3] */
    const float *opacity_logits; /* [n] */
    const float *colors;         /* [n][D] per-Gaussian values to composite */
    int D;                       /* channel count, >= 1 */
    const float *background;     /* [D] HOST memory, or NULL for zeros */
} sp_raster_in;

typedef struct sp_raster_out {
    float *image; /* [H][W][D], required */
    float *depth; /* [H][W] sum_i w_i z_i (divide by alpha for the expected depth), or NULL */
    float *alpha; /* [H][W] sum_i w_i, or NULL */
} sp_raster_out;

typedef struct sp_raster_grad_in {
    const float *v_image; /* [H][W][D], required */
    const float *v_depth; /* [H][W] or NULL */
    const float *v_alpha; /* [H][W] or NULL */
} sp_raster_grad_in;

/* Gradients, ADDED into (callers zero). Any pointer may be NULL to skip that group except that
 * computing one group costs the same as all. v_means2d is the gradient w.r.t. the projected
 * 2D mean in pixels (what densification accumulates). */
typedef struct sp_raster_grads {
    float *v_means;          /* [n][3] */
    float *v_quats;          /* [n][4] */
    float *v_log_scales;     /* [n][3] */
    float *v_opacity_logits; /* [n] */
    float *v_colors;         /* [n][D] */
    float *v_means2d;        /* [n][2] */
} sp_raster_grads;

typedef struct sp_raster sp_raster;

int sp_raster_create(sp_raster **out, sp_device *dev, sp_error *err);
void sp_raster_free(sp_raster *r);
sp_device *sp_raster_device(sp_raster *r);

/* Renders one view. Fails with SP_E_ARG on bad sizes, never on Gaussians behind the camera or
 * outside the image (those are culled). */
int sp_raster_forward(sp_raster *r, const sp_camera *cam, const sp_raster_cfg *cfg,
                      const sp_raster_in *in, sp_raster_out *out, sp_error *err);

/* Backward of the last forward (same cam, cfg, in; `in` buffers must be unchanged). */
int sp_raster_backward(sp_raster *r, const sp_raster_grad_in *gin, sp_raster_grads *grads,
                       sp_error *err);

/* Screen radius in pixels of each Gaussian in the last forward ([n] int32 on the device; 0 =
 * culled). Valid until the next forward. */
const int32_t *sp_raster_radii(const sp_raster *r);
/* Number of (Gaussian, tile) pairs in the last forward. */
size_t sp_raster_last_pairs(const sp_raster *r);

/* ---- spherical harmonics ---------------------------------------------------------------------- */

/* rgb[i*out_stride + c] = max(0, 0.5 + sum_k SH_k(dir_i) * sh[i][k][c]) for c in 0..2, with
 * dir_i = normalize(means[i] - cam_center) and bands up to degree_active <= degree (the stored
 * degree). Device buffers. */
int sp_sh_to_rgb(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                 const float *means, sp_vec3 cam_center, float *rgb, int out_stride, sp_error *err);
/* Backward: given v_rgb (same stride), ADDS into v_sh [n][K][3] and v_means [n][3] (may be NULL).
 * Needs the forward's rgb to know which channels were clamped. */
int sp_sh_to_rgb_backward(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                          const float *means, sp_vec3 cam_center, const float *rgb,
                          const float *v_rgb, int stride, float *v_sh, float *v_means,
                          sp_error *err);

/* ---- convenience for host splats (CLI, queries, previews) ------------------------------------- */

/* What to render from a host sp_splat. Any output pointer may be NULL. HOST buffers.
 *   rgb      [H][W][3]   from SH (active degree = splat degree)
 *   features [H][W][feat_dim]
 *   depth    [H][W]      expected depth (sum w z / alpha; 0 where alpha < 1e-6)
 *   alpha    [H][W] */
typedef struct sp_render_request {
    float *rgb;
    float *features;
    float *depth;
    float *alpha;
    const float *background; /* [3] for rgb, NULL = black */
} sp_render_request;

/* Uploads the splat (cached inside r between calls with the same splat pointer and count;
 * call sp_raster_forget(r) after changing the splat) and renders one view. */
int sp_render_splat(sp_raster *r, const sp_splat *s, const sp_camera *cam,
                    const sp_render_request *req, sp_error *err);
void sp_raster_forget(sp_raster *r);

#ifdef __cplusplus
}
#endif
#endif
