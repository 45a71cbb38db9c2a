/* What the nav commands (plan, explore, describe) share: numbers lists and opening a scene. */
#ifndef SEMSPLAT_NAV_CLI_H
#define SEMSPLAT_NAV_CLI_H

#include "semsplat/nav.h"

/* "a,b[,c]" -> n_min..n_max floats; prints a usage error naming cmd and flag and returns 2. */
int nav_cli_floats(const char *cmd, const char *flag, const char *s, float *out, int n_min, int n_max, int *n);
/* Creates the device (cpu / cuda / auto) and opens the model folder; prints the error and returns
 * the exit code (1, or 2 for a bad --device) when that fails, 0 when both are open. */
int nav_cli_open(const char *cmd, const char *model, const char *device, long threads, int quiet,
                 const sp_nav_opts *opts, sp_device **dev, sp_nav **nav);

#endif
