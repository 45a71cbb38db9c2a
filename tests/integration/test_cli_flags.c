/* Every command's shared flags go through one parser (tools/cli.c): an unknown --device, a
 * non-number --threads and a missing value are usage errors (exit 2) naming the flag and the value
 * for every command that takes them, before any work; commands without a device refuse --device. */
#include "test.h"

#include "cli_run.h"
#include "semsplat/core.h"

/* Each command with the arguments it needs to get past its own checks (paths need not exist:
 * flags are checked first). */
static const char *const with_device[] = {
    "render --splat s.ply --colmap c --all --out o", "train --colmap c --out o",
    "features --colmap c --out o", "embed-text hello", "lift --model m --features f",
    "distill --model m --features f --colmap c", "query --model m table", "demo --out o",
    "lexical --classes chair chair",
};

static void test_device_and_threads(void)
{
    char out[8192], args[1024];
    for (size_t k = 0; k < sizeof with_device / sizeof *with_device; k++) {
        const char *c = with_device[k];
        snprintf(args, sizeof args, "%s --device gpu0", c);
        int rc = run_cli(args, out, sizeof out);
        CHECK_MSG(rc == 2 && strstr(out, "--device") && strstr(out, "'gpu0' is not one of cpu, cuda, auto"),
                  "'%s': exit %d: %s", args, rc, out);
        snprintf(args, sizeof args, "%s --threads many", c);
        rc = run_cli(args, out, sizeof out);
        CHECK_MSG(rc == 2 && strstr(out, "--threads") && strstr(out, "'many'"), "'%s': exit %d: %s", args, rc, out);
        snprintf(args, sizeof args, "%s --device", c);
        rc = run_cli(args, out, sizeof out);
        CHECK_MSG(rc == 2 && strstr(out, "--device needs a value"), "'%s': exit %d: %s", args, rc, out);
    }
}

static void test_commands_without_a_device(void)
{
    char out[8192];
    int rc = run_cli("query --model m table --threads -2", out, sizeof out); /* range, once */
    CHECK_MSG(rc == 2 && strstr(out, "--threads: -2 not in 0..4096"), "query: exit %d: %s", rc, out);
    rc = run_cli("synth --world w --out o --device cpu", out, sizeof out);
    CHECK_MSG(rc == 2 && (strstr(out, "'--device'") || strstr(out, "not built")), "synth: exit %d: %s", rc, out);
    rc = run_cli("synth --world w --out o --threads x", out, sizeof out);
    CHECK_MSG(rc == 2 && (strstr(out, "--threads") || strstr(out, "not built")), "synth: exit %d: %s", rc, out);
    rc = run_cli("info --device cpu x", out, sizeof out);
    CHECK_MSG(rc == 2 && strstr(out, "--device"), "info: exit %d: %s", rc, out);
    rc = run_cli("align --model m --floor --device cpu", out, sizeof out);
    CHECK_MSG(rc == 2 && strstr(out, "--device"), "align: exit %d: %s", rc, out);
}

static void test_help_everywhere(void)
{
    const char *cmds[] = {"info", "render", "synth", "train", "features", "embed-text", "lift", "distill",
                          "query", "align", "demo"};
    char out[8192], args[256];
    for (size_t k = 0; k < sizeof cmds / sizeof *cmds; k++) {
        snprintf(args, sizeof args, "%s --help", cmds[k]);
        int rc = run_cli(args, out, sizeof out);
        CHECK_MSG((rc == 0 && strstr(out, "usage")) || strstr(out, "not built"), "'%s': exit %d: %s", args, rc, out);
    }
}

int main(void)
{
    require_cli();
    RUN(test_device_and_threads);
    RUN(test_commands_without_a_device);
    RUN(test_help_everywhere);
    return TEST_EXIT();
}
