#include "tl_giant.h"

#include "tl_glsl.h"
#include "tl_noise.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Hermite smoothstep on [0, 1] and its derivative. */
static double smooth01(double x, double *dx)
{
    x = x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x;
    *dx = 6.0 * x * (1.0 - x);
    return x * x * (3.0 - 2.0 * x);
}

/* The single-crest mask: 1 for |s0| <= half_length, easing to 0 at
 * half_length + falloff_along. Derivative with respect to s0 in *dm. */
static double mask_along(const tl_giant *g, double s0, double *dm)
{
    double a = fabs(s0), ds;
    double m = 1.0 - smooth01((a - g->half_length) / g->falloff_along, &ds);
    *dm = -ds / g->falloff_along * (s0 < 0.0 ? -1.0 : 1.0);
    return m;
}

double tl_giant_width_mask(const tl_giant *g, double w, double *dmask)
{
    double a = fabs(w), ds;
    double m = 1.0 - smooth01((a - (g->half_width - g->falloff_across)) / g->falloff_across, &ds);
    *dmask = -ds / g->falloff_across * (w < 0.0 ? -1.0 : 1.0);
    return m;
}

/* Distance from the peak toward the end on w's side, 0 at the peak and 1
 * at the end (|w| = half width), and its derivative with respect to w. */
static double from_peak(const tl_giant *g, double w, double *dr)
{
    double H = g->half_width, p = g->peak;
    if (w >= p) {
        *dr = 1.0 / (H - p);
        return fmin((w - p) / (H - p), 1.0);
    }
    *dr = -1.0 / (H + p);
    return fmin((p - w) / (H + p), 1.0);
}

double tl_giant_bow(const tl_giant *g, double w, double *db)
{
    double dr, r = from_peak(g, w, &dr);
    *db = r < 1.0 ? -2.0 * g->bow * r * dr : 0.0;
    return -g->bow * r * r;
}

/* |w - peak|, rounded over TL_GIANT_PEEL_ROUND metres at the peak, and
 * its derivative: a plain |x| put a corner in the settling crest there. */
static double from_peak_rounded(const tl_giant *g, double w, double *dd)
{
    double x = w - g->peak, r = TL_GIANT_PEEL_ROUND, h = sqrt(x * x + r * r);
    *dd = x / h;
    return h - r;
}

double tl_giant_break_age(const tl_giant *g, double w)
{
    double dd;
    return g->break_age - from_peak_rounded(g, w, &dd) / g->peel_speed;
}

double tl_giant_break_progress(const tl_giant *g, double w, double *dprogress)
{
    *dprogress = 0.0;
    if (!g->breaks)
        return 0.0;
    double ds, p = smooth01(tl_giant_break_age(g, w) / g->throw_time, &ds);
    double dd;
    from_peak_rounded(g, w, &dd);
    *dprogress = -ds / (g->throw_time * g->peel_speed) * dd;
    return p;
}

/* The seeded variation along the crest: a sum of sines in [-1, 1]. */
static double variation(const tl_giant *g, double w, double *dv)
{
    static const double weights[3] = TL_GIANT_VARIATION_WEIGHTS;
    double v = 0.0;
    *dv = 0.0;
    for (int i = 0; i < 3; i++) {
        double a = g->vary_k[i] * w + g->vary_phase[i];
        v += weights[i] * sin(a);
        *dv += weights[i] * g->vary_k[i] * cos(a);
    }
    return v;
}

double tl_giant_lambda(const tl_giant *g, double w, double *dl)
{
    double dm, dr, dv;
    double m = tl_giant_width_mask(g, w, &dm);
    double r = from_peak(g, w, &dr);
    double taper = 1.0 - g->taper * r * r, dtaper = r < 1.0 ? -2.0 * g->taper * r * dr : 0.0;
    double n = variation(g, w, &dv);
    double vary = 1.0 + g->variation * n, dvary = g->variation * dv;
    /* The settling after the lip has landed: from progress 1 over twice the
     * throw's time, smoothly. */
    double settle = 1.0, ds = 0.0;
    if (g->breaks) {
        double age = tl_giant_break_age(g, w);
        double dx;
        settle = 1.0 - g->break_drop * smooth01((age - g->throw_time) / (2.0 * g->throw_time), &dx);
        double dd;
        from_peak_rounded(g, w, &dd);
        ds = g->break_drop * dx / (2.0 * g->throw_time * g->peel_speed) * dd;
    }
    double F = g->fade;
    *dl = F * (dm * taper * vary * settle + m * dtaper * vary * settle +
               m * taper * dvary * settle + m * taper * vary * ds);
    return F * m * taper * vary * settle;
}

