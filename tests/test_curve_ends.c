/* Keyframe engine tests at a curve's ends and limits: extrapolation and
 * cycles, cuts, numerical stability, validation, angle unwrapping and the
 * names (test_curve.c has the curve between its keys). Expected values are
 * derived by hand or read from the fixture tests/fixtures/curve_reference.txt
 * (argv[1]) that tests/blender_curve_ref.py writes from Blender's formulas,
 * never by calling the code under test. After changing the script,
 * regenerate the fixture from the repository root:
 *     python3 tests/blender_curve_ref.py > tests/fixtures/curve_reference.txt */
#include "timeline/tl_ease.h"
#include "tl_curve_test.h"
#include "tl_fixture.h"

#include <float.h>
#include <stdlib.h>

/* ---- extrapolation --------------------------------------------------------- */

static void test_extrapolation(void)
{
    tl_curve c;
    tl_curve_init(&c);
    add(&c, key(0.0, 1.0, TL_INTERP_LINEAR));
    add(&c, key(2.0, 3.0, TL_INTERP_LINEAR));
    tl_curve_prepare(&c);
    CHECK(tl_curve_eval(&c, -5.0) == 1.0);
    CHECK(tl_curve_eval(&c, 1e6) == 3.0);
    tl_curve_set_extrap(&c, TL_EXTRAP_LINEAR);
    CHECK_NEAR(tl_curve_eval(&c, 1e6), 1e6 + 1.0, 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, -1e6), 1.0 - 1e6, 1e-9);
    /* Blender follows each END KEY's own interpolation: a constant first
     * key holds, while the linear last key still continues its chord from
     * the step (before issue 13 tideline held here: the segment's rule). */
    c.keys[0].interp = TL_INTERP_CONSTANT;
    CHECK(tl_curve_eval(&c, -3.0) == 1.0);
    CHECK_NEAR(tl_curve_eval(&c, 5.0), 6.0, 1e-15);
    /* ... and a constant last key holds after a linear segment. */
    c.keys[0].interp = TL_INTERP_LINEAR;
    c.keys[1].interp = TL_INTERP_CONSTANT;
    CHECK_NEAR(tl_curve_eval(&c, -3.0), -2.0, 1e-15);
    CHECK(tl_curve_eval(&c, 5.0) == 3.0);
    tl_curve_free(&c);

    /* Bezier: the outer handle's slope (auto: the end chord, slope 2). */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_BEZIER));
    add(&c, key(1.0, 2.0, TL_INTERP_BEZIER));
    tl_curve_set_extrap(&c, TL_EXTRAP_LINEAR);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 1e6), 2.0 + 2.0 * (1e6 - 1.0), 1e-6);
    CHECK_NEAR(tl_curve_eval(&c, -3.0), -6.0, 1e-12);
    c.keys[0].left_type = TL_HANDLE_FREE;
    c.keys[0].left = (tl_curve_point){-1.0, -0.5};
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, -10.0), -5.0, 1e-12);
    tl_curve_free(&c);

    /* Cycle, period 2.5 (1e6 is exactly 400000 periods). */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 1.0, TL_INTERP_LINEAR));
    add(&c, key(2.5, 0.0, TL_INTERP_LINEAR));
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 3.0), 0.5, 1e-15);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 0.5), 0.5, 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 1.75), 0.5, 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, -1e6 + 0.25), 0.25, 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, -0.5), 1.0 / 3.0, 1e-12); /* = 2.0 in the cycle */
    tl_curve_free(&c);

    /* Cycle with a period not representable in binary: 1e6 = 3333333 * 0.3
     * + 0.1, so t = 1e6 sits 0.1 into a cycle (error ~ 1e6 * ulp). */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(0.3, 3.0, TL_INTERP_LINEAR));
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 1e6), 1.0, 1e-8);
    /* Cycle with offset: each cycle adds 3. */
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE_OFFSET);
    CHECK_NEAR(tl_curve_eval(&c, 1e6), 3333333.0 * 3.0 + 1.0, 1e-6);
    CHECK_NEAR(tl_curve_eval(&c, 0.45), 4.5, 1e-12);
    CHECK_NEAR(tl_curve_eval(&c, -0.15), -1.5, 1e-12);
    tl_curve_free(&c);

    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 2.0, TL_INTERP_LINEAR));
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE_OFFSET);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 0.25), 2e6 + 0.5, 1e-6);
    CHECK_NEAR(tl_curve_eval(&c, -1e6 + 0.25), -2e6 + 0.5, 1e-6);
    tl_curve_free(&c);

    /* Ping-pong over [0, 2]: period 4. */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(2.0, 1.0, TL_INTERP_LINEAR));
    tl_curve_set_extrap(&c, TL_EXTRAP_PINGPONG);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 3.0), 0.5, 1e-15);
    CHECK_NEAR(tl_curve_eval(&c, 4.5), 0.25, 1e-15);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 1.0), 0.5, 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 2.5), 0.75, 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 3.0), 0.5, 1e-9);
    CHECK_NEAR(tl_curve_eval(&c, -1.0), 0.5, 1e-15);
    CHECK_NEAR(tl_curve_eval(&c, -1e6 - 0.5), 0.25, 1e-9);
    tl_curve_free(&c);

    /* Cyclic Bezier curve at 1e6 s: the value one period later matches. */
    prepared3(&c, 0, 0, 0.7, 2, 1.9, 0, TL_HANDLE_AUTO_CLAMPED);
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE);
    tl_curve_prepare(&c);
    double base = tl_curve_eval(&c, 1.1);
    double far = 1.1 + 1.9 * 526316.0; /* ~1e6 */
    CHECK_NEAR(tl_curve_eval(&c, far), base, 1e-8);
    tl_curve_free(&c);
}

