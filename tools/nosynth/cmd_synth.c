/* semsplat synth in a build without synth's dependencies (assimp, libxml2). */
#include <stdio.h>

#include "../cli.h"

int cmd_synth(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "semsplat synth: not built into this binary (install libassimp-dev and libxml2-dev "
                    "and rebuild)\n");
    return 2;
}