/* Profile with explicit steepness S and curl C (the clamps scan it with
 * unit values). Y = A·m·cos θ·(1 − q·l²) with l = (1 − cos θ)/2 and q the
 * trough's lift (TL_GIANT_TROUGH_LIFT): the crest keeps its height A and
 * nearly its slope (l² is flat there), the trough keeps 1 − q of its depth
 * and a broad bottom; the trough behind the crest keeps 1 − TL_GIANT_BACK_FILL
 * of that.
 * D = -(S/k)·m·sin θ (Gerstner pinch toward the crest) + (C/k)·m·u⁴ with
 * u = (1 + cos θ)/2 (a push forward that is strongest at the crest: the
 * curl). Both displacements scale with the wavelength, not the height, so
 * the clamps depend on shape alone. */
static void profile(const tl_giant *g, double s0, double steep, double curl, double *y, double *dy,
                    double *d, double *dd)
{
    double dm, m = mask_along(g, s0, &dm);
    double th = g->k * s0, c = cos(th), sn = sin(th);
    double A = g->amplitude, k = g->k;
    double u = 0.5 * (1.0 + c), u3 = u * u * u, du = -0.5 * k * sn;
    const double q = TL_GIANT_TROUGH_LIFT;
    double low = 0.5 * (1.0 - c); /* 0 at the crest, 1 at the trough */
    double shape = c * (1.0 - q * low * low), dshape = 1.0 - q * low * low + q * c * low; /* d/dc */
    if (s0 < 0.0 && c < 0.0) { /* the trough behind, filled (TL_GIANT_BACK_FILL) */
        const double b = TL_GIANT_BACK_FILL;
        double t = -c, fill = 1.0 - b * t * (2.0 - t); /* d fill/dc = 2b(1 - t) */
        dshape = dshape * fill + shape * 2.0 * b * (1.0 - t);
        shape *= fill;
    }
    *y = A * m * shape;
    *dy = A * (dm * shape - k * m * sn * dshape);
    *d = (-steep * m * sn + curl * m * u3 * u) / k;
    *dd = (-steep * (dm * sn + k * m * c) + curl * (dm * u3 * u + m * 4.0 * u3 * du)) / k;
}

void tl_giant_profile(const tl_giant *g, double s0, double *y, double *dy, double *d, double *dd)
{
    profile(g, s0, g->steepness, g->curl, y, dy, d, dd);
}

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Scales steepness and curl by one factor beta <= 1, the largest that
 * keeps 1 + lambda·D'(s0) >= TL_GIANT_MIN_JACOBIAN for every lambda in
 * [0, lambda_max] (the map is then one-to-one and the surface a height field),
 * then bounds displacement and slope. D' is linear in both knobs, so beta
 * is exact on the scanned profile. */
