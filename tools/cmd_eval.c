/* semsplat eval: a model folder scored against a world file (sp_eval_run_report): localization of
 * every object, open vs closed vocabulary, figures and a written analysis, as report.md,
 * report.html and report.json. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "semsplat/eval.h"

static const char *usage_text =
    "usage: semsplat eval --model DIR --world W.world --out DIR [--model-path DIR]\n"
    "                     [--queries Q.json] [--title TEXT] [--match-radius M] [--skip-missing]\n"
    "                     [--trajectories-to PHRASE] [--no-navigation] [--offline-robot]\n"
    "                     [--device cpu|cuda|auto] [--threads N] [--quiet]\n\n"
    "Scores the model against the world file's objects (ground truth from the world itself):\n"
    "  5.1 every object localized by both methods, matched one-to-one (fragments merged);\n"
    "  5.2 open vs closed vocabulary (the task's ten queries, or {\"vocabulary\": [...]} in\n"
    "      Q.json: text, coco, targets, region, near, near_m): the semantic splat against the\n"
    "      same map restricted to COCO's 80 class names;\n"
    "  5.3 ten navigation commands (the house's, or Q.json's \"navigation\": [{text, targets}])\n"
    "      through the agent and the simulated robot (over loopback DDS\n"
    "      when built with Cyclone DDS; --offline-robot for the agent's offline robot): intent\n"
    "      parsed, valid location, goal reached, views useful; skipped with --no-navigation;\n"
    "  5.4 nav's top 3 trajectories to the refrigerator (--trajectories-to), their length,\n"
    "      clearance, localizability and a visual quality 1-5 measured on their previews;\n"
    "  figures (per-object errors, per-query errors, the map) and an analysis from the numbers.\n"
    "Writes DIR/report.md, DIR/report.html (figures inline), DIR/report.json, figures/, heatmaps/.\n";

int cmd_eval(int argc, char **argv)
{
    sp_eval_run_opts o = {0};
    cli_common c = cli_common_default();
    int bad = 0, r;
    double x;
    const char *v;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return fputs(usage_text, stdout), 0;
        if ((r = cli_common_flag("eval", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) o.model_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--world", &bad))) o.world = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) o.out_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--model-path", &bad))) o.model_path = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--queries", &bad))) o.queries = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--title", &bad))) o.title = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--trajectories-to", &bad))) o.trajectory_target = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--match-radius", &bad))) {
            if (cli_parse_float("eval", "--match-radius", v, &x)) return 2;
            if (!(x > 0 && x < 100)) return cli_usage_error("eval", "--match-radius %g: expected metres > 0", x);
            o.match_radius_m = (float)x;
        } else if (!strcmp(argv[i], "--skip-missing")) o.skip_missing = 1;
        else if (!strcmp(argv[i], "--no-navigation")) o.no_navigation = 1;
        else if (!strcmp(argv[i], "--offline-robot")) o.robot = SP_DEMO_ROBOT_OFFLINE;
        else if (!bad) return cli_usage_error("eval", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!o.model_dir || !o.world || !o.out_dir)
        return cli_usage_error("eval", "--model, --world and --out are required");
    sp_log log = cli_log(&c, SP_LOG_INFO);
    o.log = &log;
    sp_device *dev = NULL;
    if (cli_device_open("eval", &c, &dev)) return 1;
    o.dev = dev;
    sp_error err = {0};
    sp_eval_run run;
    int rc = sp_eval_run_report(&o, &run, &err);
    sp_device_free(dev);
    if (rc) return cli_fail("eval", &err);
    if (!c.quiet) {
        for (int m = 0; m < SP_EVAL_METHODS; m++) {
            const sp_eval_summary *s = &run.loc.summary[m];
            printf("eval  %s  recall %d/%d  precision %d/%d  mean error %.3f m (matched), %.3f m (misses "
                   "counted)\n", m ? "multi-view" : "3D        ", s->matched, s->objects, s->true_instances,
                   s->instances, s->mean_error_m, s->mean_error_with_misses_m);
        }
        int of = 0, cf = 0, n = 0;
        for (size_t k = 0; k < run.n_vocab; k++)
            if (run.vocab[k].n_targets) n++, of += run.vocab[k].open_found, cf += run.vocab[k].closed_found;
        if (run.nav_measured)
            printf("eval  navigation  parsed %d/%d  valid %d/%d  reached %d/%d  views useful %d/%d  (%s)\n",
                   run.nav.count[0], run.nav.n, run.nav.count[1], run.nav.n, run.nav.count[2], run.nav.n,
                   run.nav.count[3], run.nav.n, run.nav.robot);
        else printf("eval  navigation  not measured: %s\n", run.nav_note);
        printf("eval  vocabulary  splat %d/%d  COCO baseline %d/%d  (%s)  -> %s/report.md\n", of, n, cf, n,
               run.vocab_encoder, o.out_dir);
    }
    sp_eval_run_free(&run);
    return 0;
}
