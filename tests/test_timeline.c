/* The timeline language end to end at the API level: text in, scenes out.
 * Every expected value is derived here from the statement's meaning (unit
 * arithmetic, the easing formula, geometry), or read from the fixture
 * tests/fixtures/curve_reference.txt (argv[1]) that
 * tests/blender_curve_ref.py writes from Blender's formulas; never read
 * back from the implementation. After changing the script, regenerate the
 * fixture from the repository root:
 *     python3 tests/blender_curve_ref.py > tests/fixtures/curve_reference.txt */
#include <stdlib.h>

#include "core/tl_math.h"
#include "scene/tl_quality.h"
#include "timeline/tl_parse.h"
#include "tl_fixture.h"
#include "tl_test.h"
#include "waves/tl_waves.h"

/* Parses `text`; on failure prints the diagnostics and counts a failure. */
static int parse_ok(const char *text, tl_timeline *tl)
{
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_timeline_parse_text("test.tl", text, strlen(text), tl, &diags, &err);
    CHECK(rc == 0);
    if (rc != 0) {
        tl_diags_write(&diags, stderr);
        return 0;
    }
    return 1;
}

static int parse_fails(const char *text)
{
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_timeline_parse_text("test.tl", text, strlen(text), &tl, &diags, &err);
    if (rc == 0)
        tl_timeline_free(&tl);
    return rc != 0 && diags.count > 0;
}

static double value_in(const tl_scene *s, const char *name, int component)
{
    const tl_channel *ch = tl_channel_find(name);
    CHECK(ch != NULL);
    if (!ch)
        return NAN;
    double v[3];
    tl_channel_get(ch, s, v);
    return v[component];
}

/* Channel `name` (component `c`) of the scene at time t. */
static double at(const tl_timeline *tl, double t, const char *name, int c)
{
    tl_scene s;
    tl_timeline_eval(tl, t, &s);
    return value_in(&s, name, c);
}

/* Angle between two vectors, accurate near zero (acos is not). */
static double angle_between(const double a[3], const double b[3])
{
    double cx = a[1] * b[2] - a[2] * b[1];
    double cy = a[2] * b[0] - a[0] * b[2];
    double cz = a[0] * b[1] - a[1] * b[0];
    double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), dot);
}

/* Difference of two angles folded into (-pi, pi]. */
static double wrapped(double a)
{
    return remainder(a, 2.0 * M_PI);
}

static void test_time_units(void)
{
    tl_error err;
    double t = -1.0;
    CHECK(tl_parse_time_text("1500ms", 24.0, &t, &err) == 0);
    CHECK_NEAR(t, 1.5, 1e-15);
    CHECK(tl_parse_time_text("36f", 24.0, &t, &err) == 0);
    CHECK_NEAR(t, 1.5, 1e-15);
    CHECK(tl_parse_time_text("36f", 30.0, &t, &err) == 0);
    CHECK_NEAR(t, 1.2, 1e-15);
    CHECK(tl_parse_time_text("2.5", 24.0, &t, &err) == 0);
    CHECK(t == 2.5);
    CHECK(tl_parse_time_text("2.5s", 24.0, &t, &err) == 0);
    CHECK(t == 2.5);
    CHECK(tl_parse_time_text("-250ms", 24.0, &t, &err) == 0);
    CHECK_NEAR(t, -0.25, 1e-15);
    CHECK(tl_parse_time_text("1.5min", 24.0, &t, &err) != 0);
    CHECK(tl_parse_time_text("nan", 24.0, &t, &err) != 0);
    CHECK(tl_parse_time_text("", 24.0, &t, &err) != 0);

    /* Keys written in ms and frames land at 1.5 s. */
    tl_timeline tl;
    if (!parse_ok("tideline 1\nfps 24\n"
                  "key render.exposure linear\n  0s 1\n  36f 4\n"
                  "key sun.intensity linear\n  0 100\n  1500ms 400\n",
                  &tl))
        return;
    const tl_track *exp = &tl.tracks[tl_channel_index(tl_channel_find("render.exposure"))];
    CHECK(exp->state == TL_TRACK_KEYED);
    CHECK(exp->curve[0].count == 2);
    if (exp->curve[0].count == 2)
        CHECK_NEAR(exp->curve[0].keys[1].t, 1.5, 1e-15);
    CHECK_NEAR(at(&tl, 1.5, "render.exposure", 0), 4.0, 1e-12);
    CHECK_NEAR(at(&tl, 0.75, "render.exposure", 0), 2.5, 1e-12);
    CHECK_NEAR(at(&tl, 1.5, "sun.intensity", 0), 400.0, 1e-12);
    CHECK_NEAR(at(&tl, 0.75, "sun.intensity", 0), 250.0, 1e-12);
    tl_timeline_free(&tl);
}

static void test_angle_and_length_units(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\n"
                  "set sun.elevation 90deg\n"
                  "set camera.roll 1rad\n"
                  "set sun.azimuth 45\n" /* bare: degrees */
                  "set giant.angle -30deg\n"
                  "set camera.fov 0.5rad\n"
                  "set ocean.depth 2.5m\n"
                  "set boat.size 12\n" /* bare: metres */
                  "set giant.height 3m\n"
                  "key camera.yaw linear\n  0s 0\n  2s 1rad\n",
                  &tl))
        return;
    tl_scene s;
    tl_timeline_eval(&tl, 0.0, &s);
    CHECK_NEAR(s.sun.elevation, M_PI / 2.0, 1e-15);
    CHECK_NEAR(s.camera.roll, 1.0, 0.0);
    CHECK_NEAR(s.sun.azimuth, M_PI / 4.0, 1e-15);
    CHECK_NEAR(s.giant.angle, -M_PI / 6.0, 1e-15);
    CHECK_NEAR(s.camera.vfov, 0.5, 0.0);
    CHECK_NEAR(s.ocean.depth, 2.5, 0.0);
    CHECK_NEAR(s.boat.size, 12.0, 0.0);
    CHECK_NEAR(s.giant.height, 3.0, 0.0);
    CHECK_NEAR(at(&tl, 1.0, "camera.yaw", 0), 0.5, 1e-15);
    tl_timeline_free(&tl);

    /* A unit of the wrong kind is an error, not a silent conversion. */
    CHECK(parse_fails("tideline 1\nset sun.elevation 5m\n"));
    CHECK(parse_fails("tideline 1\nset ocean.depth 2deg\n"));
    CHECK(parse_fails("tideline 1\nset render.exposure 2s\n"));
}

