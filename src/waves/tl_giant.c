#include "tl_giant.h"

#include <math.h>
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

/* Profile with explicit steepness S and curl C (the clamps scan it with
 * unit values). Y = A·m·cos θ; D = -(S/k)·m·sin θ (Gerstner pinch toward
 * the crest) + (C/k)·m·u⁴ with u = (1 + cos θ)/2 (a push forward that is
 * strongest at the crest: the curl). Both displacements scale with the
 * wavelength, not the height, so the clamps depend on shape alone. */
static void profile(const tl_giant *g, double s0, double steep, double curl, double *y, double *dy,
                    double *d, double *dd)
{
    double dm, m = mask_along(g, s0, &dm);
    double th = g->k * s0, c = cos(th), sn = sin(th);
    double A = g->amplitude, k = g->k;
    double u = 0.5 * (1.0 + c), u3 = u * u * u, du = -0.5 * k * sn;
    *y = A * m * c;
    *dy = A * (dm * c - k * m * sn);
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
 * [0, fade] (the map is then one-to-one and the surface a height field),
 * then bounds displacement and slope. D' is linear in both knobs, so beta
 * is exact on the scanned profile. */
static void clamp_and_bound(tl_giant *g, double steep, double curl)
{
    const int n = TL_GIANT_PROFILE_SAMPLES;
    const double reach = g->half_length + g->falloff_along;
    const double budget = 1.0 - TL_GIANT_MIN_JACOBIAN, F = g->fade;
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

    /* Bounds at lambda = fade, the worst case: |λ·Y'/J| and λ/J both grow
     * with λ while J stays positive. */
    double max_d = 0.0, min_j = 1.0;
    for (int i = 0; i <= n; i++) {
        tl_giant_profile(g, -reach + 2.0 * reach * i / n, &y, &dy, &d, &dd);
        max_d = fmax(max_d, fabs(d));
        min_j = fmin(min_j, 1.0 + F * dd);
    }
    g->max_displacement = max_d;
    g->min_jacobian = min_j;
    g->reach_along = reach + F * max_d;

    /* Slope per bin of world s. The point that starts at s0 sits anywhere
     * between s0 and s0 + F·D(s0) as lambda runs over [0, F]: its bound goes
     * to every bin that range (widened by a sample) touches. The width
     * mask's slope is at most 1.5 / falloff_across. */
    const double bin = 2.0 * g->reach_along / TL_GIANT_SLOPE_BINS, spacing = 2.0 * reach / n;
    for (int b = 0; b < TL_GIANT_SLOPE_BINS; b++)
        g->slope_bin[b] = g->height_bin[b] = 0.0;
    for (int i = 0; i <= n; i++) {
        double s0 = -reach + 2.0 * reach * i / n;
        tl_giant_profile(g, s0, &y, &dy, &d, &dd);
        double j = fmax(1.0 + F * dd, 0.5 * TL_GIANT_MIN_JACOBIAN);
        double along = fabs(F * dy) / j;
        double across = F * 1.5 / g->falloff_across * (fabs(y) + fabs(F * dy * d) / j);
        double slope = hypot(along, across);
        /* Its height, lambda·Y for lambda in [0, F], is at most F·Y or 0;
         * what lies between samples, at most a sample's spacing up the
         * slope (along s, where the samples are spaced). */
        double height = fmax(F * y, 0.0) + (fabs(F * dy) / j) * spacing;
        double lo = s0 + fmin(0.0, F * d) - spacing, hi = s0 + fmax(0.0, F * d) + spacing;
        int b0 = (int)floor((lo + g->reach_along) / bin),
            b1 = (int)floor((hi + g->reach_along) / bin);
        for (int b = b0 < 0 ? 0 : b0; b <= b1 && b < TL_GIANT_SLOPE_BINS; b++) {
            g->slope_bin[b] = fmax(g->slope_bin[b], slope);
            g->height_bin[b] = fmax(g->height_bin[b], height);
        }
    }
    /* 5% margin for what falls between the profile samples. */
    g->max_slope = 0.0;
    for (int b = 0; b < TL_GIANT_SLOPE_BINS; b++) {
        g->slope_bin[b] *= 1.05;
        g->max_slope = fmax(g->max_slope, g->slope_bin[b]);
    }
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
    g->half_length = 0.5 * L;
    g->falloff_along = clampd(p->falloff, TL_GIANT_MIN_FALLOFF_WAVELENGTHS * L,
                              TL_GIANT_MAX_FALLOFF_WAVELENGTHS * L);
    g->half_width = 0.5 * p->width;
    g->falloff_across = fmin(fmax(p->falloff, TL_GIANT_MIN_FALLOFF_WAVELENGTHS * L), g->half_width);
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
    double dmask, mask = tl_giant_width_mask(g, out->w, &dmask);
    double lambda = g->fade * mask, dlambda = g->fade * dmask;
    double s0 = tl_giant_invert(g, out->s, lambda, iterations);
    double y, dy, d, dd;
    tl_giant_profile(g, s0, &y, &dy, &d, &dd);
    /* Guard: the clamps keep J >= TL_GIANT_MIN_JACOBIAN on the scanned
     * profile; between samples it can only dip marginally lower. */
    double j = fmax(1.0 + lambda * dd, 1e-3);
    out->s0 = s0;
    out->lambda = lambda;
    out->jacobian = j;
    out->displacement = lambda * d;
    out->height = lambda * y;
    /* Implicit differentiation of s = s0 + λ(w)·D(s0): ∂s0/∂s = 1/J,
     * ∂s0/∂w = -λ'·D/J. */
    double dh_ds = lambda * dy / j;
    double dh_dw = dlambda * (y - lambda * dy * d / j);
    out->grad[0] = dh_ds * g->dir[0] + dh_dw * g->across[0];
    out->grad[1] = dh_ds * g->dir[1] + dh_dw * g->across[1];
}

double tl_giant_height(const tl_giant *g, double x, double z, int iterations)
{
    tl_giant_sample smp;
    tl_giant_sample_at(g, x, z, iterations, &smp);
    return smp.height;
}

double tl_giant_sunlit(const tl_giant *g, double x, double z, double y, const double sun[3])
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
    double dm, crest = g->fade * tl_giant_width_mask(g, w, &dm) * g->curl / g->k;
    double dist = (crest - s) / along; /* metres toward the sun to the crest line */
    if (dist <= 0.0)
        return 1.0; /* the sun's side of the crest */
    double wc = w + dist * across;
    double crest_height =
        fabs(wc) < g->half_width ? g->fade * tl_giant_width_mask(g, wc, &dm) * g->amplitude : 0.0;
    double ray_height = y + dist * sun[1] / flat;
    /* The penumbra: the sun's half degree over the distance, and the thin
     * lip near the top of a tall crest, through which light still comes. */
    double soft = 0.3 + 0.01 * dist + 0.08 * crest_height;
    double x01 = fmin(fmax((ray_height - crest_height + soft) / (2.0 * soft), 0.0), 1.0);
    /* No crest, no shadow: where the width mask has let the crest down
     * to the sea's mean level, the penumbra alone darkened the troughs
     * beside the wave along the whole crest line. */
    double shade = 1.0 - x01 * x01 * (3.0 - 2.0 * x01);
    double crest01 = fmin(fmax(crest_height / TL_GIANT_SHADOW_FADE, 0.0), 1.0);
    return 1.0 - shade * crest01 * crest01 * (3.0 - 2.0 * crest01);
}
