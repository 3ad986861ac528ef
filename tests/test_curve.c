/* Keyframe engine tests: easing, interpolation, Bezier handles and
 * segments (their ends, cuts and limits in test_curve_ends.c). Expected
 * values are derived by hand (closed forms), by an independent method
 * (dense sampling of the Bezier cubic), or read from the fixture
 * tests/fixtures/curve_reference.txt (argv[1]) that
 * tests/blender_curve_ref.py writes from Blender's formulas; never by
 * calling the code under test. After changing the script, regenerate the
 * fixture from the repository root:
 *     python3 tests/blender_curve_ref.py > tests/fixtures/curve_reference.txt */
#include "timeline/tl_ease.h"
#include "tl_curve_test.h"
#include "tl_fixture.h"

#include <float.h>
#include <stdlib.h>

/* ---- easing ------------------------------------------------------------- */

static void test_ease(void)
{
    for (int f = 0; f < TL_EASE_FAMILY_COUNT; f++) {
        for (int d = 0; d < TL_EASE_DIR_COUNT; d++) {
            CHECK_NEAR(tl_ease(f, d, 0.0), 0.0, 1e-15);
            CHECK_NEAR(tl_ease(f, d, 1.0), 1.0, 1e-15);
            CHECK_NEAR(tl_ease(f, d, -3.0), 0.0, 1e-15); /* clamped */
            CHECK_NEAR(tl_ease(f, d, 7.0), 1.0, 1e-15);
        }
    }
    const double r2 = sqrt(2.0), r3 = sqrt(3.0);
    struct {
        tl_ease_family f;
        tl_ease_dir d;
        double u, want;
    } cases[] = {
        {TL_EASE_SINE, TL_EASE_IN, 0.5, 1 - r2 / 2},
        {TL_EASE_SINE, TL_EASE_IN, 0.25, 1 - sqrt(2 + r2) / 2}, /* cos(pi/8) */
        {TL_EASE_SINE, TL_EASE_OUT, 0.5, r2 / 2},
        {TL_EASE_SINE, TL_EASE_OUT, 0.25, sqrt(2 - r2) / 2}, /* sin(pi/8) */
        {TL_EASE_SINE, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_SINE, TL_EASE_IN_OUT, 0.25, (1 - r2 / 2) / 2},
        {TL_EASE_QUAD, TL_EASE_IN, 0.5, 0.25},
        {TL_EASE_QUAD, TL_EASE_IN, 0.25, 1.0 / 16},
        {TL_EASE_QUAD, TL_EASE_OUT, 0.5, 0.75},
        {TL_EASE_QUAD, TL_EASE_OUT, 0.25, 7.0 / 16},
        {TL_EASE_QUAD, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_QUAD, TL_EASE_IN_OUT, 0.25, 0.125},
        {TL_EASE_QUAD, TL_EASE_IN_OUT, 0.75, 0.875},
        {TL_EASE_CUBIC, TL_EASE_IN, 0.5, 0.125},
        {TL_EASE_CUBIC, TL_EASE_IN, 0.25, 1.0 / 64},
        {TL_EASE_CUBIC, TL_EASE_OUT, 0.5, 0.875},
        {TL_EASE_CUBIC, TL_EASE_OUT, 0.25, 37.0 / 64},
        {TL_EASE_CUBIC, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_CUBIC, TL_EASE_IN_OUT, 0.25, 1.0 / 16},
        {TL_EASE_CUBIC, TL_EASE_IN_OUT, 0.75, 15.0 / 16},
        {TL_EASE_QUART, TL_EASE_IN, 0.5, 1.0 / 16},
        {TL_EASE_QUART, TL_EASE_IN, 0.25, 1.0 / 256},
        {TL_EASE_QUART, TL_EASE_OUT, 0.5, 15.0 / 16},
        {TL_EASE_QUART, TL_EASE_OUT, 0.25, 175.0 / 256},
        {TL_EASE_QUART, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_QUART, TL_EASE_IN_OUT, 0.25, 1.0 / 32},
        {TL_EASE_QUART, TL_EASE_IN_OUT, 0.75, 31.0 / 32},
        {TL_EASE_QUINT, TL_EASE_IN, 0.5, 1.0 / 32},
        {TL_EASE_QUINT, TL_EASE_IN, 0.25, 1.0 / 1024},
        {TL_EASE_QUINT, TL_EASE_OUT, 0.5, 31.0 / 32},
        {TL_EASE_QUINT, TL_EASE_OUT, 0.25, 781.0 / 1024},
        {TL_EASE_QUINT, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_QUINT, TL_EASE_IN_OUT, 0.25, 1.0 / 64},
        {TL_EASE_QUINT, TL_EASE_IN_OUT, 0.75, 63.0 / 64},
        /* expo, Blender's rescaled form (2^(10(u-1)) - 2^-10) / (1 - 2^-10):
         * in(1/2) = (2^-5 - 2^-10) / (1 - 2^-10) = 31/1023 (Penner: 1/32). */
        {TL_EASE_EXPO, TL_EASE_IN, 0.5, 31.0 / 1023},
        {TL_EASE_EXPO, TL_EASE_IN, 0.25, (4 * r2 - 1) / 1023}, /* 2^-7.5 rescaled */
        {TL_EASE_EXPO, TL_EASE_OUT, 0.5, 992.0 / 1023},
        {TL_EASE_EXPO, TL_EASE_OUT, 0.25, 1 - (128 * r2 - 1) / 1023}, /* 2^-2.5 rescaled */
        {TL_EASE_EXPO, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_EXPO, TL_EASE_IN_OUT, 0.25, 15.5 / 1023},
        {TL_EASE_EXPO, TL_EASE_IN_OUT, 0.75, 1 - 15.5 / 1023},
        /* continuous at the ends: 2^-30 in, not the 2^-10 jump of Penner's */
        {TL_EASE_EXPO, TL_EASE_IN, 1e-3, (pow(2, -9.99) - 1.0 / 1024) / (1023.0 / 1024)},
        {TL_EASE_CIRC, TL_EASE_IN, 0.5, 1 - r3 / 2},
        {TL_EASE_CIRC, TL_EASE_IN, 0.25, 1 - sqrt(15.0) / 4},
        {TL_EASE_CIRC, TL_EASE_OUT, 0.5, r3 / 2},
        {TL_EASE_CIRC, TL_EASE_OUT, 0.25, sqrt(7.0) / 4},
        {TL_EASE_CIRC, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_CIRC, TL_EASE_IN_OUT, 0.25, (1 - r3 / 2) / 2},
        /* back, s = 1.70158: in(0.5) = 0.25 (1.5 s + 0.5 - s)... */
        {TL_EASE_BACK, TL_EASE_IN, 0.5, 0.25 * (0.5 * 2.70158 - 1.70158)},
        {TL_EASE_BACK, TL_EASE_OUT, 0.5, 1 - 0.25 * (0.5 * 2.70158 - 1.70158)},
        {TL_EASE_BACK, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_BACK, TL_EASE_IN_OUT, 0.25, -0.09968184375}, /* s' = 1.525 s */
        /* bounce: out(0.5) = 7.5625 (1/22)^2 + 0.75 = 49/64 */
        {TL_EASE_BOUNCE, TL_EASE_OUT, 0.5, 49.0 / 64},
        {TL_EASE_BOUNCE, TL_EASE_OUT, 0.25, 0.47265625},
        {TL_EASE_BOUNCE, TL_EASE_IN, 0.5, 15.0 / 64},
        {TL_EASE_BOUNCE, TL_EASE_IN, 0.25, 0.02734375}, /* 1 - (9/256 + 15/16) */
        {TL_EASE_BOUNCE, TL_EASE_IN_OUT, 0.5, 0.5},
        {TL_EASE_BOUNCE, TL_EASE_IN_OUT, 0.25, 0.1171875},
        {TL_EASE_BOUNCE, TL_EASE_IN_OUT, 0.75, 0.8828125},
        /* elastic, p = 0.3: in(0.5) = -2^-5 sin(-23 pi / 6) = -1/64 */
        {TL_EASE_ELASTIC, TL_EASE_IN, 0.5, -1.0 / 64},
        {TL_EASE_ELASTIC, TL_EASE_IN, 0.25, -1.0 / (128 * r2)},   /* sin(-11 pi / 2) = 1 */
        {TL_EASE_ELASTIC, TL_EASE_OUT, 0.5, 1 + 1.0 / 64},        /* sin(17 pi / 6) = 1/2 */
        {TL_EASE_ELASTIC, TL_EASE_OUT, 0.25, 1 - 0.5 / (4 * r2)}, /* sin(7 pi / 6) */
        {TL_EASE_ELASTIC, TL_EASE_IN_OUT, 0.5, 0.5},
        /* p = 0.45: -0.5 * 2^-5 * sin(-49 pi / 18) = sin(50 deg) / 64 */
        {TL_EASE_ELASTIC, TL_EASE_IN_OUT, 0.25, 0.76604444311897804 / 64},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double got = tl_ease(cases[i].f, cases[i].d, cases[i].u);
        if (fabs(got - cases[i].want) > 1e-12)
            fprintf(stderr, "  ease %s at %g\n", tl_ease_name(cases[i].f, cases[i].d), cases[i].u);
        CHECK_NEAR(got, cases[i].want, 1e-12);
    }
    /* 1.70158 is chosen for a 10% undershoot: minimum at u = 2s / (3(s+1)). */
    double s = TL_EASE_BACK_OVERSHOOT, umin = 2 * s / (3 * (s + 1));
    CHECK_NEAR(tl_ease(TL_EASE_BACK, TL_EASE_IN, umin), -0.1, 1e-5);

    /* Names round-trip. */
    tl_ease_family fam;
    tl_ease_dir dir;
    CHECK(tl_ease_from_name("ease-in-out-sine", &fam, &dir));
    CHECK(fam == TL_EASE_SINE && dir == TL_EASE_IN_OUT);
    CHECK(tl_ease_from_name("ease-out-elastic", &fam, &dir));
    CHECK(fam == TL_EASE_ELASTIC && dir == TL_EASE_OUT);
    CHECK(!tl_ease_from_name("ease-sideways-sine", &fam, &dir));
    CHECK(!tl_ease_from_name("", &fam, &dir));
    for (int f = 0; f < TL_EASE_FAMILY_COUNT; f++) {
        for (int d = 0; d < TL_EASE_DIR_COUNT; d++) {
            const char *name = tl_ease_name(f, d);
            CHECK(name && tl_ease_from_name(name, &fam, &dir) && (int)fam == f && (int)dir == d);
        }
    }
    CHECK(tl_ease_name(TL_EASE_FAMILY_COUNT, TL_EASE_IN) == NULL);
    CHECK_STR_CONTAINS(tl_ease_name(TL_EASE_BOUNCE, TL_EASE_IN), "bounce");
}

