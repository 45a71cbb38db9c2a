/* semsplat demo on bad input: bad flags, a missing capture, a capture without ground truth (a
 * real one: the demo stops after lift with a hint) and a malformed ground_truth.json. Stages are
 * skipped with --reuse over stub outputs, so no training runs here. */
#include "test.h"


#include "semsplat/core.h"

/* Runs the CLI with args, returns its exit status and its combined output in out. */
static int run_cli(const char *args, char *out, size_t cap) { return test_run_cli(args, out, cap); }

static void touch(const char *dir, const char *file, const char *text)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    sp_error err = {0};
    CHECK_OK(sp_mkdirs(dir, &err), &err);
    CHECK_OK(sp_write_file_atomic(path, text, strlen(text), &err), &err);
}

static void test_bad_flags(void)
{
    char out[8192];
    CHECK(run_cli("demo --views abc", out, sizeof out) == 2);
    CHECK_MSG(strstr(out, "--views") != NULL, "output: %s", out);
    CHECK(run_cli("demo --frobnicate", out, sizeof out) == 2);
    CHECK_MSG(strstr(out, "--frobnicate") != NULL, "output: %s", out);
    CHECK(run_cli("train --colmap x --out y --sh-interval abc", out, sizeof out) == 2);
    CHECK_MSG(strstr(out, "--sh-interval") != NULL, "output: %s", out);
    CHECK(run_cli("train --colmap x --out y --sh-interval -5", out, sizeof out) == 2);
    CHECK_MSG(strstr(out, "--sh-interval must be positive") != NULL, "output: %s", out);
    /* (a build without synth says so instead) */
    CHECK(run_cli("synth --world x --out y --blur-px -1", out, sizeof out) == 2);
    CHECK_MSG(strstr(out, "--blur-px -1: expected 0..4") || strstr(out, "not built"), "output: %s", out);
}

static void test_missing_capture(void)
{
    char out[8192], args[2048];
    const char *dir = test_tmpdir("demo_missing");
    snprintf(args, sizeof args, "demo --capture %s/nothere --out %s/out --device cpu --quiet", dir, dir);
    CHECK(run_cli(args, out, sizeof out) != 0);
    CHECK_MSG(strstr(out, "nothere") != NULL, "output: %s", out);
}

/* Stub outputs of every stage, so --reuse goes straight to scoring. */
static void stub_stages(const char *dir, char *cap, size_t n)
{
    char d[1500];
    snprintf(cap, n, "%s/capture", dir);
    snprintf(d, sizeof d, "%s/out/model", dir);
    touch(d, "train.json", "{}");
    touch(d, "semantic.json", "{}");
    snprintf(d, sizeof d, "%s/out/features", dir);
    touch(d, "features.json", "{}");
    touch(cap, "labels.json", "{}");
}

static void test_no_ground_truth(void)
{
    char out[8192], args[4096], cap[1500];
    const char *dir = test_tmpdir("demo_nogt");
    stub_stages(dir, cap, sizeof cap);
    snprintf(args, sizeof args, "demo --capture %s --out %s/out --reuse --device cpu --quiet", cap, dir);
    CHECK(run_cli(args, out, sizeof out) == 0);
    CHECK_MSG(strstr(out, "no ground_truth.json") != NULL, "output: %s", out);
}

static void test_malformed_ground_truth(void)
{
    char out[8192], args[4096], cap[1500];
    const char *dir = test_tmpdir("demo_badgt");
    stub_stages(dir, cap, sizeof cap);
    touch(cap, "ground_truth.json", "{\"objects\": [ {\"name\": \"x\", }");
    snprintf(args, sizeof args, "demo --capture %s --out %s/out --reuse --device cpu --quiet", cap, dir);
    CHECK(run_cli(args, out, sizeof out) == 1);
    CHECK_MSG(strstr(out, "ground_truth.json") != NULL, "output: %s", out);
}

int main(void)
{
    char probe[1200];
    snprintf(probe, sizeof probe, "%s/semsplat", SP_BUILD_DIR);
    if (!sp_file_exists(probe)) TEST_SKIP("the semsplat CLI is not built");
    RUN(test_bad_flags);
    RUN(test_missing_capture);
    RUN(test_no_ground_truth);
    RUN(test_malformed_ground_truth);
    return TEST_EXIT();
}
