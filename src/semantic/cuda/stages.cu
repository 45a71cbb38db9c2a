/* The semantic stages of a GPU query engine on the device: the multi-view stage's per-pixel
 * scoring, relevant-pixel selection (eroded), back-projection and order-keeping compaction, and
 * the heatmap's relevancy and colour overlay. Host code in localize.c / heatmap.c does the same
 * for CPU engines; this file is compiled without FMA contraction and with IEEE division
 * (CMakeLists.txt SP_CUDA_EXACT_SOURCES), so back-projection and colours round like the host's;
 * only the scores differ by float rounding (rsqrtf, expf). */
#include <cub/cub.cuh>
#include <stdlib.h>
#include <string.h>

#include "semantic/cuda/score.cuh"
#include "semantic/overlay.h"

/* One view of the batch: its pixels start at pix0 of the concatenated buffers. */
struct view_params {
    int w, h;
    unsigned long long pix0;
    float fx, fy, cx, cy, t[3], Rt[9];
};

/* raw, rel per pixel (-1 / 0.5 where alpha <= 0.5) and keep = the relevance test. */
__global__ void k_score_pixels(const __grid_constant__ score_params sp, const view_params *__restrict__ vp,
                               const float *__restrict__ feat, const float *__restrict__ depth,
                               const float *__restrict__ alpha, float thr_raw, float thr_rel,
                               float *__restrict__ raw, float *__restrict__ rel, uint8_t *__restrict__ keep)
{
    const view_params v = vp[blockIdx.y];
    size_t p = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= (size_t)v.w * v.h) return;
    size_t g = v.pix0 + p;
    float a = alpha[g], s = -1.f, r = 0.5f;
    if (a > 0.5f) score_one(sp, feat + g * (size_t)sp.D, a, &s, &r);
    raw[g] = s, rel[g] = r;
    keep[g] = s >= thr_raw && r >= thr_rel && a > 0.9f && depth[g] > 0;
}

/* flag = kept with its four neighbours (pixels at the border never are). */
__global__ void k_erode(const view_params *__restrict__ vp, const uint8_t *__restrict__ keep,
                        uint32_t *__restrict__ flag)
{
    const view_params v = vp[blockIdx.y];
    size_t p = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= (size_t)v.w * v.h) return;
    int x = (int)(p % v.w), y = (int)(p / v.w);
    const uint8_t *k = keep + v.pix0;
    uint32_t f = x >= 1 && y >= 1 && x + 1 < v.w && y + 1 < v.h && k[p] && k[p - 1] && k[p + 1] &&
                 k[p - v.w] && k[p + v.w];
    flag[v.pix0 + p] = f;
}

/* Flagged pixels back-projected with their expected depth into slot at[g] - 1 (at: inclusive
 * scan of the flags), with the weight and confidence of localize.c. */
__global__ void k_backproject(const view_params *__restrict__ vp, const uint32_t *__restrict__ flag,
                              const uint32_t *__restrict__ at, const float *__restrict__ depth,
                              const float *__restrict__ alpha, const float *__restrict__ raw,
                              const float *__restrict__ rel, float *__restrict__ pts,
                              float *__restrict__ w, float *__restrict__ cf)
{
    const view_params v = vp[blockIdx.y];
    size_t p = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= (size_t)v.w * v.h) return;
    size_t g = v.pix0 + p;
    if (!flag[g]) return;
    int x = (int)(p % v.w), y = (int)(p / v.w);
    size_t m = at[g] - 1;
    float z = depth[g];
    float xc[3] = {((float)x + 0.5f - v.cx) / v.fx * z - v.t[0], ((float)y + 0.5f - v.cy) / v.fy * z - v.t[1],
                   z - v.t[2]};
    for (int r = 0; r < 3; r++)
        pts[3 * m + r] = v.Rt[3 * r] * xc[0] + v.Rt[3 * r + 1] * xc[1] + v.Rt[3 * r + 2] * xc[2];
    w[m] = (rel[g] - 0.5f + 1e-3f) * 2.0f * alpha[g] * (z / v.fx) * (z / v.fy);
    cf[m] = raw[g];
}

/* Carves the work scratch into aligned pieces. */
static void *carve(char **at, size_t bytes)
{
    void *p = *at;
    *at += (bytes + 255) & ~(size_t)255;
    return p;
}