/* Blender's per-key back, amplitude and period. Expected values from the
 * fixture (Blender 3.4's BLI_easing formulas, run in frames at 24 fps over
 * a 24-frame segment; the curve engine gets the same segment in seconds),
 * named by each case's inputs. */
static void test_ease_params(void)
{
    const double fps = 24.0;
    static const char *const dir_name[TL_EASE_DIR_COUNT] = {
        [TL_EASE_IN] = "in", [TL_EASE_OUT] = "out", [TL_EASE_IN_OUT] = "in-out"};
    struct {
        tl_ease_family f;
        tl_ease_dir d;
        double u, change, amplitude, period_frames;
    } cases[] = {
        /* an inserted key's defaults: amplitude 0.8, period 4.1 frames */
        {TL_EASE_ELASTIC, TL_EASE_OUT, 0.3, 10, 0.8, 4.1},
        {TL_EASE_ELASTIC, TL_EASE_OUT, 0.02, 10, 0.8, 4.1}, /* blend */
        {TL_EASE_ELASTIC, TL_EASE_IN, 0.9, 10, 0.8, 4.1},
        {TL_EASE_ELASTIC, TL_EASE_IN_OUT, 0.45, 10, 0.8, 4.1},
        {TL_EASE_ELASTIC, TL_EASE_IN_OUT, 0.7, 10, 0.8, 4.1},
        /* amplitude above the change: the asin phase */
        {TL_EASE_ELASTIC, TL_EASE_IN, 0.7, 1, 2, 6},
        {TL_EASE_ELASTIC, TL_EASE_OUT, 0.4, -1, 2, 6},
        /* amplitude 0, period 0 (0.3 of the segment): only the end blend */
        {TL_EASE_ELASTIC, TL_EASE_IN, 0.95, 3, 0, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tl_ease_params p = {TL_EASE_BACK_OVERSHOOT, cases[i].amplitude,
                            cases[i].period_frames / fps};
        double got = tl_ease_segment(cases[i].f, cases[i].d, &p, cases[i].u, cases[i].change, 1.0);
        CHECK_NEAR(got,
                   tl_fixture("elastic.%s.u=%g.change=%g.dur=24f.amp=%g.period=%gf",
                              dir_name[cases[i].d], cases[i].u, cases[i].change, cases[i].amplitude,
                              cases[i].period_frames),
                   1e-12);
    }
    /* back with its own overshoot; 0 overshoots nothing (a plain cubic). */
    tl_ease_params b = {3.0, 0.8, 4.1 / fps};
    CHECK_NEAR(tl_ease_segment(TL_EASE_BACK, TL_EASE_IN, &b, 0.4, 2.0, 1.0),
               tl_fixture("back.in.u=0.4.s=3.change=2"), 1e-12);
    b.back = 0.0;
    CHECK_NEAR(tl_ease_segment(TL_EASE_BACK, TL_EASE_OUT, &b, 0.3, 2.0, 1.0),
               tl_fixture("back.out.u=0.3.s=0.change=2"), 1e-12);
    b.back = 2.5;
    CHECK_NEAR(tl_ease_segment(TL_EASE_BACK, TL_EASE_IN_OUT, &b, 0.2, 2.0, 1.0),
               tl_fixture("back.in-out.u=0.2.s=2.5.change=2"), 1e-12);
    /* The ends are exact, whatever the settings. */
    CHECK(tl_ease_segment(TL_EASE_ELASTIC, TL_EASE_IN_OUT, &b, 1.0, 7.0, 2.0) == 7.0);
    CHECK(tl_ease_segment(TL_EASE_ELASTIC, TL_EASE_OUT, &b, 0.0, 7.0, 2.0) == 0.0);
}

/* ---- simple interpolations ---------------------------------------------- */

static void test_constant_linear_ease(void)
{
    tl_curve c;
    tl_curve_init(&c);
    add(&c, key(0.0, 1.0, TL_INTERP_CONSTANT));
    add(&c, key(2.0, 3.0, TL_INTERP_LINEAR));
    tl_key e = key(4.0, 7.0, TL_INTERP_EASE);
    e.ease_family = TL_EASE_QUAD;
    e.ease_dir = TL_EASE_IN;
    add(&c, e);
    add(&c, key(6.0, 9.0, TL_INTERP_LINEAR));
    CHECK(tl_curve_validate(&c, NULL, NULL) == 0);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 0.0), 1.0, 0);
    CHECK_NEAR(tl_curve_eval(&c, 1.999), 1.0, 0); /* step holds */
    CHECK_NEAR(tl_curve_eval(&c, 2.0), 3.0, 0);
    CHECK_NEAR(tl_curve_eval(&c, 2.5), 4.0, 1e-15);
    CHECK_NEAR(tl_curve_eval(&c, 3.0), 5.0, 1e-15);
    CHECK_NEAR(tl_curve_eval(&c, 4.0), 7.0, 0);
    CHECK_NEAR(tl_curve_eval(&c, 5.0), 7.0 + 2.0 * 0.25, 1e-15); /* quad-in at 1/2 */
    CHECK_NEAR(tl_curve_eval(&c, 6.0), 9.0, 0);
    CHECK_NEAR(tl_curve_eval(&c, -1.0), 1.0, 0); /* constant extrapolation */
    CHECK_NEAR(tl_curve_eval(&c, 9.0), 9.0, 0);

    /* Step keys may share a time: the later key wins from that time on. */
    tl_curve s;
    tl_curve_init(&s);
    add(&s, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&s, key(1.0, 1.0, TL_INTERP_CONSTANT));
    add(&s, key(1.0, 4.0, TL_INTERP_LINEAR));
    add(&s, key(2.0, 6.0, TL_INTERP_LINEAR));
    CHECK(tl_curve_validate(&s, NULL, NULL) == 0);
    tl_curve_prepare(&s);
    CHECK_NEAR(tl_curve_eval(&s, 0.5), 0.5, 1e-15);
    CHECK_NEAR(tl_curve_eval(&s, 1.0), 4.0, 0);
    CHECK_NEAR(tl_curve_eval(&s, 1.5), 5.0, 1e-15);

    /* Empty and single-key curves. */
    tl_curve z;
    tl_curve_init(&z);
    CHECK(tl_curve_eval(&z, 3.0) == 0.0);
    add(&z, key(1.0, 2.5, TL_INTERP_BEZIER));
    tl_curve_prepare(&z);
    CHECK(tl_curve_eval(&z, -4.0) == 2.5 && tl_curve_eval(&z, 1e6) == 2.5);
    tl_curve_free(&z);
    tl_curve_free(&s);
    tl_curve_free(&c);
}

