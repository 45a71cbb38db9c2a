/* CUDA backend, stage 4: what the backward compositing kernels share (rasterize_bwd.cu's
 * reduce-scatter kernel, rasterize_bwd_mm.cu's shared-memory product kernel and
 * rasterize_bwd_tc.cu's tensor-core one): the warp reduce-scatter, one pixel's geometry
 * gradients, and the product kernels' stages and walk. */
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

/* geo[k] = v, or with ADD geo[k] += v (a kernel summing two pixels' gradients in registers; the
 * multiply before it then fuses into the add). */
template <bool ADD>
__device__ __forceinline__ void sp_cu_put(float &dst, float v)
{
    dst = ADD ? dst + v : v;
}

/* One pixel's gradients of a Gaussian's 2D mean, conic (in the conic's frame, gauss_math.h) and
 * opacity, given dL/dalpha at the pixel; geo[0..5] (geo[6], depth, is the caller's), set, or
 * with ADD added. None where alpha was clamped to SP_ALPHA_MAX (no gradient flows through the
 * clamp). */
template <bool ADD = false>
__device__ __forceinline__ void sp_cu_bwd_geo(float4 co, float2 fr, float vis, float v_alpha,
                                              float dx, float dy, float geo[7])
{
    if (co.w * vis > SP_ALPHA_MAX) return;
    const float v_sigma = -co.w * vis * v_alpha;
    sp_cu_put<ADD>(geo[0], -v_sigma * (co.x * dx + co.y * dy));
    sp_cu_put<ADD>(geo[1], -v_sigma * (co.y * dx + co.z * dy));
    const float d0 = fr.x * dx + fr.y * dy, d1 = fr.x * dy - fr.y * dx;
    sp_cu_put<ADD>(geo[2], 0.5f * v_sigma * d0 * d0);
    sp_cu_put<ADD>(geo[3], 0.5f * v_sigma * d0 * d1);
    sp_cu_put<ADD>(geo[4], 0.5f * v_sigma * d1 * d1);
    sp_cu_put<ADD>(geo[5], vis * v_alpha);
}

/* dL/dalpha of a kept Gaussian at a pixel, from p = colour . v_out and the terms carried from
 * the Gaussians behind it (G: colour, Gd: depth), which it then extends by this one; with aux
 * also the depth (*z, read only then) and alpha terms, and geo[6] (dL/d depth; set, or with ADD
 * added). ra = 1 / (1 - alpha), fac = alpha T. */
template <bool ADD = false>
__device__ __forceinline__ float sp_cu_bwd_alpha_grad(float p, float T, float ra, float fac, bool aux,
                                                      const float *z, float vd, float va, float Tf,
                                                      float *G, float *Gd, float geo[7])
{
    float v_alpha = p * T - *G * ra;
    *G += p * fac;
    if (aux) {
        v_alpha += (*z * T - *Gd * ra) * vd + Tf * ra * va;
        *Gd += *z * fac;
        sp_cu_put<ADD>(geo[6], fac * vd);
    }
    return v_alpha;
}

/* ---- stages: what the product (rasterize_bwd_mm.cu) and tensor-core (rasterize_bwd_tc.cu)
 * kernels share. Both walk a tile's list in stages of NB Gaussians, store every pixel's blending
 * weight fac = alpha T for the stage in shared memory, and form the colour gradients as a product
 * over the tile's pixels after the walk. */
#define NB 32               /* Gaussians per stage, and per product */
#define NWARPS (BLOCK / 32) /* 8 */

/* One stage's inputs as a thread loads them: Gaussian `tid` of the stage (tid < NB), and the
 * colour values tid, tid + BLOCK, .. of the stage's [NB][CH] block (zero past the list or D). */
template <int CPT>
struct stage_regs {
    int g;
    float2 xy;
    float4 co;
    float z;
    float col[CPT];
};

