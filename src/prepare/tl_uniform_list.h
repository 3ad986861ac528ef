/* tl_uniform_list: the frame's uniforms, one table for the three places
 * that must agree on them.
 *
 * Each row is X(kind, field, array, feature, doc):
 *   kind     FLOAT, VEC2, VEC3, VEC4, INT, BOOL, UINT or MAT4 (the GLSL
 *            type; INT and BOOL are C ints, UINT an unsigned)
 *   field    the tl_frame_uniforms field; the GLSL name is u_<field>
 *   array    0 for a single value, else the GLSL array's length, written
 *            so that both C and GLSL read it (the renderer passes the
 *            TL_* constants to the shaders as #defines)
 *   feature  0: uploaded with every frame; a TL_FEATURE_* bit: only when
 *            the frame has that feature (the programs without it never
 *            read it)
 *   doc      what the value is, written after the GLSL declaration
 *
 * tl_renderer_upload_uniforms loops over the table to upload a frame;
 * tl_shader_frame_uniforms writes the GLSL declarations from it, which
 * shaders/uniforms.glsl includes as "frame_uniforms.glsl" (a file no
 * folder holds: the shader library serves it); tl_prepare.c checks that
 * every row's field has the row's size.
 *
 * Not in the table, and declared by the shaders that use them: the
 * texture samplers (each pass binds its own textures, TL_UNIT_* in
 * src/gl/tl_renderer_internal.h), and the uniforms a single pass sets
 * outside the frame's upload (the samples of one draw, the prepass's
 * scale and hint, the probe's mode, the boat's mesh pass: its matrices,
 * eye and clip plane, the sky-view table's air, the display's exposure),
 * and the floating objects' uniform block (tl_object_uniforms, shaders/
 * objects.glsl), which the renderer uploads as a buffer.
 *
 * This header needs nothing included before it: the C expansions name
 * TL_FEATURE_* and the TL_* sizes, which their files include. */
#ifndef TL_UNIFORM_LIST_H
#define TL_UNIFORM_LIST_H

