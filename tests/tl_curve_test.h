/* Helpers the keyframe engine's tests share (test_curve.c,
 * test_curve_ends.c). Header-only. */
#ifndef TL_CURVE_TEST_H
#define TL_CURVE_TEST_H

#include <stdint.h>

#include "timeline/tl_curve.h"
#include "tl_test.h"

#define F 2.5614 /* Blender's auto handle: reaches dt / F towards each neighbour */

/* ---- helpers ------------------------------------------------------------ */

static inline tl_key key(double t, double v, tl_interp interp)
{
    return tl_key_make(t, v, interp);
}

static inline void add(tl_curve *c, tl_key k)
{
    CHECK(tl_curve_add_key(c, &k, NULL) == 0);
}

/* Reference for one Bezier segment: sample (x(s), y(s)) densely and invert
 * x by bisection over the samples plus linear interpolation. */
#define REF_SAMPLES 200000
static inline double ref_bezier(const double p0[2], const double p1[2], const double p2[2],
                                const double p3[2], double t)
{
    static double xs[REF_SAMPLES + 1], ys[REF_SAMPLES + 1];
    for (int i = 0; i <= REF_SAMPLES; i++) {
        double s = (double)i / REF_SAMPLES, r = 1.0 - s;
        double b0 = r * r * r, b1 = 3 * r * r * s, b2 = 3 * r * s * s, b3 = s * s * s;
        xs[i] = b0 * p0[0] + b1 * p1[0] + b2 * p2[0] + b3 * p3[0];
        ys[i] = b0 * p0[1] + b1 * p1[1] + b2 * p2[1] + b3 * p3[1];
    }
    int lo = 0, hi = REF_SAMPLES;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (xs[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    double w = xs[hi] > xs[lo] ? (t - xs[lo]) / (xs[hi] - xs[lo]) : 0.0;
    return ys[lo] + w * (ys[hi] - ys[lo]);
}

/* A tiny local PRNG (no global state). */
static inline double rnd(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* Three Bezier keys with both handles of each of `type` (not prepared). */
static inline void prepared3(tl_curve *c, double t0, double v0, double t1, double v1, double t2,
                             double v2, tl_handle_type type)
{
    tl_curve_init(c);
    tl_key k[3] = {key(t0, v0, TL_INTERP_BEZIER), key(t1, v1, TL_INTERP_BEZIER),
                   key(t2, v2, TL_INTERP_BEZIER)};
    for (int i = 0; i < 3; i++) {
        k[i].left_type = k[i].right_type = type;
        add(c, k[i]);
    }
}

#endif
