/* The trainer's per-element work on the GPU (the CUDA table of src/train/train_kernels.h): the 3DGS photometric
 * loss (L1 + SSIM with its exact gradient), feature MSE, Adam, densification statistics, column
 * packing and the NaN guard. Same semantics and the same separable SSIM formulation as the CPU
 * reference in src/train/loss.c:
 *   h pass   [H][Wo][5C]  horizontal window sums of x, y, x^2, y^2, xy
 *   v pass   [Ho][Wo][3C] SSIM at each valid position and dS/d(mu_x, E[x^2], E[xy])
 *   back v   [H][Wo][3C]  transpose of the vertical window
 *   back h   v_pred       transpose of the horizontal window, chain rule, plus the L1 term.
 * Scalar sums are accumulated in double (block reduction, then one atomic per block). Everything
 * runs on the device's stream. */
#include <cuda_runtime.h>
#include <math.h>
#include <stdint.h>

#include "device/cuda/device_cuda.h"
#include "train/train_kernels.h"

#define R_SSIM (SP_SSIM_WINDOW / 2)
#define TPB 256

#define CK(call, what)                                                                        \
    do {                                                                                      \
        cudaError_t e_ = (call);                                                              \
        if (e_ != cudaSuccess)                                                                \
            return sp_error_set(err, SP_E_DEVICE, "CUDA %s: %s", (what), cudaGetErrorString(e_)); \
    } while (0)

struct ssim_win {
    float g[SP_SSIM_WINDOW];
};

static ssim_win make_window(void)
{
    ssim_win w;
    double v[SP_SSIM_WINDOW], sum = 0;
    for (int i = 0; i < SP_SSIM_WINDOW; i++) {
        double d = i - R_SSIM;
        v[i] = exp(-d * d / (2.0 * SP_SSIM_SIGMA * SP_SSIM_SIGMA));
        sum += v[i];
    }
    for (int i = 0; i < SP_SSIM_WINDOW; i++) w.g[i] = (float)(v[i] / sum);
    return w;
}

/* Sums `v` over the block and adds it to *out (one double atomic per block). */
__device__ __forceinline__ void block_add(double v, double *out)
{
    __shared__ double s[TPB / 32];
    __syncthreads(); /* a previous call's thread 0 may still be reading s */
    for (int o = 16; o >= 1; o >>= 1) v += __shfl_xor_sync(0xffffffffu, v, o);
    if ((threadIdx.x & 31) == 0) s[threadIdx.x >> 5] = v;
    __syncthreads();
    if (threadIdx.x == 0) {
        double t = 0;
        for (int i = 0; i < TPB / 32; i++) t += s[i];
        atomicAdd(out, t);
    }
}

__global__ void k_l1_mse(const float *pred, int S, const float *target, size_t npix, int C,
                         double *sums)
{
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    double l1 = 0, mse = 0;
    if (k < npix * C) {
        size_t p = k / C;
        int ch = (int)(k - p * C);
        double d = (double)pred[p * S + ch] - target[k];
        l1 = fabs(d);
        mse = d * d;
    }
    block_add(l1, sums + 0);
    block_add(mse, sums + 1);
}

__global__ void k_ssim_h(const float *pred, int S, const float *target, int H, int W, int C,
                         int Wo, ssim_win w, float *hbuf)
{
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    if (k >= (size_t)H * Wo * C) return;
    int ch = (int)(k % C);
    size_t r = k / C;
    int ox = (int)(r % Wo), y = (int)(r / Wo);
    const float *x = pred + (size_t)y * W * S, *t = target + (size_t)y * W * C;
    float sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int j = 0; j < SP_SSIM_WINDOW; j++) {
        float a = x[(ox + j) * S + ch], b = t[(ox + j) * C + ch], g = w.g[j];
        sx += g * a;
        sy += g * b;
        sxx += g * a * a;
        syy += g * b * b;
        sxy += g * a * b;
    }
    float *o = hbuf + ((size_t)y * Wo + ox) * 5 * C + ch;
    o[0] = sx;
    o[C] = sy;
    o[2 * C] = sxx;
    o[3 * C] = syy;
    o[4 * C] = sxy;
}

