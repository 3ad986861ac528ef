// Glare (render.bloom), at half the output's resolution: the scene's
// light over its mip levels 1 to 6 (box averages, each smoothed by a 3x3
// tent at the level's own texel spacing: the box-filtered chain alone shows
// its blocks around a bright sun). The finest level is two pixels wide, so
// half resolution holds it; the display pass reads this image bilinearly.
// Here, not in the display pass: its 54 taps per pixel cost a quarter as
// much at a quarter of the pixels.

uniform sampler2D u_hdr;   // the scene's radiance, with its mip chain
uniform vec2 u_glare_size; // this pass's pixels

layout(location = 0) out vec4 out_glare;

void main()
{
    vec2 size = vec2(textureSize(u_hdr, 0));
    vec2 uv = gl_FragCoord.xy / u_glare_size;
    vec3 glare = vec3(0.0);
    for (int level = 1; level <= 6; level++) {
        vec2 texel = exp2(float(level)) / size;
        vec3 sum = vec3(0.0);
        for (int j = -1; j <= 1; j++)
            for (int i = -1; i <= 1; i++) {
                float w = float((2 - abs(i)) * (2 - abs(j)));
                sum += w * textureLod(u_hdr, uv + vec2(i, j) * texel, float(level)).rgb;
            }
        glare += sum / 16.0;
    }
    out_glare = vec4(glare / 6.0, 1.0);
}