static void clamp_and_bound(tl_giant *g, double steep, double curl)
{
    const int n = TL_GIANT_PROFILE_SAMPLES;
    const double reach = g->half_length + g->falloff_along;
    const double budget = 1.0 - TL_GIANT_MIN_JACOBIAN, F = g->lambda_max;
    double y, dy, d, dd;

    double worst = 0.0; /* max of -D' at the asked knobs */
    for (int i = 0; i <= n; i++) {
        profile(g, -reach + 2.0 * reach * i / n, steep, curl, &y, &dy, &d, &dd);
        worst = fmax(worst, -dd);
    }
    if (F * worst > budget) {
        double beta = budget / (F * worst);
        steep *= beta;
        curl *= beta;
    }
    g->steepness = steep;
    g->curl = curl;

    /* Bounds at lambda = lambda_max, the worst case: |λ·Y'/J| and λ/J both grow
     * with λ while J stays positive. */
    double max_d = 0.0, min_j = 1.0;
    for (int i = 0; i <= n; i++) {
        tl_giant_profile(g, -reach + 2.0 * reach * i / n, &y, &dy, &d, &dd);
        max_d = fmax(max_d, fabs(d));
        min_j = fmin(min_j, 1.0 + F * dd);
    }
    g->max_displacement = max_d;
    g->min_jacobian = min_j;
    g->reach_along = reach + F * max_d + g->bow;

    /* Slope per bin of world s. The point that starts at s0 sits anywhere
     * between s0 - bow and s0 + F·D(s0) as lambda runs over [0, F] and the
     * bow over [-bow, 0]: its bound goes to every bin that range (widened
     * by a sample) touches. Across, dh/dw = λ'·Y + (λ·Y'/J)·(-bow' - λ'·D),
     * bounded with the envelope's bounds. */
    const double bin = 2.0 * g->reach_along / TL_GIANT_SLOPE_BINS, spacing = 2.0 * reach / n;
    for (int b = 0; b < TL_GIANT_SLOPE_BINS; b++)
        g->slope_bin[b] = g->height_bin[b] = g->squeeze_bin[b] = 0.0;
    for (int i = 0; i <= n; i++) {
        double s0 = -reach + 2.0 * reach * i / n;
        tl_giant_profile(g, s0, &y, &dy, &d, &dd);
        double j = fmax(1.0 + F * dd, 0.5 * TL_GIANT_MIN_JACOBIAN);
        double along = fabs(F * dy) / j;
        double across =
            g->max_dlambda * fabs(y) + fabs(F * dy) / j * (g->max_dbow + g->max_dlambda * fabs(d));
        double slope = hypot(along, across);
        /* |grad displacement|: λ·D'/J along, and across λ'·D - (λ·D'/J)·(λ'·D + bow'). */
        double squeeze = fabs(F * dd) / j * (1.0 + g->max_dbow + g->max_dlambda * fabs(d)) +
                         g->max_dlambda * fabs(d);
        /* Its height, lambda·Y for lambda in [0, F], is at most F·Y or 0;
         * what lies between samples, at most a sample's spacing up the
         * slope (along s, where the samples are spaced). */
        double height = fmax(F * y, 0.0) + (fabs(F * dy) / j) * spacing;
        double lo = s0 + fmin(0.0, F * d) - g->bow - spacing, hi = s0 + fmax(0.0, F * d) + spacing;
        int b0 = (int)floor((lo + g->reach_along) / bin),
            b1 = (int)floor((hi + g->reach_along) / bin);
        for (int b = b0 < 0 ? 0 : b0; b <= b1 && b < TL_GIANT_SLOPE_BINS; b++) {
            g->slope_bin[b] = fmax(g->slope_bin[b], slope);
            g->height_bin[b] = fmax(g->height_bin[b], height);
            g->squeeze_bin[b] = fmax(g->squeeze_bin[b], squeeze);
        }
    }
    /* 5% margin for what falls between the profile samples. */
    g->max_slope = g->max_squeeze = 0.0;
    for (int b = 0; b < TL_GIANT_SLOPE_BINS; b++) {
        g->slope_bin[b] *= 1.05;
        g->squeeze_bin[b] *= 1.05;
        g->max_slope = fmax(g->max_slope, g->slope_bin[b]);
        g->max_squeeze = fmax(g->max_squeeze, g->squeeze_bin[b]);
    }
}

/* A 64-bit mix (splitmix64): the variation's phases are the same on every
 * machine. */
