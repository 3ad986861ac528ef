/* The giant wave's lip and spray: the CPU mirror's geometry (the heights a
 * vertical line meets are the tube's boundary, the lip is anchored on the
 * crest's top, it exists only while it is thrown), the spray's density and
 * box, the features that compile them, and the GPU's lip and spray against
 * the CPU near the origin and 1e4 m out at t = 1e5 s. */
#include <math.h>
#include <string.h>

#include "tl_breaking_test.h"
#include "waves/tl_bow_spray.h"
#include "waves/tl_giant_spray.h"

static double smoothstep_test(double e0, double e1, double x)
{
    x = (x - e0) / (e1 - e0);
    x = x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
    return x * x * (3.0 - 2.0 * x);
}

static double base_of(const tl_scene *s)
{
    return -0.5 * s->ocean.depth;
}

/* The scene of breaking_scene 2 s into the break, its wave and the lip
 * at its peak (thrown, not yet landed); returns the ocean's mean level. */
static double thrown_lip(tl_scene *s, tl_giant *g, tl_giant_lip *lip)
{
    breaking_scene(s, 10.0, 2.0, 0.0, 0.0);
    tl_giant_prepare(g, &s->giant, s->time);
    tl_giant_lip_at(g, s->giant.peak, base_of(s), lip);
    return base_of(s);
}

/* A level hull of 9 m with its stem at `stem`, heading (x, z). */
static const tl_giant_hull *level_hull(tl_giant_hull *h, const double stem[3],
                                       const double heading[2])
{
    h->length = 9.0;
    h->heading[0] = heading[0];
    h->heading[1] = heading[1];
    for (int i = 0; i < 3; i++)
        h->stem[i] = stem[i];
    h->stern[0] = stem[0] - 9.0 * heading[0];
    h->stern[1] = stem[1];
    h->stern[2] = stem[2] - 9.0 * heading[1];
    return h;
}

/* Every height tl_giant_lip_heights returns lies on the tube's boundary,
 * and the points between consecutive heights alternate inside and outside
 * it, starting inside just above the floor when the lowest is an exit. */
static void test_lip_heights(void)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 2.0, 0.0, 0.0);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    CHECK(g.breaks);
    int lines = 0, crossings = 0;
    for (int iw = 0; iw < 9; iw++) {
        double w = s.giant.peak + 2.0 * (iw - 4);
        tl_giant_lip lip;
        tl_giant_lip_at(&g, w, base_of(&s), &lip);
        CHECK(lip.present);
        for (int is = 0; is < 40; is++) {
            double sv = lip.center[0] - 1.2 * lip.radius + 2.4 * lip.radius * is / 39.0;
            double x = g.origin[0] + g.dir[0] * sv + g.across[0] * w;
            double z = g.origin[1] + g.dir[1] * sv + g.across[1] * w;
            double h[8];
            int n = tl_giant_lip_heights(&g, x, z, -1e9, base_of(&s), h, 8);
            lines += n > 0;
            crossings += n;
            CHECK(n % 2 == 0); /* a closed tube: in and out */
            for (int i = 0; i < n; i++) {
                CHECK_NEAR(tl_giant_lip_distance(&lip, sv, h[i]), 0.0, 1e-6);
                if (i > 0)
                    CHECK(h[i] > h[i - 1]);
                if (i + 1 < n) {
                    double mid = 0.5 * (h[i] + h[i + 1]);
                    double d = tl_giant_lip_distance(&lip, sv, mid);
                    CHECK(i % 2 == 0 ? d < 0.0 : d > 0.0);
                }
            }
            if (n > 0)
                CHECK(tl_giant_lip_distance(&lip, sv, h[n - 1] + 0.01) > 0.0);
        }
    }
    printf("lip: %d of 360 vertical lines cross it, %d crossings\n", lines, crossings);
    CHECK(lines > 100);
}

/* Behind the crest's top the wave's back is the only surface: the tube's
 * root, which would stand above a back that falls away, is cut there. */
static void test_lip_behind_top(void)
{
    /* The cut is the vertical through the arc's centre: the crest's top
     * only while the anchor is straight up. */
    CHECK(TL_GIANT_LIP_ANCHOR == 0.0);
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        breaking_scene(&s, 10.0, k == 0 ? 2.0 : 4.5, 0.0, 0.0);
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        int behind = 0, front = 0;
        for (int iw = 0; iw < 9; iw++) {
            double w = s.giant.peak + 3.0 * (iw - 4);
            tl_giant_lip lip;
            tl_giant_lip_at(&g, w, base_of(&s), &lip);
            if (!lip.present)
                continue;
            for (int is = 0; is < 30; is++) {
                double sv = lip.center[0] + lip.radius * (is - 20) / 10.0, h[8];
                double x = g.origin[0] + g.dir[0] * sv + g.across[0] * w;
                double z = g.origin[1] + g.dir[1] * sv + g.across[1] * w;
                int n = tl_giant_lip_heights(&g, x, z, -1e9, base_of(&s), h, 8);
                if (sv < lip.center[0])
                    behind += n;
                else
                    front += n;
            }
        }
        printf("lip behind the crest's top: %d crossings (in front %d)\n", behind, front);
        CHECK(behind == 0);
        CHECK(front > 0);
    }
}

/* The lip is thrown out over the face (TL_GIANT_LIP_THROW): once it has
 * thrown, a vertical line in front of the crest's top meets the face,
 * then air (the barrel), then the lip; a circle's arc lay on the face.
 * And the march's bound never exceeds the distance to the tube's surface
 * (found by brute force over the cross-section), so it steps over none. */
static void test_lip_barrel(void)
{
    tl_scene s;
    tl_giant g;
    tl_giant_lip lip;
    const double base = thrown_lip(&s, &g, &lip), w = s.giant.peak;
    CHECK(lip.present && lip.progress > 0.8 && lip.spent == 0.0);
    double dl, height = tl_giant_lambda(&g, w, &dl) * g.amplitude, gap = 0.0;
    for (int is = 0; is <= 200; is++) {
        double sv = lip.center[0] + TL_GIANT_LIP_THROW * lip.radius * is / 200.0, h[8];
        double x = g.origin[0] + g.dir[0] * sv + g.across[0] * w;
        double z = g.origin[1] + g.dir[1] * sv + g.across[1] * w;
        if (tl_giant_lip_heights(&g, x, z, -1e9, base, h, 8) > 0)
            gap = fmax(gap, h[0] - (base + tl_giant_height(&g, x, z, 8)));
    }
    printf("lip's barrel: up to %.2f m of air under the lip (the crest %.2f m high)\n", gap,
           height);
    CHECK(gap > 0.25 * height);

    /* The bound against the distance, on points round the tube. */
    const int n = 500;
    const double reach = TL_GIANT_LIP_THROW * lip.radius + 2.0 * lip.thickness;
    const double step = 2.0 * reach / n;
    static double inside[2][250000];
    int count = 0;
    for (int i = 0; i < n && count < 250000; i++)
        for (int j = 0; j < n && count < 250000; j++) {
            double sv = lip.center[0] - reach + step * i, y = lip.center[1] - reach + step * j;
            if (tl_giant_lip_distance(&lip, sv, y) < 0.0) {
                inside[0][count] = sv;
                inside[1][count++] = y;
            }
        }
    CHECK(count > 100 && count < 250000);
    int probes = 0, over = 0;
    double worst = 0.0;
    for (int i = 0; i < 40; i++)
        for (int j = 0; j < 40; j++) {
            double sv = lip.center[0] - reach + 2.0 * reach * (i + 0.37) / 40.0;
            double y = lip.center[1] - reach + 2.0 * reach * (j + 0.61) / 40.0, bound;
            if (tl_giant_lip_distance_bounded(&lip, sv, y, &bound) <= 0.0)
                continue;
            double nearest = 1e30;
            for (int k = 0; k < count; k++)
                nearest = fmin(nearest, hypot(inside[0][k] - sv, inside[1][k] - y));
            probes++;
            /* The march steps 0.8 of it (lip.glsl's TL_GIANT_LIP_RELAX):
             * the bound takes the tube's thickness at the point's own
             * angle, and near the centre a thicker stretch of the arc
             * (toward its root) lies a little nearer. */
            worst = fmax(worst, bound / (nearest + step));
            over += 0.8 * bound > nearest + step;
        }
    printf("lip's march bound: at most %.3f of the distance; 0.8 of it above at %d of %d points\n",
           worst, over, probes);
    CHECK(probes > 1000);
    CHECK(over == 0);
}

/* The lowest point of the lip's tube over (s, y) columns at s: scanned
 * down from above the arc in 1 cm steps; NAN where the column misses it. */
static double lip_underside(const tl_giant_lip *lip, double sv)
{
    double top = lip->center[1] + lip->radius + 2.0 * lip->thickness, lowest = NAN;
    for (double y = top; y > lip->center[1] - 2.0 * lip->radius; y -= 0.01)
        if (tl_giant_lip_distance(lip, sv, y) < 0.0)
            lowest = y;
    return lowest;
}

