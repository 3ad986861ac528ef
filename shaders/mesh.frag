// The boat's surfaces, lit by the same sun and sky as the water: each
// vertex's material (shaders/material.glsl) under the sun, the sky and the
// sea as an environment, its baked occlusion, wet and glossy where the sea
// has been; below the waterline, the light of the water around it (with
// TL_FEATURE_UNDERWATER). With TL_MESH_MAPS (a model with textures), the
// part's maps scale its factors (glTF's metallic-roughness material).
// Writes linear radiance and the distance along
// the view ray, like the ocean, for the ocean pass to composite
// (shaders/boat.glsl).
#include "uniforms.glsl"
#include "sky.glsl"
#include "optics.glsl"
#include "material.glsl"
#include "foam_noise.glsl"
#include "hull_wash.glsl"
#ifdef TL_FEATURE_BOAT_SHADOW
#include "boat_shadow.glsl"
#endif
#ifdef TL_FEATURE_UNDERWATER
#include "water_light.glsl"
#endif
#ifdef TL_FEATURE_CAUSTICS
#include "waves.glsl"
#include "caustics.glsl"
#endif

in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
in vec4 v_surface;
in vec2 v_wet;

uniform vec3 u_eye;     // the camera (the origin), or its mirror image for the reflection
uniform float u_sunlit; // the share of the sun the hull sees past the giant wave's crest
uniform float u_lights; // boat.lights: the lamps' share of their emission
uniform int u_object;   // the object's slot in u_objects (objects.glsl)
#ifdef TL_MESH_MAPS
in vec2 v_uv;
in vec4 v_tangent;
uniform int u_maps; // which of the part's maps it has: bit k for tl_mesh_map k
uniform sampler2D u_map_base_color, u_map_metallic_roughness, u_map_normal, u_map_occlusion,
    u_map_emissive;
uniform vec3 u_emissive; // the part's emissive radiance (factor x TL_MESH_EMISSIVE_RADIANCE)
uniform float u_normal_scale, u_occlusion_strength;
#endif

layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_depth;
// With the compositing passes (a third attachment; dropped without it):
// the normal facing the eye, and 1 + the object's index in the scene.
layout(location = 2) out vec4 out_surface;
uniform int u_scene_object;

