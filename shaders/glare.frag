// Glare (render.bloom), at half the output's resolution: the scene's
// light over its mip levels 1 to 6 (box averages, each smoothed by a 3x3
// tent at the level's own texel spacing: the box-filtered chain alone shows
// its blocks around a bright sun). The finest level is two pixels wide, so
// half resolution holds it; the display pass reads this image bilinearly.
// Here, not in the display pass: its taps per pixel cost a quarter as
// much at a quarter of the pixels.

uniform sampler2D u_hdr;   // the scene's radiance, with its mip chain
uniform vec2 u_glare_size; // this pass's pixels

layout(location = 0) out vec4 out_glare;

// Along one axis, the tent (1, 2, 1) / 4 of three bilinear reads one texel
// apart weighs the four texels around the sample (1 - f, 2 - f, 1 + f, f)
// / 4, f the sample's fraction between texels: exactly two bilinear reads,
// one in each texel pair, with weights (3 - 2f) / 4 and (1 + 2f) / 4.
// `src`: the sample in texel units (texel i's centre at i). *pos: the two
// reads' positions in the same units.
vec2 tent_reads(float src, out vec2 pos)
{
    float n = floor(src), f = src - n;
    pos = vec2(n - 1.0 + (2.0 - f) / (3.0 - 2.0 * f), n + 1.0 + f / (1.0 + 2.0 * f));
    return vec2(3.0 - 2.0 * f, 1.0 + 2.0 * f) * 0.25;
}

void main()
{
    vec2 uv = gl_FragCoord.xy / u_glare_size;
    vec2 base = vec2(textureSize(u_hdr, 0));
    vec3 glare = vec3(0.0);
    for (int level = 1; level <= 6; level++) {
        // The level's size by GL's rule, from the base: textureSize of a
        // level past a small image's last one is undefined (textureLod
        // reads the last one there, which this size then matches).
        vec2 size = max(floor(base / exp2(float(level))), vec2(1.0));
        vec2 src = uv * size - 0.5;
        vec2 px, py;
        vec2 wx = tent_reads(src.x, px), wy = tent_reads(src.y, py);
        // Four reads for the nine of the 3x3 tent (separable).
        for (int j = 0; j < 2; j++)
            for (int i = 0; i < 2; i++)
                glare += wx[i] * wy[j] *
                         textureLod(u_hdr, (vec2(px[i], py[j]) + 0.5) / size, float(level)).rgb;
    }
    out_glare = vec4(glare / 6.0, 1.0);
}
