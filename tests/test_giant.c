/* The giant wave's CPU model (src/waves/tl_giant.c): geometry, the
 * height-field clamps, the inversion of the horizontal map, slope bounds
 * and travel; the crest's envelope (its peak, taper, bow, variation and
 * break) and the break's feature bit. No GPU. */
#include <math.h>
#include <stdlib.h>

#include "prepare/tl_prepare.h"
#include "scene/tl_scene.h"
#include "tl_test.h"
#include "waves/tl_giant.h"
#include "waves/tl_waves.h"

static tl_giant_wave wave(double height, double steep, double curl)
{
    tl_scene s;
    tl_scene_defaults(&s);
    tl_giant_wave p = s.giant;
    p.enabled = true;
    p.height = height;
    p.steepness = steep;
    p.curve_strength = curl;
    return p;
}

/* The old model's level crest: no taper, no bow, no variation (and no
 * break) leave lambda(w) = fade · width mask and bow(w) = 0 exactly. */
static tl_giant_wave level(tl_giant_wave p)
{
    p.taper = 0.0;
    p.bow = 0.0;
    p.variation = 0.0;
    p.breaking = false;
    return p;
}

/* The horizontal map (s0, w) -> (s0 + λ(w)·D(s0), w) is one-to-one with a
 * positive Jacobian on a dense grid, for every combination the issue names
 * and then some, up to the channel's maximum height. */
static void test_jacobian_positive(void)
{
    const double knobs[] = {0.0, 0.5, 1.0};
    const double heights[] = {0.5, 12.0, 40.0, 200.0, 1000.0};
    const double falloffs[] = {0.0, 30.0, 1e5};
    const double fades[] = {0.25, 1.0};
    double worst = INFINITY, least_curl = 1.0;
    int monotone = 1, cases = 0;
    for (size_t a = 0; a < 3; a++)
        for (size_t b = 0; b < 3; b++)
            for (size_t h = 0; h < 5; h++)
                for (size_t f = 0; f < 3; f++)
                    for (size_t fd = 0; fd < 2; fd++) {
                        tl_giant_wave p = wave(heights[h], knobs[a], knobs[b]);
                        p.falloff = falloffs[f];
                        p.fade = fades[fd];
                        tl_giant g;
                        tl_giant_prepare(&g, &p, 0.0);
                        cases++;
                        double reach = g.half_length + g.falloff_along;
                        /* 21 rows across the envelope, 4001 samples along,
                         * and a row at the largest lambda the clamps allow
                         * for (fade · (1 + variation)). */
                        for (int j = 0; j <= 21; j++) {
                            double w = -g.half_width + g.half_width * j / 10.0, dl;
                            double lambda = j == 21 ? g.lambda_max : tl_giant_lambda(&g, w, &dl);
                            double prev = -INFINITY;
                            for (int i = 0; i <= 4000; i++) {
                                double s0 = -reach + 2.0 * reach * i / 4000.0, y, dy, d, dd;
                                tl_giant_profile(&g, s0, &y, &dy, &d, &dd);
                                double jac = 1.0 + lambda * dd;
                                if (jac < worst)
                                    worst = jac;
                                double s = s0 + lambda * d;
                                monotone &= s > prev;
                                prev = s;
                            }
                        }
                        if (knobs[b] > 0.0 && g.curl / knobs[b] < least_curl)
                            least_curl = g.curl / knobs[b];
                        CHECK(g.min_jacobian >= TL_GIANT_MIN_JACOBIAN - 1e-9);
                        CHECK(g.steepness <= knobs[a] + 1e-15 && g.curl <= knobs[b] + 1e-15);
                    }
    printf("jacobian: %d cases, min over dense grids %.4f (clamp target %.2f); knobs kept "
           ">= %.4f of the asked strength\n",
           cases, worst, TL_GIANT_MIN_JACOBIAN, least_curl);
    CHECK(worst > 0.09);
    CHECK(monotone);
}

/* Gentle waves keep the knobs the author asked for; steep ones are clamped
 * no more than needed (the minimum Jacobian sits on the target). */
static void test_clamps(void)
{
    tl_giant g;
    tl_giant_wave p = wave(12.0, 0.6, 0.3);
    tl_giant_prepare(&g, &p, 0.0);
    printf("default wave: steepness %.3f curl %.3f min J %.3f max slope %.2f max |D| %.2f m\n",
           g.steepness, g.curl, g.min_jacobian, g.max_slope, g.max_displacement);
    CHECK(g.steepness == 0.6);
    CHECK(g.curl == 0.3);
    CHECK(g.min_jacobian > TL_GIANT_MIN_JACOBIAN);

    p = wave(40.0, 1.0, 1.0);
    tl_giant_prepare(&g, &p, 0.0);
    printf("40 m, steepness 1, curl 1: kept steepness %.3f curl %.3f, min J %.4f, slope %.2f\n",
           g.steepness, g.curl, g.min_jacobian, g.max_slope);
    /* One factor scales both knobs. */
    CHECK(g.steepness < 1.0 && g.steepness > 0.3);
    CHECK_NEAR(g.curl, g.steepness, 1e-15);
    CHECK_NEAR(g.min_jacobian, TL_GIANT_MIN_JACOBIAN, 1e-3);

    /* Half faded, the same wave needs less clamping. */
    p.fade = 0.5;
    tl_giant h;
    tl_giant_prepare(&h, &p, 0.0);
    CHECK(h.curl > g.curl);
}

