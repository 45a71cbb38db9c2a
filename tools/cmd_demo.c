/* semsplat demo: the whole pipeline on the bundled house (or a capture you give) through
 * sp_demo_run: synth -> train -> features -> lift -> a query for every ground-truth class with
 * both localization methods, scored one-to-one against ground_truth.json. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/eval.h"

static const char *usage_text =
    "usage: semsplat demo [--out DIR] [--world W.world] [--model-path DIR] [--capture DIR]\n"
    "                     [--views N] [--size WxH] [--steps N] [--downscale N] [--dim D] [--points N]\n"
    "                     [--depth-lambda X]\n"
    "                     [--match-radius M] [--device cpu|cuda|auto] [--threads N]\n"
    "                     [--clip MODEL.safetensors] [--skip-missing] [--reuse] [--quiet]\n"
    "                     [--model DIR] [--walk-only | --plan mixed|walk|drive] [--no-video]\n"
    "                     [--offline-robot] [--time-scale S] [--video-size WxH] [--fps N]\n"
    "                     [--drive-frames N] [--view-size WxH]\n\n"
    "Runs synth -> train -> features -> lift -> queries and writes DIR (default demo/):\n"
    "  capture/ (COLMAP model, images, depth, labels, ground_truth.json, frame.json), model/\n"
    "  (splat.ply with f_sem_* features, train.json, frame.json, semantic.json), features/,\n"
    "  heatmaps/<class>.png, demo.json, report.md, agent/ (answers, images) and demo.mp4: three\n"
    "  navigation commands through the agent and the simulated robot (over loopback DDS when\n"
    "  built with Cyclone DDS, else the offline robot, which the video then says).\n"
    "Scoring: returned instances are matched one-to-one to the objects of their class (an\n"
    "instance inside the object's box grown by --match-radius, default 0.5 m); recall,\n"
    "precision, mean and median error over matched objects, and the mean with misses counted.\n"
    "Defaults: the bundled house (data/worlds/house.world); on a GPU 150 views at 640x480 and\n"
    "7000 steps, on the CPU 48 views at 320x240 and 2000 steps; training is depth-supervised\n"
    "(--depth-lambda, default 0.5; 0 = RGB only) where the capture has depth/. Capture plan (--plan): mixed\n"
    "(spins and arcs of views at objects; default), walk (the spins only, = --walk-only) or drive\n"
    "(one robot drive through the rooms; see synth --help). --capture DIR skips synth and\n"
    "uses an existing capture (features then need --clip unless it has labels/). --reuse skips\n"
    "the stages whose outputs already exist in DIR (to re-run only the queries, say). --model DIR\n"
    "makes only the video, on an existing model folder. Video defaults: 1280x720 at 10 fps, 60\n"
    "rendered frames per drive, the splat view 480x360, the robot at 3x real time.\n";

#define INT_OPT(flag, field)                                                                       \
    else if ((v = cli_flag_value(argc, argv, &i, flag, &bad))) {                                   \
        if (cli_parse_int("demo", flag, v, &num)) return 2;                                        \
        if (num < 1) return cli_usage_error("demo", "%s must be >= 1 (got %ld)", flag, num);       \
        o->field = (int)num;                                                                       \
    }

static int parse(int argc, char **argv, sp_demo_opts *o, cli_common *c)
{
    int bad = 0, r;
    long num;
    double x;
    const char *v;
    for (int i = 1; i < argc && !bad; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return fputs(usage_text, stdout), -1;
        if ((r = cli_common_flag("demo", argc, argv, &i, CLI_ALL, c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) o->out_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--world", &bad))) o->world = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--model-path", &bad))) o->model_path = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--capture", &bad))) o->capture = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--clip", &bad))) o->clip = v;
        INT_OPT("--views", views)
        INT_OPT("--steps", steps)
        INT_OPT("--dim", dim)
        INT_OPT("--downscale", downscale)
        INT_OPT("--points", points)
        INT_OPT("--fps", fps)
        INT_OPT("--drive-frames", drive_frames)
        else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) o->model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--video-size", &bad))) {
            if (cli_parse_size("demo", "--video-size", v, &o->video_width, &o->video_height)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--view-size", &bad))) {
            if (cli_parse_size("demo", "--view-size", v, &o->view_width, &o->view_height)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--time-scale", &bad))) {
            if (cli_parse_float("demo", "--time-scale", v, &x)) return 2;
            if (!(x > 0 && x <= 20)) return cli_usage_error("demo", "--time-scale %g: expected 0 < S <= 20", x);
            o->time_scale = x;
        } else if ((v = cli_flag_value(argc, argv, &i, "--depth-lambda", &bad))) {
            if (cli_parse_float("demo", "--depth-lambda", v, &x)) return 2;
            if (!(x >= 0 && x <= 1e6)) return cli_usage_error("demo", "--depth-lambda %g: expected 0..1e6", x);
            o->depth_lambda = (float)x;
        } else if (!strcmp(argv[i], "--no-video")) o->no_video = 1;
        else if (!strcmp(argv[i], "--walk-only")) o->walk_only = 1;
        else if ((v = cli_flag_value(argc, argv, &i, "--plan", &bad))) {
            o->plan = !strcmp(v, "mixed") ? SP_DEMO_PLAN_MIXED : !strcmp(v, "walk") ? SP_DEMO_PLAN_WALK
                    : !strcmp(v, "drive") ? SP_DEMO_PLAN_DRIVE : -1;
            if (o->plan < 0) return cli_usage_error("demo", "--plan must be mixed, walk or drive (got '%s')", v);
        }
        else if (!strcmp(argv[i], "--offline-robot")) o->robot = SP_DEMO_ROBOT_OFFLINE;
        else if ((v = cli_flag_value(argc, argv, &i, "--size", &bad))) {
            if (cli_parse_size("demo", "--size", v, &o->width, &o->height)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--match-radius", &bad))) {
            if (cli_parse_float("demo", "--match-radius", v, &x)) return 2;
            if (!(x > 0 && x < 100)) return cli_usage_error("demo", "--match-radius %g: expected metres > 0", x);
            o->match_radius_m = (float)x;
        } else if (!strcmp(argv[i], "--skip-missing")) o->skip_missing = 1;
        else if (!strcmp(argv[i], "--reuse")) o->reuse = 1;
        else if (!bad) return cli_usage_error("demo", "unknown flag '%s'", argv[i]);
    }
    return bad ? 2 : 0;
}

int cmd_demo(int argc, char **argv)
{
    sp_demo_opts o = sp_demo_opts_default();
    cli_common c = cli_common_default();
    int prc = parse(argc, argv, &o, &c);
    if (prc) return prc < 0 ? 0 : prc;
    sp_log log = cli_log(&c, SP_LOG_INFO);
    o.device = c.device;
    o.threads = (int)c.threads;
    o.log = &log;
    sp_error err = {0};
    sp_demo_result r;
    if (sp_demo_run(&o, &r, &err)) return cli_fail("demo", &err);
    if (r.have_video)
        printf("video %s: %.1f s, %d of %d commands arrived, robot: %s (%.1f s)\n", r.video.path, r.video.seconds,
               r.video.n_arrived, r.video.n_commands, r.video.robot, r.t_video);
    if (r.video_error[0]) printf("no video: %s\n", r.video_error);
    if (o.model) {
        sp_demo_result_free(&r);
        return 0;
    }
    if (!r.scored) {
        printf("%s has no ground_truth.json, so there is nothing to score; the model is ready:\n"
               "  semsplat query --model %s \"refrigerator\" --heatmap fridge.png\n", r.capture_dir, r.model_dir);
        sp_demo_result_free(&r);
        return 0;
    }
    char *text = sp_eval_report_text(&r.report);
    if (text) fputs(text, stdout);
    free(text);
    printf("times: synth %.1f s, train %.1f s, features %.1f s, lift %.1f s, queries %.1f s, total %.1f s\n",
           r.t_synth, r.t_train, r.t_features, r.t_lift, r.t_queries, r.t_total);
    printf("wrote %s/demo.json, %s/report.md and heatmaps in %s\n", o.out_dir, o.out_dir, r.heatmap_dir);
    sp_demo_result_free(&r);
    return 0;
}
