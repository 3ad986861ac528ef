#ifndef TL_NOISE_H
#define TL_NOISE_H

/* The value noise of shaders/foam_noise.glsl's foam_noise in double, in [0, 1]:
 * the same integer hash at the same cells, so the CPU mirrors of what the
 * shaders shape with it (the giant wave's spray and lip, the bow's spray)
 * match the GPU's to rounding. */
double tl_noise_value(double x, double y);

#endif