/* The crest sits on the origin, the masks cut along and across the true
 * perpendicular of the travel direction at every angle. */
static void test_geometry(void)
{
    const double angles[] = {0.0, 0.3, M_PI / 4, 1.3, M_PI, 4.7, -2.2};
    for (size_t i = 0; i < sizeof angles / sizeof angles[0]; i++) {
        tl_giant_wave p = level(wave(10.0, 0.0, 0.0));
        p.angle = angles[i];
        p.center[0] = 130.0;
        p.center[1] = -40.0;
        p.arrival = 5.0;
        tl_giant g;
        tl_giant_prepare(&g, &p, 5.0);
        CHECK_NEAR(g.dir[0] * g.across[0] + g.dir[1] * g.across[1], 0.0, 1e-15);
        CHECK_NEAR(g.origin[0], 130.0, 1e-9);
        CHECK_NEAR(g.origin[1], -40.0, 1e-9);
        double ox = g.origin[0], oz = g.origin[1];
        CHECK_NEAR(tl_giant_height(&g, ox, oz, 8), 10.0, 1e-9);
        /* The troughs half a wavelength off, where the crest mask (1 out to
         * half_length) has begun to fade, lifted by TL_GIANT_TROUGH_LIFT
         * (the one behind by TL_GIANT_BACK_FILL more); a flat sea beyond
         * the mask. */
        double half = g.half_length, beyond = g.half_length + g.falloff_along + 0.01;
        double trough = M_PI / g.k, x = (trough - half) / g.falloff_along;
        double mask = 1.0 - x * x * (3.0 - 2.0 * x);
        CHECK(half < trough && x < 1.0);
        CHECK_NEAR(tl_giant_height(&g, ox + g.dir[0] * trough, oz + g.dir[1] * trough, 8),
                   -10.0 * mask * (1.0 - TL_GIANT_TROUGH_LIFT), 1e-9);
        /* The trough behind is filled by TL_GIANT_BACK_FILL more. */
        CHECK_NEAR(tl_giant_height(&g, ox - g.dir[0] * trough, oz - g.dir[1] * trough, 8),
                   -10.0 * mask * (1.0 - TL_GIANT_TROUGH_LIFT) * (1.0 - TL_GIANT_BACK_FILL), 1e-9);
        CHECK_NEAR(tl_giant_height(&g, ox + g.dir[0] * half, oz + g.dir[1] * half, 8),
                   10.0 * cos(g.k * half), 1e-9);
        CHECK_NEAR(tl_giant_height(&g, ox - g.dir[0] * beyond, oz - g.dir[1] * beyond, 8), 0.0,
                   0.0);
        /* Across: full inside the width, zero past it, symmetric. */
        double in = g.half_width - g.falloff_across - 1.0, out = g.half_width + 0.01;
        CHECK_NEAR(tl_giant_height(&g, ox + g.across[0] * in, oz + g.across[1] * in, 8), 10.0,
                   1e-9);
        CHECK_NEAR(tl_giant_height(&g, ox + g.across[0] * out, oz + g.across[1] * out, 8), 0.0,
                   0.0);
        double mid = g.half_width - 0.5 * g.falloff_across;
        double hp = tl_giant_height(&g, ox + g.across[0] * mid, oz + g.across[1] * mid, 8);
        double hm = tl_giant_height(&g, ox - g.across[0] * mid, oz - g.across[1] * mid, 8);
        CHECK_NEAR(hp, hm, 1e-9);
        CHECK_NEAR(hp, 5.0, 1e-9);
        /* The level crest is the special case: lambda = fade · mask, no lag. */
        int exact = 1;
        for (int j = -60; j <= 60; j++) {
            double w = g.half_width * j / 60.0, dl, db, dm;
            exact &= tl_giant_lambda(&g, w, &dl) == g.fade * tl_giant_width_mask(&g, w, &dm) &&
                     tl_giant_bow(&g, w, &db) == 0.0 && db == 0.0;
        }
        CHECK(exact);
        CHECK(g.lambda_max == g.fade);
    }
}

/* fade 0 and enabled off are the ocean exactly. */
static void test_off(void)
{
    tl_giant_wave p = wave(40.0, 0.5, 0.5);
    p.fade = 0.0;
    tl_giant g;
    tl_giant_prepare(&g, &p, 3.0);
    CHECK(!g.active);
    p.fade = 1.0;
    p.enabled = false;
    tl_giant h;
    tl_giant_prepare(&h, &p, 3.0);
    CHECK(!h.active);
    int zero = 1;
    for (int i = -50; i <= 50; i++)
        zero &= tl_giant_height(&g, i * 3.0, i * -1.7, 8) == 0.0 &&
                tl_giant_height(&h, i * 3.0, 0.0, 8) == 0.0;
    CHECK(zero);
}

/* The crest moves at the deep-water speed sqrt(g / k) times giant.speed
 * and reaches the centre at giant.arrival; the phase shifts it by
 * phase / k. */
