/* The render module's backend seam: one table of entry points per backend, the CPU table in
 * cpu_backend.c and the CUDA table in cuda/ (nocuda/ returns none when nvcc is absent). raster.c,
 * sh.c and scene.c check arguments and dispatch on the device's kind through these tables; the
 * backends trust their arguments. Semantics are those of the public functions in
 * include/semsplat/render.h of the same names. Every pointer is on the raster's device except
 * where marked HOST. */
#ifndef SP_RENDER_BACKEND_H
#define SP_RENDER_BACKEND_H

#include "semsplat/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One set of channels composited for a view: the colours of every Gaussian and the image. */
typedef struct sp_raster_pass {
    const float *colors;     /* [n][D] */
    int D;
    const float *background; /* HOST [D] or NULL */
    float *image;            /* [H][W][D] */
} sp_raster_pass;

/* One view of a batch: every pass shares the view's projection, sort and weights. */
typedef struct sp_raster_view {
    sp_camera cam;
    sp_raster_pass pass[2];
    int n_pass;              /* >= 1, or 0 for a view that asks only for surface_depth */
    float *depth;            /* [H][W] sum w z, or NULL */
    float *alpha;            /* [H][W] sum w, or NULL */
    float *surface_depth;    /* [H][W] first-surface depth at surface_alpha, or NULL */
    float surface_alpha;     /* in (0, 1] (per view: requests differ) */
} sp_raster_view;

typedef struct sp_render_backend {
    const char *name;
    int (*create)(void **state, sp_device *dev, sp_error *err);
    void (*destroy)(void *state);
    int (*forward)(void *state, const sp_camera *cam, const sp_raster_cfg *cfg,
                   const sp_raster_in *in, sp_raster_out *out, sp_error *err);
    int (*backward)(void *state, const sp_raster_grad_in *gin, sp_raster_grads *grads,
                    sp_error *err);
    const int32_t *(*radii)(const void *state);
    size_t (*last_pairs)(const void *state);
    /* Renders n views of one set of Gaussians (geom: n, means, quats, log_scales,
     * opacity_logits; its colors, D and background are unused). Leaves no forward to
     * differentiate. On CUDA nothing waits for the GPU between views. */
    int (*views)(void *state, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                 const sp_raster_view *views, size_t n_views, sp_error *err);
    /* depth[i] = alpha[i] >= 1e-6 ? depth[i] / alpha[i] : 0 for i < npix, in place (expected
     * depth of outputs left on the device) */
    int (*depth_normalize)(sp_device *dev, float *depth, const float *alpha, size_t npix,
                           sp_error *err);
    int (*sh_to_rgb)(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                     const float *means, sp_vec3 cam_center, float *rgb, int out_stride,
                     sp_error *err);
    int (*sh_to_rgb_backward)(sp_device *dev, size_t n, int degree, int degree_active,
                              const float *sh, const float *means, sp_vec3 cam_center,
                              const float *rgb, const float *v_rgb, int stride, float *v_sh,
                              float *v_means, sp_error *err);
    /* sp_raster_last_stages (zeros when the last forward was not profiled) */
    int (*stages)(void *state, sp_raster_stages *out, sp_error *err);
} sp_render_backend;

/* raster.c: the camera and cfg checks of sp_raster_forward (`what` names the caller in the
 * message), and the batch entry scene.c uses (views checked by the caller). */
int sp_raster_check_view(const char *what, const sp_camera *cam, const sp_raster_cfg *cfg,
                         sp_error *err);
int sp_raster_views(sp_raster *r, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                    const sp_raster_view *views, size_t n_views, sp_error *err);

extern const sp_render_backend sp_render_cpu_backend;
/* The CUDA table, or NULL when the library was built without CUDA. */
const sp_render_backend *sp_render_cuda_backend(void);
/* The table for dev's kind (never NULL for a device that exists). */
const sp_render_backend *sp_render_backend_of(const sp_device *dev);

#ifdef __cplusplus
}
#endif
#endif