static uint64_t mix64(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/* The envelope's parameters, and bounds on its slopes from a scan across. */
static void prepare_envelope(tl_giant *g, const tl_giant_wave *p, double t)
{
    static const double periods[3] = TL_GIANT_VARIATION_PERIODS;
    double L = 2.0 * M_PI / g->k;
    g->peak =
        clampd(p->peak, -TL_GIANT_PEAK_LIMIT * g->half_width, TL_GIANT_PEAK_LIMIT * g->half_width);
    g->taper = p->taper;
    g->bow = p->bow;
    g->variation = p->variation;
    for (int i = 0; i < 3; i++) {
        g->vary_k[i] = 2.0 * M_PI / (periods[i] * L);
        uint64_t h = mix64((uint64_t)(uint32_t)p->seed * 3u + (uint64_t)i);
        g->vary_phase[i] = 2.0 * M_PI * (double)(h >> 11) / 9007199254740992.0;
    }
    g->break_age = t - p->break_time;
    g->peel_speed = p->peel_speed > 0.0 ? p->peel_speed : 1.0;
    g->throw_time = TL_GIANT_THROW_FALLS * sqrt(2.0 * p->height / TL_GIANT_GRAVITY);
    g->break_drop = p->break_drop;
    g->scripted = p->breaking;
    g->breaks = p->breaking && g->break_age > 0.0 && g->throw_time > 0.0;
    g->lambda_max = g->fade * (1.0 + g->variation);

    /* |lambda'| and |bow'| across, sampled; 5% margin for what falls
     * between the samples. */
    const int n = TL_GIANT_PROFILE_SAMPLES;
    double max_dl = 0.0, max_db = 0.0, dl, db;
    for (int i = 0; i <= n; i++) {
        double w = -g->half_width + 2.0 * g->half_width * i / n;
        tl_giant_lambda(g, w, &dl);
        tl_giant_bow(g, w, &db);
        max_dl = fmax(max_dl, fabs(dl));
        max_db = fmax(max_db, fabs(db));
    }
    g->max_dlambda = 1.05 * max_dl;
    g->max_dbow = 1.05 * max_db;
}

void tl_giant_prepare(tl_giant *g, const tl_giant_wave *p, double t)
{
    memset(g, 0, sizeof *g);
    g->active =
        p->enabled && p->fade > 0.0 && p->height > 0.0 && p->wavelength > 0.0 && p->width > 0.0;
    if (!g->active)
        return;
    double L = p->wavelength;
    g->dir[0] = sin(p->angle);
    g->dir[1] = cos(p->angle);
    g->across[0] = g->dir[1];
    g->across[1] = -g->dir[0];
    g->k = 2.0 * M_PI / L;
    g->speed = sqrt(TL_GIANT_GRAVITY / g->k) * p->speed;
    /* The crest's distance past the centre: travel since the arrival time
     * plus the phase as a fraction of a wavelength. Both in double: the
     * GPU only ever sees positions relative to the camera. */
    double crest = g->speed * (t - p->arrival) + p->phase / g->k;
    g->origin[0] = p->center[0] + g->dir[0] * crest;
    g->origin[1] = p->center[1] + g->dir[1] * crest;
    g->amplitude = p->height;
    g->fade = p->fade;
    g->ride = p->ride;
    g->half_length = TL_GIANT_CREST_HALF_LENGTH * L;
    g->falloff_along =
        clampd(p->falloff, TL_GIANT_MIN_FALLOFF_ALONG * L, TL_GIANT_MAX_FALLOFF_WAVELENGTHS * L);
    g->half_width = 0.5 * p->width;
    g->falloff_across = fmin(fmax(p->falloff, TL_GIANT_MIN_FALLOFF_WAVELENGTHS * L), g->half_width);
    prepare_envelope(g, p, t);
    clamp_and_bound(g, p->steepness, p->curve_strength);
}

double tl_giant_invert(const tl_giant *g, double s, double lambda, int iterations)
{
    if (!(lambda > 0.0) || fabs(s) >= g->reach_along)
        return s;
    double y, dy, d, dd;
    /* The root lies within lambda·max|D| of s; the bracket is a quarter wider
     * so that a root on its edge does not turn Newton into bisection. */
    double reach = TL_GIANT_BRACKET * lambda * g->max_displacement;
    double lo = s - reach, hi = s + reach;
    tl_giant_profile(g, s, &y, &dy, &d, &dd);
    double s0 = clampd(s - lambda * d, lo, hi);
    for (int i = 0; i < iterations; i++) {
        tl_giant_profile(g, s0, &y, &dy, &d, &dd);
        double f = s0 + lambda * d - s;
        if (f < 0.0)
            lo = s0;
        else
            hi = s0;
        double next = s0 - f / (1.0 + lambda * dd);
        /* Safeguard: a Newton step that leaves the bracket bisects instead
         * (inclusive: a converged step lands on the bracket's end). */
        s0 = next >= lo && next <= hi ? next : 0.5 * (lo + hi);
    }
    return s0;
}

void tl_giant_sample_at(const tl_giant *g, double x, double z, int iterations, tl_giant_sample *out)
{
    memset(out, 0, sizeof *out);
    if (!g->active)
        return;
    double rx = x - g->origin[0], rz = z - g->origin[1];
    out->s = g->dir[0] * rx + g->dir[1] * rz;
    out->w = g->across[0] * rx + g->across[1] * rz;
    out->s0 = out->s;
    out->jacobian = 1.0;
    if (fabs(out->w) >= g->half_width || fabs(out->s) >= g->reach_along)
        return;
    double dlambda, lambda = tl_giant_lambda(g, out->w, &dlambda);
    double dbow, bow = tl_giant_bow(g, out->w, &dbow);
    double s0 = tl_giant_invert(g, out->s - bow, lambda, iterations);
    double y, dy, d, dd;
    tl_giant_profile(g, s0, &y, &dy, &d, &dd);
    /* Guard: the clamps keep J >= TL_GIANT_MIN_JACOBIAN on the scanned
     * profile; between samples it can only dip marginally lower. */
    double j = fmax(1.0 + lambda * dd, 1e-3);
    out->s0 = s0;
    out->lambda = lambda;
    out->jacobian = j;
    out->displacement = lambda * d;
    out->bow = bow;
    out->height = lambda * y;
    /* Implicit differentiation of s = s0 + λ(w)·D(s0) + bow(w):
     * ∂s0/∂s = 1/J, ∂s0/∂w = -(λ'·D + bow')/J. */
    double dh_ds = lambda * dy / j;
    double dh_dw = dlambda * y - dh_ds * (dlambda * d + dbow);
    out->grad[0] = dh_ds * g->dir[0] + dh_dw * g->across[0];
    out->grad[1] = dh_ds * g->dir[1] + dh_dw * g->across[1];
    /* The displacement λ·D(s0) by the same rule. */
    double dd_ds = lambda * dd / j;
    double dd_dw = dlambda * d - dd_ds * (dlambda * d + dbow);
    out->ride[0] = dd_ds * g->dir[0] + dd_dw * g->across[0];
    out->ride[1] = dd_ds * g->dir[1] + dd_dw * g->across[1];
}

void tl_giant_ride_point(const tl_giant *g, const tl_giant_sample *smp, double x, double z,
                         double q[2])
{
    double push = g->active ? g->ride * smp->displacement : 0.0;
    q[0] = x - push * g->dir[0];
    q[1] = z - push * g->dir[1];
}

void tl_giant_ride_grad(const tl_giant *g, const tl_giant_sample *smp, double grad[2])
{
    if (!g->active)
        return;
    /* q = p - ride·disp(p)·dir: dq/dp = I - ride·dir ⊗ ∇disp, and the
     * gradient in p is (dq/dp)ᵀ times the one in q. */
    double along = g->ride * (g->dir[0] * grad[0] + g->dir[1] * grad[1]);
    grad[0] -= along * smp->ride[0];
    grad[1] -= along * smp->ride[1];
}

double tl_giant_short_wave_gain(const tl_giant *g, const tl_giant_sample *smp)
{
    if (!g->active)
        return 1.0;
    double top = smp->height / fmax(g->amplitude * smp->lambda, 1.0e-3);
    top = fmin(fmax(top, 0.0), 1.0);
    double lambda = fmin(fmax(smp->lambda, 0.0), 1.0);
    return fmin(1.0 + g->k * g->amplitude * lambda * top, TL_GIANT_SHORT_WAVE_GAIN_MAX);
}

double tl_giant_height(const tl_giant *g, double x, double z, int iterations)
{
    tl_giant_sample smp;
    tl_giant_sample_at(g, x, z, iterations, &smp);
    return smp.height;
}

double tl_giant_water_along(const tl_giant *g, const double from[3], const double dir[3],
                            int iterations)
{
    double t = 0.0, step = TL_GIANT_THROUGH_FIRST, crossed = 0.0;
    double above = from[1] - tl_giant_height(g, from[0], from[2], iterations);
    for (int i = 0; i < TL_GIANT_THROUGH_STEPS; i++) {
        double t_next = t + step;
        double x = from[0] + dir[0] * t_next, z = from[2] + dir[2] * t_next;
        double next = from[1] + dir[1] * t_next - tl_giant_height(g, x, z, iterations);
        if (above < 0.0 && next < 0.0)
            crossed += step;
        else if (above < 0.0 || next < 0.0)
            crossed += step * fmax(-above, -next) / fabs(next - above);
        t = t_next;
        above = next;
        step *= TL_GIANT_THROUGH_GROWTH;
    }
    return crossed + fmax(-above, 0.0) / fmax(dir[1], 0.1);
}

double tl_giant_sunlit(const tl_giant *g, double x, double z, double y, const double sun[3])
{
    return tl_giant_clear(g, x, z, y, sun, 0.0);
}

double tl_giant_clear(const tl_giant *g, double x, double z, double y, const double sun[3],
                      double spread)
{
    double flat = hypot(sun[0], sun[2]);
    if (!g->active || !(sun[1] > 0.0) || flat < 1e-4)
        return 1.0;
    double along = (g->dir[0] * sun[0] + g->dir[1] * sun[2]) / flat;
    double across = (g->across[0] * sun[0] + g->across[1] * sun[2]) / flat;
    if (fabs(along) < 1e-4)
        return 1.0; /* a crest in line with the sun */
    double rx = x - g->origin[0], rz = z - g->origin[1];
    double s = g->dir[0] * rx + g->dir[1] * rz, w = g->across[0] * rx + g->across[1] * rz;
    double dl, db, crest = tl_giant_bow(g, w, &db) + tl_giant_lambda(g, w, &dl) * g->curl / g->k;
    double dist = (crest - s) / along; /* metres toward the sun to the crest line */
    if (dist <= 0.0)
        return 1.0; /* the sun's side of the crest */
    double wc = w + dist * across;
    double crest_height =
        fabs(wc) < g->half_width ? tl_giant_lambda(g, wc, &dl) * g->amplitude : 0.0;
    double ray_height = y + dist * sun[1] / flat;
    /* The penumbra: the sun's half degree over the distance, and the thin
     * lip near the top of a tall crest, through which light still comes. */
    double soft = 0.3 + (0.01 + spread) * dist + 0.08 * crest_height;
    double x01 = fmin(fmax((ray_height - crest_height + soft) / (2.0 * soft), 0.0), 1.0);
    /* No crest, no shadow: where the width mask has let the crest down
     * to the sea's mean level, the penumbra alone darkened the troughs
     * beside the wave along the whole crest line. */
    double shade = 1.0 - x01 * x01 * (3.0 - 2.0 * x01);
    double crest01 = fmin(fmax(crest_height / TL_GIANT_SHADOW_FADE, 0.0), 1.0);
    return 1.0 - shade * crest01 * crest01 * (3.0 - 2.0 * crest01);
}

double tl_giant_face_blend(const tl_giant_sample *smp, double level)
{
    double slope = hypot(smp->grad[0], smp->grad[1]);
    return level * (1.0 - TL_GIANT_FACE_SHARP_SHARE * tl_smoothstep(TL_GIANT_FACE_SHARP_FROM,
                                                                    TL_GIANT_FACE_SHARP_TO, slope));
}

void tl_giant_facet_seen(const double n[3], const double ray[3], const double grad[2],
                         double out[3])
{
    double wave[3] = {-grad[0], 1.0, -grad[1]};
    double wave_len = sqrt(wave[0] * wave[0] + 1.0 + wave[2] * wave[2]);
    double wave_seen = -(wave[0] * ray[0] + wave[1] * ray[1] + wave[2] * ray[2]) / wave_len;
    double least =
        TL_GIANT_FACET_GRAZE * fmax(wave_seen, 0.0) *
        tl_smoothstep(TL_GIANT_FACE_SHARP_FROM, TL_GIANT_FACE_SHARP_TO, hypot(grad[0], grad[1]));
    double seen = -(n[0] * ray[0] + n[1] * ray[1] + n[2] * ray[2]);
    for (int i = 0; i < 3; i++)
        out[i] = seen < least ? n[i] - (least - seen) * ray[i] : n[i];
    if (seen < least) {
        double len = sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
        for (int i = 0; i < 3; i++)
            out[i] /= len;
    }
}

void tl_giant_world_origin(const tl_giant *g, double out[2])
{
    double along = g->dir[0] * g->origin[0] + g->dir[1] * g->origin[1];
    double across = g->across[0] * g->origin[0] + g->across[1] * g->origin[1];
    out[0] = along - 65536.0 * floor(along / 65536.0);
    out[1] = across - 65536.0 * floor(across / 65536.0);
}

double tl_giant_foam_coverage(const tl_giant *g, const tl_giant_sample *smp, double amount,
                              double foam_compression, double foam_trail)
{
    if (!g->active || !(smp->lambda > 0.0))
        return 0.0;
    double dp, breaking;
    if (g->breaks)
        breaking = tl_giant_break_progress(g, smp->w, &dp);
    else if (g->scripted || foam_compression <= TL_GIANT_MIN_JACOBIAN)
        breaking = 0.0;
    else
        breaking = clampd((foam_compression - g->min_jacobian) /
                              (foam_compression - TL_GIANT_MIN_JACOBIAN),
                          0.0, 1.0);
    double top = clampd(smp->height / fmax(g->amplitude * smp->lambda, 1e-3), 0.0, 1.0);
    double compressed = (1.0 - tl_smoothstep(0.1, foam_compression, smp->jacobian)) *
                        (g->scripted ? fmax(breaking, TL_GIANT_UNBROKEN_FOAM) : 1.0);
    double cap = tl_smoothstep(0.9, 1.0, top) * breaking;
    double front = tl_smoothstep(-0.35, 0.0, smp->s0 / g->half_length);
    double behind = fmax(-smp->s0, 0.0);
    double fresh = exp(-behind / fmax(foam_trail, 1e-3));
    double trail = breaking * fresh * tl_smoothstep(0.0, 0.1 * g->half_length, behind);
    double face = 0.0;
    if (g->breaks) {
        face = tl_smoothstep(1.0 - 1.1 * breaking, 1.1 - 1.1 * breaking, top) * front * breaking;
        double passed = behind / fmax(g->speed, 1e-3), world[2];
        tl_giant_world_origin(g, world);
        double ragged = TL_GIANT_TRAIL_RAGGED * 2.0 *
                        (tl_noise_value((world[0] + smp->s0) / TL_GIANT_TRAIL_RAGGED_CELL + 4.1,
                                        (world[1] + smp->w) / TL_GIANT_TRAIL_RAGGED_CELL + 7.7) -
                         0.5);
        trail = fresh * tl_smoothstep(0.0, 0.1 * g->half_length, behind) *
                tl_smoothstep(0.0, 0.5 * g->throw_time,
                              tl_giant_break_age(g, smp->w) - passed + ragged);
    }
    double c = fmax(fmax(compressed, cap), fmax(face, trail)) * smp->lambda * amount;
    return clampd(c, 0.0, 1.0);
}

bool tl_giant_in_matte(const tl_giant *g, double height)
{
    return g->active && height > TL_GIANT_MATTE_SHARE * g->amplitude;
}
