// Light shafts (TL_FEATURE_SHAFTS): the sun's beam under the moving
// surface is not even but bundled by the waves (caustics.glsl), and the
// water scatters those bundles toward the eye as rays that fan out from
// the sun. Single scattering with the water's phase function, marched
// along the view ray in u_shaft_steps jittered samples over at most
// TL_SHAFT_RANGE metres. It adds only the bundles' departure from the
// even beam (focus - 1): water_inscatter has the even beam's light
// exactly, so with the shafts off the frame is as without them, and they
// leave the mean brightness as it was. A frame adds them once per pixel,
// after the rest of its light (ocean.frag), where every pixel of a 2 x 2
// quad is at hand to share its samples (shafts_quad_mean).

// Where in its step a pixel's samples sit. With fine derivatives the four
// pixels of a 2 x 2 quad take the four quarters of one offset, which
// interleaved gradient noise (Jimenez 2014) picks per quad, and share
// their samples (shafts_quad_mean). Without, each pixel takes interleaved
// gradient noise alone, whose every 3 x 3 block of pixels spreads its
// offsets over nearly the whole step, so the display's pixel filter
// averages neighbours into a finer march; that left a diagonal grid of
// dots. A hash (white noise) left a grain no filter takes out; a 4 x 4
// ordered dither a grid it does not (its period is wider than the filter).
float shaft_offset()
{
    vec2 p = floor(gl_FragCoord.xy);
#ifdef GL_ARB_derivative_control
    vec2 q = floor(p * 0.5), in_quad = p - 2.0 * q;
    float quarter = in_quad.x * 0.5 + in_quad.y * (0.75 - in_quad.x);
    return fract(fract(52.9829189 * fract(dot(q, vec2(0.06711056, 0.00583715)))) * 0.25 + quarter);
#else
    return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
#endif
}

// The light the shafts add along `ray` (unit, from the eye) over its
// first `dist` metres.
vec3 water_shafts(vec3 ray, float dist)
{
    float range = min(dist, TL_SHAFT_RANGE);
    float ds = range / float(u_shaft_steps);
    float offset = shaft_offset();
    vec3 eye = vec3(0.0, u_cam_height, 0.0);
    float pixel = 2.0 * u_tan_half_vfov / u_resolution.y;
    // A sample stands for ds of the ray, which sweeps ds sin(angle) across
    // the bundles (they run along the sun's way): they are taken no finer
    // than that (finer ones would come out as noise). The wide footprint
    // also fades the finer octaves out of the work.
    float across = TL_SHAFT_SMOOTH * ds * length(cross(ray, u_sun_water));
    vec3 sum = vec3(0.0);
    for (int i = 0; i < u_shaft_steps; i++) {
        float s = (float(i) + offset) * ds;
        vec3 p = eye + ray * s;
        float depth = -p.y;
        if (depth <= 0.0)
            continue;
        float footprint = max(max(s * pixel, TL_SHAFT_FOOTPRINT), across);
        // The coarse web alone: a shaft is a bundle wider than the fine
        // lines, which would only add noise to the march.
        float focus = caustic_focus(p.xz, depth, footprint, TL_CAUSTIC_IN_SHAFT);
        sum += (focus - 1.0) * water_sun_at(depth) * exp(-u_water_sigma * s);
    }
    return (u_shafts * u_water_scattering * water_phase(dot(u_sun_water, -ray)) * ds) * sum;
}

// The mean of `v` over the pixel's 2 x 2 quad, from fine derivatives: a
// pixel's neighbour across x is v plus or minus dFdxFine(v) by its column's
// parity, and so on for y. The quad's four offsets (shaft_offset) sit
// in the four quarters of a step, so the mean is a march four times finer,
// at a quarter of the resolution, which the shafts (broad, soft) do not
// need. Without it the pixel filter left a diagonal grid of dots. It must
// be called where the whole quad runs (not in a branch). Where the driver
// has only coarse derivatives the pixel keeps its own value.
vec3 shafts_quad_mean(vec3 v)
{
#ifdef GL_ARB_derivative_control
    vec2 parity = mod(floor(gl_FragCoord.xy), 2.0) * -2.0 + 1.0; // +1 even, -1 odd
    vec3 column = v + 0.5 * parity.y * dFdyFine(v);
    return column + 0.5 * parity.x * dFdxFine(column);
#else
    return v;
#endif
}