static int download_points(sp_device *dev, size_t m, const float *d_pts, const float *d_w,
                           const float *d_cf, float **pts, float **w, float **cf, sp_error *err)
{
    *pts = (float *)malloc(sizeof(float) * 3 * m);
    *w = (float *)malloc(sizeof(float) * m);
    *cf = (float *)malloc(sizeof(float) * m);
    int rc = *pts && *w && *cf ? 0 : sp_error_set(err, SP_E_NOMEM, "multi-view: out of memory for %zu points", m);
    if (!rc) rc = sp_device_download(dev, *pts, d_pts, sizeof(float) * 3 * m, err);
    if (!rc) rc = sp_device_download(dev, *w, d_w, sizeof(float) * m, err);
    if (!rc) rc = sp_device_download(dev, *cf, d_cf, sizeof(float) * m, err);
    if (rc) {
        free(*pts), free(*w), free(*cf);
        *pts = *w = *cf = NULL;
    }
    return rc;
}

extern "C" int sem_cuda_view_points(sp_device *dev, sp_device_scratch *work, const sp_sem_scorer *sc,
                                    float thr_raw, float thr_rel, const sp_camera *cams, int nv,
                                    const float *d_feat, const float *d_depth, const float *d_alpha,
                                    float **pts, float **w, float **cf, size_t *m, double ms[2],
                                    sp_error *err)
{
    *pts = *w = *cf = NULL;
    *m = 0;
    ms[0] = ms[1] = 0;
    score_params sp;
    int rc = score_params_fill(sc, &sp, err);
    if (rc || nv <= 0) return rc;
    view_params *vp = (view_params *)calloc((size_t)nv, sizeof *vp);
    if (!vp) return sp_error_set(err, SP_E_NOMEM, "multi-view: out of memory");
    size_t total = 0, max_np = 0;
    for (int q = 0; q < nv; q++) {
        const sp_camera *c = &cams[q];
        view_params *v = &vp[q];
        v->w = c->width, v->h = c->height, v->pix0 = total;
        v->fx = c->fx, v->fy = c->fy, v->cx = c->cx, v->cy = c->cy;
        memcpy(v->t, c->t, sizeof v->t);
        sp_mat3_transpose(c->R, v->Rt);
        size_t np = (size_t)c->width * c->height;
        total += np;
        if (np > max_np) max_np = np;
    }
    if (total >= 0xffffffffull) {
        free(vp);
        return sp_error_set(err, SP_E_ARG, "multi-view: %zu pixels exceed 2^32", total);
    }
    cudaStream_t st = sp_cuda_stream(dev);
    size_t scan_bytes = 0;
    cub::DeviceScan::InclusiveSum(NULL, scan_bytes, (const uint32_t *)NULL, (uint32_t *)NULL, (int64_t)total);
    size_t need = 0, fb = sizeof(float) * total, ub = sizeof(uint32_t) * total;
    size_t sizes[] = {sizeof *vp * nv, fb, fb, total, ub, ub, scan_bytes, 3 * fb, fb, fb};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) need += (sizes[i] + 255) & ~(size_t)255;
    if ((rc = sp_device_scratch_reserve(dev, work, need, err))) {
        free(vp);
        return rc;
    }
    char *at = (char *)work->ptr;
    view_params *d_vp = (view_params *)carve(&at, sizes[0]);
    float *raw = (float *)carve(&at, fb), *rel = (float *)carve(&at, fb);
    uint8_t *keep = (uint8_t *)carve(&at, total);
    uint32_t *flag = (uint32_t *)carve(&at, ub), *scan = (uint32_t *)carve(&at, ub);
    void *tmp = carve(&at, scan_bytes);
    float *d_pts = (float *)carve(&at, 3 * fb), *d_w = (float *)carve(&at, fb), *d_cf = (float *)carve(&at, fb);
    rc = sp_device_upload(dev, d_vp, vp, sizes[0], err);
    free(vp);
    if (rc) return rc;
    double t0 = sp_time_now();
    dim3 grid((unsigned)((max_np + 255) / 256), (unsigned)nv);
    k_score_pixels<<<grid, 256, 0, st>>>(sp, d_vp, d_feat, d_depth, d_alpha, thr_raw, thr_rel, raw, rel, keep);
    SP_CUDA_LAUNCHED(err, "multi-view: scoring pixels");
    k_erode<<<grid, 256, 0, st>>>(d_vp, keep, flag);
    SP_CUDA_LAUNCHED(err, "multi-view: eroding the relevant pixels");
    if ((rc = sp_device_sync(dev, err))) return rc;
    double t1 = sp_time_now();
    SP_CUDA_CHECK(cub::DeviceScan::InclusiveSum(tmp, scan_bytes, flag, scan, (int64_t)total, st), err,
                  "multi-view: scanning the relevant pixels");
    k_backproject<<<grid, 256, 0, st>>>(d_vp, flag, scan, d_depth, d_alpha, raw, rel, d_pts, d_w, d_cf);
    SP_CUDA_LAUNCHED(err, "multi-view: back-projecting");
    uint32_t count = 0;
    rc = sp_device_download(dev, &count, scan + total - 1, sizeof count, err);
    if (!rc && count > 0) rc = download_points(dev, count, d_pts, d_w, d_cf, pts, w, cf, err);
    if (!rc) *m = count;
    ms[0] = (t1 - t0) * 1e3;
    ms[1] = (sp_time_now() - t1) * 1e3;
    return rc;
}

