/* Training losses and per-element kernels on the CPU: 3DGS's 0.8 L1 + 0.2 (1 - SSIM) with its
 * exact gradient, feature MSE, Adam, densification statistics. These are the reference the
 * CUDA versions (src/train/cuda/) are tested against, and what the loop runs on a CPU device.
 * SSIM (Wang et al. 2004) with an 11x11 Gaussian window (sigma 1.5), separable, "valid"
 * positions only, as gsplat's fused_ssim(padding="valid"). */
#include "train/train_internal.h"

#include <stdlib.h>
#include <string.h>

#define R_SSIM (SP_SSIM_WINDOW / 2)

static void ssim_window(float g[SP_SSIM_WINDOW])
{
    double w[SP_SSIM_WINDOW], sum = 0;
    for (int i = 0; i < SP_SSIM_WINDOW; i++) {
        double d = i - R_SSIM;
        w[i] = exp(-d * d / (2.0 * SP_SSIM_SIGMA * SP_SSIM_SIGMA));
        sum += w[i];
    }
    for (int i = 0; i < SP_SSIM_WINDOW; i++) g[i] = (float)(w[i] / sum);
}

typedef struct {
    const float *pred, *target;
    int stride, H, W, C, Ho, Wo;
    float g[SP_SSIM_WINDOW];
    float *hbuf;  /* [H][Wo][5C]: horizontal sums of x, y, xx, yy, xy */
    float *dbuf;  /* [Ho][Wo][3C]: dS/dmu_x, dS/dE[xx], dS/dE[xy] */
    float *vbuf;  /* [H][Wo][3C]: dbuf scattered back vertically */
    double *row_ssim, *row_l1, *row_mse; /* per-row partial sums (deterministic reduction) */
    float *v_pred;
    float l1_scale, ssim_scale;
} ssim_ctx;

static void pass_horizontal(void *vctx, long y, int tid)
{
    ssim_ctx *c = vctx;
    int C = c->C, Wo = c->Wo, S = c->stride;
    const float *x = c->pred + (size_t)y * c->W * S, *t = c->target + (size_t)y * c->W * C;
    float *out = c->hbuf + (size_t)y * Wo * 5 * C;
    double l1 = 0, mse = 0;
    for (int px = 0; px < c->W; px++)
        for (int ch = 0; ch < C; ch++) {
            double d = (double)x[px * S + ch] - t[px * C + ch];
            l1 += fabs(d);
            mse += d * d;
        }
    c->row_l1[y] = l1;
    c->row_mse[y] = mse;
    for (int ox = 0; ox < Wo; ox++) {
        float *o = out + (size_t)ox * 5 * C;
        for (int ch = 0; ch < C; ch++) {
            float sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
            for (int j = 0; j < SP_SSIM_WINDOW; j++) {
                float a = x[(ox + j) * S + ch], b = t[(ox + j) * C + ch], g = c->g[j];
                sx += g * a;
                sy += g * b;
                sxx += g * a * a;
                syy += g * b * b;
                sxy += g * a * b;
            }
            o[ch] = sx;
            o[C + ch] = sy;
            o[2 * C + ch] = sxx;
            o[3 * C + ch] = syy;
            o[4 * C + ch] = sxy;
        }
    }
}

/* Vertical sums give the local statistics at valid position (oy, ox); SSIM there and its partial
 * derivatives w.r.t. mu_x, E[x^2], E[xy] (y = target is constant). */
static void pass_vertical(void *vctx, long oy, int tid)
{
    ssim_ctx *c = vctx;
    int C = c->C, Wo = c->Wo, n5 = 5 * C;
    double ssum = 0;
    for (int ox = 0; ox < Wo; ox++)
        for (int ch = 0; ch < C; ch++) {
            float m[5] = {0, 0, 0, 0, 0};
            for (int j = 0; j < SP_SSIM_WINDOW; j++) {
                const float *h = c->hbuf + ((size_t)(oy + j) * Wo + ox) * n5 + ch;
                float g = c->g[j];
                for (int k = 0; k < 5; k++) m[k] += g * h[k * C];
            }
            float mx = m[0], my = m[1];
            float sxx = m[2] - mx * mx, syy = m[3] - my * my, sxy = m[4] - mx * my;
            float A1 = 2 * mx * my + SP_SSIM_C1, A2 = 2 * sxy + SP_SSIM_C2;
            float B1 = mx * mx + my * my + SP_SSIM_C1, B2 = sxx + syy + SP_SSIM_C2;
            float S = (A1 * A2) / (B1 * B2);
            ssum += S;
            if (c->dbuf) {
                float inv = 1.0f / (B1 * B2);
                float d_mx = 2 * my * (A2 - A1) * inv - 2 * mx * S / B1 + 2 * mx * S / B2;
                float *d = c->dbuf + ((size_t)oy * Wo + ox) * 3 * C + ch;
                d[0] = d_mx;
                d[C] = -S / B2;
                d[2 * C] = 2 * A1 * inv;
            }
        }
    c->row_ssim[oy] = ssum;
}

