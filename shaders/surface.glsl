// The whole water surface: the ocean plus every feature that changes its
// height. tl_waves_surface_height is the same sum in double.

float surface_height(vec2 p, int octaves)
{
    float h = waves_height(p, octaves);
#ifdef TL_FEATURE_GIANT_WAVE
    h += giant_height(p);
#endif
    return h;
}
