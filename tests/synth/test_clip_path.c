/* The CLIP query path end to end, as a user runs it: semsplat synth (a 6-view house capture at
 * 64x48) -> features --source clip with the tiny CLIP fixture (tests/fixtures/clip/tiny, random
 * weights of the real architecture) -> train (30 steps) -> lift -> query --json, then the Python
 * module on the same model folder (tests/python/test_clip_path.py): shapes, the recorded source
 * and weights, the text encoder "clip" recorded in semantic.json and named in `query --json` and
 * Python results (with its explanation, no class matches), the label encoders (lexical, exact)
 * refused on CLIP features, Python and CLI agreeing. Skips without numpy for /usr/bin/python3. */
#include <stdlib.h>

#include "test.h"

static int run(const char *fmt, const char *a, const char *b)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd, fmt, SP_BUILD_DIR, a, b);
    int rc = system(cmd);
    CHECK_MSG(rc == 0, "%s exited with %d", cmd, rc);
    return rc;
}

static void test_clip_path(void)
{
    char dir[1024], tiny[1024], cap[1100], feat[1100], model[1100];
    snprintf(dir, sizeof dir, "%s", test_tmpdir("clip_path"));
    snprintf(tiny, sizeof tiny, "%s/tests/fixtures/clip/tiny/model.safetensors", SP_SOURCE_DIR);
    snprintf(cap, sizeof cap, "%s/cap", dir);
    snprintf(feat, sizeof feat, "%s/feat", dir);
    snprintf(model, sizeof model, "%s/model", dir);
    char world[1024];
    snprintf(world, sizeof world, "%s/data/worlds/house.world", SP_SOURCE_DIR);
    if (run("'%s/semsplat' synth --world '%s' --out '%s' --views 6 --size 64x48 --quiet", world, cap)) return;
    char args[4096];
    snprintf(args, sizeof args, "--colmap '%s' --source clip --clip '%s' --dim 16", cap, tiny);
    if (run("'%s/semsplat' features %s --out '%s' --device cpu --quiet", args, feat)) return;
    if (run("'%s/semsplat' train --colmap '%s' --out '%s' --steps 30 --device cpu --quiet", cap, model)) return;
    if (run("'%s/semsplat' lift --model '%s' --features '%s' --device cpu --quiet", model, feat)) return;
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             TEST_PYTHON_ENV "SEMSPLAT_LIB='%s' LD_LIBRARY_PATH='%s' /usr/bin/python3 '%s/tests/python/test_clip_path.py' "
             "'%s' '%s' '%s/semsplat'", SP_BUILD_DIR, SP_BUILD_DIR, SP_SOURCE_DIR, model, feat, SP_BUILD_DIR);
    int rc = system(cmd);
    CHECK_MSG(rc == 0, "%s exited with %d", cmd, rc);
}

int main(void)
{
    if (system("/usr/bin/python3 -c 'import numpy' 2>/dev/null") != 0)
        TEST_SKIP("/usr/bin/python3 has no numpy (apt install python3-numpy)");
    RUN(test_clip_path);
    return TEST_EXIT();
}
