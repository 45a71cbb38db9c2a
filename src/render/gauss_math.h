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
#define SP_FDIV(a, b) __fdiv_rn((a), (b))
#define SP_FSQRT(a) __fsqrt_rn(a)
#else
#define SP_FMUL(a, b) ((a) * (b))
#define SP_FADD(a, b) ((a) + (b))
#define SP_FSUB(a, b) ((a) - (b))
#define SP_FDIV(a, b) ((a) / (b))
#define SP_FSQRT(a) sqrtf(a)
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

/* ---- world -> camera ------------------------------------------------------------------------------ */

/* Camera-frame position in double: for Gaussians close to the camera, float R x + t loses digits
 * that x / z then magnifies (1e-4 px at z = 2 cm). The forward and the backward both use it. */
SP_HD static inline void sp_gm_cam_point(const sp_camera *cam, const float p[3], double pd[3])
{
    for (int k = 0; k < 3; k++)
        pd[k] = (double)cam->R[k * 3] * p[0] + (double)cam->R[k * 3 + 1] * p[1] +
                (double)cam->R[k * 3 + 2] * p[2] + (double)cam->t[k];
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

/* The projection's Jacobian at pc (camera frame, z > 0), row-major 2x3:
 * J = [[fx/z, 0, -fx tx/z^2], [0, fy/z, -fy ty/z^2]], (tx, ty) = z * clamp((x, y)/z).
 * Also returns (tx, ty) in t and, in clamp, whether x/z, y/z hit their limits (then tx, ty no
 * longer follow x, y). */
SP_HD static inline void sp_gm_jacobian(const float pc[3], const sp_camera *cam, float J[6],
                                        float t[2], int clamp[2])
{
    float lim[4];
    sp_gm_fov_limits(cam, lim);
    float rz = 1.f / pc[2], rz2 = rz * rz;
    float ux = pc[0] * rz, uy = pc[1] * rz;
    clamp[0] = !(ux <= lim[0] && ux >= -lim[1]);
    clamp[1] = !(uy <= lim[2] && uy >= -lim[3]);
    float tx = pc[2] * fminf(lim[0], fmaxf(-lim[1], ux));
    float ty = pc[2] * fminf(lim[2], fmaxf(-lim[3], uy));
    J[0] = cam->fx * rz; J[1] = 0.f; J[2] = -cam->fx * tx * rz2;
    J[3] = 0.f; J[4] = cam->fy * rz; J[5] = -cam->fy * ty * rz2;
    t[0] = tx;
    t[1] = ty;
}

/* U = J Rc R (2x3): the Gaussian's three axes on screen per unit scale, so that the 2D
 * covariance is U S^2 U^T. */
SP_HD static inline void sp_gm_screen_axes(const float J[6], const float camR[9], const float R[9],
                                           float U[6])
{
    float B[6]; /* J Rc */
    for (int r = 0; r < 2; r++)
        for (int j = 0; j < 3; j++)
            B[r * 3 + j] = J[r * 3] * camR[j] + J[r * 3 + 1] * camR[3 + j] + J[r * 3 + 2] * camR[6 + j];
    for (int r = 0; r < 2; r++)
        for (int j = 0; j < 3; j++)
            U[r * 3 + j] = B[r * 3] * R[j] + B[r * 3 + 1] * R[3 + j] + B[r * 3 + 2] * R[6 + j];
}

/* sinh(d) to a few ulp, also for small d (where (e^d - e^-d) / 2 cancels). */
SP_HD static inline float sp_gm_sinhf(float d)
{
    float ad = fabsf(d);
    if (ad < 0.35f) {
        float d2 = d * d;
        return d * (1.f + d2 * (1.f / 6.f + d2 * (1.f / 120.f + d2 * (1.f / 5040.f + d2 * (1.f / 362880.f)))));
    }
    float e = sp_gm_expf(ad);
    float r = 0.5f * (e - 1.f / e);
    return d < 0.f ? -r : r;
}

/* The conic's principal frame: e0 = (*cs, *sn) is the eigenvector of its larger eigenvalue (the
 * Gaussian's minor axis on screen), e1 = (-*sn, *cs). The rasterizer backward sums the conic
 * gradient in this frame (d' = (e0 . d, e1 . d)) rather than in pixel axes: for a needle on
 * screen (axis ratio 100) the gradient along its long axis is 1e-4 of the rest, and summed in
 * pixel axes it drowned in the other components' rounding (CPU and CUDA, summing in different
 * orders, disagreed by percents on such Gaussians' quaternions and scales). Basic IEEE
 * operations only, so both backends get the same frame from the same conic bits, also in
 * fast-math kernels. */
SP_HD static inline void sp_gm_conic_frame(const float conic[3], float *cs, float *sn)
{
    float h = SP_FMUL(0.5f, SP_FSUB(conic[0], conic[2]));
    float r = SP_FSQRT(SP_FADD(SP_FMUL(h, h), SP_FMUL(conic[1], conic[1])));
    if (!(r > 0.f)) { /* round (or NaN): any frame */
        *cs = 1.f;
        *sn = 0.f;
        return;
    }
    float c2 = SP_FDIV(h, r); /* cos 2 theta */
    if (h >= 0.f) {
        float c = SP_FSQRT(SP_FMUL(0.5f, SP_FADD(1.f, c2)));
        *cs = c;
        *sn = SP_FDIV(conic[1], SP_FMUL(SP_FMUL(2.f, r), c));
    } else {
        float sv = SP_FSQRT(SP_FMUL(0.5f, SP_FSUB(1.f, c2)));
        *sn = sv;
        *cs = SP_FDIV(conic[1], SP_FMUL(SP_FMUL(2.f, r), sv));
    }
}

/* Symmetric 2x2 m (element convention) expressed in the frame (cs, sn): Q m Q^T with rows
 * e0 = (cs, sn), e1 = (-sn, cs). */
SP_HD static inline void sp_gm_to_frame(const float m[3], float cs, float sn, float out[3])
{
    float e0m[2] = {cs * m[0] + sn * m[1], cs * m[1] + sn * m[2]};  /* e0^T m */
    float e1m[2] = {-sn * m[0] + cs * m[1], -sn * m[1] + cs * m[2]}; /* e1^T m */
    out[0] = e0m[0] * cs + e0m[1] * sn;
    out[1] = -e0m[0] * sn + e0m[1] * cs;
    out[2] = -e1m[0] * sn + e1m[1] * cs;
}

/* dL/d cov2 (element convention, in the frame (cs, sn) of sp_gm_to_frame) -> dL/d pc (through
 * the Jacobian), dL/d quat and dL/d log_scale, ADDED. With U = Q J Rc R (Q: the frame),
 * S = diag(s) and N = U^T V U (V = dL/d cov2 in the frame):
 *   dL/d log s_j = 2 s_j^2 N_jj,
 *   the rotation's body-frame gradient g_k = 2 N_ij (s_i^2 - s_j^2), (k, i, j) cyclic,
 *   dL/dq = 2 q (x) (0, g) / |q|   (quaternion product; tangent to q, so the normalisation
 *   passes it through unchanged).
 * Going through dL/d Sigma (3x3) instead gives the rotation gradient as a difference of terms of
 * size s^2 |V| that cancel for nearly round Gaussians: float noise of 1e-7 in V became tens of
 * percent there (CPU and CUDA disagreed by up to 78 %). Here the scale differences come from the
 * log-scales themselves, s_i^2 - s_j^2 = 2 e^(l_i + l_j) sinh(l_i - l_j), so every output is as
 * accurate as V. Likewise J Sigma_c for the Jacobian path is formed as U S^2 (Rc R)^T, never from
 * an explicit camera-frame covariance. */
SP_HD static inline void sp_gm_cov2d_vjp(const float quat[4], const float log_scale[3],
                                         const float pc[3], const sp_camera *cam,
                                         const float v_cov2[3], float cs, float sn,
                                         float v_pc[3], float v_quat[4], float v_log_scale[3])
{
    float J[6], t[2], R[9], U[6], s2[3];
    int clamp[2];
    sp_gm_jacobian(pc, cam, J, t, clamp);
    sp_gm_quat_to_rot(quat, R);
    sp_gm_screen_axes(J, cam->R, R, U);
    for (int j = 0; j < 3; j++) { /* into the frame */
        float u0 = U[j], u1 = U[3 + j];
        U[j] = cs * u0 + sn * u1;
        U[3 + j] = -sn * u0 + cs * u1;
    }
    for (int j = 0; j < 3; j++) s2[j] = sp_gm_expf(2.f * log_scale[j]);
    float V[4] = {v_cov2[0], v_cov2[1], v_cov2[1], v_cov2[2]};
    float VU[6]; /* V U */
    for (int r = 0; r < 2; r++)
        for (int j = 0; j < 3; j++) VU[r * 3 + j] = V[r * 2] * U[j] + V[r * 2 + 1] * U[3 + j];
#define SP_GM_N(i, j) (U[i] * VU[j] + U[3 + (i)] * VU[3 + (j)])
    for (int j = 0; j < 3; j++) v_log_scale[j] += 2.f * s2[j] * SP_GM_N(j, j);
    float g[3];
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        float ds2 = 2.f * sp_gm_expf(log_scale[i] + log_scale[j]) *
                    sp_gm_sinhf(log_scale[i] - log_scale[j]);
        g[k] = 2.f * SP_GM_N(i, j) * ds2;
    }
#undef SP_GM_N
    float n2 = quat[0] * quat[0] + quat[1] * quat[1] + quat[2] * quat[2] + quat[3] * quat[3];
    if (n2 > 0.f) {
        float inv = 1.f / sqrtf(n2);
        float w = quat[0] * inv, x = quat[1] * inv, y = quat[2] * inv, z = quat[3] * inv;
        float k2 = 2.f * inv;
        v_quat[0] += k2 * -(x * g[0] + y * g[1] + z * g[2]);
        v_quat[1] += k2 * (w * g[0] + y * g[2] - z * g[1]);
        v_quat[2] += k2 * (w * g[1] + z * g[0] - x * g[2]);
        v_quat[3] += k2 * (w * g[2] + x * g[1] - y * g[0]);
    }
    /* Jacobian path: dL/dJ = 2 V (J Sigma_c), J Sigma_c = U S^2 W^T with W = Rc R (in the
     * frame, like V and U). */
    float W[9];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            W[i * 3 + k] = cam->R[i * 3] * R[k] + cam->R[i * 3 + 1] * R[3 + k] + cam->R[i * 3 + 2] * R[6 + k];
    float JC[6], vJ[6];
    for (int r = 0; r < 2; r++)
        for (int j = 0; j < 3; j++)
            JC[r * 3 + j] = U[r * 3] * s2[0] * W[j * 3] + U[r * 3 + 1] * s2[1] * W[j * 3 + 1] +
                            U[r * 3 + 2] * s2[2] * W[j * 3 + 2];
    float vJf[6]; /* in the frame (U is), then back to pixel axes: vJ = Q^T vJf */
    for (int r = 0; r < 2; r++)
        for (int j = 0; j < 3; j++) vJf[r * 3 + j] = 2.f * (V[r * 2] * JC[j] + V[r * 2 + 1] * JC[3 + j]);
    for (int j = 0; j < 3; j++) {
        vJ[j] = cs * vJf[j] - sn * vJf[3 + j];
        vJ[3 + j] = sn * vJf[j] + cs * vJf[3 + j];
    }
    /* J00 = fx/z, J11 = fy/z, J02 = -fx tx/z^2, J12 = -fy ty/z^2; tx = x unless clamped, where
     * tx = z * limit. */
    float fx = cam->fx, fy = cam->fy, rz = 1.f / pc[2], rz2 = rz * rz, rz3 = rz2 * rz;
    float tx = t[0], ty = t[1];
    v_pc[2] += -fx * rz2 * vJ[0] - fy * rz2 * vJ[4];
    if (!clamp[0]) {
        v_pc[0] += -fx * rz2 * vJ[2];
        v_pc[2] += 2.f * fx * tx * rz3 * vJ[2];
    } else {
        v_pc[2] += fx * tx * rz3 * vJ[2];
    }
    if (!clamp[1]) {
        v_pc[1] += -fy * rz2 * vJ[5];
        v_pc[2] += 2.f * fy * ty * rz3 * vJ[5];
    } else {
        v_pc[2] += fy * ty * rz3 * vJ[5];
    }
}

