// Probe: evaluates one of the shaders' functions at inputs read from a
// texture, one per output texel, for the tests to compare with the CPU:
//   mode 0: surface height at camera-relative (x, z)   (tl_waves_surface_height)
//   mode 1: Fresnel reflectance at cos x from index y into air (tl_optics_fresnel)
//   mode 2: the water body's transmittance over x metres, R G B
//   mode 3: the fog's transmittance over x metres along a ray with y = its
//           vertical component                           (tl_optics_fog_depth)
//   mode 4: the lens's gap to the surface for the pixel at NDC (x, y)
//   mode 5: the sky's radiance (no sun disc) at elevation x, azimuth y from
//           the sun's, radians                           (tl_sky_reference)
//   mode 6: the surface's slope d height / d (x, z) at camera-relative
//           (x, z) as the analytic normal sees it (the ocean's carried
//           gradient plus the giant wave's) in .xy, that path's height in .z
//   mode 7: the share of the sun the water at camera-relative (x, z) sees
//           past the giant wave's crest, at the surface's height there
//           (tl_giant_sunlit)
//   mode 8: the foam's close-up detail at the point (x, 0.37 x) for a pixel
//           footprint of y metres (foam_detail)
//   mode 9: the boat's wake at camera-relative (x, z), no level of detail
//           and the ocean's value 0.5: foam cover, thickness, bubbles
//           (wake_foam)
//   mode 10: the giant wave's lip at the w of camera-relative (x, z):
//           its centre (s, y), radius and half thickness (tl_giant_lip_at)
//   mode 11: the same lip's angles from and to, throw and presence
//   mode 12: the spray's density at camera-relative (x, z) and height y,
//           the input's third float, over the span of height its fourth
//           (tl_giant_spray_density), and in .y the landing's and the
//           burst's optical depth toward the sun there (tl_giant_spray_shade),
//           in .z and .w what the landing's billows let in of the sun and of
//           the sky overhead (tl_giant_spray_open)
//   mode 13: a material's BRDF x cos for the normal +y, the view at angle x
//           from it, the light at angle y, z the azimuth between them; w
//           the roughness, negative for a metal; base colour 0.8 0.4 0.1
//           (tl_mesh_brdf)
//   mode 14: the environment's specular share at cos x, roughness y, for
//           f0 = 0.04 0.5 0.9                            (tl_mesh_env_brdf)
//   mode 15: how wet a hull is x metres above its waterline with the
//           streak y                                     (tl_mesh_wetness)
//   mode 16: the Kelvin wake's slope at x metres behind the boat, y across,
//           speed z m/s, footprint w m, the frame's hull length
//           (tl_kelvin_slope); z: how white its crests are there
//           (tl_kelvin_whitecap)
//   mode 17: the normal a normal map's texel (x y z) gives the normal
//           normalize(0.3, 0.9, -0.2) with the tangent (1, 0, 0.4), its
//           tilt scaled by |w|, the bitangent's side the sign of w
//           (tl_mesh_normal_map)
//   mode 18: the bow's spray density at camera-relative (x, z) and height
//           y, the input's third float       (tl_bow_spray_density), and
//           y its shade toward the sun       (tl_bow_spray_shade)
//   mode 20: the light the water scatters toward the eye along a ray from
//           x metres down, its y component the input's y, its azimuth z
//           radians from +x toward +z, over w metres (tl_optics_water_inscatter)
//   mode 19: the caustics' focus at camera-relative (x, z), the input's
//           third float metres down, its fourth the footprint
//                                            (tl_caustic_focus)
//   mode 21: the crest's caustics at camera-relative (x, z) for light that
//           crossed the input's third float metres of the crest, its
//           fourth the footprint                   (tl_caustic_crest)
//   mode 29: a small wave's shading normal on the giant wave at camera-
//           relative (x, z), the small wave's slope the input's third and
//           fourth floats added to the wave's, seen from the camera
//           (at the wave's height there)             (tl_giant_facet_seen)
//   mode 22: the giant wave's lip at camera-relative (x, z) and height y,
//           the input's third float: its signed distance in the
//           cross-section, the lumps' factor and roughness at that angle
//                  (tl_giant_lip_distance, tl_giant_lip_lump)
//   mode 24: how much of the sky in the direction whose x and z are the
//           input's third and fourth floats (y upward, unit) the water at
//           camera-relative (x, z) sees past the giant wave's crest, at the
//           surface's height there, for rays spread by 0.1 rad
//                                            (tl_giant_clear)
//   mode 25: the share of Snell's window's light on a face under the
//           water whose normal's y is x, for the index y
//                                          (tl_optics_window_share)
//   mode 26: the white water's cover on a hull x metres above the water
//           plane at y along its waterline (1 at the stem), speed z m/s,
//           the lace w              (tl_mesh_wash_cover, tl_mesh_wash_top)
//   mode 27: a lamp's glint at cos x from its centre, its angular radius y
//                                            (tl_optics_lamp_glint)
//   mode 28: the water's normal blend toward up the input's third float
//           metres from the eye, on a level sea (x) and on the giant wave
//           at camera-relative (x, z) (y)
//                          (tl_optics_normal_blend, tl_giant_face_blend)
//   mode 30: metres of the giant wave's water a ray crosses from
//           camera-relative (x, the input's third float, z), in the
//           vertical plane of the wave's travel at the input's fourth float
//           radians up from its travel direction   (tl_giant_water_along)
//   mode 31: the foam's cellular noise at (x, z), not camera-relative
//                                                   (tl_noise_cells)
#include "uniforms.glsl"
#include "waves.glsl"
#include "sky.glsl"
#include "optics.glsl"
#include "foam.glsl"
#include "material.glsl"
#include "hull_wash.glsl"
#if defined(TL_FEATURE_CAUSTICS) || defined(TL_FEATURE_GIANT_CAUSTICS)
#include "caustics.glsl"
#endif
#ifdef TL_FEATURE_GIANT_WAVE
#include "giant.glsl"
#endif
#ifdef TL_FEATURE_GIANT_LIP
#include "lip.glsl"
#endif
// Before spray.glsl, which includes it too: a file is expanded once, and
// here outside any #ifdef (its parts have their own).
#include "bow_spray.glsl"
#ifdef TL_FEATURE_GIANT_SPRAY
#include "spray.glsl"
#endif
#include "surface.glsl"
#ifdef TL_FEATURE_UNDERWATER
#include "lens.glsl"
#include "water_light.glsl"
#endif
#ifdef TL_FEATURE_WAKE
#include "wake.glsl"
#endif

