/* Shared helpers for the semsplat CLI commands (tools/cmd_*.c): flag parsing and error display.
 * Commands are thin: parse flags, call one library function, print the result. */
#ifndef SEMSPLAT_CLI_H
#define SEMSPLAT_CLI_H

#include "semsplat/core.h"

/* Each command: int cmd_<name>(int argc, char **argv), argv[0] is the command name. */
typedef int (*sp_cmd_fn)(int argc, char **argv);

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

#endif
