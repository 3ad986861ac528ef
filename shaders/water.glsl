// Water shading: normal from the many-octave height field, distance
// smoothing, Schlick Fresnel reflection of the sky, depth scattering; with
// the giant wave, its slope, light through its crest and its foam; with the
// boat, its wake.

// Ocean normal at p, exact (analytic normals) or by finite differences;
// *value is the ocean's wave value in (0, 1] at p (1 on the crests);
// *slope_var the variance per axis of the slope level of detail left out
// (waves_faded_slope_variance), for filtered shading.
vec3 water_normal(vec2 p, float e, float footprint, out float value, out float slope_var)
{
#ifdef TL_FEATURE_ANALYTIC_NORMALS
    vec2 grad;
    value = waves_value_grad(p, TL_NORMAL_OCTAVES, footprint, grad, slope_var);
    return normalize(vec3(-grad.x * u_depth, 1.0, -grad.y * u_depth));
#else
    slope_var = waves_faded_slope_variance(TL_NORMAL_OCTAVES, footprint);
    // Far out (grazing rays meet the water 1e4 m and more away) a fixed
    // step is a few float ulps of p: the difference is rounding noise and
    // the slope it gives can mirror the sun anywhere along the horizon.
    // Keep the step at least ~80 ulps of the coordinate (1e-5 relative);
    // that only matters beyond 1 km, where the normal is smoothed anyway.
    e = max(e, 1e-5 * max(abs(p.x), abs(p.y)));
    // With level of detail the step follows the pixel's footprint: the
    // surface has no detail finer than that left to difference.
    e = max(e, 0.5 * footprint);
    // The offsets the float coordinates really moved by, not e.
    vec2 px = p - vec2(e, 0.0), pz = p + vec2(0.0, e);
    value = waves_value(p, TL_NORMAL_OCTAVES, footprint);
    float h = value * u_depth;
    float hx = waves_value(px, TL_NORMAL_OCTAVES, footprint) * u_depth;
    float hz = waves_value(pz, TL_NORMAL_OCTAVES, footprint) * u_depth;
    vec3 a = vec3(p.x, h, p.y);
    return normalize(cross(a - vec3(px.x, hx, p.y), a - vec3(p.x, hz, pz.y)));
#endif
}

#ifdef TL_FEATURE_GIANT_WAVE
// The small waves' normal at p under the giant wave (its sample g there):
// taken where they ride from, finer by the squeeze, carried back to p
// (giant_ride).
vec3 water_ridden_normal(vec2 p, GiantSample g, float footprint, out float value,
                         out float slope_var)
{
    return giant_ride_normal(water_normal(giant_ride(p, g), u_normal_epsilon,
                                          footprint * giant_ride_squeeze(g), value, slope_var),
                             g);
}
#endif

// A shading normal the ray meets from behind, turned until it faces the
// ray (quality.facing_normals; off for `seed`, whose shader reflects it as
// it is). The normal has finer octaves than the surface the march met, so
// it can face away where the view grazes: at the far sea and at the top of
// a silhouette, where the march lands a hair past a crest. Reflected as it
// is, the ray turned steeply up into the dark zenith (blue dashes along the
// giant wave's lip, voyage 180); turned, it grazes the facet and mirrors
// the sky near the horizon, as the facets the eye does see there would.
vec3 water_facing(vec3 ray, vec3 n)
{
    float behind = dot(n, ray);
    return u_facing_normals && behind > -1.0e-3 ? normalize(n - (behind + 1.0e-3) * ray) : n;
}

// The sky the water mirrors, times Fresnel, averaged over the normals of a
// pixel: the mean normal n and, with filtered shading, the slopes the
// octaves level of detail faded would have added (variance slope_var per
// axis). Three normals whose slopes sit on a circle of radius
// sqrt(2·slope_var) around n's match that spread's mean and variance.
// *fresnel gets the mean Fresnel factor; the result is the reflection it
// weights. `sunlit`: the share of the sun that reaches the water there.
vec3 water_sky_reflection(vec3 ray, vec3 n, float slope_var, float sunlit, vec3 hit,
                          out float fresnel)
{
#ifdef TL_FEATURE_FILTERED_SHADING
    float radius = sqrt(2.0 * slope_var);
    vec2 slope = -n.xz / n.y;
    vec3 sum = vec3(0.0);
    float fresnel_sum = 0.0;
    for (int k = 0; k < 3; k++) {
        vec2 offset = radius * (k == 0 ? vec2(1.0, 0.0)
                                : k == 1 ? vec2(-0.5, 0.8660254)
                                         : vec2(-0.5, -0.8660254));
        vec3 nk = water_facing(
            ray, normalize(vec3(-(slope.x + offset.x), 1.0, -(slope.y + offset.y))));
        float fk = optics_schlick(ray, nk);
        vec3 r = normalize(reflect(ray, nk));
        r.y = abs(r.y); // reflections never look into the water
        vec3 seen = sky_reflected(r, sunlit);
#ifdef TL_FEATURE_BOAT
        seen += lamps_mirrored(hit, r);
#endif
        sum += fk * seen;
        fresnel_sum += fk;
    }
    fresnel = fresnel_sum / 3.0;
    return sum / max(fresnel_sum, 1e-6);
#else
    fresnel = optics_schlick(ray, n);
    vec3 r = normalize(reflect(ray, n));
    r.y = abs(r.y); // reflections never look into the water
    vec3 seen = sky_reflected(r, sunlit);
#ifdef TL_FEATURE_BOAT
    seen += lamps_mirrored(hit, r);
#endif
    return seen;
#endif
}