/* Cycle seams, per-side modes and repeat counts (Blender's Cycles
 * modifier). Expected values from the fixture. */
static void test_cycles_modifier(void)
{
    /* Issue 13, point 4: the last key's value at the end of every cycle
     * (t = 1, 2, 3), the first key's at the start of every cycle before the
     * keys (t = -1, -2): each seam belongs to the copy nearer the keys. */
    tl_curve c;
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 1.0, TL_INTERP_LINEAR));
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE);
    tl_curve_prepare(&c);
    CHECK(tl_curve_eval(&c, 1.0) == tl_fixture("cycle_0_1.at=1"));
    CHECK(tl_curve_eval(&c, 2.0) == tl_fixture("cycle_0_1.at=2")); /* 0 before issue 13 */
    CHECK(tl_curve_eval(&c, 3.0) == tl_fixture("cycle_0_1.at=3"));
    CHECK(tl_curve_eval(&c, 1e6) == 1.0);
    CHECK_NEAR(tl_curve_eval(&c, 1.5), tl_fixture("cycle_0_1.at=1.5"), 1e-15);
    CHECK(tl_curve_eval(&c, -1.0) == tl_fixture("cycle_0_1.at=-1"));
    CHECK(tl_curve_eval(&c, -2.0) == tl_fixture("cycle_0_1.at=-2"));
    CHECK_NEAR(tl_curve_eval(&c, -0.5), tl_fixture("cycle_0_1.at=-0.5"), 1e-15);
    tl_curve_free(&c);

    /* Before: ping-pong 3 times; after: cycle-offset twice; then the end
     * key's value holds (Blender falls back to the curve's constant
     * extrapolation, so the offset copy jumps back at 6 s). */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 1.0, TL_INTERP_LINEAR));
    add(&c, key(2.0, 0.5, TL_INTERP_LINEAR));
    c.before = TL_EXTRAP_PINGPONG;
    c.before_cycles = 3;
    c.after = TL_EXTRAP_CYCLE_OFFSET;
    c.after_cycles = 2;
    tl_curve_prepare(&c);
    const double t[] = {-0.25, -1.5, -2.0, -3.25, -4.5, -7.0, 2.5, 4.0, 4.5, 3.0, 6.5};
    for (int i = 0; i < 11; i++) {
        double want = tl_fixture("pingpong3_offset2.at=%g", t[i]);
        if (fabs(tl_curve_eval(&c, t[i]) - want) > 1e-12)
            fprintf(stderr, "  cycles at t=%g\n", t[i]);
        CHECK_NEAR(tl_curve_eval(&c, t[i]), want, 1e-12);
    }
    /* Cuts repeat only as far as the cycles reach: keys 0, 1, a cut at 1.5,
     * 3 (span 3). */
    tl_curve_free(&c);
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 1.0, TL_INTERP_LINEAR));
    tl_key k = key(1.5, 2.0, TL_INTERP_LINEAR);
    k.cut = true;
    add(&c, k);
    add(&c, key(3.0, 0.5, TL_INTERP_LINEAR));
    c.before = TL_EXTRAP_PINGPONG;
    c.before_cycles = 3;
    c.after = TL_EXTRAP_CYCLE_OFFSET;
    c.after_cycles = 2;
    tl_curve_prepare(&c);
    CHECK(tl_curve_has_cut_between(&c, 4.0, 5.0));    /* 1.5 + 3 */
    CHECK(tl_curve_has_cut_between(&c, 7.0, 8.0));    /* 1.5 + 6 */
    CHECK(!tl_curve_has_cut_between(&c, 10.0, 11.0)); /* past the two repeats */
    CHECK(tl_curve_has_cut_between(&c, -2.0, -1.0));  /* ping-pong: 1.5 mirrored */
    CHECK(!tl_curve_has_cut_between(&c, -20.0, -19.0));
    tl_curve_free(&c);
}

