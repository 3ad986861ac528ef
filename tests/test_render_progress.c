/* A long frame's progress (tl_render_set_progress, `still` on a terminal):
 * the share of its pixel samples drawn (the sky's rows, drawn first, left
 * out: they take next to no time) only rises and ends at exactly 1,
 * whether the samples go in one pass (the ocean's draws, at a render scale
 * below 1), a pass per sample (the boat in view) or per sub-frame (motion
 * blur); and once turned off it is not called. */
#include <string.h>

#include "mesh/tl_mesh.h"
#include "prepare/tl_prepare.h"
#include "render/tl_render.h"
#include "timeline/tl_parse.h"
#include "tl_gl_test.h"

typedef struct shares {
    int calls, rising;
    double before_last, last;
} shares;

static void record(void *ctx, double fraction)
{
    shares *s = ctx;
    s->rising &= fraction >= s->last && fraction >= 0.0 && fraction <= 1.0;
    s->before_last = s->last;
    s->last = fraction;
    s->calls++;
}

static void check_shares(const char *what, const shares *s, int at_least)
{
    printf("%s: %d calls, the last two shares %.17g and %.17g\n", what, s->calls, s->before_last,
           s->last);
    CHECK(s->calls >= at_least);
    CHECK(s->rising);
    /* All of the frame at the last draw, and only there (the share is
     * capped at 1: a count drawn twice would reach it early). */
    CHECK(s->before_last < 1.0);
    CHECK(s->last == 1.0);
}

int main(void)
{
    tl_error err;
    tl_error_clear(&err);
    tl_render *r = render_test_open();
    if (!r)
        return 1;
    tl_frame f = {0};

    /* One pass, four samples a pixel, the ocean at half the output's size. */
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 64;
    s.height = 36;
    s.quality.spp = 4;
    s.quality.render_scale = 0.5;
    shares one = {0, 1, 0.0, 0.0};
    tl_render_set_progress(r, record, &one);
    CHECK(tl_render_frame(r, &s, &f, &err) == 0);
    check_shares("one pass", &one, 2);

    /* A pass per sample: the boat in view. */
    tl_mesh boat;
    CHECK(tl_mesh_default_boat(&boat, &err) == 0);
    CHECK(tl_render_set_boat(r, &boat, &err) == 0);
    tl_mesh_free(&boat);
    tl_scene b;
    tl_scene_defaults(&b);
    b.width = 64;
    b.height = 36;
    b.quality.spp = 3;
    b.boat.enabled = true;
    b.camera.position[0] = 10.0;
    b.camera.position[1] = 4.0;
    b.camera.position[2] = -10.0;
    const double target[3] = {0.0, 0.5, 0.0};
    tl_scene_camera_look_at(&b.camera, target, NULL);
    shares per_sample = {0, 1, 0.0, 0.0};
    tl_render_set_progress(r, record, &per_sample);
    CHECK(tl_render_frame(r, &b, &f, &err) == 0);
    CHECK((tl_render_last_features(r) & TL_FEATURE_BOAT) != 0);
    check_shares("a pass per sample", &per_sample, 3);

    /* Sub-frames: a shutter of 180 degrees in three, two samples each. */
    const char *text = "tideline 1\nfps 24\nduration 1s\nsize 48x27\n"
                       "key camera.yaw linear\n  0s 0deg\n  1s 30deg\n";
    tl_timeline tl;
    tl_diags diags;
    CHECK(tl_timeline_parse_text("progress.tl", text, strlen(text), &tl, &diags, &err) == 0);
    tl_render_settings settings = {.spp = 2, .shutter_deg = 180.0, .shutter_samples = 3};
    shares blur = {0, 1, 0.0, 0.0};
    tl_render_set_progress(r, record, &blur);
    CHECK(tl_render_timeline_frame(r, &tl, 12, &settings, &f, NULL, &err) == 0);
    check_shares("sub-frames", &blur, 3);

    /* Off: not called again. */
    tl_render_set_progress(r, NULL, NULL);
    int before = blur.calls;
    CHECK(tl_render_timeline_frame(r, &tl, 12, &settings, &f, NULL, &err) == 0);
    CHECK(blur.calls == before);

    tl_timeline_free(&tl);
    tl_frame_free(&f);
    tl_render_close(r);
    TEST_END();
}
