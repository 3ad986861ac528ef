// The whole water surface: the ocean plus every feature that changes its
// height. tl_waves_surface_height is the same sum in double.

// `footprint`: the water a pixel covers there, for the ocean's level of
// detail (0: every octave); the giant wave is always whole.
float surface_height(vec2 p, int octaves, float footprint)
{
    float h = waves_height(p, octaves, footprint);
#ifdef TL_FEATURE_GIANT_WAVE
    h += giant_height(p);
#endif
    return h;
}
