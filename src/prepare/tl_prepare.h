/* tl_prepare: turns a double-precision scene into what the GPU needs.
 *
 * This is where precision is won: the GPU works in camera-relative
 * coordinates (x and z relative to the camera; y stays absolute because
 * heights are small), and every term that would need an absolute time or
 * position (wave phases, the radial phase) is reduced here in double.
 * It also decides the feature set a frame needs, which selects the shader
 * program (see tl_renderer). */
#ifndef TL_PREPARE_H
#define TL_PREPARE_H

#include <stddef.h>

#include "mesh/tl_mesh.h"
#include "scene/tl_scene.h"
#include "waves/tl_waves.h"

/* The size the ocean renders at for `s`: its size scaled by
 * quality.render_scale (at least 1 pixel each way). */
void tl_prepare_render_size(const tl_scene *s, int *width, int *height);

/* Shader features a frame may need; each is a #define in the program.
 * A frame compiles only the code its scene uses. */
typedef enum tl_feature {
    TL_FEATURE_SUN_DISC = 1u << 0,     /* the sun is above the horizon */
    TL_FEATURE_GIANT_WAVE = 1u << 1,   /* the giant wave is enabled and not faded out */
    TL_FEATURE_BOAT = 1u << 2,         /* the boat is in view */
    TL_FEATURE_WAKE = 1u << 3,         /* the moving boat's wake is in view */
    TL_FEATURE_UNDERWATER = 1u << 4,   /* some pixels see from under the water */
    TL_FEATURE_WATERLINE = 1u << 5,    /* the lens crosses the surface: decide per pixel */
    TL_FEATURE_FOG = 1u << 6,          /* fog above the water */
    TL_FEATURE_SKY_PHYSICAL = 1u << 7, /* sky.model physical (else the seed's sky) */
    /* Quality knobs whose code is compiled only when on, so that turning
     * one off (as `seed` does) costs nothing per octave: */
    TL_FEATURE_LOD = 1u << 8,               /* quality.lod */
    TL_FEATURE_ANALYTIC_NORMALS = 1u << 9,  /* quality.analytic_normals */
    TL_FEATURE_SUPERSAMPLE = 1u << 10,      /* quality.spp > 1 */
    TL_FEATURE_FILTERED_SHADING = 1u << 11, /* quality.filtered_shading with quality.lod */
    TL_FEATURE_REFINE = 1u << 12,           /* quality.refine_steps > 0 */
    TL_FEATURE_POLISH = 1u << 13,           /* quality.polish */
    /* Parts of a feature */
    TL_FEATURE_GIANT_BREAK = 1u << 14, /* the giant wave's crest has begun to break */
    TL_FEATURE_GIANT_LIP = 1u << 15,   /* and its lip is thrown somewhere along it */
    TL_FEATURE_GIANT_SPRAY = 1u << 16, /* giant.spray, where a crest is tall or a bow meets it */
    TL_FEATURE_GIANT_GLOW =
        1u << 17, /* giant.scatter > 0 with the sun up: light through the crest */
    TL_FEATURE_BOAT_SHADOW = 1u << 18, /* boat.shadows with the sun up: its shadow map */
    TL_FEATURE_BOW_SPRAY = 1u << 19,   /* the bow meets rising water: its spray (not the giant's) */
    TL_FEATURE_CAUSTICS = 1u << 20,    /* under water or a floor, the sun up, underwater.caustics */
    TL_FEATURE_SEA_FLOOR =
        1u << 21, /* ocean.floor_depth > 0: seen from below or through the surface */
    TL_FEATURE_SHAFTS = 1u << 22, /* under water, the sun up, underwater.shafts, shaft steps > 0 */
    TL_FEATURE_PARTICLES = 1u << 23,      /* under water, underwater.particles > 0 */
    TL_FEATURE_GIANT_CAUSTICS = 1u << 24, /* crest glow, the sun up, giant.caustics > 0 */
} tl_feature;

#define TL_FEATURE_COUNT 25

/* Stations a side where the CPU takes the water's height along a hull (a
 * multiple of 4: the uniform block packs them four to a vec4). */
#define TL_WASH_STATIONS 16

/* The lens: each pixel's point on an image plane this far ahead of the
 * camera decides whether it sees from above or below the water when the
 * camera is at the surface (TL_FEATURE_WATERLINE), metres. */
#define TL_LENS_DISTANCE 0.25