/* Transpose of the vertical correlation: row y gathers from valid rows oy = y - j. */
static void back_vertical(void *vctx, long y, int tid)
{
    ssim_ctx *c = vctx;
    int n3 = 3 * c->C, Wo = c->Wo;
    float *o = c->vbuf + (size_t)y * Wo * n3;
    memset(o, 0, (size_t)Wo * n3 * sizeof(float));
    for (int j = 0; j < SP_SSIM_WINDOW; j++) {
        long oy = y - j;
        if (oy < 0 || oy >= c->Ho) continue;
        const float *d = c->dbuf + (size_t)oy * Wo * n3;
        float g = c->g[j];
        for (int k = 0; k < Wo * n3; k++) o[k] += g * d[k];
    }
}

/* Transpose of the horizontal correlation, then the chain rule through x, x^2, xy, plus L1. */
static void back_horizontal(void *vctx, long y, int tid)
{
    ssim_ctx *c = vctx;
    int C = c->C, S = c->stride, Wo = c->Wo, n3 = 3 * C;
    const float *x = c->pred + (size_t)y * c->W * S, *t = c->target + (size_t)y * c->W * C;
    const float *vb = c->vbuf + (size_t)y * Wo * n3;
    float *v = c->v_pred + (size_t)y * c->W * S;
    for (int px = 0; px < c->W; px++)
        for (int ch = 0; ch < C; ch++) {
            float a0 = 0, a1 = 0, a2 = 0;
            for (int j = 0; j < SP_SSIM_WINDOW; j++) {
                int ox = px - j;
                if (ox < 0 || ox >= Wo) continue;
                const float *b = vb + (size_t)ox * n3 + ch;
                float g = c->g[j];
                a0 += g * b[0];
                a1 += g * b[C];
                a2 += g * b[2 * C];
            }
            float xv = x[px * S + ch], tv = t[px * C + ch], d = xv - tv;
            float dssim = a0 + 2 * xv * a1 + tv * a2;
            float sgn = d > 0 ? 1.0f : (d < 0 ? -1.0f : 0.0f);
            v[px * S + ch] = c->l1_scale * sgn + c->ssim_scale * dssim;
        }
}

int cpu_rgb_loss(sp_pool *pool, const float *pred, int pred_stride, const float *target, int H,
                 int W, int C, float ssim_lambda, float *scratch, float *v_pred, double stats[4],
                 sp_error *err)
{
    if (H < SP_SSIM_WINDOW || W < SP_SSIM_WINDOW || C < 1 || pred_stride < C)
        return sp_error_set(err, SP_E_ARG,
                            "rgb loss: image %dx%d with %d of %d channels (needs >= %dx%d)", W, H,
                            C, pred_stride, SP_SSIM_WINDOW, SP_SSIM_WINDOW);
    ssim_ctx c = {.pred = pred, .target = target, .stride = pred_stride, .H = H, .W = W, .C = C,
                  .Ho = H - 2 * R_SSIM, .Wo = W - 2 * R_SSIM, .v_pred = v_pred};
    ssim_window(c.g);
    size_t hw_o = (size_t)H * c.Wo * C;
    c.hbuf = scratch;
    c.dbuf = v_pred ? scratch + 5 * hw_o : NULL;
    c.vbuf = scratch + 8 * hw_o;
    double *rows = malloc(sizeof(double) * 3 * (size_t)H);
    if (!rows) return sp_error_set(err, SP_E_NOMEM, "rgb loss: out of memory");
    c.row_l1 = rows;
    c.row_mse = rows + H;
    c.row_ssim = rows + 2 * H;
    sp_pool_for(pool, H, pass_horizontal, &c);
    sp_pool_for(pool, c.Ho, pass_vertical, &c);
    double n = (double)H * W * C, n_valid = (double)c.Ho * c.Wo * C;
    double l1 = 0, mse = 0, ssim = 0;
    for (int y = 0; y < H; y++) l1 += c.row_l1[y], mse += c.row_mse[y];
    for (int y = 0; y < c.Ho; y++) ssim += c.row_ssim[y];
    l1 /= n;
    mse /= n;
    ssim /= n_valid;
    stats[0] = (1.0 - ssim_lambda) * l1 + ssim_lambda * (1.0 - ssim);
    stats[1] = l1;
    stats[2] = ssim;
    stats[3] = mse;
    if (v_pred) {
        c.l1_scale = (float)((1.0 - ssim_lambda) / n);
        c.ssim_scale = (float)(-ssim_lambda / n_valid);
        sp_pool_for(pool, H, back_vertical, &c);
        sp_pool_for(pool, H, back_horizontal, &c);
    }
    free(rows);
    return SP_OK;
}

