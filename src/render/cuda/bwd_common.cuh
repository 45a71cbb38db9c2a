/* CUDA backend, stage 4: what the two backward compositing kernels share (rasterize_bwd.cu's
 * reduce-scatter kernel and rasterize_bwd_mm.cu's shared-memory product kernel): the warp
 * reduce-scatter and one pixel's geometry gradients. */
#ifndef SP_RENDER_CUDA_BWD_COMMON_CUH
#define SP_RENDER_CUDA_BWD_COMMON_CUH
#include "common.cuh"

#define BLOCK (SP_TILE_SIZE * SP_TILE_SIZE)
#define FULL_MASK 0xffffffffu

/* Warp reduce-scatter of N values per lane. Each of the five xor-shuffle rounds either halves
 * the values a lane carries (lanes with the round's bit set keep the upper ceil-half, the others
 * the lower; an odd count is padded with an exact zero) or, once one value is left, adds it
 * across the round's partner. Afterwards a lane holds RS_LIVE(N) totals in v[0..), for channels
 * base + i (returned base); lanes that differ only in the bits of the plain-add rounds hold the
 * same totals (one of each group of RS_GROUP(N) writes). Slots that only ever held padding are
 * exactly zero and the caller skips zeros, so they never write. About N shuffles, against 5 N
 * for a full butterfly per value. */
__host__ __device__ constexpr int rs_live(int n, int steps)
{
    return steps == 0 ? n : rs_live(n >= 2 ? (n + 1) / 2 : n, steps - 1);
}
__host__ __device__ constexpr int rs_halvings(int n, int steps)
{
    return (steps == 0 || n < 2) ? 0 : 1 + rs_halvings((n + 1) / 2, steps - 1);
}
#define RS_LIVE(N) rs_live((N), 5)
#define RS_GROUP(N) (32 >> rs_halvings((N), 5))

template <int N>
__device__ __forceinline__ int warp_reduce_scatter(float (&v)[N], int lane)
{
    int base = 0;
    int live = N;
#pragma unroll
    for (int o = 16; o >= 1; o >>= 1) {
        if (live >= 2) {
            const int half = (live + 1) / 2;
            const bool upper = (lane & o) != 0;
#pragma unroll
            for (int i = 0; i < N; i++) {
                if (i < half) {
                    const float hi = (i + half < live) ? v[i + half] : 0.f;
                    const float send = upper ? v[i] : hi;
                    const float keep = upper ? hi : v[i];
                    v[i] = keep + __shfl_xor_sync(FULL_MASK, send, o);
                }
            }
            if (upper) base += half;
            live = half;
        } else {
            v[0] += __shfl_xor_sync(FULL_MASK, v[0], o);
        }
    }
    return base;
}

/* One pixel's gradients of a Gaussian's 2D mean, conic (in the conic's frame, gauss_math.h) and
 * opacity, given dL/dalpha at the pixel; geo[0..5] (geo[6], depth, is the caller's). Zero where
 * alpha was clamped to SP_ALPHA_MAX (no gradient flows through the clamp). */
__device__ __forceinline__ void sp_cu_bwd_geo(float4 co, float2 fr, float vis, float v_alpha,
                                              float dx, float dy, float geo[7])
{
    if (co.w * vis > SP_ALPHA_MAX) return;
    const float v_sigma = -co.w * vis * v_alpha;
    geo[0] = -v_sigma * (co.x * dx + co.y * dy);
    geo[1] = -v_sigma * (co.y * dx + co.z * dy);
    const float d0 = fr.x * dx + fr.y * dy, d1 = fr.x * dy - fr.y * dx;
    geo[2] = 0.5f * v_sigma * d0 * d0;
    geo[3] = 0.5f * v_sigma * d0 * d1;
    geo[4] = 0.5f * v_sigma * d1 * d1;
    geo[5] = vis * v_alpha;
}

/* dL/dalpha of a kept Gaussian at a pixel, from p = colour . v_out and the terms carried from
 * the Gaussians behind it (G: colour, Gd: depth), which it then extends by this one; with aux
 * also the depth (*z, read only then) and alpha terms, and geo[6] (dL/d depth). ra = 1 / (1 - alpha),
 * fac = alpha T. */
__device__ __forceinline__ float sp_cu_bwd_alpha_grad(float p, float T, float ra, float fac, bool aux,
                                                      const float *z, float vd, float va, float Tf,
                                                      float *G, float *Gd, float geo[7])
{
    float v_alpha = p * T - *G * ra;
    *G += p * fac;
    if (aux) {
        v_alpha += (*z * T - *Gd * ra) * vd + Tf * ra * va;
        *Gd += *z * fac;
        geo[6] = fac * vd;
    }
    return v_alpha;
}

/* rasterize_bwd_mm.cu: the shared-memory product kernel for chunks of 32 channels and more */
bool sp_cuda_bwd_mm_fits(int ch);
int sp_cuda_bwd_mm(int ch, const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                   float *vgeo, int c_base, int n_chunks, int aux, sp_error *err);

#endif