static void test_default_set_key(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\nduration 4s\n"
                  "set sun.intensity 100\n"
                  "key render.exposure linear\n  0s 1\n  4s 3\n"
                  "key water.foam\n  0s 0 ease-in-out-sine\n  4s 0.8\n"
                  "key sky.brightness step\n  0s 0.5\n  2s 1.0\n  4s 0.2\n"
                  "key water.scatter_base linear\n  0s 0.1 constant\n  2s 0.3\n  4s 0.5\n"
                  "key sun.sharpness\n  0s 100\n  4s 300\n",
                  &tl))
        return;
    /* Every channel the text does not name evaluates to the default scene. */
    const char *named[] = {"sun.intensity",      "render.exposure", "water.foam", "sky.brightness",
                           "water.scatter_base", "sun.sharpness",   NULL};
    tl_scene defaults;
    tl_scene_defaults(&defaults);
    const double times[] = {-5.0, 0.0, 1.3, 4.0, 1e6};
    for (size_t k = 0; k < sizeof times / sizeof times[0]; k++) {
        tl_scene s;
        tl_timeline_eval(&tl, times[k], &s);
        for (int i = 0; i < tl_channel_count(); i++) {
            const tl_channel *ch = tl_channel_at(i);
            int is_named = 0;
            for (int j = 0; named[j]; j++)
                is_named |= strcmp(named[j], ch->name) == 0;
            if (is_named)
                continue;
            double got[3], want[3];
            tl_channel_get(ch, &s, got);
            tl_channel_get(ch, &defaults, want);
            for (int c = 0; c < ch->components; c++)
                if (got[c] != want[c]) {
                    fprintf(stderr, "  %s[%d] at t=%g: %.17g, default %.17g\n", ch->name, c,
                            times[k], got[c], want[c]);
                    CHECK(got[c] == want[c]);
                }
        }
        /* `set`: the same constant at every time. */
        CHECK(value_in(&s, "sun.intensity", 0) == 100.0);
    }
    /* Linear: the midpoint is exact. */
    CHECK_NEAR(at(&tl, 2.0, "render.exposure", 0), 2.0, 1e-15);
    CHECK_NEAR(at(&tl, 1.0, "render.exposure", 0), 1.5, 1e-15);
    /* Ease-in-out-sine on the first key shapes the segment after it:
     * (1 - cos(pi u)) / 2 of the change; 0.5 at the midpoint. */
    CHECK_NEAR(at(&tl, 2.0, "water.foam", 0), 0.4, 1e-12);
    CHECK_NEAR(at(&tl, 1.0, "water.foam", 0), 0.8 * (1.0 - cos(M_PI / 4.0)) / 2.0, 1e-12);
    /* Step (block default) and constant (one key) hold until the next key. */
    CHECK(at(&tl, 1.999, "sky.brightness", 0) == 0.5);
    CHECK(at(&tl, 2.0, "sky.brightness", 0) == 1.0);
    CHECK(at(&tl, 3.999, "sky.brightness", 0) == 1.0);
    CHECK(at(&tl, 4.0, "sky.brightness", 0) == 0.2);
    CHECK(at(&tl, 1.999, "water.scatter_base", 0) == 0.1);
    CHECK_NEAR(at(&tl, 3.0, "water.scatter_base", 0), 0.4, 1e-12);
    /* Default interpolation (Bezier, auto-clamped): two keys give a curve
     * symmetric about the midpoint, flat at the ends. */
    CHECK_NEAR(at(&tl, 2.0, "sun.sharpness", 0), 200.0, 1e-9);
    CHECK_NEAR(at(&tl, 1.0, "sun.sharpness", 0) + at(&tl, 3.0, "sun.sharpness", 0), 400.0, 1e-9);
    CHECK(at(&tl, 1.0, "sun.sharpness", 0) < 150.0);
    /* Before the first and after the last key: the end values hold. */
    CHECK(at(&tl, -5.0, "render.exposure", 0) == 1.0);
    CHECK(at(&tl, 1e6, "render.exposure", 0) == 3.0);
    tl_timeline_free(&tl);
}

static void test_extrapolation(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\n"
                  "key render.exposure linear extrapolate cycle\n  1s 1\n  3s 3\n  5s 1\n"
                  "key ocean.speed linear extrapolate linear\n  0s 0\n  2s 2\n"
                  "key ocean.radial_phase linear extrapolate ping-pong\n  0s 0\n  2s 2\n"
                  "key ocean.direction_step linear extrapolate cycle-offset\n  0s 0\n  2s 2\n",
                  &tl))
        return;
    /* Cycle, period 4 s from 1 s: 1e6 + 0.5 s is 3.5 s into a cycle, i.e.
     * t = 4.5 s, three quarters from 3 (at 3 s) to 1 (at 5 s). */
    CHECK_NEAR(at(&tl, 4.5, "render.exposure", 0), 1.5, 1e-12);
    CHECK_NEAR(at(&tl, 1e6 + 0.5, "render.exposure", 0), 1.5, 1e-9);
    CHECK_NEAR(at(&tl, 1e6, "render.exposure", 0), at(&tl, 4.0, "render.exposure", 0), 1e-9);
    CHECK_NEAR(at(&tl, 1e6, "render.exposure", 0), 2.0, 1e-9);
    CHECK_NEAR(at(&tl, -0.5, "render.exposure", 0), 2.5, 1e-12); /* 3.5 s into the cycle */
    /* Linear: the end slope (1/s) continues, clamped to the channel range. */
    CHECK_NEAR(at(&tl, 10.0, "ocean.speed", 0), 10.0, 1e-12);
    CHECK_NEAR(at(&tl, -3.0, "ocean.speed", 0), -3.0, 1e-12);
    CHECK(at(&tl, 1e6, "ocean.speed", 0) == 1e3);
    /* Ping-pong: forwards over [0,2], backwards over [2,4]. */
    CHECK_NEAR(at(&tl, 3.5, "ocean.radial_phase", 0), 0.5, 1e-12);
    CHECK_NEAR(at(&tl, 5.0, "ocean.radial_phase", 0), 1.0, 1e-12);
    CHECK_NEAR(at(&tl, 1e6 + 0.5, "ocean.radial_phase", 0), 0.5, 1e-9);
    /* Cycle-offset: each repeat shifted by the change over one cycle. */
    CHECK_NEAR(at(&tl, 3.0, "ocean.direction_step", 0), 3.0, 1e-12);
    CHECK_NEAR(at(&tl, 11.0, "ocean.direction_step", 0), 11.0, 1e-12);
    tl_timeline_free(&tl);
}

/* What Blender authors reach for (issue 13): easing settings, per-side
 * extrapolation with repeat counts, per-side handle types, smoothing.
 * Elastic and cycle values from the fixture (Blender 3.4's formulas at
 * 30 fps). */