/* ---- screen-space dilation, antialiased compensation, conic -------------------------------------- */

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
    float R[9], J[6], t[2], U[6];
    int clamp[2];
    sp_gm_quat_to_rot(quat, R);
    sp_gm_jacobian(pc, cam, J, t, clamp);
    sp_gm_screen_axes(J, cam->R, R, U);
    float A0[3], A1[3]; /* A = U S */
    for (int j = 0; j < 3; j++) {
        float s = sp_gm_expf(log_scale[j]);
        A0[j] = U[j] * s;
        A1[j] = U[3 + j] * s;
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
    double pd[3]; /* the 2D mean from the double camera point too (sp_gm_cam_point) */
    sp_gm_cam_point(cam, mean, pd);
    for (int k = 0; k < 3; k++) pc[k] = (float)pd[k];
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
 * convention, in the conic's principal frame: sp_gm_conic_frame), dL/d depth, dL/d opacity (the effective one). ADDS into v_mean[3], v_quat[4],
 * v_log_scale[3], *v_opacity_logit. */
SP_HD static inline void sp_gm_project_vjp(const float mean[3], const float quat[4],
                                           const float log_scale[3], float opacity_logit,
                                           const sp_camera *cam, const sp_raster_cfg *cfg,
                                           const float v_mean2d[2], const float v_conic[3],
                                           float v_depth, float v_opacity, float v_mean[3],
                                           float v_quat[4], float v_log_scale[3],
                                           float *v_opacity_logit)
{
    float pc[3], cov2[3], det, conic[3], comp;
    double pd[3];
    sp_gm_cam_point(cam, mean, pd);
    for (int k = 0; k < 3; k++) pc[k] = (float)pd[k];
    /* conic and compensation exactly as the forward computed them */
    sp_gm_cov2d(quat, log_scale, pc, cam, cov2, &det);
    if (!sp_gm_blur_conic(cfg->eps2d, cov2, det, conic, &comp)) return;
    float sig = 1.f / (1.f + sp_gm_expf(-opacity_logit));

    /* v_conic is in the conic's principal frame (sp_gm_conic_frame); so is everything up to
     * N in sp_gm_cov2d_vjp, where the long axis's share is a separate number throughout. */
    float cs, sn, conf[3];
    sp_gm_conic_frame(conic, &cs, &sn);
    sp_gm_to_frame(conic, cs, sn, conf);
    float v_cov2[3] = {0.f, 0.f, 0.f};
    sp_gm_inverse2_vjp(conf, v_conic, v_cov2);
    if (cfg->antialiased) {
        *v_opacity_logit += v_opacity * comp * sig * (1.f - sig);
        sp_gm_add_blur_vjp(cfg->eps2d, conf, comp, v_opacity * sig, v_cov2);
    } else {
        *v_opacity_logit += v_opacity * sig * (1.f - sig);
    }
    /* mean2d = (fx x/z + cx, fy y/z + cy), depth = z */
    float rz = 1.f / pc[2], rz2 = rz * rz;
    float v_pc[3] = {cam->fx * rz * v_mean2d[0], cam->fy * rz * v_mean2d[1],
                     v_depth - (cam->fx * pc[0] * v_mean2d[0] + cam->fy * pc[1] * v_mean2d[1]) * rz2};
    sp_gm_cov2d_vjp(quat, log_scale, pc, cam, v_cov2, cs, sn, v_pc, v_quat, v_log_scale);
    /* pc = Rc mean + t */
    for (int j = 0; j < 3; j++)
        v_mean[j] += cam->R[j] * v_pc[0] + cam->R[3 + j] * v_pc[1] + cam->R[6 + j] * v_pc[2];
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

/* min over dy in [lo, hi] of q = (a X^2 + 2 b X dy + c dy^2) / 2, compared with thr without a
 * division: 1 when q can be <= thr on the edge dx = X (c > 0). Also used with the axes swapped. */
SP_HD static inline int sp_gm_edge_hit(float a, float b, float c, float det, float X, float lo,
                                       float hi, float thr)
{
    float mbx = -SP_FMUL(b, X); /* c dy* = -b X */
    if (mbx >= SP_FMUL(c, lo) && mbx <= SP_FMUL(c, hi)) /* minimiser on the edge: X^2 det / 2c */
        return SP_FMUL(SP_FMUL(0.5f * det, X), X) <= SP_FMUL(thr, c);
    float y = mbx < SP_FMUL(c, lo) ? lo : hi;
    float q = SP_FADD(SP_FADD(SP_FMUL(SP_FMUL(0.5f * a, X), X), SP_FMUL(SP_FMUL(b, X), y)),
                      SP_FMUL(SP_FMUL(0.5f * c, y), y));
    return q <= thr;
}

/* Exact tile culling (StopThePop / Speedy-Splat style): whether sigma <= cut (sp_gm_sigma_cut)
 * can hold at any pixel centre of the inclusive pixel rectangle [x0, x1] x [y0, y1] for a
 * Gaussian at (mx, my) with conic con. A lower bound of sigma over the continuous rectangle of
 * centres (zero when the mean is inside; else the minimum over the four edges, each a 1D
 * quadratic) against cut plus a margin far above float rounding of the per-pixel sigma (1e-5 of
 * its largest term over the rectangle, and 1e-3 px times its largest slope for the rounding of
 * dx and dy), so a tile it rejects has no pixel that sp_gm_alpha_g keeps: dropping it changes
 * no image and no gradient. Explicitly rounded operations only (no contraction, no fast-math
 * division), so every backend and kernel that calls it gets the same answer. */
SP_HD static inline int sp_gm_tile_hit(const float con[3], float cut, float mx, float my, int x0,
                                       int x1, int y0, int y1)
{
    float lx = SP_FSUB((float)x0 + 0.5f, mx), hx = SP_FSUB((float)x1 + 0.5f, mx);
    float ly = SP_FSUB((float)y0 + 0.5f, my), hy = SP_FSUB((float)y1 + 0.5f, my);
    if (lx <= 0.f && hx >= 0.f && ly <= 0.f && hy >= 0.f) return 1;
    float a = con[0], b = con[1], c = con[2], ab = fabsf(b);
    if (!(a > 0.f && c > 0.f)) return 1;
    float Mx = fmaxf(fabsf(lx), fabsf(hx)), My = fmaxf(fabsf(ly), fabsf(hy));
    float big = SP_FADD(SP_FADD(SP_FMUL(SP_FMUL(0.5f * a, Mx), Mx), SP_FMUL(SP_FMUL(ab, Mx), My)),
                        SP_FMUL(SP_FMUL(0.5f * c, My), My));
    float slope = SP_FADD(SP_FADD(SP_FMUL(a, Mx), SP_FMUL(ab, SP_FADD(Mx, My))), SP_FMUL(c, My));
    float thr = SP_FADD(SP_FADD(cut, SP_FMUL(1e-5f, big)), SP_FMUL(1e-3f, slope));
    float det = fmaxf(0.f, SP_FSUB(SP_FMUL(a, c), SP_FMUL(b, b)));
    /* vertical edges dx = lx, hx (dy free), horizontal ones dy = ly, hy (dx free, a <-> c) */
    return sp_gm_edge_hit(a, b, c, det, lx, ly, hy, thr) ||
           sp_gm_edge_hit(a, b, c, det, hx, ly, hy, thr) ||
           sp_gm_edge_hit(c, b, a, det, ly, lx, hx, thr) ||
           sp_gm_edge_hit(c, b, a, det, hy, lx, hx, thr);
}

/* alpha of a Gaussian at offset (dx, dy) = pixel centre - mean2d (dx = (px + 0.5) - mean x, one
 * rounding): min(SP_ALPHA_MAX, opacity exp(-sigma)); returns 0 when the contribution is skipped
 * (sigma < 0 from rounding, sigma beyond sigma_cut, or alpha < SP_ALPHA_MIN) and sets
 * *g = exp(-sigma) otherwise. This is THE rule: the CUDA kernels call it, the CPU's cpu_alpha4
 * is the same operations four lanes wide, so both backends keep and skip the same contributions
 * bit for bit. */
/* The rule from a row's terms (sp_gm_row_terms at the pixel's dy), for kernels that share
 * them between pixels of one row; sp_gm_alpha_g is this after sp_gm_row_terms. */
SP_HD static inline float sp_gm_alpha_row(float half_a, float by, float hy, float opacity,
                                          float sigma_cut, float dx, float *g)
{
    float sigma = sp_gm_sigma(half_a, by, hy, dx);
    if (sigma < 0.f || sigma > sigma_cut) return 0.f;
    *g = sp_gm_expf(-sigma);
    float a = SP_FMUL(opacity, *g);
    a = a < SP_ALPHA_MAX ? a : SP_ALPHA_MAX;
    return a < SP_ALPHA_MIN ? 0.f : a;
}
SP_HD static inline float sp_gm_alpha_g(const float conic[3], float opacity, float sigma_cut,
                                        float dx, float dy, float *g)
{
    float by, hy;
    sp_gm_row_terms(conic, dy, &by, &hy);
    return sp_gm_alpha_row(0.5f * conic[0], by, hy, opacity, sigma_cut, dx, g);
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
