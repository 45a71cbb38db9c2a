/* semsplat train: fits a Gaussian splat to a COLMAP capture (gsplat simple_trainer defaults) into
 * a model folder (sp_train_model: splat.ply, train.json, frame.json, checkpoints/). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "semsplat/train.h"

static void help(void)
{
    printf(
        "usage: semsplat train --colmap DIR --out DIR [flags]\n\n"
        "Trains a 3D Gaussian splat from a COLMAP capture (capture root with sparse/0 and\n"
        "images/, or the model folder itself). Writes OUT/splat.ply, OUT/train.json,\n"
        "OUT/frame.json (the capture's frame: world for synth captures, else colmap) and\n"
        "OUT/checkpoints/checkpoint.bin. Every 8th image (sorted by name) is held out.\n\n"
        "  --images DIR          image folder (default COLMAP/images)\n"
        "  --steps N             optimisation steps (default 30000); below 30000 steps the SH\n"
        "                        schedule scales; densification stops at max(N/2, N - 2000),\n"
        "                        at most at 15000 (gsplat's)\n"
        "  --downscale N         integer image downscale factor (default 1)\n"
        "  --device D            cpu, cuda or auto (default auto)\n"
        "  --threads N           CPU threads (default: all cores)\n"
        "  --init points|random  initialise from points3D (default) or randomly\n"
        "  --init-points N       number of random points (default 100000)\n"
        "  --init-ply FILE       train further from an existing splat (3DGS/gsplat PLY)\n"
        "  --sh-degree N         final SH degree 0..3 (default 3)\n"
        "  --sh-interval N       raise the SH degree every N steps (default 1000 x steps/30000)\n"
        "  --max-gaussians N     cap on the Gaussian count (default 0 = none)\n"
        "  --no-densify          keep the initial Gaussians (no clone/split/prune)\n"
        "  --refine-start N --refine-stop N --refine-every N --reset-every N\n"
        "  --grow-grad2d X       densification threshold (default 0.00015 for RGB-only runs\n"
        "                        under 30000 steps, else gsplat's 0.0002)\n"
        "  --random-bg           composite on a random background each step\n"
        "  --depth-lambda X      depth supervision weight (default 0 = off): adds X * mean of\n"
        "                        alpha |expected depth - measured depth| (metres) over pixels with\n"
        "                        depth, from --depth DIR (default COLMAP/depth: a synth capture's\n"
        "                        depth/NNNNN.npy, float32 [h][w]); views without a file skip it\n"
        "  --depth DIR           depth folder (<image stem>.npy per view)\n"
        "  --test-every N        hold out every N-th image (default 8; 0 = none)\n"
        "  --eval-every N        held-out evaluation every N steps (default: at the end)\n"
        "  --checkpoint-every N  (default 1000)\n"
        "  --resume [FILE]       continue from FILE (default OUT/checkpoints/checkpoint.bin)\n"
        "  --seed N              random seed (default 42)\n"
        "  --quiet / --verbose\n");
}

/* Flags not given keep the schedule's defaults; any value given goes to the library's range checks
 * (a bad one is an error naming it, never silently the default). */
#define UNSET LONG_MIN

typedef struct {
    long steps, downscale, init_points, sh_degree, sh_interval, max_g, test_every, eval_every;
    long ck_every, seed, refine_start, refine_stop, refine_every, reset_every;
    double grow, depth_lambda;
    const char *colmap, *images, *out, *init, *init_ply, *resume, *depth;
    int want_resume, no_densify, random_bg;
} train_flags;

#define INT_FLAG(name, var)                                                                        \
    else if ((v = cli_flag_value(argc, argv, &i, name, &bad))) {                                   \
        if (cli_parse_int("train", name, v, &f->var)) return 2;                                    \
    }