static void test_blender_options(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\nfps 30\n"
                  "key render.exposure ease-out-elastic amplitude 0.5 period 6f\n"
                  "  0s 0\n  1s 10\n"
                  "key ocean.speed ease-in-elastic\n  0s 0\n  1s 10\n"
                  "key ocean.radial_phase linear before ping-pong 2 after cycle-offset 1\n"
                  "  0s 0\n  1s 1\n  2s 0.5\n"
                  "key camera.fov bezier smoothing continuous\n"
                  "  0s 60deg\n"
                  "  1s 50deg left vector right free 0.5s 2deg\n"
                  "  2s 40deg right auto left aligned -0.25s 1deg\n"
                  "  3s 45deg ease-in-back back 0\n"
                  "  4s 50deg\n",
                  &tl))
        return;
    CHECK_NEAR(at(&tl, 0.3, "render.exposure", 0), tl_fixture("timeline.exposure_elastic.u=0.3"),
               1e-12);
    CHECK_NEAR(at(&tl, 0.5, "render.exposure", 0), tl_fixture("timeline.exposure_elastic.u=0.5"),
               1e-12);
    /* An inserted key's defaults: amplitude 0.8, period 4.1 frames. */
    CHECK_NEAR(at(&tl, 0.8, "ocean.speed", 0), tl_fixture("timeline.speed_elastic.u=0.8"), 1e-12);
    const tl_track *fov = &tl.tracks[tl_channel_index(tl_channel_find("camera.fov"))];
    const tl_curve *c = &fov->curve[0];
    CHECK(c->smoothing == TL_SMOOTH_CONTINUOUS && c->fps == 30.0);
    CHECK(c->keys[0].ease.back == TL_EASE_BACK_OVERSHOOT && c->keys[0].ease.period == 4.1);
    CHECK(c->keys[1].left_type == TL_HANDLE_VECTOR && c->keys[1].right_type == TL_HANDLE_FREE);
    CHECK_NEAR(c->keys[1].right.t, 1.5, 1e-15);
    CHECK_NEAR(c->keys[1].right.v, 52.0 * TL_DEG, 1e-15);
    CHECK(c->keys[2].left_type == TL_HANDLE_ALIGNED && c->keys[2].right_type == TL_HANDLE_AUTO);
    /* back 0: a plain cubic from 45 to 50 degrees. */
    CHECK(c->keys[3].interp == TL_INTERP_EASE && c->keys[3].ease.back == 0.0);
    CHECK_NEAR(at(&tl, 3.5, "camera.fov", 0), (45.0 + 5.0 / 8.0) * TL_DEG, 1e-12);
    const tl_track *exp = &tl.tracks[tl_channel_index(tl_channel_find("render.exposure"))];
    CHECK(exp->curve[0].keys[0].ease.amplitude == 0.5);
    CHECK_NEAR(exp->curve[0].keys[0].ease.period, 6.0, 1e-12); /* frames */
    /* Ping-pong twice before, one offset cycle after, then the end holds. */
    CHECK_NEAR(at(&tl, -1.5, "ocean.radial_phase", 0), 0.75, 1e-12);
    CHECK(at(&tl, -5.0, "ocean.radial_phase", 0) == 0.0);
    CHECK_NEAR(at(&tl, 3.0, "ocean.radial_phase", 0), 1.5, 1e-12);
    CHECK(at(&tl, 4.5, "ocean.radial_phase", 0) == 0.5);
    tl_timeline_free(&tl);

    /* Handles and elastic periods are in frames: fps must come first. */
    CHECK(parse_fails("tideline 1\nkey render.exposure\n  0s 1\n  1s 2\nfps 30\n"));
    CHECK(parse_fails("tideline 1\nkey render.exposure after linear 2\n  0s 1\n"));
    CHECK(parse_fails("tideline 1\nkey render.exposure\n  0s 1 left\n"));
}

static void test_shortest(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\nkey camera.yaw linear shortest\n  0s 170deg\n  2s -170deg\n", &tl))
        return;
    /* Through 180 deg, not back through 0. */
    double mid = at(&tl, 1.0, "camera.yaw", 0);
    CHECK_NEAR(wrapped(mid - M_PI), 0.0, 1e-12);
    CHECK_NEAR(cos(mid), -1.0, 1e-12);
    CHECK_NEAR(wrapped(at(&tl, 0.5, "camera.yaw", 0) - 175.0 * TL_DEG), 0.0, 1e-12);
    CHECK_NEAR(wrapped(at(&tl, 2.0, "camera.yaw", 0) + 170.0 * TL_DEG), 0.0, 1e-12);
    tl_timeline_free(&tl);

    /* Without `shortest` the same keys sweep through 0. */
    if (!parse_ok("tideline 1\nkey camera.yaw linear\n  0s 170deg\n  2s -170deg\n", &tl))
        return;
    CHECK_NEAR(at(&tl, 1.0, "camera.yaw", 0), 0.0, 1e-12);
    tl_timeline_free(&tl);
}

static void test_cuts(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\nduration 20s\n"
                  "key render.exposure linear\n  0s 0\n  11s 4\n  11s cut 10\n  20s 12\n"
                  "key sun.intensity linear\n  0s 100\n  5s 200\n  11s cut 800\n  20s 900\n"
                  "key camera.position linear\n  0s 0 2 0\n  11s cut 14 1.2 30\n  20s 18 1.4 40\n",
                  &tl))
        return;
    /* Before the cut the earlier segment applies, at the cut the cut value. */
    double before = 11.0 - 1e-9;
    CHECK_NEAR(at(&tl, before, "render.exposure", 0), 4.0 * before / 11.0, 1e-12);
    CHECK_NEAR(at(&tl, 10.5, "render.exposure", 0), 4.0 * 10.5 / 11.0, 1e-12);
    CHECK(at(&tl, 11.0, "render.exposure", 0) == 10.0);
    CHECK_NEAR(at(&tl, 15.5, "render.exposure", 0), 11.0, 1e-12);
    /* A cut after a held key: the earlier value holds until the jump. */
    CHECK(at(&tl, before, "sun.intensity", 0) == 200.0);
    CHECK(at(&tl, 11.0, "sun.intensity", 0) == 800.0);
    CHECK(at(&tl, before, "camera.position", 2) == 0.0);
    CHECK(at(&tl, 11.0, "camera.position", 0) == 14.0);
    CHECK(at(&tl, 11.0, "camera.position", 1) == 1.2);
    CHECK(at(&tl, 11.0, "camera.position", 2) == 30.0);

    CHECK(tl_timeline_has_cut_between(&tl, 10.0, 11.0));
    CHECK(tl_timeline_has_cut_between(&tl, before, 11.0));
    CHECK(tl_timeline_has_cut_between(&tl, 0.0, 20.0));
    CHECK(!tl_timeline_has_cut_between(&tl, 11.0, 12.0)); /* (t0, t1] excludes t0 */
    CHECK(!tl_timeline_has_cut_between(&tl, 0.0, 10.9));
    CHECK(!tl_timeline_has_cut_between(&tl, 12.0, 20.0));
    CHECK(!tl_timeline_has_cut_between(&tl, -5.0, 0.0));
    tl_timeline_free(&tl);

    if (!parse_ok("tideline 1\nkey render.exposure linear\n  0s 0\n  11s 4\n", &tl))
        return;
    CHECK(!tl_timeline_has_cut_between(&tl, -1e6, 1e6));
    tl_timeline_free(&tl);
}

static const char *const boat_path =
    "path boat constant-speed\n  0s 10 20\n  4s 30 25\n  10s 0 60\n";