static void test_travel(void)
{
    tl_giant_wave p = wave(10.0, 0.5, 0.3);
    p.angle = M_PI / 2; /* toward +X */
    p.arrival = 100.0;
    tl_giant g;
    tl_giant_prepare(&g, &p, 90.0);
    double c = sqrt(9.81 * p.wavelength / (2.0 * M_PI));
    CHECK_NEAR(g.speed, c, 1e-12);
    CHECK_NEAR(g.origin[0], -10.0 * c, 1e-9);
    CHECK_NEAR(g.origin[1], 0.0, 1e-9);
    p.phase = M_PI; /* half a wavelength further */
    p.speed = 0.5;
    tl_giant_prepare(&g, &p, 90.0);
    CHECK_NEAR(g.origin[0], -5.0 * c + 0.5 * p.wavelength, 1e-9);
    /* Far in time and space, still exact in double: the level crest's
     * height A at its centre, and with the default envelope A times the
     * variation there (the peak on the centre line: no taper, no bow; the
     * sines' phases from the seed). */
    p = level(wave(10.0, 0.0, 0.0));
    p.arrival = 1e5;
    p.center[0] = 1e4;
    p.center[1] = -3e3;
    tl_giant_prepare(&g, &p, 1e5);
    CHECK_NEAR(g.origin[0], 1e4, 1e-9);
    CHECK_NEAR(tl_giant_height(&g, 1e4, -3e3, 8), g.fade * 10.0, 1e-6);
    p = wave(10.0, 0.0, 0.0);
    p.arrival = 1e5;
    p.center[0] = 1e4;
    p.center[1] = -3e3;
    tl_giant_prepare(&g, &p, 1e5);
    static const double weights[3] = TL_GIANT_VARIATION_WEIGHTS;
    double n = 0.0;
    for (int i = 0; i < 3; i++)
        n += weights[i] * sin(g.vary_phase[i]);
    CHECK_NEAR(tl_giant_height(&g, 1e4, -3e3, 8), g.fade * 10.0 * (1.0 + p.variation * n), 1e-6);
}

/* Inversion: the residual of s = s0 + λD(s0) after n Newton steps, and the
 * finite-difference gradient against the analytic one and the bound. */
static void test_inversion_and_slope(void)
{
    tl_giant_wave p = wave(40.0, 1.0, 1.0);
    tl_giant g;
    tl_giant_prepare(&g, &p, 0.0);
    const int counts[] = {2, 3, 4, 6, 8, 12};
    double res6 = 0.0;
    printf("inversion residual (40 m, steepness 1, curl 1), max over 20001 points:");
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        double worst = 0.0;
        for (int i = 0; i <= 20000; i++) {
            double s = -g.reach_along + 2.0 * g.reach_along * i / 20000.0, y, dy, d, dd;
            double s0 = tl_giant_invert(&g, s, g.fade, counts[c]);
            tl_giant_profile(&g, s0, &y, &dy, &d, &dd);
            /* Height error: the residual times the local slope. */
            double err = fabs(s0 + g.fade * d - s) * fabs(dy) / (1.0 + g.fade * dd);
            if (err > worst)
                worst = err;
        }
        printf(" %d: %.2g m", counts[c], worst);
        if (counts[c] == 6)
            res6 = worst;
    }
    printf("\n");
    CHECK(res6 < 1e-6);

    /* Slope: finite differences against the analytic gradient, and against
     * the bound of the bin the point falls in (what the march relies on). */
    double worst_slope = 0.0, worst_grad = 0.0, worst_ratio = 0.0, worst_height = -1e9;
    double crest_bound = 0.0;
    const double e = 1e-4, bin = 2.0 * g.reach_along / TL_GIANT_SLOPE_BINS;
    for (int j = 0; j <= 60; j++)
        for (int i = 0; i <= 1200; i++) {
            double s = -g.reach_along + 2.0 * g.reach_along * i / 1200.0;
            double w = -g.half_width * 1.02 + 2.04 * g.half_width * j / 60.0;
            double x = g.origin[0] + g.dir[0] * s + g.across[0] * w;
            double z = g.origin[1] + g.dir[1] * s + g.across[1] * w;
            tl_giant_sample smp;
            tl_giant_sample_at(&g, x, z, 30, &smp);
            double gx =
                (tl_giant_height(&g, x + e, z, 30) - tl_giant_height(&g, x - e, z, 30)) / (2 * e);
            double gz =
                (tl_giant_height(&g, x, z + e, 30) - tl_giant_height(&g, x, z - e, 30)) / (2 * e);
            double slope = hypot(gx, gz);
            worst_slope = fmax(worst_slope, slope);
            double rel = hypot(gx - smp.grad[0], gz - smp.grad[1]) / fmax(1.0, slope);
            worst_grad = fmax(worst_grad, rel);
            int b = (int)floor((s + g.reach_along) / bin);
            b = b < 0 ? 0 : b >= TL_GIANT_SLOPE_BINS ? TL_GIANT_SLOPE_BINS - 1 : b;
            worst_ratio = fmax(worst_ratio, slope / fmax(g.slope_bin[b], 1e-12));
            /* The height bound of the bin (what a rising ray's box relies on). */
            worst_height = fmax(worst_height, smp.height - g.height_bin[b]);
        }
    for (int b = 0; b < TL_GIANT_SLOPE_BINS; b++)
        crest_bound = fmax(crest_bound, g.height_bin[b]);
    printf(
        "height: worst height over its bin's bound %.3g m; the highest bound %.3f m for a %.1f m "
        "crest\n",
        worst_height, crest_bound, g.fade * g.amplitude);
    CHECK(worst_height <= 0.0);
    /* Not a loose bound: the crest's bin is bounded within 5% of the
     * largest height the envelope allows, lambda_max = fade · (1 +
     * variation) times the height (the variation's sines may all peak
     * together somewhere). */
    CHECK_NEAR(g.lambda_max, g.fade * (1.0 + p.variation), 1e-15);
    CHECK(crest_bound <= 1.05 * g.lambda_max * g.amplitude);
    printf("slope: max %.3f, bound %.3f, worst slope / its bin's bound %.3f; analytic gradient vs "
           "finite differences: %.2g\n",
           worst_slope, g.max_slope, worst_ratio, worst_grad);
    CHECK(worst_slope <= g.max_slope);
    CHECK(worst_ratio <= 1.0);
    CHECK(worst_grad < 1e-4);
}

