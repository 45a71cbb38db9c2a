/* Per-Gaussian math of the 3DGS/EWA rasterizer, shared by the CPU backend (C) and the CUDA backend
 * (nvcc): every function is `static inline`, marked SP_HD (__host__ __device__ under nvcc), uses
 * only float arithmetic and the C math functions both compilers provide, and allocates nothing.
 * Each forward function has its hand-written vector-Jacobian product (`*_vjp`) beside it; the
 * vjps ADD into their outputs. Modelled on gsplat's include/Utils.cuh (our own code).
 *
 * Conventions (see include/semsplat/render.h):
 *  - 3x3 matrices are row-major float[9]; covariances are stored full (9 entries, symmetric).
 *  - 2x2 symmetric matrices (2D covariances, conics) are float[3] = (m00, m01, m11).
 *  - Gradients of symmetric matrices use the ELEMENT convention: v_m[k] is dL/dm_ij for one
 *    entry, the off-diagonal m01 and m10 each getting v_m[1] (gsplat does the same). So a scalar
 *    that uses the off-diagonal once, like the conic's b in sigma = 0.5 (a dx^2 + c dy^2) + b dx dy,
 *    has dL/db = 2 v_m[1].
 *  - Pixel (px, py) has its centre at (px + 0.5, py + 0.5); d = centre - mean2d.
 *  - Camera frame x right, y down, z forward; x_cam = R x_world + t (sp_camera). */
#ifndef SP_RENDER_GAUSS_MATH_H
#define SP_RENDER_GAUSS_MATH_H

#include <math.h>

#include "semsplat/render.h"

#ifdef __CUDACC__
#define SP_HD __host__ __device__
#else
#define SP_HD
#endif

/* 3DGS SH constants (Sloan's real SH basis as used by the original 3DGS code). */
#define SP_SH_C1 0.4886025119029199f
#define SP_SH_C2_0 1.0925484305920792f
#define SP_SH_C2_1 (-1.0925484305920792f)
#define SP_SH_C2_2 0.31539156525252005f
#define SP_SH_C2_3 (-1.0925484305920792f)
#define SP_SH_C2_4 0.5462742152960396f
#define SP_SH_C3_0 (-0.5900435899266435f)
#define SP_SH_C3_1 2.890611442640554f
#define SP_SH_C3_2 (-0.4570457994644658f)
#define SP_SH_C3_3 0.3731763325901154f
#define SP_SH_C3_4 (-0.4570457994644658f)
#define SP_SH_C3_5 1.445305721320277f
#define SP_SH_C3_6 (-0.5900435899266435f)

/* ---- arithmetic both backends round the same way ------------------------------------------------ */

/* A multiply and an add that are never fused: nvcc contracts a * b + c into one FMA (a single
 * rounding) unless told not to, GCC in ISO C mode does not (-ffp-contract=off). The keep/skip
 * tests of the rasterizer (alpha >= 1/255, T >= 1e-4) must come out identically on the CPU and
 * the GPU, so the arithmetic that feeds them goes through these. */
#if defined(__CUDA_ARCH__)
#define SP_FMUL(a, b) __fmul_rn((a), (b))
#define SP_FADD(a, b) __fadd_rn((a), (b))
#define SP_FSUB(a, b) __fsub_rn((a), (b))
#else
#define SP_FMUL(a, b) ((a) * (b))
#define SP_FADD(a, b) ((a) + (b))
#define SP_FSUB(a, b) ((a) - (b))
#endif

/* e^x, within 2 ulp for x in [-87, 88] (clamped to that range; NaN stays NaN): Cephes expf,
 * round x / ln 2 to n, a degree-5 polynomial on the remainder, times 2^n. Only basic IEEE
 * operations in a fixed order, so the CPU and the GPU get the same bits (libm's expf and CUDA's
 * expf/__expf differ from each other in the last place). cpu_exp_neg4 (render_internal.h) is the
 * same sequence four lanes wide. */
SP_HD static inline float sp_gm_expf(float x)
{
    if (x != x) return x;
    x = x < -87.f ? -87.f : (x > 88.f ? 88.f : x);
    const float magic = 12582912.f; /* 1.5 * 2^23: adding and subtracting it rounds to an integer */
    float n = SP_FSUB(SP_FADD(SP_FMUL(x, 1.44269504088896341f), magic), magic);
    float r = SP_FSUB(x, SP_FMUL(n, 0.693359375f));
    r = SP_FSUB(r, SP_FMUL(n, -2.12194440e-4f));
    float p = 1.9875691500e-4f;
    p = SP_FADD(SP_FMUL(p, r), 1.3981999507e-3f);
    p = SP_FADD(SP_FMUL(p, r), 8.3334519073e-3f);
    p = SP_FADD(SP_FMUL(p, r), 4.1665795894e-2f);
    p = SP_FADD(SP_FMUL(p, r), 1.6666665459e-1f);
    p = SP_FADD(SP_FMUL(p, r), 5.0000001201e-1f);
    p = SP_FADD(SP_FADD(SP_FMUL(p, SP_FMUL(r, r)), r), 1.f);
    union {
        int i;
        float f;
    } two_n = {.i = ((int)n + 127) << 23};
    return SP_FMUL(p, two_n.f);
}

