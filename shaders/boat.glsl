// The floating objects in the ocean pass: the mesh pass rendered their lit
// hulls and distance into textures; here they are composited with the
// water per sample. The hull wins where it is nearer; water that lies inside the
// hull (its outline: the waterline's, widening to its widest plan above)
// under a pixel the hull covers is hidden too, so no water shows on deck
// or through the hull however the boat floats, pitches or heels.

uniform sampler2D u_boat_color;      // lit hull, alpha = covered
uniform sampler2D u_boat_reflection; // the hull mirrored in the water plane, alpha = covered
#ifdef TL_PASS_AOV
uniform sampler2D u_boat_surface; // the hull's normal facing the eye, 1 + its object's scene index
#endif
uniform sampler2D u_boat_distance; // distance along the view ray, TL_SKY_DEPTH where none
// The hulls' outlines (tl_mesh_outline, in the objects' uniform block:
// objects.glsl): half widths at evenly spaced model z, at the waterline
// from outline_z.x (aft) to .y (forward), and the widest, at model height
// plan_y, from outline_z.z to .w.

// Object o's waterline (plan: 0) or widest plan (1) half width at model z,
// 0 outside; its plan's height (2) likewise.
float boat_station(int o, int table, vec2 range, float z)
{
    if (!(range.y > range.x) || z < range.x || z > range.y)
        return 0.0;
    float f = (z - range.x) / (range.y - range.x) * float(TL_MESH_WATERLINE_STATIONS - 1);
    int i = min(int(f), TL_MESH_WATERLINE_STATIONS - 2);
    float a = table == 0 ? object_waterline(o, i) : table == 1 ? object_plan(o, i) : object_plan_y(o, i);
    float b = table == 0   ? object_waterline(o, i + 1)
              : table == 1 ? object_plan(o, i + 1)
                           : object_plan_y(o, i + 1);
    return mix(a, b, f - float(i));
}

// Whether the water point (camera-relative x z, absolute y) is inside
// object o's hull (tl_mesh_outline_contains).
bool boat_contains_one(int o, vec3 p)
{
    vec3 m = (u_objects[o].to_model * vec4(p.x, p.y - u_cam_height, p.z, 1.0)).xyz;
    if (!(m.y < u_objects[o].hull.x))
        return false;
    vec4 z = u_objects[o].outline_z;
    float water = boat_station(o, 0, z.xy, m.z);
    float half_width = water;
    if (m.y > 0.0) {
        float wide = boat_station(o, 1, z.zw, m.z);
        float high = boat_station(o, 2, z.zw, m.z);
        float f = high > 1.0e-9 ? min(m.y / high, 1.0) : 1.0;
        half_width = water + (max(wide, water) - water) * f;
    }
    return abs(m.x) < half_width;
}

// Inside any hull in view.
bool boat_contains(vec3 p)
{
    for (int o = 0; o < u_object_count; o++)
        if (boat_contains_one(o, p))
            return true;
    return false;
}

// The sample's radiance and distance after the hulls: `water` at `dist`
// (TL_SKY_DEPTH for the sky) along `ray`. At one sample a pixel the hulls'
// pass holds u_mesh_scale^2 of them (quality.mesh_scale; with more, each
// sample's pass draws the hulls at its offset and this is 1): the pixel
// averages them, each the hull where the hull is nearer (or the water
// point lies inside it) and the water elsewhere, so its edges and paint
// lines are antialiased. The distance is the nearest hull any saw.
vec3 boat_composite(vec3 water, vec3 ray, inout float dist)
{
    int count = max(u_mesh_scale, 1);
    ivec2 first = ivec2(gl_FragCoord.xy) * count;
    bool inside = false, asked = false;
    vec3 sum = vec3(0.0);
    float nearest = TL_SKY_DEPTH;
    for (int j = 0; j < count; j++)
        for (int i = 0; i < count; i++) {
            ivec2 at = first + ivec2(i, j);
            float hull = texelFetch(u_boat_distance, at, 0).r;
            bool covers = false;
            if (hull < TL_SKY_DEPTH) {
                if (!asked) { // the outline test once a pixel, where a hull is
                    asked = true;
                    inside = dist < TL_SKY_DEPTH &&
                             boat_contains(vec3(0.0, u_cam_height, 0.0) + ray * dist);
                }
                covers = hull < dist || inside;
            }
            if (covers) {
                if (hull < nearest) {
                    nearest = hull;
#ifdef TL_PASS_AOV
                    vec4 surface = texelFetch(u_boat_surface, at, 0);
                    aov_surface(surface.xyz, AOV_OBJECT + int(surface.w + 0.5) - 1);
#endif
                }
                sum += layer_emit(TL_LIGHT_BOAT, texelFetch(u_boat_color, at, 0).rgb);
            } else
                sum += water;
        }
    if (nearest < TL_SKY_DEPTH)
        dist = nearest;
    return sum / float(count * count);
}

