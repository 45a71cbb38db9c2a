/* Internals shared by the CUDA render backend's stages (src/render/cuda/*.cu). Not a public header.
 *
 * Every launch and copy goes to the raster's device stream (device/cuda/device_cuda.h); memory
 * comes from the device (accounted per device). Scratch buffers are grow-only, so a training
 * loop allocates nothing after its first few steps. */
#ifndef SP_RENDER_CUDA_COMMON_CUH
#define SP_RENDER_CUDA_COMMON_CUH

#include <cuda_runtime.h>
#include <stdint.h>

#include "device/cuda/device_cuda.h"
#include "render/backend.h"
#include "render/gauss_math.h"

/* Projected Gaussians of one view, written by project.cu and read by every later stage. */
typedef struct sp_cuda_proj {
    float2 *means2d;   /* [n] pixels */
    float4 *conic_op;  /* [n] (conic a, b, c, opacity after sigmoid and AA compensation) */
    float *depths;     /* [n] camera z */
    int32_t *radii;    /* [n] 0 = culled */
    short4 *box;       /* [n] inclusive pixel box x0, y0, x1, y1 (images up to 32767 px) */
} sp_cuda_proj;

/* One view's pipeline state on the device: its camera, projection, sorted (tile, depth) pairs and
 * per-pixel results kept for the backward. */
typedef struct sp_cuda_view {
    sp_camera cam;
    int tiles_x, tiles_y;
    int box_tiles; /* sp_raster_cfg.box_tiles: bin into every box tile, no ellipse test */
    int warp_cull; /* sp_raster_cfg.warp_cull resolved: 1 on, 0 off (sp_cu_band_bits) */
    sp_cuda_proj proj;
    size_t n_pairs;
    const uint32_t *sorted_ids; /* [n_pairs] Gaussian index per sorted pair */
    const int2 *tile_ranges;    /* [tiles] [start, end) in the sorted list */
    float *t_final;             /* [H*W] */
    int32_t *last_idx;          /* [H*W] one past the last pair index used by the pixel */
} sp_cuda_view;

/* One compositing pass: colours [n][D] and where the pixels go. */
typedef struct sp_cuda_pass {
    const float *colors;
    int D;
    const float *bg_dev; /* [D] on the device, or NULL */
    float *image, *depth, *alpha;
} sp_cuda_pass;

/* Stage boundaries a profiled forward/backward records (sp_raster_last_stages). */
enum {
    SP_EV_START, SP_EV_PROJECTED, SP_EV_COUNTED, SP_EV_SORTED, SP_EV_FWD_DONE,
    SP_EV_BWD_START, SP_EV_BWD_RASTER, SP_EV_BWD_DONE, SP_EV_COUNT
};

/* The backend's state (defined here so the stage files share it). */
struct sp_cuda_raster {
    sp_device *dev;
    cudaStream_t stream;
    /* the last forward's arguments, kept for backward */
    sp_raster_cfg cfg;
    sp_raster_in in;
    int have_forward;
    float *bg_dev; /* [D] background on the device (inside s_bg) */
    sp_cuda_view view; /* the single-view path's */

    sp_device_scratch s_means2d, s_conic_op, s_depths, s_radii, s_box;
    /* pairs: tile keys (16 or 32 bits: sp_cuda_key_bytes) and Gaussian ids, double-buffered */
    sp_device_scratch s_keys[2], s_vals[2], s_tile_ranges, s_cub;
    sp_device_scratch s_tfinal, s_last, s_bg;
    /* sp_cuda_work_bytes(n): the binning's per-Gaussian temporaries (tiles.cu), then the
     * backward's per-Gaussian sums [n][SP_VGEO_STRIDE] (v_mean2d 2, v_conic 3 in the conic's
     * frame, v_opacity, v_depth): never live at once, so they share it */
    sp_device_scratch s_work;
    /* batches (sp_render_views): per-view pair counts, host copy of them */
    sp_device_scratch s_counts;
    /* batches: the views' compositing arguments and first tiles (rasterize_fwd.cu) */
    sp_device_scratch s_batch;
    /* cfg.profile: events recorded between the stages (SP_EV_*), made on first use */
    cudaEvent_t ev[SP_EV_COUNT];
    int ev_made, profiling, prof_fwd, prof_bwd;
    const char *bwd_kernel; /* the last backward's widest chunk's colour-sum kernel (a literal) */
    int fwd_px;             /* the last forward's pixels per thread in its widest chunk */
};
typedef struct sp_cuda_raster sp_cuda_raster;