/* gsplat's frustum slack for the Jacobian: x/z and y/z are clamped to the image's tan-fov limits
 * plus 0.3 tan(fov/2) on each side, so Gaussians far outside the view do not blow the 2D
 * covariance up. */
#define SP_FOV_SLACK 0.3f

/* ---- quaternion + log-scale -> 3D covariance ---------------------------------------------------- */

/* Unit quaternion (w,x,y,z) from q (any norm; a zero quaternion gives the identity) -> R. */
SP_HD static inline void sp_gm_quat_to_rot(const float q[4], float R[9])
{
    float n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    float inv = n2 > 0.f ? 1.f / sqrtf(n2) : 0.f;
    float w = n2 > 0.f ? q[0] * inv : 1.f, x = q[1] * inv, y = q[2] * inv, z = q[3] * inv;
    R[0] = 1.f - 2.f * (y * y + z * z); R[1] = 2.f * (x * y - w * z); R[2] = 2.f * (x * z + w * y);
    R[3] = 2.f * (x * y + w * z); R[4] = 1.f - 2.f * (x * x + z * z); R[5] = 2.f * (y * z - w * x);
    R[6] = 2.f * (x * z - w * y); R[7] = 2.f * (y * z + w * x); R[8] = 1.f - 2.f * (x * x + y * y);
}

/* v_R (dL/dR, 9) -> v_q, through the normalisation. */
SP_HD static inline void sp_gm_quat_to_rot_vjp(const float q[4], const float V[9], float v_q[4])
{
    float n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (!(n2 > 0.f)) return;
    float inv = 1.f / sqrtf(n2);
    float w = q[0] * inv, x = q[1] * inv, y = q[2] * inv, z = q[3] * inv;
    /* dL/d(unit quaternion), from differentiating each entry of R above. */
    float gw = 2.f * (-z * V[1] + y * V[2] + z * V[3] - x * V[5] - y * V[6] + x * V[7]);
    float gx = 2.f * (y * V[1] + z * V[2] + y * V[3] - w * V[5] + z * V[6] + w * V[7]) -
               4.f * x * (V[4] + V[8]);
    float gy = 2.f * (x * V[1] + w * V[2] + x * V[3] + z * V[5] - w * V[6] + z * V[7]) -
               4.f * y * (V[0] + V[8]);
    float gz = 2.f * (-w * V[1] + x * V[2] + w * V[3] + y * V[5] + x * V[6] + y * V[7]) -
               4.f * z * (V[0] + V[4]);
    /* normalisation: d(q/|q|) projects out the radial component and divides by |q|. */
    float dot = w * gw + x * gx + y * gy + z * gz;
    v_q[0] += (gw - w * dot) * inv;
    v_q[1] += (gx - x * dot) * inv;
    v_q[2] += (gy - y * dot) * inv;
    v_q[3] += (gz - z * dot) * inv;
}

/* cov = M M^T with M = R diag(exp(log_scale)). */
SP_HD static inline void sp_gm_quat_scale_to_cov(const float q[4], const float log_scale[3],
                                                 float cov[9])
{
    float R[9], M[9];
    sp_gm_quat_to_rot(q, R);
    float s0 = sp_gm_expf(log_scale[0]), s1 = sp_gm_expf(log_scale[1]), s2 = sp_gm_expf(log_scale[2]);
    for (int i = 0; i < 3; i++) {
        M[i * 3 + 0] = R[i * 3 + 0] * s0;
        M[i * 3 + 1] = R[i * 3 + 1] * s1;
        M[i * 3 + 2] = R[i * 3 + 2] * s2;
    }
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            float v = M[i * 3] * M[j * 3] + M[i * 3 + 1] * M[j * 3 + 1] + M[i * 3 + 2] * M[j * 3 + 2];
            cov[i * 3 + j] = v;
            cov[j * 3 + i] = v;
        }
}

/* v_cov (element convention, 9) -> v_q (4), v_log_scale (3). */
SP_HD static inline void sp_gm_quat_scale_to_cov_vjp(const float q[4], const float log_scale[3],
                                                     const float v_cov[9], float v_q[4],
                                                     float v_log_scale[3])
{
    float R[9], M[9], vM[9], vR[9];
    float s[3] = {sp_gm_expf(log_scale[0]), sp_gm_expf(log_scale[1]), sp_gm_expf(log_scale[2])};
    sp_gm_quat_to_rot(q, R);
    for (int i = 0; i < 9; i++) M[i] = R[i] * s[i % 3];
    /* cov = M M^T  ->  v_M = (G + G^T) M */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            float acc = 0.f;
            for (int k = 0; k < 3; k++) acc += (v_cov[i * 3 + k] + v_cov[k * 3 + i]) * M[k * 3 + j];
            vM[i * 3 + j] = acc;
        }
    float vs[3] = {0.f, 0.f, 0.f};
    for (int i = 0; i < 9; i++) {
        vR[i] = vM[i] * s[i % 3];
        vs[i % 3] += vM[i] * R[i];
    }
    for (int j = 0; j < 3; j++) v_log_scale[j] += vs[j] * s[j];
    sp_gm_quat_to_rot_vjp(q, vR, v_q);
}

/* ---- world -> camera ------------------------------------------------------------------------------ */

