// The floating objects' wakes (TL_FEATURE_WAKE): foam along where each
// was, from its past positions (u_objects[o].wake, filled on the CPU from
// its path, so every frame renders alone): a turbulent band behind the
// hull that widens slowly and fades with age, the Kelvin wedge's waves
// (half-angle 19.47 deg) and the whitecaps on their crests along its
// arms near the boat. The wake's data is the
// objects' uniform block's (objects.glsl, src/prepare/tl_prepare.h).

// The Kelvin wake's waves (src/waves/tl_kelvin.c, tl_kelvin_slope, holds
// the same in double): their slope d height / d (behind, across) at a
// point `behind` metres back along the track and `across` to its side,
// for a boat `length` long at `speed`; waves shorter than four footprints
// faded out.
vec2 wake_kelvin_slope(float behind, float across, float speed, float length,
                       float footprint)
{
    if (!(behind > 0.0) || !(speed > 0.1) || !(length > 0.0))
        return vec2(0.0);
    const float g = 9.81;
    float k0 = g / (speed * speed);
    float r = across / behind;
    float c = 1.0 - 8.0 * r * r;
    if (c <= 0.0)
        return vec2(0.0);
    float f = min(speed / sqrt(g * length) / TL_KELVIN_FROUDE, 1.0);
    float distance = sqrt(behind * behind + across * across);
    float wavelength = 2.0 * TL_PI / k0;
    float height = TL_KELVIN_HEIGHT * length * f * f * sqrt(wavelength / (wavelength + distance));
    height *= (1.0 + TL_KELVIN_CUSP_GAIN * (1.0 - smoothstep(0.0, 0.3, c))) *
              smoothstep(0.0, 0.04, c);
    height *= smoothstep(0.0, length, behind);
    float root = sqrt(c);
    vec2 slope = vec2(0.0);
    for (int system = 0; system < 2; system++) {
        if (system == 1 && abs(r) < 1.0e-9)
            continue; // the divergent waves' crests lie along the track itself
        float t = system == 0 ? 2.0 * r / (1.0 + root) : (1.0 + root) / (4.0 * r);
        float secant = sqrt(1.0 + t * t);
        float k = k0 * secant * secant;
        float resolved = footprint > 0.0 ? 1.0 - smoothstep(0.25, 0.5, k * footprint / TL_PI) : 1.0;
        // Reduced in double would be exact; behind and across stay within
        // the wake's few hundred metres, where float keeps the phase.
        float phase = k0 * (behind + across * t) * secant;
        float a = height * resolved * (k0 / k) * sin(phase);
        slope -= a * k0 * secant * vec2(1.0, t);
    }
    return slope;
}

// Where the Kelvin waves break (tl_kelvin_whitecap): in [0, 1], on the
// crests along the cusp line, where the two systems meet and the waves
// are steepest, over the first few hull lengths of a boat fast enough
// (the Froude factor squared, as the height). The crests come where the
// height, cos(phase), is near its top: short white bars in echelon along
// each arm, as a boat's wake shows them.
float wake_kelvin_whitecap(float behind, float across, float speed, float length)
{
    if (!(behind > 0.0) || !(speed > 0.1) || !(length > 0.0))
        return 0.0;
    const float g = 9.81;
    float k0 = g / (speed * speed);
    float r = abs(across) / behind;
    float c = 1.0 - 8.0 * r * r;
    if (c <= 0.0 || r < 1.0e-9)
        return 0.0;
    float f = min(speed / sqrt(g * length) / TL_KELVIN_FROUDE, 1.0);
    float cusp = (1.0 - smoothstep(0.0, TL_KELVIN_WHITECAP_CUSP, c)) * smoothstep(0.0, 0.04, c);
    float t = (1.0 + sqrt(c)) / (4.0 * r);
    float secant = sqrt(1.0 + t * t);
    float phase = k0 * (behind + abs(across) * t) * secant;
    return f * f * cusp * smoothstep(0.0, length, behind) *
           exp(-behind / (TL_KELVIN_WHITECAP_LENGTHS * length)) *
           smoothstep(0.75, 0.98, cos(phase));
}