__global__ void k_ssim_v(const float *hbuf, int Ho, int Wo, int C, ssim_win w, float *dbuf,
                         double *sum)
{
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    double s_out = 0;
    if (k < (size_t)Ho * Wo * C) {
        int ch = (int)(k % C);
        size_t r = k / C;
        int ox = (int)(r % Wo), oy = (int)(r / Wo);
        float m[5] = {0, 0, 0, 0, 0};
        for (int j = 0; j < SP_SSIM_WINDOW; j++) {
            const float *h = hbuf + ((size_t)(oy + j) * Wo + ox) * 5 * C + ch;
            float g = w.g[j];
            for (int q = 0; q < 5; q++) m[q] += g * h[q * C];
        }
        float mx = m[0], my = m[1];
        float sxx = m[2] - mx * mx, syy = m[3] - my * my, sxy = m[4] - mx * my;
        float A1 = 2 * mx * my + SP_SSIM_C1, A2 = 2 * sxy + SP_SSIM_C2;
        float B1 = mx * mx + my * my + SP_SSIM_C1, B2 = sxx + syy + SP_SSIM_C2;
        float Sv = (A1 * A2) / (B1 * B2);
        s_out = Sv;
        if (dbuf) {
            float inv = 1.0f / (B1 * B2);
            float d_mx = 2 * my * (A2 - A1) * inv - 2 * mx * Sv / B1 + 2 * mx * Sv / B2;
            float *d = dbuf + ((size_t)oy * Wo + ox) * 3 * C + ch;
            d[0] = d_mx;
            d[C] = -Sv / B2;
            d[2 * C] = 2 * A1 * inv;
        }
    }
    block_add(s_out, sum);
}

__global__ void k_back_v(const float *dbuf, int H, int Ho, int Wo, int C, ssim_win w, float *vbuf)
{
    size_t n3 = (size_t)3 * C * Wo;
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    if (k >= (size_t)H * n3) return;
    int y = (int)(k / n3);
    size_t q = k - (size_t)y * n3;
    float acc = 0;
    for (int j = 0; j < SP_SSIM_WINDOW; j++) {
        int oy = y - j;
        if (oy < 0 || oy >= Ho) continue;
        acc += w.g[j] * dbuf[(size_t)oy * n3 + q];
    }
    vbuf[k] = acc;
}

__global__ void k_back_h(const float *pred, int S, const float *target, const float *vbuf, int H,
                         int W, int C, int Wo, ssim_win w, float l1_scale, float ssim_scale,
                         float *v_pred)
{
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    if (k >= (size_t)H * W * C) return;
    int ch = (int)(k % C);
    size_t p = k / C;
    int px = (int)(p % W), y = (int)(p / W);
    const float *vb = vbuf + (size_t)y * Wo * 3 * C;
    float a0 = 0, a1 = 0, a2 = 0;
    for (int j = 0; j < SP_SSIM_WINDOW; j++) {
        int ox = px - j;
        if (ox < 0 || ox >= Wo) continue;
        const float *b = vb + (size_t)ox * 3 * C + ch;
        float g = w.g[j];
        a0 += g * b[0];
        a1 += g * b[C];
        a2 += g * b[2 * C];
    }
    float xv = pred[p * S + ch], tv = target[k], d = xv - tv;
    float dssim = a0 + 2 * xv * a1 + tv * a2;
    float sgn = d > 0 ? 1.0f : (d < 0 ? -1.0f : 0.0f);
    v_pred[p * S + ch] = l1_scale * sgn + ssim_scale * dssim;
}

static unsigned nblk(size_t n) { return (unsigned)((n + TPB - 1) / TPB); }

