// Foam: value noise for its texture, and its shading. Shared by the giant
// wave and the boat's wake.

// Smooth value noise in [0, 1] from an integer hash (the same on every
// GPU, unlike sin-based hashes).
float foam_hash(ivec2 c)
{
    uint h = uint(c.x) * 0x8da6b343u ^ uint(c.y) * 0xd8163841u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    return float(h & 0xffffu) / 65535.0;
}

float foam_noise(vec2 p)
{
    vec2 i = floor(p), f = p - i;
    f = f * f * (3.0 - 2.0 * f);
    ivec2 c = ivec2(i);
    float a = foam_hash(c), b = foam_hash(c + ivec2(1, 0));
    float d = foam_hash(c + ivec2(0, 1)), e = foam_hash(c + ivec2(1, 1));
    return mix(mix(a, b, f.x), mix(d, e, f.x), f.y);
}

// Four octaves of value noise, each turned and shifted so no grid shows;
// p in metres, the coarsest cell 4 m.
float foam_lace(vec2 p)
{
    const mat2 turn = mat2(0.8, 0.6, -0.6, 0.8);
    float sum = 0.0, amp = 0.5;
    p *= 0.25;
    for (int i = 0; i < 4; i++) {
        sum += amp * foam_noise(p);
        p = turn * p * 2.03 + vec2(11.7, 3.1);
        amp *= 0.5;
    }
    return sum / 0.9375;
}

// Detail for foam seen close: five octaves of value noise, cells 50, 25,
// 12, 6 and 3 cm (three, down to 12 cm, left a close wake's patches with
// smooth, painted edges), each faded out as its cell shrinks from one
// pixel's footprint to half of one (metres; 0: all): a cell is half a
// wavelength, so none goes past the pixels' Nyquist limit and aliases.
// Centred on zero, within +-0.5.
float foam_detail(vec2 p, float footprint)
{
    const mat2 turn = mat2(0.6, -0.8, 0.8, 0.6);
    float sum = 0.0, amp = 0.5, cell = 0.5;
    p *= 2.0;
    for (int i = 0; i < 5; i++) {
        float weight = footprint > 0.0 ? clamp(2.0 * cell / footprint - 1.0, 0.0, 1.0) : 1.0;
        if (weight <= 0.0)
            break;
        sum += amp * weight * (foam_noise(p) - 0.5);
        p = turn * p * 2.07 + vec2(5.3, 9.1);
        amp *= 0.5;
        cell /= 2.07;
    }
    return sum / 0.96875;
}

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