static void test_look_at_boat(void)
{
    char text[1024];
    snprintf(text, sizeof text,
             "tideline 1\nset camera.position -5 4 -3\n%slook camera at boat + 0 1.5 0\n",
             boat_path);
    tl_timeline tl;
    if (!parse_ok(text, &tl))
        return;
    double worst = 0.0;
    for (int i = -4; i <= 48; i++) {
        double t = i * 0.25;
        tl_scene s;
        tl_timeline_eval(&tl, t, &s);
        double target[3] = {s.boat.position[0], s.boat.position[1] + 1.5, s.boat.position[2]};
        double d[3] = {target[0] - s.camera.position[0], target[1] - s.camera.position[1],
                       target[2] - s.camera.position[2]};
        double r[3], u[3], f[3];
        tl_scene_camera_basis(&s.camera, r, u, f);
        double a = angle_between(f, d);
        if (!(a <= worst))
            worst = a;
        CHECK(s.camera.position[0] == -5.0 && s.camera.position[1] == 4.0);
    }
    CHECK(worst < 1e-9);
    if (!(worst < 1e-9))
        fprintf(stderr, "  look at boat: worst angle %.3g rad\n", worst);
    tl_timeline_free(&tl);
}

/* The wake's points carry their distance along the boat's path: a point
 * passed at a given time keeps it in every later frame (the foam's
 * texture hangs on it), the boat's own is how far it has come, and
 * neighbouring points lie that far apart along the path. */
static void test_wake_along(void)
{
    char text[1024];
    snprintf(text, sizeof text, "tideline 1\n%s", boat_path);
    tl_timeline tl;
    if (!parse_ok(text, &tl))
        return;
    tl_scene a, b;
    tl_timeline_eval(&tl, 6.0, &a);
    /* Three wake steps later, point k + 3 is where point k was. */
    tl_timeline_eval(&tl, 6.0 + 3.0 * a.boat.wake_step, &b);
    CHECK(a.boat.wake_step > 0.0);
    CHECK_NEAR(a.boat.wake_along[0], 0.6 * tl.objects[0].path.path.length, 1e-9);
    for (int k = 0; k + 3 < TL_WAKE_POINTS; k++) {
        CHECK_NEAR(b.boat.wake_along[k + 3], a.boat.wake_along[k], 1e-9);
        CHECK_NEAR(b.boat.wake_path[k + 3][0], a.boat.wake_path[k][0], 1e-9);
        /* The chord is shorter than the arc, by 6% where the path turns
         * hard at its second point, by much less elsewhere. */
        if (k > 0 && a.boat.wake_along[k] > 0.0) {
            double chord = hypot(a.boat.wake_path[k][0] - a.boat.wake_path[k - 1][0],
                                 a.boat.wake_path[k][1] - a.boat.wake_path[k - 1][1]);
            double arc = a.boat.wake_along[k - 1] - a.boat.wake_along[k];
            CHECK(arc >= chord - 1e-9 && arc <= 1.08 * chord);
        }
    }
    tl_timeline_free(&tl);
}

/* A boat under way in the first frame was under way before it: before the
 * path's first point (at 0 s) its wake continues back along its first
 * velocity, and the distance along the path goes negative there, keeping
 * a place's value from frame to frame. A path that starts later holds its
 * boat still before the start, and its wake with it. */
static void test_wake_before_start(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\npath boat constant-speed\n  0s 0 0\n  10s 0 50\n", &tl))
        return;
    tl_scene s, later;
    tl_timeline_eval(&tl, 0.0, &s);
    tl_timeline_eval(&tl, 2.0 * s.boat.wake_step, &later);
    CHECK(s.boat.wake_step > 0.0);
    double worst = 0.0;
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        double back = 5.0 * k * s.boat.wake_step; /* 5 m/s */
        worst = fmax(worst, fabs(s.boat.wake_path[k][0]));
        worst = fmax(worst, fabs(s.boat.wake_path[k][1] + back));
        worst = fmax(worst, fabs(s.boat.wake_along[k] + back));
        if (k + 2 < TL_WAKE_POINTS) { /* a place keeps its distance */
            worst = fmax(worst, fabs(later.boat.wake_along[k + 2] - s.boat.wake_along[k]));
            worst = fmax(worst, fabs(later.boat.wake_path[k + 2][1] - s.boat.wake_path[k][1]));
        }
    }
    printf("wake before the path's start: worst error %.3g m over %d points\n", worst,
           TL_WAKE_POINTS);
    CHECK(worst < 1e-3);
    tl_timeline_free(&tl);

    if (!parse_ok("tideline 1\npath boat constant-speed\n  2s 0 0\n  12s 0 50\n", &tl))
        return;
    tl_timeline_eval(&tl, 3.0, &s);
    int held = 0, before = 0;
    for (int k = 0; k < TL_WAKE_POINTS; k++)
        if (3.0 - k * s.boat.wake_step < 2.0) {
            before++;
            held += s.boat.wake_path[k][0] == 0.0 && s.boat.wake_path[k][1] == 0.0 &&
                    s.boat.wake_along[k] == 0.0;
        }
    CHECK(before > 10);
    CHECK(held == before);
    tl_timeline_free(&tl);
}

/* `follow giant.center boat` aims the wave: along its travel the centre
 * is where the boat (plus the offset) is at giant.arrival, fixed; across
 * it, the centre line is where the boat is now. `angle` the travel's
 * compass direction, `arrival` the arrival time; `off` the link's
 * offset (x, z). */
static void check_aimed(const tl_timeline *tl, double angle, double arrival, const double off[2])
{
    tl_scene then;
    tl_timeline_eval(tl, arrival, &then);
    const double dir[2] = {sin(angle), cos(angle)}, across[2] = {cos(angle), -sin(angle)};
    const double at[2] = {then.boat.position[0] + off[0], then.boat.position[2] + off[1]};
    for (int i = 0; i <= 40; i++) {
        tl_scene s;
        tl_timeline_eval(tl, i * 0.25, &s);
        const double now[2] = {s.boat.position[0] + off[0], s.boat.position[2] + off[1]};
        const double *c = s.giant.center;
        CHECK_NEAR(dir[0] * (c[0] - at[0]) + dir[1] * (c[1] - at[1]), 0.0, 1e-9);
        CHECK_NEAR(across[0] * (c[0] - now[0]) + across[1] * (c[1] - now[1]), 0.0, 1e-9);
    }
}

