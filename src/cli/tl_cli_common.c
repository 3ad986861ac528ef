#include <stdio.h>

#include "tl_cli.h"

void tl_cli_print_error(const char *command, const tl_error *err)
{
    if (err->file[0] && err->line > 0)
        fprintf(stderr, "%s:%d:%d: error: %s\n", err->file, err->line, err->column, err->message);
    else
        fprintf(stderr, "tideline %s: %s\n", command, err->message);
}