/* The surface the boat floats on and the tests compare with is the ocean
 * plus the wave. */
static void test_surface(void)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.giant = wave(12.0, 0.5, 0.3);
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, 0.0);
    /* The small waves ride the wave's water: the ocean is taken where the
     * wave pushed them from; with giant.ride 0 it stays where it is. */
    tl_giant_sample smp;
    tl_giant_sample_at(&g, 3.0, 4.0, 8, &smp);
    CHECK(fabs(smp.displacement) > 1.0);
    double q[2];
    tl_giant_ride_point(&g, &smp, 3.0, 4.0, q);
    CHECK_NEAR(q[0], 3.0 - g.ride * smp.displacement * g.dir[0], 1e-12);
    CHECK_NEAR(q[1], 4.0 - g.ride * smp.displacement * g.dir[1], 1e-12);
    double ocean = tl_waves_height(&w, q[0], q[1], 0.0, 12);
    double both = tl_waves_surface_height(&w, &g, 3.0, 4.0, 0.0, 12, 8);
    CHECK_NEAR(both - ocean, tl_giant_height(&g, 3.0, 4.0, 8), 1e-12);
    CHECK(both > ocean + 5.0);
    s.giant.ride = 0.0;
    tl_giant_prepare(&g, &s.giant, 0.0);
    ocean = tl_waves_height(&w, 3.0, 4.0, 0.0, 12);
    both = tl_waves_surface_height(&w, &g, 3.0, 4.0, 0.0, 12, 8);
    CHECK_NEAR(both - ocean, tl_giant_height(&g, 3.0, 4.0, 8), 1e-12);
}

/* The ocean's constant for filtered shading: an exp(sin) octave's mean
 * squared slope, integrated here over a period (the midpoint rule is
 * exact to rounding for a smooth periodic function). */
static void test_wave_slope_constant(void)
{
    const int n = 4096;
    double sum = 0.0;
    for (int i = 0; i < n; i++) {
        double x = 6.283185307179586 * (i + 0.5) / n;
        double slope = exp(sin(x) - 1.0) * cos(x);
        sum += slope * slope;
    }
    CHECK_NEAR(sum / n, TL_WAVE_SLOPE_MEAN_SQ, 1e-7);
}

/* World x, z of the wave coordinates (s, w). */
static void world_at(const tl_giant *g, double s, double w, double *x, double *z)
{
    *x = g->origin[0] + g->dir[0] * s + g->across[0] * w;
    *z = g->origin[1] + g->dir[1] * s + g->across[1] * w;
}

static double height_sw(const tl_giant *g, double s, double w, int iterations)
{
    double x, z;
    world_at(g, s, w, &x, &z);
    return tl_giant_height(g, x, z, iterations);
}

/* The crest's top at w across: the highest point along s (scanned every
 * 5 cm, refined by a parabola through the best sample and its two
 * neighbours), its s in *s_top. */
static double crest_top(const tl_giant *g, double w, double *s_top)
{
    const double step = 0.05;
    double best = -INFINITY, at = 0.0;
    for (double s = -g->reach_along; s <= g->reach_along; s += step) {
        double h = height_sw(g, s, w, 30);
        if (h > best) {
            best = h;
            at = s;
        }
    }
    double hm = height_sw(g, at - step, w, 30), hp = height_sw(g, at + step, w, 30);
    double curve = hp - 2.0 * best + hm;
    *s_top = curve < 0.0 ? at - 0.5 * step * (hp - hm) / curve : at;
    return height_sw(g, *s_top, w, 30);
}

/* A peaked crest (the default taper, bow and variation, the peak off the
 * centre line) stands higher at its peak than at ±35% of its width, for
 * several seeds; and its top at every w is the envelope's height there,
 * lambda(w)·A (the top is where the profile's cos peaks, s0 = 0). */
static void test_peak_highest(void)
{
    const double peaks[] = {20.0, -25.0};
    const int seeds[] = {1, 7, 424242};
    double worst_ratio = 0.0, worst_top = 0.0;
    for (size_t a = 0; a < 2; a++)
        for (size_t b = 0; b < 3; b++) {
            tl_giant_wave p = wave(12.0, 0.6, 0.3);
            p.peak = peaks[a];
            p.seed = seeds[b];
            tl_giant g;
            tl_giant_prepare(&g, &p, 0.0);
            CHECK(g.peak == peaks[a]);
            double st, dl, top = crest_top(&g, g.peak, &st);
            CHECK_NEAR(top, tl_giant_lambda(&g, g.peak, &dl) * g.amplitude, 1e-6);
            worst_top = fmax(worst_top, fabs(top - tl_giant_lambda(&g, g.peak, &dl) * g.amplitude));
            for (int side = -1; side <= 1; side += 2) {
                double w = side * 0.35 * p.width;
                double there = crest_top(&g, w, &st);
                CHECK(there < top);
                CHECK_NEAR(there, tl_giant_lambda(&g, w, &dl) * g.amplitude, 1e-6);
                worst_ratio = fmax(worst_ratio, there / top);
            }
        }
    printf("peak: the crest at ±35%% of its width stands at most %.3f of its peak's height; top "
           "against lambda·A within %.2g m\n",
           worst_ratio, worst_top);
}