template <int CH, int CPT>
__device__ __forceinline__ void stage_load(stage_regs<CPT> *s, const uint32_t *__restrict__ ids,
                                           const float2 *__restrict__ means2d,
                                           const float4 *__restrict__ conic_op,
                                           const float *__restrict__ depths,
                                           const float *__restrict__ colors, int D, int c0,
                                           int b_end, int cnt, int tid)
{
    if (tid < cnt) {
        s->g = (int)ids[b_end - 1 - tid];
        s->xy = means2d[s->g];
        s->co = conic_op[s->g];
        s->z = depths[s->g];
    }
#pragma unroll
    for (int i = 0; i < CPT; i++) {
        const int k = tid + i * BLOCK, j = k / CH, c = k - j * CH;
        s->col[i] = (j < cnt && c0 + c < D) ? colors[(size_t)ids[b_end - 1 - j] * D + c0 + c] : 0.f;
    }
}

/* A stage in shared memory: per Gaussian t < NB its geometry, id and flag (byte w = warp w kept
 * it), and its colours at col + t * LDC (stage_store's). */
struct stage_smem {
    float4 *conic;
    unsigned long long *flag;
    float *col;
    float2 *xy, *frame; /* frame: the conic's principal frame (cs, sn) */
    float *z, *cut;
    int *id;
};

/* Stores a stage that stage_load brought into registers. */
template <int CH, int LDC, int CPT>
__device__ __forceinline__ void stage_store(const stage_smem &s, const stage_regs<CPT> &nx, int cnt,
                                            int tid)
{
    if (tid < cnt) {
        s.id[tid] = nx.g;
        s.xy[tid] = nx.xy;
        s.conic[tid] = nx.co;
        s.cut[tid] = sp_cu_sigma_cut(nx.co.w);
        const float con[3] = {nx.co.x, nx.co.y, nx.co.z};
        float fcs, fsn;
        sp_gm_conic_frame(con, &fcs, &fsn);
        s.frame[tid] = make_float2(fcs, fsn);
        s.z[tid] = nx.z;
    }
#pragma unroll
    for (int i = 0; i < CPT; i++) {
        const int k = tid + i * BLOCK;
        if (k < NB * CH) s.col[LDC == CH ? k : (k / CH) * LDC + k % CH] = nx.col[i];
    }
}

/* The tile's v_image chunk into shared memory, read coalesced (BOX: slots in warp boxes): pixel p's channel c at
 * s_vout[p * LDV + c] for c < CHP (zero for c >= CH, past D and outside the image). */
template <int CH, int CHP, int LDV, bool BOX = false>
__device__ __forceinline__ void load_vout(float *s_vout, const float *__restrict__ v_image, int W,
                                          int H, int D, int c0, int bx, int by, int tid)
{
    for (int k = tid; k < BLOCK * CHP; k += BLOCK) {
        const int p = k / CHP, c = k - p * CHP;
        const int x = bx + (BOX ? sp_cu_box_x(p) : p % SP_TILE_SIZE);
        const int y = by + (BOX ? sp_cu_box_y(p) : p / SP_TILE_SIZE);
        s_vout[LDV == CHP ? k : p * LDV + c] = ((CHP == CH || c < CH) && x < W && y < H && c0 + c < D)
                                  ? v_image[((size_t)y * W + x) * D + c0 + c]
                                  : 0.f;
    }
}

/* What a pixel carries through the walk. */
struct walk_px {
    float px, py;  /* pixel centre */
    bool inside;   /* in the image */
    bool aux;      /* this chunk adds the depth and alpha terms */
    int last;      /* the pixel's last Gaussian (exclusive) */
    int warp_last; /* the warp's */
    float Tf, vd, va;
    float T, G, Gd; /* transmittance and the carried colour / depth terms */
};

