/* The training loop: one view per step, SH -> colours (+ features) -> rasterize -> loss ->
 * backward -> Adam, with gsplat's density control every refine_every steps, held-out
 * evaluation, checkpoints and a NaN guard. Parameters, gradients and moments stay on the
 * sp_device; the per-element kernels come from the device's table (train_kernels.h: CUDA or
 * the CPU's loss.c). */
#include "semsplat/io.h"
#include "train/train_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Parameter groups as gsplat's optimisers: SH band 0 and the higher bands are separate groups
 * (different learning rates), so they are stored apart on the device and packed into one
 * [n][K][3] array for the SH evaluation. */
enum { G_MEANS, G_QUATS, G_SCALES, G_OPAC, G_SH0, G_SHN, G_FEAT, N_GROUPS };

typedef struct {
    sp_device *dev;
    sp_pool *pool;
    const tr_kernels *k; /* the device's per-element kernels */
    size_t n;
    int K, F, D, rgb;            /* SH coeffs, feature dim, rendered channels, RGB rendered? */
    float *p[N_GROUPS], *g[N_GROUPS], *m[N_GROUPS], *v[N_GROUPS];
    float *sh, *v_sh;            /* [n][K][3] packed */
    float *colors, *v_colors;    /* [n][D] */
    float *v_means2d;            /* [n][2] */
    float *grad2d, *count;       /* [n] densification statistics */
} tr_state;

static size_t group_width(const tr_state *s, int g)
{
    switch (g) {
    case G_MEANS: return 3;
    case G_QUATS: return 4;
    case G_SCALES: return 3;
    case G_OPAC: return 1;
    case G_SH0: return 3;
    case G_SHN: return (size_t)(s->K - 1) * 3;
    default: return (size_t)s->F;
    }
}

/* ---- kernel dispatch: the device's table of per-element kernels (train_kernels.h) -------------- */

static int k_copy_columns(tr_state *s, float *dst, int ds, int doff, const float *src, int ss,
                          int soff, size_t rows, int cols, sp_error *err)
{
    if (cols <= 0 || rows == 0) return SP_OK;
    return s->k->copy_columns(s->dev, dst, ds, doff, src, ss, soff, rows, cols, err);
}

static int k_adam(tr_state *s, float *p, const float *g, float *m, float *v, size_t n, float lr,
                  const sp_train_options *o, int step, sp_error *err)
{
    if (n == 0) return SP_OK;
    return s->k->adam_step(s->dev, p, g, m, v, n, lr, o->adam_beta1, o->adam_beta2, o->adam_eps,
                           step, err);
}

static int k_rgb_loss(tr_state *s, const float *pred, int stride, const float *target, int H, int W,
                      float lambda, float *scratch, float *v_pred, double stats[4], sp_error *err)
{
    return s->k->rgb_loss(s->dev, pred, stride, target, H, W, 3, lambda, scratch, v_pred, stats, err);
}

static int k_feature_mse(tr_state *s, const float *pred, int stride, int off, const float *target,
                         int H, int W, float lambda, float *v_pred, double *mse, sp_error *err)
{
    return s->k->feature_mse(s->dev, pred, stride, off, target, H, W, s->F, lambda, v_pred, mse, err);
}

static int k_depth_loss(tr_state *s, const float *depth, const float *alpha, const float *target,
                        int H, int W, float lambda, float *v_depth, float *v_alpha, double st[3],
                        sp_error *err)
{
    return s->k->depth_loss(s->dev, depth, alpha, target, H, W, lambda, v_depth, v_alpha, st, err);
}

static int k_accumulate(tr_state *s, const int32_t *radii, float sx, float sy, sp_error *err)
{
    return s->k->densify_accumulate(s->dev, s->v_means2d, radii, s->n, sx, sy, s->grad2d, s->count,
                                    err);
}

/* ---- device state ------------------------------------------------------------------------------ */

static void state_release(tr_state *s)
{
    for (int g = 0; g < N_GROUPS; g++) {
        sp_device_release(s->dev, s->p[g]);
        sp_device_release(s->dev, s->g[g]);
        sp_device_release(s->dev, s->m[g]);
        sp_device_release(s->dev, s->v[g]);
        s->p[g] = s->g[g] = s->m[g] = s->v[g] = NULL;
    }
    float **bufs[] = {&s->sh, &s->v_sh, &s->colors, &s->v_colors, &s->v_means2d, &s->grad2d, &s->count};
    for (size_t i = 0; i < sizeof bufs / sizeof bufs[0]; i++) {
        sp_device_release(s->dev, *bufs[i]);
        *bufs[i] = NULL;
    }
    s->n = 0;
}

static float *dalloc(tr_state *s, size_t floats, sp_error *err)
{
    return sp_device_alloc(s->dev, (floats ? floats : 1) * sizeof(float), err);
}

/* Host splat field for a group, with its stride inside the host array and column offset (SH
 * groups are columns of the interleaved [n][K][3] array). */
static float *host_field(const sp_splat *h, int g, size_t *stride, size_t *off, int K)
{
    *off = 0;
    switch (g) {
    case G_MEANS: *stride = 3; return h->means;
    case G_QUATS: *stride = 4; return h->quats;
    case G_SCALES: *stride = 3; return h->log_scales;
    case G_OPAC: *stride = 1; return h->opacity_logits;
    case G_SH0: *stride = (size_t)K * 3; return h->sh;
    case G_SHN: *stride = (size_t)K * 3; *off = 3; return h->sh;
    default: *stride = (size_t)h->feat_dim; return h->features;
    }
}

/* The scratch buffers sized by the Gaussian count, for n Gaussians (statistics zeroed). */
static int scratch_realloc(tr_state *s, size_t n, sp_error *err)
{
    float **bufs[] = {&s->sh, &s->v_sh, &s->colors, &s->v_colors, &s->v_means2d, &s->grad2d, &s->count};
    for (size_t i = 0; i < sizeof bufs / sizeof bufs[0]; i++) {
        sp_device_release(s->dev, *bufs[i]);
        *bufs[i] = NULL;
    }
    size_t K3 = (size_t)s->K * 3;
    if (!(s->sh = dalloc(s, n * K3, err)) || !(s->v_sh = dalloc(s, n * K3, err)) ||
        !(s->colors = dalloc(s, n * s->D, err)) || !(s->v_colors = dalloc(s, n * s->D, err)) ||
        !(s->v_means2d = dalloc(s, n * 2, err)) || !(s->grad2d = dalloc(s, n, err)) ||
        !(s->count = dalloc(s, n, err)))
        return err ? err->code : SP_E_NOMEM;
    int rc = sp_device_zero(s->dev, s->grad2d, (n ? n : 1) * sizeof(float), err);
    return rc ? rc : sp_device_zero(s->dev, s->count, (n ? n : 1) * sizeof(float), err);
}

