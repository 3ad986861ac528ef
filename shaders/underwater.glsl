// Seeing from under the water (TL_FEATURE_UNDERWATER): the same surface as
// from above, marched from below; Snell's window through it (the sky
// refracted, with the exact Fresnel split, total internal reflection
// beyond 48.6 deg for water); and the water body between: Beer-Lambert
// extinction and in-scattered light (water_light.glsl), down to the sea
// floor where there is one. With TL_FEATURE_WATERLINE each pixel decides
// its side from its point on the lens plane.

// Distance along an upward ray from below to the surface, or -1 (rays that
// look down never meet it). Steps by the depth under the surface, divided
// inside the giant wave's box by its slope bound, as the march from above.
float underwater_march(vec3 ray, float t)
{
    if (ray.y <= 0.0)
        return -1.0;
    float top = 0.0;
    vec2 box = vec2(TL_FAR, -1.0);
#ifdef TL_FEATURE_GIANT_WAVE
    box = giant_ray_interval(ray);
    top = u_giant_bounds.w * u_giant_shape.y;
    float ray_along = abs(dot(u_giant_frame.xy, ray.xz)), ray_flat = length(ray.xz);
#endif
    for (int i = 0; i < u_march_steps; i++) {
        vec3 pos = vec3(0.0, u_cam_height, 0.0) + ray * t;
        float below = surface_height(pos.xz, TL_MARCH_OCTAVES, 0.0) - pos.y;
        if (below < u_hit_epsilon)
            return t;
        float step = below;
#ifdef TL_FEATURE_GIANT_WAVE
        if (t >= box.x && t <= box.y)
            step /= 1.0 + ray_flat * giant_slope_near(giant_coords(pos.xz).x, below * ray_along);
#endif
        t += step;
        if (pos.y > top + 1.0)
            return t; // above every crest: the surface was met (a guard)
    }
    return t;
}

// What a ray from `origin` (camera-relative, y absolute) meets below:
// the sea floor where the scene has one (TL_FEATURE_SEA_FLOOR; its
// caustics when `direct`), else the depths; with the water between, which
// dims the floor and scatters the light it holds toward the eye. *dist: the
// distance to the floor, or TL_SKY_DEPTH.
vec3 underwater_below(vec3 origin, vec3 ray, bool direct, out float dist)
{
    float depth = max(-origin.y, 0.0);
    dist = TL_SKY_DEPTH;
#ifdef TL_FEATURE_SEA_FLOOR
    float down = origin.y + u_floor_depth; // the camera may be under the floor: none
    if (ray.y < 0.0 && down > 0.0) {
        dist = down / -ray.y;
#ifdef TL_PASS_AOV
        if (direct) // the sand, seen along the view (not in a mirrored ray)
            aov_surface(vec3(0.0, 1.0, 0.0), AOV_OCEAN);
#endif
        vec3 sand = floor_color(origin + ray * dist, ray, dist, 0.0, direct);
        return layer_emit(TL_LIGHT_BODY, sand) * optics_water_transmittance(dist) +
               water_inscatter(depth, ray, dist);
    }
#endif
    return water_inscatter(depth, ray, TL_SKY_DEPTH);
}

#ifdef TL_FEATURE_BOAT
uniform sampler2D u_boat_underside;          // the hulls below the water mirrored in the
                                             // surface's underside, alpha = covered
uniform sampler2D u_boat_underside_distance; // the mirrored path's length from the eye

// What the surface's underside mirrors at the water point `hit` (camera-
// relative x z, y absolute), `t` along the view ray: the depths seen along
// the mirrored ray `down` (`water`), or a hull's part below the water
// mirrored in the surface (the mesh pass drew it from the eye's mirror
// image), dimmed on its way from the surface with the water's light
// between; looked up where the pixel is, shifted by the slope of the
// waves at TL_MIRROR_UNDER_DETAIL's detail as the reflection from above is
// (boat_reflect), less near the hull. Without it the hull's
// upper part, hidden from an eye just under the surface by the surface's
// underside, left a band of water between the boat above the waterline
// and its keel below.
vec3 boat_underside(vec3 water, vec3 hit, vec3 down, float t)
{
    vec2 size = vec2(textureSize(u_boat_underside, 0));
    // A facet tilted by a slope turns the mirrored ray by twice that, which
    // moves the image by the path beyond the surface over the whole path:
    // where the hull meets its image at the waterline, not at all (shifted
    // whole, the image's edge along the hull was a sawtooth; judge).
    ivec2 here = ivec2(clamp(gl_FragCoord.xy, vec2(0.0), size - 1.0));
    float reach = texelFetch(u_boat_underside, here, 0).a > 0.0
                      ? max(texelFetch(u_boat_underside_distance, here, 0).r - t, 0.0)
                      : t;
    float value, slope_var;
    vec3 n = water_normal(hit.xz, u_normal_epsilon, TL_MIRROR_UNDER_DETAIL, value, slope_var);
    vec2 shift = n.xz * 0.15 * min(1.0, 2.0 * reach / max(t + reach, 1.0e-6));
    shift *= min(1.0, TL_MIRROR_SHIFT / max(length(shift), 1.0e-6));
    ivec2 at = ivec2(clamp(gl_FragCoord.xy + shift * size.y, vec2(0.0), size - 1.0));
    vec4 hull = texelFetch(u_boat_underside, at, 0);
    if (!(hull.a > 0.0))
        return water;
    float beyond = max(texelFetch(u_boat_underside_distance, at, 0).r - t, 0.0);
    vec3 seen = layer_emit(TL_LIGHT_REFLECTION, hull.rgb / hull.a) *
                    optics_water_transmittance(beyond) +
                water_inscatter(max(-hit.y, 0.0), down, beyond);
    return mix(water, seen, min(hull.a, 1.0));
}
#endif

