/* semsplat lift: writes the semantic field into a model folder made by `train`, by lifting a
 * feature folder (semsplat features) in one pass over the training views. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "semsplat/render.h"
#include "semsplat/semantic.h"

static void help(void)
{
    printf("usage: semsplat lift --model DIR --features DIR [--colmap DIR] [--device cpu|cuda|auto]\n"
           "                     [--threads N] [--quiet]\n\n"
           "Sets each Gaussian's feature to the compositing-weight average of the feature maps\n"
           "it contributes to (one pass over the training views; geometry unchanged). Writes\n"
           "f_sem_* into DIR/splat.ply and DIR/semantic.json (+ the PCA beside it).\n"
           "--colmap defaults to the capture named in DIR/train.json.\n");
}

int cmd_lift(int argc, char **argv)
{
    const char *model = NULL, *features = NULL, *colmap = NULL, *device = "auto", *v;
    long threads = 0;
    int quiet = 0, bad = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--features", &bad))) features = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--threads", &bad))) {
            if (cli_parse_int("lift", "--threads", v, &threads)) return 2;
        } else if (!strcmp(argv[i], "--quiet")) quiet = 1;
        else if (!bad) return cli_usage_error("lift", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!model || !features) return cli_usage_error("lift", "--model and --features are required");
    sp_device_kind kind = !strcmp(device, "cpu") ? SP_DEVICE_CPU
                          : !strcmp(device, "cuda") ? SP_DEVICE_CUDA
                          : !strcmp(device, "auto") ? SP_DEVICE_AUTO : (sp_device_kind)-1;
    if ((int)kind < 0) return cli_usage_error("lift", "--device: '%s' is not cpu, cuda or auto", device);
    sp_error err = {0};
    sp_log log = sp_log_stderr(SP_LOG_INFO, quiet);
    sp_device *dev = NULL;
    if (sp_device_create(&dev, kind, (int)threads, &err)) return cli_fail("lift", &err);
    double t0 = sp_time_now();
    int rc = sp_semantic_lift_model(model, features, colmap, dev, &log, &err);
    double dt = sp_time_now() - t0;
    if (!rc) /* the result line is printed even with --quiet (which silences progress) */
        printf("lift  %.2f  s  (%s, model %s)\n", dt, sp_device_name(dev), model);
    sp_device_free(dev);
    return rc ? cli_fail("lift", &err) : 0;
}
