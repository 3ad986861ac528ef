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

/* The focus of a map whose Jacobian has determinant `det`, taken over a
 * step e at `depth`, rounded off. The octaves the step leaves out still
 * tilt the rays, by their RMS slope times (1 - 1/ior), and the sun's disc
 * is no point: each bundle lands spread over a band that widens with
 * depth. Across that band det changes by its width times `grad` (per
 * metre: TL_CAUSTIC_BAND times |grad det| for the coarse web, 1 / e where
 * det is taken to change by 1 across the step), so the blurred det comes
 * no closer to 0 than that. */
static double rounded_focus(const tl_waves *w, const tl_caustic_light *l, double det, double grad,
                            double depth, double e, int octaves)
{
    double tilt = (1.0 - 1.0 / l->ior) * sqrt(tl_waves_unresolved_slope_variance(w, octaves, e));
    double spread = depth * (tilt + TL_CAUSTIC_SUN_SPREAD) * grad;
    /* Past a fold (det < 0) three sheets of the surface light the point
     * and the one followed here is the dimmest: the band between a fold's
     * two lines is lit as brightly as the lines' sides, not left dark. */
    if (det < 0.0)
        det *= TL_CAUSTIC_FOLD;
    double k = 1.0 / (TL_CAUSTIC_PEAK * TL_CAUSTIC_PEAK) + spread * spread;
    return sqrt((1.0 + k) / (det * det + k));
}

/* (J - I) of the map to `depth` at surface point (x0, z0), by a forward
 * difference over e of the slant `a` there (the finer web's). */
static void map_gradient(const tl_waves *w, const tl_caustic_light *l, double x0, double z0,
                         double t, int octaves, double e, double depth, const double a[2],
                         double out[4])
{
    double ax[2], az[2];
    slant(w, l, x0 + e, z0, t, octaves, e, ax);
    slant(w, l, x0, z0 + e, t, octaves, e, az);
    double s = depth / e;
    out[0] = (ax[0] - a[0]) * s; /* d(run x)/dx */
    out[1] = (ax[1] - a[1]) * s; /* d(run z)/dx */
    out[2] = (az[0] - a[0]) * s; /* d(run x)/dz */
    out[3] = (az[1] - a[1]) * s; /* d(run z)/dz */
}

static double det_of(const double g[4])
{
    return (1.0 + g[0]) * (1.0 + g[3]) - g[2] * g[1];
}

/* (J - I) at (x0, z0) by central differences over e of the slant (`a`
 * there), and |grad det J| per metre. The slant is close to the gradient
 * of one potential phi (exactly so for small slopes), so J - I = depth ·
 * Hess(phi), and grad det needs phi's third derivatives: phi_xxx and
 * phi_xxz are the second differences along x of the run's x and z,
 * phi_xzz and phi_zzz those along z. Four taps around x0 give them all. */
static double map_gradient_central(const tl_waves *w, const tl_caustic_light *l, double x0,
                                   double z0, double t, int octaves, double e, double depth,
                                   const double a[2], double g[4])
{
    double px[2], pz[2], mx[2], mz[2];
    slant(w, l, x0 + e, z0, t, octaves, e, px);
    slant(w, l, x0, z0 + e, t, octaves, e, pz);
    slant(w, l, x0 - e, z0, t, octaves, e, mx);
    slant(w, l, x0, z0 - e, t, octaves, e, mz);
    double s = depth / (2.0 * e), s2 = depth / (e * e);
    g[0] = (px[0] - mx[0]) * s;
    g[1] = (px[1] - mx[1]) * s;
    g[2] = (pz[0] - mz[0]) * s;
    g[3] = (pz[1] - mz[1]) * s;
    double xxx = (px[0] - 2.0 * a[0] + mx[0]) * s2, xxz = (px[1] - 2.0 * a[1] + mx[1]) * s2;
    double xzz = (pz[0] - 2.0 * a[0] + mz[0]) * s2, zzz = (pz[1] - 2.0 * a[1] + mz[1]) * s2;
    double xz = 0.5 * (g[1] + g[2]);
    double gx = xxx * (1.0 + g[3]) + (1.0 + g[0]) * xzz - 2.0 * xz * xxz;
    double gz = xxz * (1.0 + g[3]) + (1.0 + g[0]) * zzz - 2.0 * xz * xzz;
    return sqrt(gx * gx + gz * gz);
}

