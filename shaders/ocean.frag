// The ocean: one ray per pixel from the camera, sky above the horizon,
// marched water below. Writes linear radiance and the distance along the
// view ray (TL_SKY_DEPTH where nothing is hit).
#include "uniforms.glsl"
#ifdef TL_PASS_AOV
#include "aov.glsl"
#endif
#include "waves.glsl"
#include "sky.glsl"
#include "optics.glsl"
#include "foam.glsl"
// Caustics before giant.glsl: the light through the crest has them too.
#if defined(TL_FEATURE_CAUSTICS) || defined(TL_FEATURE_SHAFTS) ||                                  \
    defined(TL_FEATURE_GIANT_CAUSTICS)
#include "caustics.glsl"
#endif
// The crest line, before giant.glsl (which includes it too: a file is
// expanded once, the first time, whatever #if it is under): outside the
// wave's rectangle it is all of the wave the program has, which the water
// in front of the wave mirrors (water.glsl, TL_GIANT_MIRROR).
#if defined(TL_FEATURE_GIANT_WAVE) || defined(TL_GIANT_MIRROR)
#include "giant_crest.glsl"
#endif
#ifdef TL_FEATURE_GIANT_WAVE
#include "giant.glsl"
#endif
#include "surface.glsl"
#ifdef TL_MARCH_PREPASS
uniform float u_prepass_scale; // the block a prepass ray stands for, in pixels
#endif
#include "march.glsl"
#ifdef TL_FEATURE_UNDERWATER
#include "lens.glsl"
#endif
#ifdef TL_FEATURE_WAKE
#include "wake.glsl"
#endif
#ifdef TL_FEATURE_BOAT
#include "boat.glsl"
#include "lamps.glsl"
#endif
#ifdef TL_FEATURE_BOAT_SHADOW
#include "boat_shadow.glsl"
#endif
// The water body's light and the sea floor before water.glsl:
// the floor shows through the surface from above too.
#if defined(TL_FEATURE_UNDERWATER) || defined(TL_FEATURE_SEA_FLOOR)
#include "water_light.glsl"
#endif
#ifdef TL_FEATURE_SEA_FLOOR
#include "sea_floor.glsl"
#endif
#include "water.glsl"
#ifdef TL_FEATURE_GIANT_LIP
#include "lip.glsl"
#include "lip_shade.glsl"
#endif
// Before spray.glsl, which includes it too: a file is expanded once, and
// here outside any #ifdef (its parts have their own).
#include "bow_spray.glsl"
#ifdef TL_FEATURE_GIANT_SPRAY
#include "spray.glsl"
#endif
#ifdef TL_FEATURE_UNDERWATER
#ifdef TL_FEATURE_SHAFTS
#include "shafts.glsl"
#endif
#ifdef TL_FEATURE_PARTICLES
#include "particles.glsl"
#endif
#include "underwater.glsl"
#endif

// Supersampling (TL_FEATURE_SUPERSAMPLE): u_spp stratified samples per
// pixel (N-rooks: sample s takes x stratum s and y stratum
// (s * u_spp_step) mod u_spp, jittered inside its cell by a hash of
// pixel, sample and u_seed, so a frame is the
// same every time it is rendered). One draw takes samples u_sample_first
// .. u_sample_first + u_sample_count - 1 (the renderer splits a pixel's
// samples over draws: llvmpipe caps a fragment's loop iterations), and
// u_sample_weight scales their average by the draw's share of the pixel
// and of the sub-frame passes (motion blur).
uniform int u_sample_first;
uniform int u_sample_count;
uniform float u_sample_weight;

#ifdef TL_MARCH_PREPASS
layout(location = 0) out float out_hint;
#else
layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_depth;
#endif