static int rgb_loss(sp_device *dev, const float *pred, int pred_stride, const float *target, int H,
                                int W, int C, float ssim_lambda, float *scratch, float *v_pred,
                                double stats[4], sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (H < SP_SSIM_WINDOW || W < SP_SSIM_WINDOW || C < 1 || pred_stride < C)
        return sp_error_set(err, SP_E_ARG,
                            "rgb loss: image %dx%d with %d of %d channels (needs >= %dx%d)", W, H,
                            C, pred_stride, SP_SSIM_WINDOW, SP_SSIM_WINDOW);
    if (!pred || !target || !scratch || !stats)
        return sp_error_set(err, SP_E_ARG, "rgb loss: NULL buffer");
    int Ho = H - 2 * R_SSIM, Wo = W - 2 * R_SSIM;
    size_t hw_o = (size_t)H * Wo * C;
    float *hbuf = scratch, *dbuf = v_pred ? scratch + 5 * hw_o : NULL, *vbuf = scratch + 8 * hw_o;
    double *sums = (double *)(scratch + 12 * hw_o); /* l1, mse, ssim; inside the 16 HWC floats */
    ssim_win w = make_window();
    CK(cudaMemsetAsync(sums, 0, 3 * sizeof(double), st), "clearing loss sums");
    size_t npix = (size_t)H * W;
    k_l1_mse<<<nblk(npix * C), TPB, 0, st>>>(pred, pred_stride, target, npix, C, sums);
    k_ssim_h<<<nblk(hw_o), TPB, 0, st>>>(pred, pred_stride, target, H, W, C, Wo, w, hbuf);
    k_ssim_v<<<nblk((size_t)Ho * Wo * C), TPB, 0, st>>>(hbuf, Ho, Wo, C, w, dbuf, sums + 2);
    CK(cudaGetLastError(), "SSIM kernels");
    double n = (double)npix * C, n_valid = (double)Ho * Wo * C;
    if (v_pred) {
        float l1_scale = (float)((1.0 - ssim_lambda) / n);
        float ssim_scale = (float)(-ssim_lambda / n_valid);
        k_back_v<<<nblk((size_t)H * Wo * 3 * C), TPB, 0, st>>>(dbuf, H, Ho, Wo, C, w, vbuf);
        k_back_h<<<nblk(npix * C), TPB, 0, st>>>(pred, pred_stride, target, vbuf, H, W, C, Wo, w,
                                          l1_scale, ssim_scale, v_pred);
        CK(cudaGetLastError(), "SSIM backward kernels");
    }
    double h[3];
    CK(cudaMemcpyAsync(h, sums, sizeof(h), cudaMemcpyDeviceToHost, st), "reading loss sums");
    CK(cudaStreamSynchronize(st), "reading loss sums");
    double l1 = h[0] / n, mse = h[1] / n, ssim = h[2] / n_valid;
    stats[0] = (1.0 - ssim_lambda) * l1 + ssim_lambda * (1.0 - ssim);
    stats[1] = l1;
    stats[2] = ssim;
    stats[3] = mse;
    return 0;
}

__global__ void k_feat_mse(const float *pred, int S, int off, const float *target, size_t npix,
                           int F, float scale, float *v_pred, double *sum)
{
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    double s = 0;
    if (k < npix * F) {
        size_t p = k / F;
        int f = (int)(k - p * F);
        float d = pred[p * S + off + f] - target[k];
        s = (double)d * d;
        if (v_pred) v_pred[p * S + off + f] = scale * d;
    }
    block_add(s, sum);
}

static int feature_mse(sp_device *dev, const float *pred, int pred_stride, int offset,
                                   const float *target, int H, int W, int F, float lambda,
                                   float *v_pred, double *out_mse, sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (H < 1 || W < 1 || F < 1 || offset < 0 || offset + F > pred_stride)
        return sp_error_set(err, SP_E_ARG, "feature loss: %d channels at %d do not fit stride %d",
                            F, offset, pred_stride);
    if (!pred || !target) return sp_error_set(err, SP_E_ARG, "feature loss: NULL buffer");
    size_t npix = (size_t)H * W;
    double n = (double)npix * F;
    double *sum = NULL;
    CK(cudaMallocAsync((void **)&sum, sizeof(double), st), "allocating the loss sum");
    cudaMemsetAsync(sum, 0, sizeof(double), st);
    k_feat_mse<<<nblk(npix * F), TPB, 0, st>>>(pred, pred_stride, offset, target, npix, F,
                                        (float)(2.0 * lambda / n), v_pred, sum);
    cudaError_t e = cudaGetLastError();
    double h = 0;
    if (e == cudaSuccess) e = cudaMemcpyAsync(&h, sum, sizeof(h), cudaMemcpyDeviceToHost, st);
    cudaFreeAsync(sum, st);
    if (e == cudaSuccess) e = cudaStreamSynchronize(st);
    if (e != cudaSuccess)
        return sp_error_set(err, SP_E_DEVICE, "CUDA feature loss: %s", cudaGetErrorString(e));
    if (out_mse) *out_mse = h / n;
    return 0;
}

/* Depth loss (train_kernels.h): |depth / alpha - t| where t > 0 and alpha >= SP_DEPTH_MIN_ALPHA,
 * |depth - t alpha| / SP_DEPTH_MIN_ALPHA below it; sums of the terms and the pixel count in
 * double as the CPU's per-row sums. */
