// The exp(sin) wave sum with derivative drag (seed 002), evaluated at a
// camera-relative xz position. tl_waves.c is the same model in double.

// Phase shift that grows with distance from the world origin, as the
// reference's length(position) * 0.1, written as the camera's share (folded
// into the per-octave phases on the CPU) plus the local change
// |ref + p| - |ref| = (2|ref|(d·p) + p·p) / (|ref + p| + |ref|), which has
// no cancellation however far the camera is from the origin.
float waves_radial_shift(vec2 p)
{
    float l = u_radial_len;
    float along = dot(u_radial_dir, p);
    float num = 2.0 * l * along + dot(p, p);
    float den = sqrt(max(l * l + num, 0.0)) + l;
    return u_radial_phase * (den > 0.0 ? num / den : 0.0);
}

// The mean of one octave, exp(sin x - 1) over a period (I0(1) / e): what
// an octave too fine for the pixel averages to.
const float TL_WAVE_MEAN = 0.4657596;

// How much of an octave of `frequency` (rad/m) a pixel covering
// `footprint` metres resolves: 1 while its wavelength spans four footprints
// or more, 0 at two and below (level of detail).
float waves_detail(float frequency, float footprint)
{
    return smoothstep(2.0, 4.0, 2.0 * TL_PI / (frequency * footprint));
}

// Normalised wave value in (0, 1] from the first `octaves` octaves.
// `footprint`: the width of water one pixel covers there (metres; 0 for
// none). Level of detail: an octave whose wavelength spans fewer than four
// footprints fades to its mean and its drag to nothing, and is gone at two
// (below that it could only alias); once one is gone, so are all finer
// ones, and the loop ends.
float waves_value(vec2 p, int octaves, float footprint)
{
    float shift = waves_radial_shift(p);
    float sum = 0.0;
    float weights = 0.0;
    for (int i = 0; i < octaves; i++) {
        vec4 w = u_wave[i];
        float weight = u_wave_weight[i];
        float x = dot(w.xy, p) * w.z + w.w + shift;
#ifdef TL_FEATURE_LOD
        float detail = footprint > 0.0 ? waves_detail(w.z, footprint) : 1.0;
        if (detail <= 0.0) {
            float rest = u_wave_weight_tail[i] - u_wave_weight_tail[octaves];
            sum += TL_WAVE_MEAN * rest;
            weights += rest;
            break;
        }
        float wave = exp(sin(x) - 1.0);
        p -= w.xy * (wave * cos(x) * weight * u_drag * detail);
        sum += (detail < 1.0 ? mix(TL_WAVE_MEAN, wave, detail) : wave) * weight;
#else
        // The reference shader's octave, operation for operation.
        float wave = exp(sin(x) - 1.0);
        // Derivative drag: small waves gather on the crests of large ones.
        p -= w.xy * (wave * cos(x) * weight * u_drag);
        sum += wave * weight;
#endif
        weights += weight;
    }
    return sum / weights;
}

// The mean over a period of (exp(sin x - 1)·cos x)²: an octave's squared
// slope, per unit of weight times frequency (tl_waves.h has the same).
const float TL_WAVE_SLOPE_MEAN_SQ = 0.1076346;

// Per axis, the variance of the surface's slope that level of detail took
// out: the faded share of each octave (1 - detail²) and every octave
// finer than the last one kept, to TL_MAX_OCTAVES. `raw`: the sum of
// faded (weight·frequency)² times the mean square; `weights`: the sum
// the wave value is normalised by.
float waves_slope_variance(float raw, float weights)
{
    float slope_scale = u_depth / weights;
    return 0.5 * raw * slope_scale * slope_scale;
}