uint hash_u32(uint x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

vec2 sample_offset(int s)
{
    if (u_spp <= 1)
        return vec2(0.0); // the pixel centre, exactly
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint h = hash_u32(pixel.x * 73856093u ^ pixel.y * 19349663u ^ uint(s) * 83492791u ^ u_seed);
    vec2 jitter = vec2(float(h & 0xffffu), float(h >> 16)) / 65536.0;
    vec2 stratum = vec2(float(s), float((s * u_spp_step) % u_spp));
    return (stratum + jitter) / float(u_spp) - 0.5;
}

vec3 camera_ray(vec2 pixel)
{
    vec2 ndc = pixel / u_resolution * 2.0 - 1.0;
    float aspect = u_resolution.x / u_resolution.y;
    vec3 d = u_cam_forward + (ndc.x * aspect * u_tan_half_vfov) * u_cam_right +
             (ndc.y * u_tan_half_vfov) * u_cam_up;
    return normalize(d);
}

// Radiance along one ray from above the water; *dist is the hit distance
// or TL_SKY_DEPTH. t_min: where the view starts (the lens plane when the
// camera is at the surface).
vec3 trace_water(vec3 ray, float t_min, out float dist)
{
    float t = march_water(ray, t_min);
#if defined(TL_FEATURE_GIANT_LIP) && !defined(TL_MARCH_PREPASS)
    // The lip overhangs the height field: the nearer of the two.
    float t_lip = giant_lip_march(ray, t_min, t < 0.0 ? TL_FAR : t);
    if (t_lip >= 0.0) {
        dist = t_lip;
        return giant_lip_color(ray, vec3(0.0, u_cam_height, 0.0) + ray * t_lip);
    }
#endif
    if (t < 0.0) {
        dist = TL_SKY_DEPTH;
        return sky_color(ray);
    }
#ifdef TL_FEATURE_POLISH
    t = surface_polish(ray, t);
#endif
    dist = t;
    vec3 hit = vec3(0.0, u_cam_height, 0.0) + ray * t;
    return water_color(ray, hit, t);
}

// The water and sky along one ray, and whatever mesh stands in front.
vec3 trace(vec3 ray, out float dist)
{
#ifdef TL_FEATURE_UNDERWATER
    bool under = true;
    float gap = -1.0;
#ifdef TL_FEATURE_WATERLINE
    gap = underwater_lens_gap(ray);
    under = gap < 0.0;
#endif
    if (under) {
#ifdef TL_PASS_AOV
        g_aov_under = true;
        g_aov_hit = AOV_OCEAN; // the water body, where the ray meets nothing
#endif
        vec3 below = trace_underwater(ray, dist);
#ifdef TL_FEATURE_BOAT
        // The hull under water, seen through the water body.
        float water_dist = dist;
        vec3 seen = boat_composite(below, ray, dist);
        if (dist < water_dist) {
            vec3 trans = optics_water_transmittance(dist);
            below = seen * trans + water_inscatter(max(-u_cam_height, 0.0), ray, dist);
        }
#endif
#ifdef TL_FEATURE_PARTICLES
        below += layer_emit(TL_LIGHT_BODY, water_particles(ray, dist));
#endif
        // A thin dark meniscus where the lens meets the surface.
        return below * mix(0.35, 1.0, smoothstep(0.0, 0.015, -gap));
    }
    vec3 color = trace_water(ray, underwater_start(ray), dist);
    color *= mix(0.35, 1.0, smoothstep(0.0, 0.015, gap));
#else
    vec3 color = trace_water(ray, 0.0, dist);
#endif
#ifdef TL_FEATURE_BOAT
    color = boat_composite(color, ray, dist);
#endif
#ifdef TL_FEATURE_GIANT_SPRAY
    color = giant_spray(ray, dist, color);
#endif
#ifdef TL_FEATURE_BOW_SPRAY
    color = bow_spray(ray, dist, color);
#endif
#ifdef TL_FEATURE_FOG
    color = optics_fog(color, u_cam_height, ray, dist, TL_LIGHT_SKY);
#endif
    return color;
}

#ifdef TL_FEATURE_SHAFTS
// The light shafts (shafts.glsl), added once per pixel along its centre's
// ray up to the nearest thing its samples met (the surface, the floor, a
// hull), in the pixel's whole quad at once. They take light from some
// places (focus < 1) and give it to others: a dim pixel's share cannot go
// below nothing.
vec4 add_shafts(vec4 color, float depth)
{
    vec3 ray = camera_ray(gl_FragCoord.xy);
    float seen = 1.0; // the meniscus dims them as the rest of the light
#ifdef TL_FEATURE_WATERLINE
    float gap = underwater_lens_gap(ray);
    seen = gap < 0.0 ? mix(0.35, 1.0, smoothstep(0.0, 0.015, -gap)) : 0.0;
#endif
    vec3 shafts = seen > 0.0 ? water_shafts(ray, depth) : vec3(0.0);
    shafts = shafts_quad_mean(shafts) * seen;
    color.rgb = max(color.rgb + layer_emit(TL_LIGHT_BODY, shafts) * color.a, vec3(0.0));
    return color;
}
#endif

#ifdef TL_MARCH_PREPASS
// A level of the march prepass: the march alone, one ray at the centre of
// each block of u_prepass_scale x u_prepass_scale pixels.
void main()
{
    g_pixel = u_prepass_scale * gl_FragCoord.xy;
    float t = march_water(camera_ray(g_pixel), 0.0);
    out_hint = g_pass_rose ? g_pass_near : t;
}
#else
void main()
{
#ifdef TL_FEATURE_SUPERSAMPLE
    vec3 sum = vec3(0.0);
    int good = 0;
    // Depth of a supersampled pixel: the nearest surface any sample saw.
    float depth = TL_SKY_DEPTH;
#ifdef TL_PASS_AOV
    aov_begin_pixel();
#endif
    for (int k = 0; k < max(u_sample_count, 1); k++) {
        int s = u_sample_first + k;
        float dist;
        g_pixel = gl_FragCoord.xy + sample_offset(s);
#ifdef TL_PASS_AOV
        aov_begin_sample();
#endif
        vec3 c = trace(camera_ray(g_pixel), dist);
        // Last guard: no NaN or Inf may reach a pixel. A bad sample is
        // dropped alone, here and across the pixel's other passes
        // (radiance.glsl): one stray sample cannot blacken a pixel.
        if (any(isnan(c)) || any(isinf(c)))
            continue;
#ifdef TL_PASS_AOV
        aov_add_sample();
#endif
        sum += c;
        good++;
        depth = min(depth, dist);
    }
    // Premultiplied (radiance.glsl): alpha is the share of good samples.
    vec4 color = vec4(sum, float(good)) / float(max(u_sample_count, 1));
#ifdef TL_PASS_AOV
    aov_write(float(max(u_sample_count, 1)), u_sample_weight);
#endif
#else
    // One sample at the pixel's centre, without the loop: around the whole
    // trace it costs llvmpipe a sixth of the frame.
    float depth;
    g_pixel = gl_FragCoord.xy;
#ifdef TL_PASS_AOV
    aov_begin_pixel();
    aov_begin_sample();
#endif
    vec4 color = vec4(trace(camera_ray(g_pixel), depth), 1.0);
    if (any(isnan(color)) || any(isinf(color))) { // the same last guard
        color = vec4(0.0);
        depth = TL_SKY_DEPTH;
    }
#ifdef TL_PASS_AOV
    else
        aov_add_sample();
    aov_write(1.0, u_sample_weight);
#endif
#endif
#ifdef TL_FEATURE_SHAFTS
    color = add_shafts(color, depth);
#endif
    out_color = color * u_sample_weight;
    out_depth = depth;
}
#endif
