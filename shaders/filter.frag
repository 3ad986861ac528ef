// The pixel filter (quality.pixel_filter): a 3x3 Gaussian over the display
// image, whose values are already tonemapped. Averaging after the tonemap
// bounds what one aliased glint adds to its neighbours (the same filter
// over radiance came out 1 dB further from `reference`), and a pass of its
// own tonemaps each pixel once, not nine times (14 ms of a 640x360 frame
// on llvmpipe). Edges repeat the border pixel.
uniform sampler2D u_display;
uniform float u_filter_side; // a side tap's weight per axis; the centre's is 1 - 2x

layout(location = 0) out vec4 out_display;

void main()
{
    ivec2 last = textureSize(u_display, 0) - 1;
    vec3 weight = vec3(u_filter_side, 1.0 - 2.0 * u_filter_side, u_filter_side);
    vec3 sum = vec3(0.0);
    for (int j = -1; j <= 1; j++)
        for (int i = -1; i <= 1; i++) {
            ivec2 p = clamp(ivec2(gl_FragCoord.xy) + ivec2(i, j), ivec2(0), last);
            sum += weight[i + 1] * weight[j + 1] * texelFetch(u_display, p, 0).rgb;
        }
    out_display = vec4(sum, 1.0);
}
