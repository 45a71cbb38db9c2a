/* semsplat train: fits a Gaussian splat to a COLMAP capture (gsplat simple_trainer defaults) and
 * writes OUT/splat.ply (3DGS layout), OUT/train.json (settings + held-out psnr/ssim) and
 * checkpoints in OUT/checkpoints/. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/io.h"
#include "semsplat/render.h"
#include "semsplat/train.h"

static void help(void)
{
    printf(
        "usage: semsplat train --colmap DIR --out DIR [flags]\n\n"
        "Trains a 3D Gaussian splat from a COLMAP capture (capture root with sparse/0 and\n"
        "images/, or the model folder itself). Writes OUT/splat.ply, OUT/train.json and\n"
        "OUT/checkpoints/checkpoint.bin. Every 8th image (sorted by name) is held out.\n\n"
        "  --images DIR          image folder (default COLMAP/images)\n"
        "  --steps N             optimisation steps (default 30000); density-control and SH\n"
        "                        below 30000 steps, densification stops at N/2 (gsplat: 15000)\n"
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
        "  --grow-grad2d X       densification threshold (default 0.0002)\n"
        "  --random-bg           composite on a random background each step\n"
        "  --test-every N        hold out every N-th image (default 8; 0 = none)\n"
        "  --eval-every N        held-out evaluation every N steps (default: at the end)\n"
        "  --checkpoint-every N  (default 1000)\n"
        "  --resume [FILE]       continue from FILE (default OUT/checkpoints/checkpoint.bin)\n"
        "  --seed N              random seed (default 42)\n"
        "  --quiet / --verbose\n");
}

#define INT_FLAG(name, var)                                                                        \
    else if ((v = cli_flag_value(argc, argv, &i, name, &bad))) {                                   \
        if (cli_parse_int("train", name, v, &tmp)) return 2;                                       \
        var = tmp;                                                                                 \
    }

int cmd_train(int argc, char **argv)
{
    const char *colmap = NULL, *images = NULL, *out = NULL, *device = "auto", *init = "points";
    const char *init_ply = NULL, *resume = NULL, *v;
    /* UNSET: flags not given keep the schedule's defaults; any value given goes to the library's
     * range checks (a bad one is an error naming it, never silently the default) */
    const long UNSET = LONG_MIN;
    long tmp, threads = 0, steps = 30000, downscale = 1, init_points = 100000, sh_degree = 3, sh_interval = UNSET;
    long max_g = 0, test_every = 8, eval_every = 0, ck_every = 1000, seed = 42;
    long refine_start = UNSET, refine_stop = UNSET, refine_every = UNSET, reset_every = UNSET;
    double grow = NAN;
    int quiet = 0, verbose = 0, bad = 0, no_densify = 0, random_bg = 0, want_resume = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) colmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--images", &bad))) images = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--init-ply", &bad))) init_ply = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--init-points", &bad))) {
            if (cli_parse_int("train", "--init-points", v, &init_points)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--init", &bad))) init = v;
        INT_FLAG("--threads", threads)
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
            if (cli_parse_float("train", "--grow-grad2d", v, &grow)) return 2;
        } else if (!strcmp(argv[i], "--resume")) {
            want_resume = 1;
            if (i + 1 < argc && strncmp(argv[i + 1], "--", 2) != 0) resume = argv[++i];
        } else if (!strcmp(argv[i], "--no-densify")) no_densify = 1;
        else if (!strcmp(argv[i], "--random-bg")) random_bg = 1;
        else if (!strcmp(argv[i], "--quiet")) quiet = 1;
        else if (!strcmp(argv[i], "--verbose")) verbose = 1;
        else if (!bad) return cli_usage_error("train", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!colmap || !out) return cli_usage_error("train", "--colmap and --out are required");
    if (steps < 1) return cli_usage_error("train", "--steps must be >= 1 (got %ld)", steps);
    if (downscale < 1) return cli_usage_error("train", "--downscale must be >= 1 (got %ld)", downscale);
    if (sh_degree < 0 || sh_degree > 3) return cli_usage_error("train", "--sh-degree must be 0..3");
    if (sh_interval != UNSET && sh_interval < 1) return cli_usage_error("train", "--sh-interval must be positive");
    if (max_g < 0) return cli_usage_error("train", "--max-gaussians must be >= 0");
    if (strcmp(init, "points") && strcmp(init, "random"))
        return cli_usage_error("train", "--init: '%s' is not points or random", init);
    sp_device_kind kind = !strcmp(device, "cpu") ? SP_DEVICE_CPU
                          : !strcmp(device, "cuda") ? SP_DEVICE_CUDA
                          : !strcmp(device, "auto") ? SP_DEVICE_AUTO : (sp_device_kind)-1;
    if ((int)kind < 0) return cli_usage_error("train", "--device: '%s' is not cpu, cuda or auto", device);

    sp_error err = {0};
    sp_log log = sp_log_stderr(verbose ? SP_LOG_DEBUG : SP_LOG_INFO, quiet);
    char ckdir[4096], ckfile[4200], plyp[4200], jsonp[4200];
    snprintf(ckdir, sizeof ckdir, "%s/checkpoints", out);
    snprintf(ckfile, sizeof ckfile, "%s/checkpoint.bin", ckdir);
    snprintf(plyp, sizeof plyp, "%s/splat.ply", out);
    snprintf(jsonp, sizeof jsonp, "%s/train.json", out);
    if (want_resume && !resume) resume = ckfile;
    if (resume && !sp_file_exists(resume)) {
        sp_error_set(&err, SP_E_NOTFOUND, "--resume: %s does not exist", resume);
        return cli_fail("train", &err);
    }
    if (sp_mkdirs(out, &err)) return cli_fail("train", &err);

    sp_train_data d;
    if (sp_train_data_load(&d, colmap, images, (int)downscale, (int)test_every, &err))
        return cli_fail("train", &err);
    sp_logf(&log, SP_LOG_INFO, "%zu views at %dx%d, %zu points, scene scale %.3f", d.n_views,
            d.views[0].cam.width, d.views[0].cam.height, d.n_points, (double)d.scene_scale);
    sp_device *dev = NULL;
    sp_splat s;
    memset(&s, 0, sizeof s);
    int rc = sp_device_create(&dev, kind, (int)threads, &err);
    if (!rc && !resume) {
        if (init_ply) {
            rc = sp_ply_read_splat(init_ply, &s, &err);
            if (!rc && s.n == 0) rc = sp_error_set(&err, SP_E_FORMAT, "%s: the splat is empty", init_ply);
            if (!rc) sp_logf(&log, SP_LOG_INFO, "starting from %s: %zu Gaussians", init_ply, s.n);
        } else if (!strcmp(init, "random") || d.n_points == 0) {
            if (d.n_points == 0 && strcmp(init, "random"))
                sp_logf(&log, SP_LOG_WARN, "the COLMAP model has no points3D: using random init");
            rc = sp_train_init_random(&s, &d, (size_t)init_points, 3.0f, (int)sh_degree,
                                      (uint64_t)seed, &err);
        } else {
            rc = sp_train_init_from_points(&s, &d, (int)sh_degree, (uint64_t)seed, &err);
        }
    }
    sp_train_options o = sp_train_options_default((int)steps);
    o.sh_degree = (int)sh_degree;
    if (sh_interval != UNSET) o.sh_degree_interval = (int)sh_interval;
    o.max_gaussians = (size_t)max_g;
    o.densify = !no_densify;
    o.random_background = random_bg;
    o.seed = (uint64_t)seed;
    o.eval_every = (int)eval_every;
    o.checkpoint_every = (int)ck_every;
    o.checkpoint_dir = ckdir;
    o.resume = resume;
    if (refine_start != UNSET) o.refine_start = (int)refine_start;
    if (refine_stop != UNSET) o.refine_stop = (int)refine_stop;
    if (refine_every != UNSET) o.refine_every = (int)refine_every;
    if (reset_every != UNSET) o.reset_every = (int)reset_every;
    if (!isnan(grow)) o.grow_grad2d = (float)grow;
    sp_train_result res;
    memset(&res, 0, sizeof res);
    if (!rc) rc = sp_train_run(dev, &d, &o, &s, &res, &log, &err);
    if (!rc) rc = sp_ply_write_splat(plyp, &s, &err);
    if (!rc) rc = sp_train_write_json(jsonp, &o, &res, colmap, images, (int)downscale, &err);
    if (!rc && !quiet) {
        printf("train  psnr       %.3f  dB  (%s, %d views)\n", res.psnr,
               res.eval_on_train ? "training views, none held out" : "held-out", res.n_eval_views);
        printf("train  ssim       %.4f\n", res.ssim);
        printf("train  gaussians  %zu\n", res.gaussians);
        printf("train  seconds    %.1f  s  (%d steps, %s)\n", res.seconds, res.steps, res.device);
        printf("train  wrote      %s, %s\n", plyp, jsonp);
    }
    sp_splat_free(&s);
    sp_device_free(dev);
    sp_train_data_free(&d);
    return rc ? cli_fail("train", &err) : 0;
}