int sp_train_rgb_loss(sp_pool *pool, const float *pred, int pred_stride, const float *target,
                      int H, int W, int C, float ssim_lambda, float *v_pred, double stats[4],
                      sp_error *err)
{
    if (H < 1 || W < 1 || C < 1)
        return sp_error_set(err, SP_E_ARG, "rgb loss: bad size %dx%dx%d", W, H, C);
    float *scratch = sp_alloc(SP_LOSS_SCRATCH_FLOATS(H, W, C) * sizeof(float));
    if (!scratch) return sp_error_set(err, SP_E_NOMEM, "rgb loss: out of memory for %dx%d", W, H);
    int rc = cpu_rgb_loss(pool, pred, pred_stride, target, H, W, C, ssim_lambda, scratch, v_pred,
                          stats, err);
    sp_free(scratch);
    return rc;
}

typedef struct {
    const float *pred, *target;
    int stride, offset, W, F;
    float scale;
    float *v_pred;
    double *rows;
} mse_ctx;

static void mse_row(void *vctx, long y, int tid)
{
    mse_ctx *c = vctx;
    const float *p = c->pred + (size_t)y * c->W * c->stride + c->offset;
    const float *t = c->target + (size_t)y * c->W * c->F;
    float *v = c->v_pred ? c->v_pred + (size_t)y * c->W * c->stride + c->offset : NULL;
    double s = 0;
    for (int x = 0; x < c->W; x++)
        for (int f = 0; f < c->F; f++) {
            float d = p[(size_t)x * c->stride + f] - t[(size_t)x * c->F + f];
            s += (double)d * d;
            if (v) v[(size_t)x * c->stride + f] = c->scale * d;
        }
    c->rows[y] = s;
}

int cpu_feature_mse(sp_pool *pool, const float *pred, int pred_stride, int offset,
                    const float *target, int H, int W, int F, float lambda, float *v_pred,
                    double *out_mse, sp_error *err)
{
    if (H < 1 || W < 1 || F < 1 || offset < 0 || offset + F > pred_stride)
        return sp_error_set(err, SP_E_ARG, "feature loss: %d channels at %d do not fit stride %d",
                            F, offset, pred_stride);
    double n = (double)H * W * F;
    mse_ctx c = {pred, target, pred_stride, offset, W, F, (float)(2.0 * lambda / n), v_pred, NULL};
    c.rows = malloc(sizeof(double) * (size_t)H);
    if (!c.rows) return sp_error_set(err, SP_E_NOMEM, "feature loss: out of memory");
    sp_pool_for(pool, H, mse_row, &c);
    double s = 0;
    for (int y = 0; y < H; y++) s += c.rows[y];
    free(c.rows);
    if (out_mse) *out_mse = s / n;
    return SP_OK;
}

typedef struct {
    const float *depth, *alpha, *target;
    int W;
    float scale;
    float *v_depth, *v_alpha;
    double *rows; /* [H][2]: sum |r|, count */
} depth_ctx;

/* The per-pixel term of train_kernels.h's depth loss: |d - t| above the alpha floor, the
 * alpha-weighted |depth - t alpha| / floor below it (continuous at the floor). */
