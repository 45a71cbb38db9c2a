/* Lifting 2D feature maps into the splat in one pass (no training): each Gaussian's feature is
 * the compositing-weight average of the targets it contributes to. The weights come exactly from
 * the rasterizer's backward: with v_image = [target, 1] over D+1 channels,
 *   v_colors[i] = sum_p w_ip [t_p, 1],
 * accumulated over views (gradients add), so f_i = v_colors[i][:D] / v_colors[i][D]. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/semantic.h"

sp_lift_opts sp_lift_opts_default(void)
{
    sp_lift_opts o = {1e-4f, 0};
    return o;
}

typedef struct {
    sp_device *dev;
    sp_scene *scene; /* the splat's geometry on the device */
    void *colors, *image, *v_image, *v_colors;
} lift_bufs;

static void bufs_free(lift_bufs *b)
{
    sp_scene_free(b->scene);
    b->scene = NULL;
    void **p[] = {&b->colors, &b->image, &b->v_image, &b->v_colors};
    for (size_t i = 0; i < sizeof p / sizeof p[0]; i++) {
        if (*p[i]) sp_device_release(b->dev, *p[i]);
        *p[i] = NULL;
    }
}

int sp_semantic_lift(sp_raster *r, sp_splat *s, int dim, const sp_camera *cams, size_t n_views,
                     sp_lift_target_fn target, void *user, const sp_lift_opts *opts,
                     float *weight_out, const sp_log *log, sp_error *err)
{
    sp_lift_opts o = opts ? *opts : sp_lift_opts_default();
    if (!r || !s || !cams || !target) return sp_error_set(err, SP_E_ARG, "lift: missing argument");
    int rc = sp_feature_dim_check(dim, SP_E_ARG, "lift", err);
    if (rc) return rc;
    if (n_views == 0) return sp_error_set(err, SP_E_ARG, "lift: no views");
    if (s->n == 0) return sp_error_set(err, SP_E_ARG, "lift: the splat has no Gaussians");
    int maxw = 0, maxh = 0;
    for (size_t v = 0; v < n_views; v++) {
        if (cams[v].width < 1 || cams[v].height < 1)
            return sp_error_set(err, SP_E_ARG, "lift: view %zu has size %dx%d", v, cams[v].width,
                                cams[v].height);
        if (cams[v].width > maxw) maxw = cams[v].width;
        if (cams[v].height > maxh) maxh = cams[v].height;
    }
    const int C = dim + 1;
    const size_t n = s->n, npix = (size_t)maxw * maxh;
    sp_device *dev = sp_raster_device(r);
    lift_bufs b;
    memset(&b, 0, sizeof b);
    b.dev = dev;
    float *target_buf = NULL, *vimg = NULL, *acc = NULL;
    uint8_t *mask = NULL;
    sp_progress bar;
    int bar_on = 0;

    sp_raster_in in;
    if ((rc = sp_scene_create(&b.scene, dev, s, 0, err)) ||
        (rc = sp_scene_raster_in(b.scene, &in, err)))
        goto done;
    if (!(b.colors = sp_device_alloc(dev, n * C * sizeof(float), err)) ||
        !(b.v_colors = sp_device_alloc(dev, n * C * sizeof(float), err)) ||
        !(b.image = sp_device_alloc(dev, npix * C * sizeof(float), err)) ||
        !(b.v_image = sp_device_alloc(dev, npix * C * sizeof(float), err))) {
        rc = err ? err->code : SP_E_NOMEM;
        if (rc == 0) rc = SP_E_NOMEM;
        goto done;
    }
    target_buf = malloc(npix * (size_t)dim * sizeof(float));
    vimg = malloc(npix * (size_t)C * sizeof(float));
    acc = malloc(n * (size_t)C * sizeof(float));
    if (o.mask) mask = malloc(npix);
    if (!target_buf || !vimg || !acc || (o.mask && !mask)) {
        rc = sp_error_set(err, SP_E_NOMEM, "lift: out of memory for %dx%d x %d maps", maxw, maxh, C);
        goto done;
    }

    sp_progress_begin(&bar, log, "lift", (long)n_views, "views");
    bar_on = 1;
    sp_raster_cfg cfg = sp_raster_cfg_default();
    for (size_t v = 0; v < n_views; v++) {
        const sp_camera *cam = &cams[v];
        size_t np = (size_t)cam->width * cam->height;
        if (mask) memset(mask, 1, np);
        if ((rc = target(user, v, target_buf, mask, err))) {
            sp_error_prefix(err, "lift: view %zu: ", v);
            goto done;
        }
        for (size_t p = 0; p < np; p++) {
            float *o_ = vimg + p * C;
            if (mask && !mask[p]) {
                memset(o_, 0, sizeof(float) * C);
                continue;
            }
            memcpy(o_, target_buf + p * dim, sizeof(float) * dim);
            o_[dim] = 1.0f;
        }
        if ((rc = sp_device_upload(dev, b.v_image, vimg, np * C * sizeof(float), err))) goto done;
        in.colors = b.colors;
        in.D = C;
        sp_raster_out out = {b.image, NULL, NULL, NULL};
        if ((rc = sp_raster_forward(r, cam, &cfg, &in, &out, err))) {
            sp_error_prefix(err, "lift: view %zu: ", v);
            goto done;
        }
        sp_raster_grad_in gin = {b.v_image, NULL, NULL};
        sp_raster_grads g = {0};
        g.v_colors = b.v_colors;
        if ((rc = sp_raster_backward(r, &gin, &g, err))) {
            sp_error_prefix(err, "lift: view %zu: ", v);
            goto done;
        }
        sp_progress_update(&bar, (long)v + 1, NULL);
    }
    if ((rc = sp_device_download(dev, acc, b.v_colors, n * C * sizeof(float), err))) goto done;

    float *feat = sp_calloc(n * (size_t)dim, sizeof(float));
    if (!feat) {
        rc = sp_error_set(err, SP_E_NOMEM, "lift: out of memory for %zu x %d features", n, dim);
        goto done;
    }
    size_t lifted = 0;
    for (size_t i = 0; i < n; i++) {
        const float *a = acc + i * C;
        float wsum = a[dim];
        if (weight_out) weight_out[i] = wsum;
        if (!(wsum >= o.min_weight) || !isfinite(wsum)) continue;
        lifted++;
        for (int c = 0; c < dim; c++) feat[i * dim + c] = a[c] / wsum;
    }
    sp_free(s->features);
    s->features = feat;
    s->feat_dim = dim;
    char extra[96];
    snprintf(extra, sizeof extra, "%zu of %zu Gaussians seen", lifted, n);
    sp_progress_end(&bar, extra);
    bar_on = 0;
done:
    if (bar_on) sp_progress_end(&bar, "failed");
    bufs_free(&b);
    free(target_buf);
    free(vimg);
    free(acc);
    free(mask);
    return rc;
}
