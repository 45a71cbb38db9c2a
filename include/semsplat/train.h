/* semsplat train: fit a Gaussian splat to posed images (3DGS, with gsplat's simple_trainer
 * defaults), on the CPU or one GPU through the same loop.
 *
 * Pieces, each usable alone (tests and the semantic module call them directly):
 *   - losses: 0.8 L1 + 0.2 (1 - SSIM) on RGB (SSIM: 11x11 Gaussian window, sigma 1.5, "valid"
 *     positions as gsplat/torchmetrics), and lambda * MSE on feature channels;
 *   - Adam (torch.optim.Adam semantics) on device buffers;
 *   - adaptive density control (gsplat DefaultStrategy): accumulate screen-space mean gradients,
 *     clone small / split large Gaussians over a threshold, prune transparent and oversized ones,
 *     periodic opacity reset;
 *   - the loop: pick a training view, SH -> colours, rasterize, loss, backward, Adam, densify,
 *     held-out evaluation (every test_every-th image), checkpoints, NaN guard.
 *
 * Data: sp_train_data holds the views (pinhole cameras, 8-bit RGB on the host) and the COLMAP
 * points; sp_train_data_load fills it from a COLMAP model and an images folder. Parameters,
 * gradients and Adam moments live on the sp_device; densification moves them to the host and
 * back (every refine_every steps, cheap next to rendering).
 *
 * Feature distillation hook (used by `semsplat distill`): set feature_dim > 0 and
 * get_feature_target; each Gaussian then carries feature_dim extra values (an Adam group with
 * its own lr, copied to children on densify) rendered beside RGB in one pass of 3+F channels,
 * and the loss gains feature_lambda * MSE(rendered features, target). freeze_geometry trains the
 * features only (no densification; geometry and colour untouched).
 *
 * Continuing from a trained splat (--init-ply, distillation): SH bands that are already non-zero
 * are active from the first step, and opacity resets only happen after refine_start, so setting
 * refine_start >= steps (or densify = 0) leaves the splat's density and opacities alone; the
 * Adam moments start at zero (the first steps move each parameter by about its lr).
 *
 * Ownership: sp_train_data owns its views and points (sp_train_data_free); sp_train_run fills a
 * caller-provided sp_splat (free with sp_splat_free). */
#ifndef SEMSPLAT_TRAIN_H
#define SEMSPLAT_TRAIN_H

#include "semsplat/core.h"
#include "semsplat/render.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- data -------------------------------------------------------------------------------------- */

typedef struct sp_train_view {
    char name[256];  /* image file name as in the COLMAP model */
    sp_camera cam;   /* pinhole, already downscaled to the image size below */
    uint8_t *rgb;    /* [H][W][3], H = cam.height, W = cam.width */
    float *depth;    /* [H][W] metric depth along the optical axis (0 = no measurement), or NULL:
                      * filled by sp_train_data_load_depth */
    int is_test;     /* held out for evaluation */
    int undistorted; /* resampled from a distorted camera at load time */
} sp_train_view;

typedef struct sp_train_data {
    size_t n_views;
    sp_train_view *views;
    size_t n_points;
    float *points;         /* [n_points][3] world (COLMAP points3D), may be NULL */
    uint8_t *point_rgb;    /* [n_points][3] */
    sp_vec3 scene_center;  /* mean of the camera centres */
    float scene_scale;     /* max camera distance from scene_center (gsplat parser.scene_scale) */
    size_t n_undistorted;  /* views resampled from a distorted camera at load time */
} sp_train_data;

/* Loads a COLMAP model (`colmap_dir`: capture root or model folder) and its images
 * (`images_dir`, NULL = <colmap_dir>/images). Views are sorted by name; every test_every-th
 * (index % test_every == 0, as gsplat) is held out (test_every <= 0: none). Images are
 * downscaled by an integer `downscale` >= 1 (box filter) and cameras with them.
 * Cameras with SIMPLE_RADIAL / RADIAL / OPENCV distortion are undistorted here (bilinear
 * resampling to a pinhole camera with the same size and principal point and a focal length
 * scaled so no output pixel falls outside the source, as COLMAP's image_undistorter).
 * Errors: a COLMAP image missing from the folder (names the image and the folder), an image
 * whose size does not match its camera, a fisheye or other lens model (SP_E_UNSUPPORTED, names
 * the camera and model; undistort with COLMAP's image_undistorter first). */