SP_HD static inline void sp_gm_world_to_cam(const float R[9], const float t[3], const float p[3],
                                            const float cov[9], float pc[3], float covc[9])
{
    for (int i = 0; i < 3; i++)
        pc[i] = R[i * 3] * p[0] + R[i * 3 + 1] * p[1] + R[i * 3 + 2] * p[2] + t[i];
    if (!cov || !covc) return;
    float T[9]; /* R cov */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            T[i * 3 + j] = R[i * 3] * cov[j] + R[i * 3 + 1] * cov[3 + j] + R[i * 3 + 2] * cov[6 + j];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            covc[i * 3 + j] = T[i * 3] * R[j * 3] + T[i * 3 + 1] * R[j * 3 + 1] + T[i * 3 + 2] * R[j * 3 + 2];
}

/* v_pc -> v_p (= R^T v_pc); v_covc -> v_cov (= R^T G R). */
SP_HD static inline void sp_gm_world_to_cam_vjp(const float R[9], const float v_pc[3],
                                                const float v_covc[9], float v_p[3], float v_cov[9])
{
    for (int j = 0; j < 3; j++)
        v_p[j] += R[j] * v_pc[0] + R[3 + j] * v_pc[1] + R[6 + j] * v_pc[2];
    float T[9]; /* R^T G */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            T[i * 3 + j] = R[i] * v_covc[j] + R[3 + i] * v_covc[3 + j] + R[6 + i] * v_covc[6 + j];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            v_cov[i * 3 + j] += T[i * 3] * R[j] + T[i * 3 + 1] * R[3 + j] + T[i * 3 + 2] * R[6 + j];
}

/* ---- perspective projection ------------------------------------------------------------------------ */

/* The Jacobian's x/z, y/z clamp limits (gsplat): [-neg, pos]. */
SP_HD static inline void sp_gm_fov_limits(const sp_camera *cam, float lim[4])
{
    float tan_fovx = 0.5f * (float)cam->width / cam->fx;
    float tan_fovy = 0.5f * (float)cam->height / cam->fy;
    lim[0] = ((float)cam->width - cam->cx) / cam->fx + SP_FOV_SLACK * tan_fovx; /* x pos */
    lim[1] = cam->cx / cam->fx + SP_FOV_SLACK * tan_fovx;                       /* x neg */
    lim[2] = ((float)cam->height - cam->cy) / cam->fy + SP_FOV_SLACK * tan_fovy; /* y pos */
    lim[3] = cam->cy / cam->fy + SP_FOV_SLACK * tan_fovy;                        /* y neg */
}

/* pc (camera frame, z > 0), covc -> mean2d (pixels), cov2 = J covc J^T with
 * J = [[fx/z, 0, -fx tx/z^2], [0, fy/z, -fy ty/z^2]], (tx, ty) = z * clamp((x, y)/z). */
SP_HD static inline void sp_gm_persp_proj(const float pc[3], const float covc[9],
                                          const sp_camera *cam, float mean2d[2], float cov2[3])
{
    float lim[4];
    sp_gm_fov_limits(cam, lim);
    float x = pc[0], y = pc[1], z = pc[2];
    float rz = 1.f / z, rz2 = rz * rz;
    float tx = z * fminf(lim[0], fmaxf(-lim[1], x * rz));
    float ty = z * fminf(lim[2], fmaxf(-lim[3], y * rz));
    float J0[3] = {cam->fx * rz, 0.f, -cam->fx * tx * rz2};
    float J1[3] = {0.f, cam->fy * rz, -cam->fy * ty * rz2};
    float A0[3], A1[3]; /* J covc */
    for (int j = 0; j < 3; j++) {
        A0[j] = J0[0] * covc[j] + J0[1] * covc[3 + j] + J0[2] * covc[6 + j];
        A1[j] = J1[0] * covc[j] + J1[1] * covc[3 + j] + J1[2] * covc[6 + j];
    }
    cov2[0] = A0[0] * J0[0] + A0[1] * J0[1] + A0[2] * J0[2];
    cov2[1] = A0[0] * J1[0] + A0[1] * J1[1] + A0[2] * J1[2];
    cov2[2] = A1[0] * J1[0] + A1[1] * J1[1] + A1[2] * J1[2];
    mean2d[0] = cam->fx * x * rz + cam->cx;
    mean2d[1] = cam->fy * y * rz + cam->cy;
}

