// Caustics (TL_FEATURE_CAUSTICS): the sunlight the moving surface focuses
// under the water, from the surface's own normals and the refracted sun.
// src/waves/tl_caustics.h derives the estimate; tl_caustics.c is its
// mirror in double (test_caustics). Needs waves.glsl.

// The refracted sun's horizontal run per metre down, leaving the surface
// at camera-relative x; the waves at the level of detail of `footprint`.
vec2 caustic_slant(vec2 x, float footprint)
{
    vec2 grad;
    float slope_var;
    waves_value_grad(x, TL_NORMAL_OCTAVES, footprint, grad, slope_var);
    vec3 n = normalize(vec3(-grad.x * u_depth, 1.0, -grad.y * u_depth));
    vec3 r = refract(-u_sun_dir, n, 1.0 / u_water_ior);
    if (r == vec3(0.0))
        r = vec3(0.0, -1.0, 0.0);
    return r.xz / -min(r.y, -TL_CAUSTIC_MIN_DOWN);
}

// The focus of a map whose Jacobian has determinant det, taken over a step
// e at `depth`: the finer octaves' tilt and the sun's disc spread each
// bundle over a band that widens with depth, across which det changes by
// the band's width times `grad` (per metre; TL_CAUSTIC_BAND says why), so
// det is blurred no closer to 0 than that. Inside a fold three sheets
// light the point (tl_caustics.c says why).
float caustic_rounded(float det, float grad, float depth, float e)
{
    float tilt = (1.0 - 1.0 / u_water_ior) * sqrt(waves_unresolved_slope_variance(TL_NORMAL_OCTAVES, e));
    float spread = depth * (tilt + TL_CAUSTIC_SUN_SPREAD) * grad;
    float k = 1.0 / (TL_CAUSTIC_PEAK * TL_CAUSTIC_PEAK) + spread * spread;
    if (det < 0.0)
        det *= TL_CAUSTIC_FOLD;
    return sqrt((1.0 + k) / (det * det + k));
}

float caustic_det(mat2 g)
{
    return (1.0 + g[0].x) * (1.0 + g[1].y) - g[1].x * g[0].y;
}

// |grad det J| per metre, from g = J - I and the slant's second
// differences along x and z (times depth): the slant is near the gradient
// of one potential, so its mixed derivatives follow from those two
// (tl_caustics.c says how).
float caustic_det_gradient(mat2 g, vec2 along_x, vec2 along_z)
{
    float xz = 0.5 * (g[0].y + g[1].x);
    return length(vec2(along_x.x * (1.0 + g[1].y) + (1.0 + g[0].x) * along_z.x - 2.0 * xz * along_x.y,
                       along_x.y * (1.0 + g[1].y) + (1.0 + g[0].x) * along_z.y - 2.0 * xz * along_z.x));
}

// The points the slant is taken at, in steps from x0: the centre, then
// +x, +z, -x, -z.
const vec2 TL_CAUSTIC_TAPS[5] = vec2[5](vec2(0.0), vec2(1.0, 0.0), vec2(0.0, 1.0), vec2(-1.0, 0.0), vec2(0.0, -1.0));

// What the focus lights: a surface (the sea floor, a hull) shows the web's
// lines sharp, each rounded off by how fast det changes across it; the
// glow through the giant wave's crest and the shafts are gathered along a
// view ray over a range of depths, and take the web as bundles (det
// changing by 1 across a step); the shafts take the coarse web alone.
const int TL_CAUSTIC_ON_SURFACE = 0;
const int TL_CAUSTIC_IN_GLOW = 1;
const int TL_CAUSTIC_IN_SHAFT = 2;

