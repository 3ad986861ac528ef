/* The commands. Each takes its own argv (argv[0] is the command name),
 * prints its errors as "tideline CMD: message" and returns the process
 * exit status: 0 success, 1 runtime failure, 2 usage error. */
#ifndef TL_CLI_H
#define TL_CLI_H

#include "core/tl_error.h"

int tl_cli_still(int argc, char **argv);

/* Prints err as one line (with file:line:col when it has one). */
void tl_cli_print_error(const char *command, const tl_error *err);

#endif
