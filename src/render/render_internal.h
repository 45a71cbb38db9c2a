/* Private to src/render: the CPU rasterizer's per-view state and the CPU pipeline stages (one per
 * file: project.c, tiles.c, rasterize_fwd.c, rasterize_bwd.c, rasterize_surface.c, sh.c), which
 * cpu_backend.c puts behind the render backend table (backend.h). */
#ifndef SP_RENDER_INTERNAL_H
#define SP_RENDER_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "device/device_impl.h"
#include "semsplat/render.h"

/* Grows a host scratch buffer to at least `bytes` (contents not kept), accounting the change
 * to dev. Returns 0 or SP_E_NOMEM. */
int sp_scratch_reserve(sp_device *dev, void **buf, size_t *cap, size_t bytes, sp_error *err);
void sp_scratch_release(sp_device *dev, void **buf, size_t *cap);

/* Per-thread scratch for one tile. */
typedef struct cpu_tile_scratch {
    void *buf;
    size_t cap;
} cpu_tile_scratch;

/* What compositing needs of one Gaussian, one cache line, copied into every tile list it is in so
 * the compositing loops stream through memory instead of gathering from seven arrays. */
typedef struct cpu_gauss {
    float mx, my;          /* 2D mean, pixels */
    float con[3];          /* conic (a, b, c) */
    float op;              /* effective opacity */
    float z;               /* camera depth */
    float det_con;         /* det(conic), accurate */
    float cut;             /* sp_gm_sigma_cut(op) */
    int32_t g;             /* Gaussian index */
    int32_t box[4];        /* pixel box x0, x1, y0, y1 */
    float pad[2];
} cpu_gauss;

/* The CPU rasterizer's state for one view: projections, tile lists, per-pixel results. */
typedef struct cpu_raster {
    sp_device *dev;
    sp_camera cam;
    sp_raster_cfg cfg;
    sp_raster_in in;     /* the caller's buffers (kept for backward; background copied below) */
    float *background;   /* [D] */
    size_t bg_cap;
    int W, H, D;
    size_t n;
    int valid; /* a forward ran and backward may use it */

    /* projection, [n] each (radius 0 = culled) */
    float *mean2d;   /* [n][2] pixels */
    float *conic;    /* [n][3] (a, b, c) of the inverse blurred 2D covariance */
    float *depth;    /* [n] camera z */
    float *opacity;  /* [n] effective opacity (sigmoid, times compensation if antialiased) */
    float *conic_det; /* [n] det(conic) = 1 / det(blurred 2D covariance), computed without
                       * cancellation (for the per-row pixel ranges) */
    int32_t *radii;  /* [n] */
    int32_t *pix_box; /* [n][4] inclusive pixel range x0, x1, y0, y1 touched (culled: empty) */
    size_t proj_cap;
    void *proj_buf;

    /* tile binning */
    int tiles_x, tiles_y;
    uint32_t *tile_start; /* [tiles + 1] offsets into tile_gauss / tile_slot */
    cpu_gauss *tile_rec;  /* [pairs] Gaussians front to back within each tile */
    uint32_t *tile_slot;  /* [pairs] backward slot: Gaussian g's pairs are contiguous */
    size_t *pair_off;     /* [n + 1] first slot of each Gaussian */
    size_t pairs;
    void *tile_buf;
    size_t tile_cap;
    void *sort_buf; /* depth-sort scratch */
    size_t sort_cap;

    /* per-pixel forward results kept for backward */
    float *final_T;     /* [H][W] */
    int32_t *n_contrib; /* [H][W] index (within the tile list) + 1 of the last contributor */
    void *pix_buf;
    size_t pix_cap;

    /* backward: per-pair gradient slots [pairs][SLOT_FIXED + D] */
    float *slots; /* = slot_buf */
    void *slot_buf;
    size_t slot_cap;

    cpu_tile_scratch *scratch; /* [pool size] */
    int n_scratch;
} cpu_raster;

/* Slot layout: v_mean2d x, y; v_conic (element convention, in the conic's principal frame:
 * sp_gm_conic_frame) 00, 01, 11; v_opacity; v_depth; then D colour gradients. */
#define SP_SLOT_FIXED 7

/* Pixel bounds (inclusive) of a tile, clipped to the image; and the part of a Gaussian's pixel
 * box inside it (empty when x0 > x1 or y0 > y1). Shared by the compositing passes. */
typedef struct cpu_rect {
    int x0, x1, y0, y1;
} cpu_rect;

static inline cpu_rect cpu_tile_rect(const cpu_raster *r, long tile)
{
    cpu_rect t;
    t.x0 = (int)(tile % r->tiles_x) * SP_TILE_SIZE;
    t.y0 = (int)(tile / r->tiles_x) * SP_TILE_SIZE;
    t.x1 = t.x0 + SP_TILE_SIZE - 1 < r->W - 1 ? t.x0 + SP_TILE_SIZE - 1 : r->W - 1;
    t.y1 = t.y0 + SP_TILE_SIZE - 1 < r->H - 1 ? t.y0 + SP_TILE_SIZE - 1 : r->H - 1;
    return t;
}

