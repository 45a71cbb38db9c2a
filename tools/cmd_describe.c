/* semsplat describe: "what objects are near the dining table?": the household objects found
 * within a radius of an anchor, with distances and relations, as a sentence (or JSON). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "nav_cli.h"

static void help(void)
{
    printf("usage: semsplat describe --model DIR --near \"dining table\" [flags]\n\n"
           "  --near TEXT       the anchor object\n"
           "  --radius M        objects within this of the anchor's footprint (default 1.5)\n"
           "  --from X,Y,YAW    the robot's pose, the viewpoint of left / right (default: the\n"
           "                    capture's first pose)\n"
           "  --vocabulary a,b  terms to look for (default: COCO's classes and household objects)\n"
           "  --json            print the JSON answer instead of the sentence\n"
           "  --device cpu|cuda|auto, --threads N, --quiet\n");
}

int cmd_describe(int argc, char **argv)
{
    const char *model = NULL, *near = NULL, *device = "auto", *vocab = NULL, *v;
    float from[3];
    double radius = 0;
    int has_from = 0, quiet = 0, bad = 0, json = 0;
    long threads = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--near", &bad))) near = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--device", &bad))) device = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--vocabulary", &bad))) vocab = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--radius", &bad))) {
            if (cli_parse_float("describe", "--radius", v, &radius)) return 2;
            if (!(radius > 0)) return cli_usage_error("describe", "--radius: %g is not positive", radius);
        } else if ((v = cli_flag_value(argc, argv, &i, "--from", &bad))) {
            if (nav_cli_floats("describe", "--from", v, from, 3, 3, NULL)) return 2;
            has_from = 1;
        } else if ((v = cli_flag_value(argc, argv, &i, "--threads", &bad))) {
            if (cli_parse_int("describe", "--threads", v, &threads)) return 2;
        } else if (!strcmp(argv[i], "--json")) json = 1;
        else if (!strcmp(argv[i], "--quiet")) quiet = 1;
        else if (!bad) return cli_usage_error("describe", "unknown argument '%s'", argv[i]);
        if (bad) return 2;
    }
    if (!model || !near) return cli_usage_error("describe", "--model DIR and --near TEXT are required");
    sp_nav_opts opts = sp_nav_opts_default();
    opts.vocabulary = vocab;
    sp_error err = {0};
    sp_device *dev;
    sp_nav *nav;
    int rc = nav_cli_open("describe", model, device, threads, quiet, &opts, &dev, &nav);
    if (rc) return rc;
    sp_nav_description d;
    if (sp_nav_describe(nav, near, (float)radius, has_from ? from : NULL, &d, &err)) {
        rc = cli_fail("describe", &err);
    } else if (json) {
        char *s = sp_nav_description_json(&d);
        printf("%s\n", s ? s : "null");
        free(s);
    } else {
        printf("%s\n", d.sentence);
    }
    sp_nav_description_free(&d);
    sp_nav_free(nav);
    sp_device_free(dev);
    return rc;
}
