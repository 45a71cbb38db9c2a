/* semsplat plan: k distinct ranked trajectories from a start to an object, a point or a pose on
 * the model's costmap, with previews rendered from the splat, written to a folder. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "nav_cli.h"

static void help(void)
{
    printf("usage: semsplat plan --model DIR (--to \"phrase\" | --goal X,Y[,YAW]) [flags] --out DIR\n\n"
           "  --to TEXT          the goal in words: an object or a region (\"refrigerator\", \"kitchen\")\n"
           "  --goal X,Y[,YAW]   a point (or pose) in the model's world frame\n"
           "  --from X,Y,YAW     start (default: the capture's first pose, on the floor)\n"
           "  --k N              trajectories asked for (default 3; fewer when the map allows fewer)\n"
           "  --instance N       with --to: only instance N (default: any, the path picks)\n"
           "  --radius M         robot radius in metres (default 0.2)\n"
           "  --band LO,HI       the robot's body in metres above the floor (default 0.05,1.0)\n"
           "  --approach M       end within this of the object's footprint (default 0.5)\n"
           "  --no-previews      skip the rendered views\n"
           "  --device cpu|cuda|auto, --threads N, --quiet\n\n"
           "Writes DIR/plan.json (waypoints [x,y,z,yaw] and score terms of every trajectory),\n"
           "map.pgm + map.yaml (Nav2 map_server), map.png (top-down map) and previews/.\n");
}

static void print_plan(const sp_nav_plan *p)
{
    printf("%s: %d of %d trajectories from (%.2f, %.2f, yaw %.2f)", p->id, p->n, p->k, p->start[0], p->start[1], p->start[2]);
    if (p->target.text[0]) printf(" to '%s' (%s, %d instance%s, confidence %.2f)", p->target.text, p->target.source,
                                  p->target.n, p->target.n == 1 ? "" : "s", p->target.confidence);
    printf("\n");
    if (p->note[0]) printf("  note: %s\n", p->note);
    for (int i = 0; i < p->n_related; i++)
        printf("%s%s%s", i ? ", " : "  related concepts: ", p->related[i], p->related_found[i] ? "" : " (not found)");
    if (p->n_related) printf("\n");
    printf("  %-10s %8s %10s %10s %8s %8s %7s\n", "id", "length", "clear min", "clear mean", "locali.", "semantic", "score");
    for (int i = 0; i < p->n; i++) {
        const sp_nav_score *s = &p->traj[i].score;
        printf("  %-10s %6.2f m %8.2f m %8.2f m %8.2f %8.3f %7.3f\n", p->traj[i].id, s->length_m, s->clearance_min_m,
               s->clearance_mean_m, s->localizability, s->semantic, s->total);
        printf("  %-10s terms: length %.2f, clearance min %.2f, mean %.2f, localizability %.2f, semantic %.2f\n", "",
               s->t_length, s->t_clearance_min, s->t_clearance_mean, s->t_localizability, s->t_semantic);
    }
    printf("  planning %.1f ms, ranking %.0f ms, previews %.0f ms\n", p->ms_plan, p->ms_rank, p->ms_previews);
}

int cmd_plan(int argc, char **argv)
{
    const char *model = NULL, *to = NULL, *out = NULL, *device = "auto", *v;
    float from[3], goal[3];
    int has_from = 0, n_goal = 0, quiet = 0, bad = 0, previews = 1;
    long k = 0, threads = 0, instance = -1;
    sp_nav_opts opts = sp_nav_opts_default();
    for (int i = 1; i < argc; i++) {
        double d;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--to", &bad))) to = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--from", &bad))) {
            if (nav_cli_floats("plan", "--from", v, from, 3, 3, NULL)) return 2;
            has_from = 1;
        } else if ((v = cli_flag_value(argc, argv, &i, "--goal", &bad))) {
            if (nav_cli_floats("plan", "--goal", v, goal, 2, 3, &n_goal)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--k", &bad))) {
            if (cli_parse_int("plan", "--k", v, &k)) return 2;
            if (k < 1 || k > 64) return cli_usage_error("plan", "--k: %ld not in 1..64", k);
        } else if ((v = cli_flag_value(argc, argv, &i, "--instance", &bad))) {
            if (cli_parse_int("plan", "--instance", v, &instance)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--threads", &bad))) {
            if (cli_parse_int("plan", "--threads", v, &threads)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--radius", &bad))) {
            if (cli_parse_float("plan", "--radius", v, &d)) return 2;
            opts.costmap.robot_radius_m = (float)d;
            if (opts.costmap.inflation_radius_m < d) opts.costmap.inflation_radius_m = (float)d;
        } else if ((v = cli_flag_value(argc, argv, &i, "--band", &bad))) {
            float band[2];
            if (nav_cli_floats("plan", "--band", v, band, 2, 2, NULL)) return 2;
            opts.costmap.band_lo_m = band[0], opts.costmap.band_hi_m = band[1];
        } else if ((v = cli_flag_value(argc, argv, &i, "--approach", &bad))) {
            if (cli_parse_float("plan", "--approach", v, &d)) return 2;
            opts.approach_m = (float)d;
        } else if (!strcmp(argv[i], "--no-previews")) previews = 0;
        else if (!strcmp(argv[i], "--quiet")) quiet = 1;
        else if (!bad) return cli_usage_error("plan", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!model || !out) return cli_usage_error("plan", "--model DIR and --out DIR are required");
    if (!to == !n_goal) return cli_usage_error("plan", "give the goal as --to \"phrase\" or --goal X,Y[,YAW] (one of them)");
    sp_error err = {0};
    sp_device *dev;
    sp_nav *nav;
    int rc = nav_cli_open("plan", model, device, threads, quiet, &opts, &dev, &nav);
    if (rc) return rc;
    sp_nav_request req = sp_nav_request_default();
    req.start = has_from ? from : NULL;
    req.to = to;
    req.k = (int)k;
    req.instance = (int)instance;
    req.previews = previews;
    if (n_goal) req.goal = n_goal == 3 ? sp_nav_goal_pose(goal[0], goal[1], goal[2]) : sp_nav_goal_point(goal[0], goal[1]);
    sp_nav_plan plan;
    if (sp_nav_plan_request(nav, &req, &plan, &err) || sp_nav_plan_write(nav, &plan, out, &err)) rc = cli_fail("plan", &err);
    else {
        print_plan(&plan);
        printf("  wrote %s/plan.json, map.pgm, map.yaml, map.png, previews/\n", out);
    }
    sp_nav_plan_free(&plan);
    sp_nav_free(nav);
    sp_device_free(dev);
    return rc;
}
