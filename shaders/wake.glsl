// The boat's wake (TL_FEATURE_WAKE): foam along where the boat was, from
// its past positions (u_wake, filled on the CPU from the boat's path, so
// every frame renders alone): a turbulent band behind the hull that widens
// slowly, and the two arms of the Kelvin wedge (half-angle 19.47 deg),
// both fading with age. u_wake and the other u_wake_* uniforms are
// frame_uniforms.glsl's (src/prepare/tl_uniform_list.h).

// Foam cover in [0, 1] at p; `footprint`: the water a pixel covers there
// (metres, 0: no level of detail). Out: the foam's thickness, and the
// bubbles under it (foam_aerated).
float wake_foam(vec2 p, float ocean_value, float footprint, out float thickness,
                out float aerated)
{
    const float tan_kelvin = 0.35355; // tan(19.47 deg) = 1 / sqrt(8)
    float half_beam = u_wake_params.x, cover = 0.0;
    vec2 path = vec2(0.0); // where on the path the foam's texture hangs: along, across (m)
    // Only the segments of the groups whose circles hold p (the CPU sizes
    // them to the foam's reach): the loop's bounds differ per pixel, so it
    // ends once every pixel of a block is done (llvmpipe runs a loop's
    // masked iterations, and an if's both sides, for the whole block).
    int first = TL_WAKE_GROUPS, last = -1;
    for (int g = 0; g < TL_WAKE_GROUPS; g++) {
        vec2 c = p - u_wake_groups[g].xy;
        if (dot(c, c) <= u_wake_groups[g].z * u_wake_groups[g].z) {
            first = min(first, g);
            last = g;
        }
    }
    int end = min((last + 1) * TL_WAKE_GROUP, TL_WAKE_POINTS - 1);
    for (int k = first * TL_WAKE_GROUP; k < end; k++) {
        vec2 a = u_wake[k].xy, ab = u_wake[k + 1].xy - a;
        float len2 = dot(ab, ab);
        if (len2 < 1.0e-8)
            continue;
        float along = dot(p - a, ab) / len2;
        float u = clamp(along, 0.0, 1.0);
        float d = length(p - (a + ab * u));
        float behind = mix(u_wake[k].w, u_wake[k + 1].w, u);
        float arm = half_beam + behind * tan_kelvin; // the wedge's half width here
        if (d > arm * 1.3 + 2.0)
            continue;
        float age = mix(u_wake[k].z, u_wake[k + 1].z, u);
        float fade = exp(-age / u_wake_params.y);
        float band = d / (1.3 * half_beam * (1.0 + 0.06 * behind));
        float turbulent = exp(-band * band);
        // The arms are lines beside the path: only where the point lies
        // beside this segment (not around its ends).
        float edge = (d - arm) / (0.08 * arm + 0.5);
        float beside = along >= 0.0 && along <= 1.0 ? 1.0 : 0.0;
        float arms = 0.6 * beside * exp(-edge * edge) * smoothstep(0.0, 2.0 * half_beam, behind);
        // Only a boat under way churns the water white (tl_scene.h,
        // TL_WAKE_SPEED_NONE: the CPU turns the feature off when none can).
        float speed = (u_wake[k + 1].w - u_wake[k].w) / max(u_wake[k + 1].z - u_wake[k].z, 1.0e-3);
        float churn = smoothstep(TL_WAKE_SPEED_NONE, TL_WAKE_SPEED_FULL, speed);
        float here = fade * max(turbulent, arms) * churn;
        if (here > cover) {
            cover = here;
            float side = ab.x * (p.y - a.y) - ab.y * (p.x - a.x) < 0.0 ? -1.0 : 1.0;
            path = vec2(mix(u_wake_along[k], u_wake_along[k + 1], u), side * d);
        }
    }
    cover *= u_wake_params.z;
    thickness = 0.0;
    aerated = 0.0;
    if (cover <= 0.0)
        return 0.0; // most of the sea: none of the texture below
    // The texture hangs on the path and the world, where the boat left
    // it, not where it is now: first, streaks of coverage 6 m along the
    // path by 0.8 m across.
    vec2 q = path / vec2(6.0, 0.8);
    float streaks = 0.65 * foam_noise(q) + 0.35 * foam_noise(q * vec2(2.3, 2.7) + vec2(4.1, 7.7));
    vec2 world = p + u_world_offset;
    float detail = foam_detail(world, footprint);
    // The lace: drawn out along the path (cells about 11 m by 1.6 m: the
    // churned water stretches into streaks behind the stern) and broken up
    // where the boat left it, to the pixel's detail (strong enough to
    // fray a patch's edge down to a few centimetres).
    float lace = 0.6 * foam_lace(path * vec2(0.35, 2.5)) + 0.2 * foam_lace(world * 2.0) +
                 0.2 * ocean_value + 0.9 * detail;
    // The churned water under the foam is full of bubbles, in the streaks'
    // pattern: it keeps the band pale where the foam opens.
    aerated = min(cover, 1.0) * (0.4 + 0.6 * streaks);
    // How much foam: full behind the stern, thinning with age into the
    // streaks. Even full cover leaves holes where the lace is thinnest (a
    // threshold that saturated at full cover drew flat sheets), and the
    // foam is thicker, whiter, the further the lace is above it: thin at
    // a patch's edge, where the water shows through.
    float density = clamp(pow(cover, 1.3) * (0.4 + 1.2 * streaks), 0.0, 1.0);
    float threshold = 0.75 - 0.5 * density + 0.35 * (1.0 - density) * (1.0 - density);
    thickness = clamp(smoothstep(threshold, threshold + 0.25, lace) + detail, 0.0, 1.0);
    return smoothstep(threshold, threshold + 0.06, lace);
}

#ifdef TL_FEATURE_GIANT_WAVE
// How much of the wake the giant wave leaves: none where it has lifted or
// lowered the water, nor on its face where that crosses the mean level
// (steeper than about 1 in 8).
float wake_swept(GiantSample g)
{
    return (1.0 - smoothstep(1.0, 4.0, abs(g.height))) *
           (1.0 - smoothstep(0.08, 0.25, length(g.grad)));
}
#endif