/* v_mean2d, v_cov2 (element convention) -> v_pc, v_covc (added). */
SP_HD static inline void sp_gm_persp_proj_vjp(const float pc[3], const float covc[9],
                                              const sp_camera *cam, const float v_mean2d[2],
                                              const float v_cov2[3], float v_pc[3], float v_covc[9])
{
    float lim[4];
    sp_gm_fov_limits(cam, lim);
    float fx = cam->fx, fy = cam->fy;
    float x = pc[0], y = pc[1], z = pc[2];
    float rz = 1.f / z, rz2 = rz * rz, rz3 = rz2 * rz;
    float ux = x * rz, uy = y * rz;
    int clamp_x = !(ux <= lim[0] && ux >= -lim[1]);
    int clamp_y = !(uy <= lim[2] && uy >= -lim[3]);
    float tx = z * fminf(lim[0], fmaxf(-lim[1], ux));
    float ty = z * fminf(lim[2], fmaxf(-lim[3], uy));
    float J[6] = {fx * rz, 0.f, -fx * tx * rz2, 0.f, fy * rz, -fy * ty * rz2};
    float G[4] = {v_cov2[0], v_cov2[1], v_cov2[1], v_cov2[2]};
    /* v_covc = J^T G J */
    float GJ[6]; /* G J (2x3) */
    for (int r = 0; r < 2; r++)
        for (int j = 0; j < 3; j++) GJ[r * 3 + j] = G[r * 2] * J[j] + G[r * 2 + 1] * J[3 + j];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) v_covc[i * 3 + j] += J[i] * GJ[j] + J[3 + i] * GJ[3 + j];
    /* v_J = G J covc^T + G^T J covc = 2 G J covc (G and covc symmetric) */
    float vJ[6];
    for (int r = 0; r < 2; r++)
        for (int j = 0; j < 3; j++)
            vJ[r * 3 + j] = 2.f * (GJ[r * 3] * covc[j * 3] + GJ[r * 3 + 1] * covc[j * 3 + 1] +
                                   GJ[r * 3 + 2] * covc[j * 3 + 2]);
    /* mean2d = (fx x/z + cx, fy y/z + cy) */
    v_pc[0] += fx * rz * v_mean2d[0];
    v_pc[1] += fy * rz * v_mean2d[1];
    v_pc[2] += -(fx * x * v_mean2d[0] + fy * y * v_mean2d[1]) * rz2;
    /* J entries: J00 = fx/z, J11 = fy/z, J02 = -fx tx/z^2, J12 = -fy ty/z^2; tx = x unless
     * clamped, where tx = z * limit. */
    v_pc[2] += -fx * rz2 * vJ[0] - fy * rz2 * vJ[4];
    if (!clamp_x) {
        v_pc[0] += -fx * rz2 * vJ[2];
        v_pc[2] += 2.f * fx * tx * rz3 * vJ[2];
    } else {
        v_pc[2] += fx * tx * rz3 * vJ[2];
    }
    if (!clamp_y) {
        v_pc[1] += -fy * rz2 * vJ[5];
        v_pc[2] += 2.f * fy * ty * rz3 * vJ[5];
    } else {
        v_pc[2] += fy * ty * rz3 * vJ[5];
    }
}

/* ---- screen-space dilation, antialiased compensation, conic -------------------------------------- */

/* cov2 += eps2d I (in place); *comp = sqrt(det(before) / det(after)) (the antialiased opacity
 * factor). Returns det(after). */
SP_HD static inline float sp_gm_add_blur(float eps2d, float cov2[3], float *comp)
{
    float det0 = cov2[0] * cov2[2] - cov2[1] * cov2[1];
    cov2[0] += eps2d;
    cov2[2] += eps2d;
    float det1 = cov2[0] * cov2[2] - cov2[1] * cov2[1];
    *comp = det1 > 0.f ? sqrtf(fmaxf(0.f, det0 / det1)) : 0.f;
    return det1;
}

/* v_comp -> v_cov2 (of the covariance BEFORE blur; the blur itself has identity Jacobian, so the
 * caller adds the conic path's gradient separately). conic = inverse of the blurred cov2.
 * d(det0/det1)/dM = (1 - comp^2) conic - eps2d det(conic) I (gsplat's derivation). */
SP_HD static inline void sp_gm_add_blur_vjp(float eps2d, const float conic[3], float comp,
                                            float v_comp, float v_cov2[3])
{
    if (!(comp > 0.f)) return;
    float det_conic = conic[0] * conic[2] - conic[1] * conic[1];
    float v_ratio = v_comp * 0.5f / comp;
    float k = 1.f - comp * comp;
    v_cov2[0] += v_ratio * (k * conic[0] - eps2d * det_conic);
    v_cov2[1] += v_ratio * (k * conic[1]);
    v_cov2[2] += v_ratio * (k * conic[2] - eps2d * det_conic);
}

/* conic = cov2^-1; returns 0 when cov2 is not positive definite. */
SP_HD static inline int sp_gm_inverse2(const float cov2[3], float conic[3])
{
    float det = cov2[0] * cov2[2] - cov2[1] * cov2[1];
    if (!(det > 0.f)) return 0;
    float inv = 1.f / det;
    conic[0] = cov2[2] * inv;
    conic[1] = -cov2[1] * inv;
    conic[2] = cov2[0] * inv;
    return 1;
}

/* P = M^-1: v_M = -P G P (symmetric, element convention both sides). */
SP_HD static inline void sp_gm_inverse2_vjp(const float conic[3], const float v_conic[3],
                                            float v_cov2[3])
{
    float P[4] = {conic[0], conic[1], conic[1], conic[2]};
    float G[4] = {v_conic[0], v_conic[1], v_conic[1], v_conic[2]};
    float PG[4] = {P[0] * G[0] + P[1] * G[2], P[0] * G[1] + P[1] * G[3],
                   P[2] * G[0] + P[3] * G[2], P[2] * G[1] + P[3] * G[3]};
    v_cov2[0] -= PG[0] * P[0] + PG[1] * P[2];
    v_cov2[1] -= PG[0] * P[1] + PG[1] * P[3];
    v_cov2[2] -= PG[2] * P[1] + PG[3] * P[3];
}

