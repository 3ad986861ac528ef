// The preview's false colour (X): each pixel's scene-linear luminance,
// after the exposure, in stops from mid-grey, shown as a camera's false
// colour shows exposure zones (CPU mirror: tl_color_false_colour):
// purple where the display crushes to black, blue just above it, green
// at mid-grey, pink a stop over (skin), yellow just under the tonemap's
// white, red where it clips; grey elsewhere, as bright as the display
// shows that luminance. Window only: never in a file.
#include "radiance.glsl"
#include "tonemap.glsl"

uniform sampler2D u_hdr;  // the scene's radiance, at the render size
uniform float u_exposure; // the display's
uniform ivec4 u_frame;    // the frame's rectangle in the window: x, y, width, height

layout(location = 0) out vec4 out_colour;

vec3 false_colour(float stops, float display_grey)
{
    if (stops < TL_FALSE_COLOUR_BLACK)
        return vec3(0.45, 0.10, 0.55);
    if (stops < TL_FALSE_COLOUR_SHADOW)
        return vec3(0.10, 0.30, 0.85);
    if (abs(stops) < TL_FALSE_COLOUR_BAND)
        return vec3(0.20, 0.75, 0.25);
    if (abs(stops - 1.0) < TL_FALSE_COLOUR_BAND)
        return vec3(0.95, 0.55, 0.65);
    if (stops >= TL_FALSE_COLOUR_CLIP)
        return vec3(0.90, 0.10, 0.10);
    if (stops >= TL_FALSE_COLOUR_HIGHLIGHT)
        return vec3(0.95, 0.85, 0.15);
    return vec3(display_grey);
}

void main()
{
    vec2 uv = (gl_FragCoord.xy - vec2(u_frame.xy)) / vec2(u_frame.zw);
    ivec2 size = textureSize(u_hdr, 0);
    ivec2 at = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    vec3 hdr = scene_radiance(texelFetch(u_hdr, at, 0)) * u_exposure;
    float lum = dot(hdr, vec3(0.2126, 0.7152, 0.0722));
    float stops = log2(max(lum, 1.0e-12) / 0.18);
    float grey = tonemap_srgb_encode(tonemap_aces(vec3(lum))).g;
    out_colour = vec4(false_colour(stops, grey), 1.0);
}
