/* The integration tests' CLI helpers: run `semsplat ARGS` (test.h's test_run_cli), skip without
 * the CLI. */
#ifndef SP_TEST_CLI_RUN_H
#define SP_TEST_CLI_RUN_H

#include <stdio.h>

#include "test.h"

/* Returns the exit status (-1 when it could not run or was killed); out gets the output. */
static inline int run_cli(const char *args, char *out, size_t cap) { return test_run_cli(args, out, cap); }

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
