#include "tl_args.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TL_MAX_SIZE 16384

void tl_args_init(tl_args *a, int argc, char **argv)
{
    memset(a, 0, sizeof *a);
    a->argc = argc;
    a->argv = argv;
}

bool tl_args_done(const tl_args *a)
{
    return a->index >= a->argc;
}

bool tl_args_match(tl_args *a, const char *name, const char *alias, bool takes_value, tl_error *err)
{
    const char *arg = a->argv[a->index];
    const char *names[2] = {name, alias};
    for (int i = 0; i < 2; i++) {
        if (!names[i])
            continue;
        size_t n = strlen(names[i]);
        if (strncmp(arg, names[i], n) != 0)
            continue;
        if (arg[n] == '\0') {
            a->flag = names[i];
            a->index++;
            if (!takes_value)
                return true;
            if (a->index >= a->argc) {
                tl_error_set(err, TL_ERR_USAGE, "%s needs a value", names[i]);
                a->value = NULL;
                return true;
            }
            a->value = a->argv[a->index++];
            return true;
        }
        if (arg[n] == '=' && takes_value && names[i][1] == '-') {
            a->flag = names[i];
            a->value = arg + n + 1;
            a->index++;
            return true;
        }
    }
    return false;
}

bool tl_args_positional(tl_args *a, const char **out)
{
    const char *arg = a->argv[a->index];
    if (arg[0] == '-' && arg[1] != '\0')
        return false;
    *out = arg;
    a->index++;
    return true;
}

int tl_args_unknown(tl_args *a, const char *command, tl_error *err)
{
    return tl_error_set(err, TL_ERR_USAGE, "unknown option '%s' (see 'tideline %s --help')",
                        a->argv[a->index], command);
}

int tl_args_double(const char *flag, const char *text, double *out, tl_error *err)
{
    char *end = NULL;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end != '\0')
        return tl_error_set(err, TL_ERR_USAGE, "%s: expected a number, got '%s'", flag, text);
    if (!isfinite(v) || errno == ERANGE)
        return tl_error_set(err, TL_ERR_USAGE, "%s: '%s' is not a finite number", flag, text);
    *out = v;
    return TL_OK;
}

int tl_args_int_range(const char *flag, const char *text, int lo, int hi, int *out, tl_error *err)
{
    double v;
    if (tl_args_double(flag, text, &v, err))
        return TL_ERR_USAGE;
    if (v != floor(v) || v < lo || v > hi)
        return tl_error_set(err, TL_ERR_USAGE, "%s: '%s' is not a whole number in %d..%d", flag,
                            text, lo, hi);
    *out = (int)v;
    return TL_OK;
}

int tl_args_on_off(const char *flag, const char *text, int *out, tl_error *err)
{
    if (strcmp(text, "on") && strcmp(text, "off"))
        return tl_error_set(err, TL_ERR_USAGE, "%s: '%s' is not on or off", flag, text);
    *out = !strcmp(text, "on");
    return TL_OK;
}

int tl_args_angle(const char *flag, const char *text, double *radians, tl_error *err)
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", text);
    size_t n = strlen(buf);
    double scale = M_PI / 180.0;
    if (n > 3 && strcmp(buf + n - 3, "rad") == 0) {
        buf[n - 3] = '\0';
        scale = 1.0;
    } else if (n > 3 && strcmp(buf + n - 3, "deg") == 0) {
        buf[n - 3] = '\0';
    }
    double v;
    if (tl_args_double(flag, buf, &v, err))
        return tl_error_set(err, TL_ERR_USAGE,
                            "%s: expected an angle (degrees, or NUMrad), "
                            "got '%s'",
                            flag, text);
    *radians = v * scale;
    return TL_OK;
}

int tl_args_size(const char *flag, const char *text, int *w, int *h, tl_error *err)
{
    char *end = NULL;
    errno = 0;
    long a = strtol(text, &end, 10);
    if (end == text || (*end != 'x' && *end != 'X'))
        return tl_error_set(err, TL_ERR_USAGE, "%s: expected WIDTHxHEIGHT, got '%s'", flag, text);
    const char *second = end + 1;
    long b = strtol(second, &end, 10);
    if (end == second || *end != '\0' || errno == ERANGE)
        return tl_error_set(err, TL_ERR_USAGE, "%s: expected WIDTHxHEIGHT, got '%s'", flag, text);
    if (a < 1 || b < 1 || a > TL_MAX_SIZE || b > TL_MAX_SIZE)
        return tl_error_set(err, TL_ERR_USAGE, "%s: %ldx%ld is out of range (each side 1..%d)",
                            flag, a, b, TL_MAX_SIZE);
    *w = (int)a;
    *h = (int)b;
    return TL_OK;
}

int tl_args_vec3(const char *flag, const char *text, double out[3], tl_error *err)
{
    const char *p = text;
    for (int i = 0; i < 3; i++) {
        char *end = NULL;
        errno = 0;
        double v = strtod(p, &end);
        char want = i < 2 ? ',' : '\0';
        if (end == p || *end != want)
            return tl_error_set(err, TL_ERR_USAGE, "%s: expected X,Y,Z, got '%s'", flag, text);
        if (!isfinite(v) || errno == ERANGE)
            return tl_error_set(err, TL_ERR_USAGE, "%s: '%s' holds a non-finite number", flag,
                                text);
        out[i] = v;
        p = end + 1;
    }
    return TL_OK;
}
