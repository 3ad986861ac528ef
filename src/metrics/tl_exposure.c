#include "metrics/tl_exposure.h"

#include <math.h>
#include <stddef.h>

double tl_exposure_meter(const float *rgba, int width, int height)
{
    double sum = 0.0, weights = 0.0;
    for (int y = 0; y < height; y++) {
        double v = height > 1 ? 2.0 * y / (height - 1) - 1.0 : 0.0;
        for (int x = 0; x < width; x++) {
            double u = width > 1 ? 2.0 * x / (width - 1) - 1.0 : 0.0;
            const float *p = rgba + ((size_t)y * (size_t)width + (size_t)x) * 4;
            double lum = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            if (!(lum >= TL_EXPOSURE_FLOOR)) /* also NaN */
                lum = TL_EXPOSURE_FLOOR;
            double w = 0.25 + exp(-2.0 * (u * u + v * v));
            sum += w * log2(fmin(lum, 1e30));
            weights += w;
        }
    }
    return weights > 0.0 ? sum / weights : log2(TL_EXPOSURE_FLOOR);
}

int tl_exposure_nodes(double t, double tau, double times[TL_EXPOSURE_NODES],
                      double weights[TL_EXPOSURE_NODES])
{
    t = fmax(t, 0.0);
    times[0] = t;
    if (!(tau > 0.0)) {
        weights[0] = 1.0;
        return 1;
    }
    /* The grid below t, newest first, to the window's start or 0. */
    const double h = tau / TL_EXPOSURE_STEPS_PER_TAU,
                 oldest = fmax(0.0, t - TL_EXPOSURE_WINDOW * tau);
    int n = 1;
    for (double k = floor(t / h); n < TL_EXPOSURE_NODES; k -= 1.0) {
        double g = k * h;
        if (g < oldest - 1e-9 * h)
            break;
        if (g < t - 1e-12 * (1.0 + t)) /* not t itself */
            times[n++] = g;
    }
    /* The lag's kernel exp(-(t-s)/tau)/tau integrated over each span
     * between nodes, shared by its two ends (the meter taken as linear
     * between them); what lies before the oldest node goes to it. */
    for (int i = 0; i < n; i++)
        weights[i] = 0.0;
    for (int i = 0; i + 1 < n; i++) {
        double a = exp(-(t - times[i]) / tau), b = exp(-(t - times[i + 1]) / tau);
        weights[i] += 0.5 * (a - b);
        weights[i + 1] += 0.5 * (a - b);
    }
    weights[n - 1] += exp(-(t - times[n - 1]) / tau);
    return n;
}

double tl_exposure_scale(double exposure, double strength, double adapted)
{
    strength = fmin(fmax(strength, 0.0), 1.0);
    double metered = log2(TL_EXPOSURE_KEY) - adapted;
    metered = fmin(fmax(metered, -TL_EXPOSURE_MAX_STOPS), TL_EXPOSURE_MAX_STOPS);
    if (strength >= 1.0)
        return exp2(metered);
    return pow(exposure, 1.0 - strength) * exp2(strength * metered);
}
