// The white water on a hull where it meets the water (mesh.frag): a thin
// wash all round at the waterline, where the sea slaps the hull even at
// rest, and at speed the bow wave climbing the stem, highest at the stem
// and gone by amidships, its top ragged. src/mesh/tl_mesh_shading.c holds
// the envelope in double (tl_mesh_wash_top, tl_mesh_wash_cover). Needs
// objects.glsl and foam_noise.glsl.

// How high the wash reaches above the water beside the hull (m) at
// `along` (0 at the waterline's aft end, 1 at the stem) for a hull at
// `speed` m/s: the line plus a share of the stagnation height U^2 / 2g
// over the forward part.
float hull_wash_top(float along, float speed)
{
    return TL_MESH_WASH_LINE +
           TL_MESH_BOW_CLIMB * speed * speed / (2.0 * 9.81) * smoothstep(0.5, 0.97, along);
}

// The wash's cover at `height` m above the water beside the hull under a
// top `top` (m), its edge moved up and down by `lace` in [0, 1]: full
// below 0.7 of the ragged top, none above it, and none a top's height
// under the water (the sea hides the hull there but in a trough).
float hull_wash_cover(float height, float top, float lace)
{
    float edge = top * (0.75 + 0.5 * lace);
    return (1.0 - smoothstep(0.7 * edge, edge, height)) * smoothstep(-edge, -0.5 * edge, height);
}

// Object o's wash at the camera-relative point `world`: x the sheet of
// water over the paint, y the white foam in it, the texture fixed to the
// water flowing aft past the hull (the path's distance), `footprint` the
// metres a pixel covers there.
vec2 hull_wash(int o, vec3 world, float footprint)
{
    vec3 m = (u_objects[o].to_model * vec4(world, 1.0)).xyz;
    vec2 span = u_objects[o].outline_z.xy;
    float along = (m.z - span.x) / max(span.y - span.x, 1.0e-6);
    float per_metre = length(u_objects[o].to_model[0].xyz);
    // Above the water beside it (the CPU's heights along each side): the
    // wash rides the waves running along the hull, not a level plane.
    float height = world.y - object_wash_water(o, m.z, m.x);
    float top = hull_wash_top(along, u_objects[o].hull.z);
    if (height > 1.5 * top || height < -top)
        return vec2(0.0);
    // Streaks drawn out along the hull as the water runs aft.
    vec2 flow = vec2(m.z / per_metre + object_wake_along(o, 0), height);
    float lace = foam_lace(flow * vec2(1.5, 6.0)) + 0.6 * foam_detail(flow * 2.0, footprint);
    float sheet = hull_wash_cover(height, top, clamp(lace, 0.0, 1.0));
    // The foam in it: streaks where the lace is thick, fuller low down,
    // its fine detail drawn out along the hull as well (round, it made
    // clouds stuck on the paint; judge).
    float streaks = foam_lace(flow * vec2(0.8, 9.0) + vec2(7.1, 2.3)) +
                    0.5 * foam_detail(flow * vec2(1.0, 8.0), footprint);
    return vec2(sheet, sheet * smoothstep(0.5, 0.75, streaks + 0.15 * sheet));
}
