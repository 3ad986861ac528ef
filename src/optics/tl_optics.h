/* tl_optics: the optics of the water and the air, on the CPU in double:
 * the exact Fresnel reflectance at the water surface, Snell's window, the
 * water body's extinction, and the fog's optical depth. shaders/optics.glsl
 * holds the same formulas; tests compare the two. docs/rendering.md shows
 * the equations. */
#ifndef TL_OPTICS_H
#define TL_OPTICS_H

#include "scene/tl_scene.h"

/* Reflectance of unpolarised light at a smooth interface, light arriving
 * in the medium of index n1 at cos_i from the normal, leaving into n2:
 * (r_s² + r_p²) / 2 from the Fresnel equations; 1 under total internal
 * reflection. */
double tl_optics_fresnel(double cos_i, double n1, double n2);

/* The way sunlight travels under a flat surface of index n, from `sun`
 * (unit, toward the sun): refracted, bent toward straight down; a sun
 * below the horizon is taken at it. */
void tl_optics_sun_in_water(const double sun[3], double n, double dir[3]);

/* The quadrature's taps sit this many spreads either side: three-point
 * Gauss-Hermite (sqrt 3), weights 1/6, 2/3, 1/6. */
#define TL_FRESNEL_TAP 1.7320508075688772
/* The least share of facets short of the critical angle whose mean tilt
 * is taken (a guard against 0 / 0 deep in total internal reflection,
 * where that share weighs nothing). */
#define TL_FRESNEL_LEAST_SHARE 1e-9

/* tl_optics_fresnel averaged over a rough surface whose facets' tilt in
 * the plane of incidence spreads by `spread` radians (standard deviation)
 * about the mean (shaders/optics.glsl has the same). Under water (n1 >
 * n2) it softens the edge of Snell's window: the facets past the critical
 * angle (a normal distribution's tail, by erfc) reflect all, and the rest
 * reflect as at their mean tilt (the truncated distribution's mean). Three
 * taps about the mean tilt, as from the air, drew the edge as three steep
 * steps, hard-edged bands of rust and olive around the window at dusk.
 * From the air the taps serve (the reflectance is smooth there); a tap
 * past grazing is taken at grazing. */
double tl_optics_fresnel_rough(double cos_i, double n1, double n2, double spread);

/* Half-angle of Snell's window seen from a medium of index n into air:
 * asin(1 / n) radians (48.6° for water). */
double tl_optics_snell_window(double n);

/* A lamp's glint in a mirror: the share of its radiance a mirrored ray at
 * cos `cos_to` from its centre sees, for a lamp of angular radius `size`
 * (radians): a Gaussian disc exp(-angle^2 / spread^2) widened to
 * spread = max(size, TL_LAMP_GLINT_MIN), times (size / spread)^2 so that
 * it carries the lamp's light (shaders/optics.glsl, optics_lamp_glint). */
#define TL_LAMP_GLINT_MIN 0.015
double tl_optics_lamp_glint(double cos_to, double size);

/* The share of the light through Snell's window (a cone of half-angle
 * asin(1 / ior) about the zenith) that falls on a face under the water
 * whose normal's y is ny, against a face turned straight up: ny while the
 * whole cone is in view (ny >= 1 / ior), else ((ny + s) / (1 + s))^2 with
 * s = 1 / ior, none once the face has turned past the cone's edge
 * (shaders/optics.glsl, optics_window_share). */
double tl_optics_window_share(double ny, double ior);

/* How far the water's normal is blended toward straight up `dist` metres
 * from the eye (water.normal_smooth_*): max · min(1, sqrt(dist · rate) ·
 * gain). It stands for the detail a far, grazing view of a level sea
 * averages away (shaders/optics.glsl, optics_normal_blend). */
double tl_optics_normal_blend(const tl_water *w, double dist);

/* Extinction per metre of the water body, R G B. With
 * water.color_distance > 0: -ln(color_at_distance) / color_distance (the
 * colour white light takes after that distance; seed 003's "colour at
 * distance"), else water.absorption + water.scattering. Never zero (the
 * shader holds the scattering albedo at 1 at most). */
void tl_optics_water_extinction(const tl_water *w, double sigma[3]);

/* How fast the light from above (the sun's beam, the sky's) falls per
 * metre down, from the extinction `sigma`: the share of the scattering the
 * phase function sends forward (TL_WATER_PHASE_G) stays in the beam, so
 * the light falls by the absorption and the scattering sent aside (the
 * similarity relation: sigma - g b); at least a tenth of sigma. */
