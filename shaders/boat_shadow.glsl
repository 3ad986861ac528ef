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