// The slope variance of the octaves finer than `footprint` resolves (the
// share each fades by, and every octave past the first `octaves`):
// filtered shading's roughness, and what blurs the caustics deep down.
float waves_unresolved_slope_variance(int octaves, float footprint)
{
    float raw = 0.0;
    int i = 0;
    for (; i < octaves; i++) {
        float detail = waves_detail(u_wave[i].z, footprint);
        if (detail <= 0.0)
            break;
        float wk = u_wave_weight[i] * u_wave[i].z;
        raw += (1.0 - detail * detail) * TL_WAVE_SLOPE_MEAN_SQ * wk * wk;
    }
    raw += u_wave_slope_tail[i];
    return waves_slope_variance(raw, u_wave_weight_tail[0] - u_wave_weight_tail[octaves]);
}

// The same for waves_value's octaves at this footprint, without the waves
// (the finite-difference normals' path); 0 without filtered shading.
float waves_faded_slope_variance(int octaves, float footprint)
{
#ifdef TL_FEATURE_FILTERED_SHADING
    if (footprint > 0.0)
        return waves_unresolved_slope_variance(octaves, footprint);
#endif
    return 0.0;
}

// waves_value with its gradient (per metre of p) carried through the drag:
// J is how the dragged position moves with p, so each octave's phase
// gradient is f·dᵀJ plus the radial shift's. One pass gives what finite
// differences need three for, and it is exact. *slope_var: as
// waves_faded_slope_variance (0 without filtered shading).
float waves_value_grad(vec2 p, int octaves, float footprint, out vec2 grad, out float slope_var)
{
    float shift = waves_radial_shift(p);
    vec2 q = u_radial_dir * u_radial_len + p; // from the world origin
    float ql = length(q);
    vec2 shift_grad = ql > 0.0 ? u_radial_phase * q / ql : vec2(0.0);
    mat2 jac = mat2(1.0);
    float sum = 0.0, weights = 0.0, faded = 0.0;
    vec2 sum_grad = vec2(0.0);
    int i = 0;
    for (; i < octaves; i++) {
        vec4 w = u_wave[i];
        float weight = u_wave_weight[i];
        float detail = 1.0;
// Caustics fade the octaves finer than their step whatever the preset
// (where LOD is off, every other caller's footprint is 0).
#if defined(TL_FEATURE_LOD) || defined(TL_FEATURE_CAUSTICS) || defined(TL_FEATURE_GIANT_CAUSTICS)
        if (footprint > 0.0) {
            detail = waves_detail(w.z, footprint);
            if (detail <= 0.0) {
                float rest = u_wave_weight_tail[i] - u_wave_weight_tail[octaves];
                sum += TL_WAVE_MEAN * rest;
                weights += rest;
                break;
            }
#ifdef TL_FEATURE_FILTERED_SHADING
            float wk = weight * w.z;
            faded += (1.0 - detail * detail) * TL_WAVE_SLOPE_MEAN_SQ * wk * wk;
#endif
        }
#endif
        float x = dot(w.xy, p) * w.z + w.w + shift;
        vec2 x_grad = w.z * (w.xy * jac) + shift_grad; // row vector dᵀJ
        float s = sin(x), c = cos(x);
        float wave = exp(s - 1.0);
        float k = weight * u_drag * detail;
        p -= w.xy * (wave * c * k);
        // d(wave·cos x)/dx = wave·(cos²x − sin x)
        jac -= outerProduct(w.xy, (wave * (c * c - s) * k) * x_grad);
        sum += (detail < 1.0 ? mix(TL_WAVE_MEAN, wave, detail) : wave) * weight;
        sum_grad += (wave * c * weight * detail) * x_grad;
        weights += weight;
    }
#ifdef TL_FEATURE_FILTERED_SHADING
    // Octaves i.. were not summed: finer than the pixel, or beyond the
    // preset's count.
    slope_var = footprint > 0.0 ? waves_slope_variance(faded + u_wave_slope_tail[i], weights) : 0.0;
#else
    slope_var = 0.0;
#endif
    grad = sum_grad / weights;
    return sum / weights;
}

// World height of the surface at camera-relative p: in [-depth, 0].
float waves_height(vec2 p, int octaves, float footprint)
{
    return (waves_value(p, octaves, footprint) - 1.0) * u_depth;
}