int sp_train_data_load(sp_train_data *d, const char *colmap_dir, const char *images_dir,
                       int downscale, int test_every, sp_error *err);
/* Depth targets for depth supervision (depth_lambda > 0): reads depth_dir/<image stem>.npy for every
 * view (a synth capture's depth/NNNNN.npy: float32 [h][w] metres along the optical axis, 0 where
 * nothing was hit; any numeric dtype is converted), downscaled like the images by `downscale` (the
 * mean of the valid samples of each block; 0 where fewer than half are valid, so holes stay holes
 * rather than becoming too-near averages). Depth must be in the model's units: a synth capture's
 * model frame is metric (the world); a COLMAP reconstruction of real images is not, so its depth
 * would first have to be scaled. A view without a file keeps depth NULL (its depth term is skipped);
 * one warning on `log` names the first such view and the count. Errors: the folder missing or no
 * view having a file (SP_E_NOTFOUND), a malformed or truncated .npy (the reader's error, naming the
 * file), a file whose shape is not the image's [h][w] (SP_E_FORMAT, names the file and both
 * sizes), a negative or non-finite value (SP_E_FORMAT), an undistorted view (SP_E_UNSUPPORTED: its
 * depth would need the same resampling). *n_loaded (may be NULL) receives the views with depth. */
int sp_train_data_load_depth(sp_train_data *d, const char *depth_dir, int downscale,
                             size_t *n_loaded, const sp_log *log, sp_error *err);
/* Computes scene_center / scene_scale from the views' camera centres. */
void sp_train_data_update_scene(sp_train_data *d);
void sp_train_data_free(sp_train_data *d);

/* ---- initialisation ---------------------------------------------------------------------------- */

/* gsplat init from points: means = points, colour = point colour as SH DC, log_scales =
 * log(mean distance to the 3 nearest neighbours) on all axes, opacity 0.1, random quaternions
 * (uniform in [0,1)^4 as gsplat), higher SH bands zero. Needs d->n_points >= 1. */
int sp_train_init_from_points(sp_splat *s, const sp_train_data *d, int sh_degree, uint64_t seed,
                              sp_error *err);
/* gsplat random init: n points uniform in a cube of half-size extent * scene_scale around the
 * scene centre, random colours, scales from nearest neighbours as above. */
int sp_train_init_random(sp_splat *s, const sp_train_data *d, size_t n, float extent,
                         int sh_degree, uint64_t seed, sp_error *err);

/* ---- options and results ----------------------------------------------------------------------- */

/* Called for training view `view` (index into data->views): fill dst [H][W][F] (HOST, H/W of
 * that view's camera, F = feature_dim) with the target feature map. Return 0 or a negative
 * SP_E_* code with err filled. Called once per training view and cached on the device when
 * cache_feature_targets is set, else every time the view is drawn; and once per held-out view
 * at the end for res->feature_mse (so it serves every view index). */
typedef int (*sp_feature_target_fn)(void *user, size_t view, int width, int height, int F,
                                    float *dst, sp_error *err);

typedef struct sp_train_options {
    int steps;              /* total optimisation steps (default 30000) */
    int sh_degree;          /* final SH degree (default 3) */
    int sh_degree_interval; /* raise the active degree every this many steps (default 1000) */
    float ssim_lambda;      /* default 0.2 */
    int random_background;  /* composite on a random colour each step (default 0: black) */
    float background[3];    /* fixed background when not random */
    uint64_t seed;

    /* Adam learning rates (gsplat defaults); lr_means is multiplied by the scene scale and
     * decays exponentially to lr_means_final_factor of itself over `steps`. */
    float lr_means, lr_means_final_factor, lr_scales, lr_quats, lr_opacities, lr_sh0, lr_shN;
    float adam_beta1, adam_beta2, adam_eps;

    /* Density control (gsplat DefaultStrategy); step fields in optimisation steps. */
    int densify;             /* default 1 */
    int refine_start, refine_stop, refine_every, reset_every; /* 500, 15000, 100, 3000 */
    float grow_grad2d;       /* NDC-normalised gradient norm; 0 (default) = auto,
                              * sp_train_grow_grad2d */
    float grow_scale3d;      /* 0.01 (x scene scale): clone below, split above */
    float prune_opacity;     /* 0.005 */
    float prune_scale3d;     /* 0.1 (x scene scale), applied after the first opacity reset */
    size_t max_gaussians;    /* cap on the count (0 = none); growth stops at the cap */
    float scene_scale;       /* 0 = from the data (x 1.1 as gsplat) */

    /* Evaluation and checkpoints. */
    int eval_every;          /* held-out evaluation every this many steps (0 = only at the end) */
    const char *checkpoint_dir; /* NULL = no checkpoints */
    int checkpoint_every;    /* steps between checkpoints (default 1000; 0: only the final one) */
    const char *resume;      /* checkpoint file to resume from (NULL = start fresh) */

    /* Feature distillation (see the header comment). */
    int feature_dim;
    float feature_lambda;    /* default 1.0 */
    float lr_features;       /* default 2.5e-3 */
    sp_feature_target_fn get_feature_target;
    void *feature_user;
    int cache_feature_targets; /* default 1 */
    int freeze_geometry;       /* train features only */

    /* Depth supervision (views with sp_train_view.depth): the loss gains
     *   depth_lambda * (1 / (H W)) * sum |expected depth - t|
     * over the pixels with a target t > 0 (alpha-weighted where alpha < 0.1; see train_kernels.h
     * for the form and why), in the depth's units (metres for a synth capture).
     * 0 (default) = off: no depth is rendered for the loss. */
    float depth_lambda;
} sp_train_options;