/* ---- cuts ------------------------------------------------------------------ */

static void test_cuts(void)
{
    tl_curve c;
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 1.0, TL_INTERP_LINEAR));
    tl_key k = key(1.0, 5.0, TL_INTERP_LINEAR);
    k.cut = true;
    add(&c, k);
    add(&c, key(2.0, 6.0, TL_INTERP_LINEAR));
    CHECK(tl_curve_validate(&c, NULL, NULL) == 0);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 1.0 - 1e-9), 1.0 - 1e-9, 1e-12);
    CHECK(tl_curve_eval(&c, 1.0) == 5.0);
    CHECK_NEAR(tl_curve_eval(&c, 1.5), 5.5, 1e-15);
    CHECK(tl_curve_has_cut_between(&c, 0.5, 1.0));
    CHECK(!tl_curve_has_cut_between(&c, 1.0, 1.5));
    CHECK(!tl_curve_has_cut_between(&c, 0.0, 0.999));
    tl_curve_free(&c);

    /* A cut later than the previous key: the value holds until the cut. */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 1.0, TL_INTERP_LINEAR));
    k = key(2.0, 5.0, TL_INTERP_LINEAR);
    k.cut = true;
    add(&c, k);
    add(&c, key(3.0, 6.0, TL_INTERP_LINEAR));
    tl_curve_prepare(&c);
    CHECK(tl_curve_eval(&c, 1.5) == 1.0);
    CHECK(tl_curve_eval(&c, 2.0 - 1e-12) == 1.0);
    CHECK(tl_curve_eval(&c, 2.0) == 5.0);
    CHECK_NEAR(tl_curve_eval(&c, 2.5), 5.5, 1e-15);
    CHECK(tl_curve_has_cut_between(&c, 1.5, 2.0));
    CHECK(!tl_curve_has_cut_between(&c, 2.0, 3.0));
    CHECK(!tl_curve_has_cut_between(&c, 2.5, 2.0)); /* empty interval */
    tl_curve_free(&c);

    /* Bezier handles treat the cut as a boundary: with auto-clamped keys the
     * key before the cut and the cut key are ends (flat), while a plain
     * Bezier across the same keys without the cut would not be flat. */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_BEZIER));
    add(&c, key(1.0, 1.0, TL_INTERP_BEZIER));
    k = key(2.0, 3.0, TL_INTERP_BEZIER);
    k.cut = true;
    add(&c, k);
    add(&c, key(3.0, 4.0, TL_INTERP_BEZIER));
    tl_curve_prepare(&c);
    CHECK(c.keys[1].left.v == 1.0 && c.keys[1].right.v == 1.0);
    CHECK(c.keys[2].left.v == 3.0 && c.keys[2].right.v == 3.0);
    CHECK_NEAR(c.keys[1].left.t, 1.0 - 1.0 / F, 1e-12); /* mirrored neighbour */
    CHECK_NEAR(c.keys[2].right.t, 2.0 + 1.0 / F, 1e-12);
    CHECK(tl_curve_eval(&c, 1.99) == 1.0);
    CHECK(tl_curve_eval(&c, 2.0) == 3.0);
    tl_curve_free(&c);

    /* Cuts repeat with cycles: period 2, cut at 1 (+2k). */
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 1.0, TL_INTERP_LINEAR));
    k = key(1.0, 5.0, TL_INTERP_LINEAR);
    k.cut = true;
    add(&c, k);
    add(&c, key(2.0, 6.0, TL_INTERP_LINEAR));
    tl_curve_set_extrap(&c, TL_EXTRAP_CYCLE);
    tl_curve_prepare(&c);
    CHECK(tl_curve_has_cut_between(&c, 1e6 + 0.5, 1e6 + 1.0));
    CHECK(!tl_curve_has_cut_between(&c, 1e6 + 1.0, 1e6 + 1.5));
    CHECK(tl_curve_has_cut_between(&c, 2.5, 3.5));
    CHECK(tl_curve_has_cut_between(&c, -1.5, -0.5));
    CHECK(tl_curve_has_cut_between(&c, 10.0, 30.0));
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 1.0 - 1e-6), 1.0 - 1e-6, 1e-8);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 1.0), 5.0, 1e-8);
    /* Ping-pong over [0, 3]: the cut at 1 reappears mirrored at 5 (the jump
     * just after 5, played backwards), then at 7. */
    c.keys[3].t = 3.0;
    tl_curve_set_extrap(&c, TL_EXTRAP_PINGPONG);
    tl_curve_prepare(&c);
    CHECK(tl_curve_eval(&c, 5.0) == 5.0 && tl_curve_eval(&c, 5.5) == 0.5);
    CHECK(!tl_curve_has_cut_between(&c, 4.5, 5.0));
    CHECK(tl_curve_has_cut_between(&c, 5.0, 5.5));
    CHECK(!tl_curve_has_cut_between(&c, 5.5, 6.5));
    CHECK(tl_curve_has_cut_between(&c, 6.5, 7.0));
    tl_curve_free(&c);
}

