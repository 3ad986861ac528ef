/* The shutter's sample times from the timeline (tl_shutter.c), GL-free:
 * the centres of equal slices of the interval around the frame's time,
 * the frame's time alone without a shutter, and never a time across a
 * cut, on either side of the frame. */
#include <math.h>
#include <string.h>

#include "timeline/tl_parse.h"
#include "timeline/tl_timeline.h"
#include "tl_test.h"

/* A cut at 0.1 s, between frames 2 (0.083 s) and 3 (0.125 s) at 24 fps. */
static const char with_cut[] = "tideline 1\n"
                               "fps 24\n"
                               "duration 12f\n"
                               "key camera.pitch\n"
                               "  0s      50deg\n"
                               "  0.1s    cut -50deg\n"
                               "  0.5s    -40deg\n";

static void parse(const char *text, tl_timeline *tl)
{
    tl_diags diags;
    tl_error err;
    CHECK(tl_timeline_parse_text("shutter.tl", text, strlen(text), tl, &diags, &err) == 0);
}

/* Without a shutter, or with one sample: the frame's time. */
static void test_no_shutter(const tl_timeline *tl)
{
    double times[4] = {-1, -1, -1, -1};
    CHECK(tl_timeline_shutter_times(tl, 5, 0.0, 4, times) == 0);
    CHECK(times[0] == 5.0 / 24);
    CHECK(times[1] == -1); /* nothing past the one time */
    CHECK(tl_timeline_shutter_times(tl, 5, 180.0, 1, times) == 0);
    CHECK(times[0] == 5.0 / 24);
}

/* Away from the cut: four slices of a 180-degree shutter around 0.25 s. */
static void test_times(const tl_timeline *tl)
{
    double times[4];
    int nearest = tl_timeline_shutter_times(tl, 6, 180.0, 4, times);
    double t = 6.0 / 24, open = t - 0.25 / 24, slice = 0.5 / 24 / 4;
    for (int k = 0; k < 4; k++)
        CHECK_NEAR(times[k], open + (k + 0.5) * slice, 1e-15);
    /* Two samples lie as near as each other: the first of them. */
    CHECK(nearest == 1);
    int odd = tl_timeline_shutter_times(tl, 6, 180.0, 3, times);
    CHECK(odd == 1);
    CHECK_NEAR(times[1], t, 1e-15);
}

/* Frame 2's 360-degree shutter (0.0625 .. 0.104 s) holds the cut at 0.1 s:
 * it closes before it, and every sample shows the shot before. Frame 3's
 * at 720 degrees (0.083 .. 0.167 s) opens at it: every sample shows the
 * shot after. */
static void test_cut(const tl_timeline *tl)
{
    double times[8], open, close;
    tl_timeline_shutter_interval(tl, 2, 360.0, &open, &close);
    CHECK_NEAR(open, 1.5 / 24, 1e-12);
    CHECK(close < 0.1 && close > 0.1 - 1e-9);
    tl_timeline_shutter_times(tl, 2, 360.0, 8, times);
    for (int k = 0; k < 8; k++) {
        CHECK(times[k] > open && times[k] < close);
        CHECK(!tl_timeline_has_cut_between(tl, times[k], 2.0 / 24) &&
              !tl_timeline_has_cut_between(tl, 2.0 / 24, times[k]));
        CHECK(k == 0 || times[k] > times[k - 1]);
    }
    tl_timeline_shutter_interval(tl, 3, 720.0, &open, &close);
    CHECK(open >= 0.1 && open < 0.1 + 1e-9);
    CHECK_NEAR(close, 4.0 / 24, 1e-12);
    int nearest = tl_timeline_shutter_times(tl, 3, 720.0, 8, times);
    for (int k = 0; k < 8; k++) {
        CHECK(times[k] >= 0.1);
        CHECK(!tl_timeline_has_cut_between(tl, 0.1, times[k]));
    }
    /* The nearest sample to 0.125 s, of slices of 0.1 .. 0.167 s. */
    double best = INFINITY;
    int want = 0;
    for (int k = 0; k < 8; k++)
        if (fabs(times[k] - 3.0 / 24) < best) {
            best = fabs(times[k] - 3.0 / 24);
            want = k;
        }
    CHECK(nearest == want);
    /* Frame 3 at 360 degrees (0.104 .. 0.146 s) holds no cut: whole. */
    tl_timeline_shutter_interval(tl, 3, 360.0, &open, &close);
    CHECK_NEAR(open, 2.5 / 24, 1e-12);
    CHECK_NEAR(close, 3.5 / 24, 1e-12);
}

int main(void)
{
    tl_timeline tl;
    parse(with_cut, &tl);
    test_no_shutter(&tl);
    test_times(&tl);
    test_cut(&tl);
    tl_timeline_free(&tl);
    TEST_END();
}
