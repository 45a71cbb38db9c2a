/* CUDA backend, stage 1: per-Gaussian projection (forward) and its backward, one thread per
 * Gaussian. The math is src/render/gauss_math.h, the same inline functions the CPU backend
 * runs, so both backends cull, dilate and differentiate identically. */
#include "common.cuh"
#include "render/gauss_math.h"

__global__ void k_project(size_t n, sp_camera cam, sp_raster_cfg cfg,
                          const float *__restrict__ means, const float *__restrict__ quats,
                          const float *__restrict__ log_scales,
                          const float *__restrict__ opacity_logits, float2 *__restrict__ means2d,
                          float4 *__restrict__ conic_op, float *__restrict__ depths,
                          int32_t *__restrict__ radii, short4 *__restrict__ box)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    float m[3] = {means[i * 3], means[i * 3 + 1], means[i * 3 + 2]};
    float q[4] = {quats[i * 4], quats[i * 4 + 1], quats[i * 4 + 2], quats[i * 4 + 3]};
    float s[3] = {log_scales[i * 3], log_scales[i * 3 + 1], log_scales[i * 3 + 2]};
    float mean2d[2], conic[3], cov2[3], depth = 0.f, op = 0.f;
    int radius = 0;
    int vis = sp_gm_project_ex(m, q, s, opacity_logits[i], &cam, &cfg, mean2d, conic, &depth, &op,
                               &radius, cov2);
    /* Pixels whose centres lie inside the alpha >= 1/255 ellipse's per-axis extent (never wider
     * than the radius circle), exactly as the CPU backend's project.c bins them: tighter than the
     * circle for elongated Gaussians (fewer pairs), and a Gaussian with no pixel centre in it is
     * culled (radius 0) on both backends. */
    int bx0 = 0, bx1 = -1, by0 = 0, by1 = -1;
    if (vis) {
        float ext = sqrtf(2.f * logf(op * 255.f));
        float rr = (float)radius;
        float rx = fminf(ceilf(ext * sqrtf(cov2[0])), rr), ry = fminf(ceilf(ext * sqrtf(cov2[2])), rr);
        float fx0 = ceilf(mean2d[0] - rx - 0.5f), fx1 = floorf(mean2d[0] + rx - 0.5f);
        float fy0 = ceilf(mean2d[1] - ry - 0.5f), fy1 = floorf(mean2d[1] + ry - 0.5f);
        float W = (float)cam.width, H = (float)cam.height;
        bx0 = fx0 < 0.f ? 0 : (fx0 > W ? cam.width : (int)fx0);
        bx1 = fx1 > W - 1.f ? cam.width - 1 : (fx1 < -1.f ? -1 : (int)fx1);
        by0 = fy0 < 0.f ? 0 : (fy0 > H ? cam.height : (int)fy0);
        by1 = fy1 > H - 1.f ? cam.height - 1 : (fy1 < -1.f ? -1 : (int)fy1);
    }
    if (!vis || bx0 > bx1 || by0 > by1) {
        radii[i] = 0;
        return;
    }
    radii[i] = radius;
    means2d[i] = make_float2(mean2d[0], mean2d[1]);
    conic_op[i] = make_float4(conic[0], conic[1], conic[2], op);
    depths[i] = depth;
    box[i] = make_short4((short)bx0, (short)by0, (short)bx1, (short)by1);
}

int sp_cuda_reserve_proj(sp_cuda_raster *r, size_t count, sp_cuda_proj *proj, sp_error *err)
{
    int rc;
    if ((rc = sp_cu_reserve(r, &r->s_means2d, count * sizeof(float2), err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_conic_op, count * sizeof(float4), err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_depths, count * sizeof(float), err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_radii, count * sizeof(int32_t), err))) return rc;
    if ((rc = sp_cu_reserve(r, &r->s_box, count * sizeof(short4), err))) return rc;
    proj->means2d = (float2 *)r->s_means2d.ptr;
    proj->conic_op = (float4 *)r->s_conic_op.ptr;
    proj->depths = (float *)r->s_depths.ptr;
    proj->radii = (int32_t *)r->s_radii.ptr;
    proj->box = (short4 *)r->s_box.ptr;
    return 0;
}