__global__ void k_depth_loss(const float *depth, const float *alpha, const float *target,
                             size_t npix, float scale, float *v_depth, float *v_alpha, double *sums)
{
    size_t p = (size_t)blockIdx.x * TPB + threadIdx.x;
    double s = 0, c = 0;
    if (p < npix) {
        const float inv_floor = 1.0f / SP_DEPTH_MIN_ALPHA;
        float t = target[p], a = alpha[p], vd = 0.0f, va = 0.0f;
        if (t > 0.0f) {
            float S = depth[p];
            if (a >= SP_DEPTH_MIN_ALPHA) {
                float d = S / a, r = d - t;
                float g = r > 0.0f ? scale : (r < 0.0f ? -scale : 0.0f);
                s = fabs((double)r);
                vd = g / a;
                va = -g * d / a;
            } else {
                float r = S - t * a;
                float g = r > 0.0f ? scale * inv_floor : (r < 0.0f ? -scale * inv_floor : 0.0f);
                s = fabs((double)r) * inv_floor;
                vd = g;
                va = -g * t;
            }
            c = 1.0;
        }
        if (v_depth) {
            v_depth[p] = vd;
            v_alpha[p] = va;
        }
    }
    block_add(s, sums + 0);
    block_add(c, sums + 1);
}

static int depth_loss(sp_device *dev, const float *depth, const float *alpha, const float *target,
                      int H, int W, float lambda, float *v_depth, float *v_alpha, double stats[3],
                      sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (H < 1 || W < 1) return sp_error_set(err, SP_E_ARG, "depth loss: bad size %dx%d", W, H);
    if (!depth || !alpha || !target || !v_depth != !v_alpha)
        return sp_error_set(err, SP_E_ARG, "depth loss: NULL buffer (v_depth and v_alpha go together)");
    size_t npix = (size_t)H * W;
    double *sums = NULL;
    CK(cudaMallocAsync((void **)&sums, 2 * sizeof(double), st), "allocating the depth loss sums");
    cudaMemsetAsync(sums, 0, 2 * sizeof(double), st);
    k_depth_loss<<<nblk(npix), TPB, 0, st>>>(depth, alpha, target, npix, (float)(lambda / (double)npix),
                                             v_depth, v_alpha, sums);
    cudaError_t e = cudaGetLastError();
    double h[2] = {0, 0};
    if (e == cudaSuccess) e = cudaMemcpyAsync(h, sums, sizeof(h), cudaMemcpyDeviceToHost, st);
    cudaFreeAsync(sums, st);
    if (e == cudaSuccess) e = cudaStreamSynchronize(st);
    if (e != cudaSuccess)
        return sp_error_set(err, SP_E_DEVICE, "CUDA depth loss: %s", cudaGetErrorString(e));
    stats[0] = lambda * h[0] / (double)npix;
    stats[1] = h[1] > 0 ? h[0] / h[1] : 0;
    stats[2] = h[1];
    return 0;
}

__global__ void k_adam(float *param, const float *grad, float *m, float *v, size_t n, float lr,
                       float b1, float b2, float eps, float c1, float c2)
{
    size_t i = (size_t)blockIdx.x * TPB + threadIdx.x;
    if (i >= n) return;
    float g = grad[i];
    float mi = b1 * m[i] + (1 - b1) * g;
    float vi = b2 * v[i] + (1 - b2) * g * g;
    m[i] = mi;
    v[i] = vi;
    param[i] -= lr * (mi / c1) / (sqrtf(vi / c2) + eps);
}

static int adam_step(sp_device *dev, float *param, const float *grad, float *m, float *v, size_t n,
                                 float lr, float beta1, float beta2, float eps, int step,
                                 sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (step < 1) return sp_error_set(err, SP_E_ARG, "adam: step %d (must be >= 1)", step);
    if (n == 0) return 0;
    if (!param || !grad || !m || !v) return sp_error_set(err, SP_E_ARG, "adam: NULL buffer");
    float c1 = (float)(1.0 - pow(beta1, step)), c2 = (float)(1.0 - pow(beta2, step));
    k_adam<<<nblk(n), TPB, 0, st>>>(param, grad, m, v, n, lr, beta1, beta2, eps, c1, c2);
    CK(cudaGetLastError(), "adam step");
    return 0;
}

__global__ void k_densify(const float *v2, const int32_t *radii, size_t n, float sx, float sy,
                          float *gsum, float *count)
{
    size_t i = (size_t)blockIdx.x * TPB + threadIdx.x;
    if (i >= n || radii[i] <= 0) return;
    float gx = v2[2 * i] * sx, gy = v2[2 * i + 1] * sy;
    gsum[i] += sqrtf(gx * gx + gy * gy);
    count[i] += 1.0f;
}

