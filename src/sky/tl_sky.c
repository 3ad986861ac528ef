#include "tl_sky.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

void tl_sky_atmosphere_of(const tl_scene *s, tl_atmosphere *a)
{
    memset(a, 0, sizeof *a);
    a->ground_radius = s->sky.planet_radius * 1000.0;
    a->top_radius = a->ground_radius + s->sky.atmosphere_height * 1000.0;
    const double rayleigh[3] = {5.802e-6, 13.558e-6, 33.1e-6};
    const double ozone[3] = {0.650e-6, 1.881e-6, 0.085e-6};
    for (int c = 0; c < 3; c++) {
        a->rayleigh[c] = rayleigh[c];
        a->ozone[c] = ozone[c] * s->sky.ozone;
    }
    a->rayleigh_height = 8000.0;
    a->mie_scattering = 3.996e-6 * s->sky.turbidity;
    a->mie_absorption = 4.40e-6 * s->sky.turbidity;
    a->mie_height = 1200.0;
    a->mie_g = 0.8;
    a->ozone_center = 25000.0;
    a->ozone_width = 15000.0;
    a->ground_albedo = s->sky.ground_albedo;
}

/* Scattering and extinction coefficients at height h above the ground. */
static void medium(const tl_atmosphere *a, double h, double ray_s[3], double *mie_s,
                   double ext[3])
{
    double dr = exp(-h / a->rayleigh_height), dm = exp(-h / a->mie_height);
    double dozone = fmax(0.0, 1.0 - fabs(h - a->ozone_center) / a->ozone_width);
    *mie_s = a->mie_scattering * dm;
    for (int c = 0; c < 3; c++) {
        ray_s[c] = a->rayleigh[c] * dr;
        ext[c] = ray_s[c] + (a->mie_scattering + a->mie_absorption) * dm + a->ozone[c] * dozone;
    }
}

static double to_top(const tl_atmosphere *a, double r, double mu)
{
    double disc = r * r * (mu * mu - 1.0) + a->top_radius * a->top_radius;
    return fmax(0.0, -r * mu + sqrt(fmax(disc, 0.0)));
}

/* Distance to the ground along mu, or -1 when the ray misses it. */
static double to_ground(const tl_atmosphere *a, double r, double mu)
{
    double disc = r * r * (mu * mu - 1.0) + a->ground_radius * a->ground_radius;
    if (mu >= 0.0 || disc < 0.0)
        return -1.0;
    return fmax(0.0, -r * mu - sqrt(disc));
}