static void depth_row(void *vctx, long y, int tid)
{
    depth_ctx *c = vctx;
    size_t o = (size_t)y * c->W;
    const float inv_floor = 1.0f / SP_DEPTH_MIN_ALPHA;
    double s = 0, n = 0;
    for (int x = 0; x < c->W; x++) {
        float t = c->target[o + x], a = c->alpha[o + x], vd = 0, va = 0;
        if (t > 0) {
            float S = c->depth[o + x];
            if (a >= SP_DEPTH_MIN_ALPHA) {
                float d = S / a, r = d - t;
                float g = r > 0 ? c->scale : (r < 0 ? -c->scale : 0.0f);
                s += fabs((double)r);
                vd = g / a;
                va = -g * d / a;
            } else {
                float r = S - t * a;
                float g = r > 0 ? c->scale * inv_floor : (r < 0 ? -c->scale * inv_floor : 0.0f);
                s += fabs((double)r) * inv_floor;
                vd = g;
                va = -g * t;
            }
            n += 1;
        }
        if (c->v_depth) {
            c->v_depth[o + x] = vd;
            c->v_alpha[o + x] = va;
        }
    }
    c->rows[2 * y] = s;
    c->rows[2 * y + 1] = n;
}

int cpu_depth_loss(sp_pool *pool, const float *depth, const float *alpha, const float *target,
                   int H, int W, float lambda, float *v_depth, float *v_alpha, double stats[3],
                   sp_error *err)
{
    if (H < 1 || W < 1) return sp_error_set(err, SP_E_ARG, "depth loss: bad size %dx%d", W, H);
    if (!depth || !alpha || !target || !v_depth != !v_alpha)
        return sp_error_set(err, SP_E_ARG, "depth loss: NULL buffer (v_depth and v_alpha go together)");
    double npx = (double)H * W;
    depth_ctx c = {depth, alpha, target, W, (float)(lambda / npx), v_depth, v_alpha, NULL};
    c.rows = malloc(sizeof(double) * 2 * (size_t)H);
    if (!c.rows) return sp_error_set(err, SP_E_NOMEM, "depth loss: out of memory");
    sp_pool_for(pool, H, depth_row, &c);
    double s = 0, n = 0;
    for (int y = 0; y < H; y++) s += c.rows[2 * y], n += c.rows[2 * y + 1];
    free(c.rows);
    stats[0] = lambda * s / npx;
    stats[1] = n > 0 ? s / n : 0;
    stats[2] = n;
    return SP_OK;
}

typedef struct {
    float *param, *m, *v;
    const float *grad;
    size_t n;
    float lr, b1, b2, eps, c1, c2;
} adam_ctx;

#define ADAM_CHUNK 65536

static void adam_chunk(void *vctx, long k, int tid)
{
    adam_ctx *c = vctx;
    size_t lo = (size_t)k * ADAM_CHUNK, hi = lo + ADAM_CHUNK < c->n ? lo + ADAM_CHUNK : c->n;
    for (size_t i = lo; i < hi; i++) {
        float g = c->grad[i];
        float m = c->b1 * c->m[i] + (1 - c->b1) * g;
        float v = c->b2 * c->v[i] + (1 - c->b2) * g * g;
        c->m[i] = m;
        c->v[i] = v;
        c->param[i] -= c->lr * (m / c->c1) / (sqrtf(v / c->c2) + c->eps);
    }
}

void cpu_adam_step(sp_pool *pool, float *param, const float *grad, float *m, float *v, size_t n,
                   float lr, float beta1, float beta2, float eps, int step)
{
    adam_ctx c = {param, m, v, grad, n, lr, beta1, beta2, eps,
                  (float)(1.0 - pow(beta1, step)), (float)(1.0 - pow(beta2, step))};
    sp_pool_for(pool, (long)((n + ADAM_CHUNK - 1) / ADAM_CHUNK), adam_chunk, &c);
}

void sp_train_adam_host(float *param, const float *grad, float *m, float *v, size_t n, float lr,
                        float beta1, float beta2, float eps, int step)
{
    cpu_adam_step(NULL, param, grad, m, v, n, lr, beta1, beta2, eps, step);
}

void cpu_densify_accumulate(const float *v_means2d, const int32_t *radii, size_t n, float scale_x,
                            float scale_y, float *grad2d_sum, float *count)
{
    for (size_t i = 0; i < n; i++) {
        if (radii[i] <= 0) continue;
        float gx = v_means2d[2 * i] * scale_x, gy = v_means2d[2 * i + 1] * scale_y;
        grad2d_sum[i] += sqrtf(gx * gx + gy * gy);
        count[i] += 1.0f;
    }
}

void cpu_copy_columns(float *dst, int dst_stride, int dst_offset, const float *src, int src_stride,
                      int src_offset, size_t rows, int cols)
{
    for (size_t r = 0; r < rows; r++)
        memcpy(dst + r * dst_stride + dst_offset, src + r * src_stride + src_offset,
               (size_t)cols * sizeof(float));
}

int cpu_any_nonfinite(const float *x, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i])) return 1;
    return 0;
}
