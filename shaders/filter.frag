// The pixel filter (quality.pixel_filter): a 3x3 Gaussian over the display
// image, whose values are already tonemapped. Averaging after the tonemap
// bounds what one aliased glint adds to its neighbours (the same filter
// over radiance came out further from `reference`), and a pass of its
// own tonemaps each pixel once, not nine times.
//
// The kernel is separable, (a, 1 - 2a, a) along each axis, and bilinear
// taps give it exactly from four reads instead of nine: along one axis,
// taps at -2a and +2a texels, half each, weigh the neighbours a and the
// centre 1 - 2a. Edges repeat the border pixel (clamp to edge).
uniform sampler2D u_display; // bilinear
uniform float u_filter_offset; // 2a, texels

layout(location = 0) out vec4 out_display;

void main()
{
    vec2 texel = 1.0 / vec2(textureSize(u_display, 0));
    vec2 at = gl_FragCoord.xy * texel, d = u_filter_offset * texel;
    vec3 sum = texture(u_display, at + vec2(-d.x, -d.y)).rgb;
    sum += texture(u_display, at + vec2(d.x, -d.y)).rgb;
    sum += texture(u_display, at + vec2(-d.x, d.y)).rgb;
    sum += texture(u_display, at + vec2(d.x, d.y)).rgb;
    out_display = vec4(0.25 * sum, 1.0);
}
