/* semsplat sfm: camera poses from COLMAP (CPU) for a capture's images, aligned robustly into the
 * capture's own frame, written as a new capture (see include/semsplat/sfm.h). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "semsplat/sfm.h"

static void help(void)
{
    printf("usage: semsplat sfm --capture DIR --out DIR [--colmap PROGRAM] [--work DIR]\n"
           "                    [--threads N] [--nice N] [--timeout S] [--estimate-intrinsics]\n"
           "                    [--max-features N] [--overlap N] [--peak-threshold T]\n"
           "                    [--init-tri-angle DEG] [--min-inliers N] [--quiet]\n\n"
           "Runs COLMAP 3.8 on DIR/images (feature_extractor, sequential_matcher, mapper; CPU),\n"
           "takes the largest model, aligns it to DIR/sparse/0's camera centres (least median of\n"
           "squares, refit on the inliers) and writes a capture with COLMAP's poses and points in\n"
           "that frame, the registered images, labels and ground truth, and capture.json with the\n"
           "registered count, the models and the camera errors after alignment.\n"
           "  --threads 0 (all)  --nice 0  --timeout 3600 (s, per COLMAP stage)\n"
           "  --estimate-intrinsics  let COLMAP refine the focal length (default: the capture's\n"
           "                 PINHOLE intrinsics, fixed, as for a calibrated camera)\n"
           "  --max-features 4096 (SIFT per image)  --overlap 10 (sequential neighbours)\n"
           "  --peak-threshold T  SIFT contrast threshold (COLMAP's 0.0067; lower finds more\n"
           "                 features in low-texture images such as synth's)\n"
           "  --init-tri-angle 4 (degrees; COLMAP's 16 suits photo collections, not drives)\n"
           "  --min-inliers 15 (2D-3D inliers to register an image; COLMAP's 30)\n"
           "  --work DIR     COLMAP's database, models and log (default OUT/colmap)\n");
}

int cmd_sfm(int argc, char **argv)
{
    sp_sfm_opts o = {0};
    const char *v;
    long nice = 0, feats = 0, overlap = 0;
    double timeout = 0, peak = 0, tri = 0;
    long inliers = 0;
    int bad = 0, rf;
    cli_common c = cli_common_default();
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((rf = cli_common_flag("sfm", argc, argv, &i, CLI_THREADS | CLI_QUIET, &c))) {
            if (rf == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--capture", &bad))) o.capture = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) o.out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--colmap", &bad))) o.colmap = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--work", &bad))) o.work_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--nice", &bad))) {
            if (cli_parse_int("sfm", "--nice", v, &nice)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--timeout", &bad))) {
            if (cli_parse_float("sfm", "--timeout", v, &timeout)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--max-features", &bad))) {
            if (cli_parse_int("sfm", "--max-features", v, &feats)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--overlap", &bad))) {
            if (cli_parse_int("sfm", "--overlap", v, &overlap)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--init-tri-angle", &bad))) {
            if (cli_parse_float("sfm", "--init-tri-angle", v, &tri)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--min-inliers", &bad))) {
            if (cli_parse_int("sfm", "--min-inliers", v, &inliers)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--peak-threshold", &bad))) {
            if (cli_parse_float("sfm", "--peak-threshold", v, &peak)) return 2;
        } else if (!strcmp(argv[i], "--estimate-intrinsics")) o.estimate_intrinsics = 1;
        else if (!bad) return cli_usage_error("sfm", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!o.capture || !o.out) return cli_usage_error("sfm", "--capture and --out are required");
    if (nice < 0 || nice > 19) return cli_usage_error("sfm", "--nice %ld: expected 0..19", nice);
    if (timeout < 0) return cli_usage_error("sfm", "--timeout %g: expected seconds >= 0", timeout);
    if (feats < 0 || overlap < 0) return cli_usage_error("sfm", "--max-features/--overlap: expected >= 0");
    o.threads = (int)c.threads;
    o.nice = (int)nice;
    o.timeout_s = timeout;
    o.max_features = (int)feats;
    o.overlap = (int)overlap;
    o.peak_threshold = peak;
    o.init_min_tri_angle_deg = tri;
    o.abs_pose_min_inliers = (int)inliers;
    sp_log log = cli_log(&c, SP_LOG_INFO);
    o.log = &log;
    sp_error err = {0};
    sp_sfm_result r;
    if (sp_sfm_colmap(&o, &r, &err)) {
        sp_sfm_result_free(&r);
        return cli_fail("sfm", &err);
    }
    char sizes[256] = "";
    for (int k = 0, at = 0; k < r.n_models && at < 200; k++)
        at += snprintf(sizes + at, sizeof sizes - at, "%s%d", k ? "+" : "", r.model_images[k]);
    if (!c.quiet)
        printf("sfm  registered %d of %d images (%d model%s: %s images), %d inliers; camera error after "
               "alignment RMS %.3f m, median %.3f m, max %.3f m (%s), rotation %.2f deg mean  -> %s\n",
               r.n_registered, r.n_images, r.n_models, r.n_models == 1 ? "" : "s", sizes, r.n_inliers,
               r.ate_rms_m, r.ate_median_m, r.ate_max_m, r.worst_image, r.rot_err_mean_deg, o.out);
    sp_sfm_result_free(&r);
    return 0;
}