/* Records stage boundary k on the stream when this forward is profiled. */
static inline void sp_cu_mark(sp_cuda_raster *r, int k)
{
    if (r->profiling) cudaEventRecord(r->ev[k], r->stream);
}
/* Makes the profiling events once (raster.cu). */
int sp_cuda_make_events(sp_cuda_raster *r, sp_error *err);

#define SP_VGEO_STRIDE 7

/* Bytes of s_work for n Gaussians: offsets (8) + depth order, counts, 3 sort temporaries (4 each)
 * = 28 = SP_VGEO_STRIDE floats. */
static inline size_t sp_cuda_work_bytes(size_t n) { return n * 28 + 256; }

static inline int sp_cu_reserve(sp_cuda_raster *r, sp_device_scratch *s, size_t bytes, sp_error *err)
{
    return sp_device_scratch_reserve(r->dev, s, bytes, err);
}

/* Stages (each returns 0 or a negative SP_E_*). project: proj must have room for in->n. */
int sp_cuda_project(sp_cuda_raster *r, const sp_cuda_view *v, const sp_raster_cfg *cfg,
                    const sp_raster_in *in, sp_error *err);
/* Points v->proj at the raster's projection scratch, for `count` Gaussians (a batch: views x n). */
int sp_cuda_reserve_proj(sp_cuda_raster *r, size_t count, sp_cuda_proj *proj, sp_error *err);
int sp_cuda_bin_and_sort(sp_cuda_raster *r, sp_cuda_view *v, size_t n, sp_error *err);
/* Pixels per thread of the forward's narrow chunks (cfg.fwd_px; 0 = the default, 2). */
int sp_cuda_fwd_px(const sp_raster_cfg *cfg);
int sp_cuda_rasterize_fwd(sp_cuda_raster *r, const sp_cuda_view *v, const sp_cuda_pass *p,
                          int max_ch, int px, int aux, sp_error *err);
/* A batch's views composited in one launch (their passes share colours, D and background);
 * per-pixel state for backward is not written. */
int sp_cuda_rasterize_fwd_views(sp_cuda_raster *r, const sp_cuda_view *const *views,
                                const sp_cuda_pass *passes, size_t nv, int max_ch, int px,
                                int aux, sp_error *err);
/* Uploads a HOST background of D floats into the raster's scratch; *out NULL when bg is NULL. */
int sp_cuda_upload_background(sp_cuda_raster *r, const float *bg, int D, float **out, sp_error *err);
int sp_cuda_rasterize_surface(sp_cuda_raster *r, const sp_cuda_view *v, float surface_alpha,
                              float *out, sp_error *err);
int sp_cuda_rasterize_bwd(sp_cuda_raster *r, const sp_raster_grad_in *gin, float *v_colors,
                          float *vgeo, sp_error *err);
int sp_cuda_project_bwd(sp_cuda_raster *r, sp_raster_grads *grads, const float *vgeo,
                        sp_error *err);
/* The binning steps of one view, for batches (tiles.cu). The depth order, the scan and the
 * count use s_cub, which the caller reserves (sp_cuda_prep_temp_bytes) before queueing them. */
/* ids [n] = the Gaussians front to back (culled last); tmp: [3n] uint32 scratch. */
int sp_cuda_depth_order(sp_cuda_raster *r, const sp_cuda_view *v, size_t n, uint32_t *ids,
                        uint32_t *tmp, sp_error *err);
/* counts[k] = kept tiles of Gaussian ids[k]. */
int sp_cuda_count_pairs(sp_cuda_raster *r, const sp_cuda_view *v, size_t n, const uint32_t *ids,
                        uint32_t *counts, sp_error *err);