/* The barrel's roof (TL_GIANT_LIP_FILLET): where a thrown lip leaves the
 * face its underside curves down to it instead of meeting it at a crease.
 * Where the air under an even tube first reaches a twentieth of the
 * crest's height, the roof leaves less than half of it; past the roof's
 * arc the underside is the tube's as before; the outer side is untouched;
 * and a short throw has no roof. */
static void test_lip_roof(void)
{
    tl_scene s;
    tl_giant g;
    tl_giant_lip lip;
    const double base = thrown_lip(&s, &g, &lip), w = s.giant.peak;
    CHECK(lip.present && lip.spent == 0.0);
    CHECK(fabs(lip.fillet - TL_GIANT_LIP_FILLET * lip.radius) < 1e-9);
    tl_giant_lip plain = lip;
    plain.fillet = 0.0;
    double dl, height = tl_giant_lambda(&g, w, &dl) * g.amplitude;
    /* Where the air under the even tube first reaches a twentieth of the
     * crest's height (the crease lies just behind), the roof leaves less
     * than half of it: the underside comes down to the face. */
    double at = NAN, roof_air = NAN, plain_air = NAN;
    for (int i = 1; i <= 400 && isnan(at); i++) {
        double sv = lip.center[0] + TL_GIANT_LIP_THROW * lip.radius * i / 400.0;
        double x = g.origin[0] + g.dir[0] * sv + g.across[0] * w;
        double z = g.origin[1] + g.dir[1] * sv + g.across[1] * w;
        double face = base + tl_giant_height(&g, x, z, 8);
        plain_air = lip_underside(&plain, sv) - face;
        if (plain_air > 0.05 * height) {
            at = sv - lip.center[0];
            roof_air = fmax(lip_underside(&lip, sv) - face, 0.0);
        }
    }
    /* Past the roof's arc (and its reach) the two undersides agree. */
    double beyond = 1.2 * TL_GIANT_LIP_FILLET_ARC * (M_PI / 180.0), worst = 0.0;
    double r_in = lip.radius - tl_giant_lip_half_thickness(&lip, beyond);
    double sv = lip.center[0] + TL_GIANT_LIP_THROW * r_in * sin(beyond);
    worst = fabs(lip_underside(&lip, sv) - lip_underside(&plain, sv));
    /* The outer side at the crest's top is where it was. */
    double outer = 0.0;
    for (double y = lip.center[1] + 2.0 * lip.radius; y > lip.center[1]; y -= 0.001)
        if (tl_giant_lip_distance(&lip, lip.center[0] + 0.01, y) < 0.0) {
            outer = y - (lip.center[1] + lip.radius + tl_giant_lip_half_thickness(&lip, 0.0));
            break;
        }
    printf("lip's roof: %.2f m thick at the root; %.2f m out from the crest's top %.2f m of air "
           "under an even tube, %.2f m under the roof; past its arc the undersides differ by "
           "%.3f m, the outer side by %.3f m\n",
           lip.fillet, at, plain_air, roof_air, worst, outer);
    CHECK(!isnan(at) && roof_air < 0.5 * plain_air);
    CHECK(worst < 0.02);
    CHECK(fabs(outer) < 0.01);

    /* Early in the throw (its end short of FILLET_FROM past the top) there
     * is no roof. */
    int short_throws = 0;
    for (double age = 0.01; age < 2.0; age += 0.01) {
        breaking_scene(&s, 10.0, age, 0.0, 0.0);
        tl_giant_prepare(&g, &s.giant, s.time);
        tl_giant_lip_at(&g, w, base_of(&s), &lip);
        if (lip.present && lip.to < TL_GIANT_LIP_FILLET_FROM * (M_PI / 180.0)) {
            short_throws++;
            CHECK(lip.fillet == 0.0);
        }
    }
    CHECK(short_throws > 5);
}

/* The lip's outer surface passes through the crest's top at its anchor
 * angle once the throw has passed it by the edge's arc (before, the thin
 * edge lies inside the crest, under its top); the lip is thrown further
 * the older the break, and exists only from the break's start until it
 * has thinned away. */
static void test_lip_life(void)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 1.0, 0.0, 0.0);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    double w = s.giant.peak, dl, db;
    tl_giant_lip lip;
    tl_giant_lip_at(&g, w, base_of(&s), &lip);
    CHECK(lip.present);
    double anchor = TL_GIANT_LIP_ANCHOR * M_PI / 180.0,
           edge_arc = TL_GIANT_LIP_EDGE_ARC * M_PI / 180.0;
    /* The tube's outer surface, not its centre line, holds the crest's top
     * (0.7 of the throw's time into the break). */
    {
        tl_scene later;
        breaking_scene(&later, 10.0, 0.7 * g.throw_time, 0.0, 0.0);
        tl_giant gl;
        tl_giant_prepare(&gl, &later.giant, later.time);
        tl_giant_lip held;
        tl_giant_lip_at(&gl, w, base_of(&later), &held);
        double lam = tl_giant_lambda(&gl, w, &dl);
        double hs = tl_giant_bow(&gl, w, &db) + lam * gl.curl / gl.k;
        double hy = base_of(&later) + lam * gl.amplitude;
        CHECK(held.present && held.to > anchor + edge_arc);
        double outer = held.radius + tl_giant_lip_half_thickness(&held, anchor);
        CHECK_NEAR(held.center[0] + outer * sin(anchor), hs, 1e-9);
        CHECK_NEAR(held.center[1] + outer * cos(anchor), hy, 1e-9);
        CHECK_NEAR(tl_giant_lip_distance(&held, hs, hy), 0.0, 1e-9);
    }
    /* Where the throw has just passed the top (toward the peel's front),
     * the edge is thin: a point on the arc's centre line past its end is
     * covered by less than the root's half thickness, and the crest's top
     * lies outside the tube. */
    double front = w, step = 0.05;
    tl_giant_lip at_front;
    for (double x = w; x < w + 40.0; x += step) {
        tl_giant_lip_at(&g, x, base_of(&s), &at_front);
        if (at_front.present && at_front.to > anchor + 0.2 * edge_arc)
            front = x;
    }
    tl_giant_lip_at(&g, front, base_of(&s), &at_front);
    double root = at_front.thickness *
                  (1.0 - (1.0 - TL_GIANT_LIP_TIP) * (anchor - TL_GIANT_LIP_ROOT * M_PI / 180.0) /
                             (TL_GIANT_LIP_SWEEP * M_PI / 180.0));
    double edge = tl_giant_lip_half_thickness(&at_front, at_front.to);
    printf("lip at the peel's front (%.2f m from the peak, %.1f deg past the top): edge %.3f m "
           "against a root of %.3f m\n",
           front - w, (at_front.to - anchor) * 180.0 / M_PI, edge, root);
    CHECK(at_front.to - anchor < edge_arc);
    CHECK(edge < 0.3 * root); /* fresh, short of the tearing: no lumps here */
    double lambda_f = tl_giant_lambda(&g, front, &dl);
    double top_s_f = tl_giant_bow(&g, front, &db) + lambda_f * g.curl / g.k;
    CHECK(tl_giant_lip_distance(&at_front, top_s_f, base_of(&s) + lambda_f * g.amplitude) > 0.0);
    /* Further from the peak the break is younger: a shorter arc. */
    tl_giant_lip side;
    tl_giant_lip_at(&g, w + 5.0, base_of(&s), &side);
    CHECK(side.present && side.to < lip.to);
    CHECK(side.to - side.from >= 0.0);
    /* At the peak: none before the break, one while it is thrown, none
     * once it has thinned away there (it goes on along the crest, so the
     * frame still compiles it), and none anywhere once the break has run
     * the crest's whole length. */
    double T = g.throw_time;
    const double ages[4] = {-0.5, 1.0, T * (1.0 + TL_GIANT_LIP_FADE) + 0.1, 60.0};
    for (int k = 0; k < 4; k++) {
        breaking_scene(&s, 10.0, ages[k], 0.0, 0.0);
        tl_giant_prepare(&g, &s.giant, s.time);
        tl_giant_lip_at(&g, s.giant.peak, base_of(&s), &lip);
        CHECK(lip.present == (k == 1));
        tl_waves waves;
        tl_waves_init(&waves, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &waves, &u);
        CHECK(!!(u.features & TL_FEATURE_GIANT_LIP) == (k == 1 || k == 2));
        CHECK(!!(u.features & TL_FEATURE_GIANT_BREAK) == (k != 0));
    }
    breaking_scene(&s, 10.0, 1.0, 0.0, 0.0);
    tl_giant_prepare(&g, &s.giant, s.time);
    tl_giant_lip_at(&g, s.giant.peak + 7.0 * 1.0 + 3.0, base_of(&s), &lip);
    CHECK(!lip.present); /* the break has run 7 m along the crest in 1 s (rounded at the peak) */
    s.giant.breaking = false;
    tl_giant_prepare(&g, &s.giant, s.time);
    tl_giant_lip_at(&g, s.giant.peak, base_of(&s), &lip);
    CHECK(!lip.present);
    double box[4], across[2];
    CHECK(!tl_giant_lip_bounds(&g, base_of(&s), box, across));
}