/* Seen from above the crest line bows forward: its top's s at the ends
 * lags the peak's by bow·r² (r from the peak toward that end, 1 at it),
 * less the curl's push lambda·C/k, which is smaller where the crest is
 * lower: s_top(w) - s_top(peak) = -bow·r(w)² + (lambda(w) - lambda(peak))·C/k. */
static void test_bow_lags(void)
{
    const double bows[] = {10.0, 40.0};
    for (size_t i = 0; i < 2; i++) {
        tl_giant_wave p = wave(12.0, 0.6, 0.3);
        p.peak = 15.0;
        p.bow = bows[i];
        tl_giant g;
        tl_giant_prepare(&g, &p, 0.0);
        double s_peak, s_end, dl;
        crest_top(&g, g.peak, &s_peak);
        double lp = tl_giant_lambda(&g, g.peak, &dl);
        for (int side = -1; side <= 1; side += 2) {
            double w = side * 0.35 * p.width;
            crest_top(&g, w, &s_end);
            double r = side > 0 ? (w - g.peak) / (g.half_width - g.peak)
                                : (g.peak - w) / (g.half_width + g.peak);
            double expect = -p.bow * r * r + (tl_giant_lambda(&g, w, &dl) - lp) * g.curl / g.k;
            printf("bow %g m: crest top at w = %+.0f m lies %.3f m behind the peak's (expected "
                   "%.3f m)\n",
                   p.bow, w, s_peak - s_end, -expect);
            CHECK(s_end < s_peak - 0.5 * p.bow * r * r);
            CHECK_NEAR(s_end - s_peak, expect, 2e-3);
        }
    }
}

/* The slope across and along at (s, w), from the analytic gradient. */
static void slopes_sw(const tl_giant *g, double s, double w, double *ds, double *dw, double *h)
{
    double x, z;
    world_at(g, s, w, &x, &z);
    tl_giant_sample smp;
    tl_giant_sample_at(g, x, z, 30, &smp);
    *ds = g->dir[0] * smp.grad[0] + g->dir[1] * smp.grad[1];
    *dw = g->across[0] * smp.grad[0] + g->across[1] * smp.grad[1];
    *h = smp.height;
}

/* No shoulder steeper than the face: over a grid of the wave the slope
 * across, |dh/dw|, stays below the steepest slope along (the face), with
 * the default envelope and with a breaking crest in mid-settle. */
static void test_no_steep_shoulder(void)
{
    for (int breaking = 0; breaking < 2; breaking++) {
        tl_giant_wave p = wave(12.0, 0.6, 0.3);
        p.peak = 12.0;
        double t = 0.0;
        if (breaking) {
            p.breaking = true;
            p.break_time = 0.0;
            p.break_drop = 0.6;
            t = 5.0;
        }
        tl_giant g;
        tl_giant_prepare(&g, &p, t);
        CHECK(g.breaks == (breaking != 0));
        double face = 0.0, shoulder = 0.0;
        for (int j = 0; j <= 120; j++)
            for (int i = 0; i <= 800; i++) {
                double s = -g.reach_along + 2.0 * g.reach_along * i / 800.0;
                double w = -g.half_width + 2.0 * g.half_width * j / 120.0, ds, dw, h;
                slopes_sw(&g, s, w, &ds, &dw, &h);
                face = fmax(face, fabs(ds));
                shoulder = fmax(shoulder, fabs(dw));
            }
        printf("shoulders, %s: steepest across %.3f, along (the face) %.3f\n",
               breaking ? "breaking, settling" : "default envelope", shoulder, face);
        CHECK(face > 1.0);
        CHECK(shoulder < face);
    }
}

/* The march's bounds hold for shapes far from the defaults: the sampled
 * |grad h| (the analytic gradient, which test_gradient_matches holds to
 * central differences) never exceeds its s bin's slope_bin, nor the
 * height its height_bin. */