static double quad_f(double t)
{
    return t * t - 3.0 * t + 1.0;
}

static void test_spline(void)
{
    /* Three-point tangents make a cubic Hermite reproduce a quadratic
     * exactly, ends included, at any key spacing. */
    const double ts[] = {0.0, 0.5, 1.7, 3.0, 3.2, 5.0};
    tl_curve c;
    tl_curve_init(&c);
    for (size_t i = 0; i < sizeof ts / sizeof ts[0]; i++)
        add(&c, key(ts[i], quad_f(ts[i]), TL_INTERP_SPLINE));
    tl_curve_prepare(&c);
    for (double t = 0.0; t <= 5.0; t += 0.01)
        CHECK_NEAR(tl_curve_eval(&c, t), quad_f(t), 1e-12);
    /* Linear extrapolation continues with the end derivative 2t - 3. */
    tl_curve_set_extrap(&c, TL_EXTRAP_LINEAR);
    CHECK_NEAR(tl_curve_eval(&c, 6.0), quad_f(5.0) + 7.0, 1e-12);
    CHECK_NEAR(tl_curve_eval(&c, -1.0), quad_f(0.0) + 3.0, 1e-12);
    tl_curve_free(&c);

    /* C1 at a key for arbitrary data: one-sided difference quotients agree. */
    tl_curve w;
    tl_curve_init(&w);
    const double vs[] = {0.0, 2.0, -1.0, 0.5, 3.0};
    const double tw[] = {0.0, 0.3, 1.0, 2.5, 2.9};
    for (int i = 0; i < 5; i++)
        add(&w, key(tw[i], vs[i], TL_INTERP_SPLINE));
    tl_curve_prepare(&w);
    for (int i = 1; i < 4; i++) {
        double h = 1e-6, t = tw[i];
        double left = (tl_curve_eval(&w, t) - tl_curve_eval(&w, t - h)) / h;
        double right = (tl_curve_eval(&w, t + h) - tl_curve_eval(&w, t)) / h;
        CHECK_NEAR(left, right, 1e-3 * (1.0 + fabs(left)));
        CHECK_NEAR(tl_curve_eval(&w, t), vs[i], 1e-15);
    }
    tl_curve_free(&w);
}

