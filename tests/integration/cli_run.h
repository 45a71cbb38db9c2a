/* Runs the built CLI for the integration tests: `semsplat ARGS` with stdout and stderr together. */
#ifndef SP_TEST_CLI_RUN_H
#define SP_TEST_CLI_RUN_H

#include <stdio.h>
#include <sys/wait.h>

#include "test.h"

/* Returns the exit status (-1 when it could not run or was killed); out gets the output. */
static inline int run_cli(const char *args, char *out, size_t cap)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s/semsplat' %s 2>&1", SP_BUILD_DIR, args);
    FILE *p = popen(cmd, "r");
    if (!p) return -1;
    size_t n = fread(out, 1, cap - 1, p);
    out[n] = 0;
    int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* Skips the test (exit 77) when the CLI is not built. */
static inline void require_cli(void)
{
    char probe[1200];
    snprintf(probe, sizeof probe, "%s/semsplat", SP_BUILD_DIR);
    FILE *f = fopen(probe, "rb");
    if (!f) TEST_SKIP("the semsplat CLI is not built");
    fclose(f);
}

#endif