/* The lip's box holds every point the tube covers. */
static void test_lip_bounds(void)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 2.5, 0.0, 0.0);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    double box[4], across[2];
    CHECK(tl_giant_lip_bounds(&g, base_of(&s), box, across));
    int inside = 0;
    for (int iw = 0; iw <= 200; iw++) {
        double w = -g.half_width + 2.0 * g.half_width * iw / 200.0;
        tl_giant_lip lip;
        tl_giant_lip_at(&g, w, base_of(&s), &lip);
        if (!lip.present)
            continue;
        for (int i = 0; i < 64; i++)
            for (int j = 0; j < 64; j++) {
                double sv = box[0] - 5.0 + (box[1] - box[0] + 10.0) * i / 63.0;
                double y = box[2] - 5.0 + (box[3] - box[2] + 10.0) * j / 63.0;
                if (tl_giant_lip_distance(&lip, sv, y) < 0.0) {
                    inside++;
                    CHECK(sv >= box[0] && sv <= box[1] && y >= box[2] && y <= box[3]);
                    CHECK(w >= across[0] && w <= across[1]);
                }
            }
    }
    CHECK(inside > 0);
}

/* The spray: none at giant.spray 0; spindrift above and behind the crest's
 * top, none far ahead of it (but for the lip's torn edge, thrown ahead of
 * it) or far above it; every point with spray inside
 * its box; a burst at a bow that meets a rising face. */
static void test_spray_density(void)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 1.0, 0.0, 0.0);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    tl_giant_spray sp;
    tl_giant_hull hull;
    tl_giant_spray_prepare(&sp, &g, 0.0, 8.0, s.time, s.ocean.depth, NULL);
    CHECK(!sp.active);
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, NULL);
    CHECK(sp.active && sp.bow_amount == 0.0);
    double dl, db, most = 0.0, ahead = 0.0;
    int outside = 0;
    for (int iw = 0; iw < 20; iw++) {
        double w = -60.0 + 6.0 * iw, lambda = tl_giant_lambda(&g, w, &dl);
        double top_s = tl_giant_bow(&g, w, &db) + lambda * g.curl / g.k;
        double top_y = base_of(&s) + lambda * g.amplitude;
        /* The lip's torn edge, thrown ahead of the top, is not spindrift. */
        tl_giant_lip lip;
        tl_giant_lip_at(&g, w, base_of(&s), &lip);
        double tip_s = lip.center[0] + lip.radius * TL_GIANT_LIP_THROW * sin(lip.to);
        double tip_y = lip.center[1] + lip.radius * cos(lip.to);
        double torn_reach = 3.0 * TL_SPRAY_TIP_RADIUS * lip.radius;
        for (int i = 0; i < 60; i++)
            for (int j = 0; j < 30; j++) {
                double sv = top_s - 40.0 + 60.0 * i / 59.0, y = top_y - 5.0 + 15.0 * j / 29.0;
                if (lip.present && hypot(sv - tip_s, y - tip_y) < torn_reach)
                    continue;
                double x = g.origin[0] + g.dir[0] * sv + g.across[0] * w;
                double z = g.origin[1] + g.dir[1] * sv + g.across[1] * w;
                double d = tl_giant_spray_density(&sp, &g, x, y, z, 0.0);
                /* no bow here: the spindrift alone */
                CHECK(d >= 0.0 &&
                      d <= TL_SPRAY_PLUME_GAIN * (1.0 + TL_SPRAY_ROOT_GAIN) * sp.amount);
                if (sv > top_s + 2.0)
                    ahead = fmax(ahead, d);
                else
                    most = fmax(most, d);
                if (d > 0.0 && (sv < sp.box[0] || sv > sp.box[1] || y < sp.box[2] || y > sp.box[3]))
                    outside++;
            }
    }
    printf("spray: densest behind the crest %.3f, ahead of it %.3g\n", most, ahead);
    CHECK(most > 0.3 * TL_SPRAY_PLUME_GAIN);
    CHECK(ahead < 1e-3 * most);
    CHECK(outside == 0);
    /* The plume leaves the top steeply: a quarter of its reach back, its
     * densest height stands half its full lift over the crest's top (the
     * square root's), where a lift in proportion would stand a quarter;
     * the full lift is the gust's share at that w, which varies along the
     * crest. The streaks are averaged out over the wind's drift. */
    {
        const double ws[3] = {-30.0, 0.0, 25.0};
        double least = 1e30, most_lift = 0.0;
        for (int k = 0; k < 3; k++) {
            double w = ws[k], lambda = tl_giant_lambda(&g, w, &dl);
            double top_s = tl_giant_bow(&g, w, &db) + lambda * g.curl / g.k - 0.25 * sp.reach;
            double top_y = base_of(&s) + lambda * g.amplitude;
            double rise = TL_SPRAY_RISE * (lambda * g.amplitude + sp.reach);
            double lift = TL_SPRAY_LIFT * rise * tl_giant_spray_gust(w), best = -1.0, best_up = 0.0;
            double x = g.origin[0] + g.dir[0] * top_s + g.across[0] * w;
            double z = g.origin[1] + g.dir[1] * top_s + g.across[1] * w;
            tl_giant_spray drifting = sp;
            for (int j = 0; j <= 300; j++) {
                double up = -rise + j * (lift + rise) / 300.0, sum = 0.0;
                for (int d = 0; d < 64; d++) {
                    drifting.drift = 0.37 * d;
                    sum += tl_giant_spray_density(&drifting, &g, x, top_y + up, z, 0.0);
                }
                if (sum > best) {
                    best = sum;
                    best_up = up;
                }
            }
            printf("spray at w %g: a quarter reach back, densest %.2f m over the top (its full "
                   "lift %.2f m)\n",
                   w, best_up, lift);
            CHECK(best > 0.0);
            CHECK(best_up > 0.4 * lift && best_up < 0.6 * lift);
            least = fmin(least, lift);
            most_lift = fmax(most_lift, lift);
        }
        CHECK(most_lift > 1.2 * least); /* gusts: not one even haze along the crest */
    }
    /* A bow on the rising face ahead of the crest, heading into it. */
    double sv = g.curl / g.k + 10.0;
    double bow[3] = {g.origin[0] + g.dir[0] * sv + g.across[0] * 10.0, 5.0,
                     g.origin[1] + g.dir[1] * sv + g.across[1] * 10.0};
    const double into[2] = {-g.dir[0], -g.dir[1]};
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, level_hull(&hull, bow, into));
    CHECK(sp.bow_amount > 0.0);
    const double along[2] = {g.across[0], g.across[1]}; /* along the crest: no slope ahead */
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, level_hull(&hull, bow, along));
    CHECK(sp.bow_amount < 0.5 * TL_SPRAY_BOW_GAIN * 1.5);
    bow[0] = g.origin[0] + g.dir[0] * 400.0; /* far ahead of the wave: calm water */
    bow[2] = g.origin[1] + g.dir[1] * 400.0;
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, level_hull(&hull, bow, into));
    CHECK(sp.bow_amount == 0.0);
    /* Without a break the box is the plume's alone: tight around the thin
     * plume (its floor far above the wave's foot, where the shader's few
     * steps would be wasted), and the plume has faded to nothing at its
     * far end. */
    s.giant.breaking = false;
    tl_giant_prepare(&g, &s.giant, s.time);
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, NULL);
    CHECK(sp.active);
    printf("spray box without a break: y %.2f .. %.2f m over a foot at %.2f m\n", sp.box[2],
           sp.box[3], base_of(&s));
    CHECK(sp.box[2] > base_of(&s) + 0.1 * g.amplitude);
    double lambda = tl_giant_lambda(&g, 0.0, &dl);
    double top_s = tl_giant_bow(&g, 0.0, &db) + lambda * g.curl / g.k;
    double far_s = top_s - TL_SPRAY_REACHES * sp.reach, far_y = base_of(&s) + lambda * g.amplitude;
    double worst = 0.0;
    for (int j = 0; j < 40; j++)
        worst = fmax(worst, tl_giant_spray_density(&sp, &g, g.origin[0] + g.dir[0] * far_s,
                                                   far_y - 5.0 + 0.5 * j,
                                                   g.origin[1] + g.dir[1] * far_s, 0.0));
    CHECK(worst == 0.0);
}

/* The plume's layer over a step's height: the mean of exp(-x²/r²) over
 * the span, against a fine midpoint sum, on both sides of the series'
 * threshold (a tenth of the rise) and across it without a jump; at span 0
 * the point value. */
