/* Shared helpers for the semsplat CLI commands (tools/cmd_*.c): flag parsing and error display.
 * Commands are thin: parse flags, call one library function, print the result. */
#ifndef SEMSPLAT_CLI_H
#define SEMSPLAT_CLI_H

#include "semsplat/core.h"
#include "semsplat/render.h"

/* Each command: int cmd_<name>(int argc, char **argv), argv[0] is the command name; returns the
 * exit status (0 ok, 1 failure, 2 usage error). */
typedef int (*sp_cmd_fn)(int argc, char **argv);
int cmd_info(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_synth(int argc, char **argv); /* tools/nosynth/cmd_synth.c when synth is not built */
int cmd_train(int argc, char **argv);
int cmd_features(int argc, char **argv);
int cmd_embed_text(int argc, char **argv);
int cmd_lift(int argc, char **argv);
int cmd_distill(int argc, char **argv);
int cmd_query(int argc, char **argv);
int cmd_align(int argc, char **argv);
int cmd_demo(int argc, char **argv);
int cmd_agent(int argc, char **argv);
int cmd_sim_robot(int argc, char **argv);
int cmd_ros_goal(int argc, char **argv);
int cmd_lexical(int argc, char **argv);
int cmd_plan(int argc, char **argv);
int cmd_explore(int argc, char **argv);
int cmd_describe(int argc, char **argv);
int cmd_sfm(int argc, char **argv);
int cmd_eval(int argc, char **argv);

/* Returns the value after flag `name` ("--out") at argv[*i] (advancing *i), or NULL. Accepts
 * "--out=VALUE" too. Prints an error and sets *bad when the value is missing. */
const char *cli_flag_value(int argc, char **argv, int *i, const char *name, int *bad);
int cli_is_flag(const char *arg, const char *name);
/* Prints "semsplat <cmd>: error: <message>" and returns 1. */
int cli_fail(const char *cmd, const sp_error *err);
int cli_usage_error(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Parses ints/floats strictly (whole string; ints within int's range, floats finite), printing
 * an error naming the flag on failure. */
int cli_parse_int(const char *cmd, const char *flag, const char *s, long *out);
int cli_parse_float(const char *cmd, const char *flag, const char *s, double *out);
/* "640x480" -> w, h. */
int cli_parse_size(const char *cmd, const char *flag, const char *s, int *w, int *h);

/* The flags every command that computes shares: --device cpu|cuda|auto, --threads N, --quiet,
 * --verbose. One parser for all of them, so an unknown device is a usage error everywhere. */
typedef struct cli_common {
    sp_device_kind device; /* SP_DEVICE_AUTO unless --device says otherwise */
    const char *device_name;
    long threads;          /* 0 = all cores */
    int quiet, verbose;
} cli_common;

/* Which shared flags a command takes (synth has no device, say). */
enum { CLI_DEVICE = 1, CLI_THREADS = 2, CLI_QUIET = 4, CLI_VERBOSE = 8, CLI_ALL = 15 };

cli_common cli_common_default(void);
/* Takes argv[*i] when it is one of the shared flags in `which` (advancing *i past its value):
 * returns 1 when taken, 0 when it is not such a flag, 2 (after printing a usage error naming the
 * flag and the value) when its value is bad; return that 2 as the exit status. */
int cli_common_flag(const char *cmd, int argc, char **argv, int *i, unsigned which, cli_common *c);
/* "cpu", "cuda", "auto" -> kind (sp_device_kind_parse); else prints a usage error naming the value
 * and returns 2. */
int cli_device_kind(const char *cmd, const char *value, sp_device_kind *kind);
/* Creates the device the flags asked for; prints the error and returns 1 on failure. */
int cli_device_open(const char *cmd, const cli_common *c, sp_device **dev);
/* The stderr log the flags ask for (--quiet silences progress, --verbose adds debug lines). */
sp_log cli_log(const cli_common *c, sp_log_level level);

#endif
