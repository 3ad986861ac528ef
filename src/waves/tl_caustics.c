#include "tl_caustics.h"

#include <math.h>

/* The refracted sun's horizontal run per metre down, leaving the surface
 * at (x, z). The normal is the height field's, its gradient a central
 * difference (the shader's is analytic; in double the two agree far
 * below float's precision). */
static void slant(const tl_waves *w, const tl_caustic_light *l, double x, double z, double t,
                  int octaves, double footprint, double out[2])
{
    const double h = 1e-5;
    double dx = (tl_waves_value_lod(w, x + h, z, t, octaves, footprint) -
                 tl_waves_value_lod(w, x - h, z, t, octaves, footprint)) /
                (2.0 * h) * w->depth;
    double dz = (tl_waves_value_lod(w, x, z + h, t, octaves, footprint) -
                 tl_waves_value_lod(w, x, z - h, t, octaves, footprint)) /
                (2.0 * h) * w->depth;
    double norm = sqrt(dx * dx + 1.0 + dz * dz);
    double n[3] = {-dx / norm, 1.0 / norm, -dz / norm};
    /* GLSL's refract(I, N, eta) with I the light's way (-sun), eta 1/ior. */
    double in[3] = {-l->sun_dir[0], -l->sun_dir[1], -l->sun_dir[2]};
    double eta = 1.0 / l->ior;
    double ni = n[0] * in[0] + n[1] * in[1] + n[2] * in[2];
    double k = 1.0 - eta * eta * (1.0 - ni * ni);
    double r[3] = {0.0, -1.0, 0.0};
    if (k >= 0.0)
        for (int c = 0; c < 3; c++)
            r[c] = eta * in[c] - (eta * ni + sqrt(k)) * n[c];
    double down = fmin(r[1], -TL_CAUSTIC_MIN_DOWN);
    out[0] = r[0] / -down;
    out[1] = r[2] / -down;
}

double tl_caustic_focus(const tl_waves *w, const tl_caustic_light *l, double x, double z,
                        double depth, double t, int octaves, double footprint)
{
    if (!(depth > 0.0) || !(l->sun_dir[1] > 0.0))
        return 1.0;
    double e = fmax(TL_CAUSTIC_STEP + depth * TL_CAUSTIC_BLUR, footprint);
    /* Where the straight refracted ray to (x, z) left the surface. */
    double run = depth / fmax(-l->sun_water[1], TL_CAUSTIC_MIN_DOWN);
    double x0 = x - run * l->sun_water[0], z0 = z - run * l->sun_water[2];
    /* One fixed-point step toward the surface point whose bent ray lands
     * here: without it the estimate is taken where the light would have
     * crossed a flat sea, and it no longer conserves the light on
     * average. */
    double a[2], ax[2], az[2];
    slant(w, l, x0, z0, t, octaves, e, a);
    x0 = x - depth * a[0];
    z0 = z - depth * a[1];
    slant(w, l, x0, z0, t, octaves, e, a);
    slant(w, l, x0 + e, z0, t, octaves, e, ax);
    slant(w, l, x0, z0 + e, t, octaves, e, az);
    double s = depth / e;
    double jxx = 1.0 + (ax[0] - a[0]) * s, jzx = (ax[1] - a[1]) * s;
    double jxz = (az[0] - a[0]) * s, jzz = 1.0 + (az[1] - a[1]) * s;
    double det = jxx * jzz - jxz * jzx;
    /* The octaves the step leaves out still tilt the rays, by their RMS
     * slope times (1 - 1/ior), and the sun's disc is no point: each
     * bundle lands spread over a band that widens with depth. Near a
     * focus det changes by about 1 across a step, so a line that wide
     * cannot fall below its width / e in det: the rounding widens and
     * dims the lines deep down, as the light shows there. */
    double tilt = (1.0 - 1.0 / l->ior) * sqrt(tl_waves_unresolved_slope_variance(w, octaves, e));
    double spread = depth * (tilt + TL_CAUSTIC_SUN_SPREAD) / e;
    double k = 1.0 / (TL_CAUSTIC_PEAK * TL_CAUSTIC_PEAK) + spread * spread;
    /* Past a fold (det < 0) three sheets of the surface light the point
     * and the one followed here is the dimmest: the band between a fold's
     * two lines is lit as brightly as the lines' sides, not left dark. */
    if (det < 0.0)
        det *= TL_CAUSTIC_FOLD;
    return sqrt((1.0 + k) / (det * det + k));
}
