// Optics of the water and the air (src/optics/tl_optics.c holds the same
// formulas in double): the exact Fresnel reflectance, the water body's
// transmittance, the fog's optical depth.

// Schlick's reflectance (water.fresnel_f0) of the water's surface with
// normal n, seen from the air along `ray`: the seed shader's term, which
// the water above the surface keeps (shader only, no CPU mirror).
float optics_schlick(vec3 ray, vec3 n)
{
    return u_fresnel_f0 + (1.0 - u_fresnel_f0) * pow(1.0 - max(0.0, dot(-n, ray)), 5.0);
}

// Reflectance of unpolarised light arriving in index n1 at cos_i, leaving
// into n2: (r_s² + r_p²) / 2; 1 under total internal reflection. Schlick's
// approximation with the water-side cosine is far off near the edge of
// Snell's window (0.024 instead of 0.43 at 48 deg), so the exact form.
float optics_fresnel(float cos_i, float n1, float n2)
{
    cos_i = min(abs(cos_i), 1.0);
    float sin_t = n1 / n2 * sqrt(max(0.0, 1.0 - cos_i * cos_i));
    if (sin_t >= 1.0)
        return 1.0;
    float cos_t = sqrt(1.0 - sin_t * sin_t);
    float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    float rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// The share of a standard normal distribution below a: the normal CDF,
// by Abramowitz and Stegun's 7.1.26 for erf (error under 1.5e-7; the CPU
// mirror takes libm's erfc).
float optics_normal_cdf(float a)
{
    float x = abs(a) * 0.70710678;
    float t = 1.0 / (1.0 + 0.3275911 * x);
    float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    float half_erfc = 0.5 * poly * exp(-x * x);
    return a >= 0.0 ? 1.0 - half_erfc : half_erfc;
}

// optics_fresnel averaged over a rough surface: facets whose tilt in the
// plane of incidence spreads by `spread` radians (standard deviation)
// about the mean normal's. From the water side (n1 > n2) it softens the
// edge of Snell's window, where the reflectance leaps to 1: the facets
// past the critical angle reflect all, the rest as at their mean tilt.
// From the air, three-point Gauss-Hermite quadrature (tl_optics.h says why).
float optics_fresnel_rough(float cos_i, float n1, float n2, float spread)
{
    float theta = acos(min(abs(cos_i), 1.0));
    if (n1 > n2 && spread > 0.0) {
        float critical = asin(n2 / n1), a = (critical - theta) / spread;
        float inside = optics_normal_cdf(a);
        float density = exp(-0.5 * a * a) * 0.39894228;
        float mean = theta - spread * density / max(inside, TL_FRESNEL_LEAST_SHARE);
        mean = min(abs(mean), critical);
        return 1.0 - inside + inside * optics_fresnel(cos(mean), n1, n2);
    }
    float d = TL_FRESNEL_TAP * spread;
    return (2.0 / 3.0) * optics_fresnel(cos_i, n1, n2) +
           (1.0 / 6.0) * (optics_fresnel(cos(min(theta + d, 0.5 * TL_PI)), n1, n2) +
                          optics_fresnel(cos(abs(theta - d)), n1, n2));
}

// A lamp's glint in a mirror: how much of its radiance a mirrored ray at
// cos `cos_to` from its centre sees, for a lamp of angular radius `size`:
// a Gaussian disc widened to at least TL_LAMP_GLINT_MIN radians, its
// radiance scaled down to keep its light (a facet's glint of a lamp a few
// centimetres wide is far under a pixel and would flicker frame to frame;
// the ripples' normals spread the glints into the column a lamp draws on a
// choppy sea) (tl_optics_lamp_glint).
float optics_lamp_glint(float cos_to, float size)
{
    float spread = max(size, TL_LAMP_GLINT_MIN);
    float angle2 = 2.0 * max(1.0 - cos_to, 0.0); // its angle squared, near the centre
    return (size * size) / (spread * spread) * exp(-angle2 / (spread * spread));
}

// The share of the light through Snell's window (a cone of half-angle
// asin(1 / ior) about the zenith, seen from under the water) that falls on
// a face whose normal's y is ny, against one facing straight up: cos of the
// tilt while the whole cone is in view, none once the face has turned
// past its edge, and between, ((ny + s) / (1 + s))^2 with s = 1 / ior (the
// spherical cap's irradiance, as sphere lights' horizon is handled; it
// meets cos tilt where the cone starts to set, within 0.02). A hull's
// faces turned down see little of the bright window, its sides more
// (tl_optics_window_share).
float optics_window_share(float ny, float ior)
{
    float s = 1.0 / ior;
    if (ny >= s)
        return ny;
    float t = max(ny + s, 0.0) / (1.0 + s);
    return t * t;
}

// The spread of the facets a view through the surface meets: the slope
// variance the normal leaves out, the capillary ripples finer than every
// octave (water.capillaries: without them a choppy sea's window broke
// into hard-edged shards and scraps), and at least a share of `pixel`
// (the angle a pixel spans, radians).
float optics_facet_spread(float slope_var, float pixel)
{
    float least = TL_WINDOW_PIXEL_SPREAD * pixel;
    return sqrt(slope_var + u_capillary_slope_var + least * least);
}

#if defined(TL_FEATURE_UNDERWATER) || defined(TL_FEATURE_SEA_FLOOR)
// Beer-Lambert: the share of light left after `dist` metres of water.
vec3 optics_water_transmittance(float dist)
{
    return exp(-u_water_sigma * dist);
}
#endif

#ifdef TL_FEATURE_FOG
// Optical depth along `dist` metres of a ray from height y0 with vertical
// component ray_y, through fog of density u_fog.x·exp(-y / u_fog.y).
float optics_fog_depth(float y0, float ray_y, float dist)
{
    float at_start = u_fog.x * exp(-max(y0, 0.0) / u_fog.y);
    float rise = ray_y * dist / u_fog.y;
    if (abs(rise) < 1.0e-4)
        return at_start * dist;
    // Clamp: beyond e^80 the fog is opaque anyway.
    return at_start * dist * (1.0 - exp(-clamp(rise, -80.0, 80.0))) / rise;
}
#endif

#ifdef TL_FEATURE_FOG
// Fog over `color` seen `dist` metres along `ray` from height y0
// (TL_SKY_DEPTH: the sky): extinction T = exp(-depth) and in-scatter toward
// the fog's colour, brighter toward the sun while it is up.
vec3 optics_fog(vec3 color, float y0, vec3 ray, float dist, int layer)
{
    float depth = optics_fog_depth(y0, ray.y, min(dist, 1.0e7));
    float t = exp(-depth);
    float toward_sun = pow(max(dot(ray, u_sun_dir), 0.0), 8.0);
#ifdef TL_FEATURE_SKY_PHYSICAL
    // The haze is lit by the same sky and sun: fog.color tints their light
    // (a grey fog of albedo 1 scatters the sun's light with a lobe toward
    // it), so it darkens as the sun sets. Haze scatters mostly forward:
    // three quarters of the sky's light it sends on comes from the sky just
    // behind it along the ray (the horizon, for a ray that meets the water;
    // after sunset, the glow where the sun went down), a quarter from the
    // hemisphere's mean. Lit by the mean alone it hid that glow behind a
    // dark band (docs/rendering.md, "Fog").
    vec3 behind_dir = normalize(vec3(ray.x, max(ray.y, 0.0) + 1.0e-6, ray.z));
    vec3 behind = sky_atmosphere(behind_dir, u_sun_dir);
    vec3 haze = u_fog_color * (0.25 * sky_ambient() + 0.75 * behind +
                               sky_sun_light() * (0.05 + 0.5 * toward_sun));
#else
    vec3 haze = u_fog_color * (1.0 + 1.5 * toward_sun * smoothstep(-0.05, 0.1, u_sun_dir.y));
#endif
    return color * t + layer_emit(layer, haze * (1.0 - t));
}
#endif

// How far the water's normal is blended toward up `dist` metres from the
// eye (tl_optics_normal_blend): the detail a far, grazing view of a level
// sea averages away.
float optics_normal_blend(float dist)
{
    return u_normal_smooth_max * min(1.0, sqrt(dist * u_normal_smooth_rate) * u_normal_smooth_gain);
}