/* The focus (tl_caustic_focus); `on_surface`: lighting a surface, whose
 * lines are rounded off by how fast det changes across them; else the
 * crest's glow, gathered over a range of depths, which takes the web as
 * bundles (det changing by 1 across the step). */
static double focus_at(const tl_waves *w, const tl_caustic_light *l, double x, double z,
                       double depth, double t, int octaves, double footprint, int on_surface)
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
    double a[2], coarse[4];
    slant(w, l, x0, z0, t, octaves, e, a);
    x0 = x - depth * a[0];
    z0 = z - depth * a[1];
    slant(w, l, x0, z0, t, octaves, e, a);
    double grad = 1.0 / e;
    if (on_surface)
        grad =
            TL_CAUSTIC_BAND * map_gradient_central(w, l, x0, z0, t, octaves, e, depth, a, coarse);
    else
        map_gradient(w, l, x0, z0, t, octaves, e, depth, a, coarse);
    double focus = rounded_focus(w, l, det_of(coarse), grad, depth, e, octaves);
    /* The finer waves' own map: their Jacobian is the finer step's less
     * the coarse waves' (tl_caustics.h). */
    double ef = fmax(TL_CAUSTIC_STEP + depth * TL_CAUSTIC_FINE_BLUR, footprint);
    if (ef < TL_CAUSTIC_FINE_GAP * e) {
        double af[2], fine[4];
        slant(w, l, x0, z0, t, octaves, ef, af);
        map_gradient(w, l, x0, z0, t, octaves, ef, depth, af, fine);
        for (int i = 0; i < 4; i++)
            fine[i] -= coarse[i];
        /* Its det is taken to change by 1 across its step. */
        double f = rounded_focus(w, l, det_of(fine), 1.0 / ef, depth, ef, octaves);
        double unscattered =
            exp(-l->scattering * depth / fmax(-l->sun_water[1], TL_CAUSTIC_MIN_DOWN));
        focus *= 1.0 + TL_CAUSTIC_FINE_SHARE * unscattered * (f - 1.0);
    }
    return focus;
}

double tl_caustic_focus(const tl_waves *w, const tl_caustic_light *l, double x, double z,
                        double depth, double t, int octaves, double footprint)
{
    return focus_at(w, l, x, z, depth, t, octaves, footprint, 1);
}

double tl_caustic_crest(const tl_waves *w, const tl_caustic_light *l, double x, double z,
                        double path, double t, int octaves, double footprint, double share)
{
    if (!(share > 0.0) || !(path > 0.0))
        return 1.0;
    /* The entry point is (x, z) + path·sun; the point `depth` under a level
     * surface there along the refracted beam lies path·sun_water beyond it. */
    double depth = path * fmax(-l->sun_water[1], TL_CAUSTIC_MIN_DOWN);
    double ax = x + path * (l->sun_dir[0] + l->sun_water[0]);
    double az = z + path * (l->sun_dir[2] + l->sun_water[2]);
    double focus = focus_at(w, l, ax, az, depth, t, octaves, footprint, 0);
    return 1.0 + share * exp(-path / TL_CAUSTIC_CREST_REACH) * (focus - 1.0);
}

double tl_caustic_beam_spread(const tl_waves *w, double ior, int octaves)
{
    double slope_var = tl_waves_unresolved_slope_variance(w, octaves, HUGE_VAL);
    return (1.0 - 1.0 / ior) * sqrt(fmax(slope_var, 0.0)) + TL_CAUSTIC_SUN_SPREAD;
}
