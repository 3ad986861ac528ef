/* Fuzz entry point: timeline text → parse → what `check` reports → evaluate
 * at a few times → what `eval` and a render prepare from each scene. Built
 * for libFuzzer with clang (scripts/fuzz.sh) and, with fuzz_replay.c, as a
 * plain test that replays the corpus (tests/fuzz.cmake).
 *
 * Beyond what the sanitizers see, the contract is checked and a breach
 * aborts: an invalid file has 1..TL_PARSE_MAX_ERRORS located diagnostics;
 * a valid one has no errors and evaluates to finite values inside every
 * channel's range. The input never names a file that is read: a boat model
 * is stood in for by fixed bounds (as the command line sets them after
 * loading the model), picked by the input's length. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "prepare/tl_prepare.h"
#include "timeline/tl_parse.h"
#include "waves/tl_giant.h"
#include "waves/tl_waves.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void breach(const char *what, double t)
{
    fprintf(stderr, "fuzz_timeline: contract broken at t=%.17g: %s\n", t, what);
    abort();
}

static void check_diags(const tl_diags *d)
{
    if (d->count < 1 || d->count > TL_PARSE_MAX_ERRORS || d->errors < 1)
        breach("an invalid timeline without 1..20 diagnostics", 0.0);
    for (int i = 0; i < d->count; i++)
        if (d->items[i].line < 1 || !d->items[i].message[0])
            breach("a diagnostic without a line or a message", 0.0);
    FILE *f = fopen("/dev/null", "w");
    if (f) {
        tl_diags_write(d, f);
        fclose(f);
    }
}

/* Model bounds a loaded mesh can have (finite floats, min <= max). */
static const float model_bounds[][2][3] = {
    {{-0.5f, -0.3f, -1.0f}, {0.5f, 1.2f, 1.0f}},       /* an ordinary boat */
    {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}},          /* one point */
    {{0.0f, 0.0f, -2.0f}, {0.0f, 0.0f, 2.0f}},         /* a line, no beam */
    {{-3e38f, -3e38f, -3e38f}, {3e38f, 3e38f, 3e38f}}, /* the float range */
};

static void check_scene(const tl_timeline *tl, double t)
{
    tl_scene s;
    tl_timeline_eval(tl, t, &s);
    for (int k = 0; k < s.objects; k++)
        for (int i = 0; i < tl_channel_count(); i++) {
            const tl_channel *ch = tl_channel_at(i);
            if (k > 0 && !tl_channel_is_object(ch))
                continue;
            double v[3];
            tl_channel_get_object(ch, &s, k, v);
            for (int c = 0; c < ch->components; c++)
                if (!isfinite(v[c]) || v[c] < ch->min || v[c] > ch->max)
                    breach(ch->name, t);
        }
    for (int o = 0; o < s.objects; o++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(tl_scene_object(&s, o)->position[k]))
                breach("a floating object's position", t);

    /* eval's report: the giant wave after its clamps, water heights. */
    tl_waves waves;
    tl_waves_init(&waves, &s.ocean);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    const int oct = s.quality.march_octaves, it = s.quality.giant_iterations;
    tl_waves_surface_height(&waves, &g, s.camera.position[0], s.camera.position[2], s.time, oct,
                            it);
    tl_waves_surface_height(&waves, &g, s.boat.position[0], s.boat.position[2], s.time, oct, it);
    tl_prepare_water_side(&s, &waves, &g, NULL);

    /* What a render of this scene would upload (only a valid scene is
     * rendered; the commands stop on the others). */
    tl_error err;
    tl_error_clear(&err);
    if (tl_scene_validate(&s, &err) == TL_OK) {
        static tl_frame_uniforms u;
        tl_prepare_frame(&s, &waves, &u);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    if (tl_timeline_parse_text("fuzz.tl", (const char *)data, size, &tl, &diags, &err) != TL_OK) {
        check_diags(&diags);
        return 0;
    }
    if (diags.errors)
        breach("a valid timeline with errors", 0.0);

    /* check's summary */
    tl_timeline_features f;
    tl_timeline_features_of(&tl, &f);
    long frames = tl_timeline_frame_count(&tl);
    for (int k = 0; k < tl.object_count; k++)
        if (tl.objects[k].path.present && (size + (size_t)k) % 5 < 4)
            tl_timeline_set_object_model(&tl, k, k, model_bounds[(size + (size_t)k) % 5][0],
                                         model_bounds[(size + (size_t)k) % 5][1]);

    const double d = tl.duration;
    const double times[] = {
        0.0, d * 0.37, d, -1.0, d + 1.0, tl_timeline_frame_time(&tl, frames > 0 ? frames - 1 : 0)};
    for (size_t i = 0; i < sizeof times / sizeof times[0]; i++)
        check_scene(&tl, times[i]);
    tl_timeline_has_cut_between(&tl, 0.0, d);
    tl_timeline_free(&tl);
    return 0;
}