vec3 water_color(vec3 ray, vec3 hit, float dist)
{
    float value, slope_var;
#ifdef TL_FEATURE_GIANT_WAVE
    GiantSample giant = giant_sample(hit.xz);
    vec3 n = water_ridden_normal(hit.xz, giant, dist * u_lod_angle, value, slope_var);
#else
    vec3 n = water_normal(hit.xz, u_normal_epsilon, dist * u_lod_angle, value, slope_var);
#endif
    // Far away the normal's detail is below a pixel; blending toward "up"
    // removes the shimmer the reference also suppresses this way.
    float smoothing = optics_normal_blend(dist);
#ifdef TL_FEATURE_GIANT_WAVE
    smoothing = giant_face_blend(giant, smoothing);
#endif
    // The reference shader leaves the blend unnormalised (a shorter normal
    // darkens the Fresnel term a little); `seed` keeps that.
    n = mix(n, vec3(0.0, 1.0, 0.0), smoothing);
    if (u_normalize_smoothed)
        n = normalize(n);
    // The blend flattens the left-out slopes as it flattens the normal.
    slope_var *= (1.0 - smoothing) * (1.0 - smoothing);
    float ocean_y = hit.y; // height of the ocean's own waves at the hit
    float sunlit = 1.0;    // the share of the sun that reaches the hit
#ifdef TL_FEATURE_GIANT_WAVE
    sunlit = giant_sunlit(hit.xz, hit.y);
    // The giant wave is large against a pixel: its slope is added unsmoothed
    // (slopes of summed height fields add), the small waves' steepened as
    // they ride up toward its crest, and with them the slopes the level of
    // detail left out (without, `final` lost the steepened detail that
    // `reference` resolves, and filtered shading took it further away).
    float short_gain = giant_short_wave_gain(giant);
    slope_var *= short_gain * short_gain;
    vec2 slope = -n.xz / n.y * short_gain + giant.grad;
    n = giant_facet_seen(normalize(vec3(-slope.x, 1.0, -slope.y)), ray, giant);
    ocean_y -= giant.height;
#endif
#ifdef TL_FEATURE_WAKE
    // The wake: its foam (shaded below) and the Kelvin waves' slope,
    // added like the giant wave's. The footprint is the unperturbed
    // normal's.
    float thickness, aerated;
    vec2 wake_waves;
    float wake = wake_foam(hit.xz, value, dist * u_lod_angle / max(abs(dot(ray, n)), 0.2),
                           thickness, aerated, wake_waves);
#ifdef TL_FEATURE_GIANT_WAVE
    float swept = wake_swept(giant); // the giant wave sweeps the wake away
    wake *= swept;
    aerated *= swept;
    wake_waves *= swept;
#endif
    vec2 wave_slope = -n.xz / n.y + wake_waves;
    n = normalize(vec3(-wave_slope.x, 1.0, -wave_slope.y));
#endif
    // The share of the sun in the light the water scatters back up: that
    // light entered over metres around and under the point, so a shadow
    // as small as a boat's takes only part of it.
    float scatter_sunlit = sunlit;
#ifdef TL_FEATURE_BOAT_SHADOW
    // The boat's shadow on the water: its glitter and foam lose the sun
    // there, its scattered light half of it (TL_BOAT_SHADOW_SCATTER).
    float boat_lit = boat_shadow(vec3(hit.x, hit.y - u_cam_height, hit.z));
    sunlit *= boat_lit;
    scatter_sunlit *= mix(1.0, boat_lit, TL_BOAT_SHADOW_SCATTER);
#endif
    n = water_facing(ray, n);
#ifdef TL_PASS_AOV
#ifdef TL_FEATURE_GIANT_WAVE
    aov_surface(n, giant.height > TL_GIANT_MATTE_SHARE * u_giant_shape.y ? AOV_GIANT : AOV_OCEAN);
#else
    aov_surface(n, AOV_OCEAN);
#endif
#endif

    float fresnel;
    vec3 reflection = water_sky_reflection(ray, n, slope_var, sunlit, hit, fresnel);
    // The share of the mirrored sky the giant wave leaves in view: in front
    // of it a ray mirrored toward it meets its face, not the bright sky near
    // a sun low behind it (the trough ahead of a backlit wave shone with a
    // pale sheen band, judges). The edge is as soft as the mirrored rays of
    // the pixel's normals spread (TL_GIANT_MIRROR_SPREAD of the slopes'
    // deviation, at least TL_GIANT_MIRROR_SPREAD_MIN radians): the mean
    // normal's alone drew a hard, speckled edge.
    float sky_seen = 1.0;
#if defined(TL_FEATURE_GIANT_WAVE) || defined(TL_GIANT_MIRROR)
    sky_seen = giant_clear(hit.xz, hit.y, normalize(reflect(ray, n)),
                           TL_GIANT_MIRROR_SPREAD * sqrt(2.0 * slope_var) +
                               TL_GIANT_MIRROR_SPREAD_MIN);
#endif
#ifdef TL_FEATURE_FOG
    // The sky the water mirrors is seen through the fog above it too.
    vec3 r = normalize(reflect(ray, n));
    r.y = abs(r.y);
    reflection = optics_fog(reflection, max(hit.y, 0.0), r, TL_SKY_DEPTH, TL_LIGHT_REFLECTION);
#endif
#ifdef TL_BOAT_MIRROR
    reflection = boat_reflect(reflection, n, hit);
#endif
    // Thicker water in the troughs scatters more blue-green light. Clamp:
    // the depth fraction is held in [0, 1], so a march that stopped off the
    // surface (out of steps, or a camera under the water) cannot make the
    // term negative.
    vec3 scattering = u_scatter_color * u_scatter_strength *
                      (u_scatter_base + clamp((ocean_y + u_depth) / u_depth, 0.0, 1.0));
#ifdef TL_FEATURE_SKY_PHYSICAL
    // Light scattered out of the water is light that went in: scale by the
    // irradiance on the surface (sun + sky), about 1 for the default sun at
    // 10 deg (its luminance there is 0.94) so the water keeps the seed's
    // look there, dark in the blue hour.
    scattering *=
        (sky_sun_light() * scatter_sunlit * max(u_sun_dir.y, 0.0) + TL_PI * sky_ambient()) / 0.94;
#endif
#ifdef TL_FEATURE_SEA_FLOOR
    // Over a floor the water column is finite: it sends up only the share
    // of the deep sea's light its depth holds (down and back up), and the
    // sand seen through it stands for the rest.
    scattering *= 1.0 - exp(-2.0 * u_water_fall * max(hit.y + u_floor_depth, 0.0));
#endif
    // Where the wave hides the sky the water mirrors its face: water that
    // scatters light as this water does, and mirrors the sky at a face's
    // Fresnel factor (TL_GIANT_FACE_FRESNEL; seen from the sea in front,
    // the face is met about half-way to grazing).
    vec3 face = layer_emit(TL_LIGHT_REFLECTION, scattering) + TL_GIANT_FACE_FRESNEL * reflection;
    vec3 color = fresnel * mix(face, reflection, sky_seen) + layer_emit(TL_LIGHT_BODY, scattering);
#ifdef TL_FEATURE_SEA_FLOOR
    color += (1.0 - fresnel) *
             layer_emit(TL_LIGHT_BODY, floor_through_surface(ray, n, hit, dist, slope_var));
#endif
    // The water a pixel covers (0 without level of detail), more as the
    // view grazes the surface: foam's detail and veins stay a pixel wide.
    float footprint = dist * u_lod_angle / max(abs(dot(ray, n)), 0.2);
#ifdef TL_FEATURE_WAKE
    color += foam_aerated(ray, n, aerated, u_scatter_color, sunlit);
    color = foam_shade(color, n, wake, thickness, sunlit);
#endif
#ifdef TL_FEATURE_BOAT
    float contact_thickness;
    float contact =
        boat_contact_foam(hit, -n.xz / max(n.y, 0.1), value, footprint, contact_thickness);
    color = foam_shade(color, n, contact, contact_thickness, sunlit);
#endif
#ifdef TL_FEATURE_GIANT_WAVE
    // After the boat's foam: the light through the crest passes through it
    // as through the wave's own (under a hull riding a backlit face, the
    // contact foam lit by the sky alone was a lavender stain on the glow).
    color = giant_shade(color, hit, ray, n, giant, value, footprint, sunlit);
#endif
    return color;
}