// Metres from the water point p (camera-relative x z, absolute y) out to
// object o's waterline outline (0 inside it), and down from its keel, in
// the hull's frame: water below the keel does not touch the hull (a stern
// hanging over a steep face's trough; measured in the waterline's plan
// alone, the water under such a stern lay at 0 and drew a white slab
// beside the hull, cut square at the transom, giant_wave.tl 10.4 s);
// *along: where along the hull it lies, 0 at the stern to 1 at the stem;
// *model: p's model x z, metres.
float boat_waterline_gap(int o, vec3 p, out float along, out vec2 model)
{
    mat4 to_model = u_objects[o].to_model;
    vec3 m = (to_model * vec4(p.x, p.y - u_cam_height, p.z, 1.0)).xyz;
    float per_metre = length(to_model[0].xyz); // model units per metre
    float z0 = u_objects[o].outline_z.x, z1 = u_objects[o].outline_z.y;
    along = clamp((m.z - z0) / max(z1 - z0, 1.0e-6), 0.0, 1.0);
    float f = along * float(TL_MESH_WATERLINE_STATIONS - 1);
    int i = min(int(f), TL_MESH_WATERLINE_STATIONS - 2);
    float half_width = mix(object_waterline(o, i), object_waterline(o, i + 1), f - float(i));
    vec3 outside = max(vec3(abs(m.x) - half_width, abs(m.z - clamp(m.z, z0, z1)),
                            u_objects[o].shadow_map.z - m.y), // the keel's model y
                       0.0);
    model = m.xz / per_metre;
    return length(outside) / per_metre;
}

// Foam where a hull meets the water: a thin line all round it (the water
// slapping the hull), and the bow wave's white water, from the stem back
// along both sides, wider the faster the object goes (hull.z) and where
// the bow meets rising water (`slope`: the surface's height gradient
// there). Broken up like the wake's, in the hull's frame (it travels with
// the object), by the waves' `value`; `footprint`: the water a pixel
// covers (m). Returns the cover; *thickness as foam_shade takes it.
float boat_contact_foam_one(int o, vec3 p, vec2 slope, float value, float footprint,
                            out float thickness)
{
    thickness = 0.0;
    float along;
    vec2 model;
    float gap = boat_waterline_gap(o, p, along, model);
    float speed = u_objects[o].hull.z;
    float reach = TL_BOAT_CONTACT_LINE + TL_BOAT_BOW_WAVE * speed; // the bow wave's width, m
    if (gap > 4.0 * reach + 0.5)
        return 0.0;
    // The bow's heading: the model's +z in the world (the inverse's row).
    mat4 to_model = u_objects[o].to_model;
    vec2 heading = normalize(vec2(to_model[0].z, to_model[2].z));
    float rising = clamp(dot(slope, heading), 0.0, 1.0);
    float line = exp(-(gap * gap) / (TL_BOAT_CONTACT_LINE * TL_BOAT_CONTACT_LINE));
    float bow = smoothstep(0.3, 0.95, along) * smoothstep(0.2, 1.5, speed + 8.0 * rising);
    float wave = bow * exp(-gap / (reach * (1.0 + 3.0 * rising)));
    float cover = max(0.9 * line, wave);
    if (cover < 0.02)
        return 0.0;
    float lace = 0.55 * foam_lace(model * vec2(3.0, 1.5)) + 0.25 * value +
                 0.5 * foam_detail(model * 2.0, footprint);
    // A lower threshold than the wake's: churned against the hull, the
    // water is white wherever the cover is full, seen near or far. Soft
    // edges and a fainter close-up detail: where the cover thins out (the
    // bow wave tripled up a giant wave's face) hard-edged specks read as
    // confetti.
    float threshold = 0.7 - 0.55 * cover;
    thickness = clamp(smoothstep(threshold, threshold + 0.25, lace), 0.0, 1.0);
    return smoothstep(threshold, threshold + 0.2, lace);
}

