/* tl_sky: the physical sky on the CPU, in double.
 *
 * Rayleigh and Mie scattering with ozone absorption over a spherical planet
 * (the usual coefficients of Bruneton 2017 and Hillaire 2020), in the
 * look-up-table form of Hillaire 2020, "A Scalable and Production Ready Sky
 * and Atmosphere Rendering Technique": a transmittance table, a table of
 * the multiple scattering's contribution (his isotropic psi_ms
 * approximation of all orders beyond the first), and a per-frame sky-view
 * table the shader samples (drawn on the GPU by the renderer,
 * shaders/sky_view.frag; built here too, as its reference). Also a slow
 * reference that integrates the same
 * equations without the tables, for the tests, and the sun's colour at the
 * camera. Radiance is in scene units: the sun's illuminance at the top of
 * the atmosphere is sky.sun_illuminance. docs/rendering.md has the model. */
#ifndef TL_SKY_H
#define TL_SKY_H

#include "scene/tl_scene.h"

/* The atmosphere a scene asks for, in metres and per metre. */
typedef struct tl_atmosphere {
    double ground_radius, top_radius;
    double rayleigh[3], rayleigh_height;
    double mie_scattering, mie_absorption, mie_height, mie_g;
    double ozone[3], ozone_center, ozone_width;
    double ground_albedo;
} tl_atmosphere;

void tl_sky_atmosphere_of(const tl_scene *s, tl_atmosphere *a);

/* Optical transmittance from radius r (metres from the planet's centre)
 * along cos(zenith) mu to the top of the atmosphere, R G B; 0 where the
 * ray meets the ground. Integrated with `steps` midpoint samples. */
void tl_sky_transmittance(const tl_atmosphere *a, double r, double mu, int steps, double out[3]);

#define TL_SKY_TRANSMITTANCE_W 256
#define TL_SKY_TRANSMITTANCE_H 64
#define TL_SKY_MS_SIZE         64
#define TL_SKY_VIEW_W          192
#define TL_SKY_VIEW_H          108

/* The tables. transmittance and ms depend on the atmosphere alone; view on
 * the sun's direction and the camera's height too. RGB floats, rows of
 * increasing v. */
typedef struct tl_sky_luts {
    tl_atmosphere atmosphere;
    float transmittance[TL_SKY_TRANSMITTANCE_H][TL_SKY_TRANSMITTANCE_W][3];
    float ms[TL_SKY_MS_SIZE][TL_SKY_MS_SIZE][3];
    float view[TL_SKY_VIEW_H][TL_SKY_VIEW_W][3];
    double view_sun_elevation, view_altitude; /* what `view` was built for */
    double ambient[3]; /* the sky's irradiance on a surface facing up, over pi (from `view`) */
    int valid, view_valid;
} tl_sky_luts;

/* Builds the atmosphere's tables (when the atmosphere differs from the one
 * they hold) and the sky-view table (when that or the sun's elevation or
 * the camera's altitude changed), all on the CPU. Radiance for a
 * top-of-atmosphere sun of illuminance 1; the shader scales by
 * sky.sun_illuminance. The renderer builds the sky-view table on the GPU
 * instead (the three calls below); this is its reference. */
void tl_sky_luts_update(tl_sky_luts *l, const tl_atmosphere *a, double sun_elevation,
                        double altitude);

/* The transmittance and multiple-scattering tables alone, rebuilt when the
 * atmosphere differs from theirs (which makes the sky-view table stale).
 * Returns 1 when it rebuilt them. */
int tl_sky_luts_update_atmosphere(tl_sky_luts *l, const tl_atmosphere *a);
/* Whether `view` must be rebuilt for this sun and camera altitude. */
int tl_sky_view_stale(const tl_sky_luts *l, double sun_elevation, double altitude);
/* `view` now holds the table for this sun and altitude (built elsewhere):
 * records that, and computes `ambient` from it. */
void tl_sky_view_built(tl_sky_luts *l, double sun_elevation, double altitude);
/* The camera's height above the ground that the tables use for `altitude`:
 * held at least 1 m above the ground and 1 m under the atmosphere's top. */
double tl_sky_camera_height(const tl_atmosphere *a, double altitude);

/* Sky radiance seen from `altitude` metres in direction (elevation above
 * the horizon, azimuth from the sun's), sun of illuminance 1: the sky-view
 * table's mapping, read back bilinearly (what the shader does). */
void tl_sky_view_lookup(const tl_sky_luts *l, double elevation, double azimuth, double out[3]);

/* The same radiance integrated directly, without any table (slow: the
 * tests' reference): single scattering with transmittances integrated in
 * double, plus multiple scattering from the psi_ms integral evaluated
 * where it is needed. */
void tl_sky_reference(const tl_atmosphere *a, double sun_elevation, double altitude,
                      double elevation, double azimuth, double out[3]);

/* The sun's light at the camera: its top-of-atmosphere illuminance times
 * the transmittance along its path (0 once it has set). */
void tl_sky_sun_light(const tl_atmosphere *a, double sun_elevation, double altitude,
                      double illuminance, double out[3]);

#endif