/* The sea floor's sand repeats every this many metres (a power of two:
 * each of its noises' cells divides it), so that its coordinates, the
 * camera's position wrapped by it, keep float's precision far out. */
#define TL_FLOOR_PERIOD 1024

/* The #define name of feature bit `index` ("TL_FEATURE_SUN_DISC"), and the
 * words `still -v` and `render -v` print for it ("sun disc"). */
const char *tl_feature_define(int index);
const char *tl_feature_label(int index);
/* "ocean, sun disc, giant wave": every feature of `features`, for logs. */
void tl_feature_describe(unsigned features, char *out, size_t size);

/* How the renderer draws a frame, beside what it uploads: the screen
 * rectangles each program variant covers and the prepass the frame's
 * rays start from. tl_prepare_frame fills it (tl_frame_uniforms.plan);
 * the renderer's draw code reads it, and none of it reaches a shader. */
typedef struct tl_draw_plan {
    /* The render target's pixels whose rays can meet the giant wave's box,
     * as x0, y0, x1, y1 (x1 and y1 one past the last; GL's lower-left
     * origin); empty (all 0) when none can. The renderer runs the giant
     * wave's program only there (tl_prepare_giant_rect). */
    int giant_rect[4];
    /* Rows at the top of the render target (GL's y from height - sky_rows
     * up) where every ray rises from a camera above the water: outside
     * giant_rect they meet nothing, and the renderer shades them with the
     * sky alone (sky_rows in tl_prepare.c). 0: none. */
    int sky_rows;
    /* The pixels that can show the hull's mirror image, as giant_rect
     * (tl_prepare_mirror_rect): the ocean programs look its texture up
     * only there. */
    int boat_mirror_rect[4];
    /* The pixels whose rays can meet water the wake's foam
     * reaches, as giant_rect's; the renderer leaves the foam out of the
     * programs it draws elsewhere (tl_prepare_wake_rect). Empty without
     * the wake. */
    int wake_rect[4];
    int march_prepass; /* quality.march_prepass: the prepass before every pass */
    int giant_prepass; /* quality.giant_prepass: the prepass over giant_rect alone */
} tl_draw_plan;

/* One floating object in the ocean pass's uniform block (shaders/
 * objects.glsl declares the same in GLSL, std140: every member a vec4 or a
 * mat4, or an array of vec4, so C's layout is the block's; the renderer
 * checks the block's size against this struct's). Camera-relative,
 * column-major. The outline's tables are the object's mesh's
 * (tl_mesh_outline, model units): the renderer fills them. */
typedef struct tl_object_uniforms {
    float to_model[16]; /* camera-relative world -> model */
    float shadow[16];   /* -> its shadow map's s, t and depth in [0, 1], depth away from the sun */
    /* Model y of the hull's top, camera-relative y of the water plane its
     * mirror image is taken in, speed over the ground (m/s, the bow
     * wave's), its shadow map's layer (-1: it casts none). */
    float hull[4];
    float outline_z[4]; /* the waterline's model z from x to y, the widest plan's from z to w */
    /* A texel of its shadow map's width (m), the share of the layer in
     * use; the model y of the hull's lowest point (the keel); unused. */
    float shadow_map[4];
    float waterline[TL_MESH_WATERLINE_STATIONS];
    float plan[TL_MESH_WATERLINE_STATIONS];
    float plan_y[TL_MESH_WATERLINE_STATIONS];
    /* Its wake: per past position, camera-relative x z, age in seconds and
     * distance behind the object along its path; the distance along the
     * path (tl_boat.wake_along, wrapped every 65536 m); per group of
     * TL_WAKE_GROUP segments a circle (x z, radius, unused) holding every
     * point the group's foam can reach (radius 0: none in view); half
     * beam, fade time, strength (0: no wake), hull length. */
    float wake[TL_WAKE_POINTS][4];
    float wake_along[TL_WAKE_POINTS];
    float wake_groups[TL_WAKE_GROUPS][4];
    float wake_params[4];
    /* The bow's spray (TL_FEATURE_BOW_SPRAY): camera-relative centre (y
     * absolute) and amount (0: none); heading, unit (x, z), and radius. */
    float bow_spray[4];
    float bow_spray_shape[4];
    /* Its lamps (tl_mesh_lamps, filled by the renderer, which has the
     * mesh): camera-relative centre and radius (m); radiance r g b times
     * boat.lights (0: dark) and a side light's side (model x: -1, 1; 0 all
     * round). The water mirrors them. */
    float lamp[TL_MESH_LAMPS][4];
    float lamp_light[TL_MESH_LAMPS][4];
    /* The water's height (camera-relative y) along its sides: port (-x)
     * then starboard, TL_WASH_STATIONS each from its model's least z to
     * its most (tl_prepare_wash_water). */
    float wash_water[2 * TL_WASH_STATIONS];
    float wash_z[4]; /* the stations' model z from x to y; unused x 2 */
} tl_object_uniforms;