/* ---- Bezier handles ------------------------------------------------------- */

static void test_handles(void)
{
    tl_curve c;
    /* Auto-clamped at a maximum: both handles flat, reaching dt / F. */
    prepared3(&c, 0, 0, 1, 1, 2, 0, TL_HANDLE_AUTO_CLAMPED);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].left.t, 1 - 1 / F, 1e-12);
    CHECK_NEAR(c.keys[1].left.v, 1, 0);
    CHECK_NEAR(c.keys[1].right.t, 1 + 1 / F, 1e-12);
    CHECK_NEAR(c.keys[1].right.v, 1, 0);
    tl_curve_free(&c);

    /* Auto: handle slope = mean of the neighbouring chord slopes (1 and
     * 0.25), lengths dt_prev / F and dt_next / F in time. */
    prepared3(&c, 0, 0, 1, 1, 3, 1.5, TL_HANDLE_AUTO);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].left.t, 1 - 1 / F, 1e-12);
    CHECK_NEAR(c.keys[1].left.v, 1 - 0.625 / F, 1e-12);
    CHECK_NEAR(c.keys[1].right.t, 1 + 2 / F, 1e-12);
    CHECK_NEAR(c.keys[1].right.v, 1 + 1.25 / F, 1e-12);
    /* End keys with constant extrapolation: flat (Blender's auto ease). */
    CHECK_NEAR(c.keys[0].right.t, 1 / F, 1e-12);
    CHECK_NEAR(c.keys[0].right.v, 0, 0);
    CHECK_NEAR(c.keys[2].left.t, 3 - 2 / F, 1e-12);
    CHECK_NEAR(c.keys[2].left.v, 1.5, 0);
    /* With linear extrapolation the ends point along their chord. */
    tl_curve_set_extrap(&c, TL_EXTRAP_LINEAR);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[0].right.v, 1 / F, 1e-12);
    CHECK_NEAR(c.keys[0].left.t, -1 / F, 1e-12);
    CHECK_NEAR(c.keys[0].left.v, -1 / F, 1e-12);
    CHECK_NEAR(c.keys[2].right.t, 3 + 2 / F, 1e-12);
    CHECK_NEAR(c.keys[2].right.v, 1.5 + 0.5 / F, 1e-12);
    tl_curve_free(&c);

    /* Auto-clamped, not an extremum, right handle would pass the next value
     * (1 + 1.1 * 2 / (2F) > 1.2): clamped to 1.2, left realigned through the
     * key: slope 0.2 / (2/F) so left = 1 - 0.2 / 2 = 0.9. */
    prepared3(&c, 0, 0, 1, 1, 3, 1.2, TL_HANDLE_AUTO_CLAMPED);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].right.t, 1 + 2 / F, 1e-12);
    CHECK_NEAR(c.keys[1].right.v, 1.2, 1e-15);
    CHECK_NEAR(c.keys[1].left.t, 1 - 1 / F, 1e-12);
    CHECK_NEAR(c.keys[1].left.v, 0.9, 1e-12);
    tl_curve_free(&c);

    /* Vector: one third of the way to each neighbour. */
    prepared3(&c, 0, 0, 3, 3, 6, 0, TL_HANDLE_VECTOR);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].left.t, 2, 1e-15);
    CHECK_NEAR(c.keys[1].left.v, 2, 1e-15);
    CHECK_NEAR(c.keys[1].right.t, 4, 1e-15);
    CHECK_NEAR(c.keys[1].right.v, 2, 1e-15);
    CHECK_NEAR(c.keys[0].right.t, 1, 1e-15); /* end: mirrored neighbour */
    CHECK_NEAR(c.keys[0].right.v, 1, 1e-15);
    CHECK_NEAR(c.keys[0].left.t, -1, 1e-15);
    CHECK_NEAR(c.keys[0].left.v, -1, 1e-15);
    tl_curve_free(&c);

    /* Aligned both sides: the right handle's direction wins, the left keeps
     * its length pointing the opposite way. Blender measures that length in
     * (frame, value) space, so it depends on the fps: at 1 fps frames are
     * seconds and the left keeps (1, 0) -> length 1 along (-1, -1)/sqrt 2. */
    prepared3(&c, 0, 0, 1, 1, 2, 0, TL_HANDLE_AUTO_CLAMPED);
    c.fps = 1.0;
    c.keys[1].left_type = c.keys[1].right_type = TL_HANDLE_ALIGNED;
    c.keys[1].left = (tl_curve_point){0.0, 1.0};
    c.keys[1].right = (tl_curve_point){3.0, 3.0};
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].right.t, 3, 1e-12);
    CHECK_NEAR(c.keys[1].right.v, 3, 1e-12);
    CHECK_NEAR(c.keys[1].left.t, 1 - sqrt(0.5), 1e-12);
    CHECK_NEAR(c.keys[1].left.v, 1 - sqrt(0.5), 1e-12);
    /* At 24 fps (issue 13, point 2; the old expectation above was the
     * defect at any other rate): the left's 24-frame length lies along the
     * right's (48 frames, 2). Values from the fixture. */
    c.fps = 24.0;
    c.keys[1].left = (tl_curve_point){0.0, 1.0};
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].left.t, tl_fixture("aligned_both.left_t"), 1e-12);
    CHECK_NEAR(c.keys[1].left.v, tl_fixture("aligned_both.left_v"), 1e-12);
    CHECK_NEAR(c.keys[1].right.t, tl_fixture("aligned_both.right_t"), 1e-12);
    CHECK_NEAR(c.keys[1].right.v, tl_fixture("aligned_both.right_v"), 1e-12);
    /* Aligned left with an auto-clamped right (flat at the maximum): the
     * left's (12 frames, 0.5) becomes 13 frames long, flat. */
    c.keys[1].right_type = TL_HANDLE_AUTO_CLAMPED;
    c.keys[1].left = (tl_curve_point){0.5, 1.5};
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].right.v, 1, 0);
    CHECK_NEAR(c.keys[1].left.t, tl_fixture("aligned_left_auto_clamped_right.left_t"), 1e-12);
    CHECK_NEAR(c.keys[1].left.v, tl_fixture("aligned_left_auto_clamped_right.left_v"), 1e-15);
    /* Free stays where it is, except a handle on the wrong side of its key
     * in time, which is clamped to the key's time (Blender). */
    c.keys[1].left_type = c.keys[1].right_type = TL_HANDLE_FREE;
    c.keys[1].left = (tl_curve_point){0.2, 5.0};
    c.keys[1].right = (tl_curve_point){0.5, -2.0};
    tl_curve_prepare(&c);
    CHECK(c.keys[1].left.t == 0.2 && c.keys[1].left.v == 5.0);
    CHECK(c.keys[1].right.t == 1.0 && c.keys[1].right.v == -2.0);
    tl_curve_free(&c);

    /* Cycle: with auto ends, the first key's neighbour before it is the
     * second-to-last key one cycle earlier: (-2, 2) around (0,0) with next
     * (1, 2); slopes -1 and 2, mean 0.5. */
    prepared3(&c, 0, 0, 1, 2, 3, 0, TL_HANDLE_AUTO);
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[0].left.t, -2 / F, 1e-12);
    CHECK_NEAR(c.keys[0].left.v, -1 / F, 1e-12);
    CHECK_NEAR(c.keys[0].right.t, 1 / F, 1e-12);
    CHECK_NEAR(c.keys[0].right.v, 0.5 / F, 1e-12);
    /* ... and the same seam seen from the last key (next = (4, 2)). */
    CHECK_NEAR(c.keys[2].right.v, 0.5 / F, 1e-12);
    CHECK_NEAR(c.keys[2].left.v, -1 / F, 1e-12);
    tl_curve_free(&c);

    /* Neighbour weighting limit: a handle never exceeds 5x the other side. */
    prepared3(&c, 0, 0, 1, 1, 11, 2, TL_HANDLE_AUTO);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].right.t, 1 + 5 / F, 1e-12);
    tl_curve_free(&c);
}

