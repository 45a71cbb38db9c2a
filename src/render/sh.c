/* Spherical harmonics -> RGB per Gaussian (degree 0-3, 3DGS basis and +0.5 offset, clamped at
 * 0), forward and backward: the public calls check their arguments and dispatch through the
 * render backend table; the CPU kernels here run on the device's pool. The per-Gaussian math is
 * sp_gm_sh_to_rgb / sp_gm_sh_to_rgb_vjp in gauss_math.h. Each Gaussian writes only its own
 * outputs, so the result is the same for any thread count. */
#include "render/backend.h"
#include "render/gauss_math.h"
#include "render/render_internal.h"

#define CHUNK 4096

typedef struct {
    size_t n;
    int K, degree_active;
    const float *sh, *means, *rgb, *v_rgb;
    float cam[3];
    float *out, *v_sh, *v_means;
    int stride;
} sh_ctx;

static int check_args(const char *fn, size_t n, int degree, int degree_active, const float *sh,
                      const float *means, int stride, sp_error *err)
{
    if (degree < 0 || degree > 3)
        return sp_error_set(err, SP_E_ARG, "%s: SH degree %d is outside 0..3", fn, degree);
    if (degree_active < 0 || degree_active > degree)
        return sp_error_set(err, SP_E_ARG, "%s: active SH degree %d is outside 0..%d", fn,
                            degree_active, degree);
    if (stride < 3) return sp_error_set(err, SP_E_ARG, "%s: stride %d < 3", fn, stride);
    if (n > 0 && (!sh || !means)) return sp_error_set(err, SP_E_ARG, "%s: NULL sh or means", fn);
    return 0;
}

static void forward_chunk(void *vctx, long chunk, int thread_id)
{
    const sh_ctx *c = vctx;
    size_t i0 = (size_t)chunk * CHUNK, i1 = i0 + CHUNK < c->n ? i0 + CHUNK : c->n;
    for (size_t i = i0; i < i1; i++)
        sp_gm_sh_to_rgb(c->degree_active, c->sh + i * (size_t)c->K * 3, c->means + 3 * i, c->cam,
                        c->out + i * (size_t)c->stride);
    (void)thread_id;
}

int sp_sh_to_rgb(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                 const float *means, sp_vec3 cam_center, float *rgb, int out_stride, sp_error *err)
{
    int rc = check_args("sp_sh_to_rgb", n, degree, degree_active, sh, means, out_stride, err);
    if (rc) return rc;
    if (n > 0 && !rgb) return sp_error_set(err, SP_E_ARG, "sp_sh_to_rgb: NULL rgb");
    if (n == 0) return 0;
    return sp_render_backend_of(dev)->sh_to_rgb(dev, n, degree, degree_active, sh, means,
                                                cam_center, rgb, out_stride, err);
}

int cpu_sh_to_rgb(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                  const float *means, sp_vec3 cam_center, float *rgb, int out_stride, sp_error *err)
{
    sh_ctx c = {n, sp_sh_coeffs(degree), degree_active, sh, means, NULL, NULL,
                {cam_center.x, cam_center.y, cam_center.z}, rgb, NULL, NULL, out_stride};
    sp_pool_for(dev->pool, (long)((n + CHUNK - 1) / CHUNK), forward_chunk, &c);
    return 0;
}

static void backward_chunk(void *vctx, long chunk, int thread_id)
{
    const sh_ctx *c = vctx;
    size_t i0 = (size_t)chunk * CHUNK, i1 = i0 + CHUNK < c->n ? i0 + CHUNK : c->n;
    for (size_t i = i0; i < i1; i++) {
        size_t o = i * (size_t)c->stride;
        sp_gm_sh_to_rgb_vjp(c->degree_active, c->sh + i * (size_t)c->K * 3, c->means + 3 * i,
                            c->cam, c->rgb + o, c->v_rgb + o, c->v_sh + i * (size_t)c->K * 3,
                            c->v_means ? c->v_means + 3 * i : NULL);
    }
    (void)thread_id;
}

int sp_sh_to_rgb_backward(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                          const float *means, sp_vec3 cam_center, const float *rgb,
                          const float *v_rgb, int stride, float *v_sh, float *v_means,
                          sp_error *err)
{
    int rc = check_args("sp_sh_to_rgb_backward", n, degree, degree_active, sh, means, stride, err);
    if (rc) return rc;
    if (n > 0 && (!rgb || !v_rgb || !v_sh))
        return sp_error_set(err, SP_E_ARG, "sp_sh_to_rgb_backward: NULL rgb, v_rgb or v_sh");
    if (n == 0) return 0;
    return sp_render_backend_of(dev)->sh_to_rgb_backward(dev, n, degree, degree_active, sh, means,
                                                         cam_center, rgb, v_rgb, stride, v_sh,
                                                         v_means, err);
}

int cpu_sh_to_rgb_backward(sp_device *dev, size_t n, int degree, int degree_active,
                           const float *sh, const float *means, sp_vec3 cam_center,
                           const float *rgb, const float *v_rgb, int stride, float *v_sh,
                           float *v_means, sp_error *err)
{
    sh_ctx c = {n, sp_sh_coeffs(degree), degree_active, sh, means, rgb, v_rgb,
                {cam_center.x, cam_center.y, cam_center.z}, NULL, v_sh, v_means, stride};
    sp_pool_for(dev->pool, (long)((n + CHUNK - 1) / CHUNK), backward_chunk, &c);
    return 0;
}
