/* Runs tests/python/test_query.py (the Python module against `semsplat query --json`) and
 * tests/python/test_module.py (safety after close, ABI checks, error classes, threads, per-call
 * options) on a model folder built here from the tiny labelled scene: splat.ply with f_sem_*,
 * semantic.json (with the class names, so the default text encoder is lexical), the PCA files, a COLMAP model of the cameras and a frame.json that moves the
 * model into a "world" (rotation, translation, scale), with expect.json naming where the table
 * must come out. Skips when /usr/bin/python3 has no numpy. */
#include <cjson/cJSON.h>
#include <stdlib.h>

#include "scene.h"
#include "semsplat/io.h"
#include "test.h"

/* world = 1.5 Rz(90 deg) model + (10, -2, 0.5), as `semsplat align --model` would write it */
static const sp_frame *test_frame(void)
{
    static sp_frame f;
    sp_frame_init(&f, "align");
    double M[16] = {0, -1.5, 0, 10, 1.5, 0, 0, -2, 0, 0, 1.5, 0.5, 0, 0, 0, 1};
    memcpy(f.world_from_model, M, sizeof M);
    f.residual_m = 0.01;
    return &f;
}

static int write_frame(const char *dir, sp_error *err)
{
    char path[1400];
    snprintf(path, sizeof path, "%s/frame.json", dir);
    int rc = sp_frame_write(path, test_frame(), err);
    if (rc) return rc;
    float c[3], w[3];
    sc_center(2, c);
    sp_frame_apply_point(test_frame(), c, w);
    cJSON *o = cJSON_CreateObject();
    double wd[3] = {w[0], w[1], w[2]};
    cJSON_AddItemToObject(o, "table_world", cJSON_CreateDoubleArray(wd, 3));
    snprintf(path, sizeof path, "%s/expect.json", dir);
    rc = sp_json_write_file(path, o, err);
    cJSON_Delete(o);
    return rc;
}

static int build_model(const char *dir, sp_error *err)
{
    /* with the class names, as lift records them: the folder answers through the lexical encoder */
    int rc = sc_write_model(dir, NULL, 1, err);
    return rc ? rc : write_frame(dir, err);
}

static char g_dir[1024];

static void run_script(const char *script)
{
    char cmd[4096];
    const char *pre = TEST_PYTHON_ENV;
    snprintf(cmd, sizeof cmd,
             "%sSEMSPLAT_LIB='%s' LD_LIBRARY_PATH='%s' /usr/bin/python3 '%s/tests/python/%s' '%s' '%s/semsplat'",
             pre, SP_BUILD_DIR, SP_BUILD_DIR, SP_SOURCE_DIR, script, g_dir, SP_BUILD_DIR);
    int rc = system(cmd);
    CHECK_MSG(rc == 0, "%s exited with %d", cmd, rc);
}

static void test_python_matches_cli(void) { run_script("test_query.py"); }
static void test_python_module_safety(void) { run_script("test_module.py"); }

int main(void)
{
    if (system("/usr/bin/python3 -c 'import numpy' 2>/dev/null") != 0)
        TEST_SKIP("/usr/bin/python3 has no numpy (apt install python3-numpy)");
    snprintf(g_dir, sizeof g_dir, "%s", test_tmpdir("semantic_python"));
    sp_error err = {0};
    if (build_model(g_dir, &err)) {
        fprintf(stderr, "building the model folder: %s\n", err.msg);
        return 1;
    }
    RUN(test_python_matches_cli);
    RUN(test_python_module_safety);
    return TEST_EXIT();
}
