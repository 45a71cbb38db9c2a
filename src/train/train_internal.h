/* Private to the train module: CPU versions of the per-element kernels declared for CUDA in
 * train_kernels.h (same semantics, host pointers, a thread pool), the checkpoint format, and a
 * small deterministic RNG. */
#ifndef SP_TRAIN_INTERNAL_H
#define SP_TRAIN_INTERNAL_H

#include "semsplat/train.h"
#include "train/train_kernels.h"

int cpu_rgb_loss(sp_pool *pool, const float *pred, int pred_stride, const float *target, int H,
                 int W, int C, float ssim_lambda, float *scratch, float *v_pred, double stats[4],
                 sp_error *err);
int cpu_feature_mse(sp_pool *pool, const float *pred, int pred_stride, int offset,
                    const float *target, int H, int W, int F, float lambda, float *v_pred,
                    double *out_mse, sp_error *err);
int cpu_depth_loss(sp_pool *pool, const float *depth, const float *alpha, const float *target,
                   int H, int W, float lambda, float *v_depth, float *v_alpha, double stats[3],
                   sp_error *err);
void cpu_adam_step(sp_pool *pool, float *param, const float *grad, float *m, float *v, size_t n,
                   float lr, float beta1, float beta2, float eps, int step);
void cpu_densify_accumulate(const float *v_means2d, const int32_t *radii, size_t n, float scale_x,
                            float scale_y, float *grad2d_sum, float *count);
void cpu_copy_columns(float *dst, int dst_stride, int dst_offset, const float *src, int src_stride,
                      int src_offset, size_t rows, int cols);
int cpu_any_nonfinite(const float *x, size_t n);

/* xorshift64* and a Box-Muller normal; state must be nonzero. */
static inline uint64_t tr_rng_next(uint64_t *s)
{
    uint64_t x = *s;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *s = x;
    return x * 2685821657736338717ULL;
}
static inline double tr_uniform(uint64_t *s) { return (double)(tr_rng_next(s) >> 11) * (1.0 / 9007199254740992.0); }
static inline double tr_normal(uint64_t *s)
{
    double u1 = tr_uniform(s), u2 = tr_uniform(s);
    if (u1 < 1e-300) u1 = 1e-300;
    return sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
}
static inline uint64_t tr_seed(uint64_t seed) { return seed * 0x9E3779B97F4A7C15ULL + 0x1234567ULL; }

/* Checkpoint: one binary file (params, Adam moments, step, rng) written atomically. */
typedef struct tr_checkpoint {
    int step;
    uint64_t rng;
    sp_splat params, m, v; /* m, v shaped like params */
} tr_checkpoint;

/* Every numeric option in its range (options.c); SP_E_ARG naming the option otherwise. */
int tr_check_option_ranges(const sp_train_options *o, sp_error *err);

int tr_checkpoint_write(const char *path, int step, uint64_t rng, const sp_splat *params,
                        const sp_splat *m, const sp_splat *v, sp_error *err);
int tr_checkpoint_read(const char *path, tr_checkpoint *ck, sp_error *err);
void tr_checkpoint_free(tr_checkpoint *ck);

/* densify.c: a density-control step as a plan (tr_densify_plan_make reads s's means, quats,
 * log-scales and opacities and the statistics, draws the split samples from rng, and decides
 * exactly as sp_train_densify_host, which applies the same plan on the host). Output row i copies
 * input row src[i], with Adam moments kept when keep_moments[i] (else zero) and its own means
 * and log-scales [i][3] (moved and shrunk for split children, the input's otherwise). */
typedef struct tr_densify_plan {
    size_t n_out;
    int32_t *src;
    uint8_t *keep_moments;
    float *means, *log_scales;
} tr_densify_plan;

int tr_densify_plan_make(const sp_splat *s, const float *grad2d_sum, const float *count,
                         const sp_train_options *opt, float scene_scale, int step, uint64_t *rng,
                         tr_densify_plan *plan, sp_densify_stats *st, sp_error *err);
void tr_densify_plan_free(tr_densify_plan *p);

#endif