/* Issue 13: Blender's F-curve rules the old engine missed. Expected values
 * from the fixture (Blender 3.4's formulas in frames at 24 fps,
 * independent of this code). */
static void test_blender_handles(void)
{
    tl_curve c;
    /* A missing aligned handle (on its key) gets length 1 in (frame, value)
     * space, opposite the right (12 frames, 1): ~1 frame back, 0.083 down. */
    prepared3(&c, 0, 0, 1, 1, 2, 0, TL_HANDLE_AUTO_CLAMPED);
    c.keys[1].left_type = c.keys[1].right_type = TL_HANDLE_ALIGNED;
    c.keys[1].right = (tl_curve_point){1.5, 2.0};
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].left.t, tl_fixture("aligned_left_on_its_key.left_t"), 1e-12);
    CHECK_NEAR(c.keys[1].left.v, tl_fixture("aligned_left_on_its_key.left_v"), 1e-12);
    tl_curve_free(&c);

    /* An aligned key between vector ends: the curve's value, not only its
     * handles, follows Blender at 24 fps. */
    prepared3(&c, 0, 0, 1, 1, 2, 0, TL_HANDLE_VECTOR);
    c.keys[1].left_type = c.keys[1].right_type = TL_HANDLE_ALIGNED;
    c.keys[1].left = (tl_curve_point){0.5, 0.2};
    c.keys[1].right = (tl_curve_point){1.25, 1.5};
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].left.t, tl_fixture("aligned_segment.left_t"), 1e-12);
    CHECK_NEAR(c.keys[1].left.v, tl_fixture("aligned_segment.left_v"), 1e-12);
    CHECK_NEAR(tl_curve_eval(&c, 1.5), tl_fixture("aligned_segment.at=1.5"), 1e-9);
    tl_curve_free(&c);

    /* Both handles on the wrong side of their key: swapped (Blender's
     * sort_time_fcurve), not both moved onto the key. */
    prepared3(&c, 0, 0, 1, 1, 2, 0, TL_HANDLE_VECTOR);
    c.keys[1].left_type = c.keys[1].right_type = TL_HANDLE_FREE;
    c.keys[1].left = (tl_curve_point){1.5, 3.0};
    c.keys[1].right = (tl_curve_point){0.5, -1.0};
    tl_curve_prepare(&c);
    CHECK(c.keys[1].left.t == tl_fixture("swapped.left_t") &&
          c.keys[1].left.v == tl_fixture("swapped.left_v"));
    CHECK(c.keys[1].right.t == tl_fixture("swapped.right_t") &&
          c.keys[1].right.v == tl_fixture("swapped.right_v"));
    static const double swapped_at[] = {0.5, 1.25, 1.5};
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(tl_curve_eval(&c, swapped_at[i]), tl_fixture("swapped.at=%g", swapped_at[i]),
                   1e-9);
    tl_curve_free(&c);
}