static int densify_accumulate(sp_device *dev, const float *v_means2d, const int32_t *radii, size_t n,
                                          float scale_x, float scale_y, float *grad2d_sum,
                                          float *count, sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (n == 0) return 0;
    if (!v_means2d || !radii || !grad2d_sum || !count)
        return sp_error_set(err, SP_E_ARG, "densify stats: NULL buffer");
    k_densify<<<nblk(n), TPB, 0, st>>>(v_means2d, radii, n, scale_x, scale_y, grad2d_sum, count);
    CK(cudaGetLastError(), "densify statistics");
    return 0;
}

__global__ void k_copy_cols(float *dst, int ds, int doff, const float *src, int ss, int soff,
                            size_t rows, int cols)
{
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    if (k >= rows * cols) return;
    size_t r = k / cols;
    int c = (int)(k - r * cols);
    dst[r * ds + doff + c] = src[r * ss + soff + c];
}

static int copy_columns(sp_device *dev, float *dst, int dst_stride, int dst_offset, const float *src,
                                    int src_stride, int src_offset, size_t rows, int cols,
                                    sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (rows == 0 || cols == 0) return 0;
    if (!dst || !src || cols < 0 || dst_offset < 0 || src_offset < 0 ||
        dst_offset + cols > dst_stride || src_offset + cols > src_stride)
        return sp_error_set(err, SP_E_ARG,
                            "copy columns: %d columns at %d/%d do not fit strides %d/%d", cols,
                            dst_offset, src_offset, dst_stride, src_stride);
    k_copy_cols<<<nblk(rows * (size_t)cols), TPB, 0, st>>>(dst, dst_stride, dst_offset, src, src_stride,
                                                    src_offset, rows, cols);
    CK(cudaGetLastError(), "column copy");
    return 0;
}

__global__ void k_gather_rows(float *dst, const float *src, const int32_t *idx, size_t rows, int cols)
{
    size_t k = (size_t)blockIdx.x * TPB + threadIdx.x;
    if (k >= rows * cols) return;
    size_t r = k / cols;
    int c = (int)(k - r * cols);
    int32_t j = idx[r];
    dst[k] = j >= 0 ? src[(size_t)j * cols + c] : 0.f;
}

static int gather_rows(sp_device *dev, float *dst, const float *src, const int32_t *idx, size_t rows, int cols,
                       sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (rows == 0 || cols <= 0) return 0;
    if (!dst || !src || !idx) return sp_error_set(err, SP_E_ARG, "gather rows: NULL buffer");
    k_gather_rows<<<nblk(rows * (size_t)cols), TPB, 0, st>>>(dst, src, idx, rows, cols);
    CK(cudaGetLastError(), "row gather");
    return 0;
}

__global__ void k_nonfinite(const float *x, size_t n, int *flag)
{
    size_t i = (size_t)blockIdx.x * TPB + threadIdx.x;
    bool bad = i < n && (__float_as_uint(x[i]) & 0x7f800000u) == 0x7f800000u;
    if (__syncthreads_or(bad) && threadIdx.x == 0) *flag = 1;
}

static int any_nonfinite(sp_device *dev, const float *x, size_t n, int *out_bad, sp_error *err)
{
    cudaStream_t st = sp_cuda_stream(dev);
    if (!out_bad) return sp_error_set(err, SP_E_ARG, "nonfinite check: out_bad is NULL");
    *out_bad = 0;
    if (n == 0) return 0;
    if (!x) return sp_error_set(err, SP_E_ARG, "nonfinite check: NULL buffer");
    int *flag = NULL;
    CK(cudaMallocAsync((void **)&flag, sizeof(int), st), "allocating the NaN flag");
    cudaMemsetAsync(flag, 0, sizeof(int), st);
    k_nonfinite<<<nblk(n), TPB, 0, st>>>(x, n, flag);
    cudaError_t e = cudaGetLastError();
    int h = 0;
    if (e == cudaSuccess) e = cudaMemcpyAsync(&h, flag, sizeof(int), cudaMemcpyDeviceToHost, st);
    cudaFreeAsync(flag, st);
    if (e == cudaSuccess) e = cudaStreamSynchronize(st);
    if (e != cudaSuccess)
        return sp_error_set(err, SP_E_DEVICE, "CUDA NaN check: %s", cudaGetErrorString(e));
    *out_bad = h;
    return 0;
}

static const tr_kernels cuda_kernels = {rgb_loss,     feature_mse,        depth_loss,
                                        adam_step,    densify_accumulate, copy_columns,
                                        gather_rows,  any_nonfinite};

extern "C" const tr_kernels *tr_cuda_kernels(void) { return &cuda_kernels; }