/* gsplat simple_trainer defaults for `steps` steps. Below 30000 steps the SH schedule and
 * refine_start scale by steps / 30000, densification stops 2000 steps before the end (at least
 * halfway, at most at 15000), and refinement
 * keeps gsplat's absolute cadence (every 100 steps, opacity reset every 3000), as
 * `simple_trainer --max_steps N` does. */
sp_train_options sp_train_options_default(int steps);

typedef struct sp_train_result {
    int steps;             /* steps completed (including resumed ones) */
    size_t gaussians;
    double seconds;        /* wall time of this run */
    double seconds_steps;  /* of its steps alone (first step to the final parameters on the host,
                            * checkpoints included): the span gsplat's simple_trainer-style loop
                            * times, without loading, set-up and the final evaluation */
    double psnr, ssim, l1; /* mean over held-out views (or training views when none held out) */
    int n_eval_views;
    int eval_on_train;     /* 1 when metrics are on training views (no held-out views) */
    double feature_mse;    /* feature_dim > 0: mean squared error of the features rendered at the
                            * held-out views (training views when none held out, eval_on_train)
                            * against get_feature_target's maps, over every pixel and channel */
    double last_loss;
    /* Views with depth (sp_train_data_load_depth): mean |expected depth - target| in the depth's
     * units over the pixels with a target and alpha >= 0.5 of the evaluated views (held-out, or
     * training views when none held out), the share of such pixels with alpha < 0.5 (the splat
     * rendering nothing solid where the sensor saw a surface), and the first-surface depth's error
     * (sp_raster_out.surface_depth at alpha 0.5, what nav's costmap uses) over the same pixels.
     * depth_eval_pixels = 0 when no evaluated view has depth. */
    double depth_l1, depth_hole_share, surface_depth_l1;
    double depth_eval_pixels;
    char device[128];
} sp_train_result;

/* ---- the loop ------------------------------------------------------------------------------------ */

/* Trains `splat` in place: on entry it holds the initial Gaussians (from sp_train_init_* or a
 * PLY; its sh_degree is raised to opt->sh_degree and features added when feature_dim > 0 and it
 * has none), on success the trained ones. With opt->resume, the checkpoint replaces the splat
 * and the optimiser state. On a NaN/Inf loss or parameter the run stops with SP_E_NUMERIC, a
 * message naming the step, and the last good checkpoint left as it was; `splat` then holds the
 * last finite parameters. Progress and logs go to `log` (may be NULL). */
int sp_train_run(sp_device *dev, const sp_train_data *data, const sp_train_options *opt,
                 sp_splat *splat, sp_train_result *res, const sp_log *log, sp_error *err);

/* Held-out metrics of a host splat on the test views (all views when none are test views). */
int sp_train_evaluate(sp_device *dev, const sp_train_data *data, const sp_splat *splat,
                      const float background[3], sp_train_result *res, sp_error *err);

/* Writes train.json: settings, the result (keys psnr, ssim, gaussians, steps, seconds, device). */
int sp_train_write_json(const char *path, const sp_train_options *opt, const sp_train_result *res,
                        const char *colmap_dir, const char *images_dir, int downscale,
                        sp_error *err);

/* ---- a model folder (what `semsplat train` does) ----------------------------------------------- */

