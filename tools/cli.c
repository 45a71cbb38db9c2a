/* Flag parsing and error display shared by the CLI commands. */
#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cli_is_flag(const char *arg, const char *name)
{
    size_t n = strlen(name);
    return strncmp(arg, name, n) == 0 && (arg[n] == 0 || arg[n] == '=');
}

const char *cli_flag_value(int argc, char **argv, int *i, const char *name, int *bad)
{
    const char *arg = argv[*i];
    size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0) return NULL;
    if (arg[n] == '=') return arg + n + 1;
    if (arg[n] != 0) return NULL;
    if (*i + 1 >= argc) {
        fprintf(stderr, "semsplat: error: %s needs a value\n", name);
        *bad = 1;
        return NULL;
    }
    (*i)++;
    return argv[*i];
}

int cli_fail(const char *cmd, const sp_error *err)
{
    fprintf(stderr, "semsplat %s: error: %s\n", cmd, err && err->msg[0] ? err->msg : "failed");
    return 1;
}

int cli_usage_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "semsplat %s: error: ", cmd);
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\n(see 'semsplat %s --help')\n", cmd);
    va_end(ap);
    return 2;
}

int cli_parse_int(const char *cmd, const char *flag, const char *s, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (!*s || *end) return cli_usage_error(cmd, "%s: '%s' is not an integer", flag, s);
    /* every integer flag lands in an int: a larger value would wrap into another one */
    if (errno || v < INT_MIN || v > INT_MAX) return cli_usage_error(cmd, "%s: '%s' is out of range", flag, s);
    *out = v;
    return 0;
}

int cli_parse_float(const char *cmd, const char *flag, const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (!*s || *end || errno || !isfinite(v))
        return cli_usage_error(cmd, "%s: '%s' is not a finite number", flag, s);
    *out = v;
    return 0;
}

int cli_parse_size(const char *cmd, const char *flag, const char *s, int *w, int *h)
{
    int a, b;
    char tail;
    if (sscanf(s, "%dx%d%c", &a, &b, &tail) != 2 || a <= 0 || b <= 0 || a > 16384 || b > 16384)
        return cli_usage_error(cmd, "%s: '%s' is not a size like 640x480", flag, s);
    *w = a;
    *h = b;
    return 0;
}

cli_common cli_common_default(void)
{
    cli_common c = {SP_DEVICE_AUTO, "auto", 0, 0, 0};
    return c;
}

int cli_device_kind(const char *cmd, const char *value, sp_device_kind *kind)
{
    sp_error err = {0};
    if (sp_device_kind_parse(value, kind, &err)) return cli_usage_error(cmd, "--device: %s", err.msg);
    return 0;
}

int cli_common_flag(const char *cmd, int argc, char **argv, int *i, unsigned which, cli_common *c)
{
    int bad = 0;
    const char *v;
    if ((which & CLI_DEVICE) && (v = cli_flag_value(argc, argv, i, "--device", &bad))) {
        if (cli_device_kind(cmd, v, &c->device)) return 2;
        c->device_name = v;
        return 1;
    }
    if ((which & CLI_THREADS) && (v = cli_flag_value(argc, argv, i, "--threads", &bad))) {
        if (cli_parse_int(cmd, "--threads", v, &c->threads)) return 2;
        if (c->threads < 0 || c->threads > 4096)
            return cli_usage_error(cmd, "--threads: %ld not in 0..4096 (0 = all cores)", c->threads);
        return 1;
    }
    if (bad) return 2;
    if ((which & CLI_QUIET) && (!strcmp(argv[*i], "--quiet") || !strcmp(argv[*i], "-q"))) return c->quiet = 1, 1;
    if ((which & CLI_VERBOSE) && !strcmp(argv[*i], "--verbose")) return c->verbose = 1, 1;
    return 0;
}

int cli_device_open(const char *cmd, const cli_common *c, sp_device **dev)
{
    sp_error err = {0};
    if (sp_device_create(dev, c->device, (int)c->threads, &err)) return cli_fail(cmd, &err);
    return 0;
}

sp_log cli_log(const cli_common *c, sp_log_level level)
{
    return sp_log_stderr(c->verbose ? SP_LOG_DEBUG : level, c->quiet);
}