void tl_sky_transmittance(const tl_atmosphere *a, double r, double mu, int steps, double out[3])
{
    if (to_ground(a, r, mu) >= 0.0) { /* the planet's shadow */
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    /* Steps grow with distance (t = d·x²): the air is densest at the start
     * of the rays that matter (low ones). */
    double d = to_top(a, r, mu), depth[3] = {0, 0, 0};
    for (int i = 0; i < steps; i++) {
        double x = (i + 0.5) / steps, t = d * x * x, dt = d * 2.0 * x / steps;
        double rt = sqrt(r * r + t * t + 2.0 * r * mu * t);
        double rs[3], ms, ext[3];
        medium(a, rt - a->ground_radius, rs, &ms, ext);
        for (int c = 0; c < 3; c++)
            depth[c] += ext[c] * dt;
    }
    for (int c = 0; c < 3; c++)
        out[c] = exp(-depth[c]);
}

/* ---- the transmittance table (Bruneton's mapping: fine at the horizon) ---- */

static void transmittance_uv(const tl_atmosphere *a, double r, double mu, double *u, double *v)
{
    double H = sqrt(a->top_radius * a->top_radius - a->ground_radius * a->ground_radius);
    double rho = sqrt(fmax(r * r - a->ground_radius * a->ground_radius, 0.0));
    double d = to_top(a, r, mu), d_min = a->top_radius - r, d_max = rho + H;
    *u = d_max > d_min ? (d - d_min) / (d_max - d_min) : 0.0;
    *v = rho / H;
}

static void bilinear(const float *table, int w, int h, double u, double v, double out[3])
{
    double x = fmin(fmax(u * w - 0.5, 0.0), w - 1.0), y = fmin(fmax(v * h - 0.5, 0.0), h - 1.0);
    int x0 = (int)x, y0 = (int)y;
    int x1 = x0 + 1 < w ? x0 + 1 : x0, y1 = y0 + 1 < h ? y0 + 1 : y0;
    double fx = x - x0, fy = y - y0;
    for (int c = 0; c < 3; c++) {
        double a = table[(y0 * w + x0) * 3 + c], b = table[(y0 * w + x1) * 3 + c];
        double d = table[(y1 * w + x0) * 3 + c], e = table[(y1 * w + x1) * 3 + c];
        out[c] = (a * (1 - fx) + b * fx) * (1 - fy) + (d * (1 - fx) + e * fx) * fy;
    }
}

static void lut_transmittance(const tl_sky_luts *l, double r, double mu, double out[3])
{
    if (to_ground(&l->atmosphere, r, mu) >= 0.0) {
        out[0] = out[1] = out[2] = 0.0;
        return;
    }
    double u, v;
    transmittance_uv(&l->atmosphere, r, mu, &u, &v);
    bilinear(&l->transmittance[0][0][0], TL_SKY_TRANSMITTANCE_W, TL_SKY_TRANSMITTANCE_H, u, v, out);
}

static void build_transmittance(tl_sky_luts *l)
{
    const tl_atmosphere *a = &l->atmosphere;
    double H = sqrt(a->top_radius * a->top_radius - a->ground_radius * a->ground_radius);
    for (int j = 0; j < TL_SKY_TRANSMITTANCE_H; j++) {
        double rho = H * (j + 0.5) / TL_SKY_TRANSMITTANCE_H;
        double r = sqrt(rho * rho + a->ground_radius * a->ground_radius);
        for (int i = 0; i < TL_SKY_TRANSMITTANCE_W; i++) {
            double d_min = a->top_radius - r, d_max = rho + H;
            double d = d_min + (i + 0.5) / TL_SKY_TRANSMITTANCE_W * (d_max - d_min);
            double mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
            mu = fmin(fmax(mu, -1.0), 1.0);
            /* Just above the horizon: never the ground's shadow here. */
            double t[3], disc = r * r * (mu * mu - 1.0) + a->ground_radius * a->ground_radius;
            if (mu < 0.0 && disc >= 0.0)
                mu = -sqrt(fmax(0.0, 1.0 - a->ground_radius * a->ground_radius / (r * r))) + 1e-9;
            tl_sky_transmittance(a, r, mu, 64, t);
            for (int c = 0; c < 3; c++)
                l->transmittance[j][i][c] = (float)t[c];
        }
    }
}

/* ---- multiple scattering (Hillaire's psi_ms) ---- */

typedef void (*transmittance_fn)(const void *ctx, double r, double mu, double out[3]);

static void direct_transmittance(const void *ctx, double r, double mu, double out[3])
{
    tl_sky_transmittance(ctx, r, mu, 48, out);
}

static void table_transmittance(const void *ctx, double r, double mu, double out[3])
{
    lut_transmittance(ctx, r, mu, out);
}

/* Light off the Lambertian ground where a ray from radius r along dir
 * meets it after d metres, through the optical depth gathered on the way. */
static void add_ground(const tl_atmosphere *a, transmittance_fn tr, const void *ctx,
                       const double dir[3], double r, double d, const double sun[3],
                       const double depth[3], double L[3])
{
    double g[3] = {dir[0] * d, r + dir[1] * d, dir[2] * d};
    double rg = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    double mu_g = (g[0] * sun[0] + g[1] * sun[1] + g[2] * sun[2]) / rg, ts[3];
    tr(ctx, rg, mu_g, ts);
    for (int c = 0; c < 3; c++)
        L[c] += exp(-depth[c]) * ts[c] * fmax(mu_g, 0.0) * a->ground_albedo / PI;
}

/* psi_ms at radius r with the sun at cos-zenith mu_s: the second order of
 * scattering with an isotropic phase, over a sphere of directions, divided
 * by (1 - f_ms) for all orders beyond (a geometric series). */
static void psi_ms(const tl_atmosphere *a, double r, double mu_s, transmittance_fn tr,
                   const void *ctx, int dirs, int steps, double out[3])
{
    const double iso = 1.0 / (4.0 * PI);
    double L[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    double sun[3] = {sqrt(fmax(0.0, 1.0 - mu_s * mu_s)), mu_s, 0.0};
    for (int k = 0; k < dirs; k++) {
        /* Fibonacci sphere. */
        double y = 1.0 - 2.0 * (k + 0.5) / dirs, rad = sqrt(fmax(0.0, 1.0 - y * y));
        double phi = k * 2.399963229728653;
        double dir[3] = {rad * cos(phi), y, rad * sin(phi)};
        double mu = dir[1];
        double ground = to_ground(a, r, mu);
        double d = ground >= 0.0 ? ground : to_top(a, r, mu);
        double depth[3] = {0, 0, 0};
        double dt = d / steps;
        for (int i = 0; i < steps; i++) {
            double t = (i + 0.5) * dt;
            double p[3] = {dir[0] * t, r + dir[1] * t, dir[2] * t};
            double rp = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            double rs[3], ms, ext[3], ts[3];
            medium(a, rp - a->ground_radius, rs, &ms, ext);
            double mu_sp = (p[0] * sun[0] + p[1] * sun[1] + p[2] * sun[2]) / rp;
            tr(ctx, rp, mu_sp, ts);
            for (int c = 0; c < 3; c++) {
                double seg = exp(-(depth[c] + 0.5 * ext[c] * dt));
                double scat = rs[c] + ms;
                L[c] += seg * scat * ts[c] * iso * dt;
                f[c] += seg * scat * dt;
                depth[c] += ext[c] * dt;
            }
        }
        if (ground >= 0.0)
            add_ground(a, tr, ctx, dir, r, d, sun, depth, L);
    }
    /* Both are means over the sphere of directions; f is the share of
     * light a scattering event passes on (< 1 in any real atmosphere). */
    for (int c = 0; c < 3; c++)
        out[c] = L[c] / dirs / (1.0 - fmin(f[c] / dirs, 0.999));
}

static void build_ms(tl_sky_luts *l)
{
    const tl_atmosphere *a = &l->atmosphere;
    for (int j = 0; j < TL_SKY_MS_SIZE; j++) {
        /* v = sqrt(h / H): rows crowd near the ground, where it changes. */
        double v = (j + 0.5) / TL_SKY_MS_SIZE;
        double h = v * v * (a->top_radius - a->ground_radius);
        for (int i = 0; i < TL_SKY_MS_SIZE; i++) {
            /* mu_s = x·|x|: columns crowd where the sun sets, where it changes. */
            double x = 2.0 * (i + 0.5) / TL_SKY_MS_SIZE - 1.0, mu_s = x * fabs(x), v[3];
            psi_ms(a, a->ground_radius + h, mu_s, table_transmittance, l, 64, 20, v);
            for (int c = 0; c < 3; c++)
                l->ms[j][i][c] = (float)v[c];
        }
    }
}

static void lut_ms(const tl_sky_luts *l, double r, double mu_s, double out[3])
{
    const tl_atmosphere *a = &l->atmosphere;
    double u = 0.5 + 0.5 * (mu_s < 0.0 ? -sqrt(-mu_s) : sqrt(mu_s));
    double v = sqrt(fmax(r - a->ground_radius, 0.0) / (a->top_radius - a->ground_radius));
    bilinear(&l->ms[0][0][0], TL_SKY_MS_SIZE, TL_SKY_MS_SIZE, u, v, out);
}

/* ---- radiance along a view ray ---- */

static double phase_rayleigh(double c)
{
    return 3.0 / (16.0 * PI) * (1.0 + c * c);
}

static double phase_mie(double c, double g) /* Cornette-Shanks */
{
    double k = 3.0 / (8.0 * PI) * (1.0 - g * g) / (2.0 + g * g);
    return k * (1.0 + c * c) / pow(1.0 + g * g - 2.0 * g * c, 1.5);
}

typedef void (*ms_fn)(const void *ctx, double r, double mu_s, double out[3]);

static void table_ms(const void *ctx, double r, double mu_s, double out[3])
{
    lut_ms(ctx, r, mu_s, out);
}

static void direct_ms(const void *ctx, double r, double mu_s, double out[3])
{
    psi_ms(ctx, r, mu_s, direct_transmittance, ctx, 48, 24, out);
}

/* Radiance toward the eye at radius r looking along (elevation, azimuth
 * from the sun), the sun at `sun_elevation`, for a sun of illuminance 1. */
static void radiance(const tl_atmosphere *a, transmittance_fn tr, ms_fn ms_of, const void *ctx,
                     double r, double sun_elevation, double elevation, double azimuth, int steps,
                     double out[3])
{
    double dir[3] = {cos(elevation) * sin(azimuth), sin(elevation), cos(elevation) * cos(azimuth)};
    double sun[3] = {0.0, sin(sun_elevation), cos(sun_elevation)};
    double cos_sun = dir[0] * sun[0] + dir[1] * sun[1] + dir[2] * sun[2];
    double pr = phase_rayleigh(cos_sun), pm = phase_mie(cos_sun, a->mie_g);
    double mu = dir[1];
    double ground = to_ground(a, r, mu);
    double d = ground >= 0.0 ? ground : to_top(a, r, mu);
    double depth[3] = {0, 0, 0}, L[3] = {0, 0, 0};
    double prev = 0.0;
    for (int i = 0; i < steps; i++) {
        /* Denser near the eye, where the air is densest along the ray. */
        double t1 = d * ((i + 1.0) / steps) * ((i + 1.0) / steps), dt = t1 - prev;
        double t = prev + 0.5 * dt;
        prev = t1;
        double p[3] = {dir[0] * t, r + dir[1] * t, dir[2] * t};
        double rp = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        double rs[3], msc, ext[3], ts[3], psi[3];
        medium(a, rp - a->ground_radius, rs, &msc, ext);
        double mu_s = (p[0] * sun[0] + p[1] * sun[1] + p[2] * sun[2]) / rp;
        tr(ctx, rp, mu_s, ts);
        ms_of(ctx, rp, mu_s, psi);
        for (int c = 0; c < 3; c++) {
            double source = (rs[c] * pr + msc * pm) * ts[c] + (rs[c] + msc) * psi[c];
            double seg = exp(-(depth[c] + 0.5 * ext[c] * dt));
            L[c] += seg * source * dt;
            depth[c] += ext[c] * dt;
        }
    }
    if (ground >= 0.0)
        add_ground(a, tr, ctx, dir, r, d, sun, depth, L);
    for (int c = 0; c < 3; c++)
        out[c] = L[c];
}

/* The sky-view table's latitude mapping: dense at the horizon. */
static double view_latitude(double v)
{
    double l = 2.0 * v - 1.0;
    return (l < 0.0 ? -1.0 : 1.0) * l * l * 0.5 * PI;
}

static double view_v(double latitude)
{
    double l = sqrt(fabs(latitude) / (0.5 * PI));
    return 0.5 + 0.5 * (latitude < 0.0 ? -l : l);
}

static double camera_radius(const tl_atmosphere *a, double altitude)
{
    return a->ground_radius + fmin(fmax(altitude, 1.0), a->top_radius - a->ground_radius - 1.0);
}

static void build_view(tl_sky_luts *l, double sun_elevation, double altitude)
{
    const tl_atmosphere *a = &l->atmosphere;
    double r = camera_radius(a, altitude);
    double sum[3] = {0, 0, 0}, weight = 0.0;
    for (int j = 0; j < TL_SKY_VIEW_H; j++) {
        double lat = view_latitude((j + 0.5) / TL_SKY_VIEW_H);
        for (int i = 0; i < TL_SKY_VIEW_W; i++) {
            double az = PI * (i + 0.5) / TL_SKY_VIEW_W, L[3];
            radiance(a, table_transmittance, table_ms, l, r, sun_elevation, lat, az, 40, L);
            for (int c = 0; c < 3; c++)
                l->view[j][i][c] = (float)L[c];
            if (lat > 0.0) { /* cosine-free mean over the hemisphere's solid angle */
                double w = cos(lat);
                for (int c = 0; c < 3; c++)
                    sum[c] += w * L[c];
                weight += w;
            }
        }
    }
    for (int c = 0; c < 3; c++)
        l->ambient[c] = weight > 0.0 ? sum[c] / weight : 0.0;
    l->view_sun_elevation = sun_elevation;
    l->view_altitude = altitude;
    l->view_valid = 1;
}

void tl_sky_luts_update(tl_sky_luts *l, const tl_atmosphere *a, double sun_elevation,
                        double altitude)
{
    if (!l->valid || memcmp(&l->atmosphere, a, sizeof *a) != 0) {
        l->atmosphere = *a;
        build_transmittance(l);
        build_ms(l);
        l->valid = 1;
        l->view_valid = 0;
    }
    if (!l->view_valid || l->view_sun_elevation != sun_elevation ||
        l->view_altitude != altitude)
        build_view(l, sun_elevation, altitude);
}

void tl_sky_view_lookup(const tl_sky_luts *l, double elevation, double azimuth, double out[3])
{
    double az = fabs(remainder(azimuth, 2.0 * PI)); /* symmetric about the sun's plane */
    bilinear(&l->view[0][0][0], TL_SKY_VIEW_W, TL_SKY_VIEW_H, az / PI, view_v(elevation), out);
}

void tl_sky_reference(const tl_atmosphere *a, double sun_elevation, double altitude,
                      double elevation, double azimuth, double out[3])
{
    radiance(a, direct_transmittance, direct_ms, a, camera_radius(a, altitude), sun_elevation,
             elevation, azimuth, 120, out);
}

void tl_sky_sun_light(const tl_atmosphere *a, double sun_elevation, double altitude,
                      double illuminance, double out[3])
{
    double t[3];
    tl_sky_transmittance(a, camera_radius(a, altitude), sin(sun_elevation), 128, t);
    for (int c = 0; c < 3; c++)
        out[c] = illuminance * t[c];
}
