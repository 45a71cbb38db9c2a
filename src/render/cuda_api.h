/* The seam between the render module's C dispatch (the C files in src/render) and the CUDA backend
 * (the .cu files in src/render/cuda). Plain C entry points taking device pointers; compiled only when
 * SP_HAVE_CUDA is defined. Semantics are exactly those of the public functions in
 * include/semsplat/render.h with the same names minus "cuda_". */
#ifndef SP_RENDER_CUDA_API_H
#define SP_RENDER_CUDA_API_H

#include "semsplat/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Device management. sp_cuda_probe: 1 if a GPU answers (name filled), else 0. */
int sp_cuda_probe(char *name, size_t cap);
void *sp_cuda_malloc(size_t bytes, sp_error *err); /* zeroed */
void sp_cuda_free(void *ptr);
int sp_cuda_memcpy_h2d(void *dst, const void *src, size_t bytes, sp_error *err);
int sp_cuda_memcpy_d2h(void *dst, const void *src, size_t bytes, sp_error *err);
int sp_cuda_memcpy_d2d(void *dst, const void *src, size_t bytes, sp_error *err);
int sp_cuda_memset0(void *dst, size_t bytes, sp_error *err);
int sp_cuda_sync(sp_error *err);
size_t sp_cuda_peak_bytes(void); /* from cudaMemGetInfo high-water mark tracked by the backend */

/* Rasterizer state for one view (scratch buffers grow and are reused). */
typedef struct sp_cuda_raster sp_cuda_raster;
int sp_cuda_raster_create(sp_cuda_raster **out, sp_error *err);
void sp_cuda_raster_free(sp_cuda_raster *r);
int sp_cuda_raster_forward(sp_cuda_raster *r, const sp_camera *cam, const sp_raster_cfg *cfg,
                           const sp_raster_in *in, sp_raster_out *out, sp_error *err);
int sp_cuda_raster_backward(sp_cuda_raster *r, const sp_raster_grad_in *gin,
                            sp_raster_grads *grads, sp_error *err);
const int32_t *sp_cuda_raster_radii(const sp_cuda_raster *r);
size_t sp_cuda_raster_last_pairs(const sp_cuda_raster *r);

int sp_cuda_sh_to_rgb(size_t n, int degree, int degree_active, const float *sh, const float *means,
                      sp_vec3 cam_center, float *rgb, int out_stride, sp_error *err);
int sp_cuda_sh_to_rgb_backward(size_t n, int degree, int degree_active, const float *sh,
                               const float *means, sp_vec3 cam_center, const float *rgb,
                               const float *v_rgb, int stride, float *v_sh, float *v_means,
                               sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
