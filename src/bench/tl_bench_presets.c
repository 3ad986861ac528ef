/* Preset lists for the bench: names, variants with knobs changed
 * (`final:lod=off`) and other folders' shaders (`preview@DIR`). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench/tl_bench.h"
#include "scene/tl_scene.h"
#include "timeline/tl_channels.h"

/* One `KNOB=VALUE` of a variant: a quality.* channel of one component. */
static int apply_knob(const char *spec, char *knob, tl_quality *q, tl_error *err)
{
    char *eq = strchr(knob, '=');
    char name[96];
    if (!eq || eq == knob)
        return tl_error_set(err, TL_ERR_USAGE, "'%s': '%s' is not KNOB=VALUE", spec, knob);
    *eq = '\0';
    snprintf(name, sizeof name, "quality.%s", knob);
    const tl_channel *ch = tl_channel_find(name);
    if (!ch)
        return tl_error_set(err, TL_ERR_USAGE, "'%s': no quality knob '%s'", spec, knob);
    const char *text = eq + 1;
    double v;
    char *end = NULL;
    if (ch->kind == TL_CH_BOOL) {
        if (strcmp(text, "on") && strcmp(text, "off"))
            return tl_error_set(err, TL_ERR_USAGE, "'%s': %s=%s is not on or off", spec, knob,
                                text);
        v = !strcmp(text, "on");
    } else {
        v = strtod(text, &end);
        if (end == text || *end || !(v >= ch->min && v <= ch->max) ||
            (ch->kind != TL_CH_REAL && v != (double)(long)v))
            return tl_error_set(err, TL_ERR_USAGE, "'%s': %s=%s is not a %s in %g..%g", spec, knob,
                                text, ch->kind == TL_CH_REAL ? "number" : "whole number", ch->min,
                                ch->max);
    }
    tl_scene s;
    tl_scene_defaults(&s);
    s.quality = *q;
    const double in[3] = {v, v, v};
    tl_channel_set(ch, &s, in);
    *q = s.quality;
    return TL_OK;
}

int tl_bench_parse_presets(char *list, tl_bench_preset *out, int *count, tl_error *err)
{
    *count = 0;
    for (char *save = NULL, *item = strtok_r(list, ",", &save); item;
         item = strtok_r(NULL, ",", &save)) {
        if (*count == TL_BENCH_MAX_PRESETS)
            return tl_error_set(err, TL_ERR_USAGE, "more than %d presets", TL_BENCH_MAX_PRESETS);
        if (snprintf(out[*count].name, TL_BENCH_NAME, "%s", item) >= TL_BENCH_NAME)
            return tl_error_set(err, TL_ERR_USAGE, "'%s' is too long", item);
        char *at = strchr(item, '@');
        out[*count].dir = NULL;
        if (at) {
            *at++ = '\0';
            if (!*at)
                return tl_error_set(err, TL_ERR_USAGE, "'%s' names no folder after '@'",
                                    out[*count].name);
            out[*count].dir = at;
        }
        /* PRESET+passes: with the passes' data; PRESET+lights: with the
         * light layers. */
        out[*count].aov = out[*count].lights = 0;
        size_t len = strlen(item);
        if (len > strlen("+passes") && strcmp(item + len - strlen("+passes"), "+passes") == 0) {
            out[*count].aov = 1;
            item[len - strlen("+passes")] = '\0';
        } else if (len > strlen("+lights") &&
                   strcmp(item + len - strlen("+lights"), "+lights") == 0) {
            out[*count].lights = 1;
            item[len - strlen("+lights")] = '\0';
        }
        char *rest = strchr(item, ':');
        if (rest)
            *rest++ = '\0';
        if (strcmp(item, "reference") == 0)
            return tl_error_set(err, TL_ERR_USAGE,
                                "'reference' is always rendered (it is the yardstick)");
        if (tl_quality_preset(item, &out[*count].quality, err))
            return TL_ERR_USAGE;
        for (char *knob = rest; knob;) {
            char *next = strchr(knob, ':');
            if (next)
                *next++ = '\0';
            if (apply_knob(out[*count].name, knob, &out[*count].quality, err))
                return TL_ERR_USAGE;
            knob = next;
        }
        (*count)++;
    }
    if (*count == 0)
        return tl_error_set(err, TL_ERR_USAGE, "no preset named");
    return TL_OK;
}
