/* semsplat distill: learns per-Gaussian features by joint training (sp_semantic_distill_model)
 * and prints held-out RGB PSNR before and after, so the cost to appearance is visible. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "semsplat/semantic.h"

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

static int parse(int argc, char **argv, sp_distill_opts *o, cli_common *c)
{
    const char *v, *init = "lift";
    long num;
    double lambda;
    int bad = 0, r;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), -1;
        if ((r = cli_common_flag("distill", argc, argv, &i, CLI_ALL, c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) o->model_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--features", &bad))) o->features_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) o->colmap_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--images", &bad))) o->images_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--init", &bad))) init = v;
        else if (!strcmp(argv[i], "--densify")) o->densify = 1;
        else if (!strcmp(argv[i], "--freeze-geometry")) o->freeze_geometry = 1;
        else if ((v = cli_flag_value(argc, argv, &i, "--steps", &bad))) {
            if (cli_parse_int("distill", "--steps", v, &num)) return 2;
            o->steps = (int)num;
        } else if ((v = cli_flag_value(argc, argv, &i, "--downscale", &bad))) {
            if (cli_parse_int("distill", "--downscale", v, &num)) return 2;
            o->downscale = (int)num;
        } else if ((v = cli_flag_value(argc, argv, &i, "--lambda", &bad))) {
            if (cli_parse_float("distill", "--lambda", v, &lambda)) return 2;
            o->lambda = (float)lambda;
        } else if (!bad) return cli_usage_error("distill", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!o->model_dir || !o->features_dir || !o->colmap_dir)
        return cli_usage_error("distill", "--model, --features and --colmap are required");
    if (o->steps < 1 || o->downscale < 1) return cli_usage_error("distill", "--steps and --downscale must be >= 1");
    if (strcmp(init, "lift") && strcmp(init, "zero"))
        return cli_usage_error("distill", "--init: '%s' is not lift or zero", init);
    o->init_from_lift = !strcmp(init, "lift");
    return 0;
}

int cmd_distill(int argc, char **argv)
{
    sp_distill_opts o = sp_distill_opts_default();
    cli_common c = cli_common_default();
    int prc = parse(argc, argv, &o, &c);
    if (prc) return prc < 0 ? 0 : prc;
    sp_device *dev = NULL;
    if (cli_device_open("distill", &c, &dev)) return 1;
    sp_error err = {0};
    sp_log log = cli_log(&c, SP_LOG_INFO);
    sp_distill_result r;
    int rc = sp_semantic_distill_model(dev, &o, &r, &log, &err);
    if (!rc) { /* results, printed even with --quiet (which silences progress) */
        printf("distill  psnr_before  %.3f  dB  (%s)\n", r.before.psnr,
               r.before.eval_on_train ? "train views" : "held-out");
        printf("distill  psnr_after   %.3f  dB  (steps %d, lambda %g%s)\n", r.after.psnr, o.steps,
               (double)o.lambda, o.freeze_geometry ? ", geometry frozen" : "");
        printf("distill  feature_mse  %.5f  (%s)\n", r.after.feature_mse,
               r.after.eval_on_train ? "train views" : "held-out");
        printf("distill  seconds      %.1f  s  (%s)\n", r.after.seconds, sp_device_name(dev));
    }
    sp_device_free(dev);
    return rc ? cli_fail("distill", &err) : 0;
}