int sp_cuda_scan_counts(sp_cuda_raster *r, const uint32_t *counts, unsigned long long *offsets,
                        size_t m, sp_error *err);
int sp_cuda_prep_temp_bytes(size_t n, size_t m, size_t *bytes, sp_error *err);
/* Writes Gaussian ids[k]'s pairs at [offsets[k-1], offsets[k]) (inclusive sums; the first
 * Gaussian's start at `first`: 0 for one view, the view's first pair in a batch). */
int sp_cuda_emit_pairs(sp_cuda_raster *r, const sp_cuda_view *v, size_t n, const uint32_t *ids,
                       const unsigned long long *offsets, unsigned long long first, void *keys,
                       uint32_t *vals, sp_error *err);
/* Tile key width of view v: 2 bytes up to 65536 tiles, else 4. */
int sp_cuda_key_bytes(const sp_cuda_view *v);
/* cub's temporary bytes for sorting m pairs of view v (host-side query, no device work). */
int sp_cuda_sort_temp_bytes(const sp_cuda_view *v, size_t m, size_t *bytes, sp_error *err);
/* Sorts v->n_pairs pairs by tile (stable), fills ranges and v->sorted_ids; reserves s_cub. */
int sp_cuda_sort_pairs(sp_cuda_raster *r, sp_cuda_view *v, void *k0, void *k1, uint32_t *v0,
                       uint32_t *v1, int2 *ranges, sp_error *err);
/* The backend table's entries (raster.cu, rasterize_fwd.cu, rasterize_bwd.cu, views.cu, sh.cu). */
int sp_cuda_raster_forward(void *state, const sp_camera *cam, const sp_raster_cfg *cfg,
                           const sp_raster_in *in, sp_raster_out *out, sp_error *err);
int sp_cuda_raster_backward(void *state, const sp_raster_grad_in *gin, sp_raster_grads *grads,
                            sp_error *err);
int sp_cuda_sh_to_rgb(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                      const float *means, sp_vec3 cam_center, float *rgb, int out_stride,
                      sp_error *err);
int sp_cuda_sh_to_rgb_backward(sp_device *dev, size_t n, int degree, int degree_active,
                               const float *sh, const float *means, sp_vec3 cam_center,
                               const float *rgb, const float *v_rgb, int stride, float *v_sh,
                               float *v_means, sp_error *err);
int sp_cuda_depth_normalize(sp_device *dev, float *depth, const float *alpha, size_t npix,
                            sp_error *err);
int sp_cuda_views(void *state, const sp_raster_cfg *cfg, const sp_raster_in *geom,
                  const sp_raster_view *views, size_t n_views, sp_error *err);

/* alpha of a Gaussian at offset (dx, dy) from a pixel centre: sp_gm_alpha_g (gauss_math.h), the
 * rule the CPU backend runs bit for bit (unfused multiplies and adds, the shared polynomial exp),
 * so both backends keep and skip the same contributions; forward and backward kernels both call
 * this. co = (conic a, b, c, opacity). Returns 0 when skipped; *vis gets exp(-sigma). `cut` is
 * sp_cu_sigma_cut(opacity): beyond it alpha is surely below 1/255, so the exp is skipped for the
 * many pixels outside the ellipse without changing any decision (the 1e-3 margin is far above
 * the fast log's error). */
__device__ __forceinline__ float sp_cu_sigma_cut(float opacity)
{
    return __logf(opacity * 255.f) + 1e-3f;
}
__device__ __forceinline__ float sp_cu_alpha(float4 co, float cut, float dx, float dy, float *vis)
{
    const float conic[3] = {co.x, co.y, co.z};
    return sp_gm_alpha_g(conic, co.w, cut, dx, dy, vis);
}

/* sp_cu_alpha without its branch: the exp is evaluated whether or not the pixel is inside the
 * cut, so two Gaussians' alphas are straight-line code the compiler can interleave (the pair
 * walk of the backward). The same operations on the same values, so the same bits and the same
 * decisions as sp_cu_alpha wherever that keeps the pixel, and 0 wherever it does not. */