static void test_spray_layer(void)
{
    const double r = 1.3;
    double worst = 0.0;
    for (int i = 0; i <= 40; i++) {
        double x = -4.0 + 0.2 * i;
        CHECK_NEAR(tl_giant_spray_layer(x, r, 0.0), exp(-x * x / (r * r)), 1e-15);
        const double spans[] = {0.05, 0.2599, 0.2601, 1.0, 3.0, 12.0};
        for (size_t k = 0; k < sizeof spans / sizeof spans[0]; k++) {
            const int n = 20000;
            double h = 0.5 * spans[k], sum = 0.0;
            for (int j = 0; j < n; j++) {
                double y = x - h + 2.0 * h * (j + 0.5) / n;
                sum += exp(-y * y / (r * r));
            }
            worst = fmax(worst, fabs(tl_giant_spray_layer(x, r, spans[k]) - sum / n));
        }
    }
    printf("spray layer: mean over a span against a midpoint sum: %.2g\n", worst);
    CHECK(worst < 1e-6);
}

/* The lumps (TL_GIANT_LIP_LUMP): a fresh sheet is smooth away from its
 * free edge (factor 1), torn at it; once landed, the whole tube is
 * lumped, within 1 -+ TL_GIANT_LIP_LUMP and spanning most of that. */
static void test_lip_lumps(void)
{
    const double ages[2] = {2.5, 4.5};
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        breaking_scene(&s, 10.0, ages[k], 0.0, 0.0);
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        double lo = 2.0, hi = 0.0, smooth = 0.0, edge = 0.0;
        int samples = 0;
        for (int iw = 0; iw <= 40; iw++) {
            tl_giant_lip lip;
            tl_giant_lip_at(&g, s.giant.peak - 10.0 + 0.5 * iw, base_of(&s), &lip);
            if (!lip.present)
                continue;
            for (int ia = 0; ia <= 20; ia++) {
                double angle = lip.from + (lip.to - lip.from) * ia / 20.0;
                double along = (angle - TL_GIANT_LIP_ROOT * M_PI / 180.0) /
                               (TL_GIANT_LIP_SWEEP * M_PI / 180.0);
                double f = tl_giant_lip_lump(&lip, angle);
                lo = fmin(lo, f);
                hi = fmax(hi, f);
                if (along < 0.7)
                    smooth = fmax(smooth, fabs(f - 1.0) * (lip.spent == 0.0));
                else
                    edge = fmax(edge, fabs(f - 1.0));
                samples++;
            }
        }
        printf("lip lumps, age %g s: %d samples, factor %.3f .. %.3f; fresh away from the edge "
               "within %.3g of 1, at the edge %.3f\n",
               ages[k], samples, lo, hi, smooth, edge);
        CHECK(samples > 100);
        CHECK(lo >= 1.0 - TL_GIANT_LIP_LUMP - 1e-12 && hi <= 1.0 + TL_GIANT_LIP_LUMP + 1e-12);
        if (k == 0) {
            CHECK(smooth == 0.0);
            CHECK(edge > 0.05);
        } else {
            CHECK(hi - lo > TL_GIANT_LIP_LUMP);
        }
    }
}

/* The bow's burst starts from the stem where the pitched hull has it: a
 * boat bow down on the face has its stem half a hull's length times the
 * pitch's sine below its middle, and the burst's centre drops with it
 * (taken level, it rose from the crest beside the boat). */
static void test_bow_burst_pitched(void)
{
    double centre_y[2], centre_s[2];
    const double pitches[2] = {0.0, -0.6};
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        breaking_scene(&s, 10.0, 0.0, 0.0, 0.0);
        s.giant.breaking = false;
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        /* On the face ahead of the crest, heading down it, the stern
         * clear of the crest (no crossing yet). */
        double sv = g.curl / g.k + 9.0;
        s.boat.enabled = s.boat.visible = true;
        s.boat.length = 9.0;
        s.boat.beam = 3.0;
        s.boat.position[0] = g.origin[0] + g.dir[0] * sv;
        s.boat.position[1] = 8.0;
        s.boat.position[2] = g.origin[1] + g.dir[1] * sv;
        s.boat.heading = atan2(g.dir[0], g.dir[1]);
        s.boat.pitch = pitches[k];
        tl_waves waves;
        tl_waves_init(&waves, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &waves, &u);
        CHECK(u.features & TL_FEATURE_GIANT_SPRAY);
        CHECK(u.giant_spray_bow[3] > 0.0f);
        centre_y[k] = u.giant_spray_bow[1];
        centre_s[k] = g.dir[0] * (u.giant_spray_bow[0] + s.camera.position[0] - g.origin[0]) +
                      g.dir[1] * (u.giant_spray_bow[2] + s.camera.position[2] - g.origin[1]);
    }
    printf("bow burst: centre %.3f m up, %.3f m along level; %.3f, %.3f bow down\n", centre_y[0],
           centre_s[0], centre_y[1], centre_s[1]);
    CHECK(fabs((centre_y[0] - centre_y[1]) - 4.5 * sin(0.6)) < 1e-3);
    CHECK(fabs((centre_s[0] - centre_s[1]) - 4.5 * (1.0 - cos(0.6))) < 1e-3);
}

/* Where the crest passes under a hull heading into the wave, the burst
 * stands over the crest at full strength with the crossing's radius; the
 * crest far ahead of the bow on the wave's gentle front throws none; a
 * hull beam on to the crest does not split it. As the crest sweeps along
 * the hull the burst never goes out and its centre and radius move
 * smoothly (no jump between frames). */
static void test_crossing_burst(void)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 0.0, 0.0, 0.0);
    s.giant.breaking = false;
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    const double w = s.giant.peak, L = 9.0;
    double dl, db, lambda = tl_giant_lambda(&g, w, &dl);
    double top_s = tl_giant_bow(&g, w, &db) + lambda * g.curl / g.k;
    double top_y = base_of(&s) + lambda * g.amplitude;
    const double into[2] = {-g.dir[0], -g.dir[1]};
    tl_giant_spray sp;
    tl_giant_hull hull;
    double stem[3];
    /* The hull's middle at crest + `mid` along the travel, level at the top. */
#define AT(mid)                                                                                    \
    (stem[0] = g.origin[0] + g.dir[0] * (top_s + (mid)-0.5 * L) + g.across[0] * w,                 \
     stem[1] = top_y,                                                                              \
     stem[2] = g.origin[1] + g.dir[1] * (top_s + (mid)-0.5 * L) + g.across[1] * w,                 \
     level_hull(&hull, stem, into))
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, AT(0.0));
    printf("crossing burst: amount %.3f, radius %.3f m, centre %.3f m from the crest's top\n",
           sp.bow_amount, sp.bow_radius, sp.bow[1] - top_y);
    CHECK(fabs(sp.bow_amount - TL_SPRAY_CROSS_GAIN * 1.5) < 1e-9);
    CHECK(fabs(sp.bow_radius - TL_SPRAY_CROSS_RADIUS * L) < 1e-9);
    CHECK(fabs(sp.bow[1] - (top_y - 0.1 * sp.bow_radius)) < 1e-9); /* a skirt at the crest */
    /* Split into a wing each side of the hull: over the hull's centre line
     * the spray is thin, out at the wings it is thick (the burst's alone:
     * the spindrift without a hull is taken off). */
    CHECK(fabs(sp.bow_split - TL_SPRAY_CROSS_SPLIT * L) < 1e-9);
    tl_giant_spray plume, open = sp;
    tl_giant_spray_prepare(&plume, &g, 1.5, 8.0, s.time, s.ocean.depth, NULL);
    open.shelter = 0.0; /* the burst over the whole plume */
    double centre_line = 0.0, wings = 0.0;
    for (int i = 0; i < 21; i++)
        for (int j = 0; j < 11; j++)
            for (int side = -1; side <= 1; side++) {
                double a = 0.4 * sp.bow_radius * (i - 10) / 10.0, up = sp.bow_radius * j / 10.0;
                double out = side * sp.bow_split;
                double x = sp.bow[0] + sp.heading[0] * a + sp.heading[1] * out;
                double z = sp.bow[2] + sp.heading[1] * a - sp.heading[0] * out;
                double d = tl_giant_spray_density(&open, &g, x, sp.bow[1] + up, z, 0.0) -
                           tl_giant_spray_density(&plume, &g, x, sp.bow[1] + up, z, 0.0);
                *(side == 0 ? &centre_line : &wings) += side == 0 ? d : 0.5 * d;
            }
    printf("crossing burst split %.2f m: over the hull's centre line %.3f of the wings' spray\n",
           sp.bow_split, centre_line / wings);
    CHECK(wings > 0.0 && centre_line < 0.2 * wings);
    /* The hull has broken the crest's top: behind it, beyond the burst's
     * reach, the plume is gone across the hull, and whole a few radii out
     * along the crest. */
    CHECK(sp.shelter > 0.99);
    {
        double bw =
            g.across[0] * (sp.bow[0] - g.origin[0]) + g.across[1] * (sp.bow[2] - g.origin[1]);
        double behind = top_s - 2.0 * sp.reach, kept[2] = {0.0, 0.0}, whole[2] = {0.0, 0.0};
        for (int k = 0; k < 2; k++)
            for (int j = 0; j < 60; j++) {
                double across = bw + k * 2.0 * TL_SPRAY_SHELTER_OUT * sp.bow_radius;
                double x = g.origin[0] + g.dir[0] * behind + g.across[0] * across;
                double z = g.origin[1] + g.dir[1] * behind + g.across[1] * across;
                double y = top_y - 2.0 + 0.25 * j;
                kept[k] += tl_giant_spray_density(&sp, &g, x, y, z, 0.0);
                whole[k] += tl_giant_spray_density(&plume, &g, x, y, z, 0.0);
            }
        printf("spindrift behind the hull: %.3g of the plume; %.1f radii along the crest %.3g\n",
               kept[0] / whole[0], 2.0 * TL_SPRAY_SHELTER_OUT, kept[1] / whole[1]);
        CHECK(whole[0] > 0.0 && kept[0] < 0.02 * whole[0]);
        CHECK(whole[1] > 0.0 && fabs(kept[1] - whole[1]) < 1e-9 * whole[1]);
    }
    /* The crest 1.5 hull lengths beyond the bow: nothing from the crossing. */
    double far_mid = -(0.5 + 1.5) * L;
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, AT(far_mid));
    CHECK(fabs(sp.bow_radius - TL_SPRAY_CROSS_RADIUS * L) > 1e-6);
    /* Beam on, on the crest: no crossing (the burst, if any, is the bow's). */
    const double beam[2] = {g.across[0], g.across[1]};
    stem[0] = g.origin[0] + g.dir[0] * top_s + g.across[0] * (w + 0.5 * L);
    stem[1] = top_y;
    stem[2] = g.origin[1] + g.dir[1] * top_s + g.across[1] * (w + 0.5 * L);
    tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, level_hull(&hull, stem, beam));
    CHECK(sp.bow_amount == 0.0 || fabs(sp.bow_radius - TL_SPRAY_BOW_RADIUS * L) < 1e-9);
    /* The crest sweeping from just short of the bow to past the stern, in
     * 0.3 m steps: while the burst is dense, no step moves it more than
     * one. */
    double last[4] = {0.0, 0.0, 0.0, 0.0}, worst = 0.0, weakest = 1e30;
    for (int i = 0; i <= 40; i++) {
        double mid = -0.5 * L + 12.0 * i / 40.0 - 0.5;
        tl_giant_spray_prepare(&sp, &g, 1.5, 8.0, s.time, s.ocean.depth, AT(-mid));
        if (mid < 0.5 * L)
            weakest = fmin(weakest, sp.bow_amount);
        if (i > 0 && sp.bow_amount > 0.2 * TL_SPRAY_CROSS_GAIN * 1.5) {
            for (int k = 0; k < 3; k++)
                worst = fmax(worst, fabs(sp.bow[k] - last[k]));
            worst = fmax(worst, fabs(sp.bow_radius - last[3]));
        }
        for (int k = 0; k < 3; k++)
            last[k] = sp.bow[k];
        last[3] = sp.bow_radius;
    }
