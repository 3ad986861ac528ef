// Glare (render.bloom), at a quarter of the output's resolution
// (TL_GLARE_DIVISOR): the scene's light over its mip levels 1 to 6 (box
// averages, each read through a cubic B-spline of its texels: the
// box-filtered chain alone shows its blocks around a bright sun, and a
// tent of bilinear reads, only continuous, still showed the coarsest
// level's square as a lit box on the dark face under a sun behind the
// giant wave). Even the finest level's B-spline, two output pixels a
// texel and smooth, is as good as whole at a quarter of the resolution
// once the display pass reads this image bilinearly: nearly the image at
// half resolution, as close to `reference`, for a quarter of the pixels'
// work. Here, not in the display pass: its
// taps per pixel cost a sixteenth as much at a sixteenth of the pixels.

uniform sampler2D u_hdr;   // the scene's radiance (radiance.glsl), with its mip chain
uniform vec2 u_glare_size; // this pass's pixels
uniform float u_glare_shift; // log2 of the output over the scene's size, rounded

layout(location = 0) out vec4 out_glare;

// Along one axis, the cubic B-spline through the level's texels at the
// sample's fraction f between them: weights (1-f)^3, 3f^3-6f^2+4,
// -3f^3+3f^2+3f+1, f^3 (over 6) on the four texels around it, all
// positive, so two bilinear reads give them exactly.
vec2 bspline_reads(float src, out vec2 pos)
{
    float n = floor(src), f = src - n;
    float f2 = f * f, f3 = f2 * f;
    vec4 w = vec4(1.0 - 3.0 * f + 3.0 * f2 - f3, 3.0 * f3 - 6.0 * f2 + 4.0,
                  -3.0 * f3 + 3.0 * f2 + 3.0 * f + 1.0, f3) / 6.0;
    vec2 g = vec2(w.x + w.y, w.z + w.w);
    pos = vec2(n - 1.0 + w.y / g.x, n + 1.0 + w.w / g.y);
    return g;
}

void main()
{
    vec2 uv = gl_FragCoord.xy / u_glare_size;
    vec2 base = vec2(textureSize(u_hdr, 0));
    // Premultiplied sums: the weights of the good samples among the texels
    // read, six levels' worth where all were good (radiance.glsl).
    vec4 glare = vec4(0.0);
    for (int level = 1; level <= 6; level++) {
        // The level's size by GL's rule, from the base: textureSize of a
        // level past a small image's last one is undefined (textureLod
        // reads the last one there, which this size then matches).
        // A scene rendered at half the output's size holds at its level k
        // what a full-size one holds at k + 1: the glare reads the level
        // whose texels are as wide in output pixels (render_scale).
        float lod = max(float(level) - u_glare_shift, 0.0);
        vec2 size = max(floor(base / exp2(lod)), vec2(1.0));
        vec2 src = uv * size - 0.5;
        vec2 px, py;
        vec2 wx = bspline_reads(src.x, px), wy = bspline_reads(src.y, py);
        // Four reads for the sixteen texels (separable).
        for (int j = 0; j < 2; j++)
            for (int i = 0; i < 2; i++)
                glare += wx[i] * wy[j] *
                         textureLod(u_hdr, (vec2(px[i], py[j]) + 0.5) / size, lod);
    }
    out_glare = vec4(glare.a > 0.0 ? glare.rgb / glare.a : vec3(0.0), 1.0);
}