/* clang-format off */
#define TL_FRAME_UNIFORMS(X) \
    X(VEC2, resolution, 0, 0, "pixels of the render target") \
    X(VEC3, cam_right, 0, 0, "the camera's basis") \
    X(VEC3, cam_up, 0, 0, "") \
    X(VEC3, cam_forward, 0, 0, "") \
    X(FLOAT, tan_half_vfov, 0, 0, "") \
    X(FLOAT, cam_height, 0, 0, "absolute world y of the camera (metres)") \
    X(VEC2, radial_dir, 0, 0, "unit xz direction of the camera from the origin") \
    X(FLOAT, radial_len, 0, 0, "its distance from the origin (metres)") \
    X(FLOAT, radial_phase, 0, 0, "phase per metre of distance from the origin") \
    X(VEC4, wave, TL_MAX_OCTAVES, 0, "(dir.x, dir.z, frequency, phase offset)") \
    X(FLOAT, wave_weight, TL_MAX_OCTAVES, 0, "") \
    X(FLOAT, wave_weight_tail, TL_MAX_OCTAVES + 1, 0, "sum of the weights of octaves i..") \
    X(FLOAT, wave_slope_tail, TL_MAX_OCTAVES + 1, 0, "mean squared slope of octaves i.. (raw)") \
    X(FLOAT, lod_angle, 0, 0, "water a pixel covers per metre of distance (0: no LOD)") \
    X(FLOAT, drag, 0, 0, "") \
    X(FLOAT, depth, 0, 0, "") \
    X(INT, march_octaves, 0, 0, "the probe's; ocean programs compile the counts in") \
    X(INT, normal_octaves, 0, 0, "") \
    X(INT, march_steps, 0, 0, "") \
    X(FLOAT, hit_epsilon, 0, 0, "") \
    X(FLOAT, normal_epsilon, 0, 0, "") \
    X(INT, refine_steps, 0, 0, "secant steps after a hit") \
    X(BOOL, miss_at_start, 0, 0, "out of steps: the march's start (seed shader)") \
    X(FLOAT, march_relax, 0, 0, "over-relaxation of the ocean's steps (1: plain)") \
    X(INT, prepass_budget, 0, 0, "march steps before regula falsi where the prepass disagrees") \
    X(BOOL, normalize_smoothed, 0, 0, "renormalise the smoothed normal (not the seed)") \
    X(BOOL, facing_normals, 0, 0, "turn a normal met from behind to face the ray (not the seed)") \
    X(VEC3, sun_dir, 0, 0, "") \
    X(FLOAT, sun_intensity, 0, 0, "") \
    X(FLOAT, sun_sharpness, 0, 0, "") \
    X(FLOAT, sky_brightness, 0, 0, "") \
    X(FLOAT, fresnel_f0, 0, 0, "") \
    X(VEC3, scatter_color, 0, 0, "") \
    X(FLOAT, scatter_strength, 0, 0, "") \
    X(FLOAT, scatter_base, 0, 0, "") \
    X(FLOAT, normal_smooth_max, 0, 0, "") \
    X(FLOAT, normal_smooth_rate, 0, 0, "") \
    X(FLOAT, normal_smooth_gain, 0, 0, "") \
    X(INT, spp, 0, 0, "stratified samples per pixel") \
    X(INT, spp_step, 0, 0, "their y-stratum step, coprime with u_spp") \
    X(UINT, seed, 0, 0, "jitter seed of this pass (sub-frame sample index)") \
    X(FLOAT, water_ior, 0, 0, "the water's refractive index") \
    X(VEC4, giant_frame, 0, TL_FEATURE_GIANT_WAVE, "(dir.x, dir.z, camera s, camera w)") \
    X(VEC4, giant_shape, 0, TL_FEATURE_GIANT_WAVE, "(k, height, steepness, curl), clamped on the CPU") \
    X(VEC4, giant_mask, 0, TL_FEATURE_GIANT_WAVE, "(half length, falloff along, half width, falloff across)") \
    X(VEC4, giant_bounds, 0, TL_FEATURE_GIANT_WAVE, "(reach along, Newton bracket, slope bound, largest lambda)") \
    X(VEC4, giant_crest, 0, TL_FEATURE_GIANT_WAVE, "(peak w, taper, bow, variation)") \
    X(VEC3, giant_vary_k, 0, TL_FEATURE_GIANT_WAVE, "wavenumbers of the variation's sines") \
    X(VEC3, giant_vary_phase, 0, TL_FEATURE_GIANT_WAVE, "their phases (giant.seed)") \
    X(FLOAT, giant_fade, 0, TL_FEATURE_GIANT_WAVE, "giant.fade") \
    X(VEC3, giant_sigma, 0, TL_FEATURE_GIANT_WAVE, "the water's diffuse attenuation per metre (tl_optics_water_fall): light through the crest") \
    X(VEC4, giant_break, 0, TL_FEATURE_GIANT_BREAK, "(age at the peak, peel speed, throw time, drop)") \
    X(FLOAT, giant_speed, 0, TL_FEATURE_GIANT_BREAK, "the crest's speed over the water, m/s") \
    X(VEC4, giant_lip_box, 0, TL_FEATURE_GIANT_LIP, "the lip's box: (s low, s high, y low, y high)") \
    X(VEC2, giant_lip_w, 0, TL_FEATURE_GIANT_LIP, "and its w range") \
    X(VEC4, giant_spray, 0, TL_FEATURE_GIANT_SPRAY, "(amount, reach, drift, bow radius)") \
    X(VEC4, giant_spray_box, 0, TL_FEATURE_GIANT_SPRAY, "the crest's spray box (s low, s high, y low, y high)") \
    X(VEC4, giant_spray_bow, 0, TL_FEATURE_GIANT_SPRAY, "the bow's burst: camera-relative centre, amount") \
    X(VEC4, giant_spray_heading, 0, TL_FEATURE_GIANT_SPRAY, "the boat's heading, unit (x, z); the burst's split, metres; the crossing's shelter") \
    X(FLOAT, spray_step, 0, 0, "quality.spray_step: metres a step of the spray's march") \
    X(VEC4, giant_foam, 0, TL_FEATURE_GIANT_WAVE, "(Jacobian where foam starts, trail metres, amount, breaking)") \
    X(VEC4, giant_scatter, 0, TL_FEATURE_GIANT_WAVE, "(strength, forward g, backward g, giant.caustics)") \
    X(VEC3, giant_scatter_color, 0, TL_FEATURE_GIANT_WAVE, "") \
    X(INT, giant_iterations, 0, TL_FEATURE_GIANT_WAVE, "") \
    X(FLOAT, giant_ride, 0, TL_FEATURE_GIANT_WAVE, "giant.ride: the share of the push the small waves ride") \
    X(FLOAT, giant_compression_foam, 0, TL_FEATURE_GIANT_WAVE, "compression foam where the crest has not broken: 1, or TL_GIANT_UNBROKEN_FOAM with a scripted break") \
    X(FLOAT, giant_slope, TL_GIANT_SLOPE_BINS, TL_FEATURE_GIANT_WAVE, "slope bound per bin of s") \
    X(VEC2, giant_world, 0, TL_FEATURE_GIANT_WAVE, "the crest's world (s, w), wrapped every 65536 m") \
    X(VEC2, giant_rise, 0, TL_FEATURE_GIANT_WAVE, "s where the wave reaches the camera's height (empty: none)") \
    X(VEC3, water_sigma, 0, TL_FEATURE_UNDERWATER | TL_FEATURE_SEA_FLOOR, "extinction per metre, R G B") \
    X(VEC3, water_fall, 0, TL_FEATURE_UNDERWATER | TL_FEATURE_SEA_FLOOR, "the light from above: its fall per metre down, R G B") \
    X(FLOAT, water_scattering, 0, TL_FEATURE_UNDERWATER | TL_FEATURE_SEA_FLOOR | TL_FEATURE_GIANT_CAUSTICS | TL_FEATURE_GIANT_GLOW, "per metre, grey") \
    X(FLOAT, beam_spread, 0, TL_FEATURE_UNDERWATER | TL_FEATURE_SEA_FLOOR, "radians the sun's beam under the water spreads: the waves' tilt and the sun's disc") \
    X(FLOAT, capillary_slope_var, 0, TL_FEATURE_UNDERWATER | TL_FEATURE_SEA_FLOOR, "water.capillaries: the slope variance per axis of the ripples finer than the waves") \
    X(FLOAT, cam_depth, 0, TL_FEATURE_UNDERWATER, "metres below the surface at the camera") \
    X(FLOAT, lens, 0, TL_FEATURE_UNDERWATER, "the lens plane's distance ahead of the camera") \
    X(VEC3, sun_water, 0, TL_FEATURE_UNDERWATER | TL_FEATURE_SEA_FLOOR | TL_FEATURE_GIANT_CAUSTICS, "the direction sunlight travels in the water") \
    X(FLOAT, sun_water_trans, 0, TL_FEATURE_UNDERWATER | TL_FEATURE_SEA_FLOOR, "the share of it that crossed the surface") \
    X(FLOAT, caustics, 0, TL_FEATURE_CAUSTICS, "underwater.caustics: their strength") \
    X(FLOAT, shafts, 0, TL_FEATURE_SHAFTS, "underwater.shafts: their strength") \
    X(INT, shaft_steps, 0, TL_FEATURE_SHAFTS, "quality.shaft_steps: their samples along a ray") \
    X(INT, mesh_scale, 0, TL_FEATURE_BOAT, "quality.mesh_scale: the hulls' target holds n x n samples a pixel") \
    X(FLOAT, particles, 0, TL_FEATURE_PARTICLES, "underwater.particles: motes per cubic metre") \
    X(VEC3, particle_offset, 0, TL_FEATURE_PARTICLES, "camera x y z wrapped every TL_PARTICLE_PERIOD m: the motes' grid") \
    X(FLOAT, floor_depth, 0, TL_FEATURE_SEA_FLOOR, "metres from the mean surface down to the sea floor") \
    X(VEC2, floor_offset, 0, TL_FEATURE_SEA_FLOOR, "camera x z wrapped every TL_FLOOR_PERIOD m: the sand's coordinates") \
    X(FLOAT, sky_scale, 0, TL_FEATURE_SKY_PHYSICAL, "the sun's illuminance above the air") \
    X(VEC3, sun_light, 0, TL_FEATURE_SKY_PHYSICAL, "its light at the camera: illuminance x transmittance") \
    X(FLOAT, sun_cos_radius, 0, TL_FEATURE_SKY_PHYSICAL, "cos of the disc's angular radius") \
    X(VEC3, sky_ambient, 0, TL_FEATURE_SKY_PHYSICAL, "the sky's irradiance on a surface facing up, over pi") \
    X(VEC2, fog, 0, TL_FEATURE_FOG, "density per metre at the water, height over which it thins by e") \
    X(VEC3, fog_color, 0, TL_FEATURE_FOG, "") \
    X(VEC2, world_offset, 0, TL_FEATURE_WAKE, "camera x z wrapped every 65536 m: texture coordinates") \
    X(INT, object_count, 0, 0, "floating objects in view: slots of u_objects (shaders/objects.glsl)")