static inline cpu_rect cpu_box_in_tile(const cpu_gauss *rec, cpu_rect t)
{
    const int32_t *b = rec->box;
    cpu_rect o = {b[0] > t.x0 ? b[0] : t.x0, b[1] < t.x1 ? b[1] : t.x1,
                  b[2] > t.y0 ? b[2] : t.y0, b[3] < t.y1 ? b[3] : t.y1};
    return o;
}

/* project.c */
int cpu_project(cpu_raster *r, sp_error *err);
void cpu_project_backward(cpu_raster *r, const sp_raster_grads *grads);

/* tiles.c: depth sort and per-tile lists, needs the projection. */
int cpu_bin_tiles(cpu_raster *r, sp_error *err);

/* Pixel range [*lo, *hi] of row py where sigma <= cut can hold for Gaussian g (clipped to
 * [x0, x1]; empty when *lo > *hi): the roots of the quadratic in dx, widened by one pixel so
 * float error never drops a pixel. Only skips work: the alpha test decides every kept pixel. */
static inline void cpu_row_range(const float con[3], float det_con, float cut, float mx, float dy,
                                 int x0, int x1, int *lo, int *hi)
{
    float disc = 2.f * con[0] * cut - det_con * dy * dy;
    if (disc < 0.f) {
        *lo = x0, *hi = x0 - 1;
        return;
    }
    float sq = sqrtf(disc), inv_a = 1.f / con[0], c = -con[1] * dy;
    float flo = mx - 0.5f + (c - sq) * inv_a, fhi = mx - 0.5f + (c + sq) * inv_a;
    /* clamp in float first (the roots can be huge), then truncate with a 2-pixel margin, which
     * covers floor/ceil (truncation is within 1 of either) plus the 1-pixel safety margin */
    flo = flo > (float)x0 ? (flo < (float)x1 + 1.f ? flo : (float)x1 + 1.f) : (float)x0;
    fhi = fhi < (float)x1 ? (fhi > (float)x0 - 1.f ? fhi : (float)x0 - 1.f) : (float)x1;
    int l = (int)flo - 2, h = (int)fhi + 2;
    *lo = l > x0 ? l : x0;
    *hi = h < x1 ? h : x1;
}

/* Four pixels of one row at once (GCC vector extensions: SSE2 on x86-64, NEON on arm64). */
typedef float cpu_v4f __attribute__((vector_size(16)));
typedef int32_t cpu_v4i __attribute__((vector_size(16)));

static inline cpu_v4f cpu_v4_splat(float x) { return (cpu_v4f){x, x, x, x}; }

static inline cpu_v4f cpu_v4_select(cpu_v4i mask, cpu_v4f a, cpu_v4f b)
{
    return (cpu_v4f)(((cpu_v4i)a & mask) | ((cpu_v4i)b & ~mask));
}

/* Unaligned four-lane loads and stores of tile state. */
static inline cpu_v4f load4(const float *p)
{
    cpu_v4f v;
    memcpy(&v, p, sizeof v);
    return v;
}
static inline void store4(float *p, cpu_v4f v) { memcpy(p, &v, sizeof v); }
static inline cpu_v4i load4i(const int32_t *p)
{
    cpu_v4i v;
    memcpy(&v, p, sizeof v);
    return v;
}
static inline void store4i(int32_t *p, cpu_v4i v) { memcpy(p, &v, sizeof v); }

/* Per-pixel tile state is laid out channel-major ([c][TILE_STRIDE]) so that four neighbouring
 * pixels of a row are one vector; the stride leaves room for the lanes past a row's end. */
#define TILE_PIX (SP_TILE_SIZE * SP_TILE_SIZE)
#define TILE_STRIDE (TILE_PIX + 4)

/* e^x for x in [-80, 0] per lane: sp_gm_expf (gauss_math.h) four lanes wide, the same operations
 * in the same order, so the same bits (tests/render/test_exact_alpha checks); branch-free. */
static inline cpu_v4f cpu_exp_neg4(cpu_v4f x)
{
    const cpu_v4f magic = cpu_v4_splat(12582912.f);
    cpu_v4f n = (x * cpu_v4_splat(1.44269504088896341f) + magic) - magic;
    cpu_v4f r = x - n * cpu_v4_splat(0.693359375f);
    r = r - n * cpu_v4_splat(-2.12194440e-4f);
    cpu_v4f p = cpu_v4_splat(1.9875691500e-4f);
    p = p * r + cpu_v4_splat(1.3981999507e-3f);
    p = p * r + cpu_v4_splat(8.3334519073e-3f);
    p = p * r + cpu_v4_splat(4.1665795894e-2f);
    p = p * r + cpu_v4_splat(1.6666665459e-1f);
    p = p * r + cpu_v4_splat(5.0000001201e-1f);
    p = p * (r * r) + r + cpu_v4_splat(1.f);
    cpu_v4i e = (__builtin_convertvector(n, cpu_v4i) + 127) << 23;
    return p * (cpu_v4f)e;
}