/* ---- stability ----------------------------------------------------------- */

static void test_stability(void)
{
    /* Keys 1 microsecond apart at t = 1e6: the time grid there is ~1.2e-10,
     * so values are right to ~1e-4 of the change. */
    tl_curve c;
    tl_curve_init(&c);
    add(&c, key(1e6, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1e6 + 1e-6, 1.0, TL_INTERP_BEZIER));
    add(&c, key(1e6 + 2e-6, 0.0, TL_INTERP_SPLINE));
    add(&c, key(1e6 + 3e-6, 1.0, TL_INTERP_LINEAR));
    CHECK(tl_curve_validate(&c, NULL, NULL) == 0);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 1e6 + 0.5e-6), 0.5, 2e-4);
    for (int i = 0; i <= 300; i++) {
        double v = tl_curve_eval(&c, 1e6 + i * 1e-8);
        CHECK(isfinite(v) && v > -0.5 && v < 1.5);
    }
    CHECK(tl_curve_eval(&c, 1e6 + 1e-6) == 1.0);
    tl_curve_free(&c);

    /* Same spacing near zero: exact grid, Bezier mid-value by symmetry. */
    prepared3(&c, 0, 0, 1e-6, 1, 2e-6, 2, TL_HANDLE_AUTO_CLAMPED);
    tl_curve_prepare(&c);
    CHECK_NEAR(tl_curve_eval(&c, 1e-6), 1.0, 1e-15);
    /* Second segment: right handle of the middle key (1/F, 1/F) along the
     * data, last key flat; equal handle spans make x symmetric, so s = 1/2
     * at the midpoint and y = (1 + 3 (1 + 1/F) + 3 * 2 + 2) / 8. */
    CHECK_NEAR(tl_curve_eval(&c, 1.5e-6), (12.0 + 3.0 / F) / 8.0, 1e-9);
    tl_curve_free(&c);

    /* Many keys: v = 2t on a 10 ms grid; binary search must find the right
     * segment everywhere. */
    tl_curve_init(&c);
    for (int i = 0; i < 100000; i++)
        add(&c, key(i * 0.01, i * 0.02, TL_INTERP_LINEAR));
    tl_curve_prepare(&c);
    uint64_t seed = 7;
    int bad = 0;
    for (int i = 0; i < 200000; i++) {
        double t = 999.99 * rnd(&seed);
        if (fabs(tl_curve_eval(&c, t) - 2.0 * t) > 1e-9)
            bad++;
    }
    CHECK(bad == 0);
    tl_curve_free(&c);

    /* Non-finite times never give non-finite values. */
    prepared3(&c, 0, 0, 1, 1, 2, 0, TL_HANDLE_AUTO);
    for (int m = 0; m < TL_EXTRAP_COUNT; m++) {
        tl_curve_set_extrap(&c, (tl_extrap)m);
        tl_curve_prepare(&c);
        CHECK(isfinite(tl_curve_eval(&c, INFINITY)));
        CHECK(isfinite(tl_curve_eval(&c, -INFINITY)));
        CHECK(isfinite(tl_curve_eval(&c, NAN)));
        CHECK(isfinite(tl_curve_eval(&c, 1e300)));
    }
    tl_curve_free(&c);
}

/* ---- validation, unwrap, names ---------------------------------------------- */

