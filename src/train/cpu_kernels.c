/* The CPU table of the train module's per-element kernels (train_kernels.h): the functions of
 * loss.c on the device's pool, with the argument checks the CUDA entries make, so both tables
 * accept and refuse the same calls. */
#include "device/device_impl.h"
#include "train/train_internal.h"

#include <string.h>

static int rgb_loss(sp_device *dev, const float *pred, int stride, const float *target, int H,
                    int W, int C, float lambda, float *scratch, float *v_pred, double stats[4],
                    sp_error *err)
{
    return cpu_rgb_loss(dev->pool, pred, stride, target, H, W, C, lambda, scratch, v_pred, stats, err);
}

static int feature_mse(sp_device *dev, const float *pred, int stride, int off, const float *target,
                       int H, int W, int F, float lambda, float *v_pred, double *mse, sp_error *err)
{
    return cpu_feature_mse(dev->pool, pred, stride, off, target, H, W, F, lambda, v_pred, mse, err);
}

static int depth_loss(sp_device *dev, const float *depth, const float *alpha, const float *target,
                      int H, int W, float lambda, float *v_depth, float *v_alpha, double stats[3],
                      sp_error *err)
{
    return cpu_depth_loss(dev->pool, depth, alpha, target, H, W, lambda, v_depth, v_alpha, stats, err);
}

static int adam_step(sp_device *dev, float *p, const float *g, float *m, float *v, size_t n,
                     float lr, float b1, float b2, float eps, int step, sp_error *err)
{
    if (step < 1) return sp_error_set(err, SP_E_ARG, "adam: step %d (must be >= 1)", step);
    cpu_adam_step(dev->pool, p, g, m, v, n, lr, b1, b2, eps, step);
    return 0;
}

static int densify_accumulate(sp_device *dev, const float *v_means2d, const int32_t *radii,
                              size_t n, float sx, float sy, float *grad2d, float *count,
                              sp_error *err)
{
    cpu_densify_accumulate(v_means2d, radii, n, sx, sy, grad2d, count);
    return 0;
}

static int copy_columns(sp_device *dev, float *dst, int ds, int doff, const float *src, int ss,
                        int soff, size_t rows, int cols, sp_error *err)
{
    if (rows == 0 || cols == 0) return 0;
    if (cols < 0 || doff < 0 || soff < 0 || doff + cols > ds || soff + cols > ss)
        return sp_error_set(err, SP_E_ARG, "copy columns: %d columns at %d/%d do not fit strides %d/%d",
                            cols, doff, soff, ds, ss);
    cpu_copy_columns(dst, ds, doff, src, ss, soff, rows, cols);
    return 0;
}

static int gather_rows(sp_device *dev, float *dst, const float *src, const int32_t *idx, size_t rows, int cols,
                       sp_error *err)
{
    (void)dev;
    if (rows == 0 || cols <= 0) return 0;
    if (!dst || !src || !idx) return sp_error_set(err, SP_E_ARG, "gather rows: NULL buffer");
    for (size_t i = 0; i < rows; i++) {
        if (idx[i] >= 0) memcpy(dst + i * (size_t)cols, src + (size_t)idx[i] * (size_t)cols, sizeof(float) * (size_t)cols);
        else memset(dst + i * (size_t)cols, 0, sizeof(float) * (size_t)cols);
    }
    return 0;
}

static int any_nonfinite(sp_device *dev, const float *x, size_t n, int *out_bad, sp_error *err)
{
    *out_bad = cpu_any_nonfinite(x, n);
    return 0;
}

const tr_kernels tr_cpu_kernels = {rgb_loss,     feature_mse,        depth_loss,
                                   adam_step,    densify_accumulate, copy_columns,
                                   gather_rows,  any_nonfinite};

const tr_kernels *tr_kernels_of(const sp_device *dev)
{
    return sp_device_kind_of(dev) == SP_DEVICE_CUDA ? tr_cuda_kernels() : &tr_cpu_kernels;
}