static void test_bounds_hold(void)
{
    struct {
        const char *what;
        double height, wavelength, width, steep, curl, peak, bow, variation;
        int breaking;
        double drop, t;
    } cases[] = {
        {"defaults", 12.0, 80.0, 120.0, 0.6, 0.3, 0.0, 10.0, 0.12, 0, 0.3, 0.0},
        {"peak off-centre", 12.0, 80.0, 120.0, 0.6, 0.3, 45.0, 10.0, 0.12, 0, 0.3, 0.0},
        {"large bow", 12.0, 80.0, 120.0, 0.6, 0.3, -20.0, 80.0, 0.12, 0, 0.3, 0.0},
        {"variation 1", 12.0, 80.0, 120.0, 0.6, 0.3, 10.0, 10.0, 1.0, 0, 0.3, 0.0},
        {"breaking, drop 1", 12.0, 80.0, 120.0, 0.6, 0.3, -15.0, 10.0, 0.12, 1, 1.0, 4.0},
        {"steep, bowed, varied, breaking", 40.0, 80.0, 200.0, 1.0, 1.0, 30.0, 30.0, 0.5, 1, 0.6,
         6.0},
        {"the render tests' facing wave", 20.0, 90.0, 260.0, 0.6, 0.3, 0.0, 10.0, 0.12, 0, 0.3,
         0.0},
        {"narrow, large bow", 20.0, 60.0, 40.0, 0.8, 0.6, 5.0, 40.0, 0.3, 1, 0.5, 3.0},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        tl_giant_wave p = wave(cases[c].height, cases[c].steep, cases[c].curl);
        p.wavelength = cases[c].wavelength;
        p.width = cases[c].width;
        p.peak = cases[c].peak;
        p.bow = cases[c].bow;
        p.variation = cases[c].variation;
        p.breaking = cases[c].breaking != 0;
        p.break_drop = cases[c].drop;
        p.break_time = 0.0;
        tl_giant g;
        tl_giant_prepare(&g, &p, cases[c].t);
        const double bin = 2.0 * g.reach_along / TL_GIANT_SLOPE_BINS;
        double worst_slope = 0.0, worst_height = -INFINITY, steepest = 0.0;
        int inside = 1;
        for (int j = 0; j <= 60; j++)
            for (int i = 0; i <= 1000; i++) {
                double s = -g.reach_along + 2.0 * g.reach_along * i / 1000.0;
                double w = -1.02 * g.half_width + 2.04 * g.half_width * j / 60.0, x, z;
                world_at(&g, s, w, &x, &z);
                tl_giant_sample smp;
                tl_giant_sample_at(&g, x, z, 30, &smp);
                double slope = hypot(smp.grad[0], smp.grad[1]);
                int b = (int)floor((s + g.reach_along) / bin);
                b = b < 0 ? 0 : b >= TL_GIANT_SLOPE_BINS ? TL_GIANT_SLOPE_BINS - 1 : b;
                worst_slope = fmax(worst_slope, slope / fmax(g.slope_bin[b], 1e-12));
                worst_height = fmax(worst_height, smp.height - g.height_bin[b]);
                steepest = fmax(steepest, slope);
                inside &= slope <= g.max_slope;
            }
        printf("bounds, %s: steepest %.3f (max_slope %.3f); worst slope / its bin's bound %.3f, "
               "height over its bin's bound %.3g m\n",
               cases[c].what, steepest, g.max_slope, worst_slope, worst_height);
        CHECK(worst_slope <= 1.0);
        CHECK(worst_height <= 0.0);
        CHECK(inside);
    }
}

/* The small waves ride the wave's water (giant.ride): up the face, where
 * the water is compressed (J < 1), they are squeezed along the travel by
 * 1 - ride·(J - 1)/J, so their slope along it grows by about that; on
 * open water and with ride 0 they are as they were. The displacement's
 * gradient (the chain rule's) matches central differences and stays
 * within the march's bound (squeeze_bin). */