__device__ __forceinline__ float sp_cu_alpha_flat(float4 co, float cut, float dx, float dy, float *vis)
{
    const float conic[3] = {co.x, co.y, co.z};
    float by, hy;
    sp_gm_row_terms(conic, dy, &by, &hy);
    const float sigma = sp_gm_sigma(0.5f * conic[0], by, hy, dx);
    const float g = sp_gm_expf(-sigma);
    float a = SP_FMUL(co.w, g);
    a = a < SP_ALPHA_MAX ? a : SP_ALPHA_MAX;
    *vis = g;
    return (sigma < 0.f || sigma > cut || a < SP_ALPHA_MIN) ? 0.f : a;
}

/* Warp culling. Every compositing kernel's warp w owns band w of its 16x16 tile, rows
 * rh w .. rh w + rh - 1 (rh = 16 / warps per block), so a Gaussian that no
 * pixel of the band can keep costs that warp nothing if it is skipped before its alpha test.
 * Whether a pixel of the band (clipped to the image) can keep it is sp_gm_tile_hit on the band:
 * the binning's exact ellipse test, conservative against the alpha rule (its margin is far
 * above float rounding), so skipping changes no bit of any image or gradient. Returns this
 * warp's bits for the staged Gaussians base .. base + 31 of a batch of cnt (bit l: slot
 * base + l may be kept), all set where culling is off; lanes test one Gaussian each, so the
 * whole warp must call it, converged. */
/* Pixel slots in warp boxes (BOX), 8 x 4 by default: slot p of a tile is thread p's pixel, warp
 * p / 32 covers the box of columns 8 (warp & 1) .. + 7 and rows 4 (warp >> 1) .. + 3, so a Gaussian's footprint
 * meets fewer warps than with 16 x 2 bands (a disc of radius r meets a w x h box over
 * (w + 2r)(h + 2r): at r = 6 px 320 against 392). */
#ifndef SP_BOX_W
#define SP_BOX_W 8 /* box width: 8 (8 x 4), 4 (4 x 8) or 16 (16 x 2, the bands) */
#endif
#define SP_BOX_H (32 / SP_BOX_W)
#define SP_BOXES_X (SP_TILE_SIZE / SP_BOX_W) /* boxes across a tile */
__device__ __forceinline__ int sp_cu_box_x(int p) { return ((p >> 5) % SP_BOXES_X) * SP_BOX_W + p % SP_BOX_W; }
__device__ __forceinline__ int sp_cu_box_y(int p) { return ((p >> 5) / SP_BOXES_X) * SP_BOX_H + (p & 31) / SP_BOX_W; }
/* warp w's BW x BH box in tile (tx, ty) (boxes row by row), clipped to the image: [x0, x1] x
 * [y0, y1] (x0 > x1 or y0 > y1 when it lies outside) */
template <int BW, int BH>
__device__ __forceinline__ void sp_cu_warp_box(int tx, int ty, int w, int W, int H, int *x0, int *x1,
                                               int *y0, int *y1)
{
    constexpr int NX = SP_TILE_SIZE / BW;
    *x0 = tx * SP_TILE_SIZE + (w % NX) * BW, *x1 = min(*x0 + BW - 1, W - 1);
    *y0 = ty * SP_TILE_SIZE + (w / NX) * BH, *y1 = min(*y0 + BH - 1, H - 1);
}
/* the one-pixel kernels' boxes (sp_cu_box_x) */
__device__ __forceinline__ void sp_cu_box_rect(int tx, int ty, int w, int W, int H, int *x0, int *x1,
                                               int *y0, int *y1)
{
    sp_cu_warp_box<SP_BOX_W, SP_BOX_H>(tx, ty, w, W, H, x0, x1, y0, y1);
}

/* Two pixels per thread (the narrow kernels' PX = 2, 128 threads, 4 warps): with SP_PX_BOX each
 * warp owns an 8 x 8 box of the tile, its lane l the pixels (l % 4 + 4 q, l / 4), q < 2, of it (a
 * thread's pixels still share a row); without, a 16 x 4 band, thread (x, y) pixels (x + 8 q, y). */