/* Uploads host params (and moments, NULL = zero) into freshly allocated device buffers. */
static int state_upload(tr_state *s, const sp_splat *P, const sp_splat *M, const sp_splat *V,
                        sp_error *err)
{
    state_release(s);
    size_t n = P->n;
    s->n = n;
    float *tmp = NULL;
    size_t wmax = 0;
    for (int g = 0; g < N_GROUPS; g++) wmax = group_width(s, g) > wmax ? group_width(s, g) : wmax;
    tmp = malloc((n ? n : 1) * wmax * sizeof(float));
    if (!tmp) return sp_error_set(err, SP_E_NOMEM, "train: out of host memory for %zu Gaussians", n);
    int rc = SP_OK;
    for (int g = 0; g < N_GROUPS && !rc; g++) {
        size_t w = group_width(s, g);
        if (w == 0) continue;
        if (!(s->p[g] = dalloc(s, n * w, err)) || !(s->g[g] = dalloc(s, n * w, err)) ||
            !(s->m[g] = dalloc(s, n * w, err)) || !(s->v[g] = dalloc(s, n * w, err))) {
            rc = err ? err->code : SP_E_NOMEM;
            break;
        }
        const sp_splat *src[3] = {P, M, V};
        float *dst[3] = {s->p[g], s->m[g], s->v[g]};
        for (int k = 0; k < 3 && !rc; k++) {
            if (!src[k] || n == 0) continue;
            size_t stride, off;
            const float *f = host_field(src[k], g, &stride, &off, s->K);
            for (size_t i = 0; i < n; i++) memcpy(tmp + i * w, f + i * stride + off, w * sizeof(float));
            rc = sp_device_upload(s->dev, dst[k], tmp, n * w * sizeof(float), err);
        }
    }
    free(tmp);
    return rc ? rc : scratch_realloc(s, n, err);
}

/* Downloads params (and moments when M/V are given) into host splats allocated here. */
static int state_download(tr_state *s, int sh_degree, sp_splat *P, sp_splat *M, sp_splat *V,
                          sp_error *err)
{
    sp_splat *dst[3] = {P, M, V};
    float **src[3] = {s->p, s->m, s->v};
    size_t n = s->n, wmax = 0;
    for (int g = 0; g < N_GROUPS; g++) wmax = group_width(s, g) > wmax ? group_width(s, g) : wmax;
    float *tmp = malloc((n ? n : 1) * wmax * sizeof(float));
    if (!tmp) return sp_error_set(err, SP_E_NOMEM, "train: out of host memory");
    int rc = SP_OK;
    for (int k = 0; k < 3 && !rc; k++) {
        if (!dst[k]) continue;
        if ((rc = sp_splat_alloc(dst[k], n, sh_degree, s->F, err))) break;
        for (int g = 0; g < N_GROUPS && !rc; g++) {
            size_t w = group_width(s, g), stride, off;
            if (w == 0 || n == 0) continue;
            if ((rc = sp_device_download(s->dev, tmp, src[k][g], n * w * sizeof(float), err))) break;
            float *f = host_field(dst[k], g, &stride, &off, s->K);
            for (size_t i = 0; i < n; i++) memcpy(f + i * stride + off, tmp + i * w, w * sizeof(float));
        }
    }
    free(tmp);
    return rc;
}

/* Packs sh0 / shN into the [n][K][3] array and the colours buffer (RGB from SH, features). */
static int prepare_colors(tr_state *s, int sh_degree, int active, sp_vec3 center, sp_error *err)
{
    int rc, K3 = s->K * 3;
    if (s->rgb) {
        if ((rc = k_copy_columns(s, s->sh, K3, 0, s->p[G_SH0], 3, 0, s->n, 3, err))) return rc;
        if ((rc = k_copy_columns(s, s->sh, K3, 3, s->p[G_SHN], K3 - 3, 0, s->n, K3 - 3, err))) return rc;
        if ((rc = sp_sh_to_rgb(s->dev, s->n, sh_degree, active, s->sh, s->p[G_MEANS], center,
                               s->colors, s->D, err)))
            return rc;
    }
    if (s->F)
        return k_copy_columns(s, s->colors, s->D, s->rgb ? 3 : 0, s->p[G_FEAT], s->F, 0, s->n, s->F, err);
    return SP_OK;
}

static sp_raster_in raster_in(const tr_state *s, const float *bg)
{
    sp_raster_in in = {s->n, s->p[G_MEANS], s->p[G_QUATS], s->p[G_SCALES], s->p[G_OPAC],
                       s->colors, s->D, bg};
    return in;
}

/* ---- evaluation -------------------------------------------------------------------------------- */

typedef struct {
    float *image_d;  /* [H][W][D] device */
    float *image_h;  /* host copy, clamped */
    float *target_h; /* host [H][W][3] */
    float *scratch_h;
    size_t cap;      /* pixels */
} eval_bufs;

/* Depth error sums of one evaluated view against its target (pixels with a target): expected
 * depth where alpha >= 0.5, the count of pixels where alpha < 0.5, the surface depth's error. */
typedef struct {
    double l1, surf_l1, solid, holes;
} depth_sums;

static void depth_view_error(const float *dsum, const float *alpha, const float *surf,
                             const float *target, size_t np, depth_sums *ds)
{
    for (size_t p = 0; p < np; p++) {
        float t = target[p];
        if (!(t > 0)) continue;
        if (alpha[p] < 0.5f) {
            ds->holes += 1;
            continue;
        }
        ds->l1 += fabs((double)dsum[p] / alpha[p] - t);
        ds->surf_l1 += fabs((double)surf[p] - t);
        ds->solid += 1;
    }
}