#undef AT
    printf("crossing burst swept: weakest %.3f while the crest is under the hull, largest step "
           "%.3f m\n",
           weakest, worst);
    CHECK(weakest > 0.8 * TL_SPRAY_CROSS_GAIN * 1.5);
    CHECK(worst < 0.3);
}

/* The burst's self-shade (tl_bow_spray_sheet_depth) is its envelope
 * integrated toward the sun: the closed form matches a midpoint sum along
 * the sun's ray for a low and a high sun and a sheet heading across and
 * along it, and a point on the sheet's sunward side lies in less shade
 * than one on its far side. */
static void test_burst_shade(void)
{
    const double radius = 3.0, headings[2][2] = {{1.0, 0.0}, {0.6, 0.8}};
    const double elevations[2] = {0.15, 0.9};
    double worst = 0.0, near = 0.0, far = 0.0;
    for (int k = 0; k < 8; k++) {
        /* One sheet, and split into wings 2.5 m out. */
        const double *h = headings[k % 2], el = elevations[(k / 2) % 2], az = 0.7;
        const double split = k < 4 ? 0.0 : 2.5;
        const double across = (k < 4 ? 1.3 : TL_BOW_SPRAY_WING) * radius;
        const double sun[3] = {cos(el) * sin(az), sin(el), cos(el) * cos(az)};
        for (int j = -1; j <= 1; j++) {
            const double d[3] = {j * radius * sun[0], j * radius * sun[1] + 0.4,
                                 j * radius * sun[2] - 0.3 + split};
            double closed = tl_bow_spray_sheet_depth(d, h, radius, split, sun), sum = 0.0;
            const double dt = 0.002;
            for (int i = 0; i < 20000; i++) {
                double t = (i + 0.5) * dt;
                const double p[3] = {d[0] + sun[0] * t, d[1] + sun[1] * t, d[2] + sun[2] * t};
                double a = (p[0] * h[0] + p[2] * h[1]) / (0.4 * radius);
                double u = p[1] / (0.9 * radius);
                for (int wing = split > 0.0 ? -1 : 0; wing <= (split > 0.0 ? 1 : 0); wing += 2) {
                    double c = (p[0] * h[1] - p[2] * h[0] - wing * split) / across;
                    sum += exp(-(a * a + c * c + u * u)) * dt;
                }
            }
            worst = fmax(worst, fabs(closed - sum) / fmax(sum, 1e-9));
            if (k == 0 && j != 0)
                *(j > 0 ? &near : &far) = closed;
        }
    }
    printf("burst's shade: closed form within %.2g of the sum (one sheet and split); sunward "
           "side %.3f m, far side %.3f m\n",
           worst, near, far);
    CHECK(worst < 1e-3);
    CHECK(near < 0.2 * far);
}

/* What the burst's self-shade takes for its tearing
 * (TL_BOW_SPRAY_TORN_MEAN) is the torn sheet's mass over its envelope's:
 * summed over a grid through the whole sheet, one sheet and split into
 * wings, within a tenth of the constant. */
static void test_burst_torn_mean(void)
{
    const double radius = 3.0, h[2] = {0.6, 0.8};
    double worst = 0.0, ratios[2];
    for (int k = 0; k < 2; k++) {
        const double split = k ? 2.5 : 0.0;
        const double across = (k ? TL_BOW_SPRAY_WING : 1.3) * radius;
        const double reach = tl_bow_spray_reach(radius, split);
        const int n = 120;
        double torn = 0.0, envelope = 0.0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                for (int l = 0; l < n; l++) {
                    const double d[3] = {(2.0 * (i + 0.5) / n - 1.0) * reach,
                                         (2.0 * (j + 0.5) / n - 1.0) * reach,
                                         (2.0 * (l + 0.5) / n - 1.0) * reach};
                    torn += tl_bow_spray_sheet(d, h, radius, split);
                    double a = (d[0] * h[0] + d[2] * h[1]) / (0.4 * radius);
                    double u = d[1] / (0.9 * radius);
                    for (int wing = k ? -1 : 0; wing <= (k ? 1 : 0); wing += 2) {
                        double c = (d[0] * h[1] - d[2] * h[0] - wing * split) / across;
                        envelope += exp(-(a * a + c * c + u * u));
                    }
                }
        ratios[k] = torn / envelope;
        worst = fmax(worst, fabs(ratios[k] - TL_BOW_SPRAY_TORN_MEAN) / TL_BOW_SPRAY_TORN_MEAN);
    }
    printf("burst's torn mass over its envelope's: %.3f one sheet, %.3f split (constant %.3f)\n",
           ratios[0], ratios[1], TL_BOW_SPRAY_TORN_MEAN);
    CHECK(worst < 0.1);
}

/* What the landing's self-shade takes for its billows
 * (TL_SPRAY_LANDING_MEAN) is the billowed cloud's mass over its
 * envelope's: summed over a grid through a cloud 4 m in radius along 40 m
 * of crest, within a tenth of the constant. */
static void test_landing_billow_mean(void)
{
    const double r = 4.0;
    double billowed = 0.0, envelope = 0.0;
    for (int i = 0; i < 200; i++)
        for (int j = 0; j < 100; j++)
            for (int k = 0; k < 100; k++) {
                double w = 40.0 * (i + 0.5) / 200.0;
                double ts = 2.5 * r * (2.0 * (j + 0.5) / 100.0 - 1.0);
                double ty = 2.5 * r * (2.0 * (k + 0.5) / 100.0 - 1.0);
                double e = exp(-(ts * ts + ty * ty) / (r * r));
                billowed += tl_giant_spray_whitewater(e, w, ts, ty, r);
                envelope += e;
            }
    double ratio = billowed / envelope;
    printf("landing's billowed mass over its envelope's: %.3f (constant %.3f)\n", ratio,
           TL_SPRAY_LANDING_MEAN);
    CHECK(fabs(ratio - TL_SPRAY_LANDING_MEAN) < 0.1 * TL_SPRAY_LANDING_MEAN);
}

/* A landed lip 2.5 s into the break, at the peak: the scene, its wave,
 * spray and lip, the landing cloud's middle (cs, cy) in the crest's
 * cross-section, and a low sun behind the wave. */
