/* semsplat synth: renders a Gazebo/SDF world into a COLMAP capture with ground truth (images,
 * depth, instance labels, labels.json, ground_truth.json). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "semsplat/synth.h"

static void help(void)
{
    printf("usage: semsplat synth --world W.world --out DIR [--model-path DIR[:DIR...]]\n"
           "                      [--views N] [--size WxH] [--fov-deg DEG] [--heights MIN,MAX]\n"
           "                      [--supersample S] [--blur-px SIGMA] [--points N] [--seed N]\n"
           "                      [--threads N] [--skip-missing] [--quiet]\n"
           "                      [--walk-only | --drive [--drive-speed M/S] [--drive-rate HZ]\n"
           "                       [--drive-turn RAD/S]]\n\n"
           "Renders the world (SDF 1.6+: models, includes via model://, boxes, cylinders,\n"
           "spheres, planes, .dae/.obj/.stl meshes with textures) along a robot-like path\n"
           "through every room plus views around objects, and writes DIR/sparse/0 (COLMAP,\n"
           "PINHOLE, exact poses), images/, depth/ (.npy metres), labels/ (16-bit PNG ids),\n"
           "labels.json and ground_truth.json.\n"
           "  --model-path   where model://NAME is looked up (also GAZEBO_MODEL_PATH,\n"
           "                 GZ_SIM_RESOURCE_PATH, and <world dir>/models, ../models)\n"
           "  --views 150  --size 640x480  --fov-deg 70 (horizontal)  --heights 0.3,1.5 (m)\n"
           "  --supersample 4 (per axis)  --points 30000  --seed 1\n"
           "  --blur-px 0.5  the camera's blur (Gaussian sigma, pixels) over the colours;\n"
           "                 0 = none (sharp box-filtered pixels)\n"
           "  --skip-missing warn about missing models and meshes and go on (a missing\n"
           "                 texture is always a warning: the mesh keeps its colour)\n"
           "  --walk-only    only the walk's spins: no view aimed at a ground-truth object\n"
           "                 (for captures used in evaluation)\n"
           "  --drive        one continuous robot drive through the reachable rooms, frames at\n"
           "                 --drive-rate (10 Hz) at --drive-speed (0.4 m/s), turning at\n"
           "                 --drive-turn (0.5 rad/s), a spin at each waypoint; every k-th frame\n"
           "                 is kept so at most --views remain (capture.json says which)\n");
}

int cmd_synth(int argc, char **argv)
{
    const char *world = NULL, *out = NULL, *mpath = NULL, *v;
    long views = 150, ss = 4, points = 30000, seed = 1;
    int w = 640, h = 480, skip = 0, bad = 0, r;
    cli_common c = cli_common_default();
    double fov = 70, hmin = 0.3, hmax = 1.5, psf = 0.5;
    double dspeed = 0, drate = 0, dturn = 0;
    int plan = SP_SYNTH_PLAN_MIXED;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((r = cli_common_flag("synth", argc, argv, &i, CLI_THREADS | CLI_QUIET, &c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--world", &bad))) world = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--model-path", &bad))) mpath = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--views", &bad))) {
            if (cli_parse_int("synth", "--views", v, &views)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--size", &bad))) {
            if (cli_parse_size("synth", "--size", v, &w, &h)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--fov-deg", &bad))) {
            if (cli_parse_float("synth", "--fov-deg", v, &fov)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--heights", &bad))) {
            char tail;
            if (sscanf(v, "%lf,%lf%c", &hmin, &hmax, &tail) != 2 || !(hmin > 0) || !(hmax >= hmin) || !(hmax <= 100))
                return cli_usage_error("synth", "--heights: '%s' is not MIN,MAX in metres", v);
        } else if ((v = cli_flag_value(argc, argv, &i, "--supersample", &bad))) {
            if (cli_parse_int("synth", "--supersample", v, &ss)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--blur-px", &bad))) {
            if (cli_parse_float("synth", "--blur-px", v, &psf)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--points", &bad))) {
            if (cli_parse_int("synth", "--points", v, &points)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--seed", &bad))) {
            if (cli_parse_int("synth", "--seed", v, &seed)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--drive-speed", &bad))) {
            if (cli_parse_float("synth", "--drive-speed", v, &dspeed)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--drive-rate", &bad))) {
            if (cli_parse_float("synth", "--drive-rate", v, &drate)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--drive-turn", &bad))) {
            if (cli_parse_float("synth", "--drive-turn", v, &dturn)) return 2;
        } else if (!strcmp(argv[i], "--walk-only") || !strcmp(argv[i], "--drive")) {
            int p = argv[i][2] == 'w' ? SP_SYNTH_PLAN_WALK : SP_SYNTH_PLAN_DRIVE;
            if (plan != SP_SYNTH_PLAN_MIXED && plan != p)
                return cli_usage_error("synth", "--walk-only and --drive exclude each other");
            plan = p;
        } else if (!strcmp(argv[i], "--skip-missing")) skip = 1;
        else if (!bad) return cli_usage_error("synth", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!world || !out) return cli_usage_error("synth", "--world and --out are required");
    if (views < 1 || views > 100000) return cli_usage_error("synth", "--views %ld: expected 1..100000", views);
    if (ss < 1 || ss > 4) return cli_usage_error("synth", "--supersample %ld: expected 1..4", ss);
    if (!(fov > 1 && fov < 170)) return cli_usage_error("synth", "--fov-deg %g: expected 1..170", fov);
    if (!(psf >= 0 && psf <= 4)) return cli_usage_error("synth", "--blur-px %g: expected 0..4", psf);
    if (points < 1) return cli_usage_error("synth", "--points %ld: expected at least 1", points);
    if ((dspeed || drate || dturn) && plan != SP_SYNTH_PLAN_DRIVE)
        return cli_usage_error("synth", "--drive-speed/--drive-rate/--drive-turn need --drive");
    sp_error err = {0};
    sp_log log = cli_log(&c, SP_LOG_INFO);
    sp_synth_load_opts lo = {.model_path = mpath, .skip_missing = skip, .log = &log};
    sp_world wd;
    double t0 = sp_time_now();
    if (sp_synth_load_world(world, &lo, &wd, &err)) {
        if (err.code == SP_E_NOTFOUND && !skip)
            fprintf(stderr, "semsplat synth: (use --skip-missing to render without missing assets)\n");
        return cli_fail("synth", &err);
    }
    size_t n_obj = 0;
    for (size_t i = 0; i < wd.n_objects; i++) n_obj += !wd.objects[i].is_structure;
    sp_logf(&log, SP_LOG_INFO, "%s: %zu models (%zu objects), %zu triangles, %zu textures, %zu lights%s%s, loaded in %.2f s",
            wd.path, wd.n_objects, n_obj, wd.n_triangles, wd.n_textures, wd.n_lights,
            wd.n_missing ? " (some assets missing, skipped)" : "",
            wd.n_missing_textures ? " (some textures missing: material colour)" : "", sp_time_now() - t0);
    sp_synth_capture_opts co = {.n_views = (int)views, .width = w, .height = h, .fov_deg = (float)fov,
                                .min_height_m = (float)hmin, .max_height_m = (float)hmax,
                                .supersample = (int)ss, .psf_px = psf > 0 ? (float)psf : -1.f, .n_points = (int)points, .seed = (unsigned)seed,
                                .n_threads = (int)c.threads, .log = &log, .plan = plan,
                                .drive_speed_mps = (float)dspeed, .drive_rate_hz = (float)drate,
                                .drive_turn_rad_s = (float)dturn};
    double t1 = sp_time_now();
    int rc = sp_synth_capture(&wd, out, &co, &err);
    sp_world_free(&wd);
    if (rc) return cli_fail("synth", &err);
    if (!c.quiet)
        printf("synth  %.2f  s  (%s plan, at most %ld views %dx%d, %s -> %s; see capture.json)\n",
               sp_time_now() - t1, plan == SP_SYNTH_PLAN_DRIVE ? "drive" : plan ? "walk" : "walk+objects",
               views, w, h, world, out);
    return 0;
}