/* One stage's walk at this thread's pixel, back to front, over the Gaussians t whose bit is set
 * in bits (warp-uniform; bit t clear where t >= the stage's count or the warp's band cannot keep
 * t: sp_cu_band_bits) and that lie before the warp's last (idx < warp_last): alpha,
 * transmittance, dL/dalpha (its colour term p = colour_t . v_out from dot(t)) and the geometry
 * sums (warp reduce-scatter, one atomic per value and warp). Only those Gaussians are visited
 * (set-bit order is back-to-front order), so a Gaussian the warp cannot keep costs it nothing
 * but its zero: fac of every t (0 where not kept) ends up in fac_out[t * ldf + tid] and the
 * warp's flag byte (did any of its pixels keep t) in s.flag[t]. ZERO_ALL: the 32 fac slots are
 * zeroed up front, unrolled (cheapest when nothing else lives there); otherwise only the slots
 * not visited are zeroed, after the walk (the tensor-core kernel keeps its scores there until
 * the walk reads them). dot(t) is called only where the pixel keeps t, before
 * fac_out[t * ldf + tid] is written (so it may read that slot). */
template <bool ZERO_ALL, class Dot>
__device__ __forceinline__ void stage_walk(const stage_smem &s, walk_px &q, int b_end, unsigned bits,
                                           float *fac_out, int ldf, Dot dot,
                                           float *__restrict__ vgeo, int tid)
{
    const int lane = tid & 31, warp = tid >> 5;
    /* idx = b_end - 1 - t < warp_last  <=>  t >= b_end - warp_last */
    const int t_lo = b_end - q.warp_last;
    const unsigned live = t_lo <= 0 ? ~0u : (t_lo >= NB ? 0u : ~0u << t_lo);
    const unsigned walk = bits & live;
    if (ZERO_ALL) {
#pragma unroll
        for (int t = 0; t < NB; t++) fac_out[t * ldf + tid] = 0.f;
    }
    unsigned kept_bits = 0;
    for (unsigned rest = walk; rest; rest &= rest - 1) { /* warp-uniform */
        const int t = __ffs(rest) - 1;
        float fac = 0.f, geo[7];
        bool valid = false;
#pragma unroll
        for (int k = 0; k < 7; k++) geo[k] = 0.f;
        const float4 co = s.conic[t];
        const float2 xy = s.xy[t];
        const float dx = q.px - xy.x, dy = q.py - xy.y;
        float vis = 0.f, alpha = 0.f;
        if (q.inside && b_end - 1 - t < q.last) alpha = sp_cu_alpha(co, s.cut[t], dx, dy, &vis);
        valid = alpha > 0.f;
        if (valid) {
            /* IEEE 1/x, as the CPU's division (see rasterize_bwd.cu) */
            const float ra = __frcp_rn(1.f - alpha);
            q.T *= ra;
            fac = alpha * q.T;
            const float p = dot(t);
            const float v_alpha = sp_cu_bwd_alpha_grad(p, q.T, ra, fac, q.aux, s.z + t, q.vd, q.va,
                                                       q.Tf, &q.G, &q.Gd, geo);
            sp_cu_bwd_geo(co, s.frame[t], vis, v_alpha, dx, dy, geo);
        }
        if (ZERO_ALL) {
            if (valid) fac_out[t * ldf + tid] = fac;
        } else {
            fac_out[t * ldf + tid] = fac;
        }
        const unsigned kept = __ballot_sync(FULL_MASK, valid);
        if (!kept) continue;
        kept_bits |= 1u << t;
        const int slot = warp_reduce_scatter<7>(geo, lane);
        if (lane % RS_GROUP(7) == 0 && slot < 7 && geo[0] != 0.f)
            atomicAdd(vgeo + (size_t)s.id[t] * SP_VGEO_STRIDE + slot, geo[0]);
    }
    if (!ZERO_ALL)
        for (unsigned rest = ~walk; rest; rest &= rest - 1) fac_out[(__ffs(rest) - 1) * ldf + tid] = 0.f;
    /* lane t: this warp's byte of Gaussian t's flag */
    ((unsigned char *)(s.flag + lane))[warp] = (kept_bits >> lane) & 1u;
}

/* stage_walk (ZERO_ALL, with MASKS false) two Gaussians at a time: the pair's alphas are
 * computed first, branch-free (sp_cu_alpha_flat), so their exps interleave, then the pixel's
 * recursion runs through both in order, and one reduce-scatter of 14 values (two per lane
 * fewer rounds than two of 7) carries both Gaussians' geometry sums. The same values, order
 * and atomics as stage_walk, up to which lane adds which sum. */
