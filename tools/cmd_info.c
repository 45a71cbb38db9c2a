/* semsplat info PATH: says what is in a COLMAP model (folder or capture root), a splat PLY, a PNG
 * or JPEG image, a .npy array or a safetensors file (sp_io_describe: the kind from the content). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "semsplat/io.h"

static void help(void)
{
    printf("usage: semsplat info [--all] PATH\n\n"
           "  PATH   a COLMAP model folder or capture root (sparse/0 or sparse inside), a splat\n"
           "         .ply, a PNG/JPEG image, a .npy array or a .safetensors file\n"
           "  --all  list every camera / tensor (default: the first 20)\n");
}

int cmd_info(int argc, char **argv)
{
    const char *path = NULL;
    int all = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            help();
            return 0;
        } else if (!strcmp(argv[i], "--all")) {
            all = 1;
        } else if (!strcmp(argv[i], "--quiet")) {
            /* nothing to silence: info prints only its answer */
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return cli_usage_error("info", "unknown flag '%s'", argv[i]);
        } else if (path) {
            return cli_usage_error("info", "one PATH at a time (got '%s' and '%s')", path, argv[i]);
        } else {
            path = argv[i];
        }
    }
    if (!path) return cli_usage_error("info", "PATH is required");
    sp_error err = {0};
    char *text = NULL;
    if (sp_io_describe(path, all, &text, &err)) return cli_fail("info", &err);
    fputs(text, stdout);
    free(text);
    return 0;
}
