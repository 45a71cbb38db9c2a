/* semsplat lift: writes the semantic field into a model folder made by `train`, by lifting a
 * feature folder (semsplat features) in one pass over the training views. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "semsplat/semantic.h"

static void help(void)
{
    printf("usage: semsplat lift --model DIR --features DIR [--colmap DIR] [--encoder NAME]\n"
           "                     [--device cpu|cuda|auto] [--threads N] [--quiet]\n\n"
           "Sets each Gaussian's feature to the compositing-weight average of the feature maps\n"
           "it contributes to (one pass over the training views; geometry unchanged). Writes\n"
           "f_sem_* into DIR/splat.ply and DIR/semantic.json (+ the PCA beside it).\n"
           "--colmap defaults to the capture named in DIR/train.json. --encoder records the text\n"
           "encoder queries use (semantic.json \"encoder\"): clip for CLIP features; lexical\n"
           "(default: WordNet against the class names) or exact (hashed names) for label features.\n");
}

int cmd_lift(int argc, char **argv)
{
    const char *model = NULL, *features = NULL, *colmap = NULL, *encoder = NULL, *v;
    cli_common c = cli_common_default();
    int bad = 0, r;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((r = cli_common_flag("lift", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--features", &bad))) features = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--encoder", &bad))) encoder = v;
        else if (!bad) return cli_usage_error("lift", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!model || !features) return cli_usage_error("lift", "--model and --features are required");
    if (encoder && strcmp(encoder, SP_ENCODER_CLIP) && strcmp(encoder, SP_ENCODER_LEXICAL) && strcmp(encoder, SP_ENCODER_EXACT))
        return cli_usage_error("lift", "--encoder: '%s' is not clip, lexical or exact", encoder);
    sp_device *dev = NULL;
    if (cli_device_open("lift", &c, &dev)) return 1;
    sp_error err = {0};
    sp_log log = cli_log(&c, SP_LOG_INFO);
    double t0 = sp_time_now();
    int rc = sp_semantic_lift_model(model, features, colmap, dev, &log, &err);
    if (!rc && encoder) rc = sp_semantic_set_encoder(model, encoder, &err);
    double dt = sp_time_now() - t0;
    if (!rc) /* the result line is printed even with --quiet (which silences progress) */
        printf("lift  %.2f  s  (%s, model %s)\n", dt, sp_device_name(dev), model);
    sp_device_free(dev);
    return rc ? cli_fail("lift", &err) : 0;
}