// Foam cover in [0, 1] at p; `footprint`: the water a pixel covers there
// (metres, 0: no level of detail). Out: the foam's thickness, the
// bubbles under it (foam_aerated), and the slope the Kelvin wake's waves
// add to the surface there (d height / d (x, z), camera-relative).
// Object o's wake at p: its cover (before its strength), where on its
// path the texture hangs (along, across; metres) and the Kelvin waves'
// slope there.
float wake_cover(int o, vec2 p, float footprint, out vec2 path, out vec2 waves, out float caps)
{
    const float tan_kelvin = 0.35355; // tan(19.47 deg) = 1 / sqrt(8)
    float half_beam = u_objects[o].wake_params.x, cover = 0.0;
    float hull = u_objects[o].wake_params.w;
    path = vec2(0.0);
    // The nearest segment p lies beside: where the Kelvin waves are taken.
    float near = 1.0e30, kelvin_behind = 0.0, kelvin_across = 0.0, kelvin_speed = 0.0;
    float kelvin_fade = 0.0, kelvin_along = 0.0;
    vec2 kelvin_track = vec2(0.0), kelvin_side = vec2(0.0);
    // Only the segments of the groups whose circles hold p (the CPU sizes
    // them to the foam's reach): the loop's bounds differ per pixel, so it
    // ends once every pixel of a block is done (llvmpipe runs a loop's
    // masked iterations, and an if's both sides, for the whole block).
    int first = TL_WAKE_GROUPS, last = -1;
    for (int g = 0; g < TL_WAKE_GROUPS; g++) {
        vec4 group = u_objects[o].wake_groups[g];
        vec2 c = p - group.xy;
        if (dot(c, c) <= group.z * group.z) {
            first = min(first, g);
            last = g;
        }
    }
    int end = min((last + 1) * TL_WAKE_GROUP, TL_WAKE_POINTS - 1);
    for (int k = first * TL_WAKE_GROUP; k < end; k++) {
        vec4 w0 = u_objects[o].wake[k], w1 = u_objects[o].wake[k + 1];
        vec2 a = w0.xy, ab = w1.xy - a;
        float len2 = dot(ab, ab);
        if (len2 < 1.0e-8)
            continue;
        float along = dot(p - a, ab) / len2;
        float u = clamp(along, 0.0, 1.0);
        float d = length(p - (a + ab * u));
        float behind = mix(w0.w, w1.w, u);
        float arm = half_beam + behind * tan_kelvin; // the wedge's half width here
        if (d > arm * 1.3 + 2.0)
            continue;
        float age = mix(w0.z, w1.z, u);
        float fade = exp(-age / u_objects[o].wake_params.y);
        // The churned water behind the stern: a band about the beam wide
        // that spreads as the root of the distance (turbulence widens
        // slowly; the wedge's arms are waves, not foam).
        float band = d / (half_beam * (1.0 + TL_WAKE_SPREAD * sqrt(behind / hull)));
        float turbulent = exp(-band * band);
        // Only a boat under way churns the water white (tl_scene.h,
        // TL_WAKE_SPEED_NONE: the CPU turns the feature off when none can).
        float speed = (w1.w - w0.w) / max(w1.z - w0.z, 1.0e-3);
        float churn = smoothstep(TL_WAKE_SPEED_NONE, TL_WAKE_SPEED_FULL, speed);
        float here = fade * turbulent * churn;
        // The Kelvin waves are taken beside the nearest segment p lies
        // beside (not around its ends).
        if (along >= 0.0 && along <= 1.0 && d < near) {
            near = d;
            kelvin_behind = behind;
            kelvin_speed = speed;
            kelvin_fade = fade * churn;
            kelvin_along = mix(object_wake_along(o, k), object_wake_along(o, k + 1), u);
            kelvin_track = ab / sqrt(len2); // toward where the boat was
            kelvin_side = vec2(-kelvin_track.y, kelvin_track.x);
            kelvin_across = dot(p - a, kelvin_side);
        }
        if (here > cover) {
            cover = here;
            float side = ab.x * (p.y - a.y) - ab.y * (p.x - a.x) < 0.0 ? -1.0 : 1.0;
            path = vec2(mix(object_wake_along(o, k), object_wake_along(o, k + 1), u), side * d);
        }
    }
    vec2 s = wake_kelvin_slope(kelvin_behind, kelvin_across, kelvin_speed, hull, footprint);
    waves = s.x * kelvin_track + s.y * kelvin_side;
    // The arms' breaking crests.
    caps = kelvin_fade * wake_kelvin_whitecap(kelvin_behind, kelvin_across, kelvin_speed, hull);
    if (caps > cover)
        path = vec2(kelvin_along, kelvin_across);
    return cover;
}