template <class Dot>
__device__ __forceinline__ void stage_walk_pairs(const stage_smem &s, walk_px &q, int b_end,
                                                 unsigned bits, float *fac_out, int ldf, Dot dot,
                                                 float *__restrict__ vgeo, int tid)
{
    const int lane = tid & 31, warp = tid >> 5;
    const int t_lo = b_end - q.warp_last;
    const unsigned live = t_lo <= 0 ? ~0u : (t_lo >= NB ? 0u : ~0u << t_lo);
#pragma unroll
    for (int t = 0; t < NB; t++) fac_out[t * ldf + tid] = 0.f;
    unsigned kept_bits = 0;
    for (unsigned rest = bits & live; rest;) { /* warp-uniform */
        const int ta = __ffs(rest) - 1;
        rest &= rest - 1;
        const bool two = rest != 0;
        const int tb = two ? __ffs(rest) - 1 : ta;
        rest &= rest - 1;
        float4 co[2] = {s.conic[ta], s.conic[tb]};
        const float2 xa = s.xy[ta], xb = s.xy[tb];
        const float dx[2] = {q.px - xa.x, q.px - xb.x}, dy[2] = {q.py - xa.y, q.py - xb.y};
        float vis[2], alpha[2];
        alpha[0] = sp_cu_alpha_flat(co[0], s.cut[ta], dx[0], dy[0], &vis[0]);
        alpha[1] = sp_cu_alpha_flat(co[1], s.cut[tb], dx[1], dy[1], &vis[1]);
        if (!(q.inside && b_end - 1 - ta < q.last)) alpha[0] = 0.f;
        if (!(two && q.inside && b_end - 1 - tb < q.last)) alpha[1] = 0.f;
        float geo[14];
#pragma unroll
        for (int k = 0; k < 14; k++) geo[k] = 0.f;
#pragma unroll
        for (int h = 0; h < 2; h++) {
            const int t = h ? tb : ta;
            if (alpha[h] > 0.f) {
                const float ra = __frcp_rn(1.f - alpha[h]);
                q.T *= ra;
                const float fac = alpha[h] * q.T;
                const float p = dot(t);
                const float v_alpha = sp_cu_bwd_alpha_grad(p, q.T, ra, fac, q.aux, s.z + t, q.vd,
                                                           q.va, q.Tf, &q.G, &q.Gd, geo + 7 * h);
                sp_cu_bwd_geo(co[h], s.frame[t], vis[h], v_alpha, dx[h], dy[h], geo + 7 * h);
                fac_out[t * ldf + tid] = fac;
            }
        }
        const unsigned ka = __ballot_sync(FULL_MASK, alpha[0] > 0.f);
        const unsigned kb = __ballot_sync(FULL_MASK, alpha[1] > 0.f);
        if (ka) kept_bits |= 1u << ta;
        if (kb) kept_bits |= 1u << tb;
        if (!(ka | kb)) continue;
        const int slot = warp_reduce_scatter<14>(geo, lane);
        if (lane % RS_GROUP(14) == 0 && slot < 14 && geo[0] != 0.f)
            atomicAdd(vgeo + (size_t)s.id[slot < 7 ? ta : tb] * SP_VGEO_STRIDE + (slot < 7 ? slot : slot - 7),
                      geo[0]);
    }
    ((unsigned char *)(s.flag + lane))[warp] = (kept_bits >> lane) & 1u;
}

/* rasterize_bwd_mm.cu: the shared-memory product kernel for chunks of 32 channels and more */
bool sp_cuda_bwd_mm_fits(int ch);
int sp_cuda_bwd_mm(int ch, const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                   float *vgeo, int c_base, int n_chunks, int aux, sp_error *err);
/* rasterize_bwd_tc.cu: the same with both D-wide sums on tensor cores (cfg.bwd_gather = 2) */
bool sp_cuda_bwd_tc_fits(int ch);
int sp_cuda_bwd_tc(int ch, const sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                   float *vgeo, int c_base, int n_chunks, int aux, sp_error *err);

#endif