static int evaluate_state(tr_state *s, sp_raster *r, const sp_train_data *d, int sh_degree,
                          int active, const float *bg, sp_train_result *res, sp_error *err)
{
    size_t maxpx = 0;
    int any_test = 0;
    for (size_t i = 0; i < d->n_views; i++) {
        size_t px = (size_t)d->views[i].cam.width * d->views[i].cam.height;
        if (px > maxpx) maxpx = px;
        any_test |= d->views[i].is_test;
    }
    int D = s->D, rc = SP_OK;
    float *image_d = sp_device_alloc(s->dev, maxpx * D * sizeof(float), err);
    float *image_h = malloc(maxpx * D * sizeof(float)), *target_h = malloc(maxpx * 3 * sizeof(float));
    float *scratch = sp_alloc(SP_LOSS_SCRATCH_FLOATS(1, maxpx, 3) * sizeof(float));
    /* depth, alpha, surface depth: device [3][maxpx] and host copies, only with depth targets */
    float *dep_d = NULL, *dep_h = NULL;
    int any_depth = 0;
    for (size_t i = 0; i < d->n_views; i++)
        any_depth |= d->views[i].depth != NULL && (!any_test || d->views[i].is_test);
    if (any_depth) {
        dep_d = sp_device_alloc(s->dev, 3 * maxpx * sizeof(float), err);
        dep_h = malloc(3 * maxpx * sizeof(float));
    }
    if (!image_d || !image_h || !target_h || !scratch || (any_depth && (!dep_d || !dep_h))) {
        rc = sp_error_set(err, SP_E_NOMEM, "evaluation: out of memory");
        goto done;
    }
    depth_sums dsum = {0, 0, 0, 0};
    double psnr = 0, ssim = 0, l1 = 0;
    int nv = 0;
    for (size_t i = 0; i < d->n_views; i++) {
        const sp_train_view *v = &d->views[i];
        if (any_test && !v->is_test) continue;
        int W = v->cam.width, H = v->cam.height;
        /* SH colours depend on the direction from this view's camera, as in training */
        if ((rc = prepare_colors(s, sh_degree, active, sp_camera_center(&v->cam), err))) goto done;
        sp_raster_in in = raster_in(s, bg);
        sp_raster_out out = {image_d, NULL, NULL, NULL};
        size_t np = (size_t)W * H;
        if (v->depth) {
            out.depth = dep_d;
            out.alpha = dep_d + maxpx;
            out.surface_depth = dep_d + 2 * maxpx;
        }
        sp_raster_cfg cfg = sp_raster_cfg_default();
        if ((rc = sp_raster_forward(r, &v->cam, &cfg, &in, &out, err))) goto done;
        if ((rc = sp_device_download(s->dev, image_h, image_d, (size_t)W * H * D * sizeof(float), err)))
            goto done;
        if (v->depth) {
            for (int k = 0; k < 3 && !rc; k++)
                rc = sp_device_download(s->dev, dep_h + k * maxpx, dep_d + k * maxpx, np * sizeof(float), err);
            if (rc) goto done;
            depth_view_error(dep_h, dep_h + maxpx, dep_h + 2 * maxpx, v->depth, np, &dsum);
        }
        for (size_t p = 0; p < np; p++)
            for (int c = 0; c < 3; c++) {
                float x = image_h[p * D + c];
                image_h[p * D + c] = x < 0 ? 0 : (x > 1 ? 1 : x); /* gsplat clamps before metrics */
                target_h[p * 3 + c] = v->rgb[p * 3 + c] / 255.0f;
            }
        double st[4];
        if ((rc = cpu_rgb_loss(s->pool, image_h, D, target_h, H, W, 3, 0.2f, scratch, NULL, st, err)))
            goto done;
        psnr += st[3] > 1e-10 ? -10.0 * log10(st[3]) : 100.0;
        ssim += st[2];
        l1 += st[1];
        nv++;
    }
    res->psnr = nv ? psnr / nv : 0;
    res->ssim = nv ? ssim / nv : 0;
    res->l1 = nv ? l1 / nv : 0;
    res->n_eval_views = nv;
    res->eval_on_train = !any_test;
    double with_target = dsum.solid + dsum.holes;
    res->depth_eval_pixels = with_target;
    res->depth_l1 = dsum.solid > 0 ? dsum.l1 / dsum.solid : 0;
    res->surface_depth_l1 = dsum.solid > 0 ? dsum.surf_l1 / dsum.solid : 0;
    res->depth_hole_share = with_target > 0 ? dsum.holes / with_target : 0;
done:
    sp_device_release(s->dev, dep_d);
    free(dep_h);
    sp_device_release(s->dev, image_d);
    free(image_h);
    free(target_h);
    sp_free(scratch);
    return rc;
}

int sp_train_evaluate(sp_device *dev, const sp_train_data *data, const sp_splat *splat,
                      const float background[3], sp_train_result *res, sp_error *err)
{
    tr_state s;
    memset(&s, 0, sizeof s);
    s.dev = dev;
    s.pool = sp_device_pool(dev);
    s.k = tr_kernels_of(dev);
    s.K = sp_sh_coeffs(splat->sh_degree);
    s.F = 0;
    s.D = 3;
    s.rgb = 1;
    sp_raster *r = NULL;
    int rc = sp_raster_create(&r, dev, err);
    if (!rc) rc = state_upload(&s, splat, NULL, NULL, err);
    float bg[3] = {0, 0, 0};
    if (background) memcpy(bg, background, sizeof bg);
    if (!rc) rc = evaluate_state(&s, r, data, splat->sh_degree, splat->sh_degree, bg, res, err);
    state_release(&s);
    sp_raster_free(r);
    if (!rc) res->gaussians = splat->n;
    return rc;
}


/* ---- options ----------------------------------------------------------------------------------- */

sp_train_options sp_train_options_default(int steps)
{
    sp_train_options o;
    memset(&o, 0, sizeof o);
    o.steps = steps > 0 ? steps : 30000;
    o.sh_degree = 3;
    o.ssim_lambda = 0.2f;
    o.seed = 42;
    o.lr_means = 1.6e-4f;
    o.lr_means_final_factor = 0.01f;
    o.lr_scales = 5e-3f;
    o.lr_quats = 1e-3f;
    o.lr_opacities = 5e-2f;
    o.lr_sh0 = 2.5e-3f;
    o.lr_shN = 2.5e-3f / 20.0f;
    o.adam_beta1 = 0.9f;
    o.adam_beta2 = 0.999f;
    o.adam_eps = 1e-15f;
    o.densify = 1;
    /* Short runs keep gsplat's absolute density schedule (refine every 100 steps, opacity reset
     * every 3000), as `simple_trainer --max_steps N` does. That recipe refines until step 15000
     * however short the run (at 7000 steps, to the end); here densification stops 2000 steps
     * before the end, so the last Gaussians grown are trained, and not before half the run (at
     * most 15000): 1000 at 2000 steps, 5000 at 7000, 15000 at 30000. Stopping at half the run
     * at 7000 steps too measured 0.3-0.4 dB under gsplat's recipe on the house (H200, issue
     * 23). Compressing the whole schedule (refine every 25, reset every 700 at 7000 steps)
     * measured 25.3 dB held-out on the house with 958k Gaussians, the last reset only 700 steps
     * before the end. */
    double f = o.steps < 30000 ? o.steps / 30000.0 : 1.0;
    o.sh_degree_interval = (int)(1000 * f + 0.5) > 1 ? (int)(1000 * f + 0.5) : 1;
    o.refine_start = (int)(500 * f + 0.5);
    int stop = o.steps - 2000 > o.steps / 2 ? o.steps - 2000 : o.steps / 2;
    o.refine_stop = stop < 15000 ? stop : 15000;
    o.refine_every = 100;
    o.reset_every = 3000;
    o.grow_grad2d = 0; /* auto: sp_train_grow_grad2d */
    o.grow_scale3d = 0.01f;
    o.prune_opacity = 0.005f;
    o.prune_scale3d = 0.1f;
    o.checkpoint_every = 1000;
    o.feature_lambda = 1.0f;
    o.lr_features = 2.5e-3f;
    o.cache_feature_targets = 1;
    return o;
}