static void test_follow_boat(void)
{
    char text[1024];
    snprintf(text, sizeof text,
             "tideline 1\n%sfollow camera boat + 0 3 -10\nlook camera at boat + 0 1.5 0\n"
             "follow giant.center boat + 5 -3\n",
             boat_path);
    tl_timeline tl;
    if (!parse_ok(text, &tl))
        return;
    for (int i = 0; i <= 40; i++) {
        double t = i * 0.25;
        tl_scene s, arrival;
        tl_timeline_eval(&tl, t, &s);
        tl_timeline_eval(&tl, 0.0, &arrival); /* giant.arrival 0, travel +Z (angle 0) */
        const double *b = s.boat.position;
        CHECK(s.boat.enabled);
        CHECK_NEAR(s.camera.position[0], b[0], 1e-12);
        CHECK_NEAR(s.camera.position[1], b[1] + 3.0, 1e-12);
        CHECK_NEAR(s.camera.position[2], b[2] - 10.0, 1e-12);
        /* Travelling +Z: across is x, the boat's now; along is z, the
         * boat's at the arrival (0 s: the path's first point, z 20). */
        CHECK_NEAR(s.giant.center[0], b[0] + 5.0, 1e-12);
        CHECK_NEAR(s.giant.center[1], 20.0 - 3.0, 1e-12);
        CHECK_NEAR(s.giant.center[1], arrival.boat.position[2] - 3.0, 1e-12);
        /* Looking 1.5 m below its own height, 10 m ahead (+Z): yaw 0,
         * pitch atan(-1.5 / 10). */
        CHECK_NEAR(s.camera.yaw, 0.0, 1e-12);
        CHECK_NEAR(s.camera.pitch, atan2(-1.5, 10.0), 1e-12);
    }
    tl_timeline_free(&tl);

    snprintf(text, sizeof text, "tideline 1\n%sfollow giant.center boat\n", boat_path);
    if (!parse_ok(text, &tl))
        return;
    for (int i = 0; i <= 10; i++) {
        tl_scene s;
        tl_timeline_eval(&tl, i, &s);
        CHECK(s.giant.center[0] == s.boat.position[0]);
        CHECK(s.giant.center[1] == 20.0);
    }
    /* At the ends of the path: across (x) its first and last points'; along
     * (z) the first point's, where the boat is at giant.arrival = 0. */
    CHECK_NEAR(at(&tl, 0.0, "giant.center", 0), 10.0, 1e-9);
    CHECK_NEAR(at(&tl, 0.0, "giant.center", 1), 20.0, 1e-9);
    CHECK_NEAR(at(&tl, 10.0, "giant.center", 0), 0.0, 1e-9);
    CHECK_NEAR(at(&tl, 10.0, "giant.center", 1), 20.0, 1e-9);
    tl_timeline_free(&tl);

    /* Travelling at an angle and arriving mid-path (4 s), with an offset:
     * the centre's part along the travel stays the boat's at the arrival;
     * across, the boat's now. At the arrival both are the boat's, so the
     * centre is the boat plus the offset. */
    snprintf(text, sizeof text,
             "tideline 1\n%sset giant.angle 30deg\nset giant.arrival 4s\n"
             "follow giant.center boat + 5 -3\n",
             boat_path);
    if (!parse_ok(text, &tl))
        return;
    const double off[2] = {5.0, -3.0};
    check_aimed(&tl, 30.0 * M_PI / 180.0, 4.0, off);
    tl_scene s;
    tl_timeline_eval(&tl, 4.0, &s);
    CHECK_NEAR(s.giant.center[0], s.boat.position[0] + 5.0, 1e-9);
    CHECK_NEAR(s.giant.center[1], s.boat.position[2] - 3.0, 1e-9);
    /* Not the boat's position before or after it: the wave is aimed, not
     * carried. */
    tl_timeline_eval(&tl, 8.0, &s);
    CHECK(hypot(s.giant.center[0] - s.boat.position[0] - 5.0,
                s.giant.center[1] - s.boat.position[2] + 3.0) > 1.0);
    tl_timeline_free(&tl);
}

static void check_heading(const char *points, double expected)
{
    char text[512];
    snprintf(text, sizeof text, "tideline 1\npath boat\n%s", points);
    tl_timeline tl;
    if (!parse_ok(text, &tl))
        return;
    for (int i = 0; i <= 10; i++) {
        tl_scene s;
        tl_timeline_eval(&tl, i, &s);
        CHECK_NEAR(wrapped(s.boat.heading - expected), 0.0, 1e-12);
    }
    tl_timeline_free(&tl);
}

static void test_boat_heading_and_float(void)
{
    check_heading("  0s 0 0\n  10s 0 100\n", 0.0);         /* +Z */
    check_heading("  0s 0 0\n  10s 100 0\n", M_PI / 2.0);  /* +X */
    check_heading("  0s 0 0\n  10s 50 50\n", M_PI / 4.0);  /* north-east */
    check_heading("  0s 0 0\n  10s 0 -100\n", M_PI);       /* -Z */
    check_heading("  0s 5 5\n  10s -45 5\n", -M_PI / 2.0); /* -X */

    /* A set heading overrides the tangent. */
    tl_timeline tl;
    if (!parse_ok("tideline 1\npath boat\n  0s 0 0\n  10s 100 0\nset boat.heading 30\n", &tl))
        return;
    CHECK_NEAR(at(&tl, 5.0, "boat.heading", 0), 30.0 * TL_DEG, 1e-15);
    tl_timeline_free(&tl);

    /* Floating on a still sea (no wave moves, the boat rests): the spring
     * has settled, so the pose is the hull's five samples exactly, with the
     * march octaves of the quality (draft: 8, then 5). */
    const char *texts[2] = {
        "tideline 1\nquality draft\nset ocean.depth 2\nset ocean.speed 0\n"
        "path boat\n  0s 3 -4\n  5s 3.0001 -4\n",
        "tideline 1\nquality draft\nset quality.march_octaves 5\nset ocean.depth 2\n"
        "set ocean.speed 0\npath boat\n  0s 3 -4\n  5s 3.0001 -4\n"};
    const int octaves[2] = {8, 5};
    for (int k = 0; k < 2; k++) {
        if (!parse_ok(texts[k], &tl))
            continue;
        tl_scene s;
        tl_timeline_eval(&tl, 30.0, &s); /* long after the boat stopped */
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        const double *b = s.boat.position;
        double fx = sin(s.boat.heading), fz = cos(s.boat.heading);
        double a = 0.4 * s.boat.length, c = 0.5 * s.boat.beam;
        double hc = tl_waves_height(&w, b[0], b[2], 30.0, octaves[k]);
        double hb = tl_waves_height(&w, b[0] + fx * a, b[2] + fz * a, 30.0, octaves[k]);
        double hs = tl_waves_height(&w, b[0] - fx * a, b[2] - fz * a, 30.0, octaves[k]);
        double hr = tl_waves_height(&w, b[0] + fz * c, b[2] - fx * c, 30.0, octaves[k]);
        double hp = tl_waves_height(&w, b[0] - fz * c, b[2] + fx * c, 30.0, octaves[k]);
        CHECK_NEAR(b[1], (hc + hb + hs + hr + hp) / 5.0, 1e-9);
        CHECK_NEAR(s.boat.pitch, atan2(hb - hs, 2.0 * a), 1e-9);
        CHECK_NEAR(s.boat.roll, atan2(hp - hr, 2.0 * c), 1e-9);
        CHECK_NEAR(s.boat.length, 8.0, 0.0);
        CHECK_NEAR(s.boat.beam, 8.0 * TL_BOAT_BEAM_RATIO, 1e-12);
        /* The octave count matters, so the check above can tell. */
        CHECK(fabs(hc - tl_waves_height(&w, b[0], b[2], 30.0, 12)) > 1e-6);
        tl_timeline_free(&tl);
    }

    /* On the moving default sea: finite, within the wave band, pure
     * (the same t gives the same pose whatever was evaluated before), and
     * smooth from frame to frame. */
    if (!parse_ok("tideline 1\npath boat\n  0s 0 0\n  10s 0 60\n", &tl))
        return;
    double prev_pitch = 0.0, prev_roll = 0.0, worst = 0.0;
    int sane = 1;
    for (int f = 0; f <= 240; f++) {
        tl_scene s, again;
        tl_timeline_eval(&tl, f / 24.0, &s);
        sane &= isfinite(s.boat.position[1]) && s.boat.position[1] <= 0.0 &&
                s.boat.position[1] >= -1.0 && fabs(s.boat.pitch) < 0.5 && fabs(s.boat.roll) < 0.5;
        if (f > 0)
            worst =
                fmax(worst, fmax(fabs(s.boat.pitch - prev_pitch), fabs(s.boat.roll - prev_roll)));
        prev_pitch = s.boat.pitch;
        prev_roll = s.boat.roll;
        tl_timeline_eval(&tl, 3.0, &again);
        tl_timeline_eval(&tl, f / 24.0, &again);
        sane &= memcmp(&again.boat, &s.boat, sizeof s.boat) == 0;
    }
    printf("floating on the default sea: largest pitch/roll change between frames %.3g deg\n",
           worst / TL_DEG);
    CHECK(sane);
    CHECK(worst < 1.0 * TL_DEG);
    tl_timeline_free(&tl);
}

