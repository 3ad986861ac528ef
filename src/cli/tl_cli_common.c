#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "image/tl_image_io.h"
#include "movie/tl_movie.h"
#include "passes/tl_passes.h"
#include "scene/tl_quality.h"
#include "tl_cli.h"

int tl_cli_passes(const char *flag, const char *value, unsigned *passes, tl_error *err)
{
    size_t at, len;
    if (!tl_passes_parse(value, passes, &at, &len))
        return TL_OK;
    if (len == 4 && strncmp(value + at, "none", 4) == 0)
        return tl_error_set(err, TL_ERR_USAGE, "%s: 'none' stands alone (in '%s')", flag, value);
    return tl_error_set(err, TL_ERR_USAGE, "%s: unknown pass '%.*s' in '%s' (passes: %s)", flag,
                        (int)len, value + at, value, tl_passes_valid_names());
}

void tl_cli_print_error(const char *command, const tl_error *err)
{
    if (!tl_error_write_located(stderr, err))
        fprintf(stderr, "tideline %s: %s\n", command, err->message);
}

/* mkdir -p of the folder part of `path`. */
int tl_cli_make_parent_dirs(const char *path, tl_error *err)
{
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (!slash || slash == dir)
        return TL_OK;
    *slash = '\0';
    for (char *p = dir + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(dir, 0777) != 0 && errno != EEXIST)
            return tl_error_set(err, TL_ERR_USAGE, "cannot create folder '%s': %s", dir,
                                strerror(errno));
        *p = '/';
    }
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return tl_error_set(err, TL_ERR_USAGE, "cannot create folder '%s': %s", dir,
                            strerror(errno));
    return TL_OK;
}

void tl_cli_format_duration(double s, char *out, size_t size)
{
    if (!isfinite(s) || s < 0)
        snprintf(out, size, "--");
    else if (s < 60)
        snprintf(out, size, "%.0fs", s);
    else if (s < 3600)
        snprintf(out, size, "%dm%02ds", (int)(s / 60), (int)fmod(s, 60));
    else
        snprintf(out, size, "%dh%02dm", (int)(s / 3600), (int)fmod(s / 60, 60));
}

double tl_cli_progress_delay(void)
{
    const char *text = getenv("TIDELINE_PROGRESS_DELAY");
    char *end = NULL;
    double v = text ? strtod(text, &end) : 1.0;
    return text && end != text && *end == '\0' && v >= 0.0 && isfinite(v) ? v : 1.0;
}

void tl_cli_catch_stop(void (*handler)(int), tl_cli_signals *saved)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &saved->old_int);
    sigaction(SIGTERM, &sa, &saved->old_term);
}

void tl_cli_restore_stop(const tl_cli_signals *saved)
{
    sigaction(SIGINT, &saved->old_int, NULL);
    sigaction(SIGTERM, &saved->old_term, NULL);
}

void tl_cli_describe_sound(FILE *to, const tl_movie_sound *sound)
{
    const char *slash = strrchr(sound->path, '/');
    const char *name = slash ? slash + 1 : sound->path;
    if (sound->start >= 0.0)
        fprintf(to, ", with the sound of %s from %.3f s into it", name, sound->start);
    else
        fprintf(to, ", with the sound of %s, its start %.3f s into the movie", name, -sound->start);
}
