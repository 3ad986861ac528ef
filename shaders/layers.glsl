// The light layers (TL_PASS_LAYERS): every source of light in the ocean
// program passes through layer_emit with its layer (TL_LIGHT_*, the C
// enum tl_light_layer). A frame drawn with u_layer = k keeps layer k's
// light alone; everything else the light meets on its way to the eye
// (Fresnel, fog, spray and foam covering it, the meniscus) only scales
// it, so the frames of the layers add up to the frame drawn with them
// all. Without TL_PASS_LAYERS it is the light itself.
#ifdef TL_PASS_LAYERS
uniform int u_layer;
vec3 layer_emit(int layer, vec3 light)
{
    return layer == u_layer ? light : vec3(0.0);
}
#else
#define layer_emit(layer, light) (light)
#endif