/* Boat speed in the water plane, by central differences. */
static double boat_speed(const tl_timeline *tl, double t)
{
    const double h = 1e-4;
    tl_scene a, b;
    tl_timeline_eval(tl, t - h, &a);
    tl_timeline_eval(tl, t + h, &b);
    return hypot(b.boat.position[0] - a.boat.position[0], b.boat.position[2] - a.boat.position[2]) /
           (2.0 * h);
}

static void test_constant_speed(void)
{
    const char *points = "  0s 0 0\n  1s 2 1\n  2s 40 5\n  7s 45 60\n  10s 80 62\n";
    char text[512];
    for (int constant = 1; constant >= 0; constant--) {
        snprintf(text, sizeof text, "tideline 1\npath boat%s\n%s",
                 constant ? " constant-speed" : "", points);
        tl_timeline tl;
        if (!parse_ok(text, &tl))
            return;
        double lo = INFINITY, hi = 0.0, sum = 0.0;
        int n = 0;
        for (double t = 0.5; t <= 9.5; t += 0.05, n++) {
            double v = boat_speed(&tl, t);
            lo = fmin(lo, v);
            hi = fmax(hi, v);
            sum += v;
        }
        double mean = sum / n;
        if (constant) {
            CHECK((hi - lo) / mean < 0.01);
            /* The whole length in the path's 10 s. */
            CHECK_NEAR(mean, tl.objects[0].path.path.length / 10.0, 0.01 * mean);
            if (!((hi - lo) / mean < 0.01))
                fprintf(stderr, "  constant speed: %g .. %g m/s\n", lo, hi);
        } else {
            /* Timed points this uneven vary far more: the test can tell. */
            CHECK((hi - lo) / mean > 0.5);
        }
        tl_timeline_free(&tl);
    }
}

/* Yaw and pitch of a camera aimed at a boat over every frame: no step
 * larger than 10 degrees between frames (angles compared modulo a turn). */
static void check_no_flip(const char *label, const char *text)
{
    tl_timeline tl;
    if (!parse_ok(text, &tl))
        return;
    long frames = tl_timeline_frame_count(&tl);
    double worst_yaw = 0.0, worst_pitch = 0.0, worst_fwd = 0.0, prev_f[3] = {0, 0, 0};
    tl_scene prev;
    for (long i = 0; i <= frames; i++) {
        tl_scene s;
        tl_timeline_eval(&tl, tl_timeline_frame_time(&tl, i), &s);
        double r[3], u[3], f[3];
        tl_scene_camera_basis(&s.camera, r, u, f);
        CHECK(isfinite(s.camera.yaw) && isfinite(s.camera.pitch));
        if (i > 0) {
            worst_yaw = fmax(worst_yaw, fabs(wrapped(s.camera.yaw - prev.camera.yaw)));
            worst_pitch = fmax(worst_pitch, fabs(s.camera.pitch - prev.camera.pitch));
            worst_fwd = fmax(worst_fwd, angle_between(f, prev_f));
        }
        prev = s;
        memcpy(prev_f, f, sizeof prev_f);
    }
    CHECK(worst_yaw < 10.0 * TL_DEG);
    CHECK(worst_pitch < 10.0 * TL_DEG);
    CHECK(worst_fwd < 10.0 * TL_DEG);
    if (!(worst_yaw < 10.0 * TL_DEG && worst_pitch < 10.0 * TL_DEG))
        fprintf(stderr, "  %s: largest step yaw %.3g deg, pitch %.3g deg\n", label,
                worst_yaw / TL_DEG, worst_pitch / TL_DEG);
    tl_timeline_free(&tl);
}

static void test_orientation_never_flips(void)
{
    /* Nearly beneath: 20 m up, the boat passes 5 m to the side at 10 m/s. */
    check_no_flip("beneath", "tideline 1\nfps 24\nduration 20s\nset camera.position 0 20 0\n"
                             "path boat\n  0s 5 -100\n  20s 5 100\n"
                             "look camera at boat\n");
    /* Behind the camera: yaw passes +-180 deg. */
    check_no_flip("behind", "tideline 1\nfps 24\nduration 20s\nset camera.position 0 2 0\n"
                            "path boat\n  0s -60 -8\n  20s 60 -8\n"
                            "look camera at boat + 0 1.5 0\n");
    /* All the way round. */
    check_no_flip("circle", "tideline 1\nfps 24\nduration 20s\nset camera.position 0 3 0\n"
                            "path boat\n  0s 30 0\n  5s 0 30\n  10s -30 0\n  15s 0 -30\n"
                            "  20s 30 0\nlook camera at boat\n");
}