#ifndef SP_PX_BOX
#define SP_PX_BOX 1
#endif
__device__ __forceinline__ void sp_cu_px2_rect(int tx, int ty, int w, int W, int H, int *x0, int *x1,
                                               int *y0, int *y1)
{
    sp_cu_warp_box<8, 8>(tx, ty, w, W, H, x0, x1, y0, y1);
}
/* thread tid's first pixel's offset in its tile and the step to its next pixel (PX = 2) */
__device__ __forceinline__ void sp_cu_px2_pixel(int tid, int *ox, int *oy, int *step)
{
    const int w = tid >> 5, l = tid & 31;
    if (SP_PX_BOX) {
        *ox = (w & 1) * 8 + (l & 3), *oy = (w >> 1) * 8 + (l >> 2), *step = 4;
    } else {
        *ox = tid & 7, *oy = tid >> 3, *step = 8;
    }
}

/* The same for any pixel rectangle [x0, x1] x [y0, y1] (inclusive, already clipped to the image;
 * empty when x0 > x1 or y0 > y1). */
__device__ __forceinline__ unsigned sp_cu_rect_bits(const float4 *s_conic, const float2 *s_xy,
                                                    const float *s_cut, int base, int cnt,
                                                    int cull, int x0, int x1, int y0, int y1,
                                                    int lane)
{
    const int j = base + lane;
    bool hit = j < cnt;
    if (hit && cull) {
        const float4 co = s_conic[j];
        const float2 xy = s_xy[j];
        const float con[3] = {co.x, co.y, co.z};
        hit = y0 <= y1 && x0 <= x1 && sp_gm_tile_hit(con, s_cut[j], xy.x, xy.y, x0, x1, y0, y1);
    }
    return __ballot_sync(0xffffffffu, hit);
}

__device__ __forceinline__ unsigned sp_cu_band_bits(const float4 *s_conic, const float2 *s_xy,
                                                    const float *s_cut, int base, int cnt,
                                                    int cull, int tx, int ty, int band, int rh,
                                                    int W, int H, int lane)
{
    const int x0 = tx * SP_TILE_SIZE, x1 = min(x0 + SP_TILE_SIZE - 1, W - 1);
    const int y0 = ty * SP_TILE_SIZE + band * rh, y1 = min(y0 + rh - 1, H - 1);
    return sp_cu_rect_bits(s_conic, s_xy, s_cut, base, cnt, cull, x0, x1, y0, y1, lane);
}

/* The rows a Gaussian can touch, for the cheap band test of wide forward chunks: [lo, hi] with
 * every pixel centre y that keeps it (sigma <= cut, sp_gm_alpha_g) inside. Over dx, sigma at a
 * given dy is least at dx = -b dy / a, where it is dy^2 det / (2 a), so |dy| <= sqrt(2 a cut /
 * det). Conservative against float rounding: the cut is widened by 1e-5 a c / det (the
 * cancellation between sigma's terms grows with that ratio) and the half-extent by 0.01 px; an
 * ellipse too thin for that (a c / det > 1e4) or degenerate gets every row, one whose cut is
 * negative (nothing is kept) none. */
__device__ __forceinline__ float2 sp_cu_y_extent(float4 co, float cut, float my)
{
    const float a = co.x, b = co.y, c = co.z, det = a * c - b * b;
    if (!(a > 0.f && c > 0.f && det > 0.f) || a * c > 1e4f * det)
        return make_float2(-INFINITY, INFINITY);
    if (!(cut >= 0.f)) return make_float2(INFINITY, -INFINITY);
    const float cm = cut * (1.f + 1e-5f * (a * c / det)) + 1e-4f;
    const float ry = sqrtf(2.f * a * cm / det) * 1.0001f + 0.01f;
    return make_float2(my - ry, my + ry);
}

static inline unsigned sp_div_up(size_t a, size_t b) { return (unsigned)((a + b - 1) / b); }

#endif
