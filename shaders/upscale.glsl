// Catmull-Rom weights of the four texels around a sample at fraction t
// between the second and the third (upscale.frag, present.frag).
vec4 catmull_rom(float t)
{
    return vec4(t * (-0.5 + t * (1.0 - 0.5 * t)), 1.0 + t * t * (-2.5 + 1.5 * t),
                t * (0.5 + t * (2.0 - 1.5 * t)), t * t * (-0.5 + 0.5 * t));
}