static void landing_scene(tl_scene *s, tl_giant *g, tl_giant_spray *sp, tl_giant_lip *lip,
                          double *cs, double *cy, double sun[3])
{
    breaking_scene(s, 10.0, 2.5, 0.0, 0.0);
    tl_giant_prepare(g, &s->giant, s->time);
    tl_giant_spray_prepare(sp, g, 1.5, 8.0, s->time, s->ocean.depth, NULL);
    tl_giant_lip_at(g, s->giant.peak, base_of(s), lip);
    CHECK(lip->present && lip->progress > TL_SPRAY_LANDING_FROM);
    double ahead = TL_SPRAY_SPLASH_AHEAD * (0.3 + 0.7 * lip->spent);
    *cs = lip->center[0] + lip->radius * (TL_GIANT_LIP_THROW * sin(lip->to) + ahead);
    *cy = lip->center[1] + lip->radius * (cos(lip->to) + TL_SPRAY_SPLASH_RISE * lip->spent);
    const double el = 0.2, az = 2.8;
    sun[0] = cos(el) * sin(az);
    sun[1] = sin(el);
    sun[2] = cos(el) * cos(az);
}

/* The landing's self-shade (tl_giant_spray_landing_shade) is its
 * envelope's optical depth toward the sun: the closed form matches a
 * midpoint sum of the envelope's density (noise at its mean) along the
 * sun's ray, and a point on the cloud's sunward side lies in less shade
 * than one on its far side. */
static void test_landing_shade(void)
{
    tl_scene s;
    tl_giant g;
    tl_giant_spray sp;
    tl_giant_lip lip;
    double cs, cy, sun[3];
    landing_scene(&s, &g, &sp, &lip, &cs, &cy, sun);
    double w = s.giant.peak;
    double r =
        TL_SPRAY_LANDING_RADIUS * lip.radius * (1.0 + TL_SPRAY_SPLASH_GROW * lip.spent) *
        (TL_SPRAY_LANDING_SEED +
         (1.0 - TL_SPRAY_LANDING_SEED) * smoothstep_test(TL_SPRAY_LANDING_FROM, 1.0, lip.progress));
    double vs = sun[0] * g.dir[0] + sun[2] * g.dir[1];
    double worst = 0.0, side[2];
    for (int k = -1; k <= 1; k++) {
        /* The middle, and a radius toward and away from the sun. */
        double ps = cs + k * r * vs / hypot(vs, sun[1]),
               py = cy + k * r * sun[1] / hypot(vs, sun[1]);
        double x = g.origin[0] + g.dir[0] * ps + g.across[0] * w;
        double z = g.origin[1] + g.dir[1] * ps + g.across[1] * w;
        double closed = tl_giant_spray_landing_shade(&sp, &g, x, py, z, sun);
        /* The sum holds the lip as at w, as the closed form does. */
        double sum = 0.0, dt = 0.002 * r;
        for (int i = 0; i < 20000; i++) {
            double t = (i + 0.5) * dt;
            double qs = cs - (ps + vs * t), qy = cy - (py + sun[1] * t);
            sum += exp(-(qs * qs + qy * qy) / (r * r)) * dt;
        }
        sum *= TL_SPRAY_SIGMA * TL_SPRAY_LANDING_GAIN * 1.5 * TL_SPRAY_LANDING_MEAN *
               (1.0 - lip.spent * lip.spent);
        worst = fmax(worst, fabs(closed - sum) / fmax(sum, 1e-9));
        if (k != 0)
            side[k > 0] = closed;
    }
    printf(
        "landing's shade: closed form within %.2g of the sum; sunward side %.3f, far side %.3f\n",
        worst, side[1], side[0]);
    CHECK(worst < 1e-3);
    CHECK(side[1] < 0.5 * side[0]);
}

/* The billows' own shade (tl_giant_spray_open): inside the landing's
 * cloud, a billow's top (clear air TL_SPRAY_BURY_STEP over it) lets in
 * more of the sky than its underside or a fold (a billow over it), and
 * likewise toward the sun; outside the cloud all the light comes in. */
static void test_landing_billow_shade(void)
{
    tl_scene s;
    tl_giant g;
    tl_giant_spray sp;
    tl_giant_lip lip;
    double cs, cy, sun[3];
    landing_scene(&s, &g, &sp, &lip, &cs, &cy, sun);
    const double up[3] = {0, 1, 0}, *lights[2] = {up, sun};
    double w0 = s.giant.peak;
    double peak = TL_SPRAY_LANDING_GAIN * sp.amount;
    /* [light][0: buried, 1: clear over it] */
    double sum[2][2] = {{0, 0}, {0, 0}};
    int n[2][2] = {{0, 0}, {0, 0}};
    for (int iw = 0; iw < 20; iw++)
        for (int i = -20; i <= 20; i++)
            for (int j = -20; j <= 20; j++) {
                double w = w0 - 5.0 + 0.5 * iw, ps = cs + 0.25 * i, py = cy + 0.25 * j;
                double x = g.origin[0] + g.dir[0] * ps + g.across[0] * w;
                double z = g.origin[1] + g.dir[1] * ps + g.across[1] * w;
                if (tl_giant_spray_density(&sp, &g, x, py, z, 0.0) < 0.5 * peak)
                    continue; /* inside a billow only */
                for (int l = 0; l < 2; l++) {
                    const double *L = lights[l], step = TL_SPRAY_BURY_STEP;
                    double o = tl_giant_spray_open(&sp, &g, x, py, z, 0.0, L);
                    CHECK(o >= 1.0 - TL_SPRAY_BURY - 1e-12 && o <= 1.0);
                    double over = tl_giant_spray_density(&sp, &g, x + step * L[0], py + step * L[1],
                                                         z + step * L[2], 0.0);
                    if (over < 0.1 * peak || over > 0.9 * peak) {
                        sum[l][over < 0.1 * peak] += o;
                        n[l][over < 0.1 * peak]++;
                    }
                }
            }
    double ps = cs + 4.0 * lip.radius; /* far ahead of the cloud */
    double far_open =
        tl_giant_spray_open(&sp, &g, g.origin[0] + g.dir[0] * ps + g.across[0] * w0, cy,
                            g.origin[1] + g.dir[1] * ps + g.across[1] * w0, 0.0, up);
    for (int l = 0; l < 2; l++)
        for (int k = 0; k < 2; k++) {
            CHECK(n[l][k] > 20);
            sum[l][k] /= n[l][k] > 0 ? n[l][k] : 1;
        }
    printf("landing's billows let in of the sky %.3f at their tops, %.3f under a billow; of the "
           "sun %.3f and %.3f; %.3f outside the cloud\n",
           sum[0][1], sum[0][0], sum[1][1], sum[1][0], far_open);
    CHECK(sum[0][1] > sum[0][0] + 0.3 * TL_SPRAY_BURY);
    CHECK(sum[1][1] > sum[1][0] + 0.3 * TL_SPRAY_BURY);
    CHECK(far_open == 1.0);
}

/* The landing's jets (tl_giant_spray_jets) radiate from the impact: in
 * their whole shell a point's density is its direction's, whatever its
 * distance (a streak, not a lump); over the directions some carry a jet
 * and some none; none point down (a direction whose downward part is over
 * 0.2, past the gate's soft edge), none reach past TL_SPRAY_JET_END radii
 * or start within TL_SPRAY_JET_FROM. */
static void test_landing_jets(void)
{
    const double r = 5.0, drop = TL_SPRAY_JET_DROP * r;
    int jets = 0, gaps = 0;
    double worst = 0.0, down = 0.0, beyond = 0.0;
    for (int k = 0; k < 180; k++) {
        double a = M_PI * k / 179.0; /* forward (0) through up to back (pi) */
        double dx = cos(a), dy = sin(a);
        for (int iw = 0; iw < 4; iw++) {
            double w = 3.1 * iw;
            /* (ts, ty) of a point rho along the direction from the impact */
            double near = tl_giant_spray_jets(w, -dx * TL_SPRAY_JET_IN * r,
                                              drop - dy * TL_SPRAY_JET_IN * r, r);
            double far = tl_giant_spray_jets(w, -dx * TL_SPRAY_JET_OUT * r,
                                             drop - dy * TL_SPRAY_JET_OUT * r, r);
            worst = fmax(worst, fabs(near - far));
            if (dy > 0.5) {
                jets += near > 0.5 * TL_SPRAY_JET;
                gaps += near == 0.0;
            }
            if (dy >= 0.2) /* down more than the gate's soft edge */
                down = fmax(down, tl_giant_spray_jets(w, -dx * r, drop + dy * r, r));
            beyond = fmax(beyond, tl_giant_spray_jets(w, -dx * TL_SPRAY_JET_END * r,
                                                      drop - dy * TL_SPRAY_JET_END * r, r));
            beyond = fmax(beyond, tl_giant_spray_jets(w, -dx * 0.9 * TL_SPRAY_JET_FROM * r,
                                                      drop - 0.9 * dy * TL_SPRAY_JET_FROM * r, r));
        }
    }
    printf("landing's jets: %d directions up with a jet, %d with none; along a direction %.2g "
           "apart; pointing down %.2g, outside the shell %.2g\n",
           jets, gaps, worst, down, beyond);
    CHECK(jets > 20 && gaps > 20);
    CHECK(worst < 1e-12);
    CHECK(down == 0.0 && beyond == 0.0);
}