static void test_large_times(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\n"
                  "key render.exposure linear\n  1000000s 1\n  1000000.000001s 3\n"
                  "key sun.intensity\n  1000000s 100\n  1000000.000001s 300\n"
                  "key camera.yaw linear shortest\n  1000000s 170deg\n  1000000.000001s -170deg\n"
                  "path boat constant-speed\n  1000000s 0 0\n  1000000.000001s 0 0.001\n",
                  &tl))
        return;
    /* Double resolution at 1e6 s is ~1.2e-10 s, 1e-4 of the key spacing. */
    CHECK(at(&tl, 0.0, "render.exposure", 0) == 1.0);
    CHECK(at(&tl, 999999.0, "render.exposure", 0) == 1.0);
    CHECK(at(&tl, 1e6, "render.exposure", 0) == 1.0);
    CHECK_NEAR(at(&tl, 1e6 + 5e-7, "render.exposure", 0), 2.0, 1e-3);
    CHECK_NEAR(at(&tl, 1e6 + 5e-7, "sun.intensity", 0), 200.0, 0.1);
    CHECK_NEAR(cos(at(&tl, 1e6 + 5e-7, "camera.yaw", 0)), -1.0, 1e-6);
    CHECK(at(&tl, 2e6, "render.exposure", 0) == 3.0);
    for (int i = 0; i <= 1000; i++) {
        double t = 1e6 * i / 1000.0;
        tl_scene s;
        tl_timeline_eval(&tl, t, &s);
        for (int k = 0; k < tl_channel_count(); k++) {
            double v[3];
            tl_channel_get(tl_channel_at(k), &s, v);
            CHECK(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]));
        }
        CHECK(isfinite(s.boat.position[0]) && isfinite(s.boat.position[1]) &&
              isfinite(s.boat.position[2]) && isfinite(s.boat.heading));
        CHECK(s.boat.position[2] >= 0.0 && s.boat.position[2] <= 0.001);
    }
    tl_timeline_free(&tl);
}

static tl_timeline_features features(const char *text)
{
    tl_timeline_features f = {true, true, true, true, 1};
    tl_timeline tl;
    if (!parse_ok(text, &tl))
        return f;
    tl_timeline_features_of(&tl, &f);
    tl_timeline_free(&tl);
    return f;
}

static const char calm[] = "tideline 1\nfps 24\nduration 10s\nsize 1280x720\nquality final\n"
                           "set ocean.drag 0.3\nset ocean.depth 0.8\nset render.exposure 2.2\n"
                           "key sun.elevation\n  0s    2deg\n  10s   9deg    ease-in-out-sine\n"
                           "set sun.azimuth -10deg\n"
                           "key camera.position\n  0s    0 1.8 0\n  10s   0 2.1 6\n"
                           "key camera.yaw shortest\n  0s    -35deg\n  10s   -8deg\n"
                           "key camera.pitch\n  0s    -4deg\n  10s   -2deg\n";

static void test_features(void)
{
    tl_timeline_features f = features(calm);
    CHECK(!f.boat && !f.giant_wave && !f.fog && !f.underwater);

    f = features("tideline 1\npath boat\n  0s 0 0\n  10s 0 50\n");
    CHECK(f.boat && !f.giant_wave && !f.fog && !f.underwater);

    f = features("tideline 1\nset giant.enabled on\nset camera.position 0 20 -200\n");
    CHECK(f.giant_wave && !f.boat && !f.fog && !f.underwater);
    /* A camera lower than the giant wave's crest may be under it. */
    f = features("tideline 1\nset giant.enabled on\nset camera.position 0 5 -200\n");
    CHECK(f.giant_wave && f.underwater);
    /* Enabled but faded out for the whole timeline: nothing to draw. */
    f = features("tideline 1\nset giant.enabled on\nset giant.fade 0\n");
    CHECK(!f.giant_wave);

    f = features("tideline 1\nset fog.density 0.02\n");
    CHECK(f.fog && !f.boat && !f.giant_wave && !f.underwater);
    f = features("tideline 1\nkey fog.density linear\n  0s 0\n  10s 0\n");
    CHECK(!f.fog);
    f = features("tideline 1\nkey fog.density linear\n  0s 0\n  5s 0\n  10s 0.1\n");
    CHECK(f.fog);

    /* Auto: under water once the camera goes below y = 0. */
    f = features("tideline 1\nkey camera.position linear\n  0s 0 2 0\n  10s 0 -1 0\n");
    CHECK(f.underwater && !f.fog && !f.boat && !f.giant_wave);
    f = features("tideline 1\nkey camera.position linear\n  0s 0 2 0\n  10s 0 0.5 0\n");
    CHECK(!f.underwater);
    f = features("tideline 1\nset underwater.mode off\n"
                 "key camera.position linear\n  0s 0 2 0\n  10s 0 -1 0\n");
    CHECK(!f.underwater);
    f = features("tideline 1\nset underwater.mode on\n");
    CHECK(f.underwater && !f.fog && !f.boat && !f.giant_wave);
}

static void test_frames(void)
{
    tl_timeline tl;
    if (!parse_ok("tideline 1\nfps 24\nduration 10s\n", &tl))
        return;
    CHECK(tl_timeline_frame_count(&tl) == 240);
    CHECK(tl_timeline_frame_time(&tl, 0) == 0.0);
    CHECK(tl_timeline_frame_time(&tl, 240) == 10.0);
    CHECK(tl_timeline_frame_time(&tl, 1000001) == 1000001.0 / 24.0);
    CHECK(tl_timeline_frame_time(&tl, 36) == 1.5);
    tl_timeline_free(&tl);

    if (!parse_ok("tideline 1\nfps 29.97\nduration 10s\n", &tl))
        return;
    CHECK(tl_timeline_frame_count(&tl) == 300); /* 299.7 rounds to 300 */
    CHECK(tl_timeline_frame_time(&tl, 1000001) == 1000001.0 / 29.97);
    tl_timeline_free(&tl);

    if (!parse_ok("tideline 1\nfps 24\nduration 240f\n", &tl))
        return;
    CHECK_NEAR(tl.duration, 10.0, 1e-12);
    CHECK(tl_timeline_frame_count(&tl) == 240);
    tl_timeline_free(&tl);

    if (!parse_ok("tideline 1\nduration 10ms\n", &tl))
        return;
    CHECK(tl_timeline_frame_count(&tl) == 1); /* never zero frames */
    tl_timeline_free(&tl);
}

/* set boat.model: relative to the timeline's folder, absolute as given;
 * the model's bounds set the hull's length and beam (model_yaw turns it,
 * model_scale sizes it). */