/* A floating object's mesh pass, beside its uniforms. */
typedef struct tl_object_pass {
    int object;      /* its index in the scene (tl_scene_object) */
    int mesh;        /* tl_boat.model: the mesh it is drawn with */
    int drawn;       /* its hull or mirror image is in view: the mesh pass draws it */
    float model[16]; /* model -> camera-relative world */
    float sunlit;    /* the share of the sun its hull sees past the giant wave's crest */
    float lights;    /* boat.lights: the lamps' share of their emission */
    int shadow_size; /* texels of its shadow map's layer in use a side (0: none) */
} tl_object_pass;

/* What the GPU needs for one frame. The fields the shaders read are the
 * rows of tl_uniform_list.h, which declares them to GLSL and uploads them;
 * the rest drive the renderer (sizes, the screen rectangles, the boat's
 * mesh pass, the display). */
typedef struct tl_frame_uniforms {
    unsigned features;
    tl_draw_plan plan;         /* how it is drawn; the rest is what the shaders read */
    int width, height;         /* the ocean's render size (quality.render_scale) */
    float resolution[2];       /* the same, for the shaders */
    int out_width, out_height; /* the frame's */

    /* Camera: basis vectors and lens; the camera sits at the xz origin. */
    float cam_right[3], cam_up[3], cam_forward[3];
    float tan_half_vfov;
    float cam_height; /* absolute world y of the camera */

    /* Radial phase: |ref + p| - |ref| is evaluated in a cancellation-free
     * form on the GPU from the unit direction and length of ref. */
    float radial_dir[2];
    float radial_len;
    float radial_phase;

    /* Waves, per octave: (dir_x, dir_z, frequency, phase offset), weight. */
    int octaves; /* entries filled: max(march, normal) octaves */
    float wave[TL_MAX_OCTAVES][4];
    float wave_weight[TL_MAX_OCTAVES];
    /* wave_weight_tail[i]: the sum of the weights of octaves i.. (all of
     * them, to TL_MAX_OCTAVES), summed in double; its differences
     * normalise the wave sum and stand in for faded octaves. */
    float wave_weight_tail[TL_MAX_OCTAVES + 1];
    /* wave_slope_tail[i]: the mean square of the slopes of octaves i.. (the
     * sum of (weight · frequency)² times TL_WAVE_SLOPE_MEAN_SQ, unnormalised):
     * what level of detail leaves out, for filtered shading. */
    float wave_slope_tail[TL_MAX_OCTAVES + 1];
    float drag, depth;

    /* Quality knobs. */
    int march_octaves, normal_octaves, march_steps;
    float hit_epsilon, normal_epsilon;
    int refine_steps, miss_at_start, normalize_smoothed, facing_normals;
    float march_relax;  /* quality.march_relax: the ocean march's over-relaxation */
    int prepass_budget; /* quality.prepass_budget */
    /* Level of detail: the water one pixel covers per metre of distance
     * (radians; 0 = none): pixel angle / sqrt(samples per pixel). */
    float lod_angle;
    int spp, spp_step; /* samples per pixel; y-stratum step, coprime with spp */
    unsigned seed;     /* jitter seed of this pass (sub-frame sample index) */

    /* Lighting and water look. */
    float sun_dir[3];
    float sun_intensity, sun_sharpness, sky_brightness;
    float fresnel_f0, scatter_color[3], scatter_strength, scatter_base;
    float normal_smooth_max, normal_smooth_rate, normal_smooth_gain;
    float exposure;      /* render.exposure × 2^-render.ev: the display's scale */
    float bloom;         /* render.bloom: the display's glare */
    float pixel_filter;  /* quality.pixel_filter: the display's Gaussian, sigma in pixels */
    float white_gain[3]; /* the display's white balance (tl_prepare_white_gain) */

    /* The giant wave (TL_FEATURE_GIANT_WAVE), see shaders/giant.glsl:
     * frame = (dir.x, dir.z, s, w of the camera relative to the crest),
     * shape = (k, height, steepness, curl) after the clamps,
     * mask = (half length, falloff along, half width, falloff across),
     * bounds = (reach along, Newton bracket half width, slope bound,
     * largest lambda), crest = (peak w, taper, bow, variation), the
     * variation's sines, break = (seconds since the break began at the
     * peak, peel speed, throw time, drop) with TL_FEATURE_GIANT_BREAK,
     * foam = (Jacobian where foam starts, trail length, amount, breaking
     * without a scripted break), scatter = (strength, forward g, backward
     * g, unused), sigma the water's extinction. */
    float giant_frame[4], giant_shape[4], giant_mask[4], giant_bounds[4];
    float giant_crest[4], giant_vary_k[3], giant_vary_phase[3], giant_fade, giant_break[4];
    float giant_speed;
    float giant_lip_box[4], giant_lip_w[2]; /* TL_FEATURE_GIANT_LIP */
    /* TL_FEATURE_GIANT_SPRAY: (amount, reach, drift, bow radius), the
     * crest's box, the bow's burst (camera-relative x, absolute y, z,
     * amount). */
    float giant_spray[4], giant_spray_box[4], giant_spray_bow[4], giant_spray_heading[4];
    float spray_step; /* quality.spray_step: metres a step of the spray's march */
    /* TL_FEATURE_BOW_SPRAY (tl_bow_spray): the centre relative to the
     * camera (y absolute) and amount; the heading (x, z) and radius. */
    float bow_spray[4], bow_spray_shape[4];
    float giant_foam[4], giant_scatter[4], giant_scatter_color[3], giant_sigma[3];
    float giant_slope[TL_GIANT_SLOPE_BINS]; /* slope bound per bin of s */
    float giant_world[2]; /* the crest's world (s, w) wrapped to [0, 65536) m: foam */
    /* The s (crest-relative, as giant_frame's) between which the wave can
     * rise to the camera's height: a rising ray meets nothing outside it.
     * The whole reach when the camera is at or under the still water. */
    float giant_rise[2];
    int giant_iterations;
    float giant_ride;             /* giant.ride */
    float giant_compression_foam; /* 1, or TL_GIANT_UNBROKEN_FOAM with a scripted break */

    /* The floating objects in view (their hulls, mirror images or wakes),
     * slots 0 .. object_count - 1 of the ocean pass's uniform block
     * (objects) and of the mesh pass (object_pass). Matrices are
     * column-major and work in camera-relative metres (the camera at the
     * origin, y too). */
    int object_count;
    tl_object_uniforms objects[TL_OBJECT_MAX];
    tl_object_pass object_pass[TL_OBJECT_MAX];
    float view_proj[16];   /* camera-relative world -> clip (TL_FEATURE_BOAT) */
    float world_offset[2]; /* camera x z wrapped to [0, 65536) m: texture coordinates */

    /* Under water (TL_FEATURE_UNDERWATER); water_ior in every frame, the
     * giant wave's crest refracts the sun with it too. */
    float water_sigma[3];   /* extinction per metre, R G B */
    float water_fall[3];    /* the light from above: its fall per metre down */
    float water_scattering; /* per metre, grey */
    /* The slope variance per axis of the capillary ripples finer than the
     * finest octave (tl_prepare_capillary_slope_variance). */
    float capillary_slope_var;
    /* The angle the sun's beam under the water spreads over
     * (tl_caustic_beam_spread): a floating object's shadow blurs by it per
     * metre down. */
    float beam_spread;
    float water_ior;
    float cam_depth;          /* metres below the surface at the camera (0 above) */
    float lens;               /* TL_LENS_DISTANCE */
    float sun_water[3];       /* the direction sunlight travels in the water */
    float sun_water_trans;    /* the share of it that crosses a flat surface */
    float caustics;           /* underwater.caustics (TL_FEATURE_CAUSTICS) */
    float shafts;             /* underwater.shafts (TL_FEATURE_SHAFTS) */
    int shaft_steps;          /* quality.shaft_steps (TL_FEATURE_SHAFTS) */
    int mesh_scale;           /* quality.mesh_scale (TL_FEATURE_BOAT): the hulls' target's n */
    float particles;          /* underwater.particles (TL_FEATURE_PARTICLES) */
    float particle_offset[3]; /* the camera wrapped every TL_PARTICLE_PERIOD m */
    float floor_depth;        /* ocean.floor_depth (TL_FEATURE_SEA_FLOOR) */
    float floor_offset[2];    /* the camera's x z wrapped every TL_FLOOR_PERIOD */

    /* Fog (TL_FEATURE_FOG): density per metre at the water, height scale. */
    float fog[2];
    float fog_color[3];

    /* The physical sky (TL_FEATURE_SKY_PHYSICAL). The sky-view table and
     * sky_ambient come from tl_sky_luts (tl_render fills the ambient). */
    float sky_scale;      /* the sun's illuminance above the air */
    float sun_light[3];   /* its light at the camera */
    float sun_cos_radius; /* cos of the disc's angular radius */
    float sky_ambient[3]; /* the sky's irradiance on a surface facing up, over pi */
} tl_frame_uniforms;

