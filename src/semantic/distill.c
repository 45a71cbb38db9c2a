/* Distillation of a model folder: continue training DIR/splat.ply with the feature loss (the
 * trainer's feature pass) against a feature folder's maps, starting from the one-pass lift or
 * from zero, then write f_sem_* and the sidecar. RGB PSNR is measured before and after so the
 * cost to appearance is visible. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"

sp_distill_opts sp_distill_opts_default(void)
{
    sp_distill_opts o;
    memset(&o, 0, sizeof o);
    o.steps = 3000;
    o.lambda = 1.0f;
    o.init_from_lift = 1;
    o.downscale = 1;
    return o;
}

typedef struct {
    sp_features *f;
    const sp_train_data *d;
} target_ctx;

static int feature_target(void *user, size_t view, int width, int height, int F, float *dst,
                          sp_error *err)
{
    target_ctx *c = user;
    const char *name = c->d->views[view].name;
    long k = sp_features_find(c->f, name);
    if (k < 0) return sp_error_set(err, SP_E_NOTFOUND, "%s: no feature map for image %s", c->f->dir, name);
    if (F != c->f->dim)
        return sp_error_set(err, SP_E_ARG, "distill: asked for %d channels, maps have %d", F, c->f->dim);
    int rc = sp_features_load_map(c->f, (size_t)k, err);
    if (rc) return rc;
    sp_features_image *im = &c->f->images[k];
    if (im->w == width && im->h == height)
        memcpy(dst, im->map, sizeof(float) * (size_t)width * height * F);
    else
        sp_clip_upsample(im->map, im->w, im->h, F, width, height, dst);
    free(im->map); /* one map at a time */
    im->map = NULL;
    return 0;
}

static sp_train_options distill_options(const sp_distill_opts *o, const sp_splat *s, int dim,
                                        target_ctx *ctx)
{
    sp_train_options t = sp_train_options_default(o->steps);
    t.sh_degree = s->sh_degree;
    t.feature_dim = dim;
    t.feature_lambda = o->lambda;
    t.get_feature_target = feature_target;
    t.feature_user = ctx;
    t.freeze_geometry = o->freeze_geometry;
    /* Continuing from a trained model: no fresh densification or opacity resets (their
     * schedules scale down with short runs and would wipe the trained opacities). */
    if (!o->densify) t.refine_start = o->steps + 1;
    t.reset_every = o->steps + 1;
    return t;
}

int sp_semantic_distill_model(sp_device *dev, const sp_distill_opts *o, sp_distill_result *res,
                              const sp_log *log, sp_error *err)
{
    if (!o->model_dir || !o->features_dir || !o->colmap_dir)
        return sp_error_set(err, SP_E_ARG, "distill: model_dir, features_dir and colmap_dir are required");
    if (o->steps < 1 || o->downscale < 1)
        return sp_error_set(err, SP_E_ARG, "distill: steps (%d) and downscale (%d) must be >= 1",
                            o->steps, o->downscale);
    sp_features f;
    sp_train_data d;
    sp_splat s;
    memset(&f, 0, sizeof f);
    memset(&d, 0, sizeof d);
    memset(&s, 0, sizeof s);
    memset(res, 0, sizeof *res);
    char path[2048];
    snprintf(path, sizeof path, "%s/splat.ply", o->model_dir);
    int rc = sp_features_open(o->features_dir, &f, err);
    if (!rc) rc = sp_train_data_load(&d, o->colmap_dir, o->images_dir, o->downscale, 8, err);
    /* The trainer undistorts the images, not the feature maps: refuse rather than distil maps
     * whose pixels sit where the lens put them (lift resamples them: use lift). */
    if (!rc && d.n_undistorted)
        rc = sp_error_set(err, SP_E_UNSUPPORTED,
                          "%s: %zu of %zu images have a distorted camera; distill does not resample "
                          "feature maps through the lens yet: use `semsplat lift`, or run `colmap "
                          "image_undistorter` and extract features from its output",
                          o->colmap_dir, d.n_undistorted, d.n_views);
    if (!rc) rc = sp_ply_read_splat(path, &s, err);
    float bg[3] = {0, 0, 0};
    if (!rc) rc = sp_train_evaluate(dev, &d, &s, bg, &res->before, err);
    if (!rc && o->init_from_lift)
        rc = sp_semantic_lift_features(&s, o->features_dir, o->colmap_dir, dev, log, err);
    if (!rc && !o->init_from_lift && s.feat_dim) {
        sp_free(s.features);
        s.features = NULL;
        s.feat_dim = 0;
    }
    target_ctx ctx = {&f, &d};
    if (!rc) {
        sp_train_options t = distill_options(o, &s, f.dim, &ctx);
        rc = sp_train_run(dev, &d, &t, &s, &res->after, log, err);
    }
    if (!rc) rc = sp_ply_write_splat(path, &s, err);
    if (!rc) rc = sp_semantic_write_sidecar(o->model_dir, o->features_dir, o->colmap_dir, "distill", err);
    sp_splat_free(&s);
    sp_train_data_free(&d);
    sp_features_free(&f);
    return rc;
}
