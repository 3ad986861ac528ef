#include "tl_waves.h"

#include <math.h>

void tl_waves_init(tl_waves *w, const tl_ocean *ocean)
{
    w->count = TL_MAX_OCTAVES;
    w->drag = ocean->drag;
    w->depth = ocean->depth;
    w->radial_phase = ocean->radial_phase;
    /* The reference shader accumulates the direction angle in a float; doing
     * the same keeps our octave directions identical to its. */
    float angle = 0.0f;
    double frequency = ocean->frequency, speed = ocean->speed, weight = 1.0;
    for (int i = 0; i < TL_MAX_OCTAVES; i++) {
        tl_wave_octave *o = &w->octave[i];
        o->dir_x = sin((double)angle);
        o->dir_z = cos((double)angle);
        o->frequency = frequency;
        o->speed = speed;
        o->weight = weight;
        angle += (float)ocean->direction_step;
        frequency *= ocean->frequency_growth;
        speed *= ocean->speed_growth;
        weight *= ocean->weight_ratio;
    }
}

double tl_waves_value(const tl_waves *w, double x, double z, double t, int octaves)
{
    return tl_waves_value_lod(w, x, z, t, octaves, 0.0);
}

double tl_waves_detail(double frequency, double footprint)
{
    double x = (2.0 * M_PI / (frequency * footprint) - 2.0) / 2.0;
    x = fmin(fmax(x, 0.0), 1.0);
    return x * x * (3.0 - 2.0 * x);
}

double tl_waves_value_lod(const tl_waves *w, double x, double z, double t, int octaves,
                          double footprint)
{
    if (octaves > w->count)
        octaves = w->count;
    /* The radial term uses the unwarped position, as in the reference. */
    double radial = w->radial_phase * hypot(x, z);
    double sum = 0.0, weights = 0.0;
    for (int i = 0; i < octaves; i++) {
        const tl_wave_octave *o = &w->octave[i];
        double detail = footprint > 0.0 ? tl_waves_detail(o->frequency, footprint) : 1.0;
        if (detail <= 0.0) { /* this octave and every finer one: their mean */
            for (int k = i; k < octaves; k++) {
                sum += TL_WAVE_MEAN * w->octave[k].weight;
                weights += w->octave[k].weight;
            }
            break;
        }
        double phase = o->frequency * (o->dir_x * x + o->dir_z * z) + o->speed * t + radial;
        double wave = exp(sin(phase) - 1.0);
        double slope = wave * cos(phase);
        /* Derivative drag: later octaves ride on the crests of earlier ones. */
        x -= o->dir_x * slope * o->weight * w->drag * detail;
        z -= o->dir_z * slope * o->weight * w->drag * detail;
        sum += (detail < 1.0 ? TL_WAVE_MEAN + (wave - TL_WAVE_MEAN) * detail : wave) * o->weight;
        weights += o->weight;
    }
    return weights > 0.0 ? sum / weights : 1.0;
}

double tl_waves_unresolved_slope_variance(const tl_waves *w, int octaves, double footprint)
{
    if (octaves > w->count)
        octaves = w->count;
    double raw = 0.0, weights = 0.0;
    int i = 0;
    for (; i < octaves; i++) {
        double detail = tl_waves_detail(w->octave[i].frequency, footprint);
        if (detail <= 0.0)
            break;
        double wk = w->octave[i].weight * w->octave[i].frequency;
        raw += (1.0 - detail * detail) * TL_WAVE_SLOPE_MEAN_SQ * wk * wk;
    }
    for (; i < w->count; i++) {
        double wk = w->octave[i].weight * w->octave[i].frequency;
        raw += TL_WAVE_SLOPE_MEAN_SQ * wk * wk;
    }
    for (int k = 0; k < octaves; k++)
        weights += w->octave[k].weight;
    double scale = weights > 0.0 ? w->depth / weights : 0.0;
    return 0.5 * raw * scale * scale;
}

double tl_waves_capillary_slope_variance(const tl_waves *w, int octaves, double share)
{
    /* Every octave is finer than an endless footprint: their total. */
    return share * tl_waves_unresolved_slope_variance(w, octaves, HUGE_VAL);
}

double tl_waves_height(const tl_waves *w, double x, double z, double t, int octaves)
{
    return (tl_waves_value(w, x, z, t, octaves) - 1.0) * w->depth;
}

double tl_waves_surface_height(const tl_waves *w, const tl_giant *g, double x, double z, double t,
                               int octaves, int giant_iterations)
{
    if (!g || !g->active)
        return tl_waves_height(w, x, z, t, octaves);
    tl_giant_sample smp;
    tl_giant_sample_at(g, x, z, giant_iterations, &smp);
    double q[2];
    tl_giant_ride_point(g, &smp, x, z, q);
    return tl_waves_height(w, q[0], q[1], t, octaves) + smp.height;
}

int tl_waves_surfaces(const tl_waves *w, const tl_giant *g, double x, double z, double t,
                      int octaves, int giant_iterations, double *heights, int max)
{
    if (max < 1)
        return 0;
    heights[0] = tl_waves_surface_height(w, g, x, z, t, octaves, giant_iterations);
    int n = 1;
    if (g && g->active)
        n += tl_giant_lip_heights(g, x, z, heights[0], -0.5 * w->depth, heights + 1, max - 1);
    return n;
}

void tl_waves_phases(const tl_waves *w, double ref_x, double ref_z, double t, int octaves,
                     double *phase_out)
{
    const double two_pi = 2.0 * M_PI;
    double radial = fmod(w->radial_phase * hypot(ref_x, ref_z), two_pi);
    for (int i = 0; i < octaves && i < w->count; i++) {
        const tl_wave_octave *o = &w->octave[i];
        /* Reduce each large term on its own before summing, so the sum never
         * carries more magnitude than a few turns. */
        double spatial = fmod(o->frequency * (o->dir_x * ref_x + o->dir_z * ref_z), two_pi);
        double temporal = fmod(o->speed * t, two_pi);
        double p = fmod(spatial + temporal + radial, two_pi);
        if (p < 0.0)
            p += two_pi;
        phase_out[i] = p;
    }
}