/* For frames with TL_FEATURE_SKY_PHYSICAL (else it returns 0): brings the
 * atmosphere's tables in `luts` up to date for the scene (rebuilt only
 * when the air changed) and gives the sun's elevation and the altitude the
 * sky-view table must be built for. Returns 1. The renderer builds that
 * table (tl_renderer_prepare_sky), then tl_prepare_sky_ambient. */
struct tl_sky_luts;
int tl_prepare_sky_tables(const tl_scene *s, struct tl_sky_luts *luts, const tl_frame_uniforms *u,
                          double *sun_elevation, double *altitude);
/* u->sky_ambient from the sky-view table in `luts`. */
void tl_prepare_sky_ambient(const tl_scene *s, const struct tl_sky_luts *luts,
                            tl_frame_uniforms *u);

/* The altitude the sky-view table is built for: the camera's, in steps of
 * 100 m (the sky changes little below that), so every frame of a shot can
 * share one table and a frame rendered alone gets the same one. */
double tl_prepare_sky_altitude(const tl_scene *s);

/* Where the camera sees from, for underwater.mode auto: above the water,
 * below it, or with the lens across the surface (decided per pixel). */
typedef enum tl_water_side {
    TL_WATER_ABOVE,
    TL_WATER_BELOW,
    TL_WATER_STRADDLES,
} tl_water_side;

