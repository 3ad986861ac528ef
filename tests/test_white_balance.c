/* The display's white balance (render.white_point, render.white_depth):
 * a pixel whose scene colour is the white point shows neutral, at its own
 * luminance; the scene's light (the colour plane, the EXR's) is the same
 * with any balance; and the white depth's gains follow the daylight the
 * water leaves at that depth (tl_optics_water_fall). */
#include <math.h>

#include "optics/tl_optics.h"
#include "tl_gl_test.h"

enum { W = 64, H = 36 };

static void balance_scene(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = W;
    s->height = H;
    s->time = 3.0;
    s->bloom = 0.0;
    s->quality.pixel_filter = 0.0; /* a pixel's display is its own colour's */
}

static void test_white_point(tl_renderer *r)
{
    tl_scene s;
    balance_scene(&s);
    tl_frame plain, balanced;
    if (render(r, &s, &plain))
        return;
    /* The white point: the sea's colour at a pixel near the bottom. */
    const int at = ((H - 4) * W + W / 2) * 4, sky = (2 * W + W / 2) * 4;
    for (int c = 0; c < 3; c++)
        s.white_point[c] = plain.color[at + c];
    if (render(r, &s, &balanced)) {
        tl_frame_free(&plain);
        return;
    }
    double scene_moved = 0.0;
    for (int i = 0; i < W * H * 4; i++)
        scene_moved = fmax(scene_moved, fabs(balanced.color[i] - plain.color[i]));
    const float *d = balanced.display + at;
    double spread = fmax(fabs(d[0] - d[1]), fmax(fabs(d[1] - d[2]), fabs(d[0] - d[2])));
    double before = plain.display[at + 2] - plain.display[at + 0];
    /* The sky, bluer than the sea's white point's luminance share, turns
     * warmer: its red over blue rises. */
    double sky_before = plain.display[sky] / plain.display[sky + 2];
    double sky_after = balanced.display[sky] / balanced.display[sky + 2];
    float gain[3];
    tl_prepare_white_gain(&s, gain);
    double y = 0.2126 * s.white_point[0] + 0.7152 * s.white_point[1] + 0.0722 * s.white_point[2];
    double gain_error = 0.0;
    for (int c = 0; c < 3; c++)
        gain_error = fmax(gain_error, fabs(gain[c] * s.white_point[c] / y - 1.0));
    printf("white point (%.4f %.4f %.4f): that pixel shows (%.4f %.4f %.4f), was blue - red "
           "%.3f; the sky's red over blue %.3f -> %.3f; scene light moved %.2g; gain error %.2g\n",
           s.white_point[0], s.white_point[1], s.white_point[2], d[0], d[1], d[2], before,
           sky_before, sky_after, scene_moved, gain_error);
    CHECK(before > 0.05); /* the sea was blue: the test has a cast to take out */
    CHECK(spread < 2e-3);
    CHECK(sky_after > 1.2 * sky_before);
    CHECK(scene_moved == 0.0);
    CHECK(gain_error < 1e-6);
    tl_frame_free(&plain);
    tl_frame_free(&balanced);
}

static void test_white_depth(void)
{
    tl_scene s;
    balance_scene(&s);
    float none[3], deep[3];
    tl_prepare_white_gain(&s, none);
    s.white_depth = 8.0;
    tl_prepare_white_gain(&s, deep);
    double sigma[3], fall[3];
    tl_optics_water_extinction(&s.water, sigma);
    tl_optics_water_fall(&s.water, sigma, fall);
    /* Red over blue rises by what the water takes of blue over red. */
    double ratio = (deep[0] / deep[2]) / exp((fall[0] - fall[2]) * 8.0);
    printf("white depth 8 m: gains %.3f %.3f %.3f (none: %.3f %.3f %.3f); red over blue "
           "against the daylight's fall %.6f\n",
           deep[0], deep[1], deep[2], none[0], none[1], none[2], ratio);
    CHECK(none[0] == 1.0f && none[1] == 1.0f && none[2] == 1.0f);
    CHECK(fabs(ratio - 1.0) < 1e-5);
    CHECK(deep[0] > 2.0 && deep[0] < TL_WHITE_GAIN_MAX);
    /* Past what float holds the gains are held. */
    s.white_point[0] = 1e-6;
    s.white_depth = TL_WHITE_DEPTH_MAX;
    tl_prepare_white_gain(&s, deep);
    CHECK(deep[0] == (float)TL_WHITE_GAIN_MAX && isfinite(deep[1]) && isfinite(deep[2]));
}

int main(void)
{
    test_white_depth();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_white_point(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