/* dx of the four pixel centres px .. px + 3 of a row from mean x: centres first (exact), then one
 * rounding, as sp_gm_alpha_g computes it on the GPU. */
static inline cpu_v4f cpu_dx4(int px, float mx)
{
    const cpu_v4f lanef = {0.f, 1.f, 2.f, 3.f};
    return (cpu_v4_splat((float)px + 0.5f) + lanef) - cpu_v4_splat(mx);
}

/* The CPU backend's alpha rule for four pixels of a row (sp_gm_alpha_g's operations, bit for
 * bit): dx = pixel centres - mean x; per-row constants half_a = a / 2, by = b dy,
 * hy = c dy^2 / 2 (all arguments broadcast to the four lanes by the caller, out of the loops), so
 * sigma = (half_a dx + by) dx + hy. Forward and backward both call this, so
 * they make the same decisions and get the same bits. Returns alpha (0 = skipped) and
 * *g = exp(-sigma). */
static inline cpu_v4f cpu_alpha4(cpu_v4f half_a, cpu_v4f by, cpu_v4f hy, cpu_v4f op, cpu_v4f cut,
                                 cpu_v4f dx, cpu_v4f *g)
{
    cpu_v4f sigma = (half_a * dx + by) * dx + hy;
    cpu_v4i in = (sigma >= cpu_v4_splat(0.f)) & (sigma <= cut);
    /* out-of-range lanes: evaluate at sigma = 0 (harmless), then zero */
    cpu_v4f gv = cpu_exp_neg4(-cpu_v4_select(in, sigma, cpu_v4_splat(0.f)));
    cpu_v4f a = op * gv;
    a = cpu_v4_select(a < cpu_v4_splat(SP_ALPHA_MAX), a, cpu_v4_splat(SP_ALPHA_MAX));
    in &= a >= cpu_v4_splat(SP_ALPHA_MIN);
    *g = gv;
    return cpu_v4_select(in, a, cpu_v4_splat(0.f));
}

/* The set lanes of a mask as bits 0..3 (lane l: bit l). */
static inline unsigned cpu_v4_bits(cpu_v4i m)
{
#if defined(__SSE__)
    return (unsigned)__builtin_ia32_movmskps((cpu_v4f)m); /* one instruction on x86 */
#else
    return (m[0] ? 1u : 0u) | (m[1] ? 2u : 0u) | (m[2] ? 4u : 0u) | (m[3] ? 8u : 0u);
#endif
}

/* The mask whose lane l is set where bit l of bits is (cpu_v4_bits' inverse). */
static inline cpu_v4i cpu_v4_mask(unsigned bits)
{
    return (cpu_v4i){-(int32_t)(bits & 1u), -(int32_t)((bits >> 1) & 1u), -(int32_t)((bits >> 2) & 1u),
                     -(int32_t)((bits >> 3) & 1u)};
}

/* Number of set lanes of a mask (a table: baseline x86-64 has no popcount instruction, and
 * __builtin_popcount became a library call in the hot loops). */
static inline int cpu_v4_count(cpu_v4i m)
{
#if defined(__SSE__)
    static const unsigned char nbits[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
    return nbits[cpu_v4_bits(m)];
#else
    return -(m[0] + m[1] + m[2] + m[3]);
#endif
}

static inline int cpu_v4_any(cpu_v4i m)
{
#if defined(__SSE__)
    return __builtin_ia32_movmskps((cpu_v4f)m) != 0; /* one instruction on x86 */
#else
    return (m[0] | m[1] | m[2] | m[3]) != 0;
#endif
}

_Static_assert(sizeof(cpu_gauss) == 64, "cpu_gauss is one cache line");

/* rasterize_fwd.c / rasterize_bwd.c (thread scratch sized for both passes at r->D) */
int cpu_reserve_thread_scratch(cpu_raster *r, sp_error *err);
int cpu_rasterize_forward(cpu_raster *r, sp_raster_out *out, sp_error *err);
int cpu_rasterize_backward(cpu_raster *r, const sp_raster_grad_in *gin, sp_error *err);
/* rasterize_surface.c: first-surface depth of the last projection and binning (out [H][W]). */
int cpu_rasterize_surface(cpu_raster *r, float surface_alpha, float *out, sp_error *err);
/* sh.c: the CPU SH kernels for the backend table. */
int cpu_sh_to_rgb(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                  const float *means, sp_vec3 cam_center, float *rgb, int out_stride, sp_error *err);
int cpu_sh_to_rgb_backward(sp_device *dev, size_t n, int degree, int degree_active,
                           const float *sh, const float *means, sp_vec3 cam_center,
                           const float *rgb, const float *v_rgb, int stride, float *v_sh,
                           float *v_means, sp_error *err);

#endif
