/* The Kelvin wake's waves (tl_kelvin.h). */
#include "tl_kelvin.h"
#include "tl_glsl.h"

#include <math.h>

void tl_kelvin_slope(double behind, double across, double speed, double length, double footprint,
                     double slope[2])
{
    slope[0] = slope[1] = 0.0;
    if (!(behind > 0.0) || !(speed > 0.1) || !(length > 0.0))
        return;
    const double g = 9.81;
    double k0 = g / (speed * speed);
    /* r = across / behind: inside the wedge r^2 < 1/8. */
    double r = across / behind;
    double c = 1.0 - 8.0 * r * r;
    if (c <= 0.0)
        return;
    double froude = speed / sqrt(g * length);
    double f = fmin(froude / TL_KELVIN_FROUDE, 1.0);
    double distance = sqrt(behind * behind + across * across);
    double wavelength = 2.0 * M_PI / k0;
    /* Spreading: amplitude falls as one over the root of the distance
     * past a wavelength; taller near the cusp, where the two systems
     * meet, and faded in just inside it. */
    double height = TL_KELVIN_HEIGHT * length * f * f * sqrt(wavelength / (wavelength + distance));
    height *= (1.0 + TL_KELVIN_CUSP_GAIN * (1.0 - tl_smoothstep(0.0, 0.3, c))) *
              tl_smoothstep(0.0, 0.04, c);
    /* Faded in over the hull's length behind the stern. */
    height *= tl_smoothstep(0.0, length, behind);
    double root = sqrt(c);
    for (int system = 0; system < 2; system++) {
        /* tan(theta) of the wave that is stationary here: 2 r t^2 - t + r = 0. */
        double t;
        if (fabs(r) < 1e-9)
            t = system == 0 ? 0.0 : INFINITY;
        else
            t = system == 0 ? 2.0 * r / (1.0 + root) : (1.0 + root) / (4.0 * r);
        if (!isfinite(t))
            continue;
        double secant = sqrt(1.0 + t * t);
        double k = k0 * secant * secant; /* the wave's number: k0 / cos^2 theta */
        /* Shorter than four footprints: faded before a pixel aliases them. */
        double resolved =
            footprint > 0.0 ? 1.0 - tl_smoothstep(0.25, 0.5, k * footprint / M_PI) : 1.0;
        if (resolved <= 0.0)
            continue;
        double phase = k0 * (behind + across * t) * secant;
        /* The short divergent waves near the track are lower in
         * proportion: their slopes stay those of the longest. */
        double a = height * resolved * (k0 / k) * sin(phase);
        /* The gradient of the phase is the wave vector, k0 sec (1, t). */
        slope[0] -= a * k0 * secant;
        slope[1] -= a * k0 * secant * t;
    }
}

double tl_kelvin_whitecap(double behind, double across, double speed, double length)
{
    if (!(behind > 0.0) || !(speed > 0.1) || !(length > 0.0))
        return 0.0;
    const double g = 9.81;
    double k0 = g / (speed * speed);
    double r = fabs(across) / behind;
    double c = 1.0 - 8.0 * r * r;
    if (c <= 0.0 || r < 1e-9)
        return 0.0;
    double f = fmin(speed / sqrt(g * length) / TL_KELVIN_FROUDE, 1.0);
    double cusp =
        (1.0 - tl_smoothstep(0.0, TL_KELVIN_WHITECAP_CUSP, c)) * tl_smoothstep(0.0, 0.04, c);
    /* The divergent waves' phase; their height goes as its cosine. */
    double t = (1.0 + sqrt(c)) / (4.0 * r);
    double secant = sqrt(1.0 + t * t);
    double phase = k0 * (behind + fabs(across) * t) * secant;
    return f * f * cusp * tl_smoothstep(0.0, length, behind) *
           exp(-behind / (TL_KELVIN_WHITECAP_LENGTHS * length)) *
           tl_smoothstep(0.75, 0.98, cos(phase));
}