void main()
{
    vec3 view = normalize(v_world - u_eye); // from the eye
    vec3 v = -view;
    vec3 n = normalize(v_normal);
    // Two-sided: models may be open or wound either way. A back face's
    // normal, mapped or not, is turned round whole (as glTF's double-sided
    // materials have it), by which way the geometry faces.
    bool back = dot(n, view) > 0.0;
    vec3 base = v_color;
    float roughness = v_surface.x, metallic = v_surface.y, occlusion = v_surface.z;
    vec3 emission = v_color * v_surface.w;
#ifdef TL_MESH_MAPS
    // glTF: the maps multiply the factors; occlusion by its strength.
    if ((u_maps & 1) != 0)
        base *= texture(u_map_base_color, v_uv).rgb;
    if ((u_maps & 2) != 0) {
        vec3 mr = texture(u_map_metallic_roughness, v_uv).rgb;
        roughness *= mr.g;
        metallic *= mr.b;
    }
    if ((u_maps & 4) != 0)
        n = material_normal_map(n, v_tangent, texture(u_map_normal, v_uv).rgb, u_normal_scale);
    if ((u_maps & 8) != 0)
        occlusion *= 1.0 + u_occlusion_strength * (texture(u_map_occlusion, v_uv).r - 1.0);
    emission += u_emissive * ((u_maps & 16) != 0 ? texture(u_map_emissive, v_uv).rgb : vec3(1.0));
#endif
    if (back)
        n = -n;
    float streak = 0.6 * material_streak(v_wet.y * 6.0) + 0.4 * material_streak(v_wet.y * 23.0);
    float wet = material_wetness(v_wet.x, streak);
    float porous = smoothstep(0.3, 0.8, roughness);
    base *= 1.0 - wet * (TL_MESH_WET_DARKEN + (0.5 - TL_MESH_WET_DARKEN) * porous);
    roughness = mix(roughness, min(roughness, 0.1), wet);
    vec3 f0 = material_f0(base, metallic);
    float nv = max(dot(n, v), 1.0e-4);
    vec3 r = reflect(view, n);
    vec3 diffuse_color = base * (1.0 - metallic);
    vec3 color;
#ifdef TL_FEATURE_UNDERWATER
    float depth = u_objects[u_object].hull.y - v_world.y;
    if (depth > 0.0) {
        // Under the water: the sun refracted and dimmed along its path
        // down, focused by the waves (caustics), the sky's light from above
        // and the water's own from below (its albedo's share of what comes
        // down); the surface above is the environment looking up, the
        // depths looking down.
        vec3 sun = water_sun_at(depth) * u_sunlit;
#ifdef TL_FEATURE_CAUSTICS
        float footprint = length(v_world - u_eye) * 2.0 * u_tan_half_vfov / (u_resolution.y * float(max(u_mesh_scale, 1)));
        sun *= caustic_light(v_world.xz, depth, footprint);
#endif
        // From above: the sky's light and the share of the sun the water
        // has turned diffuse (the rest is the beam above, caustics and
        // all); from below, the water's own back-scatter of all of it, and
        // a sandy floor's light where there is one.
        vec3 sun_even = water_sun_at(depth) * (-u_sun_water.y / TL_PI);
        vec3 from_above = water_sky_at(depth) + sun_even * water_sun_diffuse(depth);
        vec3 water_below = 0.5 * water_albedo() * (water_sky_at(depth) + sun_even);
        vec3 from_below = water_below, mirrored_below = water_below;
#ifdef TL_FEATURE_SEA_FLOOR
        // The sand fills the lower hemisphere's even light; a reflection
        // sees it along r, far off and faded toward the horizon.
        from_below += water_floor_up(depth, -1.0);
        mirrored_below += water_floor_up(depth, min(r.y, 0.0));
#endif
        // The light from above comes through Snell's window, high overhead:
        // a face turned down sees little of it (the hull's bottom is dark,
        // its sides and keel lighter, so its form shows); the light from
        // below is even, as the lower hemisphere's share.
        vec3 ambient = from_above * optics_window_share(n.y, u_water_ior) +
                       from_below * (0.5 - 0.5 * n.y);
        // A mirrored ray sees the window's light (its radiance the even
        // light's over sin^2 of its half-angle: the same irradiance from a
        // narrower cone) only inside it, blurred by the roughness; past
        // its edge the surface mirrors the water below. Paint against
        // water reflects a tenth of what it does in air.
        float s = 1.0 / u_water_ior;
        float edge = sqrt(1.0 - s * s), blur = 0.05 + 0.5 * roughness;
        float in_window = smoothstep(edge - blur, edge + blur, r.y);
        vec3 env = mix(mirrored_below, from_above / (s * s), in_window);
        f0 = mix(vec3(TL_MESH_F0_UNDER_WATER), base, metallic);
        color = material_brdf(n, v, -u_sun_water, base, roughness, metallic) * sun +
                (diffuse_color * ambient + env * material_env_brdf(f0, roughness, nv)) * occlusion;
    } else
#endif
    {
        // The water's light: what it scatters up (as the ocean shades it)
        // and what it mirrors; the sky above. The hemisphere around n sees
        // a blend of the two, by how far it faces up.
        vec3 sunlight = sky_sun_light() * u_sunlit;
#ifdef TL_FEATURE_BOAT_SHADOW
        // Looked up a texel and a half off the surface along its normal,
        // so that a face lit at a grazing angle does not shadow itself.
        sunlight *= boat_shadow(v_world + n * (1.5 * u_objects[u_object].shadow_map.x));
#endif
        vec3 upwelling = u_scatter_color * u_scatter_strength * (u_scatter_base + 0.5);
#ifdef TL_FEATURE_SKY_PHYSICAL
        upwelling *= (sunlight * max(u_sun_dir.y, 0.0) + TL_PI * sky_ambient()) / 0.94;
#endif
        vec3 sea = 0.06 * sky_ambient() + upwelling;
        vec3 ambient = mix(sea, sky_ambient(), 0.5 + 0.5 * n.y);
        // A rough surface's reflection is the hemisphere's blur.
        vec3 env = mix(material_environment(r, upwelling), mix(sea, sky_ambient(), 0.5 + 0.5 * r.y),
                       roughness);
        color = material_brdf(n, v, u_sun_dir, base, roughness, metallic) * sunlight +
                (diffuse_color * ambient + env * material_env_brdf(f0, roughness, nv)) * occlusion;
        // The water at the waterline and the bow wave up the stem: a sheet
        // of sea over the paint (its own colour, the sky mirrored at the
        // paint's gloss), and white foam in it lit as the water's is (the
        // sun wrapped a little round, as through a froth).
        float footprint = length(v_world - u_eye) * 2.0 * u_tan_half_vfov / (u_resolution.y * float(max(u_mesh_scale, 1)));
        vec2 wash = hull_wash(u_object, v_world, footprint);
        vec3 film = sea + env * material_env_brdf(vec3(0.02), 0.05, nv);
        vec3 froth = 0.8 * (sunlight * (0.3 + 0.7 * max(dot(n, u_sun_dir), 0.0)) / TL_PI + ambient);
        color = mix(mix(color, film, TL_MESH_WASH_FILM * wash.x), froth, wash.y);
    }
    color += emission * u_lights;
    if (any(isnan(color)) || any(isinf(color)))
        color = vec3(0.0);
    out_color = vec4(max(color, vec3(0.0)), 1.0);
    out_depth = length(v_world - u_eye);
    out_surface = vec4(n, 1.0 + float(u_scene_object));
}