// Foam cover in [0, 1] at p; `footprint`: the water a pixel covers there
// (metres, 0: no level of detail). Out: the foam's thickness, the
// bubbles under it (foam_aerated), and the slope the Kelvin wakes' waves
// add to the surface there (d height / d (x, z), camera-relative). The
// wakes of several objects: the densest's foam, every one's waves.
float wake_foam(vec2 p, float ocean_value, float footprint, out float thickness,
                out float aerated, out vec2 waves)
{
    float cover = 0.0, caps = 0.0, densest = 0.0;
    vec2 path = vec2(0.0);
    waves = vec2(0.0);
    for (int o = 0; o < u_object_count; o++) {
        float strength = u_objects[o].wake_params.z;
        if (!(strength > 0.0))
            continue;
        vec2 at, slope;
        float object_caps;
        float c = strength * wake_cover(o, p, footprint, at, slope, object_caps);
        waves += slope;
        cover = max(cover, c);
        caps = max(caps, strength * object_caps);
        if (max(c, strength * object_caps) > densest) {
            densest = max(c, strength * object_caps);
            // Each object's texture a kilometre along from the last's.
            path = at + vec2(1000.0 * float(o), 0.0);
        }
    }
    thickness = 0.0;
    aerated = 0.0;
    if (cover <= 0.0 && caps <= 0.0)
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
                 0.2 * ocean_value + 0.4 * detail;
    // The churned water under the foam is full of bubbles, in the streaks'
    // pattern: it keeps the band pale where the foam opens.
    aerated = min(cover, 1.0) * (0.4 + 0.6 * streaks);
    // How much foam: full behind the stern, thinning with age into the
    // streaks. Even full cover leaves holes where the lace is thinnest (a
    // threshold that saturated at full cover drew flat sheets), and the
    // foam is thicker, whiter, the further the lace is above it: thin at
    // a patch's edge, where the water shows through.
    float density = clamp(pow(cover, 1.3) * (0.4 + 1.2 * streaks), 0.0, 1.0);
    float threshold = 0.75 - 0.45 * density + 0.35 * (1.0 - density) * (1.0 - density);
    thickness = clamp(smoothstep(threshold, threshold + 0.25, lace) + detail, 0.0, 1.0);
    float patches = smoothstep(threshold, threshold + 0.06, lace);
    // A patch's edge frays into specks of a finer detail, thinning out
    // below its threshold (one contour alone cut white blobs like
    // cotton wool out of the band; judge).
    float fringe = smoothstep(threshold - 0.25, threshold + 0.02, lace) *
                   smoothstep(0.1, 0.25, foam_detail(world * 2.5 + vec2(4.7, 2.9), 2.5 * footprint) +
                                             0.15 * (detail - 0.5));
    patches = max(patches, 0.7 * fringe);
    // Between the patches the churned water is a web of foam: veins along
    // the middle contours of a lace drawn out along the path, wider where
    // the wash is dense (as the giant wave's trail; patches alone read as
    // milky sheets with soft edges), their width varying along the path
    // and broken into lengths (one width, all joined, read as contour
    // lines). A vein narrower than the pixel is drawn a pixel wide and as
    // much fainter, so it cannot flicker.
    float web = 0.8 * foam_lace(path * vec2(0.7, 4.0)) + 0.2 * foam_lace(world * 6.0) +
                0.15 * detail;
    float half_width = mix(0.008, 0.025, density) *
                       (0.25 + 1.5 * foam_noise(path * vec2(0.15, 0.6) + vec2(7.3, 1.9)));
    float drawn = max(half_width, 0.2 * footprint);
    float veins = (1.0 - smoothstep(drawn, 2.0 * drawn, abs(web - 0.5))) * (half_width / drawn) *
                  smoothstep(0.0, 0.5, cover);
    veins *= smoothstep(0.3, 0.55, foam_lace(path * vec2(0.6, 4.0) + vec2(9.1, 2.2)) + 0.5 * detail);
    // Broken into drifts, brighter and fainter, as a web of foam ages.
    veins *= smoothstep(0.25, 0.55, foam_noise(world * 0.45 + vec2(3.3, 1.7)) + 0.3 * density) *
             (0.55 + 0.45 * foam_noise(world * 1.7 + vec2(8.2, 2.9)));
    aerated *= 0.7 + 0.6 * clamp(web - 0.2, 0.0, 0.5);
    thickness = max(thickness, 0.4 * veins);
    // Foam thins as it ages and toward the band's edges: greyer and more
    // of the water through it, not only fewer patches (at one opacity to
    // the end the old wake read as paper cut-outs).
    float fresh = TL_WAKE_OLD_OPACITY + (1.0 - TL_WAKE_OLD_OPACITY) * smoothstep(0.05, 0.6, cover);
    thickness *= fresh;
    // The arms' whitecaps: the crest's bar frayed by the world's lace and
    // the pixel's detail, thin and grey at its ends.
    float cap = smoothstep(0.2, 0.45, caps * (0.2 + 1.0 * foam_lace(world * 1.7) + 0.6 * detail));
    thickness = max(thickness, 0.6 * cap);
    aerated = max(aerated, 0.5 * caps);
    return max(max(patches, 0.85 * veins) * fresh, cap);
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