/* Screen radius (pixels) of a Gaussian with blurred 2D covariance cov2 and effective opacity:
 * the opacity-aware extent of gsplat (arXiv 2402.00525, B.2) along the largest eigenvalue,
 * sqrt(2 ln(255 opacity)) sigma_max (at most 3.33 sigma). Outside that circle alpha < 1/255, so
 * binning by this radius never drops a contribution the compositing rules would keep (the tiled
 * result equals the every-Gaussian-at-every-pixel one). 0 = invisible. */
SP_HD static inline int sp_gm_radius(const float cov2[3], float opacity)
{
    if (!(opacity * 255.f > 1.f)) return 0;
    float mid = 0.5f * (cov2[0] + cov2[2]);
    float det = cov2[0] * cov2[2] - cov2[1] * cov2[1];
    float lmax = mid + sqrtf(fmaxf(0.f, mid * mid - det));
    float extent = sqrtf(2.f * logf(opacity * 255.f));
    float r = ceilf(extent * sqrtf(lmax));
    if (!(r >= 1.f)) return 0;
    return r > 1e6f ? 1000000 : (int)r;
}

/* ---- the whole per-Gaussian projection ------------------------------------------------------------- */

/* The 2D covariance J Rc Sigma Rc^T J^T computed as A A^T with A = J Rc R S (2x3), and its
 * determinant by Cauchy-Binet as the sum of the squared 2x2 minors of A. The textbook
 * a c - b^2 cancels catastrophically in float for needle-like Gaussians (one huge, two tiny
 * scales), which made the conic wrong by tens of percent; the minors stay accurate. */
SP_HD static inline void sp_gm_cov2d(const float quat[4], const float log_scale[3],
                                     const float pc[3], const sp_camera *cam, float cov2[3],
                                     float *det)
{
    float R[9], lim[4];
    sp_gm_quat_to_rot(quat, R);
    sp_gm_fov_limits(cam, lim);
    float rz = 1.f / pc[2], rz2 = rz * rz;
    float tx = pc[2] * fminf(lim[0], fmaxf(-lim[1], pc[0] * rz));
    float ty = pc[2] * fminf(lim[2], fmaxf(-lim[3], pc[1] * rz));
    float J0[3] = {cam->fx * rz, 0.f, -cam->fx * tx * rz2};
    float J1[3] = {0.f, cam->fy * rz, -cam->fy * ty * rz2};
    /* rows of J Rc */
    float B0[3], B1[3];
    for (int j = 0; j < 3; j++) {
        B0[j] = J0[0] * cam->R[j] + J0[1] * cam->R[3 + j] + J0[2] * cam->R[6 + j];
        B1[j] = J1[0] * cam->R[j] + J1[1] * cam->R[3 + j] + J1[2] * cam->R[6 + j];
    }
    /* A = (J Rc) R S */
    float A0[3], A1[3];
    for (int j = 0; j < 3; j++) {
        float s = sp_gm_expf(log_scale[j]);
        A0[j] = (B0[0] * R[j] + B0[1] * R[3 + j] + B0[2] * R[6 + j]) * s;
        A1[j] = (B1[0] * R[j] + B1[1] * R[3 + j] + B1[2] * R[6 + j]) * s;
    }
    cov2[0] = A0[0] * A0[0] + A0[1] * A0[1] + A0[2] * A0[2];
    cov2[1] = A0[0] * A1[0] + A0[1] * A1[1] + A0[2] * A1[2];
    cov2[2] = A1[0] * A1[0] + A1[1] * A1[1] + A1[2] * A1[2];
    float m01 = A0[0] * A1[1] - A0[1] * A1[0];
    float m02 = A0[0] * A1[2] - A0[2] * A1[0];
    float m12 = A0[1] * A1[2] - A0[2] * A1[1];
    *det = m01 * m01 + m02 * m02 + m12 * m12;
}

/* Blur, compensation and conic from sp_gm_cov2d's output: cov2 += eps2d I (in place),
 * det(after) = det + eps2d (a + c) + eps2d^2 (no cancellation), comp = sqrt(det / det(after)).
 * Returns 0 when the result is not positive definite. */
SP_HD static inline int sp_gm_blur_conic(float eps2d, float cov2[3], float det, float conic[3],
                                         float *comp)
{
    float det1 = det + eps2d * (cov2[0] + cov2[2]) + eps2d * eps2d;
    cov2[0] += eps2d;
    cov2[2] += eps2d;
    if (!(det1 > 0.f)) return 0;
    *comp = sqrtf(det / det1);
    float inv = 1.f / det1;
    conic[0] = cov2[2] * inv;
    conic[1] = -cov2[1] * inv;
    conic[2] = cov2[0] * inv;
    return 1;
}