/* Continuous Acceleration smoothing. Expected handles and values from the
 * fixture (BKE_nurb_handle_smooth_fcurve's equations solved by dense
 * Gaussian elimination), under `prefix`. */
static void check_handles(const tl_curve *c, const char *prefix, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        CHECK_NEAR(c->keys[i].left.t, tl_fixture("%s.key%zu.left_t", prefix, i), 1e-12);
        CHECK_NEAR(c->keys[i].left.v, tl_fixture("%s.key%zu.left_v", prefix, i), 1e-12);
        CHECK_NEAR(c->keys[i].right.t, tl_fixture("%s.key%zu.right_t", prefix, i), 1e-12);
        CHECK_NEAR(c->keys[i].right.v, tl_fixture("%s.key%zu.right_v", prefix, i), 1e-12);
    }
}

static void test_smoothing(void)
{
    static const double ts[] = {0, 1, 1.5, 3, 4, 6}, vs[] = {0, 2, 2.5, 1, 1.5, -1};
    static const double at[] = {0.5, 1.2, 2.2, 3.5, 5.0};
    /* auto, then auto-clamped: the extremes lock flat and split the runs. */
    static const char *const prefix[2] = {"smooth.auto", "smooth.auto-clamped"};
    for (int pass = 0; pass < 2; pass++) {
        tl_curve c;
        tl_curve_init(&c);
        for (int i = 0; i < 6; i++) {
            tl_key k = key(ts[i], vs[i], TL_INTERP_BEZIER);
            k.left_type = k.right_type = pass ? TL_HANDLE_AUTO_CLAMPED : TL_HANDLE_AUTO;
            add(&c, k);
        }
        c.smoothing = TL_SMOOTH_CONTINUOUS;
        tl_curve_prepare(&c);
        check_handles(&c, prefix[pass], 6);
        for (int i = 0; i < 5; i++)
            CHECK_NEAR(tl_curve_eval(&c, at[i]), tl_fixture("%s.at=%g", prefix[pass], at[i]), 1e-9);
        /* Without smoothing the same keys give other handles (0.39 of each gap). */
        c.smoothing = TL_SMOOTH_NONE;
        tl_curve_prepare(&c);
        CHECK_NEAR(c.keys[1].right.t, 1 + 0.5 / F, 1e-12);
        tl_curve_free(&c);
    }

    /* A full cycle of auto keys solves as one closed system; the first
     * key's left handle mirrors its right (Blender's endpoint rule). */
    static const double cyc_t[] = {0, 1, 2.5, 4}, cyc_v[] = {0, 1, -0.5, 0};
    tl_curve c;
    tl_curve_init(&c);
    for (int i = 0; i < 4; i++) {
        tl_key k = key(cyc_t[i], cyc_v[i], TL_INTERP_BEZIER);
        k.left_type = k.right_type = TL_HANDLE_AUTO;
        add(&c, k);
    }
    c.smoothing = TL_SMOOTH_CONTINUOUS;
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE);
    tl_curve_prepare(&c);
    check_handles(&c, "smooth.cycle", 4);
    CHECK_NEAR(tl_curve_eval(&c, 0.3), tl_fixture("smooth.cycle.at=0.3"), 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, 1.7), tl_fixture("smooth.cycle.at=1.7"), 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, 3.6), tl_fixture("smooth.cycle.at=3.6"), 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, 3.6 + 4e5), tl_fixture("smooth.cycle.at=3.6"), 1e-8);
    tl_curve_free(&c);
}

