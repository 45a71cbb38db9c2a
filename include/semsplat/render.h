/* semsplat render: the 3DGS/EWA Gaussian rasterizer, forward and backward, for any channel count,
 * with a CPU and a CUDA backend behind one interface (sp_device).
 *
 * Pipeline per view (one stage per file in src/render/, same split in src/render/cuda/):
 *   project (means, covariances -> 2D means, conics, depths, radii)
 *   -> tile binning (16x16 tiles) -> sort by (tile, depth) -> composite front to back.
 * Colours are whatever the caller passes per Gaussian ([n][D]: RGB from sp_sh_to_rgb, features,
 * or both concatenated); the rasterizer also gives expected depth and accumulated alpha.
 *
 * Memory: every buffer in sp_raster_in / sp_raster_out / sp_raster_grads lives on the device
 * the sp_raster was created for (host memory for the CPU backend, GPU memory for CUDA). Use
 * sp_device_alloc/upload/download to move data. An sp_raster keeps the forward pass's state
 * (projections, sorted lists, per-pixel final transmittance) for the backward of the same view.
 *
 * Callers other than training (queries, previews, view selection) upload a host splat once as
 * an sp_scene and render it from any number of cameras, one at a time or as a batch
 * (sp_render_views); a scene is a snapshot: after the host splat changes, sp_scene_update says
 * what changed. sp_render_splat is the one-off convenience that uploads on every call.
 *
 * Threads: an sp_raster or sp_scene is used by one thread at a time (like its device).
 *
 * Conventions (same as gsplat / 3DGS): camera frame x right, y down, z forward; pixel (px, py)
 * has its centre at (px + 0.5, py + 0.5); covariance = R S S^T R^T with S = diag(exp(log_scales));
 * the 2D covariance gets eps2d (0.3 px^2) added to its diagonal; alpha = min(0.99, opacity *
 * exp(-0.5 d^T conic d)), skipped below 1/255; compositing stops when transmittance < 1e-4.
 * Gradients are ADDED to the output buffers (callers zero them), so several passes (RGB, then
 * features) can accumulate into one set. */
#ifndef SEMSPLAT_RENDER_H
#define SEMSPLAT_RENDER_H

#include "semsplat/core.h"
#include "semsplat/device.h" /* sp_device (was declared here) */