static void test_boat_model(void)
{
    const char *text =
        "tideline 1\npath boat\n  0s 0 0\n  5s 0 20\nset boat.model boats/skiff.glb\n"
        "set boat.model_scale 2\nset boat.model_yaw 90deg\n";
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    tl_timeline tl;
    CHECK(tl_timeline_parse_text("shots/sea/a.tl", text, strlen(text), &tl, &diags, &err) == 0);
    CHECK(strcmp(tl.objects[0].model, "shots/sea/boats/skiff.glb") == 0);
    CHECK(tl.objects[0].model_line == 5 && tl.objects[0].model_column == 16);
    const float lo[3] = {-1.0f, 0.0f, -3.0f}, hi[3] = {1.0f, 2.0f, 3.0f};
    tl_timeline_set_object_model(&tl, 0, 0, lo, hi);
    tl_scene s;
    tl_timeline_eval(&tl, 1.0, &s);
    CHECK_NEAR(s.boat.scale, 2.0, 0.0);
    CHECK_NEAR(s.boat.length, 4.0, 1e-12); /* turned 90 deg: its 2-unit width lies along */
    CHECK_NEAR(s.boat.beam, 12.0, 1e-12);
    tl_timeline_free(&tl);
    const char *abs_text = "tideline 1\npath boat\n  0s 0 0\n  5s 0 20\nset boat.model /m/x.obj\n";
    CHECK(parse_ok(abs_text, &tl));
    CHECK(strcmp(tl.objects[0].model, "/m/x.obj") == 0);
    tl_timeline_free(&tl);
    /* Without a model: the built-in boat, boat.size long. */
    CHECK(parse_ok("tideline 1\npath boat\n  0s 0 0\n  5s 0 20\nset boat.size 12\n", &tl));
    tl_timeline_eval(&tl, 1.0, &s);
    CHECK_NEAR(s.boat.length, 12.0, 1e-12);
    CHECK_NEAR(s.boat.beam, 12.0 * TL_BOAT_BEAM_RATIO, 1e-9);
    tl_timeline_free(&tl);
}

/* A camera as Blender gives it: its Euler orders, quaternion and axis
 * angle turned into yaw, pitch and roll, with hand-worked cases (Blender's
 * camera looks along its -Z: turned 90 deg about X it looks north, then
 * about Z toward the west), and its lens by the sensor's fit. The Blender
 * round trip (test_blender_export.sh) checks every mode against Blender. */
static void test_blender_camera(void)
{
    tl_timeline tl;
    tl_scene s;
    if (parse_ok("tideline 1\nsize 1280x720\nset camera.rotation_mode xyz\n"
                 "set camera.rotation 90deg 0 30deg\nset camera.focal_length 50\n",
                 &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.yaw, -30.0 * TL_DEG, 1e-12);
        CHECK_NEAR(s.camera.pitch, 0.0, 1e-12);
        CHECK_NEAR(s.camera.roll, 0.0, 1e-12);
        /* 36 mm across 1280 px at 50 mm: tan(v / 2) = 18 / 50 * 720 / 1280 */
        CHECK_NEAR(s.camera.vfov, 2.0 * atan(18.0 / 50.0 * 720.0 / 1280.0), 1e-12);
        tl_timeline_free(&tl);
    }
    /* The same turn in the other order (Z first) is another view: ZYX
     * with X 90 deg, Z 30 deg rolls the camera instead. */
    if (parse_ok("tideline 1\nset camera.rotation_mode zyx\nset camera.rotation 90deg 0 30deg\n",
                 &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.yaw, 0.0, 1e-12);
        CHECK_NEAR(s.camera.pitch, 0.0, 1e-12);
        CHECK_NEAR(s.camera.roll, 30.0 * TL_DEG, 1e-12);
        tl_timeline_free(&tl);
    }
    /* No rotation: looking straight down, north at the top of the frame. */
    if (parse_ok("tideline 1\nset camera.rotation_mode quaternion\n", &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.pitch, -90.0 * TL_DEG, 1e-12);
        double right[3], up[3], forward[3];
        tl_scene_camera_basis(&s.camera, right, up, forward);
        CHECK_NEAR(up[2], 1.0, 1e-12);
        CHECK_NEAR(right[0], 1.0, 1e-12);
        tl_timeline_free(&tl);
    }
    /* A quaternion is normalised; an axis-angle turn equals it. */
    if (parse_ok("tideline 1\nset camera.rotation_mode quaternion\nset camera.quaternion_w 2\n"
                 "set camera.quaternion 2 0 0\n",
                 &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.pitch, 0.0, 1e-12);
        CHECK_NEAR(s.camera.yaw, 0.0, 1e-12);
        tl_timeline_free(&tl);
    }
    if (parse_ok("tideline 1\nset camera.rotation_mode axis_angle\nset camera.axis_angle 90deg\n"
                 "set camera.axis 5 0 0\n",
                 &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.pitch, 0.0, 1e-12);
        CHECK_NEAR(s.camera.yaw, 0.0, 1e-12);
        tl_timeline_free(&tl);
    }
    /* Blender's degenerate cases: a zero quaternion normalises to (0, 1, 0,
     * 0), half a turn about X (looking straight up); a zero axis turns
     * nothing (looking straight down). */
    if (parse_ok("tideline 1\nset camera.rotation_mode quaternion\nset camera.quaternion_w 0\n",
                 &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.pitch, 90.0 * TL_DEG, 1e-12);
        tl_timeline_free(&tl);
    }
    if (parse_ok("tideline 1\nset camera.rotation_mode axis_angle\nset camera.axis_angle 40deg\n"
                 "set camera.axis 0 0 0\n",
                 &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.pitch, -90.0 * TL_DEG, 1e-12);
        tl_timeline_free(&tl);
    }
    /* A tall frame: auto fits the width's value down the frame; vertical
     * the sensor's height. */
    if (parse_ok("tideline 1\nsize 720x1280\nset camera.focal_length 50\n", &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.vfov, 2.0 * atan(18.0 / 50.0), 1e-12);
        tl_timeline_free(&tl);
    }
    if (parse_ok("tideline 1\nset camera.focal_length 50\nset camera.sensor_fit vertical\n"
                 "set camera.sensor_height 20\n",
                 &tl)) {
        tl_timeline_eval(&tl, 0.0, &s);
        CHECK_NEAR(s.camera.vfov, 2.0 * atan(10.0 / 50.0), 1e-12);
        tl_timeline_free(&tl);
    }
    /* Control bytes in comments (a terminal's colour codes pasted in) do
     * not make a timeline binary. */
    if (parse_ok("tideline 1\n# \x1b[1mbold\x1b[0m \x1b[2m\x1b[3m\x1b[4m\nset camera.fov 50\n",
                 &tl))
        tl_timeline_free(&tl);
    /* `baked` is kept for check, and changes nothing else. */
    if (parse_ok("tideline 1\nkey camera.fov linear baked\n  0f 50deg\n  1f 51deg\n", &tl)) {
        const tl_track *tr = &tl.tracks[tl_channel_index(tl_channel_find("camera.fov"))];
        CHECK(tr->baked && tr->state == TL_TRACK_KEYED);
        tl_timeline_free(&tl);
    }
}

int main(int argc, char **argv)
{
    if (!tl_fixture_load(argc > 1 ? argv[1] : NULL))
        TEST_END();
    test_time_units();
    test_angle_and_length_units();
    test_default_set_key();
    test_extrapolation();
    test_blender_options();
    test_blender_camera();
    test_shortest();
    test_cuts();
    test_look_at_boat();
    test_wake_along();
    test_wake_before_start();
    test_follow_boat();
    test_boat_heading_and_float();
    test_constant_speed();
    test_orientation_never_flips();
    test_large_times();
    test_features();
    test_frames();
    test_boat_model();
    TEST_END();
}
