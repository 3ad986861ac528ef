// Display pass: linear HDR in, tonemapped sRGB out (PNG, movies, window),
// at the output size; it also carries the colour (EXR, without glare) and
// the distance planes to that size. A scene rendered smaller than the
// output (quality.render_scale < 1) is upscaled here: Catmull-Rom for
// radiance, the second of its two axes (upscale.frag did x; each axis held
// between its two nearest texels, upscale_hold), nearest for
// distance (an average of two distances is neither).
// Glare first: a share u_bloom of the light is spread over the image's mip
// levels 1 to 6 (glare.frag; the spread keeps the energy), so a small, very
// bright sun still reads as bright once the tonemap clips it.
// The upscale (TL_PRESENT_UPSCALE) and the glare (TL_PRESENT_GLARE) are
// compiled in only when a frame uses them: llvmpipe runs an `if` body for
// every pixel whether taken or not.
// The planes are written top row first (image order), so that the readback
// needs no row flip: target row r is the image's row r from the top, which
// is GL row (height - 1 - r) of the scene. frag_xy() is that pixel's centre
// in the scene's GL coordinates.
#include "radiance.glsl"
#include "tonemap.glsl"
#ifdef TL_PRESENT_UPSCALE
#include "upscale.glsl"
#endif

uniform sampler2D u_hdr; // the scene's radiance, or with the upscale upscale.frag's rows
uniform sampler2D u_distance;
uniform sampler2D u_glare; // glare.frag's image (TL_PRESENT_GLARE)
uniform ivec2 u_out_size; // the output, pixels
uniform float u_exposure;
uniform vec3 u_white_gain; // the white balance (tl_prepare_white_gain)
uniform float u_bloom;
#ifdef TL_PRESENT_LUT
// An OpenColorIO display transform baked into a table over a log2 shaper
// (src/color/tl_color.h): it takes the place of the ACES fit and the sRGB
// curve, its outputs the display's code values.
uniform sampler3D u_display_lut;

vec3 display_lut(vec3 radiance)
{
    vec3 u = (log2(max(radiance, vec3(1.0e-30))) - TL_COLOR_SHAPER_LO) /
             (TL_COLOR_SHAPER_HI - TL_COLOR_SHAPER_LO);
    float n = float(textureSize(u_display_lut, 0).x);
    return texture(u_display_lut, (clamp(u, 0.0, 1.0) * (n - 1.0) + 0.5) / n).rgb;
}
#endif

layout(location = 0) out vec4 out_display;
layout(location = 1) out vec4 out_color;
layout(location = 2) out float out_depth;

vec2 frag_xy()
{
    return vec2(gl_FragCoord.x, float(u_out_size.y) - gl_FragCoord.y);
}

#ifdef TL_PRESENT_UPSCALE
// The scene's radiance at output position `uv` (0..1), bicubic: along y
// through upscale.frag's rows, which hold the output's columns already.
vec3 upscaled(vec2 uv)
{
    ivec2 size = textureSize(u_hdr, 0);
    float src = uv.y * float(size.y) - 0.5;
    float base = floor(src);
    vec4 w = catmull_rom(src - base);
    int x = int(gl_FragCoord.x);
    vec3 tap[4];
    for (int j = 0; j < 4; j++) {
        int y = clamp(int(base) + j - 1, 0, size.y - 1);
        tap[j] = texelFetch(u_hdr, ivec2(x, y), 0).rgb;
    }
    return upscale_hold(w, tap);
}
#endif

void main()
{
#ifdef TL_PRESENT_UPSCALE
    ivec2 size = textureSize(u_distance, 0);
    vec2 uv = frag_xy() / vec2(u_out_size);
    vec3 hdr = upscaled(uv);
    out_depth = texelFetch(u_distance, clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0).r;
#else
    vec3 hdr = scene_radiance(texelFetch(u_hdr, ivec2(frag_xy()), 0));
    out_depth = texelFetch(u_distance, ivec2(frag_xy()), 0).r;
#endif
    out_color = vec4(hdr, 1.0);
#ifdef TL_PRESENT_GLARE
    vec3 glare = texture(u_glare, frag_xy() / vec2(u_out_size)).rgb;
    hdr = mix(hdr, glare, u_bloom);
#ifdef TL_PRESENT_GLARE_LAYER
    // The glare's light layer: what the display adds to colour * (1 - bloom).
    out_color = vec4(u_bloom * glare, 1.0);
#endif
#endif
    // The white balance, as a camera's: the display's alone (out_color,
    // the EXR's, keeps the scene's light).
    hdr *= u_white_gain;
#ifdef TL_PRESENT_LUT
    out_display = vec4(clamp(display_lut(hdr * u_exposure), 0.0, 1.0), 1.0);
#else
    out_display = vec4(tonemap_srgb_encode(tonemap_aces(hdr * u_exposure)), 1.0);
#endif
}
