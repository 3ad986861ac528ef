// Frame uniforms shared by every program (filled by tl_prepare on the CPU).
// Nothing here holds an absolute time or an absolute horizontal position:
// x and z are relative to the camera, and per-octave phases are reduced on
// the CPU in double.

#include "constants.glsl"

uniform vec2 u_resolution;      // pixels
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec3 u_cam_forward;
uniform float u_tan_half_vfov;
uniform float u_cam_height;     // absolute world y of the camera (metres)

uniform vec2 u_radial_dir;      // unit xz direction of the camera from the origin
uniform float u_radial_len;     // its distance from the origin (metres)
uniform float u_radial_phase;   // phase per metre of distance from the origin

uniform vec4 u_wave[TL_MAX_OCTAVES];        // (dir.x, dir.z, frequency, phase offset)
uniform float u_wave_weight[TL_MAX_OCTAVES];
uniform float u_wave_weight_tail[TL_MAX_OCTAVES + 1]; // sum of the weights of octaves i..
uniform float u_wave_slope_tail[TL_MAX_OCTAVES + 1];  // mean squared slope of octaves i.. (raw)
uniform float u_lod_angle;      // water a pixel covers per metre of distance (0: no LOD)
uniform float u_drag;
uniform float u_depth;

uniform int u_march_octaves;
uniform int u_normal_octaves;
// The ocean programs are built with the octave counts as constants: a wave
// loop with a constant bound is unrolled and its per-octave uniforms become
// direct loads. Other programs (the probe) read the uniforms.
#ifndef TL_MARCH_OCTAVES
#define TL_MARCH_OCTAVES u_march_octaves
#endif
#ifndef TL_NORMAL_OCTAVES
#define TL_NORMAL_OCTAVES u_normal_octaves
#endif
uniform int u_march_steps;
uniform float u_hit_epsilon;
uniform float u_normal_epsilon;
uniform int u_refine_steps;       // secant steps after a hit
uniform bool u_miss_at_start;     // out of steps: the march's start (seed shader)
uniform float u_march_relax;      // over-relaxation of the ocean's steps (1: plain)
uniform int u_prepass_budget;     // march steps before regula falsi where the prepass disagrees
uniform bool u_normalize_smoothed; // renormalise the smoothed normal (not the seed)
uniform bool u_facing_normals;     // turn a normal met from behind to face the ray (not the seed)

uniform vec3 u_sun_dir;
uniform float u_sun_intensity;
uniform float u_sun_sharpness;
uniform float u_sky_brightness;

uniform float u_fresnel_f0;
uniform vec3 u_scatter_color;
uniform float u_scatter_strength;
uniform float u_scatter_base;
uniform float u_normal_smooth_max;
uniform float u_normal_smooth_rate;
uniform float u_normal_smooth_gain;
