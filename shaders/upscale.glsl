// Catmull-Rom weights of the four texels around a sample at fraction t
// between the second and the third (upscale.frag, present.frag).
vec4 catmull_rom(float t)
{
    return vec4(t * (-0.5 + t * (1.0 - 0.5 * t)), 1.0 + t * t * (-2.5 + 1.5 * t),
                t * (0.5 + t * (2.0 - 1.5 * t)), t * t * (-0.5 + 0.5 * t));
}

// The four taps weighted by w, held between the two nearest (anti-ringing):
// the kernel still sharpens a gradient, but it cannot overshoot an edge,
// so a glint next to dark water no longer rings into a dark halo with
// bright corners, nor any value go below zero.
vec3 upscale_hold(vec4 w, vec3 tap[4])
{
    vec3 sum = w.x * tap[0] + w.y * tap[1] + w.z * tap[2] + w.w * tap[3];
    return clamp(sum, min(tap[1], tap[2]), max(tap[1], tap[2]));
}