/* Only a tall stretch of the crest throws a lip: none where the envelope
 * is below TL_GIANT_LIP_LOW, though the break has passed there, and the
 * whole tube where it is above TL_GIANT_LIP_HIGH. */
static void test_lip_low_crest(void)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 1.5, 0.0, 0.0);
    s.giant.peel_speed = 40.0; /* the break has run the whole crest */
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    int low = 0, high = 0;
    for (int iw = 0; iw <= 80; iw++) {
        double w = -g.half_width + 2.0 * g.half_width * iw / 80.0, dl, dp;
        double lambda = tl_giant_lambda(&g, w, &dl);
        tl_giant_lip lip;
        tl_giant_lip_at(&g, w, base_of(&s), &lip);
        if (!(tl_giant_break_progress(&g, w, &dp) > 0.0))
            continue;
        if (lambda < TL_GIANT_LIP_LOW) {
            CHECK(!lip.present);
            low++;
        } else if (lambda > TL_GIANT_LIP_HIGH && lip.spent == 0.0) {
            CHECK(lip.present);
            double grow = fmin(lip.progress / TL_GIANT_LIP_GROW, 1.0);
            grow = grow * grow * (3.0 - 2.0 * grow);
            CHECK(fabs(lip.thickness - TL_GIANT_LIP_THICKNESS * lambda * g.amplitude * grow) <
                  1e-9 * g.amplitude);
            high++;
        }
    }
    printf("lip on a low crest: %d points low without one, %d tall with the whole tube\n", low,
           high);
    CHECK(low > 0 && high > 0);
}

/* GPU against CPU: the lip's cross-section (probe modes 10, 11), the
 * spray's density and shade (mode 12) and the tube's lumped distance
 * (mode 22) at points across the crest, for a wave at the origin at
 * t = 10 s and for one 1e4 m out at t = 1e5 s, and for the first once it
 * has landed; the last with a boat crossing the crest 8 m beside the
 * peak, its burst among the points. */
static void test_gpu_mirror(tl_renderer *r)
{
    /* t, x, z and the break's age at the peak: thrown, and landed there
     * (its whitewater lumped all along the tube). */
    const double where[4][4] = {
        {10.0, 0.0, 0.0, 2.0}, {1e5, 1e4, -7e3, 2.0}, {10.0, 0.0, 0.0, 4.5}, {10.0, 0.0, 0.0, 2.0}};
    for (int k = 0; k < 4; k++) {
        tl_scene s;
        breaking_scene(&s, where[k][0], where[k][3], where[k][1], where[k][2]);
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        tl_giant_hull hull, *crossing = NULL;
        if (k == 3) { /* heading into the wave, the crest under its middle */
            double w = s.giant.peak + 8.0, dl, db, lambda = tl_giant_lambda(&g, w, &dl);
            double top = tl_giant_bow(&g, w, &db) + lambda * g.curl / g.k;
            s.boat.enabled = s.boat.visible = true;
            s.boat.length = 9.0;
            s.boat.beam = 3.0;
            s.boat.position[0] = g.origin[0] + g.dir[0] * top + g.across[0] * w;
            s.boat.position[1] = base_of(&s) + lambda * g.amplitude;
            s.boat.position[2] = g.origin[1] + g.dir[1] * top + g.across[1] * w;
            s.boat.heading = atan2(-g.dir[0], -g.dir[1]);
            tl_giant_hull_of(&hull, &s.boat);
            crossing = &hull;
        }
        /* The camera 60 m in front of the crest, looking at it. */
        s.camera.position[0] = g.origin[0] + g.dir[0] * 60.0;
        s.camera.position[1] = 6.0;
        s.camera.position[2] = g.origin[1] + g.dir[1] * 60.0;
        tl_waves waves;
        tl_waves_init(&waves, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &waves, &u);
        CHECK(u.features & TL_FEATURE_GIANT_LIP);
        CHECK(u.features & TL_FEATURE_GIANT_SPRAY);
        enum { N = 48 };
        float in4[4 * N], lip4[4 * N], ang4[4 * N], spray4[4 * N], dist4[4 * N];
        double shade[N], open_sun[N], open_sky[N];
        const double sun[3] = {u.sun_dir[0], u.sun_dir[1], u.sun_dir[2]}, up[3] = {0.0, 1.0, 0.0};
        tl_giant_lip cpu[N];
        double density[N];
        tl_giant_spray sp;
        tl_giant_spray_prepare(&sp, &g, s.giant.spray, s.giant.spray_wind, s.time, s.ocean.depth,
                               crossing);
        CHECK((sp.bow_amount > 0.0) == (crossing != NULL));
        for (int i = 0; i < N; i++) {
            double w = s.giant.peak - 12.0 + 24.0 * i / (N - 1), dl, db;
            double lambda = tl_giant_lambda(&g, w, &dl);
            double sv = tl_giant_bow(&g, w, &db) + lambda * g.curl / g.k - 4.0 * (i % 4);
            double y = base_of(&s) + lambda * g.amplitude + 0.5 * (i % 3);
            tl_giant_lip_at(&g, w, base_of(&s), &cpu[i]);
            if (i % 4 == 3 && cpu[i].present) { /* beside the lip's tip: where it lands */
                sv = cpu[i].center[0] + TL_GIANT_LIP_THROW * cpu[i].radius * sin(cpu[i].to) + 0.3;
                y = cpu[i].center[1] + cpu[i].radius * cos(cpu[i].to) + 0.2;
            }
            double x = g.origin[0] + g.dir[0] * sv + g.across[0] * w;
            double z = g.origin[1] + g.dir[1] * sv + g.across[1] * w;
            if (crossing && i % 4 == 2) { /* in the burst, the lip where it is */
                x = sp.bow[0] + 0.3 * sp.bow_radius * ((i % 7) - 3);
                y = sp.bow[1] + 0.2 * sp.bow_radius * ((i % 5) - 2);
                z = sp.bow[2] + 0.1 * sp.bow_radius * ((i % 3) - 1);
                w = g.across[0] * (x - g.origin[0]) + g.across[1] * (z - g.origin[1]);
                tl_giant_lip_at(&g, w, base_of(&s), &cpu[i]);
            }
            /* Points, and samples standing for up to 2.4 m of height (a
             * march's step through the plume's layer). */
            double span = 0.6 * (i % 5);
            density[i] = tl_giant_spray_density(&sp, &g, x, y, z, span);
            shade[i] = tl_giant_spray_shade(&sp, &g, x, y, z, sun);
            open_sun[i] = tl_giant_spray_open(&sp, &g, x, y, z, span, sun);
            open_sky[i] = tl_giant_spray_open(&sp, &g, x, y, z, span, up);
            in4[4 * i + 0] = (float)(x - s.camera.position[0]);
            in4[4 * i + 1] = (float)(z - s.camera.position[2]);
            in4[4 * i + 2] = (float)y;
            in4[4 * i + 3] = (float)span;
        }
        tl_error err;
        tl_error_clear(&err);
        int rc = tl_renderer_probe4(r, &u, 10, in4, N, u.octaves, lip4, &err) ||
                 tl_renderer_probe4(r, &u, 11, in4, N, u.octaves, ang4, &err) ||
                 tl_renderer_probe4(r, &u, 12, in4, N, u.octaves, spray4, &err) ||
                 tl_renderer_probe4(r, &u, 22, in4, N, u.octaves, dist4, &err);
        if (rc) {
            fprintf(stderr, "probe: %s\n", err.message);
            CHECK(0);
            return;
        }
        /* The lip's centre s is the wave's (relative to the crest on the
         * centre line), as the CPU's. */
        double worst = 0.0, worst_angle = 0.0, worst_density = 0.0, landing = 0.0;
        double worst_distance = 0.0, worst_lump = 0.0, worst_shade = 0.0, most_shade = 0.0;
        double burst = 0.0, worst_open = 0.0;
        int present = 0, rough = 0, buried = 0;
        for (int i = 0; i < N; i++) {
            CHECK((ang4[4 * i + 3] > 0.5) == cpu[i].present);
            if (!cpu[i].present)
                continue;
            present++;
            worst = fmax(worst, fabs(lip4[4 * i + 0] - cpu[i].center[0]));
            worst = fmax(worst, fabs(lip4[4 * i + 1] - cpu[i].center[1]));
            worst = fmax(worst, fabs(lip4[4 * i + 2] - cpu[i].radius));
            worst = fmax(worst, fabs(lip4[4 * i + 3] - cpu[i].thickness));
            worst_angle = fmax(worst_angle, fabs(ang4[4 * i + 1] - cpu[i].to));
            worst_density = fmax(worst_density, fabs(spray4[4 * i] - density[i]));
            worst_shade =
                fmax(worst_shade, fabs(spray4[4 * i + 1] - shade[i]) / fmax(shade[i], 1.0));
            most_shade = fmax(most_shade, shade[i]);
            worst_open = fmax(worst_open, fabs(spray4[4 * i + 2] - open_sun[i]));
            worst_open = fmax(worst_open, fabs(spray4[4 * i + 3] - open_sky[i]));
            buried += open_sun[i] < 0.99 || open_sky[i] < 0.99;
            /* The tube's signed distance there and its lumps (the point's
             * (s, y) back from its world position, as the GPU has it). */
            double x = in4[4 * i + 0] + s.camera.position[0],
                   z = in4[4 * i + 1] + s.camera.position[2];
            double rx = x - g.origin[0], rz = z - g.origin[1];
            double sv = g.dir[0] * rx + g.dir[1] * rz, y = in4[4 * i + 2];
            double angle = tl_giant_lip_angle(&cpu[i], sv, y);
            double d = tl_giant_lip_distance(&cpu[i], sv, y);
            if (fabs(d) < 50.0)
                worst_distance = fmax(worst_distance, fabs(dist4[4 * i] - d));
            worst_lump =
                fmax(worst_lump, fabs(dist4[4 * i + 1] - tl_giant_lip_lump(&cpu[i], angle)));
            worst_lump =
                fmax(worst_lump, fabs(dist4[4 * i + 2] - tl_giant_lip_roughness(&cpu[i], angle)));
            rough += tl_giant_lip_roughness(&cpu[i], angle) > 0.1;
            if (i % 4 == 3)
                landing = fmax(landing, density[i]);
            if (crossing && i % 4 == 2)
                burst = fmax(burst, shade[i]);
        }
        printf("t = %g s, %g m out: lip %d of %d, |GPU - CPU| %.3g m, %.3g rad; spray %.3g; "
               "distance %.3g m, lumps %.3g (%d points rough); shade %.3g (up to %.3g; in the "
               "burst %.3g); billows' light %.3g (%d points shaded)\n",
               s.time, hypot(where[k][1], where[k][2]), present, N, worst, worst_angle,
               worst_density, worst_distance, worst_lump, rough, worst_shade, most_shade, burst,
               worst_open, buried);
        CHECK(present > N / 2);
        CHECK(worst <= 1e-3);
        CHECK(worst_angle <= 1e-4);
        CHECK(worst_density <=
              2e-3 * TL_SPRAY_PLUME_GAIN * (1.0 + TL_SPRAY_ROOT_GAIN) * s.giant.spray);
        CHECK(worst_distance <= 1e-3 && worst_lump <= 1e-3 && rough > 0);
        CHECK(worst_shade <= 2e-3);
        CHECK(worst_open <= 2e-3 && buried > 0);
        CHECK(landing > 0.1);             /* the landing's cloud is among the points compared */
        CHECK(!crossing || burst > 0.02); /* and the crossing's burst (a clot of it) */
    }
}

