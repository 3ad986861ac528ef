// Sky: the reference's "extra cheap atmosphere" plus the sun disc lobe.

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
    return sky_atmosphere(dir, u_sun_dir) + vec3(sky_sun(dir));
}

// Irradiance on a surface facing the sun: the integral of the sun lobe
// pow(cos, sharpness)·intensity over the hemisphere.
float sky_sun_irradiance()
{
#ifdef TL_FEATURE_SUN_DISC
    return u_sun_intensity * 6.2831853 / (u_sun_sharpness + 1.0);
#else
    return 0.0;
#endif
}

// Mean sky radiance over the upper hemisphere, for diffuse surfaces (foam,
// the hull): the zenith and three directions 15 deg up.
vec3 sky_ambient()
{
    return 0.25 * (sky_atmosphere(vec3(0.0, 1.0, 0.0), u_sun_dir) +
                   sky_atmosphere(vec3(0.0, 0.259, 0.966), u_sun_dir) +
                   sky_atmosphere(vec3(0.837, 0.259, -0.483), u_sun_dir) +
                   sky_atmosphere(vec3(-0.837, 0.259, -0.483), u_sun_dir));
}
