// The first half of the display pass's Catmull-Rom upscale
// (quality.render_scale < 1): along x only, from the scene's radiance to
// an image as wide as the output and as high as the scene. The display
// pass (present.frag) then runs the same kernel along y. The kernel is
// separable, so the two make what sixteen taps a pixel did in one pass,
// for four taps at half the pixels and four: sixteen taps were most of
// `draft`'s display pass on llvmpipe. Each axis holds its
// result between the two nearest texels (upscale_hold): the kernel's
// negative lobes rang around a sun glint hundreds of times brighter than
// the water, a dark ring with bright corners.
#include "radiance.glsl"
#include "upscale.glsl"

uniform sampler2D u_hdr; // the scene's radiance (radiance.glsl)
uniform int u_out_width;  // the output's width, pixels

layout(location = 0) out vec4 out_row;

void main()
{
    ivec2 size = textureSize(u_hdr, 0);
    float src = gl_FragCoord.x / float(u_out_width) * float(size.x) - 0.5;
    float base = floor(src);
    vec4 w = catmull_rom(src - base);
    int y = int(gl_FragCoord.y);
    vec3 tap[4];
    for (int i = 0; i < 4; i++) {
        int x = clamp(int(base) + i - 1, 0, size.x - 1);
        tap[i] = scene_radiance(texelFetch(u_hdr, ivec2(x, y), 0));
    }
    out_row = vec4(upscale_hold(w, tap), 1.0);
}
