// The floating objects' shadows (TL_FEATURE_BOAT_SHADOW): the sun's
// orthographic depth view of each object that casts one, a layer of the
// map array each (src/gl/tl_renderer_boat.c draws them; tl_prepare.c sets
// their matrices), looked up for the hulls and for the water around them.

uniform sampler2DArrayShadow u_boat_shadow_map;

// The share of the sun that reaches camera-relative point p past object
// o: 1 outside its map's beam, a soft edge over a few of its texels
// (about the sun's own penumbra a metre behind a wheelhouse). Beyond the
// object, away from the sun, the depth is held at the map's far end,
// where only the object itself stands nearer.
float boat_shadow_one(int o, vec3 p)
{
    float layer = u_objects[o].hull.w;
    if (layer < 0.0)
        return 1.0;
    vec3 s = (u_objects[o].shadow * vec4(p, 1.0)).xyz;
    if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(u_objects[o].shadow_map.y))) ||
        s.z <= 0.0)
        return 1.0;
    float depth = min(s.z, 1.0);
    float texel = 1.0 / float(TL_BOAT_SHADOW_SIZE);
    float lit = 0.0;
    for (int i = 0; i < 4; i++) {
        vec2 d = (vec2(i & 1, i >> 1) - 0.5) * 1.5 * texel;
        lit += texture(u_boat_shadow_map, vec4(s.xy + d, layer, depth));
    }
    return 0.25 * lit;
}

// The share of the sun that reaches p past every object in view.
float boat_shadow(vec3 p)
{
    float lit = 1.0;
    for (int o = 0; o < u_object_count; o++)
        lit *= boat_shadow_one(o, p);
    return lit;
}

#if defined(TL_FEATURE_UNDERWATER) || defined(TL_FEATURE_SEA_FLOOR)
// The share of the sun's beam that reaches camera-relative p, `depth`
// metres under the mean surface, past every object: the beam crossed the
// surface where the refracted ray through p meets it, and the hulls stand
// at the surface, so it is looked up there (the sand's shadow under a
// boat; a point on a hull's own bottom lies too near the hull for that
// lookup, and its faces turned from the sun are dark by their angle). The waves tilt the refracted
// beam and the sun's disc widens it (u_beam_spread radians), so a hull's
// shadow blurs with depth: over a square that wide a side (four lookups),
// the band a bundle lands spread over, as the caustics' lines are.
float boat_shadow_below(vec3 p, float depth)
{
    depth = max(depth, 0.0);
    vec3 q = p - u_sun_water * (depth / max(-u_sun_water.y, TL_CAUSTIC_MIN_DOWN));
    float blur = depth * u_beam_spread, lit = 0.0;
    for (int i = 0; i < 4; i++)
        lit += boat_shadow(q + vec3(float(i & 1) - 0.5, 0.0, float(i >> 1) - 0.5) * blur);
    return 0.25 * lit;
}
#endif
