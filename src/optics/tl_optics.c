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

double tl_optics_fresnel_rough(double cos_i, double n1, double n2, double spread)
{
    double theta = acos(fmin(fabs(cos_i), 1.0));
    if (n1 > n2 && spread > 0.0) {
        /* Past the critical angle a facet reflects all; short of it, the
         * facets' mean tilt there stands for them. */
        double critical = asin(n2 / n1), a = (critical - theta) / spread;
        double inside = 0.5 * erfc(-a * M_SQRT1_2); /* the share short of it */
        double density = exp(-0.5 * a * a) / sqrt(2.0 * M_PI);
        double mean = theta - spread * density / fmax(inside, TL_FRESNEL_LEAST_SHARE);
        mean = fmin(fabs(mean), critical);
        return 1.0 - inside + inside * tl_optics_fresnel(cos(mean), n1, n2);
    }
    double d = TL_FRESNEL_TAP * spread;
    return 2.0 / 3.0 * tl_optics_fresnel(cos_i, n1, n2) +
           1.0 / 6.0 *
               (tl_optics_fresnel(cos(fmin(theta + d, 0.5 * M_PI)), n1, n2) +
                tl_optics_fresnel(cos(fabs(theta - d)), n1, n2));
}

double tl_optics_snell_window(double n)
{
    return asin(1.0 / n);
}

double tl_optics_lamp_glint(double cos_to, double size)
{
    double spread = fmax(size, TL_LAMP_GLINT_MIN);
    double angle2 = 2.0 * fmax(1.0 - cos_to, 0.0);
    return (size * size) / (spread * spread) * exp(-angle2 / (spread * spread));
}

double tl_optics_window_share(double ny, double ior)
{
    double s = 1.0 / ior;
    if (ny >= s)
        return ny;
    double t = fmax(ny + s, 0.0) / (1.0 + s);
    return t * t;
}

double tl_optics_normal_blend(const tl_water *w, double dist)
{
    return w->normal_smooth_max *
           fmin(1.0, sqrt(fmax(dist, 0.0) * w->normal_smooth_rate) * w->normal_smooth_gain);
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

void tl_optics_water_fall(const tl_water *w, const double sigma[3], double fall[3])
{
    for (int c = 0; c < 3; c++)
        fall[c] = fmax(sigma[c] - TL_WATER_PHASE_G * w->scattering, 0.1 * sigma[c]);
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

void tl_optics_sun_in_water(const double sun[3], double n, double dir[3])
{
    double cos_i = fmax(sun[1], 0.0);
    double sin_t = sqrt(fmax(0.0, 1.0 - cos_i * cos_i)) / n;
    double horizontal = hypot(sun[0], sun[2]);
    dir[0] = 0.0;
    dir[1] = -1.0;
    dir[2] = 0.0;
    if (horizontal > 0.0) { /* light travels away from the sun, bent down */
        dir[0] = -sun[0] / horizontal * sin_t;
        dir[2] = -sun[2] / horizontal * sin_t;
        dir[1] = -sqrt(1.0 - sin_t * sin_t);
    }
}

/* The integral over [0, t] of exp(-c s) ds. */
static double path_integral(double c, double t)
{
    double ct = fmin(c * t, TL_WATER_MAX_OPTICAL);
    if (fabs(ct) < 1e-3)
        return t * (1.0 - 0.5 * ct);
    return (1.0 - exp(-ct)) / c;
}

double tl_optics_particle_scattering(double density)
{
    const double a = TL_PARTICLE_RADIUS_MIN, b = TL_PARTICLE_RADIUS_MAX;
    /* Of a radius in [a, b] with a density ∝ 1/r²: ∫r²·r⁻² / ∫r⁻² = ab. */
    double mean_square = a * b;
    return density * TL_PARTICLE_EFFICIENCY * M_PI * mean_square;
}

void tl_optics_water_inscatter(const tl_water_light *l, double depth, const double ray[3], double t,
                               double out[3])
{
    const double g = TL_WATER_PHASE_G;
    double mu = -(l->sun_water[0] * ray[0] + l->sun_water[1] * ray[1] + l->sun_water[2] * ray[2]);
    double phase = (1.0 - g * g) / (4.0 * M_PI * pow(1.0 + g * g - 2.0 * g * mu, 1.5));
    double sun_down = fmax(-l->sun_water[1], TL_WATER_MIN_SUN_DOWN);
    double z = fmax(depth, 0.0);
    if (ray[1] > 0.0) /* it leaves the water by the mean surface */
        t = fmin(t, z / ray[1]);
    for (int c = 0; c < 3; c++) {
        double sigma = l->sigma[c], fall = l->fall[c];
        double sun = l->sun_light[c] * l->sun_water_trans * exp(-fall * z / sun_down);
        double sky = l->sky_ambient[c] * exp(-fall * z);
        /* Along the ray the light it meets changes by exp(fall · rise / down)
         * and what it scatters is dimmed by exp(-sigma s) on the way back. */
        out[c] =
            l->scattering * (phase * sun * path_integral(sigma - fall * ray[1] / sun_down, t) +
                             TL_WATER_SKY_SCATTER * sky * path_integral(sigma - fall * ray[1], t));
    }
}
