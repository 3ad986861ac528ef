#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "image/tl_image_io.h"
#include "scene/tl_quality.h"
#include "tl_cli.h"

void tl_cli_print_error(const char *command, const tl_error *err)
{
    if (err->file[0] && err->line > 0)
        fprintf(stderr, "%s:%d:%d: error: %s\n", err->file, err->line, err->column, err->message);
    else
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

int tl_cli_quality_meta(const tl_quality *q, tl_meta *out)
{
    const tl_meta m[TL_CLI_QUALITY_META] = {
        {"tideline/quality", TL_META_STRING, q->name, 0, 0},
        {"tideline/spp", TL_META_INT, NULL, 0, q->spp},
        {"tideline/march_octaves", TL_META_INT, NULL, 0, q->march_octaves},
        {"tideline/normal_octaves", TL_META_INT, NULL, 0, q->normal_octaves},
        {"tideline/march_steps", TL_META_INT, NULL, 0, q->march_steps},
        {"tideline/hit_epsilon", TL_META_DOUBLE, NULL, q->hit_epsilon, 0},
        {"tideline/normal_epsilon", TL_META_DOUBLE, NULL, q->normal_epsilon, 0},
        {"tideline/giant_iterations", TL_META_INT, NULL, 0, q->giant_iterations},
        {"tideline/refine_steps", TL_META_INT, NULL, 0, q->refine_steps},
        {"tideline/polish", TL_META_INT, NULL, 0, q->polish},
        {"tideline/lod", TL_META_INT, NULL, 0, q->lod},
        {"tideline/analytic_normals", TL_META_INT, NULL, 0, q->analytic_normals},
        {"tideline/filtered_shading", TL_META_INT, NULL, 0, q->filtered_shading},
        {"tideline/render_scale", TL_META_DOUBLE, NULL, q->render_scale, 0},
        {"tideline/pixel_filter", TL_META_DOUBLE, NULL, q->pixel_filter, 0},
        {"tideline/march_relax", TL_META_DOUBLE, NULL, q->march_relax, 0},
        {"tideline/march_prepass", TL_META_INT, NULL, 0, q->march_prepass},
        {"tideline/prepass_budget", TL_META_INT, NULL, 0, q->prepass_budget},
        {"tideline/giant_prepass", TL_META_INT, NULL, 0, q->giant_prepass},
        {"tideline/miss_at_start", TL_META_INT, NULL, 0, q->miss_at_start},
        {"tideline/normalize_smoothed", TL_META_INT, NULL, 0, q->normalize_smoothed},
        {"tideline/facing_normals", TL_META_INT, NULL, 0, q->facing_normals},
    };
    memcpy(out, m, sizeof m);
    return TL_CLI_QUALITY_META;
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
