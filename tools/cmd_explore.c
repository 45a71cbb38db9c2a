/* semsplat explore: views covering a region in words ("kitchen"), preferring what the splat
 * reconstructs poorly, ordered into a short tour, written to a folder with previews and a map. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "nav_cli.h"

static void help(void)
{
    printf("usage: semsplat explore --model DIR --region \"kitchen\" [--from X,Y,YAW] [--views N] --out DIR\n\n"
           "  --region TEXT     a region (\"kitchen\", \"the area around the bed\") or an object\n"
           "  --from X,Y,YAW    start (default: the capture's first pose, on the floor)\n"
           "  --views N         at most N views (default 12)\n"
           "  --device cpu|cuda|auto, --threads N, --quiet\n\n"
           "Writes DIR/tour.json (views in visiting order with their reconstruction quality and\n"
           "the coverage they add, the tour's waypoints), map.png and previews/.\n");
}

int cmd_explore(int argc, char **argv)
{
    const char *model = NULL, *region = NULL, *out = NULL, *device = "auto", *v;
    float from[3];
    int has_from = 0, quiet = 0, bad = 0;
    long threads = 0, views = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--region", &bad))) region = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) out = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--from", &bad))) {
            if (nav_cli_floats("explore", "--from", v, from, 3, 3, NULL)) return 2;
            has_from = 1;
        } else if ((v = cli_flag_value(argc, argv, &i, "--views", &bad))) {
            if (cli_parse_int("explore", "--views", v, &views)) return 2;
            if (views < 1 || views > 64) return cli_usage_error("explore", "--views: %ld not in 1..64", views);
        } else if ((v = cli_flag_value(argc, argv, &i, "--threads", &bad))) {
            if (cli_parse_int("explore", "--threads", v, &threads)) return 2;
        } else if (!strcmp(argv[i], "--quiet")) quiet = 1;
        else if (!bad) return cli_usage_error("explore", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!model || !region || !out) return cli_usage_error("explore", "--model DIR, --region TEXT and --out DIR are required");
    sp_nav_opts opts = sp_nav_opts_default();
    if (views) opts.max_tour_poses = (int)views;
    sp_error err = {0};
    sp_device *dev;
    sp_nav *nav;
    int rc = nav_cli_open("explore", model, device, threads, quiet, &opts, &dev, &nav);
    if (rc) return rc;
    sp_nav_tour tour;
    if (sp_nav_explore(nav, region, has_from ? from : NULL, &tour, &err) || sp_nav_tour_write(nav, &tour, out, &err)) {
        rc = cli_fail("explore", &err);
    } else {
        printf("exploring '%s' (%s): %d views, %.0f %% of the area seen, tour %.1f m\n", tour.target.text,
               tour.target.source, tour.n, 100 * tour.coverage, tour.path.length_m);
        if (tour.note[0]) printf("  note: %s\n", tour.note);
        for (int k = 0; k < tour.n; k++)
            printf("  %2d. (%.2f, %.2f) yaw %4.0f deg  reconstruction quality %.2f  adds %.0f %% of the area\n", k + 1,
                   tour.poses[4 * k], tour.poses[4 * k + 1], tour.poses[4 * k + 3] * 57.29578f, tour.quality[k],
                   100 * tour.gain[k]);
        printf("  wrote %s/tour.json, map.png, previews/\n", out);
    }
    sp_nav_tour_free(&tour);
    sp_nav_free(nav);
    sp_device_free(dev);
    return rc;
}