/* gsplat's 0.0002 is its 30000-step recipe's; a shorter RGB run has fewer refinements to reach
 * the density it needs (45 at 7000 steps against 145), so it grows at 0.00015: on the H200 at
 * 7000 steps that measured +0.45-0.56 dB on the house, +0.7-0.9 dB on the bookstore and +1.25 dB
 * on the office over gsplat's recipe in 41-67 % of its time (at 0.0002 the house was level with
 * it or below). Depth supervision adds its own gradient to the screen-space one the threshold
 * is compared with (1.3-1.8x the Gaussians at 0.0002 already), so such runs keep 0.0002: the
 * 2000-step CPU demo at 0.00015 grew 165k -> 215k Gaussians, trained 21 % longer and its
 * costmap lost a point of agreement. */
float sp_train_grow_grad2d(const sp_train_options *o)
{
    if (o->grow_grad2d > 0) return o->grow_grad2d;
    return o->steps < 30000 && !(o->depth_lambda > 0) ? 1.5e-4f : 2e-4f;
}

/* ---- the loop ---------------------------------------------------------------------------------- */

typedef struct {
    float **target;   /* per view [H][W][3] on the device (training views only) */
    float **ftarget;  /* per view [H][W][F] on the device when cached */
    float **dtarget;  /* per view [H][W] depth on the device (depth_lambda > 0, views with depth) */
    float *depth, *alpha, *v_depth, *v_alpha; /* [maxpx] each, depth supervision only */
    float *ftmp_h;    /* host staging for feature targets */
    float *ftmp_d;    /* device staging when not cached */
    float *image, *v_image, *scratch;
    size_t maxpx;
} step_bufs;

static void bufs_free(sp_device *dev, const sp_train_data *d, step_bufs *b)
{
    for (size_t i = 0; b->target && i < d->n_views; i++) sp_device_release(dev, b->target[i]);
    for (size_t i = 0; b->ftarget && i < d->n_views; i++) sp_device_release(dev, b->ftarget[i]);
    for (size_t i = 0; b->dtarget && i < d->n_views; i++) sp_device_release(dev, b->dtarget[i]);
    free(b->target);
    free(b->ftarget);
    free(b->dtarget);
    float *dbufs[] = {b->depth, b->alpha, b->v_depth, b->v_alpha};
    for (int k = 0; k < 4; k++) sp_device_release(dev, dbufs[k]);
    free(b->ftmp_h);
    sp_device_release(dev, b->ftmp_d);
    sp_device_release(dev, b->image);
    sp_device_release(dev, b->v_image);
    sp_device_release(dev, b->scratch);
    memset(b, 0, sizeof *b);
}

/* Depth targets of the training views cached on the device (like the RGB targets) and the
 * per-step depth / alpha buffers, when depth supervision is on. */
static int depth_bufs_init(tr_state *s, const sp_train_data *d, const sp_train_options *o,
                           step_bufs *b, sp_error *err)
{
    if (!(o->depth_lambda > 0) || !s->rgb) return SP_OK;
    if (!(b->dtarget = calloc(d->n_views, sizeof(float *))))
        return sp_error_set(err, SP_E_NOMEM, "train: out of memory for depth targets");
    size_t with = 0;
    for (size_t i = 0; i < d->n_views; i++) {
        const sp_train_view *v = &d->views[i];
        if (v->is_test || !v->depth) continue;
        size_t bytes = (size_t)v->cam.width * v->cam.height * sizeof(float);
        if (!(b->dtarget[i] = sp_device_alloc(s->dev, bytes, err))) return err->code;
        int rc = sp_device_upload(s->dev, b->dtarget[i], v->depth, bytes, err);
        if (rc) return rc;
        with++;
    }
    if (with == 0)
        return sp_error_set(err, SP_E_ARG, "train: depth_lambda %g but no training view has depth "
                            "(load it with sp_train_data_load_depth)", (double)o->depth_lambda);
    float **bufs[] = {&b->depth, &b->alpha, &b->v_depth, &b->v_alpha};
    for (int k = 0; k < 4; k++)
        if (!(*bufs[k] = sp_device_alloc(s->dev, b->maxpx * sizeof(float), err))) return err->code;
    return SP_OK;
}

static int bufs_init(tr_state *s, const sp_train_data *d, const sp_train_options *o, step_bufs *b,
                     sp_error *err)
{
    memset(b, 0, sizeof *b);
    for (size_t i = 0; i < d->n_views; i++) {
        size_t px = (size_t)d->views[i].cam.width * d->views[i].cam.height;
        if (px > b->maxpx) b->maxpx = px;
    }
    b->target = calloc(d->n_views, sizeof(float *));
    b->ftarget = calloc(d->n_views, sizeof(float *));
    float *tmp = malloc(b->maxpx * 3 * sizeof(float));
    if (!b->target || !b->ftarget || !tmp) {
        free(tmp);
        return sp_error_set(err, SP_E_NOMEM, "train: out of memory for %zu views", d->n_views);
    }
    int rc = SP_OK;
    for (size_t i = 0; i < d->n_views && !rc; i++) {
        const sp_train_view *v = &d->views[i];
        if (v->is_test) continue;
        size_t px = (size_t)v->cam.width * v->cam.height;
        if (s->rgb) {
            for (size_t k = 0; k < px * 3; k++) tmp[k] = v->rgb[k] / 255.0f;
            if (!(b->target[i] = sp_device_alloc(s->dev, px * 3 * sizeof(float), err))) rc = err->code;
            else rc = sp_device_upload(s->dev, b->target[i], tmp, px * 3 * sizeof(float), err);
        }
    }
    free(tmp);
    if (rc) return rc;
    if (s->F) {
        b->ftmp_h = malloc(b->maxpx * s->F * sizeof(float));
        if (!b->ftmp_h) return sp_error_set(err, SP_E_NOMEM, "train: out of memory for feature targets");
        for (size_t i = 0; i < d->n_views && !rc && o->cache_feature_targets; i++) {
            const sp_train_view *v = &d->views[i];
            if (v->is_test) continue;
            size_t bytes = (size_t)v->cam.width * v->cam.height * s->F * sizeof(float);
            if ((rc = o->get_feature_target(o->feature_user, i, v->cam.width, v->cam.height, s->F,
                                            b->ftmp_h, err)))
                return sp_error_prefix(err, "feature target of view '%s': ", v->name);
            if (!(b->ftarget[i] = sp_device_alloc(s->dev, bytes, err))) return err->code;
            rc = sp_device_upload(s->dev, b->ftarget[i], b->ftmp_h, bytes, err);
        }
        if (!rc && !o->cache_feature_targets &&
            !(b->ftmp_d = sp_device_alloc(s->dev, b->maxpx * s->F * sizeof(float), err)))
            rc = err->code;
    }
    if (rc) return rc;
    if ((rc = depth_bufs_init(s, d, o, b, err))) return rc;
    if (!(b->image = sp_device_alloc(s->dev, b->maxpx * s->D * sizeof(float), err)) ||
        !(b->v_image = sp_device_alloc(s->dev, b->maxpx * s->D * sizeof(float), err)) ||
        !(b->scratch = sp_device_alloc(s->dev, SP_LOSS_SCRATCH_FLOATS(1, b->maxpx, 3) * sizeof(float), err)))
        return err->code;
    return SP_OK;
}

