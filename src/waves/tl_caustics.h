/* tl_caustics: the sunlight the moving surface focuses under the water, on
 * the CPU in double; shaders/caustics.glsl is the same estimate, and
 * test_caustics compares the two.
 *
 * Sunlight reaching a point at `depth` under the mean surface crossed the
 * surface near x0, where the straight refracted ray from the sun starts.
 * Each surface point x sends its refracted ray to X(x) = x + depth · a(x),
 * a(x) the ray's horizontal run per metre down. Light that crossed an
 * area dA of surface lands on |det J| dA of the plane at that depth,
 * J = dX/dx = I + depth · da/dx, so the irradiance there is the flat
 * surface's over |det J|: bright where the waves focus (det near 0),
 * dim where they spread the light. da/dx is a finite difference over a
 * step that grows with depth (TL_CAUSTIC_BLUR), and never under the
 * pixel's footprint; the
 * waves themselves are taken at that footprint's level of detail, so
 * nothing finer than the step aliases into the pattern. */
#ifndef TL_CAUSTICS_H
#define TL_CAUSTICS_H

#include "waves/tl_waves.h"

/* The finite difference's step at the surface, metres: fine enough for
 * the ripples that make the brightest lines near the surface. */
#define TL_CAUSTIC_STEP 0.01
/* Its growth per metre of depth. The sun's disc alone would blur by its
 * angular diameter in the water (0.007 per metre); the estimate follows
 * one ray back to the surface, and below the ripples' focal depths each
 * point is lit through several, so the step takes out the waves that
 * focus above the point: with this growth the light is conserved on
 * average at every depth from 0.5 to 40 m (test_caustics). */
#define TL_CAUSTIC_BLUR 0.06
/* The finer waves' pattern: a second estimate from the octaves between
 * this growth's step and TL_CAUSTIC_BLUR's, their Jacobian less the
 * coarser waves' (the two scales' maps compose, so their determinants,
 * and their foci, multiply). It nets the coarse web's cells with finer,
 * dimmer lines. */
#define TL_CAUSTIC_FINE_BLUR 0.02
/* The share of the finer waves' contrast kept near the surface: they are
 * far past their focal depths, where several sheets overlap and one
 * followed sheet overstates the pattern. Deeper it falls with the share
 * of the sun's beam the water has not yet scattered (the scattered light
 * comes in at angles that wash fine lines out first); with it the light
 * stays within 15% of a flat sea's on average at 1, 5 and 40 m
 * (test_caustics). */
#define TL_CAUSTIC_FINE_SHARE 0.5
/* Skipped where the finer step is over this share of the coarse one:
 * there is no band between them. */
#define TL_CAUSTIC_FINE_GAP 0.8
/* The brightest focus, in flat surface irradiances: where det J passes
 * through 0 the estimate would be infinite; focus = sqrt((1 + k) /
 * (det² + k)), k = 1 / PEAK², rounds it off and keeps a flat sea at
 * exactly 1. */
#define TL_CAUSTIC_PEAK 6.0
/* The sun's disc seen from under the water: its angular diameter
 * (0.53 deg) over the water's refractive index, radians. */
#define TL_CAUSTIC_SUN_SPREAD 0.007
/* Inside a fold, the share of |det| the followed sheet's estimate keeps
 * (the other two sheets' light taken as its own twice over). */
#define TL_CAUSTIC_FOLD (1.0 / 3.0)
/* How a line is rounded off: the sun's disc and the unresolved tilt
 * spread a bundle over a band, and from the band's middle to its edge
 * (this share of its width) det changes by that distance times
 * |grad det|: the least |det| the band's light sees. Lines where the fold
 * is sharp come out thin and dim, lines where det lingers near 0 (where
 * lines meet) bright, so the web's lines differ in brightness as real
 * ones do; before, det was taken to change by 1 across the step, and
 * every line reached one peak. The light stays conserved on average as
 * well as it was (test_caustics). The finer web and the shafts' bundles
 * still take the change of 1 across their step. */
#define TL_CAUSTIC_BAND 0.5
/* The steepest a refracted ray's run is taken (its |y| at least this):
 * a sun at the horizon through a tilted facet. */
#define TL_CAUSTIC_MIN_DOWN 0.2
/* The crest caustics' reach, metres: their contrast falls by
 * exp(-path / reach) with the water the light crossed. Beyond a few metres
 * the view ray gathers the glow over a range of depths where the web has
 * spread into broad, smooth cells, and kept whole those read as marble on
 * the face; under the thin lip the web is sharp and is seen as such. */
#define TL_CAUSTIC_CREST_REACH 3.0

/* The light shafts (shaders/shafts.glsl): how far along a view ray they
 * are sampled, metres (beyond, at the steps a frame can afford, they
 * came out as noise), and the least footprint their focus is
 * taken at (a shaft shows only the waves' coarse bundles). */
#define TL_SHAFT_RANGE     20.0
#define TL_SHAFT_FOOTPRINT 0.3
/* ... and at least this share of the width a sample's length of ray
 * sweeps across them. */
#define TL_SHAFT_SMOOTH 0.35

typedef struct tl_caustic_light {
    double sun_dir[3];   /* unit, toward the sun */
    double sun_water[3]; /* unit, the way sunlight travels under a flat surface */
    double ior;          /* the water's refractive index */
    double scattering;   /* the water's scattering per metre (water.scattering) */
} tl_caustic_light;

/* The focus at world (x, z), `depth` metres under the mean surface (y = 0),
 * at time t, from the ocean's first `octaves` octaves: the irradiance in
 * units of a flat sea's, in [0, sqrt(1 + PEAK²)]; 1 at depth 0 or with
 * the sun down.
 * `footprint`: the pixel's width there (metres, 0 for none). */
double tl_caustic_focus(const tl_waves *w, const tl_caustic_light *l, double x, double z,
                        double depth, double t, int octaves, double footprint);

/* The angle (radians, a width) the sun's beam spreads over under the
 * ocean's first `octaves` octaves: the waves tilt the refracted rays by
 * (1 - 1/ior) of their whole RMS slope, and the sun's disc adds its width
 * (TL_CAUSTIC_SUN_SPREAD). A floating object's shadow on the sand, or on
 * its own keel, blurs by it per metre down (boat_shadow_below). */
double tl_caustic_beam_spread(const tl_waves *w, double ior, int octaves);

/* The caustics in the light through the giant wave's crest (feature
 * `crest caustics`, caustic_crest in shaders/caustics.glsl): the sunlight
 * that reaches world point (x, z) under the face (where the ocean's waves
 * see it: the giant wave's push taken off, tl_giant_ride_point) crossed
 * `path` metres of
 * water from where it entered the crest's far side, toward the sun, and
 * the ripples there focused it as they focus the sun under a level sea:
 * the focus `path` metres along the refracted beam below that entry
 * point. The view ray gathers the glow over a range of depths, which
 * averages the web: `share` of its contrast is kept (giant.caustics; 0
 * gives 1), less with the path (TL_CAUSTIC_CREST_REACH). */
double tl_caustic_crest(const tl_waves *w, const tl_caustic_light *l, double x, double z,
                        double path, double t, int octaves, double footprint, double share);

#endif