/* ---- Bezier segments -------------------------------------------------------- */

static void check_segment(const tl_curve *c, const double p0[2], const double p1[2],
                          const double p2[2], const double p3[2], double tol)
{
    for (int i = 0; i <= 40; i++) {
        double t = p0[0] + (p3[0] - p0[0]) * i / 40.0;
        double want = ref_bezier(p0, p1, p2, p3, t);
        double got = tl_curve_eval(c, t);
        if (fabs(got - want) > tol)
            fprintf(stderr, "  bezier at t=%.17g\n", t);
        CHECK_NEAR(got, want, tol);
    }
}

static void test_bezier_segments(void)
{
    /* Auto-clamped keys: handles derived by hand as in test_handles. */
    tl_curve c;
    prepared3(&c, 0, 0, 1, 1, 3, 1.5, TL_HANDLE_AUTO_CLAMPED);
    tl_curve_prepare(&c);
    {
        double p0[2] = {0, 0}, p1[2] = {1 / F, 0}, p2[2] = {1 - 1 / F, 1 - 0.625 / F},
               p3[2] = {1, 1};
        check_segment(&c, p0, p1, p2, p3, 1e-8);
        double q0[2] = {1, 1}, q1[2] = {1 + 2 / F, 1 + 1.25 / F}, q2[2] = {3 - 2 / F, 1.5},
               q3[2] = {3, 1.5};
        check_segment(&c, q0, q1, q2, q3, 1e-8);
    }
    tl_curve_free(&c);

    /* Handles twice as long as the segment: Blender scales each back to the
     * segment span, keeping direction: (2,1) -> (1,0.5), (-1,1) -> (0,1).
     * The time cubic is then 3s - 6s^2 + 4s^3, flat at s = 1/2. */
    tl_curve_init(&c);
    tl_key a = key(0, 0, TL_INTERP_BEZIER), b = key(1, 1, TL_INTERP_BEZIER);
    a.left_type = a.right_type = b.left_type = b.right_type = TL_HANDLE_FREE;
    a.right = (tl_curve_point){2.0, 1.0};
    b.left = (tl_curve_point){-1.0, 1.0};
    add(&c, a);
    add(&c, b);
    tl_curve_prepare(&c);
    {
        double p0[2] = {0, 0}, p1[2] = {1, 0.5}, p2[2] = {0, 1}, p3[2] = {1, 1};
        check_segment(&c, p0, p1, p2, p3, 1e-6);
        /* x(1/2) = 1/2 exactly; y(1/2) = (0 + 3*0.5 + 3*1 + 1) / 8 = 0.6875 */
        CHECK_NEAR(tl_curve_eval(&c, 0.5), 0.6875, 1e-9);
    }
    /* Zero-length handles: x and y are the same polynomial, so linear. */
    c.keys[0].right = (tl_curve_point){0.0, 0.0};
    c.keys[1].left = (tl_curve_point){1.0, 1.0};
    for (double t = 0.0; t <= 1.0; t += 0.0625)
        CHECK_NEAR(tl_curve_eval(&c, t), t, 1e-12);
    /* One handle at full length, the other zero (x'(1) = 0 at the end). */
    c.keys[0].right = (tl_curve_point){1.0, 3.0};
    {
        double p0[2] = {0, 0}, p1[2] = {1, 3}, p2[2] = {1, 1}, p3[2] = {1, 1};
        check_segment(&c, p0, p1, p2, p3, 1e-6);
    }
    tl_curve_free(&c);

    /* Random free handles (any length, any slope): always finite, within
     * the convex hull of the corrected control values. */
    uint64_t seed = 12345;
    for (int trial = 0; trial < 200; trial++) {
        tl_curve_init(&c);
        double span = pow(10.0, -6.0 + 8.0 * rnd(&seed));
        tl_key k0 = key(0, 0, TL_INTERP_BEZIER), k1 = key(span, 1, TL_INTERP_BEZIER);
        k0.right_type = k1.left_type = TL_HANDLE_FREE;
        k0.right = (tl_curve_point){span * 3 * rnd(&seed), 4 * rnd(&seed) - 2};
        k1.left = (tl_curve_point){span * (1 - 3 * rnd(&seed)), 4 * rnd(&seed) - 1};
        add(&c, k0);
        add(&c, k1);
        tl_curve_prepare(&c);
        for (int i = 0; i <= 50; i++) {
            double v = tl_curve_eval(&c, span * i / 50.0);
            CHECK(isfinite(v) && v >= -2.0 - 1e-9 && v <= 3.0 + 1e-9);
        }
        if (trial < 20) {
            /* Against the sampled cubic, with the handles shortened by hand
             * to the span (Blender's correction) in normalised time. */
            double p0[2] = {0, 0}, p3[2] = {1, 1};
            double p1[2] = {k0.right.t / span, k0.right.v};
            double p2[2] = {(k1.left.t - span) / span, k1.left.v}; /* relative to p3 */
            double l1 = fabs(p1[0]), l2 = fabs(p2[0]);
            if (l1 > 1) {
                p1[0] /= l1;
                p1[1] /= l1;
            }
            if (l2 > 1) {
                p2[0] /= l2;
                p2[1] = 1 + (p2[1] - 1) / l2;
            }
            p2[0] += 1;
            /* Off u = 1/2, where full-length handles give a vertical
             * tangent and 1 ulp in u moves the value by ~1e-6. */
            for (int i = 0; i < 10; i++) {
                double u = (i + 0.37) / 10.0;
                CHECK_NEAR(tl_curve_eval(&c, span * u), ref_bezier(p0, p1, p2, p3, u), 1e-6);
            }
        }
        tl_curve_free(&c);
    }
}
int main(int argc, char **argv)
{
    if (!tl_fixture_load(argc > 1 ? argv[1] : NULL))
        TEST_END();
    test_ease();
    test_ease_params();
    test_constant_linear_ease();
    test_spline();
    test_handles();
    test_blender_handles();
    test_smoothing();
    test_bezier_segments();
    TEST_END();
}