/* Held-out feature error: the features rendered at each held-out view (every view when none is
 * held out, res->eval_on_train) against that view's target from get_feature_target, as one mean
 * of squared differences over all pixels and channels of those views. */
static int evaluate_features(tr_state *s, sp_raster *r, const sp_train_data *d,
                             const sp_train_options *o, step_bufs *b, int active,
                             sp_train_result *res, sp_error *err)
{
    int any_test = 0;
    for (size_t i = 0; i < d->n_views; i++) any_test |= d->views[i].is_test;
    float *image_h = malloc(b->maxpx * (size_t)s->D * sizeof(float));
    float *bg = calloc((size_t)s->D, sizeof(float));
    int rc = SP_OK;
    if (!image_h || !bg) {
        rc = sp_error_set(err, SP_E_NOMEM, "feature evaluation: out of memory");
        goto done;
    }
    if (s->rgb)
        for (int c = 0; c < 3; c++) bg[c] = o->background[c];
    double sse = 0, count = 0;
    int nv = 0;
    for (size_t i = 0; i < d->n_views; i++) {
        const sp_train_view *v = &d->views[i];
        if (any_test && !v->is_test) continue;
        int W = v->cam.width, H = v->cam.height;
        if ((rc = prepare_colors(s, o->sh_degree, active, sp_camera_center(&v->cam), err))) goto done;
        sp_raster_in in = raster_in(s, bg);
        sp_raster_out out = {b->image, NULL, NULL, NULL};
        sp_raster_cfg cfg = sp_raster_cfg_default();
        if ((rc = sp_raster_forward(r, &v->cam, &cfg, &in, &out, err))) goto done;
        if ((rc = sp_device_download(s->dev, image_h, b->image, (size_t)W * H * s->D * sizeof(float), err)))
            goto done;
        if ((rc = o->get_feature_target(o->feature_user, i, W, H, s->F, b->ftmp_h, err))) {
            sp_error_prefix(err, "feature target of view '%s': ", v->name);
            goto done;
        }
        double mse = 0;
        if ((rc = cpu_feature_mse(s->pool, image_h, s->D, s->rgb ? 3 : 0, b->ftmp_h, H, W, s->F, 0.0f,
                                  NULL, &mse, err)))
            goto done;
        sse += mse * W * H * s->F;
        count += (double)W * H * s->F;
        nv++;
    }
    res->feature_mse = count > 0 ? sse / count : 0;
    res->n_eval_views = nv;
    res->eval_on_train = !any_test;
done:
    free(image_h);
    free(bg);
    return rc;
}

static int check_options(const sp_train_data *d, const sp_train_options *o, const sp_splat *sp,
                         sp_error *err)
{
    int rc = tr_check_option_ranges(o, err);
    if (rc) return rc;
    if (o->feature_dim < 0 || (o->feature_dim > 0 && !o->get_feature_target))
        return sp_error_set(err, SP_E_ARG, "train: feature_dim %d needs a get_feature_target callback",
                            o->feature_dim);
    if (o->freeze_geometry && o->feature_dim == 0)
        return sp_error_set(err, SP_E_ARG, "train: freeze_geometry without features leaves nothing to train");
    if (sp->feat_dim && o->feature_dim && sp->feat_dim != o->feature_dim)
        return sp_error_set(err, SP_E_ARG, "train: the splat has %d features, options ask for %d",
                            sp->feat_dim, o->feature_dim);
    size_t n_train = 0;
    for (size_t i = 0; i < d->n_views; i++) n_train += !d->views[i].is_test;
    if (n_train == 0) return sp_error_set(err, SP_E_ARG, "train: no training views");
    if (sp->n == 0 && !o->resume) return sp_error_set(err, SP_E_ARG, "train: the initial splat is empty");
    return SP_OK;
}

/* Brings a splat to the SH degree and feature width training uses (new entries zero). */
static int conform_splat(sp_splat *sp, int sh_degree, int F, sp_error *err)
{
    if (sp->sh_degree == sh_degree && (sp->feat_dim == F || F == 0)) return SP_OK;
    sp_splat t;
    int rc = sp_splat_alloc(&t, sp->n, sh_degree, F ? F : sp->feat_dim, err);
    if (rc) return rc;
    size_t n = sp->n, Ko = (size_t)sp_sh_coeffs(sp->sh_degree), Kn = (size_t)sp_sh_coeffs(sh_degree);
    size_t Kc = Ko < Kn ? Ko : Kn;
    memcpy(t.means, sp->means, n * 3 * sizeof(float));
    memcpy(t.quats, sp->quats, n * 4 * sizeof(float));
    memcpy(t.log_scales, sp->log_scales, n * 3 * sizeof(float));
    memcpy(t.opacity_logits, sp->opacity_logits, n * sizeof(float));
    for (size_t i = 0; i < n; i++) memcpy(t.sh + i * Kn * 3, sp->sh + i * Ko * 3, Kc * 3 * sizeof(float));
    if (sp->feat_dim && t.feat_dim == sp->feat_dim)
        memcpy(t.features, sp->features, n * (size_t)t.feat_dim * sizeof(float));
    sp_splat_free(sp);
    *sp = t;
    return SP_OK;
}

/* Applies a density-control plan on the device: every group's parameters and moments gathered
 * into buffers of the new size (moments zero where the plan says), the means and log-scales
 * the plan computed uploaded over the gathered ones. */
static int apply_plan(tr_state *s, const tr_densify_plan *pl, sp_error *err)
{
    size_t n = pl->n_out;
    int32_t *idx_h = malloc(sizeof(int32_t) * 2 * (n ? n : 1)), *idx = NULL;
    if (!idx_h) return sp_error_set(err, SP_E_NOMEM, "densify: out of host memory for %zu Gaussians", n);
    for (size_t i = 0; i < n; i++) idx_h[i] = pl->src[i], idx_h[n + i] = pl->keep_moments[i] ? pl->src[i] : -1;
    int rc = SP_OK;
    if (!(idx = sp_device_alloc(s->dev, sizeof(int32_t) * 2 * (n ? n : 1), err))) rc = err ? err->code : SP_E_NOMEM;
    if (!rc && n) rc = sp_device_upload(s->dev, idx, idx_h, sizeof(int32_t) * 2 * n, err);
    free(idx_h);
    for (int g = 0; g < N_GROUPS && !rc; g++) {
        size_t w = group_width(s, g);
        if (w == 0) continue;
        float *np = dalloc(s, n * w, err), *nm = dalloc(s, n * w, err), *nv = dalloc(s, n * w, err), *ng = dalloc(s, n * w, err);
        if (!np || !nm || !nv || !ng) rc = err ? err->code : SP_E_NOMEM;
        if (!rc) rc = s->k->gather_rows(s->dev, np, s->p[g], idx, n, (int)w, err);
        if (!rc) rc = s->k->gather_rows(s->dev, nm, s->m[g], idx + n, n, (int)w, err);
        if (!rc) rc = s->k->gather_rows(s->dev, nv, s->v[g], idx + n, n, (int)w, err);
        float **old[4] = {&s->p[g], &s->m[g], &s->v[g], &s->g[g]}, *fresh[4] = {np, nm, nv, ng};
        for (int k = 0; k < 4; k++) {
            float *drop = rc ? fresh[k] : *old[k];
            if (!rc) *old[k] = fresh[k];
            sp_device_release(s->dev, drop);
        }
    }
    sp_device_release(s->dev, idx);
    if (!rc) s->n = n;
    if (!rc && n) rc = sp_device_upload(s->dev, s->p[G_MEANS], pl->means, sizeof(float) * 3 * n, err);
    if (!rc && n) rc = sp_device_upload(s->dev, s->p[G_SCALES], pl->log_scales, sizeof(float) * 3 * n, err);
    return rc ? rc : scratch_realloc(s, n, err);
}