/* sp_gm_project plus the blurred 2D covariance (cov2, for per-axis extents). */
SP_HD static inline int sp_gm_project_ex(const float mean[3], const float quat[4],
                                         const float log_scale[3], float opacity_logit,
                                         const sp_camera *cam, const sp_raster_cfg *cfg,
                                         float mean2d[2], float conic[3], float *depth,
                                         float *opacity, int *radius, float cov2[3])
{
    float pc[3], det, comp;
    *radius = 0;
    /* The camera-frame position and the 2D mean in double: for Gaussians close to the camera,
     * float R x + t loses digits that x / z then magnifies (1e-4 px at z = 2 cm). 12 double
     * operations per Gaussian, nothing per pixel. */
    double pd[3];
    for (int k = 0; k < 3; k++) {
        pd[k] = (double)cam->R[k * 3] * mean[0] + (double)cam->R[k * 3 + 1] * mean[1] +
                (double)cam->R[k * 3 + 2] * mean[2] + (double)cam->t[k];
        pc[k] = (float)pd[k];
    }
    if (!(pc[2] >= cfg->near_plane && pc[2] <= cfg->far_plane)) return 0;
    sp_gm_cov2d(quat, log_scale, pc, cam, cov2, &det);
    if (!sp_gm_blur_conic(cfg->eps2d, cov2, det, conic, &comp)) return 0;
    mean2d[0] = (float)((double)cam->fx * pd[0] / pd[2] + (double)cam->cx);
    mean2d[1] = (float)((double)cam->fy * pd[1] / pd[2] + (double)cam->cy);
    float op = 1.f / (1.f + sp_gm_expf(-opacity_logit));
    if (cfg->antialiased) op *= comp;
    int r = sp_gm_radius(cov2, op);
    if (r <= 0) return 0;
    float W = (float)cam->width, H = (float)cam->height;
    if (mean2d[0] + r <= 0.f || mean2d[0] - r >= W || mean2d[1] + r <= 0.f || mean2d[1] - r >= H)
        return 0;
    *depth = pc[2];
    *opacity = op;
    *radius = r;
    return 1;
}

/* Projects one Gaussian. Returns 1 and fills the outputs when visible; 0 (radius 0) when culled:
 * camera z outside [near, far], non-positive-definite 2D covariance, opacity below 1/255, or the
 * radius circle entirely outside the image. opacity is sigmoid(logit), times the compensation
 * when antialiased. */
SP_HD static inline int sp_gm_project(const float mean[3], const float quat[4],
                                      const float log_scale[3], float opacity_logit,
                                      const sp_camera *cam, const sp_raster_cfg *cfg,
                                      float mean2d[2], float conic[3], float *depth,
                                      float *opacity, int *radius)
{
    float cov2[3];
    return sp_gm_project_ex(mean, quat, log_scale, opacity_logit, cam, cfg, mean2d, conic, depth,
                            opacity, radius, cov2);
}

/* Backward of sp_gm_project for a visible Gaussian. Inputs: dL/d mean2d, dL/d conic (element
 * convention), dL/d depth, dL/d opacity (the effective one). ADDS into v_mean[3], v_quat[4],
 * v_log_scale[3], *v_opacity_logit. */
