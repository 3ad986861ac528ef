#include "tl_optics.h"

#include <math.h>

double tl_optics_fresnel(double cos_i, double n1, double n2)
{
    cos_i = fmin(fabs(cos_i), 1.0);
    double sin_t = n1 / n2 * sqrt(fmax(0.0, 1.0 - cos_i * cos_i));
    if (sin_t >= 1.0)
        return 1.0; /* total internal reflection */
    double cos_t = sqrt(1.0 - sin_t * sin_t);
    double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    double rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

double tl_optics_snell_window(double n)
{
    return asin(1.0 / n);
}

void tl_optics_water_extinction(const tl_water *w, double sigma[3])
{
    for (int c = 0; c < 3; c++) {
        double s = w->absorption[c] + w->scattering;
        if (w->color_distance > 0.0) {
            /* Clamp: a colour channel of 0 would be an infinite extinction. */
            double color = fmin(fmax(w->color_at_distance[c], 1e-4), 1.0);
            s = -log(color) / w->color_distance;
        }
        sigma[c] = fmax(s, 1e-6);
    }
}

double tl_optics_fog_depth(double density, double height, double y0, double ray_y, double dist)
{
    if (!(density > 0.0) || !(dist > 0.0))
        return 0.0;
    /* Density at the start: the fog thins above the water as exp(-y/H)
     * (no thicker than at the water below it). */
    double at_start = density * exp(-fmax(y0, 0.0) / height);
    double rise = ray_y * dist / height; /* change of y/H along the ray */
    if (fabs(rise) < 1e-6)
        return at_start * dist;
    /* Clamp: beyond e^80 the fog is opaque anyway. */
    return at_start * dist * -expm1(-fmax(fmin(rise, 80.0), -80.0)) / rise;
}