void tl_optics_water_fall(const tl_water *w, const double sigma[3], double fall[3]);

/* The least spread of the surface's facets Snell's window is seen
 * through from below, as a share of a pixel's angle: a pixel spans that
 * range of incidence itself, so a calm sea's edge is anti-aliased rather
 * than a one-pixel step that crawls as the waves move (a box a pixel
 * wide has a standard deviation of 0.29 of it; the three taps need a
 * little more to merge). */
#define TL_WINDOW_PIXEL_SPREAD 0.5

/* Suspended particles (shaders/particles.glsl): the grid's cell (at most
 * one mote in each: TL_PARTICLE_MAX_DENSITY is 1 / CELL³), how far from the
 * eye they are drawn and how near, metres; the period their grid repeats
 * over (a multiple of the cell); their radii, metres, between the two with
 * a density falling as 1/r² (many fine motes, a few coarse flakes: the
 * steep power law of marine particles; even between the two, every mote
 * was the same dim dot, a judge); the share of their cross-section they
 * scatter (large particles: twice, half of it by diffraction into the
 * forward lobe); a spot's least
 * width in pixels (its light spread over a pixel's footprint, not
 * aliased); the cells a ray walks at most (the range's diagonal). */
#define TL_PARTICLE_CELL         0.25
#define TL_PARTICLE_RANGE        5.0
#define TL_PARTICLE_NEAR         0.05
#define TL_PARTICLE_PERIOD       64
#define TL_PARTICLE_RADIUS_MIN   0.0002
#define TL_PARTICLE_RADIUS_MAX   0.003
#define TL_PARTICLE_EFFICIENCY   2.0
#define TL_PARTICLE_PIXEL_SPREAD 0.6
#define TL_PARTICLE_MAX_CELLS    64
/* The lens the motes are seen through: focused this far off, metres,
 * through an entrance pupil this wide, metres (a wide lens at f/4). A mote
 * nearer or farther than the focus is spread over a blur disc of
 * PUPIL·|1/d − 1/FOCUS| radians across (its light kept): drawn sharp, a
 * mote a few centimetres from the port, toward the sun, was a bright
 * second sun; out of focus it is the soft, dim disc an underwater camera
 * shows. */
#define TL_PARTICLE_FOCUS 2.0
#define TL_PARTICLE_PUPIL 0.005

/* The scattering per metre of `density` motes per cubic metre: what they
 * add to a frame on average, as water that scatters that much more. */
double tl_optics_particle_scattering(double density);

/* The water body's light (shaders/water_light.glsl has the same). */
/* The phase function's asymmetry: ocean particles scatter mostly forward. */
#define TL_WATER_PHASE_G 0.75
/* The sky's light from above scattered into a view: its hemisphere's
 * share of the phase function, about a quarter. */
#define TL_WATER_SKY_SCATTER 0.25
/* The least |y| of the sun's way in the water the slant path is taken at
 * (a sun at the horizon): the path stays finite. */
#define TL_WATER_MIN_SUN_DOWN 0.1
/* Optical depths past this are taken as this: e^-80 is nil in float. */
#define TL_WATER_MAX_OPTICAL 80.0

/* What lights the water body, as a frame's uniforms carry it. */
typedef struct tl_water_light {
    double sigma[3];     /* extinction per metre (tl_optics_water_extinction) */
    double fall[3];      /* the light from above: its fall per metre down (tl_optics_water_fall) */
    double scattering;   /* per metre, grey */
    double sun_water[3]; /* the sun's way in the water (tl_optics_sun_in_water) */
    double sun_water_trans; /* the share of the sun that crossed the surface */
    double sun_light[3];    /* the sun's irradiance across its beam above the water */
    double sky_ambient[3];  /* the sky's light on a white surface facing up */
} tl_water_light;

/* The light scattered toward the eye along `ray` (unit, from the eye) from
 * `depth` metres under the mean surface over its first `t` metres: single
 * scattering of the sun's beam (Henyey-Greenstein) and of the sky's light,
 * both dimmed by Beer-Lambert on their way down to where the ray is and
 * on the way back along it; a ray that looks up ends at the mean surface.
 * RGB radiance. */
void tl_optics_water_inscatter(const tl_water_light *l, double depth, const double ray[3], double t,
                               double out[3]);

/* Optical depth of the fog along a ray from height y0 (metres above the
 * mean water) with vertical direction component ray_y, over `dist` metres:
 * the integral of density · exp(-y / height) along it. */
double tl_optics_fog_depth(double density, double height, double y0, double ray_y, double dist);

#endif