// Radiance along a ray seen from under the water; *dist is the distance to
// the surface, or TL_SKY_DEPTH for the depths.
vec3 trace_underwater(vec3 ray, out float dist)
{
    vec3 eye = vec3(0.0, u_cam_height, 0.0);
    float t = underwater_march(ray, underwater_start(ray));
    if (t < 0.0)
        return underwater_below(eye, ray, true, dist);
#ifdef TL_FEATURE_POLISH
    t = surface_polish(ray, t);
#endif
    dist = t;
    vec3 hit = vec3(0.0, u_cam_height, 0.0) + ray * t;
    float value;
    float slope_var; // the facets finer than the normal: they spread the window
#ifdef TL_FEATURE_GIANT_WAVE
    GiantSample giant = giant_sample(hit.xz);
    vec3 n = water_ridden_normal(hit.xz, giant, t * u_lod_angle, value, slope_var);
    vec2 slope = -n.xz / n.y + giant.grad;
    n = normalize(vec3(-slope.x, 1.0, -slope.y));
#else
    vec3 n = water_normal(hit.xz, u_normal_epsilon, t * u_lod_angle, value, slope_var);
#endif
#ifdef TL_PASS_AOV
#ifdef TL_FEATURE_GIANT_WAVE
    aov_surface(-n, giant.height > TL_GIANT_MATTE_SHARE * u_giant_shape.y ? AOV_GIANT : AOV_OCEAN);
#else
    aov_surface(-n, AOV_OCEAN);
#endif
#endif
    // Light from above crosses into the water (radiance grows by n²: the
    // sky's hemisphere is squeezed into the window); what does not cross
    // comes back down from the depths. The facets finer than the normal
    // (filtered shading's slope variance, and a pixel's own least share)
    // spread the window's edge: where the mean facet reflects it all, some
    // still let the horizon's light through.
    float cos_i = max(dot(ray, n), 0.0);
    float spread = optics_facet_spread(slope_var, 2.0 * u_tan_half_vfov / u_resolution.y);
    float fresnel = optics_fresnel_rough(cos_i, u_water_ior, 1.0, spread);
    vec3 through = vec3(0.0);
    if (fresnel < 1.0) {
        vec3 out_dir = refract(ray, -n, u_water_ior);
        if (out_dir == vec3(0.0)) // past the mean facet's edge: grazing out
            out_dir = ray - dot(ray, n) * n;
        out_dir.y = max(out_dir.y, 0.0);
        through = sky_color(normalize(out_dir + vec3(0.0, 1e-4, 0.0))) * (u_water_ior * u_water_ior);
    }
    // A facet tilted past the ray mirrors it upward, into the surface
    // again, which mirrors it back down (or lets it out): taken as the
    // depths seen along the ray turned down. Left looking up, it ended at
    // once on the mean surface with no water to light it, and drew black
    // stippled lines along the waves' backs at grazing angles.
    vec3 down = reflect(ray, -n);
    down.y = -abs(down.y);
    float mirrored;
    vec3 depths = underwater_below(hit, down, false, mirrored);
#ifdef TL_FEATURE_BOAT
    depths = boat_underside(depths, hit, down, t);
#endif
    vec3 surface = (1.0 - fresnel) * through + fresnel * depths;
#if defined(TL_FEATURE_GIANT_WAVE) || defined(TL_FEATURE_WAKE)
    // Foam on the surface seen from below (the giant wave's and the
    // wake's): it hides Snell's window and glows with the daylight it lets
    // through, diffusely, about half of it through thin foam and a fifth
    // through thick; the bubbles under it scatter the same light. Without
    // this the foam vanished from below: a wake's white water was clear sky.
    float footprint = t * u_lod_angle / max(abs(dot(ray, n)), 0.2);
    float foam = 0.0, thickness = 0.0, aerated = 0.0, sunlit = 1.0;
#ifdef TL_FEATURE_GIANT_WAVE
    sunlit = giant_sunlit(hit.xz, hit.y);
    foam = giant_foam(giant, value, footprint, thickness, aerated);
#endif
#ifdef TL_FEATURE_WAKE
    float wake_thickness, wake_aerated;
    vec2 wake_waves; // the Kelvin waves' slope: not drawn from below
    float wake = wake_foam(hit.xz, value, footprint, wake_thickness, wake_aerated, wake_waves);
#ifdef TL_FEATURE_GIANT_WAVE
    float swept = wake_swept(giant);
    wake *= swept;
    wake_aerated *= swept;
#endif
    if (wake > foam) {
        foam = wake;
        thickness = wake_thickness;
    }
    aerated = max(aerated, wake_aerated);
#endif
#ifdef TL_PASS_AOV
    aov_foam(foam);
#endif
    vec3 foam_light = (0.5 - 0.3 * thickness) * foam_daylight(sunlit);
    surface = mix(surface, layer_emit(TL_LIGHT_FOAM, foam_light), foam) +
              foam_bubbles(aerated, u_scatter_color, sunlit);
#endif
    return surface * optics_water_transmittance(t) + water_inscatter(max(-u_cam_height, 0.0), ray, t);
}
