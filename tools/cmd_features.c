/* semsplat features: dense per-image feature maps (CLIP, imported .npy, or synthetic labels) and
 * the scene PCA, written as a feature folder for lift/distill/query. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/clip.h"

static void help(void)
{
    printf("usage: semsplat features --colmap DIR --out DIR [--source clip|npy|labels] [--dim D]\n"
           "         clip:   --clip MODEL.safetensors [--config config.json] [--head clearclip|maskclip]\n"
           "                 [--scales 2,1] [--tile PX] [--stride PX] [--batch N] [--fp16]\n"
           "         npy:    --maps DIR   (DIR/<image stem>.npy, [H][W][C] or [C][H][W], any C)\n"
           "         labels: [--labels DIR] [--clip MODEL.safetensors] [--factor F]\n"
           "       [--images DIR] [--samples N] [--device cpu|cuda|auto] [--threads N] [--quiet]\n\n"
           "Writes DIR/features.json, pca_mean.npy [full_dim], pca_basis.npy [dim][full_dim] and\n"
           "maps/<image stem>.npy [h][w][dim] float16. --dim is the PCA size (at most 64, 16..64 typical,\n"
           "default 32). clip: CLIP ViT dense features (ClearCLIP head) in the text space, one per\n"
           "patch/scale pixels (8 px for ViT-B/16 at scale 2) from overlapping tiles. labels: each\n"
           "class's CLIP text embedding when --clip is given, else a fixed random unit vector per\n"
           "class (sp_label_embedding); maps at 1/F of the image (default 4). Real weights:\n"
           "openai/clip-vit-base-patch16 model.safetensors + config.json from Hugging Face.\n");
}

static int parse_scales(const char *s, sp_clip_dense_opts *d)
{
    d->n_scales = 0;
    while (*s && d->n_scales < 4) {
        char *end;
        double v = strtod(s, &end);
        if (end == s) return -1;
        d->scales[d->n_scales++] = (float)v;
        s = *end == ',' ? end + 1 : end;
        if (*end && *end != ',') return -1;
    }
    return d->n_scales > 0 && !*s ? 0 : -1;
}

int cmd_features(int argc, char **argv)
{
    sp_features_opts o = sp_features_opts_default();
    cli_common c = cli_common_default();
    const char *v;
    long num;
    int bad = 0, r;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((r = cli_common_flag("features", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) o.colmap_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) o.out_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--source", &bad))) o.source = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--clip", &bad))) o.clip_weights = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--config", &bad))) o.clip_config = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--maps", &bad))) o.maps_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--labels", &bad))) o.labels_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--images", &bad))) o.images_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--head", &bad))) {
            if (!strcmp(v, "clearclip")) o.dense.head = SP_CLIP_HEAD_CLEARCLIP;
            else if (!strcmp(v, "maskclip")) o.dense.head = SP_CLIP_HEAD_MASKCLIP;
            else return cli_usage_error("features", "--head: '%s' is not clearclip or maskclip", v);
        } else if ((v = cli_flag_value(argc, argv, &i, "--scales", &bad))) {
            if (parse_scales(v, &o.dense)) return cli_usage_error("features", "--scales: '%s' is not like 2,1", v);
        } else if ((v = cli_flag_value(argc, argv, &i, "--dim", &bad))) {
            if (cli_parse_int("features", "--dim", v, &num)) return 2;
            if (num < 1) return cli_usage_error("features", "--dim %ld: expected at least 1", num);
            o.dim = (int)num;
        } else if ((v = cli_flag_value(argc, argv, &i, "--factor", &bad))) {
            if (cli_parse_int("features", "--factor", v, &num)) return 2;
            if (num < 1) return cli_usage_error("features", "--factor %ld: expected at least 1", num);
            o.map_factor = (int)num;
        } else if ((v = cli_flag_value(argc, argv, &i, "--samples", &bad))) {
            if (cli_parse_int("features", "--samples", v, &num)) return 2;
            if (num < 1) return cli_usage_error("features", "--samples %ld: expected at least 1", num);
            o.pca_samples = num;
        } else if ((v = cli_flag_value(argc, argv, &i, "--tile", &bad))) {
            if (cli_parse_int("features", "--tile", v, &num)) return 2;
            o.dense.tile = (int)num;
        } else if ((v = cli_flag_value(argc, argv, &i, "--stride", &bad))) {
            if (cli_parse_int("features", "--stride", v, &num)) return 2;
            o.dense.stride = (int)num;
        } else if ((v = cli_flag_value(argc, argv, &i, "--batch", &bad))) {
            if (cli_parse_int("features", "--batch", v, &num)) return 2;
            o.dense.batch = (int)num;
        } else if (!strcmp(argv[i], "--fp16")) o.fp16 = 1;
        else if (!bad) return cli_usage_error("features", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!o.colmap_dir || !o.out_dir) return cli_usage_error("features", "--colmap and --out are required");
    sp_error err = {0};
    sp_log log = cli_log(&c, SP_LOG_INFO);
    sp_device *dev = NULL;
    if (cli_device_open("features", &c, &dev)) return 1;
    o.dev = dev;
    o.log = &log;
    double t0 = sp_time_now();
    int rc = sp_features_extract(&o, &err);
    double dt = sp_time_now() - t0;
    if (!rc && !c.quiet)
        printf("features  %.2f  s  (source %s, dim %d, %s, out %s)\n", dt, o.source, o.dim,
               sp_device_name(dev), o.out_dir);
    sp_device_free(dev);
    return rc ? cli_fail("features", &err) : 0;
}