static void test_ride(void)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.giant = wave(16.0, 0.75, 0.6);
    s.giant.taper = 0.0;
    s.giant.variation = 0.0;
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    double ratio[2], expected = 0.0;
    for (int k = 0; k < 2; k++) {
        s.giant.ride = k == 0 ? 1.0 : 0.0;
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, 0.0);
        /* The face: where J is least on the centre line. */
        double face = 0.0, least = 1e9;
        for (int i = 0; i <= 2000; i++) {
            double sv = -g.reach_along + 2.0 * g.reach_along * i / 2000.0, x, z;
            world_at(&g, sv, 0.0, &x, &z);
            tl_giant_sample smp;
            tl_giant_sample_at(&g, x, z, 40, &smp);
            if (smp.jacobian < least) {
                least = smp.jacobian;
                face = sv;
            }
        }
        /* The RMS slope along the travel of the ocean's part of the
         * surface, on the face and 400 m ahead, over 2000 points across. */
        const double e = 1e-3;
        double sum[2] = {0.0, 0.0}, squeeze = 0.0;
        for (int where = 0; where < 2; where++)
            for (int j = 0; j < 2000; j++) {
                double wv = -0.25 * g.half_width + 0.5 * g.half_width * j / 1999.0;
                double sv = where ? face + 400.0 : face, x0, z0, x1, z1, x, z;
                world_at(&g, sv - e, wv, &x0, &z0);
                world_at(&g, sv + e, wv, &x1, &z1);
                double h0 = tl_waves_surface_height(&w, &g, x0, z0, 0.0, 12, 40) -
                            tl_giant_height(&g, x0, z0, 40);
                double h1 = tl_waves_surface_height(&w, &g, x1, z1, 0.0, 12, 40) -
                            tl_giant_height(&g, x1, z1, 40);
                sum[where] += (h1 - h0) * (h1 - h0) / (4.0 * e * e);
                world_at(&g, sv, wv, &x, &z);
                tl_giant_sample smp;
                tl_giant_sample_at(&g, x, z, 40, &smp);
                if (!where)
                    squeeze += 1.0 - g.ride * (smp.jacobian - 1.0) / smp.jacobian;
            }
        ratio[k] = sqrt(sum[0] / sum[1]);
        if (k == 0)
            expected = squeeze / 2000.0;
        printf("ride %g: least J %.3f on the face; the small waves' slope along the travel there "
               "%.2f of open water's (the squeeze averages %.2f)\n",
               g.ride, least, ratio[k], k == 0 ? expected : 1.0);
    }
    CHECK(expected > 2.0);
    CHECK(ratio[0] > 0.75 * expected && ratio[0] < 1.25 * expected);
    CHECK(ratio[1] > 0.8 && ratio[1] < 1.25);

    /* The displacement's gradient, and the chain rule, against central
     * differences; and the bound. */
    s.giant = wave(12.0, 0.6, 0.3);
    s.giant.peak = -18.0;
    s.giant.bow = 20.0;
    s.giant.variation = 0.3;
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, 0.0);
    const double e = 1e-4, bin = 2.0 * g.reach_along / TL_GIANT_SLOPE_BINS;
    double worst = 0.0, worst_chain = 0.0, worst_bound = 0.0;
    for (int j = 0; j <= 40; j++)
        for (int i = 0; i <= 200; i++) {
            double sv = -g.reach_along + 2.0 * g.reach_along * (i + 0.37) / 200.0;
            double wv = -g.half_width + 2.0 * g.half_width * (j + 0.41) / 41.0, x, z;
            world_at(&g, sv, wv, &x, &z);
            tl_giant_sample smp, a, b, c, d;
            tl_giant_sample_at(&g, x, z, 40, &smp);
            tl_giant_sample_at(&g, x + e, z, 40, &a);
            tl_giant_sample_at(&g, x - e, z, 40, &b);
            tl_giant_sample_at(&g, x, z + e, 40, &c);
            tl_giant_sample_at(&g, x, z - e, 40, &d);
            double gx = (a.displacement - b.displacement) / (2 * e);
            double gz = (c.displacement - d.displacement) / (2 * e);
            double size = hypot(smp.ride[0], smp.ride[1]);
            worst = fmax(worst, hypot(gx - smp.ride[0], gz - smp.ride[1]) / fmax(1.0, size));
            int bi = (int)floor((sv + g.reach_along) / bin);
            if (bi >= 0 && bi < TL_GIANT_SLOPE_BINS)
                worst_bound = fmax(worst_bound, size / fmax(g.squeeze_bin[bi], 1e-12));
            /* The ocean at the ride point, differentiated through it. */
            double q[2], qa[2], qb[2], qc[2], qd[2];
            tl_giant_ride_point(&g, &smp, x, z, q);
            tl_giant_ride_point(&g, &a, x + e, z, qa);
            tl_giant_ride_point(&g, &b, x - e, z, qb);
            tl_giant_ride_point(&g, &c, x, z + e, qc);
            tl_giant_ride_point(&g, &d, x, z - e, qd);
            double grad[2] = {(tl_waves_height(&w, q[0] + e, q[1], 0.0, 8) -
                               tl_waves_height(&w, q[0] - e, q[1], 0.0, 8)) /
                                  (2 * e),
                              (tl_waves_height(&w, q[0], q[1] + e, 0.0, 8) -
                               tl_waves_height(&w, q[0], q[1] - e, 0.0, 8)) /
                                  (2 * e)};
            tl_giant_ride_grad(&g, &smp, grad);
            double fx = (tl_waves_height(&w, qa[0], qa[1], 0.0, 8) -
                         tl_waves_height(&w, qb[0], qb[1], 0.0, 8)) /
                        (2 * e);
            double fz = (tl_waves_height(&w, qc[0], qc[1], 0.0, 8) -
                         tl_waves_height(&w, qd[0], qd[1], 0.0, 8)) /
                        (2 * e);
            worst_chain =
                fmax(worst_chain, hypot(fx - grad[0], fz - grad[1]) / fmax(1.0, hypot(fx, fz)));
        }
    printf("ride: displacement gradient within %.2g of central differences, the chain rule "
           "within %.2g, |grad| at most %.3f of its bin's bound\n",
           worst, worst_chain, worst_bound);
    CHECK(worst < 1e-5);
    CHECK(worst_chain < 1e-5);
    CHECK(worst_bound <= 1.0);
}

/* The analytic gradient of tl_giant_sample_at (the envelope's, the bow's
 * and the break's terms through the implicit derivative of the map) is
 * the central differences of tl_giant_height to 1e-6 relative, away from
 * the few lines where the model is only once differentiable (the
 * smoothsteps' ends, the peak of a settling crest, whose settle goes with
 * |w - peak|): there differences of the second derivative's jump show. */