typedef enum {
    SP_TRAIN_INIT_POINTS = 0, /* COLMAP points3D (random when the model has none, with a warning) */
    SP_TRAIN_INIT_RANDOM = 1, /* init_points uniform points around the cameras */
    SP_TRAIN_INIT_PLY = 2     /* init_ply: continue from an existing splat (3DGS/gsplat PLY) */
} sp_train_init;

typedef struct sp_train_model_opts {
    const char *colmap_dir;  /* capture root or COLMAP model folder (required) */
    const char *images_dir;  /* NULL: <colmap_dir>/images */
    const char *depth_dir;   /* depth targets when train.depth_lambda > 0 (NULL: <colmap_dir>/depth);
                              * also read, when present, for the held-out depth error in train.json */
    const char *out_dir;     /* the model folder (required; made when missing) */
    int downscale;           /* integer image downscale (1) */
    int test_every;          /* hold out every n-th image (8; 0 = none) */
    sp_train_init init;
    const char *init_ply;    /* SP_TRAIN_INIT_PLY */
    size_t init_points;      /* SP_TRAIN_INIT_RANDOM (100000) */
    const char *resume;      /* continue from this checkpoint (NULL = fresh); replaces init */
    sp_train_options train;  /* checkpoint_dir and resume are set by the call */
} sp_train_model_opts;

/* sp_train_options_default(steps) inside, init from points, downscale 1, test_every 8. */
sp_train_model_opts sp_train_model_opts_default(int steps);

/* Trains a model folder: OUT/splat.ply (3DGS layout), OUT/train.json (settings, held-out metrics),
 * OUT/frame.json (the capture's frame: a synth capture's model frame is the world frame, see
 * sp_frame_of_capture in io.h) and OUT/checkpoints/checkpoint.bin. res (may be NULL) receives the
 * result; log the progress. Errors name the capture, image, file or setting at fault. */
int sp_train_model(sp_device *dev, const sp_train_model_opts *o, sp_train_result *res,
                   const sp_log *log, sp_error *err);

/* ---- building blocks (host buffers; the loop uses device versions) ------------------------------ */

/* RGB loss (see train_cuda_api.h for the exact definition): stats = loss, L1, SSIM, MSE; v_pred
 * (may be NULL) WRITTEN into channels [0, C) of [H][W][pred_stride]. pool may be NULL. */
int sp_train_rgb_loss(sp_pool *pool, const float *pred, int pred_stride, const float *target,
                      int H, int W, int C, float ssim_lambda, float *v_pred, double stats[4],
                      sp_error *err);
/* One Adam step on host arrays (step is 1-based). */
void sp_train_adam_host(float *param, const float *grad, float *m, float *v, size_t n, float lr,
                        float beta1, float beta2, float eps, int step);

/* The densification threshold a run uses: grow_grad2d when set, else 0.00015 for runs under
 * 30000 steps without depth supervision and gsplat's 0.0002 otherwise (loop.c says why). */
float sp_train_grow_grad2d(const sp_train_options *o);

/* Density control on a host splat (gsplat DefaultStrategy grow + prune, in that order) with
 * per-Gaussian statistics accumulated since the last refinement (grad2d_sum, count [n]):
 * clone where the mean NDC gradient > grow_grad2d and max scale <= grow_scale3d * scene_scale,
 * split (2 children sampled from the Gaussian, scales / 1.6) where it is larger; then prune
 * opacity < prune_opacity and, when step > reset_every, max scale > prune_scale3d * scene_scale.
 * Growth stops at max_gaussians (clones first, by gradient order of indices). adam_m / adam_v
 * (may be NULL) are Adam moments shaped like s and are reorganised alongside; children get
 * zero moments as in gsplat. rng: xorshift state for the split samples. */
typedef struct sp_densify_stats {
    size_t n_cloned, n_split, n_pruned;
} sp_densify_stats;

int sp_train_densify_host(sp_splat *s, sp_splat *adam_m, sp_splat *adam_v,
                          const float *grad2d_sum, const float *count,
                          const sp_train_options *opt, float scene_scale, int step, uint64_t *rng,
                          sp_densify_stats *st, sp_error *err);

/* Opacity reset (3DGS): logits clamped to at most logit(2 * prune_opacity); moments zeroed. */
void sp_train_reset_opacity_host(sp_splat *s, sp_splat *adam_m, sp_splat *adam_v, float prune_opacity);

#ifdef __cplusplus
}
#endif
#endif
