// The boat's shadow (TL_FEATURE_BOAT_SHADOW): the sun's orthographic depth
// view of it (src/gl/tl_renderer_boat.c draws it; tl_prepare.c sets the
// map's matrix), looked up for the hull and for the water around it.

uniform sampler2DShadow u_boat_shadow_map;

// The share of the sun that reaches camera-relative point p past the
// boat: 1 outside the map's beam, a soft edge over a few of its texels
// (about the sun's own penumbra a metre behind a wheelhouse). Beyond the
// boat, away from the sun, the depth is held at the map's far end, where
// only the boat itself stands nearer.
float boat_shadow(vec3 p)
{
    vec3 s = (u_boat_shadow * vec4(p, 1.0)).xyz;
    if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(u_boat_shadow_extent))) ||
        s.z <= 0.0)
        return 1.0;
    float depth = min(s.z, 1.0);
    float texel = 1.0 / float(TL_BOAT_SHADOW_SIZE);
    float lit = 0.0;
    for (int i = 0; i < 4; i++) {
        vec2 o = (vec2(i & 1, i >> 1) - 0.5) * 1.5 * texel;
        lit += texture(u_boat_shadow_map, vec3(s.xy + o, depth));
    }
    return 0.25 * lit;
}