static void test_gradient_matches(void)
{
    struct {
        double peak, bow, variation;
        int breaking;
        double t;
    } cases[] = {{0.0, 10.0, 0.12, 0, 0.0}, {22.0, 35.0, 0.6, 0, 0.0}, {-18.0, 20.0, 0.3, 1, 5.0}};
    const double e = 1e-4;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        tl_giant_wave p = wave(12.0, 0.6, 0.3);
        p.peak = cases[c].peak;
        p.bow = cases[c].bow;
        p.variation = cases[c].variation;
        p.breaking = cases[c].breaking != 0;
        p.break_time = 0.0;
        p.break_drop = 0.5;
        tl_giant g;
        tl_giant_prepare(&g, &p, cases[c].t);
        /* Where the model's second derivatives jump: across (w) and along (s0). */
        double H = g.half_width, fa = g.falloff_across, hl = g.half_length, fl = g.falloff_along;
        double joints_w[8] = {g.peak, H - fa, fa - H, H, -H, g.peak, g.peak, g.peak};
        if (g.breaks) {
            double age = g.break_age, T = g.throw_time, v = g.peel_speed;
            joints_w[5] = g.peak + v * (age - T);
            joints_w[6] = g.peak - v * (age - T);
            joints_w[7] = g.peak + v * (age - 3.0 * T);
        }
        const double joints_s0[4] = {hl, -hl, hl + fl, -hl - fl};
        double worst = 0.0;
        int compared = 0;
        for (int j = 0; j <= 80; j++)
            for (int i = 0; i <= 400; i++) {
                double s = -g.reach_along + 2.0 * g.reach_along * (i + 0.37) / 400.0;
                double w = -H + 2.0 * H * (j + 0.41) / 81.0, x, z;
                world_at(&g, s, w, &x, &z);
                tl_giant_sample smp;
                tl_giant_sample_at(&g, x, z, 40, &smp);
                int near = smp.lambda <= 0.0;
                for (int k = 0; k < 8; k++)
                    near |= fabs(w - joints_w[k]) < 0.05;
                for (int k = 0; k < 4; k++)
                    near |= fabs(smp.s0 - joints_s0[k]) < 0.05;
                if (near)
                    continue;
                double gx =
                    (tl_giant_height(&g, x + e, z, 40) - tl_giant_height(&g, x - e, z, 40)) /
                    (2 * e);
                double gz =
                    (tl_giant_height(&g, x, z + e, 40) - tl_giant_height(&g, x, z - e, 40)) /
                    (2 * e);
                double rel = hypot(gx - smp.grad[0], gz - smp.grad[1]) /
                             fmax(1.0, hypot(smp.grad[0], smp.grad[1]));
                worst = fmax(worst, rel);
                compared++;
            }
        printf("gradient, peak %+g m, bow %g m, variation %g%s: %d points, worst relative "
               "difference from central differences %.2g\n",
               p.peak, p.bow, p.variation, g.breaks ? ", breaking" : "", compared, worst);
        CHECK(compared > 25000);
        CHECK(worst < 1e-6);
    }
}

/* The break's shader code (TL_FEATURE_GIANT_BREAK) is compiled only once
 * the break has begun at the peak: not before giant.break_time, not with
 * giant.breaking off, not without the wave; and then only with the wave. */
static void test_break_feature(void)
{
    struct {
        int breaking;
        double t, fade;
        int wave, brk;
    } cases[] = {
        {1, 4.9, 1.0, 1, 0},  {1, 5.0, 1.0, 1, 0},  {1, 5.1, 1.0, 1, 1},
        {1, 60.0, 1.0, 1, 1}, {0, 60.0, 1.0, 1, 0}, {1, 60.0, 0.0, 0, 0},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        tl_scene s;
        tl_scene_defaults(&s);
        s.giant.enabled = true;
        s.giant.breaking = cases[c].breaking != 0;
        s.giant.break_time = 5.0;
        s.giant.fade = cases[c].fade;
        s.time = cases[c].t;
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &w, &u);
        CHECK(!!(u.features & TL_FEATURE_GIANT_WAVE) == cases[c].wave);
        CHECK(!!(u.features & TL_FEATURE_GIANT_BREAK) == cases[c].brk);
        if (cases[c].brk)
            CHECK_NEAR(u.giant_break[0], cases[c].t - 5.0, 1e-5);
    }
}

/* A scripted crest stays green until it breaks: before giant.break_time
 * the most compressed point of a steep crest foams at most
 * TL_GIANT_UNBROKEN_FOAM of what the same crest without a script does
 * there, and the shader gets the same weight (u_giant_compression_foam);
 * once the lip has landed there it foams as much as the unscripted one. */
static void test_unbroken_foam(void)
{
    double coverage[3];
    for (int k = 0; k < 3; k++) {
        tl_scene s;
        tl_scene_defaults(&s);
        s.giant.enabled = true;
        s.giant.height = 16.0;
        s.giant.steepness = 0.75;
        s.giant.curve_strength = 0.6;
        s.giant.breaking = k > 0;
        s.giant.break_time = k == 2 ? -30.0 : 5.0; /* k = 2: long broken everywhere */
        s.giant.break_drop = 0.0;
        s.time = 0.0;
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        /* The least Jacobian along the centre line. */
        tl_giant_sample best = {0};
        best.jacobian = 1e9;
        for (int i = 0; i <= 2000; i++) {
            double sv = -g.reach_along + 2.0 * g.reach_along * i / 2000.0, x, z;
            world_at(&g, sv, 0.0, &x, &z);
            tl_giant_sample smp;
            tl_giant_sample_at(&g, x, z, 40, &smp);
            if (smp.jacobian < best.jacobian)
                best = smp;
        }
        coverage[k] =
            tl_giant_foam_coverage(&g, &best, 1.0, s.giant.foam_compression, s.giant.foam_trail);
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &w, &u);
        CHECK_NEAR(u.giant_compression_foam, k ? TL_GIANT_UNBROKEN_FOAM : 1.0, 1e-7);
        CHECK(k != 1 || u.giant_foam[3] == 0.0f);
    }
    printf("foam at the most compressed point: no script %.3f, scripted before the break "
           "%.3f, after %.3f\n",
           coverage[0], coverage[1], coverage[2]);
    CHECK(coverage[0] > 0.5);
    CHECK(coverage[1] <= TL_GIANT_UNBROKEN_FOAM * coverage[0] + 1e-12);
    CHECK(coverage[2] >= coverage[0] - 1e-9);
}

int main(void)
{
    test_wave_slope_constant();
    test_jacobian_positive();
    test_clamps();
    test_geometry();
    test_off();
    test_travel();
    test_inversion_and_slope();
    test_surface();
    test_ride();
    test_peak_highest();
    test_bow_lags();
    test_no_steep_shoulder();
    test_bounds_hold();
    test_gradient_matches();
    test_break_feature();
    test_unbroken_foam();
    TEST_END();
}
