/* semsplat distill: learns per-Gaussian features by joint training (RGB loss + lambda * feature
 * MSE through the N-channel rasterizer, the trainer's feature pass), starting from the RGB model
 * that `train` made, and writes the semantic field into the model folder. Prints held-out RGB
 * PSNR before and after so the cost to appearance is visible. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/clip.h"
#include "semsplat/io.h"
#include "semsplat/semantic.h"
#include "semsplat/train.h"

static void help(void)
{
    printf("usage: semsplat distill --model DIR --features DIR --colmap DIR [--images DIR]\n"
           "                        [--steps N] [--lambda L] [--freeze-geometry] [--densify]\n"
           "                        [--init lift|zero] [--downscale F]\n"
           "                        [--device cpu|cuda|auto] [--threads N] [--quiet]\n\n"
           "Continues training DIR/splat.ply with feature_lambda * MSE(rendered features, maps)\n"
           "added to the RGB loss (densification copies features to children; --freeze-geometry\n"
           "trains the features only). Features start from the one-pass lift (--init lift, the\n"
           "default) or zero. --densify keeps the trainer's clone/split schedule (children copy\n"
           "their parent's features); off by default as the model is already trained.\n"
           "Writes f_sem_* into DIR/splat.ply and DIR/semantic.json; prints RGB PSNR before/after.\n");
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
    if (F != c->f->dim) return sp_error_set(err, SP_E_ARG, "distill: asked for %d channels, maps have %d", F, c->f->dim);
    int rc = sp_features_load_map(c->f, (size_t)k, err);
    if (rc) return rc;
    sp_features_image *im = &c->f->images[k];
    if (im->w == width && im->h == height)
        memcpy(dst, im->map, sizeof(float) * (size_t)width * height * F);
    else
        sp_clip_upsample(im->map, im->w, im->h, F, width, height, dst);
    free(im->map);
    im->map = NULL;
    return 0;
}

int cmd_distill(int argc, char **argv)
{
    const char *model = NULL, *features = NULL, *colmap = NULL, *images = NULL, *device = "auto", *v;
    const char *init = "lift";
    int densify = 0;
    long steps = 3000, threads = 0, downscale = 1;
    double lambda = 1.0;
    int freeze = 0, quiet = 0, bad = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--features", &bad))) features = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--images", &bad))) images = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--init", &bad))) init = v;
        else if (!strcmp(argv[i], "--densify")) densify = 1;
        else if ((v = cli_flag_value(argc, argv, &i, "--steps", &bad))) {
            if (cli_parse_int("distill", "--steps", v, &steps)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--threads", &bad))) {
            if (cli_parse_int("distill", "--threads", v, &threads)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--downscale", &bad))) {
            if (cli_parse_int("distill", "--downscale", v, &downscale)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--lambda", &bad))) {
            if (cli_parse_float("distill", "--lambda", v, &lambda)) return 2;
        } else if (!strcmp(argv[i], "--freeze-geometry")) freeze = 1;
        else if (!strcmp(argv[i], "--quiet")) quiet = 1;
        else if (!bad) return cli_usage_error("distill", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!model || !features || !colmap)
        return cli_usage_error("distill", "--model, --features and --colmap are required");
    if (steps < 1 || downscale < 1) return cli_usage_error("distill", "--steps and --downscale must be >= 1");
    if (strcmp(init, "lift") && strcmp(init, "zero")) return cli_usage_error("distill", "--init: '%s' is not lift or zero", init);
    sp_device_kind kind = !strcmp(device, "cpu") ? SP_DEVICE_CPU
                          : !strcmp(device, "cuda") ? SP_DEVICE_CUDA
                          : !strcmp(device, "auto") ? SP_DEVICE_AUTO : (sp_device_kind)-1;
    if ((int)kind < 0) return cli_usage_error("distill", "--device: '%s' is not cpu, cuda or auto", device);
    sp_error err = {0};
    sp_log log = sp_log_stderr(SP_LOG_INFO, quiet);
    sp_device *dev = NULL;
    sp_features f;
    sp_train_data d;
    sp_splat s = {0};
    memset(&f, 0, sizeof f);
    memset(&d, 0, sizeof d);
    char path[2048];
    int rc = sp_device_create(&dev, kind, (int)threads, &err);
    if (!rc) rc = sp_features_open(features, &f, &err);
    if (!rc) rc = sp_train_data_load(&d, colmap, images, (int)downscale, 8, &err);
    /* The trainer undistorts the images, not the feature maps: refuse rather than distil maps
     * whose pixels sit where the lens put them (lift resamples them: use lift). */
    if (!rc && d.n_undistorted)
        rc = sp_error_set(&err, SP_E_UNSUPPORTED,
                          "%s: %zu of %zu images have a distorted camera; distill does not resample "
                          "feature maps through the lens yet: use `semsplat lift`, or run `colmap "
                          "image_undistorter` and extract features from its output",
                          colmap, d.n_undistorted, d.n_views);
    snprintf(path, sizeof path, "%s/splat.ply", model);
    if (!rc) rc = sp_ply_read_splat(path, &s, &err);
    sp_train_result before = {0}, after = {0};
    float bg[3] = {0, 0, 0};
    if (!rc) rc = sp_train_evaluate(dev, &d, &s, bg, &before, &err);
    /* Features start from the one-pass lift (the trainer then refines them jointly with RGB),
     * or from zero with --init zero. */
    if (!rc && !strcmp(init, "lift")) rc = sp_semantic_lift_features(&s, features, colmap, dev, &log, &err);
    if (!rc && !strcmp(init, "zero") && s.feat_dim) {
        sp_free(s.features);
        s.features = NULL;
        s.feat_dim = 0;
    }
    target_ctx ctx = {&f, &d};
    if (!rc) {
        sp_train_options o = sp_train_options_default((int)steps);
        o.sh_degree = s.sh_degree;
        o.feature_dim = f.dim;
        o.feature_lambda = (float)lambda;
        o.get_feature_target = feature_target;
        o.feature_user = &ctx;
        o.freeze_geometry = freeze;
        /* continuing from a trained model: no fresh densification or opacity resets (their
         * schedules scale down with short runs and would wipe the trained opacities) */
        if (!densify) o.refine_start = (int)steps + 1;
        o.reset_every = (int)steps + 1;
        rc = sp_train_run(dev, &d, &o, &s, &after, &log, &err);
    }
    if (!rc) rc = sp_ply_write_splat(path, &s, &err);
    if (!rc) rc = sp_semantic_write_sidecar(model, features, colmap, "distill", &err);
    if (!rc) { /* results, printed even with --quiet (which silences progress) */
        printf("distill  psnr_before  %.3f  dB  (%s)\n", before.psnr, before.eval_on_train ? "train views" : "held-out");
        printf("distill  psnr_after   %.3f  dB  (steps %ld, lambda %g%s)\n", after.psnr, steps, lambda,
               freeze ? ", geometry frozen" : "");
        printf("distill  feature_mse  %.5f  (%s)\n", after.feature_mse, after.eval_on_train ? "train views" : "held-out");
        printf("distill  seconds      %.1f  s  (%s)\n", after.seconds, sp_device_name(dev));
    }
    sp_splat_free(&s);
    sp_train_data_free(&d);
    sp_features_free(&f);
    sp_device_free(dev);
    return rc ? cli_fail("distill", &err) : 0;
}
