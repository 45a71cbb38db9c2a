/* CUDA backend: spherical harmonics to RGB and its backward, one thread per Gaussian, with the
 * per-Gaussian math from gauss_math.h (shared with the CPU backend). */
#include "common.cuh"
#include "render/gauss_math.h"

__global__ void k_sh_fwd(size_t n, int K, int degree_active, const float *__restrict__ sh,
                         const float *__restrict__ means, float3 cc, float *__restrict__ rgb,
                         int stride)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    float m[3] = {means[i * 3], means[i * 3 + 1], means[i * 3 + 2]};
    float c[3] = {cc.x, cc.y, cc.z}, out[3];
    sp_gm_sh_to_rgb(degree_active, sh + i * K * 3, m, c, out);
    for (int k = 0; k < 3; k++) rgb[i * stride + k] = out[k];
}

__global__ void k_sh_bwd(size_t n, int K, int degree_active, const float *__restrict__ sh,
                         const float *__restrict__ means, float3 cc, const float *__restrict__ rgb,
                         const float *__restrict__ v_rgb, int stride, float *__restrict__ v_sh,
                         float *__restrict__ v_means)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    float m[3] = {means[i * 3], means[i * 3 + 1], means[i * 3 + 2]};
    float c[3] = {cc.x, cc.y, cc.z};
    float o[3] = {rgb[i * stride], rgb[i * stride + 1], rgb[i * stride + 2]};
    float g[3] = {v_rgb[i * stride], v_rgb[i * stride + 1], v_rgb[i * stride + 2]};
    if (g[0] == 0.f && g[1] == 0.f && g[2] == 0.f) return;
    float vm[3] = {0.f, 0.f, 0.f};
    sp_gm_sh_to_rgb_vjp(degree_active, sh + i * K * 3, m, c, o, g, v_sh + i * K * 3,
                        v_means ? vm : NULL);
    if (v_means)
        for (int k = 0; k < 3; k++) v_means[i * 3 + k] += vm[k];
}

static int check_args(size_t n, int degree, int degree_active, int stride, sp_error *err)
{
    if (degree < 0 || degree > 3)
        return sp_error_set(err, SP_E_ARG, "SH degree %d outside 0..3", degree);
    if (degree_active < 0 || degree_active > degree)
        return sp_error_set(err, SP_E_ARG, "active SH degree %d outside 0..%d", degree_active,
                            degree);
    if (stride < 3) return sp_error_set(err, SP_E_ARG, "rgb stride %d < 3", stride);
    return 0;
}

extern "C" int sp_cuda_sh_to_rgb(size_t n, int degree, int degree_active, const float *sh,
                                 const float *means, sp_vec3 cam_center, float *rgb,
                                 int out_stride, sp_error *err)
{
    int rc = check_args(n, degree, degree_active, out_stride, err);
    if (rc) return rc;
    if (n == 0) return 0;
    if (!sh || !means || !rgb) return sp_error_set(err, SP_E_ARG, "sp_sh_to_rgb: NULL buffer");
    k_sh_fwd<<<sp_div_up(n, 256), 256>>>(n, sp_sh_coeffs(degree), degree_active, sh, means,
                                         make_float3(cam_center.x, cam_center.y, cam_center.z),
                                         rgb, out_stride);
    SP_CUDA_LAUNCHED(err, "SH to RGB");
    return 0;
}

extern "C" int sp_cuda_sh_to_rgb_backward(size_t n, int degree, int degree_active, const float *sh,
                                          const float *means, sp_vec3 cam_center, const float *rgb,
                                          const float *v_rgb, int stride, float *v_sh,
                                          float *v_means, sp_error *err)
{
    int rc = check_args(n, degree, degree_active, stride, err);
    if (rc) return rc;
    if (n == 0) return 0;
    if (!sh || !means || !rgb || !v_rgb || !v_sh)
        return sp_error_set(err, SP_E_ARG, "sp_sh_to_rgb_backward: NULL buffer");
    k_sh_bwd<<<sp_div_up(n, 256), 256>>>(n, sp_sh_coeffs(degree), degree_active, sh, means,
                                         make_float3(cam_center.x, cam_center.y, cam_center.z),
                                         rgb, v_rgb, stride, v_sh, v_means);
    SP_CUDA_LAUNCHED(err, "SH to RGB backward");
    return 0;
}