/* gsplat's density control on the device state: the plan is made from the geometry and the
 * statistics alone (downloaded: 13 floats a Gaussian, against 3 x 59 for parameters and moments
 * with SH degree 3), then applied where the state lives; then the opacity reset (logits clamped,
 * their moments zeroed). Either way the statistics restart from zero. The result is the same as
 * sp_train_densify_host and sp_train_reset_opacity_host on downloaded copies. */
static int refine_state(tr_state *s, const sp_train_options *o, float scene_scale, int step, uint64_t *rng,
                        int do_refine, int do_reset, sp_densify_stats *ds, sp_error *err)
{
    size_t n = s->n;
    int rc = SP_OK;
    if (do_refine) {
        sp_splat geo;
        float *g2 = malloc(sizeof(float) * 2 * (n ? n : 1));
        if (!g2) return sp_error_set(err, SP_E_NOMEM, "densify: out of memory");
        if ((rc = sp_splat_alloc(&geo, n, 0, 0, err))) {
            free(g2);
            return rc;
        }
        if (n) {
            rc = sp_device_download(s->dev, geo.means, s->p[G_MEANS], n * 3 * sizeof(float), err);
            if (!rc) rc = sp_device_download(s->dev, geo.quats, s->p[G_QUATS], n * 4 * sizeof(float), err);
            if (!rc) rc = sp_device_download(s->dev, geo.log_scales, s->p[G_SCALES], n * 3 * sizeof(float), err);
            if (!rc) rc = sp_device_download(s->dev, geo.opacity_logits, s->p[G_OPAC], n * sizeof(float), err);
            if (!rc) rc = sp_device_download(s->dev, g2, s->grad2d, n * sizeof(float), err);
            if (!rc) rc = sp_device_download(s->dev, g2 + n, s->count, n * sizeof(float), err);
        }
        tr_densify_plan pl;
        if (!rc && !(rc = tr_densify_plan_make(&geo, g2, g2 + n, o, scene_scale, step, rng, &pl, ds, err))) {
            rc = apply_plan(s, &pl, err);
            tr_densify_plan_free(&pl);
        }
        sp_splat_free(&geo);
        free(g2);
        if (rc) return rc;
        n = s->n;
    }
    if (do_reset && n) {
        float *op = malloc(sizeof(float) * n), cap = sp_logit(2.0f * o->prune_opacity);
        if (!op) return sp_error_set(err, SP_E_NOMEM, "opacity reset: out of memory");
        rc = sp_device_download(s->dev, op, s->p[G_OPAC], n * sizeof(float), err);
        for (size_t i = 0; !rc && i < n; i++)
            if (op[i] > cap) op[i] = cap;
        if (!rc) rc = sp_device_upload(s->dev, s->p[G_OPAC], op, n * sizeof(float), err);
        if (!rc) rc = sp_device_zero(s->dev, s->m[G_OPAC], n * sizeof(float), err);
        if (!rc) rc = sp_device_zero(s->dev, s->v[G_OPAC], n * sizeof(float), err);
        free(op);
        if (!rc && !do_refine) { /* the statistics restart, as after a refinement */
            rc = sp_device_zero(s->dev, s->grad2d, n * sizeof(float), err);
            if (!rc) rc = sp_device_zero(s->dev, s->count, n * sizeof(float), err);
        }
    }
    return rc;
}

static void shuffle(size_t *a, size_t n, uint64_t *rng)
{
    for (size_t i = n; i > 1; i--) {
        size_t j = (size_t)(tr_uniform(rng) * i);
        if (j >= i) j = i - 1;
        size_t t = a[i - 1];
        a[i - 1] = a[j];
        a[j] = t;
    }
}

static int save_checkpoint(tr_state *s, const sp_train_options *o, int step, uint64_t rng,
                           sp_splat *last_good, int *last_good_step, const sp_log *log, sp_error *err)
{
    sp_splat P, M, V;
    memset(&M, 0, sizeof M);
    memset(&V, 0, sizeof V);
    int rc = state_download(s, o->sh_degree, &P, &M, &V, err);
    if (!rc) rc = sp_splat_check_finite(&P, err);
    if (rc == SP_E_NUMERIC)
        sp_error_prefix(err, "step %d: parameters became non-finite: ", step);
    if (!rc && o->checkpoint_dir) {
        char path[4096];
        if ((rc = sp_mkdirs(o->checkpoint_dir, err)) == 0) {
            sp_path_join(path, sizeof path, o->checkpoint_dir, "checkpoint.bin");
            rc = tr_checkpoint_write(path, step, rng, &P, &M, &V, err);
            if (!rc) sp_logf(log, SP_LOG_DEBUG, "checkpoint at step %d: %s", step, path);
        }
    }
    if (!rc) {
        sp_splat_free(last_good);
        *last_good = P;
        *last_good_step = step;
    } else {
        sp_splat_free(&P);
    }
    sp_splat_free(&M);
    sp_splat_free(&V);
    return rc;
}

static int nan_stop(sp_error *err, int step, const char *what, const sp_train_options *o,
                    int last_good_step)
{
    char where[4200];
    if (o->checkpoint_dir && last_good_step >= 0)
        snprintf(where, sizeof where, "the last good checkpoint (step %d) is kept in %s/checkpoint.bin",
                 last_good_step, o->checkpoint_dir);
    else
        snprintf(where, sizeof where, "returning the parameters of step %d", last_good_step);
    return sp_error_set(err, SP_E_NUMERIC,
                        "training diverged at step %d: %s is not finite; stopped (%s); try a "
                        "lower learning rate or check the input images", step, what, where);
}

