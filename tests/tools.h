/* Tests that check files with command-line tools (ffprobe, ffmpeg): whether one is installed, and
 * its output. */
#ifndef SEMSPLAT_TEST_TOOLS_H
#define SEMSPLAT_TEST_TOOLS_H

#include <stdio.h>
#include <stdlib.h>

static inline int have_tool(const char *name)
{
    char cmd[256];
    snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", name);
    return system(cmd) == 0;
}

/* Runs cmd and returns its exit status; out gets its stdout (first cap - 1 bytes). */
static inline int capture(const char *cmd, char *out, size_t cap)
{
    FILE *p = popen(cmd, "r");
    if (!p) return -1;
    size_t n = fread(out, 1, cap - 1, p);
    out[n] = 0;
    return pclose(p);
}

#endif
