// The light in the water body (TL_FEATURE_UNDERWATER): the sun's beam and
// the sky's light from above, each dimmed by Beer-Lambert on its way down
// (so the sea darkens and blues with depth), and what the water scatters
// toward the eye along a ray. tl_optics_water_inscatter (src/optics) is
// the same in double; test_underwater probes the two (mode 20). Needs
// sky.glsl.

// Pale wet sand's reflectance (linear: a bay's shell and coral sand).
const vec3 TL_FLOOR_SAND = vec3(0.62, 0.58, 0.48);

// The share of a collision that scatters rather than absorbs (grey).
vec3 water_albedo()
{
    return min(vec3(u_water_scattering) / u_water_sigma, vec3(1.0));
}

// The sun's irradiance across its beam `depth` metres under the mean
// surface: what crossed a flat surface, dimmed along its slant path by
// u_water_fall (the light the water scatters forward stays in the beam:
// tl_optics_water_fall).
vec3 water_sun_at(float depth)
{
    return sky_sun_light() * u_sun_water_trans *
           exp(-u_water_fall * (max(depth, 0.0) / max(-u_sun_water.y, TL_WATER_MIN_SUN_DOWN)));
}

// The sky's light from above at that depth, as the radiance of an even
// sky: the diffuse light taken straight down (its mean cosine 1).
vec3 water_sky_at(float depth)
{
    return sky_ambient() * exp(-u_water_fall * max(depth, 0.0));
}

// The sun's share in the even light from above at that depth: what the
// water has scattered on the way down. Near the surface the sun is all
// beam (its caustics sharp on what it lights), deeper it turns diffuse.
float water_sun_diffuse(float depth)
{
    float sun_down = max(-u_sun_water.y, TL_WATER_MIN_SUN_DOWN);
    return 1.0 - exp(-u_water_scattering * max(depth, 0.0) / sun_down);
}

#ifdef TL_FEATURE_SEA_FLOOR
// The light the sand sends up, as radiance, `depth` metres under the mean
// surface, seen looking down along a direction whose y is `down_y` (< 0;
// -1 straight down): the floor's mean (its caustics average out), the sun
// and the sky on it by the sand's reflectance, dimmed along the slant way
// up. Toward the horizon the sand lies far off and fades out.
vec3 water_floor_up(float depth, float down_y)
{
    float floor_depth = u_floor_depth, sun_down = max(-u_sun_water.y, TL_WATER_MIN_SUN_DOWN);
    vec3 sand = TL_FLOOR_SAND * (water_sun_at(floor_depth) * sun_down / TL_PI + water_sky_at(floor_depth));
    // Clamp: a way within a tenth of level is taken at a tenth (the
    // sand there is faded out anyway).
    float way = max(floor_depth - max(depth, 0.0), 0.0) / max(-down_y, TL_WATER_MIN_SUN_DOWN);
    return sand * exp(-u_water_fall * way);
}
#endif

// The water's phase function toward the eye: Henyey-Greenstein, g = 0.75
// (the strong forward lobe of ocean particles).
float water_phase(float mu)
{
    const float g = TL_WATER_PHASE_G;
    return (1.0 - g * g) / (4.0 * TL_PI * pow(1.0 + g * g - 2.0 * g * mu, 1.5));
}

// The integral over [0, t] of exp(-c s) ds, per channel: (1 - e^-ct) / c,
// t where c t is small (looking up as steeply as the light comes down).
vec3 water_path_integral(vec3 c, float t)
{
    vec3 ct = min(c * t, vec3(TL_WATER_MAX_OPTICAL));
    vec3 exact = (1.0 - exp(-ct)) / max(abs(c), vec3(1e-12)) * sign(c);
    vec3 series = t * (1.0 - 0.5 * ct);
    return mix(exact, series, lessThan(abs(ct), vec3(1e-3)));
}

// The light scattered toward the eye along a ray (unit, from the eye)
// starting `depth` metres under the mean surface, over its first t metres
// (TL_SKY_DEPTH or more for the depths): single scattering of the sun's
// beam (phase function) and of the sky's light (evenly), each at the depth
// the ray has reached, and dimmed on the way back to the eye.
vec3 water_inscatter(float depth, vec3 ray, float t)
{
    vec3 sigma = u_water_sigma;
    float sun_down = max(-u_sun_water.y, TL_WATER_MIN_SUN_DOWN);
    // A ray looking up leaves the water by the mean surface: the light
    // grows toward it, and past it there is no water to scatter.
    if (ray.y > 0.0)
        t = min(t, max(depth, 0.0) / ray.y);
    // The light it meets changes by exp(fall rise / cos) as the ray climbs
    // rise = ray.y s, and what it scatters is dimmed by exp(-sigma s).
    vec3 fall = u_water_fall;
    vec3 sun = u_water_scattering * water_phase(dot(u_sun_water, -ray)) * water_sun_at(depth) *
               water_path_integral(sigma - fall * (ray.y / sun_down), t);
    vec3 sky = u_water_scattering * TL_WATER_SKY_SCATTER * water_sky_at(depth) *
               water_path_integral(sigma - fall * ray.y, t);
    return layer_emit(TL_LIGHT_BODY, sun + sky);
}