int sp_train_run(sp_device *dev, const sp_train_data *d, const sp_train_options *o,
                 sp_splat *splat, sp_train_result *res, const sp_log *log, sp_error *err)
{
    memset(res, 0, sizeof *res);
    int rc = check_options(d, o, splat, err);
    if (rc) return rc;
    double t0 = sp_time_now();
    tr_state s;
    memset(&s, 0, sizeof s);
    s.dev = dev;
    s.pool = sp_device_pool(dev);
    s.k = tr_kernels_of(dev);
    s.K = sp_sh_coeffs(o->sh_degree);
    s.F = o->feature_dim;
    s.rgb = !o->freeze_geometry;
    s.D = (s.rgb ? 3 : 0) + s.F;
    int train_geom = !o->freeze_geometry;
    int start_step = 0;
    uint64_t rng = tr_seed(o->seed);
    sp_splat M0, V0, last_good;
    memset(&M0, 0, sizeof M0);
    memset(&V0, 0, sizeof V0);
    memset(&last_good, 0, sizeof last_good);
    sp_raster *r = NULL;
    step_bufs b;
    memset(&b, 0, sizeof b);
    size_t *order = NULL;
    int have_moments = 0, last_good_step = -1;

    if (o->resume) {
        tr_checkpoint ck;
        if ((rc = tr_checkpoint_read(o->resume, &ck, err))) return rc;
        if (ck.params.sh_degree != o->sh_degree || ck.params.feat_dim != s.F) {
            rc = sp_error_set(err, SP_E_ARG,
                              "%s: checkpoint has SH degree %d and %d features, this run asks for "
                              "%d and %d", o->resume, ck.params.sh_degree, ck.params.feat_dim,
                              o->sh_degree, s.F);
            tr_checkpoint_free(&ck);
            return rc;
        }
        sp_splat_free(splat);
        *splat = ck.params;
        M0 = ck.m;
        V0 = ck.v;
        start_step = ck.step;
        rng = ck.rng;
        have_moments = 1;
        sp_logf(log, SP_LOG_INFO, "resuming from %s at step %d with %zu Gaussians", o->resume,
                start_step, splat->n);
    } else if ((rc = conform_splat(splat, o->sh_degree, s.F, err))) {
        return rc;
    }
    float scene_scale = o->scene_scale > 0 ? o->scene_scale : d->scene_scale * 1.1f;
    /* SH bands that already carry colour (a trained splat) are active from the first step. */
    int init_degree = 0;
    for (int deg = 1; deg <= o->sh_degree; deg++) {
        size_t K3 = (size_t)s.K * 3, lo = (size_t)deg * deg * 3, hi = (size_t)(deg + 1) * (deg + 1) * 3;
        for (size_t i = 0; i < splat->n && init_degree < deg; i++)
            for (size_t k = lo; k < hi; k++)
                if (splat->sh[i * K3 + k] != 0.0f) {
                    init_degree = deg;
                    break;
                }
    }
    if ((rc = state_upload(&s, splat, have_moments ? &M0 : NULL, have_moments ? &V0 : NULL, err))) goto out;
    if ((rc = sp_raster_create(&r, dev, err))) goto out;
    if ((rc = bufs_init(&s, d, o, &b, err))) goto out;
    if ((rc = sp_splat_copy(&last_good, splat, err))) goto out;
    last_good_step = start_step;

    size_t n_train = 0, pos = 0;
    order = malloc(d->n_views * sizeof(size_t));
    if (!order) {
        rc = sp_error_set(err, SP_E_NOMEM, "train: out of memory");
        goto out;
    }
    for (size_t i = 0; i < d->n_views; i++)
        if (!d->views[i].is_test) order[n_train++] = i;
    shuffle(order, n_train, &rng);
    snprintf(res->device, sizeof res->device, "%s", sp_device_name(dev));
    sp_logf(log, SP_LOG_INFO, "training %zu Gaussians on %s: %zu training / %zu held-out views, %d steps",
            s.n, res->device, n_train, d->n_views - n_train, o->steps);

    sp_progress prog;
    sp_progress_begin(&prog, log, "train", o->steps, "steps");
    double loss_ema = 0, mse_ema = 0;
    float *bg = malloc((size_t)s.D * sizeof(float));
    if (!bg) {
        rc = sp_error_set(err, SP_E_NOMEM, "train: out of memory");
        goto out;
    }
    sp_raster_cfg cfg = sp_raster_cfg_default();
    int step = start_step;
    const double t_steps = sp_time_now();
    for (; step < o->steps; step++) {
        size_t vi = order[pos++];
        if (pos == n_train) {
            shuffle(order, n_train, &rng);
            pos = 0;
        }
        const sp_train_view *v = &d->views[vi];
        int W = v->cam.width, H = v->cam.height;
        size_t px = (size_t)W * H;
        int active = o->sh_degree_interval > 0 ? step / o->sh_degree_interval : o->sh_degree;
        if (active < init_degree) active = init_degree;
        if (active > o->sh_degree) active = o->sh_degree;
        if ((rc = prepare_colors(&s, o->sh_degree, active, sp_camera_center(&v->cam), err))) break;
        for (int c = 0; c < s.D; c++) bg[c] = 0;
        if (s.rgb)
            for (int c = 0; c < 3; c++)
                bg[c] = o->random_background ? (float)tr_uniform(&rng) : o->background[c];
        sp_raster_in in = raster_in(&s, bg);
        const float *dt = b.dtarget ? b.dtarget[vi] : NULL; /* NULL: no depth term this view */
        sp_raster_out out = {b.image, dt ? b.depth : NULL, dt ? b.alpha : NULL, NULL};
        if ((rc = sp_raster_forward(r, &v->cam, &cfg, &in, &out, err))) break;
        if ((rc = sp_device_zero(dev, b.v_image, px * s.D * sizeof(float), err))) break;
        double st[4] = {0, 0, 1, 0}, fmse = 0;
        if (s.rgb && (rc = k_rgb_loss(&s, b.image, s.D, b.target[vi], H, W, o->ssim_lambda, b.scratch,
                                      b.v_image, st, err)))
            break;
        if (s.F) {
            float *ft = b.ftarget[vi];
            if (!o->cache_feature_targets) {
                if ((rc = o->get_feature_target(o->feature_user, vi, W, H, s.F, b.ftmp_h, err))) {
                    sp_error_prefix(err, "feature target of view '%s': ", v->name);
                    break;
                }
                if ((rc = sp_device_upload(dev, b.ftmp_d, b.ftmp_h, px * s.F * sizeof(float), err))) break;
                ft = b.ftmp_d;
            }
            if ((rc = k_feature_mse(&s, b.image, s.D, s.rgb ? 3 : 0, ft, H, W, o->feature_lambda,
                                    b.v_image, &fmse, err)))
                break;
        }
        double dst[3] = {0, 0, 0};
        if (dt && (rc = k_depth_loss(&s, b.depth, b.alpha, dt, H, W, o->depth_lambda, b.v_depth,
                                     b.v_alpha, dst, err)))
            break;
        double loss = (s.rgb ? st[0] : 0) + o->feature_lambda * fmse + dst[0];
        if (!isfinite(loss)) {
            rc = nan_stop(err, step, "the loss", o, last_good_step);
            break;
        }
        for (int g = 0; g < N_GROUPS && !rc; g++)
            if (group_width(&s, g)) rc = sp_device_zero(dev, s.g[g], s.n * group_width(&s, g) * sizeof(float), err);
        if (!rc) rc = sp_device_zero(dev, s.v_colors, s.n * s.D * sizeof(float), err);
        if (!rc) rc = sp_device_zero(dev, s.v_means2d, s.n * 2 * sizeof(float), err);
        if (!rc && s.rgb) rc = sp_device_zero(dev, s.v_sh, s.n * s.K * 3 * sizeof(float), err);
        if (rc) break;
        sp_raster_grad_in gin = {b.v_image, dt ? b.v_depth : NULL, dt ? b.v_alpha : NULL};
        sp_raster_grads gr = {train_geom ? s.g[G_MEANS] : NULL, train_geom ? s.g[G_QUATS] : NULL,
                              train_geom ? s.g[G_SCALES] : NULL, train_geom ? s.g[G_OPAC] : NULL,
                              s.v_colors, train_geom ? s.v_means2d : NULL};
        if ((rc = sp_raster_backward(r, &gin, &gr, err))) break;
        if (s.rgb) {
            int K3 = s.K * 3;
            if ((rc = sp_sh_to_rgb_backward(dev, s.n, o->sh_degree, active, s.sh, s.p[G_MEANS],
                                            sp_camera_center(&v->cam), s.colors, s.v_colors, s.D,
                                            s.v_sh, s.g[G_MEANS], err)))
                break;
            if ((rc = k_copy_columns(&s, s.g[G_SH0], 3, 0, s.v_sh, K3, 0, s.n, 3, err))) break;
            if ((rc = k_copy_columns(&s, s.g[G_SHN], K3 - 3, 0, s.v_sh, K3, 3, s.n, K3 - 3, err))) break;
        }
        if (s.F && (rc = k_copy_columns(&s, s.g[G_FEAT], s.F, 0, s.v_colors, s.D, s.rgb ? 3 : 0,
                                        s.n, s.F, err)))
            break;
        int refining = o->densify && train_geom && step < o->refine_stop;
        if (refining && (rc = k_accumulate(&s, sp_raster_radii(r), W * 0.5f, H * 0.5f, err))) break;

        /* Adam, one group at a time (gsplat: one optimiser per parameter). */
        float decay = powf(o->lr_means_final_factor, (float)step / (float)o->steps);
        float lr[N_GROUPS] = {o->lr_means * scene_scale * decay, o->lr_quats, o->lr_scales,
                              o->lr_opacities, o->lr_sh0, o->lr_shN, o->lr_features};
        for (int g = 0; g < N_GROUPS && !rc; g++) {
            if (!group_width(&s, g) || (!train_geom && g != G_FEAT)) continue;
            rc = k_adam(&s, s.p[g], s.g[g], s.m[g], s.v[g], s.n * group_width(&s, g), lr[g], o,
                        step + 1, err);
        }
        if (rc) break;

        /* Density control, gsplat DefaultStrategy.step_post_backward. */
        int do_refine = refining && step > o->refine_start && o->refine_every > 0 &&
                        step % o->refine_every == 0;
        /* Resets only once densification has started, so continuing from a trained splat with
         * refine_start beyond the run (distillation) never knocks its opacities down. */
        int do_reset = refining && o->reset_every > 0 && step > o->refine_start &&
                       step % o->reset_every == 0;
        if (do_refine || do_reset) {
            double t_ref = sp_time_now();
            sp_densify_stats ds = {0, 0, 0};
            if ((rc = refine_state(&s, o, scene_scale, step, &rng, do_refine, do_reset, &ds, err))) break;
            if (do_refine)
                sp_logf(log, SP_LOG_DEBUG,
                        "step %d: %zu cloned, %zu split, %zu pruned -> %zu Gaussians (%.0f ms)",
                        step, ds.n_cloned, ds.n_split, ds.n_pruned, s.n,
                        1000.0 * (sp_time_now() - t_ref));
        }

        loss_ema = step == start_step ? loss : 0.9 * loss_ema + 0.1 * loss;
        mse_ema = step == start_step ? st[3] : 0.9 * mse_ema + 0.1 * st[3];
        res->last_loss = loss;
        int done = step + 1;
        if (o->checkpoint_every > 0 && done % o->checkpoint_every == 0 && done < o->steps) {
            if ((rc = save_checkpoint(&s, o, done, rng, &last_good, &last_good_step, log, err))) {
                if (rc == SP_E_NUMERIC) rc = nan_stop(err, done, "a parameter", o, last_good_step);
                break;
            }
        }
        if (o->eval_every > 0 && done % o->eval_every == 0 && done < o->steps && s.rgb) {
            sp_train_result er = *res;
            if ((rc = evaluate_state(&s, r, d, o->sh_degree, active, o->background, &er, err))) break;
            sp_logf(log, SP_LOG_INFO, "step %d: held-out PSNR %.2f dB, SSIM %.4f, %zu Gaussians",
                    done, er.psnr, er.ssim, s.n);
        }
        char extra[128];
        snprintf(extra, sizeof extra, "loss %.4f psnr %.2f n %zu", loss_ema,
                 s.rgb ? -10.0 * log10(mse_ema > 1e-10 ? mse_ema : 1e-10) : 0.0, s.n);
        sp_progress_update(&prog, done, extra);
    }
    free(bg);
    if (!rc) {
        /* Final parameters: download (NaN-checked) and evaluate. */
        if ((rc = save_checkpoint(&s, o, step, rng, &last_good, &last_good_step, log, err))) {
            if (rc == SP_E_NUMERIC) rc = nan_stop(err, step, "a parameter", o, last_good_step);
        }
    }
    res->seconds_steps = sp_time_now() - t_steps; /* the final download waited for the device */
    sp_progress_end(&prog, rc ? "stopped" : NULL);
    int active = o->sh_degree_interval > 0 ? (step - 1) / o->sh_degree_interval : o->sh_degree;
    if (active < init_degree) active = init_degree;
    if (active > o->sh_degree) active = o->sh_degree;
    if (active < 0) active = 0;
    /* The saved splat is rendered by viewers at its full degree; evaluate it that way only
     * when training reached it, else at the degree trained. */
    if (!rc && s.rgb) rc = evaluate_state(&s, r, d, o->sh_degree, active, o->background, res, err);
    if (!rc && s.F) rc = evaluate_features(&s, r, d, o, &b, active, res, err);
    res->steps = step;
    res->gaussians = last_good.n;
    res->seconds = sp_time_now() - t0;
    /* On success last_good is the final state; on failure it is the last finite one. */
    sp_splat_free(splat);
    *splat = last_good;
    memset(&last_good, 0, sizeof last_good);
out:
    free(order);
    bufs_free(dev, d, &b);
    sp_raster_free(r);
    state_release(&s);
    sp_splat_free(&M0);
    sp_splat_free(&V0);
    sp_splat_free(&last_good);
    return rc;
}