/* ---- heatmaps ------------------------------------------------------------------------------------ */

__global__ void k_interleave(size_t n, const float *__restrict__ raw, const float *__restrict__ rel,
                             float *__restrict__ out)
{
    size_t i = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) out[2 * i] = raw[i], out[2 * i + 1] = rel[i];
}

extern "C" int sem_cuda_interleave(sp_device *dev, size_t n, const float *d_raw, const float *d_rel,
                                   float *d_scores2, sp_error *err)
{
    if (n == 0) return 0;
    k_interleave<<<(unsigned)((n + 255) / 256), 256, 0, sp_cuda_stream(dev)>>>(n, d_raw, d_rel, d_scores2);
    SP_CUDA_LAUNCHED(err, "heatmap: interleaving scores");
    return 0;
}

__global__ void k_set_int(int *p, int v) { *p = v; }

static int float_bits(float f)
{
    int i;
    memcpy(&i, &f, sizeof i);
    return i;
}

/* rel = two[1] / alpha where alpha > 0.5 (else neutral), and the largest (as int bits: every
 * value is >= 0, where float order is integer order). */
__global__ void k_hm_rel(size_t np, const float *__restrict__ two, const float *__restrict__ alpha,
                         float *__restrict__ rel, int *__restrict__ rmax)
{
    size_t p = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    float r = 0.5f;
    if (p < np) {
        float a = alpha[p];
        r = a > 0.5f ? two[2 * p + 1] / a : 0.5f;
        rel[p] = r;
    }
    /* NaN or negative (never for relevancies) would not order as ints: leave them out */
    float m = r >= 0.f ? r : 0.5f;
    for (int o = 16; o > 0; o >>= 1) m = fmaxf(m, __shfl_down_sync(0xffffffffu, m, o));
    if ((threadIdx.x & 31) == 0) atomicMax(rmax, __float_as_int(m));
}

__global__ void k_hm_overlay(size_t np, const float *__restrict__ rgb, const float *__restrict__ rel,
                             const int *__restrict__ rmax, int found, float fade, uint8_t *__restrict__ img)
{
    size_t p = (size_t)blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= np) return;
    float scale = found ? sem_found_scale(__int_as_float(*rmax)) : fade;
    sem_overlay_pixel(rgb + 3 * p, 0.5f + (rel[p] - 0.5f) * scale, img + 3 * p);
}

extern "C" int sem_cuda_heatmap(sp_device *dev, size_t np, const float *d_rgb, const float *d_two,
                                const float *d_alpha, int found, float fade, uint8_t *d_img, float *d_rel,
                                float *d_max, sp_error *err)
{
    if (np == 0) return 0;
    cudaStream_t st = sp_cuda_stream(dev);
    int *rmax = (int *)d_max;
    k_set_int<<<1, 1, 0, st>>>(rmax, float_bits(0.5f));
    SP_CUDA_LAUNCHED(err, "heatmap: clearing the maximum");
    unsigned blocks = (unsigned)((np + 255) / 256);
    k_hm_rel<<<blocks, 256, 0, st>>>(np, d_two, d_alpha, d_rel, rmax);
    SP_CUDA_LAUNCHED(err, "heatmap: relevancy");
    k_hm_overlay<<<blocks, 256, 0, st>>>(np, d_rgb, d_rel, rmax, found, fade, d_img);
    SP_CUDA_LAUNCHED(err, "heatmap: colour overlay");
    return 0;
}
