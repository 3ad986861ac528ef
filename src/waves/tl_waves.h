/* tl_waves: the ocean's height field on the CPU, in double.
 *
 * The model is the reference shader's exp(sin) sum with derivative drag
 * (seed 002). This file is the accuracy reference for the GPU (tests
 * compare shader probes against it), floats the boat and tells whether
 * the camera is under water. It also produces the per-octave phase
 * offsets that keep absolute time and position off the GPU. */
#ifndef TL_WAVES_H
#define TL_WAVES_H

#include "scene/tl_quality.h"
#include "scene/tl_scene.h"
#include "waves/tl_giant.h"

/* The mean over a period of (exp(sin x - 1) · cos x)²: an octave's mean
 * squared slope per unit of weight times frequency, before drag
 * (shaders/waves.glsl has the same; test_giant checks the value). */
#define TL_WAVE_SLOPE_MEAN_SQ 0.1076346

typedef struct tl_wave_octave {
    double dir_x, dir_z; /* unit travel direction in the xz plane */
    double frequency;    /* radians per metre */
    double speed;        /* radians per second */
    double weight;       /* amplitude weight */
} tl_wave_octave;

typedef struct tl_waves {
    int count; /* octaves available (TL_MAX_OCTAVES) */
    tl_wave_octave octave[TL_MAX_OCTAVES];
    double drag, depth, radial_phase;
} tl_waves;

/* Builds the octave table from the ocean parameters. */
void tl_waves_init(tl_waves *w, const tl_ocean *ocean);

/* Normalised wave value in (0,1] at world (x, z) and time t using the
 * first `octaves` octaves: sum(weight * exp(sin(phase) - 1)) / sum(weight). */
double tl_waves_value(const tl_waves *w, double x, double z, double t, int octaves);

/* The mean of one octave, exp(sin x - 1) over a period (I0(1) / e): what
 * an octave too fine for a footprint averages to (shaders/waves.glsl has
 * the same). */
#define TL_WAVE_MEAN 0.4657596

/* How much of an octave of `frequency` (rad/m) a footprint of `footprint`
 * metres resolves: 1 while its wavelength spans four footprints, 0 at two
 * (waves_detail). */
double tl_waves_detail(double frequency, double footprint);

/* tl_waves_value with the shaders' level of detail (waves_value under
 * TL_FEATURE_LOD): octaves finer than `footprint` fade to their mean and
 * their drag to nothing; 0 is tl_waves_value. */
double tl_waves_value_lod(const tl_waves *w, double x, double z, double t, int octaves,
                          double footprint);

/* The slope variance (per axis, as the shaders' filtered shading counts
 * it) of the octaves a footprint of `footprint` metres does not resolve:
 * each of the first `octaves` by the share it fades, and every octave past
 * them whole (waves_unresolved_slope_variance). */
double tl_waves_unresolved_slope_variance(const tl_waves *w, int octaves, double footprint);

/* The slope variance per axis of the capillary ripples finer than the
 * finest of the first `octaves` octaves: `share` (water.capillaries) of
 * the octaves' own. No octave draws them, but they spread the light that
 * crosses the surface: the edge of Snell's window from below, the floor
 * seen through it from above. A calm sea has none. */
double tl_waves_capillary_slope_variance(const tl_waves *w, int octaves, double share);

/* World height of the surface: (value - 1) * depth, in [-depth, 0]. */
double tl_waves_height(const tl_waves *w, double x, double z, double t, int octaves);

/* Height of the whole surface: the ocean plus the giant wave `g` (which
 * adds nothing when inactive), its map inverted with `giant_iterations`;
 * the ocean is taken where its small waves came from (tl_giant_ride_point:
 * they ride the giant wave's water). */
double tl_waves_surface_height(const tl_waves *w, const tl_giant *g, double x, double z, double t,
                               int octaves, int giant_iterations);

/* Every height at which a vertical line at world (x, z) meets the water
 * surface, lowest first, at most `max` of them: the ocean plus the giant
 * wave's height field first, then, where the giant wave's lip overhangs
 * the point, the lip's lower and upper faces above it. Returns the count
 * (at least 1). The boat floats on the highest. */
int tl_waves_surfaces(const tl_waves *w, const tl_giant *g, double x, double z, double t,
                      int octaves, int giant_iterations, double *heights, int max);

/* Per-octave phase offsets for a GPU frame centred on (ref_x, ref_z):
 * fmod(f·dot(d, ref) + speed·t + radial·|ref|, 2π), so the shader adds only
 * terms that are small near the camera. */
void tl_waves_phases(const tl_waves *w, double ref_x, double ref_z, double t, int octaves,
                     double *phase_out);

#endif
