// Height probe: evaluates the surface height at camera-relative points read
// from a texture, one per output texel. Tests compare it with the CPU
// mirror (tl_waves_surface_height).
#include "uniforms.glsl"
#include "waves.glsl"
#ifdef TL_FEATURE_GIANT_WAVE
#include "sky.glsl"
#include "foam.glsl"
#include "giant.glsl"
#endif
#include "surface.glsl"

uniform sampler2D u_points; // .xy = camera-relative (x, z)
uniform int u_probe_octaves;

layout(location = 0) out vec4 out_height;

void main()
{
    vec2 p = texelFetch(u_points, ivec2(gl_FragCoord.xy), 0).xy;
    out_height = vec4(surface_height(p, u_probe_octaves), 0.0, 0.0, 1.0);
}
