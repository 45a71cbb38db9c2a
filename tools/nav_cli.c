/* Helpers of the nav commands (tools/cmd_plan.c, cmd_explore.c, cmd_describe.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "nav_cli.h"

int nav_cli_floats(const char *cmd, const char *flag, const char *s, float *out, int n_min, int n_max, int *n_out)
{
    int n = 0;
    const char *p = s;
    while (n < n_max) {
        char *end;
        double v = strtod(p, &end);
        if (end == p) break;
        if (!isfinite((float)v)) /* nan, inf, 1e999 and beyond float range */
            return cli_usage_error(cmd, "%s: '%s' has a number that is not finite", flag, s);
        out[n++] = (float)v;
        p = end;
        if (*p != ',') break;
        p++;
    }
    if (*p || n < n_min)
        return cli_usage_error(cmd, "%s: '%s' is not %d to %d numbers separated by commas", flag, s, n_min, n_max);
    if (n_out) *n_out = n;
    return 0;
}

int nav_cli_open(const char *cmd, const char *model, const char *device, long threads, int quiet,
                 const sp_nav_opts *opts, sp_device **dev, sp_nav **nav)
{
    sp_device_kind kind = !strcmp(device, "cpu") ? SP_DEVICE_CPU : !strcmp(device, "cuda") ? SP_DEVICE_CUDA
                          : !strcmp(device, "auto") ? SP_DEVICE_AUTO : (sp_device_kind)-1;
    if ((int)kind < 0) return cli_usage_error(cmd, "--device: '%s' is not cpu, cuda or auto", device);
    sp_error err = {0};
    sp_log log = sp_log_stderr(SP_LOG_WARN, quiet);
    *dev = NULL, *nav = NULL;
    if (sp_device_create(dev, kind, (int)threads, &err)) return cli_fail(cmd, &err);
    if (sp_nav_open(nav, model, opts, *dev, &log, &err)) {
        sp_device_free(*dev);
        *dev = NULL;
        return cli_fail(cmd, &err);
    }
    return 0;
}