// The irradiance at camera-relative p, `depth` metres under the mean
// surface, in units of a flat sea's: 1 / |det J| of the map from the
// surface to that depth, rounded off at TL_CAUSTIC_PEAK, times the finer
// waves' own (tl_caustics.h) but in a shaft. `footprint`: the pixel's
// width there (metres); `lit`: one of TL_CAUSTIC_*.
float caustic_focus(vec2 p, float depth, float footprint, int lit)
{
    if (depth <= 0.0 || u_sun_dir.y <= 0.0)
        return 1.0;
    float e = max(TL_CAUSTIC_STEP + depth * TL_CAUSTIC_BLUR, footprint);
    float ef = max(TL_CAUSTIC_STEP + depth * TL_CAUSTIC_FINE_BLUR, footprint);
    vec2 x0 = p - (depth / max(-u_sun_water.y, TL_CAUSTIC_MIN_DOWN)) * u_sun_water.xz;
    // One fixed-point step toward the surface point whose bent ray lands
    // here (tl_caustics.c says why).
    x0 = p - depth * caustic_slant(x0, e);
    // The slant at x0 and around it at the coarse step (on a surface, on
    // both sides: central differences and the second differences that
    // give det's gradient; bundles take a forward difference), then at
    // the fine step for the finer web: in one loop, so that the waves' own loop is
    // compiled once (six inlined copies of it took llvmpipe's compiler
    // minutes).
    bool sharp = lit == TL_CAUSTIC_ON_SURFACE;
    int coarse_count = sharp ? 5 : 3;
    int count = coarse_count + (lit != TL_CAUSTIC_IN_SHAFT && ef < TL_CAUSTIC_FINE_GAP * e ? 3 : 0);
    vec2 slant[8];
    for (int i = 0; i < count; i++) {
        bool coarse_tap = i < coarse_count;
        float step = coarse_tap ? e : ef;
        slant[i] = caustic_slant(x0 + step * TL_CAUSTIC_TAPS[coarse_tap ? i : i - coarse_count], step);
    }
    mat2 coarse;
    float grad;
    if (sharp) {
        coarse = mat2(slant[1] - slant[3], slant[2] - slant[4]) * (depth / (2.0 * e));
        float second = depth / (e * e);
        grad = TL_CAUSTIC_BAND * caustic_det_gradient(coarse, (slant[1] - 2.0 * slant[0] + slant[3]) * second,
                                    (slant[2] - 2.0 * slant[0] + slant[4]) * second);
    } else {
        coarse = mat2(slant[1] - slant[0], slant[2] - slant[0]) * (depth / e);
        grad = 1.0 / e;
    }
    float focus = caustic_rounded(caustic_det(coarse), grad, depth, e);
    if (count > coarse_count) {
        int f = coarse_count;
        mat2 fine_map = mat2(slant[f + 1] - slant[f], slant[f + 2] - slant[f]) * (depth / ef) - coarse;
        float unscattered = exp(-u_water_scattering * depth / max(-u_sun_water.y, TL_CAUSTIC_MIN_DOWN));
        float share = TL_CAUSTIC_FINE_SHARE * unscattered;
        focus *= 1.0 + share * (caustic_rounded(caustic_det(fine_map), 1.0 / ef, depth, ef) - 1.0);
    }
    return focus;
}

// The caustics' share of the sun at that point: the focus, by
// underwater.caustics (0: the flat sea's 1).
float caustic_light(vec2 p, float depth, float footprint)
{
    return max(mix(1.0, caustic_focus(p, depth, footprint, TL_CAUSTIC_ON_SURFACE), u_caustics), 0.0);
}

#ifdef TL_FEATURE_GIANT_CAUSTICS
// The caustics in the light through the giant wave's crest
// (tl_caustic_crest): the light that reaches camera-relative `hit` (where
// the ocean's waves see it: the caller rides it with the wave) crossed
// `path` metres of water from where it entered the crest's far side,
// toward the sun, and the ripples there focused it as they focus the sun
// under a level sea; the focus that far along the refracted beam below the
// entry point. The view ray gathers the glow over a range of depths, which
// averages the web: giant.caustics of its contrast is kept, less with the
// path (TL_CAUSTIC_CREST_REACH says why).
float caustic_crest(vec2 hit, float path, float footprint)
{
    if (path <= 0.0)
        return 1.0;
    float depth = path * max(-u_sun_water.y, TL_CAUSTIC_MIN_DOWN);
    vec2 at = hit + path * (u_sun_dir.xz + u_sun_water.xz);
    return mix(1.0, caustic_focus(at, depth, footprint, TL_CAUSTIC_IN_GLOW),
               u_giant_scatter.w * exp(-path / TL_CAUSTIC_CREST_REACH));
}
#endif
