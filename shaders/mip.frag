// One mip level of the scene's radiance, for the glare (glare.frag): each
// texel the mean of the 2x2 texels under it in the level above (the last
// row or column of an odd size is left out, the edge repeats where a
// level is one texel thin). The texels are premultiplied (radiance.glsl),
// so the mean weighs each by its good samples. A pass per level, not
// glGenerateMipmap, whose filter each driver chooses: the glare is the
// same on llvmpipe and on a GPU (docs/rendering.md, "Glare").

uniform sampler2D u_src; // its base level is the level above this one

layout(location = 0) out vec4 out_level;

void main()
{
    ivec2 last = textureSize(u_src, 0) - 1;
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    out_level = 0.25 * (texelFetch(u_src, min(p, last), 0) +
                        texelFetch(u_src, min(p + ivec2(1, 0), last), 0) +
                        texelFetch(u_src, min(p + ivec2(0, 1), last), 0) +
                        texelFetch(u_src, min(p + ivec2(1, 1), last), 0));
}
