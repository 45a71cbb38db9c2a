/* CUDA backend: spherical harmonics to RGB and its backward, one thread per Gaussian, with the
 * per-Gaussian math from gauss_math.h (shared with the CPU backend). Arguments are checked by
 * the public calls (src/render/sh.c). */
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

int sp_cuda_sh_to_rgb(sp_device *dev, size_t n, int degree, int degree_active,
                                 const float *sh, const float *means, sp_vec3 cam_center,
                                 float *rgb, int out_stride, sp_error *err)
{
    k_sh_fwd<<<sp_div_up(n, 256), 256, 0, sp_cuda_stream(dev)>>>(
        n, sp_sh_coeffs(degree), degree_active, sh, means,
        make_float3(cam_center.x, cam_center.y, cam_center.z), rgb, out_stride);
    SP_CUDA_LAUNCHED(err, "SH to RGB");
    return 0;
}

int sp_cuda_sh_to_rgb_backward(sp_device *dev, size_t n, int degree, int degree_active,
                                          const float *sh, const float *means, sp_vec3 cam_center,
                                          const float *rgb, const float *v_rgb, int stride,
                                          float *v_sh, float *v_means, sp_error *err)
{
    k_sh_bwd<<<sp_div_up(n, 256), 256, 0, sp_cuda_stream(dev)>>>(
        n, sp_sh_coeffs(degree), degree_active, sh, means,
        make_float3(cam_center.x, cam_center.y, cam_center.z), rgb, v_rgb, stride, v_sh, v_means);
    SP_CUDA_LAUNCHED(err, "SH to RGB backward");
    return 0;
}
