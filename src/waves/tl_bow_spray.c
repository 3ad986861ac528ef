#include "waves/tl_bow_spray.h"

#include <math.h>
#include <string.h>

#include "waves/tl_giant_spray.h"
#include "waves/tl_glsl.h"
#include "waves/tl_noise.h"

void tl_bow_spray_prepare(tl_bow_spray *sp, const tl_boat *b)
{
    memset(sp, 0, sizeof *sp);
    double strength = tl_smoothstep(TL_BOW_SPRAY_FROM, TL_BOW_SPRAY_FULL, b->impact);
    if (!(strength > 0.0) || !(b->spray > 0.0) || !(b->length > 0.0))
        return;
    sp->heading[0] = sin(b->heading);
    sp->heading[1] = cos(b->heading);
    /* A harder slam throws a larger sheet, up and out from the stem. */
    sp->radius = TL_BOW_SPRAY_RADIUS * b->length * (0.6 + 0.4 * strength);
    const double a = 0.5 * b->length; /* the stem, at its waterline */
    sp->center[0] = b->position[0] + sp->heading[0] * a;
    sp->center[1] = b->position[1] + sin(b->pitch) * a + 0.6 * sp->radius;
    sp->center[2] = b->position[2] + sp->heading[1] * a;
    sp->amount = TL_BOW_SPRAY_GAIN * b->spray * strength;
    sp->active = true;
}

double tl_bow_spray_reach(double radius, double split)
{
    return split > 0.0 ? split + sqrt(TL_BOW_SPRAY_END) * fmax(TL_BOW_SPRAY_WING, 0.9) * radius
                       : TL_BOW_SPRAY_REACH * radius;
}

/* The sheet's width across the heading: one sheet's, or each wing's. */
static double sheet_across(double radius, double split)
{
    return (split > 0.0 ? TL_BOW_SPRAY_WING : 1.3) * radius;
}

double tl_bow_spray_sheet(const double d[3], const double heading[2], double radius, double split)
{
    /* Thin along the heading, wide across it, rising; torn by the noise.
     * Split, a wing each side (their envelopes summed). */
    double along = (d[0] * heading[0] + d[2] * heading[1]) / (0.4 * radius);
    double side_m = d[0] * heading[1] - d[2] * heading[0];
    double up = d[1] / (0.9 * radius), across = sheet_across(radius, split);
    double envelope = 0.0;
    for (int wing = split > 0.0 ? -1 : 0; wing <= (split > 0.0 ? 1 : 0); wing += 2) {
        double side = (side_m - wing * split) / across;
        double r2 = along * along + side * side + up * up;
        if (r2 < TL_BOW_SPRAY_END)
            envelope += exp(-r2) * (1.0 - tl_smoothstep(1.0, TL_BOW_SPRAY_END, r2));
    }
    if (!(envelope > 0.0))
        return 0.0;
    /* Torn into sheets and clots of droplets: two scales of noise, cut
     * sharply (a soft cut left a smoke, not thrown water), the clots
     * shrinking toward the edge (TL_BOW_SPRAY_THIN); the wings tear alike,
     * mirrored. */
    double side = (split > 0.0 ? fabs(side_m) - split : side_m) / across;
    double torn = 0.65 * tl_noise_value(side * 2.6 + 17.0, up * 3.1 - along) +
                  0.35 * tl_noise_value(side * 7.3 - 4.0, up * 8.9 + along * 2.0);
    double cover = sqrt(fmin(envelope, 1.0));
    return cover * tl_smoothstep(TL_BOW_SPRAY_TEAR_FROM, TL_BOW_SPRAY_TEAR_TO,
                                 torn + TL_BOW_SPRAY_THIN * (cover - 1.0));
}

double tl_bow_spray_density(const tl_bow_spray *sp, double x, double y, double z)
{
    if (!sp->active)
        return 0.0;
    const double d[3] = {x - sp->center[0], y - sp->center[1], z - sp->center[2]};
    return sp->amount * tl_bow_spray_sheet(d, sp->heading, sp->radius, 0.0);
}

double tl_bow_spray_sheet_depth(const double d[3], const double heading[2], double radius,
                                double split, const double sun[3])
{
    /* In the sheet's frame scaled by its three widths the envelope is
     * exp(-|q + t e|²) along the sun's ray; with a = q·e / |e| that is
     * exp(-(|q|² - a²)) exp(-(t|e| + a)²), whose integral over t >= 0 is
     * exp(-(|q|² - a²)) sqrt(pi) / (2|e|) erfc(a); split, the wings'
     * sum. */
    const double sa = 0.4 * radius, ss = sheet_across(radius, split), su = 0.9 * radius;
    const double e[3] = {(sun[0] * heading[0] + sun[2] * heading[1]) / sa,
                         (sun[0] * heading[1] - sun[2] * heading[0]) / ss, sun[1] / su};
    double len = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]), depth = 0.0;
    for (int wing = split > 0.0 ? -1 : 0; wing <= (split > 0.0 ? 1 : 0); wing += 2) {
        const double q[3] = {(d[0] * heading[0] + d[2] * heading[1]) / sa,
                             (d[0] * heading[1] - d[2] * heading[0] - wing * split) / ss,
                             d[1] / su};
        double a = (q[0] * e[0] + q[1] * e[1] + q[2] * e[2]) / len;
        double perp = fmax(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - a * a, 0.0);
        depth += exp(-perp) * 0.5 * sqrt(M_PI) / len * (1.0 - erf(a));
    }
    return depth;
}

double tl_bow_spray_shade(const tl_bow_spray *sp, double x, double y, double z, const double sun[3])
{
    if (!sp->active)
        return 0.0;
    const double d[3] = {x - sp->center[0], y - sp->center[1], z - sp->center[2]};
    return TL_SPRAY_SIGMA * sp->amount * TL_BOW_SPRAY_TORN_MEAN *
           tl_bow_spray_sheet_depth(d, sp->heading, sp->radius, 0.0, sun);
}