uniform int u_probe_mode;

uniform sampler2D u_points; // .xy = camera-relative (x, z)
uniform int u_probe_octaves;

layout(location = 0) out vec4 out_height;

void main()
{
    vec4 input4 = texelFetch(u_points, ivec2(gl_FragCoord.xy), 0);
    vec2 p = input4.xy;
    vec4 result = vec4(0.0);
    if (u_probe_mode == 0)
        result.x = surface_height(p, u_probe_octaves, 0.0);
    else if (u_probe_mode == 1)
        result.x = optics_fresnel(p.x, p.y, 1.0);
    else if (u_probe_mode == 25)
        result.x = optics_window_share(p.x, p.y);
    else if (u_probe_mode == 32) // cos_i, n1, spread; into air
        result.x = optics_fresnel_rough(input4.x, input4.y, 1.0, input4.z);
    else if (u_probe_mode == 27)
        result.x = optics_lamp_glint(p.x, p.y);
#ifdef TL_FEATURE_UNDERWATER
    else if (u_probe_mode == 2)
        result.xyz = optics_water_transmittance(p.x);
    else if (u_probe_mode == 4) {
        vec3 ray = normalize(u_cam_forward + (p.x * u_resolution.x / u_resolution.y *
                                             u_tan_half_vfov) * u_cam_right +
                             (p.y * u_tan_half_vfov) * u_cam_up);
        result.x = underwater_lens_gap(ray);
    } else if (u_probe_mode == 20) {
        float level = sqrt(max(1.0 - input4.y * input4.y, 0.0));
        vec3 ray = vec3(level * cos(input4.z), input4.y, level * sin(input4.z));
        result.xyz = water_inscatter(input4.x, ray, input4.w);
    }
#endif
#ifdef TL_FEATURE_WAKE
    else if (u_probe_mode == 16) {
        result.xy = wake_kelvin_slope(input4.x, input4.y, input4.z, u_objects[0].wake_params.w,
                                      input4.w);
        result.z =
            wake_kelvin_whitecap(input4.x, input4.y, input4.z, u_objects[0].wake_params.w);
    }
#endif
    else if (u_probe_mode == 13) {
        vec3 v = vec3(sin(input4.x), cos(input4.x), 0.0);
        vec3 l = vec3(sin(input4.y) * cos(input4.z), cos(input4.y), sin(input4.y) * sin(input4.z));
        result.xyz = material_brdf(vec3(0.0, 1.0, 0.0), v, l, vec3(0.8, 0.4, 0.1), abs(input4.w),
                                   input4.w < 0.0 ? 1.0 : 0.0);
    } else if (u_probe_mode == 14)
        result.xyz = material_env_brdf(vec3(0.04, 0.5, 0.9), p.y, p.x);
    else if (u_probe_mode == 15)
        result.x = material_wetness(p.x, p.y);
    else if (u_probe_mode == 31)
        result.x = foam_cells(p);
    else if (u_probe_mode == 26)
        result.x = hull_wash_cover(input4.x, hull_wash_top(input4.y, input4.z), input4.w);
#ifdef TL_FEATURE_CAUSTICS
    else if (u_probe_mode == 19)
        result.x = caustic_focus(p, input4.z, input4.w, TL_CAUSTIC_ON_SURFACE);
#endif
#ifdef TL_FEATURE_GIANT_CAUSTICS
    else if (u_probe_mode == 21)
        result.x = caustic_crest(p, input4.z, input4.w);
#endif
#ifdef TL_FEATURE_BOW_SPRAY
    else if (u_probe_mode == 18)
    {
        result.x = bow_spray_density(0, vec3(p.x, input4.z, p.y));
        result.y = bow_spray_shade(0, vec3(p.x, input4.z, p.y));
    }
#endif
    else if (u_probe_mode == 17)
        result.xyz = material_normal_map(normalize(vec3(0.3, 0.9, -0.2)),
                                         vec4(1.0, 0.0, 0.4, input4.w < 0.0 ? -1.0 : 1.0),
                                         input4.xyz, abs(input4.w));
    else if (u_probe_mode == 5) {
        vec3 dir = vec3(cos(p.x) * sin(p.y), sin(p.x), cos(p.x) * cos(p.y));
        float a = atan(u_sun_dir.x, u_sun_dir.z); // turn azimuth 0 to the sun's
        dir.xz = mat2(cos(a), -sin(a), sin(a), cos(a)) * dir.xz;
        result.xyz = sky_atmosphere(dir, u_sun_dir);
    }
    else if (u_probe_mode == 6) {
        vec2 grad;
        float slope_var;
#ifdef TL_FEATURE_GIANT_WAVE
        GiantSample g = giant_sample(p);
        float value = waves_value_grad(giant_ride(p, g), u_probe_octaves, 0.0, grad, slope_var);
        result.xyz = vec3(giant_ride_grad(grad * u_depth, g) + g.grad,
                          (value - 1.0) * u_depth + g.height);
#else
        float value = waves_value_grad(p, u_probe_octaves, 0.0, grad, slope_var);
        result.xyz = vec3(grad * u_depth, (value - 1.0) * u_depth);
#endif
    }
#ifdef TL_FEATURE_GIANT_WAVE
    else if (u_probe_mode == 7)
        result.x = giant_sunlit(p, surface_height(p, u_probe_octaves, 0.0));
    else if (u_probe_mode == 8)
        result.x = foam_detail(vec2(p.x, 0.37 * p.x), p.y);
    else if (u_probe_mode == 23)
        result.x = giant_short_wave_gain(giant_sample(p));
    else if (u_probe_mode == 28) {
        result.x = optics_normal_blend(input4.z);
        result.y = giant_face_blend(giant_sample(p), result.x);
    }
    else if (u_probe_mode == 29) {
        GiantSample g = giant_sample(p);
        vec2 slope = g.grad + input4.zw;
        vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
        vec3 ray = normalize(vec3(p.x, g.height - u_cam_height, p.y));
        result.xyz = giant_facet_seen(n, ray, g);
    }
    else if (u_probe_mode == 30) {
        vec2 d = u_giant_frame.xy;
        vec3 dir = vec3(cos(input4.w) * d.x, sin(input4.w), cos(input4.w) * d.y);
        result.x = giant_water_along(vec3(p.x, input4.z, p.y), dir);
    }
    else if (u_probe_mode == 24) {
        vec2 flat_dir = input4.zw;
        vec3 dir = vec3(flat_dir.x, sqrt(max(1.0 - dot(flat_dir, flat_dir), 0.0)), flat_dir.y);
        result.x = giant_clear(p, surface_height(p, u_probe_octaves, 0.0), dir, 0.1);
    }
#endif
#ifdef TL_FEATURE_GIANT_LIP
    else if (u_probe_mode == 10 || u_probe_mode == 11) {
        GiantLip lip = giant_lip_at(giant_coords(p).y);
        result = u_probe_mode == 10 ? vec4(lip.center, lip.radius, lip.thickness)
                                    : vec4(lip.from, lip.to, lip.progress, lip.present ? 1.0 : 0.0);
    } else if (u_probe_mode == 22) {
        vec2 sw = giant_coords(p), n2;
        GiantLip lip = giant_lip_at(sw.y);
        float angle = giant_lip_angle(lip, vec2(sw.x, input4.z));
        result.xyz = vec3(giant_lip_distance(lip, vec2(sw.x, input4.z), n2),
                          giant_lip_lump(lip, angle, lip.w), giant_lip_roughness(lip, angle));
    }
#endif
#ifdef TL_FEATURE_GIANT_SPRAY
    else if (u_probe_mode == 12) {
        float cloud;
        vec2 open;
        result.x = giant_spray_sample(vec3(p.x, input4.z, p.y), input4.w, result.y, cloud, open);
        result.zw = open;
    }
#endif
#ifdef TL_FEATURE_WAKE
    else if (u_probe_mode == 9) {
        float thickness, aerated;
        vec2 waves;
        result.x = wake_foam(p, 0.5, 0.0, thickness, aerated, waves);
        result.yz = vec2(thickness, aerated);
    }
#endif
#ifdef TL_FEATURE_FOG
    else if (u_probe_mode == 3)
        result.x = exp(-optics_fog_depth(u_cam_height, p.y, p.x));
#endif
    out_height = result;
}