/* The wave's program draws the lip and the spray, so its rectangle holds
 * them: for a low camera in front of the crest, looking at its top against
 * the sky, the rectangle with them holds the one without and reaches higher
 * up the frame (the lip and the spindrift rise above the height field). */
static void test_rect_holds_lip(void)
{
    int rects[2][4];
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        breaking_scene(&s, 10.0, 2.0, 0.0, 0.0);
        s.giant.breaking = k == 0;
        s.giant.spray = k == 0 ? 1.5 : 0.0;
        s.width = 320;
        s.height = 180;
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        s.camera.position[0] = g.origin[0] + g.dir[0] * 260.0 + g.across[0] * s.giant.peak;
        s.camera.position[1] = 3.0;
        s.camera.position[2] = g.origin[1] + g.dir[1] * 260.0 + g.across[1] * s.giant.peak;
        s.camera.yaw = atan2(-g.dir[0], -g.dir[1]);
        s.camera.pitch = 0.02;
        tl_waves waves;
        tl_waves_init(&waves, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &waves, &u);
        CHECK(!!(u.features & TL_FEATURE_GIANT_LIP) == (k == 0));
        memcpy(rects[k], u.plan.giant_rect, sizeof rects[k]);
    }
    printf("rectangle with the lip and spray: y %d-%d; without: y %d-%d\n", rects[0][1],
           rects[0][3], rects[1][1], rects[1][3]);
    CHECK(rects[0][0] <= rects[1][0] && rects[0][1] <= rects[1][1]);
    CHECK(rects[0][2] >= rects[1][2] && rects[0][3] >= rects[1][3]);
    CHECK(rects[0][3] > rects[1][3] || rects[0][3] == 180);
}

/* The lip's march draws all of it: a frame looking along the crest at a
 * lip peeling toward the camera (where its free end sweeps metres per
 * metre of crest), every pixel's ray marched on the CPU through the lip's
 * box in 5 cm steps: where the CPU meets the lip well before the frame's
 * distance the GPU stepped over it. Trusting the cross-section's distance
 * alone left a floating blade of a lip (a few rays landed on it). */
static void test_lip_march(tl_renderer *r)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 3.0, 0.0, 0.0);
    s.giant.spray = 0.0;
    s.width = 160;
    s.height = 90;
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    const double base = base_of(&s);
    /* Ahead of the crest and 25 m beyond the peel's front on the +w side,
     * high, looking back along the crest and down at it. */
    const double cs = 18.0, cw = s.giant.peak + s.giant.peel_speed * 3.0 + 25.0;
    for (int i = 0; i < 2; i++)
        s.camera.position[i == 0 ? 0 : 2] = g.origin[i] + g.dir[i] * cs + g.across[i] * cw;
    s.camera.position[1] = 24.0;
    const double look[2] = {-g.across[0] - 0.35 * g.dir[0], -g.across[1] - 0.35 * g.dir[1]};
    s.camera.yaw = atan2(look[0], look[1]);
    s.camera.pitch = -20.0 * M_PI / 180.0;
    s.camera.vfov = 52.0 * M_PI / 180.0;
    double box[4], across[2];
    CHECK(tl_giant_lip_bounds(&g, base, box, across));
    tl_frame f;
    if (render(r, &s, &f))
        return;
    int lip_pixels = 0, missed = 0;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            double d = f.depth[(size_t)y * s.width + x], ray[3];
            pixel_ray(&s, x, y, ray);
            const double *c = s.camera.position;
            /* The ray's part in the lip's box, in (s, y, w). */
            double lo = 0.0, hi = fmin(d, 1e3) * 1.02;
            double o[3] = {g.dir[0] * (c[0] - g.origin[0]) + g.dir[1] * (c[2] - g.origin[1]), c[1],
                           g.across[0] * (c[0] - g.origin[0]) + g.across[1] * (c[2] - g.origin[1])};
            double v[3] = {g.dir[0] * ray[0] + g.dir[1] * ray[2], ray[1],
                           g.across[0] * ray[0] + g.across[1] * ray[2]};
            double bmin[3] = {box[0], box[2], across[0]}, bmax[3] = {box[1], box[3], across[1]};
            for (int k = 0; k < 3 && lo <= hi; k++) {
                if (fabs(v[k]) < 1e-12) {
                    if (o[k] < bmin[k] || o[k] > bmax[k])
                        hi = -1.0;
                    continue;
                }
                double t0 = (bmin[k] - o[k]) / v[k], t1 = (bmax[k] - o[k]) / v[k];
                lo = fmax(lo, fmin(t0, t1));
                hi = fmin(hi, fmax(t0, t1));
            }
            for (double t = lo; t <= hi; t += 0.05) {
                tl_giant_lip lip;
                tl_giant_lip_at(&g, o[2] + v[2] * t, base, &lip);
                if (tl_giant_lip_distance(&lip, o[0] + v[0] * t, o[1] + v[1] * t) < 0.0) {
                    lip_pixels++;
                    missed += t < 0.98 * d - 0.1;
                    break;
                }
            }
        }
    tl_frame_free(&f);
    printf("lip's march: the CPU meets the lip on %d of %d pixels; the frame's distance lies "
           "beyond it on %d\n",
           lip_pixels, s.width * s.height, missed);
    CHECK(lip_pixels > 300);
    CHECK(missed <= lip_pixels / 100);
}

int main(void)
{
    test_lip_heights();
    test_lip_behind_top();
    test_lip_barrel();
    test_lip_roof();
    test_lip_life();
    test_lip_bounds();
    test_spray_density();
    test_spray_layer();
    test_lip_low_crest();
    test_lip_lumps();
    test_bow_burst_pitched();
    test_crossing_burst();
    test_burst_shade();
    test_burst_torn_mean();
    test_landing_billow_mean();
    test_landing_shade();
    test_landing_billow_shade();
    test_landing_jets();
    test_rect_holds_lip();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_gpu_mirror(r);
    test_lip_march(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