static int parse(int argc, char **argv, train_flags *f, cli_common *c)
{
    int bad = 0, r;
    const char *v;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), -1;
        if ((r = cli_common_flag("train", argc, argv, &i, CLI_ALL, c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) f->colmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--images", &bad))) f->images = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) f->out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--init-ply", &bad))) f->init_ply = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--init", &bad))) f->init = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--depth", &bad))) f->depth = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--depth-lambda", &bad))) {
            if (cli_parse_float("train", "--depth-lambda", v, &f->depth_lambda)) return 2;
        }
        INT_FLAG("--init-points", init_points)
        INT_FLAG("--steps", steps)
        INT_FLAG("--downscale", downscale)
        INT_FLAG("--sh-degree", sh_degree)
        INT_FLAG("--sh-interval", sh_interval)
        INT_FLAG("--max-gaussians", max_g)
        INT_FLAG("--test-every", test_every)
        INT_FLAG("--eval-every", eval_every)
        INT_FLAG("--checkpoint-every", ck_every)
        INT_FLAG("--seed", seed)
        INT_FLAG("--refine-start", refine_start)
        INT_FLAG("--refine-stop", refine_stop)
        INT_FLAG("--refine-every", refine_every)
        INT_FLAG("--reset-every", reset_every)
        else if ((v = cli_flag_value(argc, argv, &i, "--grow-grad2d", &bad))) {
            if (cli_parse_float("train", "--grow-grad2d", v, &f->grow)) return 2;
        } else if (!strcmp(argv[i], "--resume")) {
            f->want_resume = 1;
            if (i + 1 < argc && strncmp(argv[i + 1], "--", 2) != 0) f->resume = argv[++i];
        } else if (!strcmp(argv[i], "--no-densify")) f->no_densify = 1;
        else if (!strcmp(argv[i], "--random-bg")) f->random_bg = 1;
        else if (!bad) return cli_usage_error("train", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!f->colmap || !f->out) return cli_usage_error("train", "--colmap and --out are required");
    if (f->steps < 1) return cli_usage_error("train", "--steps must be >= 1 (got %ld)", f->steps);
    if (f->downscale < 1) return cli_usage_error("train", "--downscale must be >= 1 (got %ld)", f->downscale);
    if (f->sh_degree < 0 || f->sh_degree > 3) return cli_usage_error("train", "--sh-degree must be 0..3");
    if (f->sh_interval != UNSET && f->sh_interval < 1) return cli_usage_error("train", "--sh-interval must be positive");
    if (f->ck_every < 1) return cli_usage_error("train", "--checkpoint-every must be >= 1 (got %ld)", f->ck_every);
    if (f->max_g < 0) return cli_usage_error("train", "--max-gaussians must be >= 0");
    if (f->init_points < 1) return cli_usage_error("train", "--init-points must be >= 1");
    if (strcmp(f->init, "points") && strcmp(f->init, "random"))
        return cli_usage_error("train", "--init: '%s' is not points or random", f->init);
    return 0;
}

static sp_train_model_opts to_opts(const train_flags *f, char *resume, size_t cap)
{
    sp_train_model_opts m = sp_train_model_opts_default((int)f->steps);
    sp_train_options *o = &m.train;
    m.colmap_dir = f->colmap, m.images_dir = f->images, m.out_dir = f->out;
    m.downscale = (int)f->downscale, m.test_every = (int)f->test_every;
    m.init = f->init_ply ? SP_TRAIN_INIT_PLY : !strcmp(f->init, "random") ? SP_TRAIN_INIT_RANDOM : SP_TRAIN_INIT_POINTS;
    m.init_ply = f->init_ply, m.init_points = (size_t)f->init_points;
    if (f->want_resume) snprintf(resume, cap, "%s", f->resume ? f->resume : "");
    if (f->want_resume && !f->resume) snprintf(resume, cap, "%s/checkpoints/checkpoint.bin", f->out);
    m.resume = f->want_resume ? resume : NULL;
    o->sh_degree = (int)f->sh_degree;
    if (f->sh_interval != UNSET) o->sh_degree_interval = (int)f->sh_interval;
    o->max_gaussians = (size_t)f->max_g;
    o->densify = !f->no_densify;
    o->random_background = f->random_bg;
    o->seed = (uint64_t)f->seed;
    o->eval_every = (int)f->eval_every;
    o->checkpoint_every = (int)f->ck_every;
    if (f->refine_start != UNSET) o->refine_start = (int)f->refine_start;
    if (f->refine_stop != UNSET) o->refine_stop = (int)f->refine_stop;
    if (f->refine_every != UNSET) o->refine_every = (int)f->refine_every;
    if (f->reset_every != UNSET) o->reset_every = (int)f->reset_every;
    if (!isnan(f->grow)) o->grow_grad2d = (float)f->grow;
    o->depth_lambda = (float)f->depth_lambda;
    m.depth_dir = f->depth;
    return m;
}

int cmd_train(int argc, char **argv)
{
    train_flags f = {30000, 1, 100000, 3, UNSET, 0, 8, 0, 1000, 42, UNSET, UNSET, UNSET, UNSET, NAN, 0,
                     NULL, NULL, NULL, "points", NULL, NULL, NULL, 0, 0, 0};
    cli_common c = cli_common_default();
    int prc = parse(argc, argv, &f, &c);
    if (prc) return prc < 0 ? 0 : prc;
    char resume[4200];
    sp_train_model_opts m = to_opts(&f, resume, sizeof resume);
    sp_device *dev = NULL;
    if (cli_device_open("train", &c, &dev)) return 1;
    sp_error err = {0};
    sp_log log = cli_log(&c, SP_LOG_INFO);
    sp_train_result res;
    int rc = sp_train_model(dev, &m, &res, &log, &err);
    sp_device_free(dev);
    if (rc) return cli_fail("train", &err);
    if (!c.quiet) {
        printf("train  psnr       %.3f  dB  (%s, %d views)\n", res.psnr,
               res.eval_on_train ? "training views, none held out" : "held-out", res.n_eval_views);
        printf("train  ssim       %.4f\n", res.ssim);
        if (res.depth_eval_pixels > 0)
            printf("train  depth L1   %.4f  (expected depth; first surface %.4f; %.1f %% of depth pixels "
                   "not solid)\n", res.depth_l1, res.surface_depth_l1, 100.0 * res.depth_hole_share);
        printf("train  gaussians  %zu\n", res.gaussians);
        printf("train  seconds    %.1f  s  (%d steps, %s)\n", res.seconds, res.steps, res.device);
        printf("train  wrote      %s/splat.ply, %s/train.json, %s/frame.json\n", f.out, f.out, f.out);
    }
    return 0;
}