#ifdef __cplusplus
extern "C" {
#endif

/* ---- rasterization ---------------------------------------------------------------------------- */

#define SP_TILE_SIZE 16
#define SP_ALPHA_MAX 0.99f             /* 3DGS: cap per-Gaussian alpha */
#define SP_ALPHA_MIN (1.0f / 255.0f)   /* 3DGS: skip fainter contributions */
#define SP_TRANSMITTANCE_MIN 1e-4f     /* 3DGS: stop compositing below this */
#define SP_EPS2D 0.3f                  /* 3DGS/gsplat screen-space dilation, px^2 */

#define SP_SURFACE_ALPHA 0.5f         /* default alpha threshold of first-surface depth */

typedef struct sp_raster_cfg {
    float near_plane;   /* Gaussians with camera z below this are culled (default 0.01 m) */
    float far_plane;    /* and beyond this (default 1e10) */
    float eps2d;        /* default SP_EPS2D */
    int antialiased;    /* gsplat "antialiased" mode: opacity *= sqrt(det(S)/det(S + eps2d I)) */
    float surface_alpha; /* sp_raster_out.surface_depth: the depth of the Gaussian at which the
                          * accumulated alpha first reaches this, in (0, 1] (default 0.5) */
    /* CUDA only, for tuning: the widest channel chunk one compositing pass handles, forward and
     * backward; 0 (default) = SP_CHANNEL_CHUNK_MAX, the measured best; else one of
     * SP_CHANNEL_WIDTHS. Results do not depend on it. */
    int chunk_fwd, chunk_bwd;
    /* 0 (default): a Gaussian is binned only into the tiles its alpha >= 1/255 ellipse reaches
     * (exact ellipse-vs-tile culling); 1: into every tile of its bounding box. The images and
     * gradients are the same either way (tests compare them); 1 only costs more pairs. */
    int box_tiles;
    /* 1: time the forward's and backward's stages (sp_raster_last_stages); CUDA records events
     * on its stream between stages (no extra waits). 0 (default): no timing. */
    int profile;
    /* CUDA only, for tuning: how the backward sums colour gradients. 0 (default): chunks of 32
     * channels and more as a product in shared memory over the tile's pixels, narrower ones by
     * warp reduce-scatter; -1: reduce-scatter at every width; 1: gather over the lanes that kept
     * the Gaussian (v_image staged in shared memory); 2: as 0, but chunks of 32, 40, 48 and 64
     * channels on a GPU with TF32 tensor cores (compute capability 8.0+) take the product and
     * the per-pixel colour dot product on tensor cores (3xTF32 WMMA, float-level error; not yet
     * measured). sp_raster_last_stages says which kernel ran. Results agree up to float
     * rounding and summation order. Other values fail with SP_E_ARG. */
    int bwd_gather;
    /* CUDA only, for tuning: pixels per thread of the reduce-scatter backward for chunks of up
     * to 8 channels (the one D=3 takes). 0 (default) and 2: two pixels of a row per thread (128
     * threads per tile), so a warp's per-Gaussian costs (shared loads, ballot, the reduce-scatter
     * and its atomics) serve 64 pixels, not 32 (H200, 1M Gaussians 1080p D=3: backward 2.96
     * against 3.80 ms); 1: one pixel per thread (a 256-thread block per tile); 4: four (3.09 ms).
     * Wider chunks and the other kernels ignore it. Results agree up to summation order. Other
     * values fail with SP_E_ARG. */
    int bwd_px;
    /* CUDA only, for tuning: pixels per thread of the forward for chunks of up to 8 channels.
     * 0 (default) and 2: two pixels of a row per thread (128 threads per tile), so a Gaussian's
     * shared-memory loads, row terms and loop overhead serve two pixels; 1: one pixel per thread;
     * 4: four. The results are the same bit for bit. Other values fail with SP_E_ARG. */
    int fwd_px;
    /* CUDA only, for tuning: warp culling. 0 (default) and 1: each warp of a compositing kernel
     * (forward and backward) skips the Gaussians that no pixel of its band of the tile can keep
     * (the binning's exact ellipse test on the warp's rows instead of the whole tile, made once
     * per staged batch); -1: off, every warp tests every pixel. The results are the same bit
     * for bit. Other values fail with SP_E_ARG. */
    int warp_cull;
} sp_raster_cfg;

sp_raster_cfg sp_raster_cfg_default(void);

typedef struct sp_raster_in {
    size_t n;
    const float *means;          /* [n][3] world */
    const float *quats;          /* [n][4] (w,x,y,z) unnormalised */
    const float *log_scales;     /* [n][3] */
    const float *opacity_logits; /* [n] */
    const float *colors;         /* [n][D] per-Gaussian values to composite */
    int D;                       /* channel count, >= 1 */
    const float *background;     /* [D] HOST memory, or NULL for zeros */
} sp_raster_in;

typedef struct sp_raster_out {
    float *image; /* [H][W][D], required */
    float *depth; /* [H][W] sum_i w_i z_i (divide by alpha for the expected depth), or NULL */
    float *alpha; /* [H][W] sum_i w_i, or NULL */
    /* [H][W] first-surface (median) depth, or NULL: camera z of the first Gaussian, front to
     * back, after which the accumulated alpha 1 - T reaches cfg->surface_alpha; 0 where it never
     * does. Unlike the expected depth it does not blend foreground and background at edges.
     * Forward only (no gradient); costs one more pass over the sorted lists. */
    float *surface_depth;
} sp_raster_out;

typedef struct sp_raster_grad_in {
    const float *v_image; /* [H][W][D], required */
    const float *v_depth; /* [H][W] or NULL */
    const float *v_alpha; /* [H][W] or NULL */
} sp_raster_grad_in;

/* Gradients, ADDED into (callers zero). Any pointer may be NULL to skip that group except that
 * computing one group costs the same as all. v_means2d is the gradient w.r.t. the projected
 * 2D mean in pixels (what densification accumulates). */
typedef struct sp_raster_grads {
    float *v_means;          /* [n][3] */
    float *v_quats;          /* [n][4] */
    float *v_log_scales;     /* [n][3] */
    float *v_opacity_logits; /* [n] */
    float *v_colors;         /* [n][D] */
    float *v_means2d;        /* [n][2] */
} sp_raster_grads;

typedef struct sp_raster sp_raster;

int sp_raster_create(sp_raster **out, sp_device *dev, sp_error *err);
void sp_raster_free(sp_raster *r);
sp_device *sp_raster_device(sp_raster *r);

/* Renders one view. Fails with SP_E_ARG on bad sizes, never on Gaussians behind the camera or
 * outside the image (those are culled). */
int sp_raster_forward(sp_raster *r, const sp_camera *cam, const sp_raster_cfg *cfg,
                      const sp_raster_in *in, sp_raster_out *out, sp_error *err);

/* Backward of the last forward (same cam, cfg, in; `in` buffers must be unchanged). */
int sp_raster_backward(sp_raster *r, const sp_raster_grad_in *gin, sp_raster_grads *grads,
                       sp_error *err);

/* Screen radius in pixels of each Gaussian in the last forward ([n] int32 on the device; 0 =
 * culled). Valid until the next forward. */
const int32_t *sp_raster_radii(const sp_raster *r);
/* Where the last forward and backward spent their time, in milliseconds, when that forward
 * ran with cfg.profile (else, and on the CPU backend, zeros). */
typedef struct sp_raster_stages {
    double project;     /* projection */
    double bin;         /* depth order, tile-pair counts and their scan */
    double sort;        /* the pair-count wait, pair emission and the tile sort */
    double raster_fwd;  /* forward compositing (every channel chunk) */
    double raster_bwd;  /* gradient clearing and backward compositing (0 before a backward) */
    double project_bwd; /* projection backward */
    /* CUDA: which kernel summed the last backward's colour gradients for its widest channel
     * chunk ("tensor-core", "product", "gather", "reduce-scatter" or, with cfg.bwd_px = 2 or 4,
     * "reduce-scatter-2px" or "-4px"; cfg.bwd_gather and cfg.bwd_px pick, and
     * a kernel that does not fit the GPU or width falls back), set with or without cfg.profile;
     * NULL before a backward and on the CPU. */
    const char *bwd_kernel;
    /* CUDA: pixels per thread of the last forward's widest chunk (cfg.fwd_px resolved: 1, 2 or
     * 4); 0 on the CPU. */
    int fwd_px;
} sp_raster_stages;

/* Fills *out for the last forward/backward (waits for them to finish). Returns 0 or SP_E_*. */
int sp_raster_last_stages(sp_raster *r, sp_raster_stages *out, sp_error *err);

/* Number of (Gaussian, tile) pairs in the last forward. */
size_t sp_raster_last_pairs(const sp_raster *r);

/* ---- spherical harmonics ---------------------------------------------------------------------- */

/* rgb[i*out_stride + c] = max(0, 0.5 + sum_k SH_k(dir_i) * sh[i][k][c]) for c in 0..2, with
 * dir_i = normalize(means[i] - cam_center) and bands up to degree_active <= degree (the stored
 * degree). Device buffers. */
int sp_sh_to_rgb(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                 const float *means, sp_vec3 cam_center, float *rgb, int out_stride, sp_error *err);
/* Backward: given v_rgb (same stride), ADDS into v_sh [n][K][3] and v_means [n][3] (may be NULL).
 * Needs the forward's rgb to know which channels were clamped. */
int sp_sh_to_rgb_backward(sp_device *dev, size_t n, int degree, int degree_active, const float *sh,
                          const float *means, sp_vec3 cam_center, const float *rgb,
                          const float *v_rgb, int stride, float *v_sh, float *v_means,
                          sp_error *err);

/* ---- uploaded scenes: rendering for callers other than training ------------------------------- */

/* An sp_scene is a host splat uploaded once to a device, holding what it was made to render:
 * SP_SCENE_RGB (colour from SH) and/or SP_SCENE_FEATURES (the splat's features). It is a
 * snapshot: edits to the host splat are seen only after sp_scene_update. It does not keep a
 * pointer to the host splat. Free it before its device. */
typedef struct sp_scene sp_scene;

enum {
    SP_SCENE_RGB = 1,      /* colour from SH (needs sh, 0 <= sh_degree <= 3) */
    SP_SCENE_FEATURES = 2  /* the per-Gaussian features (needs feat_dim >= 1 and features) */
};

/* What changed in the host splat since the scene was made or last updated. */
enum {
    SP_SCENE_CHANGED_GEOMETRY = 1, /* means, quats, log_scales, opacity_logits */
    SP_SCENE_CHANGED_SH = 2,
    SP_SCENE_CHANGED_FEATURES = 4,
    SP_SCENE_CHANGED_ALL = 7
};

/* Uploads s to dev. what: SP_SCENE_RGB and/or SP_SCENE_FEATURES, or 0 for geometry only (for
 * sp_scene_raster_in). Fails with SP_E_ARG naming the missing field when s lacks what is asked,
 * SP_E_NUMERIC when a value is not finite, SP_E_NOMEM / SP_E_DEVICE from the device. */
int sp_scene_create(sp_scene **out, sp_device *dev, const sp_splat *s, unsigned what,
                    sp_error *err);
/* Re-uploads the parts of s named in `changed` (SP_SCENE_CHANGED_*). When s's count, SH degree
 * or feature dim differ from the scene's, everything is uploaded again whatever `changed` says.
 * On error the scene refuses to render until an update succeeds. */
int sp_scene_update(sp_scene *sc, const sp_splat *s, unsigned changed, sp_error *err);
void sp_scene_free(sp_scene *sc);
size_t sp_scene_count(const sp_scene *sc);
int sp_scene_feat_dim(const sp_scene *sc); /* 0 without SP_SCENE_FEATURES */
sp_device *sp_scene_device(const sp_scene *sc);
/* The scene's device geometry as a raster input (means, quats, log_scales, opacity_logits, n;
 * colors NULL, D 0: the caller sets them) for sp_raster_forward / backward. Valid until the
 * next sp_scene_update or sp_scene_free. */
int sp_scene_raster_in(const sp_scene *sc, sp_raster_in *in, sp_error *err);
/* The scene's features on its device ([n][feat_dim]), or NULL without SP_SCENE_FEATURES. */
const float *sp_scene_device_features(const sp_scene *sc);
/* Replaces the scene's features with d_features [n][feat_dim] that already live on its device
 * (a device-to-device copy: per-query values computed there need no host round trip). SP_E_ARG
 * when the scene has no features or its last update failed. */
int sp_scene_copy_features(sp_scene *sc, const float *d_features, sp_error *err);

typedef enum {
    SP_DEPTH_EXPECTED = 0, /* sum w z / sum w: blends foreground and background at edges */
    SP_DEPTH_SURFACE = 1   /* first-surface (median) depth at depth_alpha, see sp_raster_out */
} sp_depth_mode;

/* What to render of one view. Any output pointer may be NULL. HOST buffers, unless on_device.
 *   rgb      [H][W][3]        from SH (active degree = the splat's degree); needs SP_SCENE_RGB
 *   features [H][W][feat_dim] composited features (not divided by alpha); needs SP_SCENE_FEATURES
 *   depth    [H][W]           depth_mode SP_DEPTH_EXPECTED: sum w z / alpha (0 where alpha < 1e-6);
 *                             SP_DEPTH_SURFACE: first-surface depth (0 where alpha never reaches
 *                             depth_alpha)
 *   alpha    [H][W]           accumulated opacity sum w
 * A zero-initialised request (plus outputs) asks for expected depth.
 * on_device = 1: the output pointers are buffers on the scene's device (sp_device_alloc; host
 * memory for the CPU backend) and the outputs stay there, same layout and values: the
 * rasterizer writes them in place, nothing is downloaded, and the call returns without waiting
 * for the GPU to finish them (a download or sp_device_sync on that device orders after them).
 * For device-side consumers (semantic scoring, heatmaps) that should not copy images to the host. */
typedef struct sp_render_request {
    float *rgb;
    float *features;
    float *depth;
    float *alpha;
    const float *background;  /* [3] for rgb, NULL = black */
    sp_depth_mode depth_mode;
    float depth_alpha;        /* SP_DEPTH_SURFACE threshold in (0, 1]; 0 = SP_SURFACE_ALPHA */
    int on_device;            /* 1: outputs are device buffers, left on the device (above) */
} sp_render_request;

/* Renders n views of a scene, view i through cams[i] into reqs[i] (views may differ in size and
 * in what they ask). The scene is not uploaded again; on CUDA the views are rendered in batches
 * with one wait for the GPU per batch (sizing the sort), not one per view. Uses r's scratch and
 * leaves no forward for sp_raster_backward. Fails with SP_E_ARG naming the view and what is
 * wrong (size, a request the scene cannot serve, a bad depth_alpha). */
int sp_render_views(sp_raster *r, sp_scene *sc, const sp_camera *cams, size_t n,
                    const sp_render_request *reqs, sp_error *err);

/* Convenience for one-off renders of a host splat: makes a scene of what req asks for, renders
 * one view and frees the scene, so the splat is uploaded on EVERY call (and edits in place are
 * always seen). For repeated renders of the same splat make an sp_scene instead. */
int sp_render_splat(sp_raster *r, const sp_splat *s, const sp_camera *cam,
                    const sp_render_request *req, sp_error *err);

/* ---- colour maps ------------------------------------------------------------------------------ */

/* Turbo colour map (Google, 2019) at t in [0,1] -> rgb in [0,1]. */
void sp_turbo(float t, float rgb[3]);
/* depth [n] (expected depth, metres) -> rgb [n][3] floats: turbo between the 2nd and 98th
 * percentile of covered pixels (alpha >= 0.5), near red, far blue; black where nothing solid. */
int sp_depth_colormap(const float *depth, const float *alpha, size_t n, float *rgb, sp_error *err);

#ifdef __cplusplus
}
#endif
#endif
