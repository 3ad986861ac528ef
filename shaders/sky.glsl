// The sky: one function that the sky pixels, the water's reflection,
// Snell's window and the fog all call, so they agree.
//
// TL_FEATURE_SKY_PHYSICAL: Rayleigh + Mie + ozone with multiple scattering
// (sky_view.frag draws the sky-view table each time the sun moves; here it
// is read), and the sun as a disc of its real size with limb darkening, its
// colour from the air along its path. Without it: the reference shader's
// "extra cheap atmosphere" and its sun lobe, exactly as they were.
// sky_color is the sky's light layer, sky_reflected the water's
// reflection and the sun's glitter (layers.glsl).
#include "layers.glsl"

#ifdef TL_FEATURE_SKY_PHYSICAL
uniform sampler2D u_sky_view;  // radiance for a sun of illuminance 1: azimuth from the sun, latitude

vec3 sky_atmosphere(vec3 dir, vec3 sun)
{
    float lat = asin(clamp(dir.y, -1.0, 1.0));
    vec2 flat_dir = dir.xz, flat_sun = sun.xz;
    float lf = length(flat_dir), ls = length(flat_sun);
    float c = lf > 1.0e-6 && ls > 1.0e-6 ? dot(flat_dir, flat_sun) / (lf * ls) : 1.0;
    float az = acos(clamp(c, -1.0, 1.0));
    // The table's latitude mapping crowds rows at the horizon (tl_sky.c).
    float l = sqrt(abs(lat) / (0.5 * TL_PI));
    vec2 uv = vec2(az / TL_PI, 0.5 + 0.5 * (lat < 0.0 ? -l : l));
    return texture(u_sky_view, uv).rgb * u_sky_scale;
}

// The disc seen in direction dir, radius widened to `cos_radius` (the same
// light spread over more sky): limb-darkened (Neckel & Labs' u = 0.6 form,
// normalised so the disc's mean radiance is light / solid angle).
vec3 sky_disc(vec3 dir, float cos_radius)
{
#ifdef TL_FEATURE_SUN_DISC
    float c = dot(dir, u_sun_dir);
    if (c < cos_radius)
        return vec3(0.0);
    float solid = 2.0 * TL_PI * (1.0 - cos_radius);
    float edge = sqrt(max(0.0, 1.0 - (1.0 - c) / (1.0 - cos_radius))); // cos at the limb point
    float limb = (1.0 - 0.6 * (1.0 - edge)) / 0.8;
    return u_sun_light / solid * limb;
#else
    return vec3(0.0);
#endif
}

vec3 sky_color(vec3 dir)
{
    return layer_emit(TL_LIGHT_SKY,
                      sky_atmosphere(dir, u_sun_dir) + sky_disc(dir, u_sun_cos_radius));
}

// The sky the water mirrors: the sun's disc widened to 1.5 deg at least, so
// its glitter on the waves is a few pixels, not single flickering ones (the
// same light, spread; a documented anti-aliasing clamp). `sunlit`: the
// share of the sun that reaches the water there (the giant wave's shadow).
vec3 sky_reflected(vec3 dir, float sunlit)
{
    return layer_emit(TL_LIGHT_REFLECTION, sky_atmosphere(dir, u_sun_dir)) +
           layer_emit(TL_LIGHT_GLITTER, sunlit * sky_disc(dir, min(u_sun_cos_radius, 0.99966)));
}

// The sun's light on a surface facing it.
vec3 sky_sun_light()
{
#ifdef TL_FEATURE_SUN_DISC
    return u_sun_light;
#else
    return vec3(0.0);
#endif
}

vec3 sky_ambient()
{
    return u_sky_ambient;
}

#else

vec3 sky_atmosphere(vec3 dir, vec3 sun)
{
    // Clamp: the reference divides by (sun.y * 11 + 1), which reaches zero
    // for a sun 5.2 deg below the horizon; hold it at -3 deg instead.
    float sun_y = max(sun.y, -0.05);
    float horizon = 1.0 / (max(dir.y, 0.0) + 0.1);
    float sun_low = 1.0 / (sun_y * 11.0 + 1.0);
    float toward_sun = pow(abs(dot(sun, dir)), 2.0);
    vec3 base = vec3(5.5, 13.0, 22.4) / 22.4;
    vec3 sun_color = mix(vec3(1.0), max(vec3(0.0), vec3(1.0) - base), sun_low);
    vec3 blue = base * sun_color;
    vec3 sky = max(vec3(0.0), blue - vec3(5.5, 13.0, 22.4) * 0.002 *
                                         (horizon - 6.0 * sun_y * sun_y));
    sky *= horizon * (0.24 + toward_sun * 0.24);
    return sky * (1.0 + pow(1.0 - max(dir.y, 0.0), 3.0)) * u_sky_brightness;
}

float sky_sun(vec3 dir)
{
#ifdef TL_FEATURE_SUN_DISC
    return pow(max(0.0, dot(dir, u_sun_dir)), u_sun_sharpness) * u_sun_intensity;
#else
    return 0.0;
#endif
}

vec3 sky_color(vec3 dir)
{
    return layer_emit(TL_LIGHT_SKY, sky_atmosphere(dir, u_sun_dir) + vec3(sky_sun(dir)));
}

vec3 sky_reflected(vec3 dir, float sunlit)
{
    return layer_emit(TL_LIGHT_REFLECTION, sky_atmosphere(dir, u_sun_dir)) +
           layer_emit(TL_LIGHT_GLITTER, vec3(sunlit * sky_sun(dir)));
}

// Irradiance on a surface facing the sun: the integral of the sun lobe
// pow(cos, sharpness)·intensity over the hemisphere.
vec3 sky_sun_light()
{
#ifdef TL_FEATURE_SUN_DISC
    return vec3(u_sun_intensity * (2.0 * TL_PI) / (u_sun_sharpness + 1.0));
#else
    return vec3(0.0);
#endif
}

// The light a white diffuse surface facing up returns (foam, the hull):
// the sky's irradiance on it over pi, from the zenith and three directions
// 15 deg up, weighted to be exact for a sky whose radiance is linear in
// the sine of the elevation (as the physical sky's mean is).
vec3 sky_ambient()
{
    return 0.55 * sky_atmosphere(vec3(0.0, 1.0, 0.0), u_sun_dir) +
           0.15 * (sky_atmosphere(vec3(0.0, 0.259, 0.966), u_sun_dir) +
                   sky_atmosphere(vec3(0.837, 0.259, -0.483), u_sun_dir) +
                   sky_atmosphere(vec3(-0.837, 0.259, -0.483), u_sun_dir));
}
#endif
