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

// Normalised wave value in (0, 1] from the first `octaves` octaves.
float waves_value(vec2 p, int octaves)
{
    float shift = waves_radial_shift(p);
    float sum = 0.0;
    float weights = 0.0;
    for (int i = 0; i < octaves; i++) {
        vec4 w = u_wave[i];
        float weight = u_wave_weight[i];
        float x = dot(w.xy, p) * w.z + w.w + shift;
        float wave = exp(sin(x) - 1.0);
        // Derivative drag: small waves gather on the crests of large ones.
        p -= w.xy * (wave * cos(x) * weight * u_drag);
        sum += wave * weight;
        weights += weight;
    }
    return sum / weights;
}

// World height of the surface at camera-relative p: in [-depth, 0].
float waves_height(vec2 p, int octaves)
{
    return (waves_value(p, octaves) - 1.0) * u_depth;
}