// The contact foam of every hull in view: the most of any.
float boat_contact_foam(vec3 p, vec2 slope, float value, float footprint, out float thickness)
{
    float cover = 0.0;
    thickness = 0.0;
    for (int o = 0; o < u_object_count; o++) {
        float t;
        float c = boat_contact_foam_one(o, p, slope, value, footprint, t);
        if (c > cover) {
            cover = c;
            thickness = t;
        }
    }
    return cover;
}

#ifdef TL_BOAT_MIRROR
// The look-up's shift is TL_MIRROR_DISTORT of the height per unit of the
// water's slope, held to TL_MIRROR_SHIFT of it (facets steeper than about
// 18 degrees; src/gl/tl_renderer_internal.h defines both):
// the program with the image runs only that far around it (draw_area in
// src/gl/tl_renderer.c).

// The sky's reflection in the water with the hull's mirror image over it,
// looked up where the pixel is, shifted by the wave's slope (the classic
// planar reflection, distorted by the normal). The image is a mirror in a
// plane at the hull's waterline, and lands, on screen, on whatever water
// lies under the hull: a swell lifting the near sea is such water, and
// cannot mirror the hull (voyage 105-125 drew its dark image, and the
// mast's as a wavering line, on a swell's near face between the camera and
// the boat). Water further from the plane than the ocean's own waves reach
// is not where the image holds: it fades out from half the waves' depth
// to all of it. `hit`: the water point (x z camera-relative, y absolute).
// The program with the image (TL_BOAT_MIRROR) runs only around it: its
// taps cost every pixel of a block on llvmpipe, `if` or not.
vec3 boat_reflect(vec3 sky, vec3 n, vec3 hit)
{
    vec2 size = vec2(textureSize(u_boat_reflection, 0));
    vec2 shift = n.xz * TL_MIRROR_DISTORT;
    shift *= min(1.0, TL_MIRROR_SHIFT / max(length(shift), 1.0e-6));
    vec2 at = gl_FragCoord.xy + shift * size.y;
    // Ripples finer than a pixel smear the image up and down, as they
    // draw a lamp's reflection on a choppy sea out into a column of glints
    // (a single look-up drew isolated specks): eight taps, two 3 px apart
    // across, four rows over TL_MIRROR_STREAK of the height either side,
    // weighted toward the middle.
    vec4 hull = vec4(0.0);
    float streak = TL_MIRROR_STREAK * size.y, weights = 0.0;
    for (int i = 0; i < 8; i++) {
        float row = (float(i >> 1) + 0.5) / 2.0 - 1.0; // -0.75 .. 0.75
        float w = 1.0 - 0.5 * abs(row);
        vec2 tap = at + vec2(float(i & 1) * 3.0 - 1.5, row * streak);
        hull += w * texelFetch(u_boat_reflection, ivec2(clamp(tap, vec2(0.0), size - 1.0)), 0);
        weights += w;
    }
    hull /= weights;
    // The taps' colours are weighted by their coverage: unpremultiply.
    vec3 color = hull.a > 0.0 ? hull.rgb / hull.a : vec3(0.0);
    // The nearest of the objects' planes (each is mirrored in its own).
    float off_plane = 1.0e30;
    for (int o = 0; o < u_object_count; o++)
        off_plane = min(off_plane, abs(hit.y - (u_objects[o].hull.y + u_cam_height)));
    return mix(sky, layer_emit(TL_LIGHT_REFLECTION, color),
               hull.a * (1.0 - smoothstep(0.5 * u_depth, u_depth, off_plane)));
}
#endif
