/* The train module's backend seam: the per-element work of one training step (losses, Adam,
 * densification statistics, column packing) as a table of entry points on DEVICE pointers, one
 * table per backend: the CPU's (cpu_kernels.c over loss.c) and CUDA's (cuda/train_ops.cu;
 * nocuda/ returns none). Both have exactly the same semantics; the CPU functions in loss.c are the
 * reference the CUDA test compares against. All sizes are element counts, all images row-major
 * [H][W][stride]. Every entry returns 0 or a negative SP_E_* code (SP_E_DEVICE on a CUDA failure,
 * with the CUDA error string in err). CUDA work runs on the device's stream; entries that return
 * host values (stats, out_mse, out_bad) wait for it. */
#ifndef SP_TRAIN_KERNELS_H
#define SP_TRAIN_KERNELS_H

#include "semsplat/device.h"

#ifdef __cplusplus
extern "C" {
#endif

/* SSIM as in 3DGS / gsplat: 11x11 Gaussian window, sigma 1.5, C1 = 0.01^2, C2 = 0.03^2, per
 * channel, averaged over the "valid" positions (where the whole window fits: (H-10) x (W-10)),
 * as gsplat's fused_ssim(padding="valid") and torchmetrics do. Images smaller than 11x11 are
 * rejected with SP_E_ARG. */
#define SP_SSIM_WINDOW 11
#define SP_SSIM_SIGMA 1.5f
#define SP_SSIM_C1 (0.01f * 0.01f)
#define SP_SSIM_C2 (0.03f * 0.03f)

/* Scratch the RGB loss needs, in floats (device memory the caller allocates once per size). */
/* Depth loss: pixels with alpha below this add nothing (see depth_loss). */
#define SP_DEPTH_MIN_ALPHA 0.1f

#define SP_LOSS_SCRATCH_FLOATS(H, W, C) ((size_t)16 * (size_t)(H) * (size_t)(W) * (size_t)(C))

typedef struct tr_kernels {
    /* RGB photometric loss of 3DGS: loss = (1 - ssim_lambda) * L1 + ssim_lambda * (1 - SSIM), with
     * L1 = mean |pred - target| over H*W*C and SSIM the mean SSIM above.
     *   pred    [H][W][pred_stride]   channels [0, C) are compared (C <= pred_stride)
     *   target  [H][W][C]
     *   scratch SP_LOSS_SCRATCH_FLOATS(H, W, C) floats
     *   v_pred  [H][W][pred_stride] or NULL (evaluation only): d loss / d pred WRITTEN into channels
     *           [0, C) (other channels untouched). L1's subgradient at pred == target is 0.
     *   stats   HOST double[4]: loss, L1, SSIM, MSE (mean squared error over H*W*C, for PSNR). */
    int (*rgb_loss)(sp_device *dev, const float *pred, int pred_stride, const float *target, int H,
                    int W, int C, float ssim_lambda, float *scratch, float *v_pred,
                    double stats[4], sp_error *err);

    /* Feature distillation loss: lambda * mean over H*W*F of (pred - target)^2.
     *   pred    [H][W][pred_stride], channels [offset, offset + F) compared
     *   target  [H][W][F]
     *   v_pred  same layout as pred or NULL: d loss / d pred WRITTEN into channels [offset, offset+F)
     *   out_mse HOST: the unweighted mean squared error (may be NULL) */
    int (*feature_mse)(sp_device *dev, const float *pred, int pred_stride, int offset,
                       const float *target, int H, int W, int F, float lambda, float *v_pred,
                       double *out_mse, sp_error *err);

    /* Depth supervision loss on the rasterizer's depth outputs (sp_raster_out depth = sum w z,
     * alpha = sum w): with the expected depth d = depth / alpha and a = SP_DEPTH_MIN_ALPHA,
     *   loss = lambda / (H W) * sum over pixels with target t > 0 of
     *          |d - t|                       where alpha >= a
     *          |depth - t alpha| / a         where alpha <  a   (= (alpha / a) |d - t|)
     * Pixels without a measurement (t = 0: holes, sky) add nothing. Normalising by alpha moves
     * the depth towards t (the Gaussians in front of it lose weight relative to those behind)
     * without an incentive to thin the pixel out: |depth - t alpha| (= alpha |d - t|) everywhere
     * can also be lowered by lowering alpha, and on the tiny capture of tests/train/test_depth.c
     * it left 24 % of the held-out depth pixels below alpha 0.5 against 8 % for this form (13 %
     * with RGB alone), at the same depth error. Below the floor a the division's gradient
     * (1 / alpha) would be unbounded on faint fringes and holes, so there the alpha-weighted form
     * takes over, continuous at a, its gradient bounded by 1 / a; thinning such pixels is
     * harmless (coverage is the RGB loss's). L1 keeps the mixed pixels at depth edges from
     * dominating as a square would. Normalised over all H W pixels like the RGB L1, so a view's
     * weight does not grow with its holes.
     *   depth, alpha, target  [H][W]
     *   v_depth, v_alpha      [H][W] or both NULL (evaluation only): d loss / d depth, d alpha
     *                         WRITTEN at every pixel (0 where t = 0); the subgradient at a zero
     *                         residual is 0.
     *   stats                 HOST double[3]: loss, the unweighted mean of the per-pixel terms
     *                         over the pixels with a target (0 when none), their count. */
    int (*depth_loss)(sp_device *dev, const float *depth, const float *alpha, const float *target,
                      int H, int W, float lambda, float *v_depth, float *v_alpha, double stats[3],
                      sp_error *err);

    /* One Adam step (Kingma & Ba, as torch.optim.Adam without weight decay), elementwise on n:
     *   m = b1 m + (1-b1) g;  v = b2 v + (1-b2) g^2;
     *   param -= lr * (m / (1 - b1^step)) / (sqrt(v / (1 - b2^step)) + eps)
     * step is 1-based (the count of steps taken including this one). */
    int (*adam_step)(sp_device *dev, float *param, const float *grad, float *m, float *v, size_t n,
                     float lr, float beta1, float beta2, float eps, int step, sp_error *err);

    /* Densification statistics (gsplat DefaultStrategy._update_state, absgrad off): for every
     * Gaussian i with radii[i] > 0,
     *   grad2d_sum[i] += sqrt((v_means2d[i][0] * scale_x)^2 + (v_means2d[i][1] * scale_y)^2)
     *   count[i]      += 1
     * where scale_x = W / 2 and scale_y = H / 2 turn pixel gradients into NDC ones.
     *   v_means2d [n][2], radii [n] (sp_raster_radii), grad2d_sum [n], count [n] */
    int (*densify_accumulate)(sp_device *dev, const float *v_means2d, const int32_t *radii,
                              size_t n, float scale_x, float scale_y, float *grad2d_sum,
                              float *count, sp_error *err);

    /* Strided column copy, used to pack features next to RGB in the colours buffer and to unpack
     * their gradients: for r < rows, c < cols:
     *   dst[r * dst_stride + dst_offset + c] = src[r * src_stride + src_offset + c] */
    int (*copy_columns)(sp_device *dev, float *dst, int dst_stride, int dst_offset,
                        const float *src, int src_stride, int src_offset, size_t rows, int cols,
                        sp_error *err);

    /* Row gather for density control: for i < rows, c < cols:
     *   dst[i * cols + c] = idx[i] >= 0 ? src[idx[i] * cols + c] : 0
     * (idx a device array; dst and src do not overlap). */
    int (*gather_rows)(sp_device *dev, float *dst, const float *src, const int32_t *idx, size_t rows,
                       int cols, sp_error *err);

    /* 1 when any of the n values is NaN or Inf (out_bad HOST int), for the NaN guard. */
    int (*any_nonfinite)(sp_device *dev, const float *x, size_t n, int *out_bad, sp_error *err);
} tr_kernels;

/* The CPU table (cpu_kernels.c), the CUDA table (NULL when built without CUDA) and the one for a
 * device (never NULL for a device that exists). */
extern const tr_kernels tr_cpu_kernels;
const tr_kernels *tr_cuda_kernels(void);
const tr_kernels *tr_kernels_of(const sp_device *dev);

#ifdef __cplusplus
}
#endif
#endif
