// The boat in the ocean pass: the mesh pass rendered the lit hull and its
// distance into textures; here they are composited with the water per
// sample. The hull wins where it is nearer; water that lies inside the
// hull's waterplane (an ellipse just within the model's bounds) under a
// pixel the hull covers is hidden too, so no water shows on deck or
// through the hull however the boat floats.

uniform sampler2D u_boat_color;      // lit hull (alpha: its distance, 0 where none)
uniform sampler2D u_boat_reflection; // the hull mirrored in the water plane, alpha the same
uniform float u_boat_water; // camera-relative y of the water plane it is mirrored in
uniform sampler2D u_boat_distance; // distance along the view ray, TL_SKY_DEPTH where none
uniform mat4 u_boat_to_model;      // camera-relative world -> model
uniform vec4 u_boat_hull;          // ellipse centre x z, semi-axes x z (model units)
uniform float u_boat_top;          // model y of the hull's top

// Whether the water point (camera-relative x z, absolute y) is inside the hull.
bool boat_contains(vec3 p)
{
    vec3 m = (u_boat_to_model * vec4(p.x, p.y - u_cam_height, p.z, 1.0)).xyz;
    vec2 e = (m.xz - u_boat_hull.xy) / u_boat_hull.zw;
    return dot(e, e) < 1.0 && m.y < u_boat_top;
}

// The sample's radiance and distance after the hull: `water` at `dist`
// (TL_SKY_DEPTH for the sky) along `ray`.
vec3 boat_composite(vec3 water, vec3 ray, inout float dist)
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float hull = texelFetch(u_boat_distance, px, 0).r;
    if (hull >= TL_SKY_DEPTH)
        return water;
    bool inside = dist < TL_SKY_DEPTH && boat_contains(vec3(0.0, u_cam_height, 0.0) + ray * dist);
    if (hull < dist || inside) {
        dist = hull;
        return texelFetch(u_boat_color, px, 0).rgb;
    }
    return water;
}

#ifdef TL_BOAT_MIRROR
// How much of the mirrored hull point `mirror_dist` along `ray` the water
// point `hit` sees. The image is a mirror in a plane at the hull's
// waterline: water further from that plane than the ocean's own waves
// reach (a swell lifting the near sea; voyage 120 drew the mast's image
// on one, a wavering dark line) is not where it holds, and fades out from
// half the waves' depth to all of it. Then the hull point is the image's
// point mirrored in the plane, and the line to it is tested against the
// water at three points. A point less than TL_MIRROR_MARGIN above the
// water already hides part of the image, so it fades in as the line
// clears the waves (no pixel-sharp edge to crawl from frame to frame).
// Below the water plane (the mirror pass clips there) or behind the water
// point, none. The program with the image (TL_BOAT_MIRROR) runs only
// around it (draw_area in src/gl/tl_renderer.c): llvmpipe runs an `if`'s
// body, and a loop's once, for every pixel, and these tests everywhere
// cost voyage's frame 120 a sixth of its time at `preview`.
#define TL_MIRROR_MARGIN 0.1
#define TL_MIRROR_SHIFT 0.05
float boat_mirror_seen(vec3 hit, float mirror_dist, vec3 ray)
{
    vec3 mirrored = ray * min(mirror_dist, 1.0e6); // camera-relative, y too
    vec3 target = vec3(mirrored.x, 2.0 * u_boat_water - mirrored.y + u_cam_height, mirrored.z);
    float off_plane = abs(hit.y - (u_boat_water + u_cam_height));
    float seen = 1.0 - smoothstep(0.5 * u_depth, u_depth, off_plane);
    bool image = mirror_dist < TL_SKY_DEPTH && target.y > hit.y && seen > 0.0;
    seen = image ? seen : 0.0;
    for (int i = 1; i <= (image ? 3 : 0); i++) {
        vec3 p = mix(hit, target, 0.25 * float(i));
        float footprint = length(vec3(p.x, p.y - u_cam_height, p.z)) * u_lod_angle;
        float above = p.y - surface_height(p.xz, TL_MARCH_OCTAVES, footprint);
        seen = min(seen, smoothstep(-TL_MIRROR_MARGIN, TL_MIRROR_MARGIN, above));
    }
    return seen;
}

// The sky's reflection in the water with the hull's mirror image over it,
// looked up where the pixel is, shifted by the wave's slope (the classic
// planar reflection, distorted by the normal). The planar image lands on
// whatever water lies under the hull on screen, and a swell between the
// camera and the boat is such water: there the reflected ray runs into the
// swell, not to the hull (voyage 105-125 drew the hull's dark mirror image,
// and the mast's, on the near face of the swell). So the image is kept only
// as far as the line from the water point to the mirrored hull point stays
// above the water (boat_mirror_seen).
// `ray`, `hit`: the view ray and the water point (x z camera-relative,
// y absolute).
vec3 boat_reflect(vec3 sky, vec3 n, vec3 ray, vec3 hit)
{
    vec2 size = vec2(textureSize(u_boat_reflection, 0));
    // The shift is held to TL_MIRROR_SHIFT of the height (facets steeper
    // than about 20 degrees): the program runs only that far around the
    // image (draw_area in src/gl/tl_renderer.c).
    vec2 shift = n.xz * 0.15;
    shift *= min(1.0, TL_MIRROR_SHIFT / max(length(shift), 1.0e-6));
    vec2 at = gl_FragCoord.xy + shift * size.y;
    // Four taps 3 px apart: ripples break a reflection's edges up softly.
    vec3 sum = vec3(0.0);
    float covered = 0.0, mirror_dist = TL_SKY_DEPTH;
    for (int i = 0; i < 4; i++) {
        vec2 tap = at + vec2(i & 1, i >> 1) * 3.0 - 1.5;
        vec4 hull = texelFetch(u_boat_reflection, ivec2(clamp(tap, vec2(0.0), size - 1.0)), 0);
        sum += hull.rgb;
        covered += hull.a > 0.0 ? 0.25 : 0.0;
        mirror_dist = min(mirror_dist, hull.a > 0.0 ? hull.a : TL_SKY_DEPTH);
    }
    // The taps' colours, over those that cover the hull (0 elsewhere).
    vec3 color = covered > 0.0 ? 0.25 * sum / covered : vec3(0.0);
    return mix(sky, color, covered * boat_mirror_seen(hit, mirror_dist, ray));
}
#endif
