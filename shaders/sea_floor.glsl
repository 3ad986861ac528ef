// The sea floor (TL_FEATURE_SEA_FLOOR): a plane of sand u_floor_depth
// metres under the mean surface, with a procedural relief (low dunes and
// the ripples the waves comb into it) and a mottled colour, lit by the
// sun's beam (through the caustics, with TL_FEATURE_CAUSTICS) and the
// sky's light as they reach its depth. Needs foam.glsl (its hash) and
// water_light.glsl.

// The wavelength of the sand's ripples (its reflectance, TL_FLOOR_SAND, is
// in water_light.glsl: the hulls above take its light too).
const float TL_FLOOR_RIPPLE = 0.3;

// Value noise with cells of `cell` metres that repeats every
// TL_FLOOR_PERIOD metres (each cell size divides it), at world p wrapped
// by the same period.
float floor_noise(vec2 p, float cell)
{
    vec2 q = p / cell;
    vec2 i = floor(q), f = q - i;
    f = f * f * (3.0 - 2.0 * f);
    int n = int(float(TL_FLOOR_PERIOD) / cell);
    ivec2 c = ((ivec2(i) % n) + n) % n;
    ivec2 c1 = (c + 1) % n;
    float a = foam_hash(c), b = foam_hash(ivec2(c1.x, c.y));
    float d = foam_hash(ivec2(c.x, c1.y)), e = foam_hash(c1);
    return mix(mix(a, b, f.x), mix(d, e, f.x), f.y);
}

// The sand's height (metres) at world p, its ripples faded where a pixel
// covers `footprint` metres (they would only alias).
float floor_relief(vec2 p, float footprint)
{
    float dunes = 0.25 * floor_noise(p, 8.0) + 0.08 * floor_noise(p + 3.7, 2.0);
    // Ripples across the swell's way, their crests bent, forked and
    // broken by noise, everywhere (the shallow sea's swell combs all of
    // the sand) but higher in patches: their light and shade are what
    // breaks a caustic web up on sand, and what tells a sea floor from a
    // pool's; at 2 cm in patches alone they did not read.
    float bend = 0.6 * floor_noise(p, 2.0) + 0.3 * floor_noise(p, 0.5);
    float phase = 2.0 * TL_PI * (p.y + 0.3 * p.x) / TL_FLOOR_RIPPLE + 9.0 * bend;
    float ripples = 0.03 * (0.5 + 0.5 * smoothstep(0.2, 0.7, floor_noise(p + 11.0, 1.0))) *
                    (sin(phase) + 0.3 * sin(2.0 * phase));
    float resolved = 1.0 - smoothstep(0.15, 0.5, footprint / TL_FLOOR_RIPPLE);
    return dunes + ripples * resolved;
}

// The sand's radiance at camera-relative p seen along `ray` from `dist`
// metres, blurred over `blur` metres more than a pixel's footprint there;
// `lit_by_caustics`: false where the floor is only seen mirrored
// in the surface (its caustics would cost more than they show there).
vec3 floor_color(vec3 p, vec3 ray, float dist, float blur, bool lit_by_caustics)
{
    vec2 world = p.xz + u_floor_offset;
    float footprint = dist * 2.0 * u_tan_half_vfov / u_resolution.y + blur;
    float e = max(footprint, 0.01);
    float h = floor_relief(world, footprint);
    vec2 slope = vec2(floor_relief(world + vec2(e, 0.0), footprint) - h,
                      floor_relief(world + vec2(0.0, e), footprint) - h) /
                 e;
    vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
    // Pale sand, mottled, with darker patches of weed and shell.
    float mottle = floor_noise(world, 0.5) * 0.6 + floor_noise(world, 0.125) * 0.4;
    float patches = smoothstep(0.62, 0.8, floor_noise(world + 40.0, 6.0));
    vec3 albedo = TL_FLOOR_SAND * (0.75 + 0.5 * mottle) * (1.0 - 0.55 * patches);
    float depth = u_floor_depth;
    float sun = max(dot(n, -u_sun_water), 0.0);
#ifdef TL_FEATURE_CAUSTICS
    if (lit_by_caustics)
        sun *= caustic_light(p.xz, depth, footprint);
#endif
#ifdef TL_FEATURE_BOAT_SHADOW
    // The floating objects' shadows on the sand: the share of the beam the
    // water has not yet scattered on its way down is cut out, caustics and
    // all; what it has scattered comes in from around the shadow and still
    // lights the sand (in a bay's water a shadow 7 m down keeps about half
    // of the sun: black, it read as an oil slick from above; judge).
    if (lit_by_caustics) {
        float unscattered = exp(-u_water_scattering * depth / max(-u_sun_water.y, TL_CAUSTIC_MIN_DOWN));
        sun *= 1.0 - unscattered * (1.0 - boat_shadow_below(vec3(p.x, p.y - u_cam_height, p.z), depth));
    }
#endif
    vec3 light = water_sun_at(depth) * sun / TL_PI + water_sky_at(depth) * (0.5 + 0.5 * n.y);
    return albedo * light;
}

// The sand seen from above through the surface at `hit` (normal n) along
// `ray`, `dist` metres from the eye: the view refracted down to it, dimmed
// by the water on the way up, its radiance divided by n² as it leaves
// the water (the window's squeeze undone). Dimmed by the downwelling
// light's fall, not the whole extinction: what the water scatters forward
// off the view comes from the sand around, as bright on average (the
// image blurs, which the facets' spread stands for; no in-scatter is
// added from above, the water's colour stands for the column). The facets finer than the
// normal (their slope variance) scatter a pixel's view over the sand,
// more the deeper it lies: that blurs it as the footprint.
vec3 floor_through_surface(vec3 ray, vec3 n, vec3 hit, float dist, float slope_var)
{
    vec3 down = refract(ray, n, 1.0 / u_water_ior);
    float depth = hit.y + u_floor_depth;
    if (down.y >= 0.0 || depth <= 0.0)
        return vec3(0.0);
    float t = depth / -down.y;
    float spread = optics_facet_spread(slope_var, 2.0 * u_tan_half_vfov / u_resolution.y);
    vec3 sand = floor_color(hit + down * t, down, dist + t, t * spread * (1.0 - 1.0 / u_water_ior), true);
    return sand * exp(-u_water_fall * t) / (u_water_ior * u_water_ior);
}
