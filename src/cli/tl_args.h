/* tl_args: a small, strict command-line reader shared by every command.
 *
 * Accepts `--flag value`, `--flag=value` and short `-o value`. Every
 * parse error names the flag and the offending text and has status
 * TL_ERR_USAGE (exit status 2). */
#ifndef TL_ARGS_H
#define TL_ARGS_H

#include <stdbool.h>

#include "core/tl_error.h"

typedef struct tl_args {
    int argc;
    char **argv;
    int index;         /* next argument to read */
    const char *flag;  /* the flag just matched (for messages) */
    const char *value; /* its value, when it takes one */
    const char *inline_value;
} tl_args;

void tl_args_init(tl_args *a, int argc, char **argv);
bool tl_args_done(const tl_args *a);
/* True if the current argument is `name` (or `alias`); consumes it. For a
 * flag that takes a value, pass takes_value and read a->value. */
bool tl_args_match(tl_args *a, const char *name, const char *alias, bool takes_value,
                   tl_error *err);
/* True and consumes it if the current argument is a positional one. */
bool tl_args_positional(tl_args *a, const char **out);
/* The error for whatever argument no match consumed. */
int tl_args_unknown(tl_args *a, const char *command, tl_error *err);

int tl_args_double(const char *flag, const char *text, double *out, tl_error *err);
/* A whole number in lo..hi. */
int tl_args_int_range(const char *flag, const char *text, int lo, int hi, int *out, tl_error *err);
/* on (1) or off (0). */
int tl_args_on_off(const char *flag, const char *text, int *out, tl_error *err);
/* A number with an optional unit: deg (default for angles) or rad. */
int tl_args_angle(const char *flag, const char *text, double *radians, tl_error *err);
/* WxH, each in 1..16384. */
int tl_args_size(const char *flag, const char *text, int *w, int *h, tl_error *err);
/* X,Y,Z: three finite numbers. */
int tl_args_vec3(const char *flag, const char *text, double out[3], tl_error *err);

#endif
