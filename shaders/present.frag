// Display pass: linear HDR in, tonemapped sRGB out (PNG, movies, window).
// Glare first: a share u_bloom of the light is spread over the image's mip
// levels 1 to 6 (box averages, smoothed by a tent: the spread keeps the
// energy), so a small, very bright sun still reads as bright once the
// tonemap clips it.
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
        vec2 size = vec2(textureSize(u_hdr, 0));
        vec2 uv = gl_FragCoord.xy / size;
        vec3 glare = vec3(0.0);
        for (int level = 1; level <= 6; level++) {
            // A 3x3 tent at the level's own texel spacing: the box-filtered
            // mip chain alone shows its blocks around a bright sun.
            vec2 texel = exp2(float(level)) / size;
            vec3 sum = vec3(0.0);
            for (int j = -1; j <= 1; j++)
                for (int i = -1; i <= 1; i++) {
                    float w = float((2 - abs(i)) * (2 - abs(j)));
                    sum += w * textureLod(u_hdr, uv + vec2(i, j) * texel, float(level)).rgb;
                }
            glare += sum / 16.0;
        }
        hdr = mix(hdr, glare / 6.0, u_bloom);
    }
    out_display = vec4(tonemap_srgb_encode(tonemap_aces(hdr * u_exposure)), 1.0);
}
