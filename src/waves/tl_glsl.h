/* GLSL's built-ins that the waves' CPU mirrors share with the shaders, in
 * double, so a mirror reads as its shader does. Header-only. */
#ifndef TL_GLSL_H
#define TL_GLSL_H

/* smoothstep(e0, e1, x): 0 up to e0, 1 from e1, Hermite between. */
static inline double tl_smoothstep(double e0, double e1, double x)
{
    double t = (x - e0) / (e1 - e0);
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return t * t * (3.0 - 2.0 * t);
}

#endif
