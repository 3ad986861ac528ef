// The scene target holds radiance premultiplied by the share of a pixel's
// samples that came out finite: rgb sums those samples (each pass adds its
// own, or blends into the running mean), alpha sums their weights. A
// non-finite sample is dropped alone (ocean.frag), whichever pass takes
// it: a pass per sample (the boat), the preview's refinement or one pass
// of all. A pixel whose every sample failed stays black.
vec3 scene_radiance(vec4 texel)
{
    return texel.a > 0.0 ? texel.rgb / texel.a : vec3(0.0);
}
