/* The water's height along a floating object's sides (tl_prepare_internal.h):
 * the CPU evaluates the surface where the hull meets it, so the wash on the
 * hull (shaders/hull_wash.glsl) follows the waves running along it instead
 * of a level plane, which drew it as a painted stripe. */
#include "tl_prepare_internal.h"

void tl_prepare_wash_water(const tl_scene *s, const tl_waves *w, const tl_giant *giant,
                           const tl_boat *b, const float model[16], tl_object_uniforms *o)
{
    o->wash_z[0] = (float)b->model_min[2];
    o->wash_z[1] = (float)b->model_max[2];
    for (int side = 0; side < 2; side++)
        for (int i = 0; i < TL_WASH_STATIONS; i++) {
            /* Just inside the widest beam, at the design waterline. */
            double m[3] = {(side ? 0.45 : -0.45) * (b->model_max[0] - b->model_min[0]) +
                               0.5 * (b->model_max[0] + b->model_min[0]),
                           0.0,
                           b->model_min[2] +
                               (b->model_max[2] - b->model_min[2]) * i / (TL_WASH_STATIONS - 1)};
            double p[3];
            for (int k = 0; k < 3; k++)
                p[k] = model[k] * m[0] + model[4 + k] * m[1] + model[8 + k] * m[2] + model[12 + k];
            double x = p[0] + s->camera.position[0], z = p[2] + s->camera.position[2];
            double height = tl_waves_surface_height(
                w, giant, x, z, s->time, s->quality.march_octaves, s->quality.giant_iterations);
            o->wash_water[side * TL_WASH_STATIONS + i] = (float)(height - s->camera.position[1]);
        }
}
