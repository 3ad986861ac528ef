#include "tl_channels.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "core/tl_math.h"

#define BIG 1.0e9 /* positions and sizes: far beyond any scene, still finite */

static const char *const underwater_names[] = {"auto", "on", "off", NULL};
static const char *const sky_model_names[] = {"physical", "seed", NULL};
/* In tl_rotation_mode's order (Blender's names, lower case). */
static const char *const rotation_mode_names[] = {
    "yaw_pitch_roll", "xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "quaternion", "axis_angle", NULL};
static const char *const sensor_fit_names[] = {"auto", "horizontal", "vertical", NULL};

/* Enum channels are read and written as int. */
_Static_assert(sizeof(tl_underwater_mode) == sizeof(int), "enum channels are int-sized");
_Static_assert(sizeof(tl_sky_model) == sizeof(int), "enum channels are int-sized");
_Static_assert(sizeof(tl_rotation_mode) == sizeof(int), "enum channels are int-sized");
_Static_assert(sizeof(tl_sensor_fit) == sizeof(int), "enum channels are int-sized");

#define REAL(n, comps, unit, lo, hi, field, doc)                                                   \
    {                                                                                              \
        n, TL_CH_REAL, comps, unit, lo, hi, true, offsetof(tl_scene, field), NULL, doc             \
    }

static const tl_channel channels[] = {
    REAL("render.exposure", 1, TL_UNIT_NONE, 0.0, 1e6, exposure,
         "linear exposure before tonemapping"),
    REAL("render.ev", 1, TL_UNIT_NONE, -20.0, 20.0, ev,
         "exposure value in stops: +1 halves the light, -3 for dusk"),
    REAL("render.auto_exposure", 1, TL_UNIT_NONE, 0.0, 1.0, auto_exposure,
         "exposure that meters itself: 0 off (render.exposure), 1 the meter's; "
         "`set render.exposure auto` sets 1"),
    REAL("render.adapt_time", 1, TL_UNIT_TIME, 0.0, 60.0, adapt_time,
         "seconds the metered exposure takes to adapt (a time constant; 0 at once)"),
    REAL("render.bloom", 1, TL_UNIT_NONE, 0.0, 1.0, bloom,
         "share of the light spread into glare in the display image (not EXR)"),
    REAL("render.white_point", 3, TL_UNIT_NONE, 1e-6, 1e6, white_point,
         "white balance: the scene's colour (linear R G B) the display shows as neutral, "
         "as a camera balanced on a grey card (not EXR)"),
    REAL("render.white_depth", 1, TL_UNIT_LENGTH, 0.0, TL_WHITE_DEPTH_MAX, white_depth,
         "white balance under water: the daylight at this depth of the scene's water shows as "
         "white (metres; 0 none; not EXR)"),

    REAL("camera.position", 3, TL_UNIT_LENGTH, -BIG, BIG, camera.position,
         "camera position x y z (metres; +Y up, +Z north)"),
    REAL("camera.yaw", 1, TL_UNIT_ANGLE, -BIG, BIG, camera.yaw,
         "heading: 0 looks along +Z, 90 along +X"),
    REAL("camera.pitch", 1, TL_UNIT_ANGLE, -90 * TL_DEG, 90 * TL_DEG, camera.pitch,
         "up/down, positive looks up"),
    REAL("camera.roll", 1, TL_UNIT_ANGLE, -BIG, BIG, camera.roll, "roll about the view direction"),
    REAL("camera.fov", 1, TL_UNIT_ANGLE, 0.1 * TL_DEG, 179 * TL_DEG, camera.vfov,
         "vertical field of view"),
    /* The camera as Blender gives it (docs/blender.md). */
    {"camera.rotation_mode", TL_CH_ENUM, 1, TL_UNIT_NONE, 0, TL_ROTATION_AXIS_ANGLE, true,
     offsetof(tl_scene, rig.rotation_mode), rotation_mode_names,
     "yaw_pitch_roll (camera.yaw, .pitch, .roll), or Blender's: xyz ... zyx (camera.rotation), "
     "quaternion (camera.quaternion_w, camera.quaternion), axis_angle (camera.axis_angle, "
     "camera.axis)"},
    REAL("camera.rotation", 3, TL_UNIT_ANGLE, -BIG, BIG, rig.euler,
         "Blender's Euler angles X Y Z (Blender's axes: Z up, Y north)"),
    REAL("camera.quaternion_w", 1, TL_UNIT_NONE, -BIG, BIG, rig.quat_w,
         "Blender's rotation quaternion's W"),
    REAL("camera.quaternion", 3, TL_UNIT_NONE, -BIG, BIG, rig.quat,
         "Blender's rotation quaternion's X Y Z"),
    REAL("camera.axis_angle", 1, TL_UNIT_ANGLE, -BIG, BIG, rig.axis_angle,
         "Blender's axis-angle rotation's angle"),
    REAL("camera.axis", 3, TL_UNIT_NONE, -BIG, BIG, rig.axis,
         "Blender's axis-angle rotation's axis"),
    REAL("camera.focal_length", 1, TL_UNIT_NONE, 0.0, 1e5, rig.focal_length,
         "lens in mm on camera.sensor (0: camera.fov gives the field of view)"),
    REAL("camera.sensor", 1, TL_UNIT_NONE, 1e-3, 1e4, rig.sensor_width, "sensor width in mm"),
    REAL("camera.sensor_height", 1, TL_UNIT_NONE, 1e-3, 1e4, rig.sensor_height,
         "sensor height in mm (camera.sensor_fit vertical)"),
    {"camera.sensor_fit", TL_CH_ENUM, 1, TL_UNIT_NONE, 0, TL_SENSOR_VERTICAL, true,
     offsetof(tl_scene, rig.sensor_fit), sensor_fit_names,
     "as Blender's: auto (the width across the longer side), horizontal, vertical"},

    REAL("sun.elevation", 1, TL_UNIT_ANGLE, -90 * TL_DEG, 90 * TL_DEG, sun.elevation,
         "sun above the horizon"),
    REAL("sun.azimuth", 1, TL_UNIT_ANGLE, -BIG, BIG, sun.azimuth, "sun compass direction"),
    REAL("sun.intensity", 1, TL_UNIT_NONE, 0.0, 1e6, sun.intensity,
         "peak radiance of the seed sky's sun lobe"),
    REAL("sun.sharpness", 1, TL_UNIT_NONE, 1.0, 1e6, sun.sharpness,
         "exponent of the seed sky's sun lobe (larger = smaller sun)"),
    REAL("sun.angular_diameter", 1, TL_UNIT_ANGLE, 0.01 * TL_DEG, 20 * TL_DEG, sun.angular_diameter,
         "the sun's disc (physical sky)"),
    {"sky.model", TL_CH_ENUM, 1, TL_UNIT_NONE, 0, 1, true, offsetof(tl_scene, sky.model),
     sky_model_names, "physical: Rayleigh, Mie, ozone, multiple scattering; seed: the cheap one"},
    REAL("sky.brightness", 1, TL_UNIT_NONE, 0.0, 1e3, sky.brightness,
         "scale of the seed atmosphere"),
    REAL("sky.sun_illuminance", 1, TL_UNIT_NONE, 0.0, 1e6, sky.sun_illuminance,
         "the sun's illuminance above the air (physical sky)"),
    REAL("sky.turbidity", 1, TL_UNIT_NONE, 0.0, 50.0, sky.turbidity,
         "aerosols (Mie scattering) relative to a clear day"),
    REAL("sky.ozone", 1, TL_UNIT_NONE, 0.0, 10.0, sky.ozone,
         "ozone relative to the standard layer (the blue hour's blue)"),
    REAL("sky.ground_albedo", 1, TL_UNIT_NONE, 0.0, 1.0, sky.ground_albedo,
         "the planet's surface below, lighting the air from below"),
    REAL("sky.planet_radius", 1, TL_UNIT_NONE, 100.0, 1e5, sky.planet_radius, "kilometres"),
    REAL("sky.atmosphere_height", 1, TL_UNIT_NONE, 1.0, 1000.0, sky.atmosphere_height,
         "kilometres of air above the ground"),

    REAL("ocean.depth", 1, TL_UNIT_LENGTH, 0.001, 1e3, ocean.depth,
         "crest-to-trough height band of the waves"),
    REAL("ocean.drag", 1, TL_UNIT_NONE, 0.0, 1.0, ocean.drag,
         "derivative drag: ripples gather on crests"),
    REAL("ocean.frequency", 1, TL_UNIT_NONE, 1e-4, 1e3, ocean.frequency,
         "first octave frequency, radians per metre"),
    REAL("ocean.frequency_growth", 1, TL_UNIT_NONE, 1.0, 4.0, ocean.frequency_growth,
         "frequency ratio between octaves"),
    REAL("ocean.speed", 1, TL_UNIT_NONE, -1e3, 1e3, ocean.speed,
         "first octave speed, radians per second"),
    REAL("ocean.speed_growth", 1, TL_UNIT_NONE, 0.0, 4.0, ocean.speed_growth,
         "speed ratio between octaves (dispersion)"),
    REAL("ocean.weight_ratio", 1, TL_UNIT_NONE, 0.0, 1.0, ocean.weight_ratio,
         "amplitude ratio between octaves"),
    REAL("ocean.direction_step", 1, TL_UNIT_NONE, -1e6, 1e6, ocean.direction_step,
         "radians between octave directions"),
    REAL("ocean.radial_phase", 1, TL_UNIT_NONE, -1e3, 1e3, ocean.radial_phase,
         "phase per metre of distance from the origin"),
    REAL("ocean.floor_depth", 1, TL_UNIT_LENGTH, 0.0, 1e4, ocean.floor_depth,
         "depth of a sandy sea floor under the mean surface; 0 = none (deep sea)"),

    REAL("water.scatter_color", 3, TL_UNIT_NONE, 0.0, 1e3, water.scatter_color,
         "linear RGB of light scattered in the water"),
    REAL("water.scatter_strength", 1, TL_UNIT_NONE, 0.0, 1e3, water.scatter_strength,
         "scale of the scattering"),
    REAL("water.scatter_base", 1, TL_UNIT_NONE, 0.0, 1e3, water.scatter_base,
         "scattering at the crests"),
    REAL("water.absorption", 3, TL_UNIT_NONE, 0.0, 1e3, water.absorption,
         "absorption per metre, R G B (pure water by default)"),
    REAL("water.scattering", 1, TL_UNIT_NONE, 0.0, 10.0, water.scattering,
         "scattering per metre (grey): lights the water body under water"),
    REAL("water.color_at_distance", 3, TL_UNIT_NONE, 0.0, 1.0, water.color_at_distance,
         "the colour white light takes after water.color_distance"),
    REAL("water.color_distance", 1, TL_UNIT_LENGTH, 0.0, 1e4, water.color_distance,
         "> 0: extinction from water.color_at_distance instead of absorption"),
    REAL("water.ior", 1, TL_UNIT_NONE, 1.0, 3.0, water.ior, "refractive index of the water"),
    REAL("water.capillaries", 1, TL_UNIT_NONE, 0.0, 10.0, water.capillaries,
         "slope variance of the ripples finer than the waves, over the waves' own: they soften "
         "Snell's window's edge and blur the floor seen through the surface"),
    REAL("water.foam", 1, TL_UNIT_NONE, 0.0, 1.0, water.foam,
         "scale of all foam (today the giant wave's)"),
    REAL("water.fresnel_f0", 1, TL_UNIT_NONE, 0.0, 1.0, water.fresnel_f0,
         "reflectance at normal incidence"),
    REAL("water.normal_smooth_max", 1, TL_UNIT_NONE, 0.0, 1.0, water.normal_smooth_max,
         "max blend of far normals toward up"),
    REAL("water.normal_smooth_rate", 1, TL_UNIT_NONE, 0.0, 1e3, water.normal_smooth_rate,
         "normal smoothing per metre of distance"),
    REAL("water.normal_smooth_gain", 1, TL_UNIT_NONE, 0.0, 1e3, water.normal_smooth_gain,
         "normal smoothing gain"),

    REAL("fog.density", 1, TL_UNIT_NONE, 0.0, 10.0, fog.density, "extinction per metre; 0 = off"),
    REAL("fog.color", 3, TL_UNIT_NONE, 0.0, 1e3, fog.color,
         "the fog's tint of the sky's light (physical sky), its radiance (seed)"),
    REAL("fog.height", 1, TL_UNIT_LENGTH, 0.1, 1e5, fog.height,
         "height over which the fog thins by e (denser near the water)"),
    {"underwater.mode", TL_CH_ENUM, 1, TL_UNIT_NONE, 0, 2, true,
     offsetof(tl_scene, underwater.mode), underwater_names,
     "auto: under water when the camera is below the surface; on; off"},
    REAL("underwater.caustics", 1, TL_UNIT_NONE, 0.0, 10.0, underwater.caustics,
         "strength of the light the waves focus under water; 0 = off"),
    REAL("underwater.shafts", 1, TL_UNIT_NONE, 0.0, 10.0, underwater.shafts,
         "strength of the light shafts the waves cast in the water; 0 = off"),
    REAL("underwater.particles", 1, TL_UNIT_NONE, 0.0, TL_PARTICLE_MAX_DENSITY,
         underwater.particles,
         "motes per cubic metre that catch the light near the camera; 0 = none"),

    {"giant.enabled", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, true, offsetof(tl_scene, giant.enabled),
     NULL, "the giant wave exists"},
    REAL("giant.height", 1, TL_UNIT_LENGTH, 0.0, 1e3, giant.height, "crest height"),
    REAL("giant.width", 1, TL_UNIT_LENGTH, 0.01, 1e5, giant.width,
         "extent across the travel direction"),
    REAL("giant.wavelength", 1, TL_UNIT_LENGTH, 0.01, 1e5, giant.wavelength,
         "wavelength: sets the crest's length and deep-water speed"),
    REAL("giant.angle", 1, TL_UNIT_ANGLE, -BIG, BIG, giant.angle, "travel direction (compass)"),
    REAL("giant.center", 2, TL_UNIT_LENGTH, -BIG, BIG, giant.center, "x z the wave travels toward"),
    REAL("giant.falloff", 1, TL_UNIT_LENGTH, 0.0, 1e5, giant.falloff,
         "softness of the side and crest masks (at least wavelength/4)"),
    REAL("giant.phase", 1, TL_UNIT_ANGLE, -BIG, BIG, giant.phase,
         "extra progress along the travel direction (360deg = one wavelength)"),
    REAL("giant.arrival", 1, TL_UNIT_TIME, -BIG, BIG, giant.arrival,
         "when the crest reaches the centre"),
    REAL("giant.speed", 1, TL_UNIT_NONE, 0.0, 10.0, giant.speed,
         "crest speed as a multiple of the deep-water speed (0 = only phase moves it)"),
    REAL("giant.steepness", 1, TL_UNIT_NONE, 0.0, 1.0, giant.steepness,
         "Gerstner steepness q·k·A (sharper crest)"),
    REAL("giant.curve_strength", 1, TL_UNIT_NONE, 0.0, 1.0, giant.curve_strength,
         "crest curl toward the travel direction"),
    REAL("giant.fade", 1, TL_UNIT_NONE, 0.0, 1.0, giant.fade, "0 invisible .. 1 full strength"),
    REAL("giant.peak", 1, TL_UNIT_LENGTH, -BIG, BIG, giant.peak,
         "across from the centre line to the crest's peak (held within 90% of half the width)"),
    REAL("giant.taper", 1, TL_UNIT_NONE, 0.0, 1.0, giant.taper,
         "how much lower the crest stands at its ends than at its peak"),
    REAL("giant.bow", 1, TL_UNIT_LENGTH, 0.0, 1e5, giant.bow,
         "how far the crest's ends lag behind its peak"),
    REAL("giant.variation", 1, TL_UNIT_NONE, 0.0, 1.0, giant.variation,
         "seeded height variation along the crest, a fraction of its height"),
    {"giant.seed", TL_CH_INT, 1, TL_UNIT_NONE, 0, 1e6, false, offsetof(tl_scene, giant.seed), NULL,
     "seed of the variation along the crest"},
    {"giant.breaking", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, true, offsetof(tl_scene, giant.breaking),
     NULL, "the crest breaks: at its peak from giant.break_time, then outward"},
    REAL("giant.break_time", 1, TL_UNIT_TIME, -BIG, BIG, giant.break_time,
         "when the lip begins to throw at the peak"),
    REAL("giant.peel_speed", 1, TL_UNIT_NONE, 0.1, 1e3, giant.peel_speed,
         "m/s the break runs along the crest from the peak"),
    REAL("giant.break_drop", 1, TL_UNIT_NONE, 0.0, 1.0, giant.break_drop,
         "fraction of its height a broken crest loses as it settles"),
    REAL("giant.spray", 1, TL_UNIT_NONE, 0.0, 10.0, giant.spray,
         "spray blown off a tall crest and thrown up at the bow; 0 = none"),
    REAL("giant.spray_wind", 1, TL_UNIT_NONE, 0.0, 100.0, giant.spray_wind,
         "m/s of wind blowing the spindrift back off the crest"),
    REAL("giant.ride", 1, TL_UNIT_NONE, 0.0, 1.0, giant.ride,
         "share of the wave's push the small waves ride: 1 compressed up the face, 0 still"),
    REAL("giant.foam_compression", 1, TL_UNIT_NONE, 0.1, 1.0, giant.foam_compression,
         "surface compression (Jacobian) below which foam appears"),
    REAL("giant.foam_trail", 1, TL_UNIT_LENGTH, 0.0, 1e5, giant.foam_trail,
         "distance over which foam fades behind a breaking crest"),
    REAL("giant.scatter", 1, TL_UNIT_NONE, 0.0, 1e3, giant.scatter,
         "strength of sunlight through the crest"),
    REAL("giant.scatter_forward", 1, TL_UNIT_NONE, 0.0, 0.99, giant.scatter_forward,
         "forward lobe (Henyey-Greenstein g) of that light"),
    REAL("giant.scatter_back", 1, TL_UNIT_NONE, 0.0, 0.99, giant.scatter_back,
         "backward lobe (Henyey-Greenstein g, mirrored)"),
    REAL("giant.caustics", 1, TL_UNIT_NONE, 0.0, 1.0, giant.caustics,
         "share of the caustic web the far side's ripples cast in that light; 0 = none"),
    REAL("giant.scatter_color", 3, TL_UNIT_NONE, 0.0, 1e3, giant.scatter_color,
         "colour of what the water scatters in the crest (its suspended matter), over the water's "
         "own extinction"),

    {"boat.visible", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, true, offsetof(tl_scene, boat.visible),
     NULL, "the boat is drawn (off: the water plate, for compositing; it still floats)"},
    REAL("boat.heading", 1, TL_UNIT_ANGLE, -BIG, BIG, boat.heading,
         "compass heading (from the path tangent unless set or keyed)"),
    REAL("boat.size", 1, TL_UNIT_LENGTH, 0.1, 1e3, boat.size, "hull length of the built-in boat"),
    REAL("boat.model_yaw", 1, TL_UNIT_ANGLE, -BIG, BIG, boat.model_yaw,
         "turns a model whose bow does not point along +Z"),
    REAL("boat.model_scale", 1, TL_UNIT_NONE, 1e-6, 1e6, boat.model_scale,
         "metres per unit of a loaded model"),
    REAL("boat.wake", 1, TL_UNIT_NONE, 0.0, 1.0, boat.wake, "strength of the wake's foam"),
    REAL("boat.wake_time", 1, TL_UNIT_TIME, 0.1, 600.0, boat.wake_time,
         "time over which the wake's foam fades"),
    REAL("boat.float_time", 1, TL_UNIT_TIME, 0.01, 10.0, boat.float_time,
         "response time of the floating spring (smaller follows the waves closer)"),
    REAL("boat.lights", 1, TL_UNIT_NONE, 0.0, 1.0, boat.lights,
         "its navigation lights' brightness (for dusk and night), 0 off"),
    REAL("boat.spray", 1, TL_UNIT_NONE, 0.0, 10.0, boat.spray,
         "strength of the spray the bow throws where it meets rising water"),
    {"boat.shadows", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, true, offsetof(tl_scene, boat.shadows),
     NULL, "the sun casts the boat's shadows, on itself, the water and the sea floor"},
    {"boat.paint", TL_CH_REAL, 3, TL_UNIT_NONE, 0.0, 1.0, false, offsetof(tl_scene, boat.paint),
     NULL,
     "the built-in boat's topsides colour, linear RGB (a rescue boat's orange: 0.8 0.15 0.02)"},
    {"boat.cabin_paint", TL_CH_REAL, 3, TL_UNIT_NONE, 0.0, 1.0, false,
     offsetof(tl_scene, boat.cabin_paint), NULL,
     "the built-in boat's wheelhouse colour, linear RGB"},

    {"quality.march_octaves", TL_CH_INT, 1, TL_UNIT_NONE, 1, TL_MAX_OCTAVES, false,
     offsetof(tl_scene, quality.march_octaves), NULL, "wave octaves while marching"},
    {"quality.normal_octaves", TL_CH_INT, 1, TL_UNIT_NONE, 1, TL_MAX_OCTAVES, false,
     offsetof(tl_scene, quality.normal_octaves), NULL, "wave octaves for normals"},
    {"quality.march_steps", TL_CH_INT, 1, TL_UNIT_NONE, 1, 10000, false,
     offsetof(tl_scene, quality.march_steps), NULL, "max march steps"},
    {"quality.spp", TL_CH_INT, 1, TL_UNIT_NONE, 1, TL_MAX_SPP, false,
     offsetof(tl_scene, quality.spp), NULL, "stratified samples per pixel"},
    {"quality.giant_iterations", TL_CH_INT, 1, TL_UNIT_NONE, 0, 64, false,
     offsetof(tl_scene, quality.giant_iterations), NULL,
     "Newton steps inverting the giant wave's horizontal displacement"},
    {"quality.spray_step", TL_CH_REAL, 1, TL_UNIT_LENGTH, 0.1, 10.0, false,
     offsetof(tl_scene, quality.spray_step), NULL,
     "metres of a ray in the giant wave's spray per step of its march (16 to 64 steps)"},
    {"quality.shaft_steps", TL_CH_INT, 1, TL_UNIT_NONE, 0, 256, false,
     offsetof(tl_scene, quality.shaft_steps), NULL,
     "samples of the light shafts along a ray under water (0: none)"},
    {"quality.mesh_scale", TL_CH_INT, 1, TL_UNIT_NONE, 1, 4, false,
     offsetof(tl_scene, quality.mesh_scale), NULL,
     "the hulls' pass draws n x n samples a pixel (1: one, edges aliased)"},
    {"quality.hit_epsilon", TL_CH_REAL, 1, TL_UNIT_LENGTH, 1e-6, 1.0, false,
     offsetof(tl_scene, quality.hit_epsilon), NULL, "distance that counts as a hit"},
    {"quality.normal_epsilon", TL_CH_REAL, 1, TL_UNIT_LENGTH, 1e-6, 1.0, false,
     offsetof(tl_scene, quality.normal_epsilon), NULL, "normal finite-difference step"},
    {"quality.refine_steps", TL_CH_INT, 1, TL_UNIT_NONE, 0, 16, false,
     offsetof(tl_scene, quality.refine_steps), NULL,
     "secant steps toward the surface after a hit (0: none)"},
    {"quality.polish", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false, offsetof(tl_scene, quality.polish),
     NULL, "one Newton step moves each hit onto the normals' finer surface before shading"},
    {"quality.lod", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false, offsetof(tl_scene, quality.lod), NULL,
     "fade wave octaves finer than a pixel to their mean (no aliasing, less work far out)"},
    {"quality.render_scale", TL_CH_REAL, 1, TL_UNIT_NONE, 0.25, 1.0, false,
     offsetof(tl_scene, quality.render_scale), NULL,
     "share of the output's width and height the ocean renders at, upscaled bicubically"},
    {"quality.analytic_normals", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false,
     offsetof(tl_scene, quality.analytic_normals), NULL,
     "normals from the wave sum's exact gradient (off: finite differences)"},
    {"quality.filtered_shading", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false,
     offsetof(tl_scene, quality.filtered_shading), NULL,
     "with quality.lod: the slopes of the faded octaves widen the water's reflection"},
    {"quality.pixel_filter", TL_CH_REAL, 1, TL_UNIT_NONE, 0.0, 1.0, false,
     offsetof(tl_scene, quality.pixel_filter), NULL,
     "sigma in pixels of a 3x3 Gaussian over the display image (0: none)"},
    {"quality.march_relax", TL_CH_REAL, 1, TL_UNIT_NONE, 1.0, 2.0, false,
     offsetof(tl_scene, quality.march_relax), NULL,
     "over-relaxation of the ocean's march steps (1: plain steps)"},
    {"quality.march_prepass", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false,
     offsetof(tl_scene, quality.march_prepass), NULL,
     "march one ray per 2x2 pixels first, then solve each pixel's hit between its neighbours'"},
    {"quality.prepass_budget", TL_CH_INT, 1, TL_UNIT_NONE, 0, 1000, false,
     offsetof(tl_scene, quality.prepass_budget), NULL,
     "with the prepass: march steps before regula falsi where the neighbours disagree (0: "
     "march to the end)"},
    {"quality.giant_prepass", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false,
     offsetof(tl_scene, quality.giant_prepass), NULL,
     "with quality.march_prepass off: the giant wave's pixels still start from a prepass over its "
     "rectangle"},
    {"quality.miss_at_start", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false,
     offsetof(tl_scene, quality.miss_at_start), NULL,
     "a ray out of march steps ends where its march began (the seed shader's way)"},
    {"quality.normalize_smoothed", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false,
     offsetof(tl_scene, quality.normalize_smoothed), NULL,
     "renormalise the distance-smoothed normal (off: the seed shader's way)"},
    {"quality.facing_normals", TL_CH_BOOL, 1, TL_UNIT_NONE, 0, 1, false,
     offsetof(tl_scene, quality.facing_normals), NULL,
     "turn a shading normal the ray meets from behind to face it (off: the seed shader's way)"},
};

#define CHANNEL_COUNT ((int)(sizeof channels / sizeof channels[0]))

int tl_channel_count(void)
{
    return CHANNEL_COUNT;
}

const tl_channel *tl_channel_at(int index)
{
    return index >= 0 && index < CHANNEL_COUNT ? &channels[index] : NULL;
}

const tl_channel *tl_channel_find(const char *name)
{
    for (int i = 0; i < CHANNEL_COUNT; i++)
        if (strcmp(channels[i].name, name) == 0)
            return &channels[i];
    return NULL;
}

int tl_channel_index(const tl_channel *ch)
{
    return (int)(ch - channels);
}

/* Where a channel's value lives in the scene: floating object k's copy of
 * a `boat.*` channel lies in its slot (tl_scene_object), at the same place
 * in its tl_boat as the boat's. */
static size_t channel_offset(const tl_channel *ch, int object)
{
    if (object <= 0 || !tl_channel_is_object(ch))
        return ch->offset;
    return ch->offset - offsetof(tl_scene, boat) + offsetof(tl_scene, fleet) +
           (size_t)(object - 1) * sizeof(tl_boat);
}

bool tl_channel_is_object(const tl_channel *ch)
{
    return strncmp(ch->name, "boat.", 5) == 0;
}

void tl_channel_get_object(const tl_channel *ch, const tl_scene *scene, int object, double out[3])
{
    const char *base = (const char *)scene + channel_offset(ch, object);
    for (int i = 0; i < 3; i++)
        out[i] = 0.0;
    switch (ch->kind) {
    case TL_CH_REAL: memcpy(out, base, sizeof(double) * (size_t)ch->components); break;
    case TL_CH_BOOL: out[0] = *(const bool *)base ? 1.0 : 0.0; break;
    case TL_CH_ENUM: out[0] = (double)*(const int *)base; break; /* enums are int-sized */
    case TL_CH_INT: out[0] = (double)*(const int *)base; break;
    }
}

void tl_channel_set_object(const tl_channel *ch, tl_scene *scene, int object, const double in[3])
{
    char *base = (char *)scene + channel_offset(ch, object);
    switch (ch->kind) {
    case TL_CH_REAL: memcpy(base, in, sizeof(double) * (size_t)ch->components); break;
    case TL_CH_BOOL: *(bool *)base = in[0] >= 0.5; break;
    case TL_CH_ENUM: *(int *)base = (int)lround(in[0]); break;
    case TL_CH_INT: *(int *)base = (int)lround(in[0]); break;
    }
}

void tl_channel_get(const tl_channel *ch, const tl_scene *scene, double out[3])
{
    tl_channel_get_object(ch, scene, 0, out);
}

void tl_channel_set(const tl_channel *ch, tl_scene *scene, const double in[3])
{
    tl_channel_set_object(ch, scene, 0, in);
}

/* Optimal string alignment distance (edits incl. transposition), capped
 * at 64 characters so the cost stays bounded whatever the input. */
static int edit_distance(const char *a, const char *b)
{
    enum { MAXLEN = 64 };
    size_t n = strlen(a), m = strlen(b);
    if (n > MAXLEN || m > MAXLEN)
        return MAXLEN;
    int d[MAXLEN + 1][MAXLEN + 1];
    for (size_t i = 0; i <= n; i++)
        d[i][0] = (int)i;
    for (size_t j = 0; j <= m; j++)
        d[0][j] = (int)j;
    for (size_t i = 1; i <= n; i++)
        for (size_t j = 1; j <= m; j++) {
            int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            int best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (d[i - 1][j - 1] + cost < best)
                best = d[i - 1][j - 1] + cost;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[n][m];
}

const char *tl_suggest(const char *word, const char *const *candidates)
{
    const char *best = NULL;
    int best_d = 1 << 30;
    for (int i = 0; candidates[i]; i++) {
        int d = edit_distance(word, candidates[i]);
        if (d < best_d) {
            best_d = d;
            best = candidates[i];
        }
    }
    /* A likely typo: at most a third of the word wrong (and at least one). */
    int allowed = (int)strlen(word) / 3;
    if (allowed < 1)
        allowed = 1;
    return best_d <= allowed ? best : NULL;
}

const char *tl_channel_suggest(const char *word)
{
    const char *names[CHANNEL_COUNT + 1];
    for (int i = 0; i < CHANNEL_COUNT; i++)
        names[i] = channels[i].name;
    names[CHANNEL_COUNT] = NULL;
    return tl_suggest(word, names);
}