SP_HD static inline void sp_gm_project_vjp(const float mean[3], const float quat[4],
                                           const float log_scale[3], float opacity_logit,
                                           const sp_camera *cam, const sp_raster_cfg *cfg,
                                           const float v_mean2d[2], const float v_conic[3],
                                           float v_depth, float v_opacity, float v_mean[3],
                                           float v_quat[4], float v_log_scale[3],
                                           float *v_opacity_logit)
{
    float pc[3], cov[9], covc[9], cov2[3], det, conic[3], comp;
    sp_gm_quat_scale_to_cov(quat, log_scale, cov);
    sp_gm_world_to_cam(cam->R, cam->t, mean, cov, pc, covc);
    /* conic and compensation exactly as the forward computed them */
    sp_gm_cov2d(quat, log_scale, pc, cam, cov2, &det);
    if (!sp_gm_blur_conic(cfg->eps2d, cov2, det, conic, &comp)) return;
    float sig = 1.f / (1.f + sp_gm_expf(-opacity_logit));

    float v_cov2[3] = {0.f, 0.f, 0.f};
    sp_gm_inverse2_vjp(conic, v_conic, v_cov2);
    if (cfg->antialiased) {
        *v_opacity_logit += v_opacity * comp * sig * (1.f - sig);
        sp_gm_add_blur_vjp(cfg->eps2d, conic, comp, v_opacity * sig, v_cov2);
    } else {
        *v_opacity_logit += v_opacity * sig * (1.f - sig);
    }
    float v_pc[3] = {0.f, 0.f, v_depth};
    float v_covc[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    sp_gm_persp_proj_vjp(pc, covc, cam, v_mean2d, v_cov2, v_pc, v_covc);
    float v_cov[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    sp_gm_world_to_cam_vjp(cam->R, v_pc, v_covc, v_mean, v_cov);
    sp_gm_quat_scale_to_cov_vjp(quat, log_scale, v_cov, v_quat, v_log_scale);
}

/* ---- per-pixel alpha -------------------------------------------------------------------------------- */

/* sigma = 0.5 (a dx^2 + c dy^2) + b dx dy for conic (a, b, c), evaluated as
 * (half_a dx + by) dx + hy with the per-row terms of sp_gm_row_terms, in exactly this order on
 * both backends (the CPU keeps by and hy for a whole row, four pixels at a time). */
SP_HD static inline void sp_gm_row_terms(const float conic[3], float dy, float *by, float *hy)
{
    *by = SP_FMUL(conic[1], dy);
    *hy = SP_FMUL(SP_FMUL(0.5f * conic[2], dy), dy);
}
SP_HD static inline float sp_gm_sigma(float half_a, float by, float hy, float dx)
{
    return SP_FADD(SP_FMUL(SP_FADD(SP_FMUL(half_a, dx), by), dx), hy);
}

/* A sigma beyond which alpha is surely below SP_ALPHA_MIN: ln(255 opacity) plus a margin far
 * larger than float rounding, so skipping there before the exp never changes a decision (and
 * the log need not round the same on both backends). */
SP_HD static inline float sp_gm_sigma_cut(float opacity)
{
    return logf(opacity * 255.f) + 1e-3f;
}

/* alpha of a Gaussian at offset (dx, dy) = pixel centre - mean2d (dx = (px + 0.5) - mean x, one
 * rounding): min(SP_ALPHA_MAX, opacity exp(-sigma)); returns 0 when the contribution is skipped
 * (sigma < 0 from rounding, sigma beyond sigma_cut, or alpha < SP_ALPHA_MIN) and sets
 * *g = exp(-sigma) otherwise. This is THE rule: the CUDA kernels call it, the CPU's cpu_alpha4
 * is the same operations four lanes wide, so both backends keep and skip the same contributions
 * bit for bit. */
SP_HD static inline float sp_gm_alpha_g(const float conic[3], float opacity, float sigma_cut,
                                        float dx, float dy, float *g)
{
    float by, hy;
    sp_gm_row_terms(conic, dy, &by, &hy);
    float sigma = sp_gm_sigma(0.5f * conic[0], by, hy, dx);
    if (sigma < 0.f || sigma > sigma_cut) return 0.f;
    *g = sp_gm_expf(-sigma);
    float a = SP_FMUL(opacity, *g);
    a = a < SP_ALPHA_MAX ? a : SP_ALPHA_MAX;
    return a < SP_ALPHA_MIN ? 0.f : a;
}

/* Backward of sp_gm_alpha_g at a kept contribution: dL/dalpha -> v_conic (element convention),
 * v_mean2d, v_opacity (added). Zero where alpha was clamped at SP_ALPHA_MAX. */
SP_HD static inline void sp_gm_alpha_vjp(const float conic[3], float opacity, float dx, float dy,
                                         float v_alpha, float v_conic[3], float v_mean2d[2],
                                         float *v_opacity)
{
    float sigma = 0.5f * (conic[0] * dx * dx + conic[2] * dy * dy) + conic[1] * dx * dy;
    float g = sp_gm_expf(-sigma);
    if (opacity * g > SP_ALPHA_MAX) return;
    *v_opacity += g * v_alpha;
    float v_sigma = -opacity * g * v_alpha;
    v_conic[0] += 0.5f * v_sigma * dx * dx;
    v_conic[1] += 0.5f * v_sigma * dx * dy;
    v_conic[2] += 0.5f * v_sigma * dy * dy;
    /* d = centre - mean2d, so d sigma / d mean2d = -(conic d) */
    v_mean2d[0] -= v_sigma * (conic[0] * dx + conic[1] * dy);
    v_mean2d[1] -= v_sigma * (conic[1] * dx + conic[2] * dy);
}

/* ---- spherical harmonics ---------------------------------------------------------------------------- */

/* Real SH basis up to `degree` (0..3) at unit direction (x, y, z): basis[0..(degree+1)^2). */
SP_HD static inline void sp_gm_sh_basis(int degree, float x, float y, float z, float *basis)
{
    basis[0] = SP_SH_C0;
    if (degree < 1) return;
    basis[1] = -SP_SH_C1 * y;
    basis[2] = SP_SH_C1 * z;
    basis[3] = -SP_SH_C1 * x;
    if (degree < 2) return;
    float xx = x * x, yy = y * y, zz = z * z;
    basis[4] = SP_SH_C2_0 * x * y;
    basis[5] = SP_SH_C2_1 * y * z;
    basis[6] = SP_SH_C2_2 * (2.f * zz - xx - yy);
    basis[7] = SP_SH_C2_3 * x * z;
    basis[8] = SP_SH_C2_4 * (xx - yy);
    if (degree < 3) return;
    basis[9] = SP_SH_C3_0 * y * (3.f * xx - yy);
    basis[10] = SP_SH_C3_1 * x * y * z;
    basis[11] = SP_SH_C3_2 * y * (4.f * zz - xx - yy);
    basis[12] = SP_SH_C3_3 * z * (2.f * zz - 3.f * xx - 3.f * yy);
    basis[13] = SP_SH_C3_4 * x * (4.f * zz - xx - yy);
    basis[14] = SP_SH_C3_5 * z * (xx - yy);
    basis[15] = SP_SH_C3_6 * x * (xx - 3.f * yy);
}

/* v_basis -> v_dir (added) for the unnormalised components (x, y, z) of the basis above. */
SP_HD static inline void sp_gm_sh_basis_vjp(int degree, float x, float y, float z,
                                            const float *v_basis, float v_dir[3])
{
    if (degree < 1) return;
    float gx = -SP_SH_C1 * v_basis[3];
    float gy = -SP_SH_C1 * v_basis[1];
    float gz = SP_SH_C1 * v_basis[2];
    if (degree >= 2) {
        const float *b = v_basis;
        gx += SP_SH_C2_0 * y * b[4] - 2.f * SP_SH_C2_2 * x * b[6] + SP_SH_C2_3 * z * b[7] +
              2.f * SP_SH_C2_4 * x * b[8];
        gy += SP_SH_C2_0 * x * b[4] + SP_SH_C2_1 * z * b[5] - 2.f * SP_SH_C2_2 * y * b[6] -
              2.f * SP_SH_C2_4 * y * b[8];
        gz += SP_SH_C2_1 * y * b[5] + 4.f * SP_SH_C2_2 * z * b[6] + SP_SH_C2_3 * x * b[7];
    }
    if (degree >= 3) {
        const float *b = v_basis;
        float xx = x * x, yy = y * y, zz = z * z;
        gx += 6.f * SP_SH_C3_0 * x * y * b[9] + SP_SH_C3_1 * y * z * b[10] -
              2.f * SP_SH_C3_2 * x * y * b[11] - 6.f * SP_SH_C3_3 * x * z * b[12] +
              SP_SH_C3_4 * (4.f * zz - 3.f * xx - yy) * b[13] + 2.f * SP_SH_C3_5 * x * z * b[14] +
              SP_SH_C3_6 * (3.f * xx - 3.f * yy) * b[15];
        gy += SP_SH_C3_0 * (3.f * xx - 3.f * yy) * b[9] + SP_SH_C3_1 * x * z * b[10] +
              SP_SH_C3_2 * (4.f * zz - xx - 3.f * yy) * b[11] - 6.f * SP_SH_C3_3 * y * z * b[12] -
              2.f * SP_SH_C3_4 * x * y * b[13] - 2.f * SP_SH_C3_5 * y * z * b[14] -
              6.f * SP_SH_C3_6 * x * y * b[15];
        gz += SP_SH_C3_1 * x * y * b[10] + 8.f * SP_SH_C3_2 * y * z * b[11] +
              SP_SH_C3_3 * (6.f * zz - 3.f * xx - 3.f * yy) * b[12] + 8.f * SP_SH_C3_4 * x * z * b[13] +
              SP_SH_C3_5 * (xx - yy) * b[14];
    }
    v_dir[0] += gx;
    v_dir[1] += gy;
    v_dir[2] += gz;
}

/* rgb[c] = max(0, 0.5 + sum_k basis_k(dir) sh[k*3 + c]) for the bands up to degree_active, with
 * dir = normalize(mean - cam_center). sh is one Gaussian's [K][3]. */
SP_HD static inline void sp_gm_sh_to_rgb(int degree_active, const float *sh, const float mean[3],
                                         const float cam_center[3], float rgb[3])
{
    float d[3] = {mean[0] - cam_center[0], mean[1] - cam_center[1], mean[2] - cam_center[2]};
    float n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    float inv = n2 > 0.f ? 1.f / sqrtf(n2) : 0.f;
    float basis[16];
    sp_gm_sh_basis(degree_active, d[0] * inv, d[1] * inv, d[2] * inv, basis);
    int K = (degree_active + 1) * (degree_active + 1);
    for (int c = 0; c < 3; c++) {
        float acc = 0.5f;
        for (int k = 0; k < K; k++) acc += basis[k] * sh[k * 3 + c];
        rgb[c] = fmaxf(0.f, acc);
    }
}

/* Backward: v_rgb -> v_sh (one Gaussian's [K][3], added) and v_mean (added, may be NULL).
 * rgb is the forward's output: channels at 0 were clamped and pass no gradient. */
SP_HD static inline void sp_gm_sh_to_rgb_vjp(int degree_active, const float *sh,
                                             const float mean[3], const float cam_center[3],
                                             const float rgb[3], const float v_rgb_in[3],
                                             float *v_sh, float *v_mean)
{
    float v_rgb[3];
    for (int c = 0; c < 3; c++) v_rgb[c] = rgb[c] > 0.f ? v_rgb_in[c] : 0.f;
    float d[3] = {mean[0] - cam_center[0], mean[1] - cam_center[1], mean[2] - cam_center[2]};
    float n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    float inv = n2 > 0.f ? 1.f / sqrtf(n2) : 0.f;
    float u[3] = {d[0] * inv, d[1] * inv, d[2] * inv};
    float basis[16], v_basis[16];
    sp_gm_sh_basis(degree_active, u[0], u[1], u[2], basis);
    int K = (degree_active + 1) * (degree_active + 1);
    for (int k = 0; k < K; k++) {
        v_basis[k] = 0.f;
        for (int c = 0; c < 3; c++) {
            v_sh[k * 3 + c] += basis[k] * v_rgb[c];
            v_basis[k] += sh[k * 3 + c] * v_rgb[c];
        }
    }
    if (!v_mean || degree_active < 1 || !(n2 > 0.f)) return;
    float v_u[3] = {0.f, 0.f, 0.f};
    sp_gm_sh_basis_vjp(degree_active, u[0], u[1], u[2], v_basis, v_u);
    /* u = d / |d|: v_d = (v_u - u (u . v_u)) / |d| */
    float dot = u[0] * v_u[0] + u[1] * v_u[1] + u[2] * v_u[2];
    for (int i = 0; i < 3; i++) v_mean[i] += (v_u[i] - u[i] * dot) * inv;
}

#endif
