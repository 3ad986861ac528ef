// Display pass: linear HDR in, tonemapped sRGB out (PNG, movies, window).
// Glare first: a share u_bloom of the light is spread over the image's mip
// levels 1 to 6 (each a box average, so the spread keeps the energy), so a
// small, very bright sun still reads as bright once the tonemap clips it.
// EXR files hold the colour plane, without glare.
#include "tonemap.glsl"

uniform sampler2D u_hdr;
uniform float u_exposure;
uniform float u_bloom;

layout(location = 0) out vec4 out_display;

void main()
{
    vec3 hdr = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb;
    if (u_bloom > 0.0) {
        vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_hdr, 0));
        vec3 glare = vec3(0.0);
        for (int level = 1; level <= 6; level++)
            glare += textureLod(u_hdr, uv, float(level)).rgb;
        hdr = mix(hdr, glare / 6.0, u_bloom);
    }
    out_display = vec4(tonemap_srgb_encode(tonemap_aces(hdr * u_exposure)), 1.0);
}