/* clang-format on */

/* The kinds, for code that switches on them (TL_UNIFORM_##kind). */
typedef enum tl_uniform_kind {
    TL_UNIFORM_FLOAT,
    TL_UNIFORM_VEC2,
    TL_UNIFORM_VEC3,
    TL_UNIFORM_VEC4,
    TL_UNIFORM_INT,
    TL_UNIFORM_BOOL,
    TL_UNIFORM_UINT,
    TL_UNIFORM_MAT4
} tl_uniform_kind;

/* The GLSL type of each kind. */
#define TL_UNIFORM_GLSL_FLOAT "float"
#define TL_UNIFORM_GLSL_VEC2  "vec2"
#define TL_UNIFORM_GLSL_VEC3  "vec3"
#define TL_UNIFORM_GLSL_VEC4  "vec4"
#define TL_UNIFORM_GLSL_INT   "int"
#define TL_UNIFORM_GLSL_BOOL  "bool"
#define TL_UNIFORM_GLSL_UINT  "uint"
#define TL_UNIFORM_GLSL_MAT4  "mat4"

/* Bytes of one value of each kind in tl_frame_uniforms. */
#define TL_UNIFORM_BYTES_FLOAT sizeof(float)
#define TL_UNIFORM_BYTES_VEC2  (2 * sizeof(float))
#define TL_UNIFORM_BYTES_VEC3  (3 * sizeof(float))
#define TL_UNIFORM_BYTES_VEC4  (4 * sizeof(float))
#define TL_UNIFORM_BYTES_INT   sizeof(int)
#define TL_UNIFORM_BYTES_BOOL  sizeof(int)
#define TL_UNIFORM_BYTES_UINT  sizeof(unsigned)
#define TL_UNIFORM_BYTES_MAT4  (16 * sizeof(float))

/* The number of values a row holds: its array's length, 1 for a single
 * value. */
#define TL_UNIFORM_COUNT(array) ((array) > 0 ? (array) : 1)

/* The frame's uniforms in the table, and the GLSL file that declares them. */
#define TL_FRAME_UNIFORM_ROW_COUNT_(kind, field, array, feature, doc) +1
#define TL_FRAME_UNIFORM_ROWS                                         (0 TL_FRAME_UNIFORMS(TL_FRAME_UNIFORM_ROW_COUNT_))
#define TL_FRAME_UNIFORMS_FILE                                        "frame_uniforms.glsl"

#endif