/* The frame's side of the water from the double CPU surface (giant wave
 * included); *gap (may be NULL) gets the camera's height above it. */
tl_water_side tl_prepare_water_side(const tl_scene *s, const tl_waves *w, const tl_giant *giant,
                                    double *gap);

/* Near and far planes of the boat's rasterised pass, metres. */
#define TL_BOAT_NEAR 0.05
/* The boat's shadow map: texels a side at most (a 10 m boat's at half a
 * centimetre) and at least; a frame uses twice the boat's size on screen. */
#define TL_BOAT_SHADOW_SIZE  2048
#define TL_BOAT_SHADOW_LEAST 128
/* The share of the sun's part of the light the water scatters up that a
 * boat's shadow takes away: that light entered the water over metres
 * around the point, most of a boat's shadow wide. */
#define TL_BOAT_SHADOW_SCATTER 0.5
/* The water's foam at the hull (shaders/boat.glsl): a line this wide (m)
 * all round the waterline, and the bow wave's white water reaching out
 * TL_BOAT_CONTACT_LINE + TL_BOAT_BOW_WAVE x the speed (m/s) from the bow. */
#define TL_BOAT_CONTACT_LINE 0.35
#define TL_BOAT_BOW_WAVE     0.2
#define TL_BOAT_FAR          1.0e5

/* Fills `u` from `scene` (validated by the caller). `waves` must have been
 * built from scene->ocean; it is passed in so callers reuse it per shot. */
/* The display's white balance (render.white_point, render.white_depth):
 * per channel, the white's luminance over its value, so the white shows
 * neutral at its own luminance (von Kries scaling in linear Rec.709), each
 * held within 1 / TL_WHITE_GAIN_MAX .. TL_WHITE_GAIN_MAX. */
#define TL_WHITE_GAIN_MAX 1e4
void tl_prepare_white_gain(const tl_scene *s, float gain[3]);

void tl_prepare_frame(const tl_scene *scene, const tl_waves *waves, tl_frame_uniforms *u);

/* Shifts the boat's projection (u->view_proj) by the centre of sample
 * `sample`'s stratum, of u->spp: where the ocean's N-rooks sample of that
 * index looks, less its per-pixel jitter. Drawn once per sample, the
 * hull's edges are then anti-aliased as the water's are. */
void tl_prepare_boat_sample(tl_frame_uniforms *u, int sample);

#endif
