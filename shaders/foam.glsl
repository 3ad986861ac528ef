// Foam: its shading (its texture is foam_noise.glsl). Shared by the giant
// wave and the boat's wake.

#include "foam_noise.glsl"

// The daylight on the sea (radiance of a white surface facing up, lit by
// the sky and by the share `sunlit` of the sun), which foam and bubbles
// scatter.
vec3 foam_daylight(float sunlit)
{
    return sky_ambient() + sky_sun_light() * sunlit * max(u_sun_dir.y, 0.0) / TL_PI;
}

// Water full of bubbles under foam scatters light: a milky layer tinted by
// the water's colour `hue` (its scale does not matter), lit as the water's
// own scattering is, by what enters the sea around. As seen from below.
vec3 foam_bubbles(float aerated, vec3 hue, float sunlit)
{
    vec3 tint = hue / max(max(hue.r, 1.0e-6), max(hue.g, hue.b));
    return layer_emit(TL_LIGHT_FOAM, 0.4 * aerated * tint * foam_daylight(sunlit));
}

// The same seen from above, less what the surface reflects. Added to the
// water's colour before the foam.
vec3 foam_aerated(vec3 ray, vec3 n, float aerated, vec3 hue, float sunlit)
{
    return (1.0 - optics_schlick(ray, n)) * foam_bubbles(aerated, hue, sunlit);
}

// Foam over the water's colour: a white diffuse layer lit by the sky's
// hemisphere and the sun, with a wrapped term for light through the foam.
// Thin foam (thickness near 0) is half transparent and greyer: opaque
// everywhere, a close wake read as flat paint.
// `sunlit`: the share of the sun that reaches it (0 in the giant wave's
// shadow, where the wrapped term lit foam on a dark face); `sky`: the
// share of the sky's light (foam_shade: 1; less in a lump's hollows and
// on its underside).
vec3 foam_shade_sky(vec3 color, vec3 n, float foam, float thickness, float sunlit, float sky)
{
    vec3 sun = sky_sun_light() * sunlit * (0.3 + 0.7 * max(dot(n, u_sun_dir), 0.0)) / TL_PI;
    float albedo = 0.85 * (0.55 + 0.45 * thickness);
#ifdef TL_PASS_AOV
    aov_foam(foam);
#endif
    return mix(color, layer_emit(TL_LIGHT_FOAM, albedo * (sky * sky_ambient() + sun)),
               foam * (0.5 + 0.5 * thickness));
}

vec3 foam_shade(vec3 color, vec3 n, float foam, float thickness, float sunlit)
{
    return foam_shade_sky(color, n, foam, thickness, sunlit, 1.0);
}
