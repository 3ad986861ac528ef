// Display pass: linear HDR in, tonemapped sRGB out (PNG, movies, window).
#include "tonemap.glsl"

uniform sampler2D u_hdr;
uniform float u_exposure;

layout(location = 0) out vec4 out_display;

void main()
{
    vec3 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb;
    out_display = vec4(tonemap_srgb_encode(tonemap_aces(hdr * u_exposure)), 1.0);
}