static void test_validation(void)
{
    tl_curve c;
    tl_error err;
    size_t bad = 99;
    tl_curve_init(&c);
    add(&c, key(0.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, 0.0, TL_INTERP_LINEAR));
    add(&c, key(2.0, NAN, TL_INTERP_LINEAR));
    tl_error_clear(&err);
    CHECK(tl_curve_validate(&c, &bad, &err) != 0);
    CHECK(bad == 2);
    CHECK_STR_CONTAINS(err.message, "key 2");
    CHECK_STR_CONTAINS(err.message, "finite");

    c.keys[2].v = 1.0;
    c.keys[2].t = 0.5; /* decreasing */
    tl_error_clear(&err);
    CHECK(tl_curve_validate(&c, &bad, &err) != 0);
    CHECK(bad == 2);
    CHECK_STR_CONTAINS(err.message, "key 2");
    CHECK_STR_CONTAINS(err.message, "before");

    c.keys[2].t = 1.0; /* same time as key 1, which is linear */
    tl_error_clear(&err);
    CHECK(tl_curve_validate(&c, &bad, &err) != 0);
    CHECK(bad == 2);
    CHECK_STR_CONTAINS(err.message, "key 2");
    CHECK_STR_CONTAINS(err.message, "same time");
    c.keys[2].cut = true;
    CHECK(tl_curve_validate(&c, &bad, NULL) == 0);
    c.keys[2].cut = false;
    c.keys[1].interp = TL_INTERP_CONSTANT;
    CHECK(tl_curve_validate(&c, &bad, NULL) == 0);

    c.keys[1].t = INFINITY;
    tl_error_clear(&err);
    CHECK(tl_curve_validate(&c, &bad, &err) != 0);
    CHECK(bad == 1);
    CHECK_STR_CONTAINS(err.message, "key 1");
    c.keys[1].t = 1.0;

    c.keys[0].right_type = TL_HANDLE_FREE;
    c.keys[0].right.v = NAN;
    tl_error_clear(&err);
    CHECK(tl_curve_validate(&c, &bad, &err) != 0);
    CHECK(bad == 0);
    CHECK_STR_CONTAINS(err.message, "handle");
    tl_curve_free(&c);
}

static void test_unwrap(void)
{
    tl_curve c;
    tl_curve_init(&c);
    add(&c, key(0.0, 170.0, TL_INTERP_LINEAR));
    add(&c, key(1.0, -170.0, TL_INTERP_LINEAR)); /* the short way is +20 */
    add(&c, key(2.0, 175.0, TL_INTERP_LINEAR));  /* from 190: -15 */
    add(&c, key(3.0, 900.0, TL_INTERP_LINEAR));  /* 900 = 180 + 720: from 175, +5 */
    tl_curve_unwrap(&c, 360.0);
    tl_curve_prepare(&c);
    CHECK_NEAR(c.keys[1].v, 190.0, 1e-12);
    CHECK_NEAR(c.keys[2].v, 175.0, 1e-12);
    CHECK_NEAR(c.keys[3].v, 180.0, 1e-12);
    CHECK_NEAR(tl_curve_eval(&c, 0.5), 180.0, 1e-12);
    for (size_t i = 1; i < c.count; i++)
        CHECK(fabs(c.keys[i].v - c.keys[i - 1].v) <= 180.0);
    tl_curve_free(&c);
}

static void test_names(void)
{
    tl_interp ip;
    tl_handle_type ht;
    tl_extrap ex;
    CHECK(tl_interp_from_name("bezier", &ip) && ip == TL_INTERP_BEZIER);
    CHECK(!tl_interp_from_name("cubic", &ip));
    CHECK(tl_handle_type_from_name("auto-clamped", &ht) && ht == TL_HANDLE_AUTO_CLAMPED);
    CHECK(tl_handle_type_from_name("vector", &ht) && ht == TL_HANDLE_VECTOR);
    CHECK(tl_extrap_from_name("ping-pong", &ex) && ex == TL_EXTRAP_PINGPONG);
    CHECK(tl_extrap_from_name("cycle-offset", &ex) && ex == TL_EXTRAP_CYCLE_OFFSET);
    CHECK(strcmp(tl_interp_name(TL_INTERP_SPLINE), "spline") == 0);
    CHECK(strcmp(tl_extrap_name(TL_EXTRAP_CYCLE), "cycle") == 0);
    CHECK(strcmp(tl_handle_type_name(TL_HANDLE_ALIGNED), "aligned") == 0);
    CHECK(tl_interp_name(TL_INTERP_COUNT) == NULL);
    tl_key k = tl_key_make(1.0, 2.0, TL_INTERP_BEZIER);
    CHECK(k.left_type == TL_HANDLE_AUTO_CLAMPED && k.right_type == TL_HANDLE_AUTO_CLAMPED);
    CHECK(!k.cut);
}
int main(int argc, char **argv)
{
    if (!tl_fixture_load(argc > 1 ? argv[1] : NULL))
        TEST_END();
    test_extrapolation();
    test_cycles_modifier();
    test_cuts();
    test_stability();
    test_validation();
    test_unwrap();
    test_names();
    TEST_END();
}