int sp_cuda_project(sp_cuda_raster *r, const sp_cuda_view *v, const sp_raster_cfg *cfg,
                    const sp_raster_in *in, sp_error *err)
{
    size_t n = in->n;
    if (n == 0) return 0;
    if (v->cam.width > 32767 || v->cam.height > 32767)
        return sp_error_set(err, SP_E_ARG, "CUDA rasterizer: %dx%d image is over 32767 px a side",
                            v->cam.width, v->cam.height);
    const sp_cuda_proj *p = &v->proj;
    k_project<<<sp_div_up(n, 256), 256, 0, r->stream>>>(n, v->cam, *cfg, in->means, in->quats,
                                                        in->log_scales, in->opacity_logits,
                                                        p->means2d, p->conic_op, p->depths,
                                                        p->radii, p->box);
    SP_CUDA_LAUNCHED(err, "projection");
    return 0;
}

/* vgeo[i] = per-Gaussian sums from the rasterizer backward:
 * (v_mean2d x, y, v_conic a, b, c (element convention, in the conic's principal frame:
 * sp_gm_conic_frame), v_opacity, v_depth, unused). */
__global__ void k_project_bwd(size_t n, sp_camera cam, sp_raster_cfg cfg,
                              const float *__restrict__ means, const float *__restrict__ quats,
                              const float *__restrict__ log_scales,
                              const float *__restrict__ opacity_logits,
                              const int32_t *__restrict__ radii, const float *__restrict__ vgeo,
                              float *__restrict__ v_means, float *__restrict__ v_quats,
                              float *__restrict__ v_log_scales,
                              float *__restrict__ v_opacity_logits,
                              float *__restrict__ v_means2d)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n || radii[i] <= 0) return;
    const float *g = vgeo + i * SP_VGEO_STRIDE;
    float v2[2] = {g[0], g[1]}, vc[3] = {g[2], g[3], g[4]};
    float m[3] = {means[i * 3], means[i * 3 + 1], means[i * 3 + 2]};
    float q[4] = {quats[i * 4], quats[i * 4 + 1], quats[i * 4 + 2], quats[i * 4 + 3]};
    float s[3] = {log_scales[i * 3], log_scales[i * 3 + 1], log_scales[i * 3 + 2]};
    float vm[3] = {0.f, 0.f, 0.f}, vq[4] = {0.f, 0.f, 0.f, 0.f}, vs[3] = {0.f, 0.f, 0.f}, vo = 0.f;
    sp_gm_project_vjp(m, q, s, opacity_logits[i], &cam, &cfg, v2, vc, g[6], g[5], vm, vq, vs, &vo);
    if (v_means)
        for (int k = 0; k < 3; k++) v_means[i * 3 + k] += vm[k];
    if (v_quats)
        for (int k = 0; k < 4; k++) v_quats[i * 4 + k] += vq[k];
    if (v_log_scales)
        for (int k = 0; k < 3; k++) v_log_scales[i * 3 + k] += vs[k];
    if (v_opacity_logits) v_opacity_logits[i] += vo;
    if (v_means2d) {
        v_means2d[i * 2] += v2[0];
        v_means2d[i * 2 + 1] += v2[1];
    }
}

int sp_cuda_project_bwd(sp_cuda_raster *r, sp_raster_grads *grads, const float *vgeo,
                        sp_error *err)
{
    size_t n = r->in.n;
    if (n == 0) return 0;
    k_project_bwd<<<sp_div_up(n, 256), 256, 0, r->stream>>>(
        n, r->view.cam, r->cfg, r->in.means, r->in.quats, r->in.log_scales, r->in.opacity_logits,
        r->view.proj.radii, vgeo, grads->v_means, grads->v_quats, grads->v_log_scales,
        grads->v_opacity_logits, grads->v_means2d);
    SP_CUDA_LAUNCHED(err, "projection backward");
    return 0;
}
