#include "tl_prepare.h"

#include "core/tl_math.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "waves/tl_giant.h"

static const char *const feature_defines[TL_FEATURE_COUNT] = {"TL_FEATURE_SUN_DISC",
                                                              "TL_FEATURE_GIANT_WAVE"};
static const char *const feature_labels[TL_FEATURE_COUNT] = {"sun disc", "giant wave"};

const char *tl_feature_define(int index)
{
    return index >= 0 && index < TL_FEATURE_COUNT ? feature_defines[index] : NULL;
}

const char *tl_feature_label(int index)
{
    return index >= 0 && index < TL_FEATURE_COUNT ? feature_labels[index] : NULL;
}

void tl_feature_describe(unsigned features, char *out, size_t size)
{
    size_t n = (size_t)snprintf(out, size, "ocean");
    for (int i = 0; i < TL_FEATURE_COUNT && n < size; i++)
        if (features & (1u << i))
            n += (size_t)snprintf(out + n, size - n, ", %s", feature_labels[i]);
}

/* The y-stratum step for N-rooks sampling: near N times the golden ratio's
 * fractional part (well spread), and coprime with N so that every y
 * stratum is used exactly once. */
static int rooks_step(int n)
{
    int step = (int)lround(0.6180339887 * n);
    if (step < 1)
        step = 1;
    while (tl_gcd(step, n) != 1)
        step++;
    return step;
}

static void to_float3(const double in[3], float out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = (float)in[i];
}

/* How much the crest breaks, for the foam trail: 0 while the surface is
 * never compressed past the foam threshold, 1 at the clamp's limit. */
static double breaking(double threshold, double min_jacobian)
{
    if (threshold <= TL_GIANT_MIN_JACOBIAN)
        return 0.0;
    double b = (threshold - min_jacobian) / (threshold - TL_GIANT_MIN_JACOBIAN);
    return b < 0.0 ? 0.0 : b > 1.0 ? 1.0 : b;
}

/* The giant wave relative to the camera: only the camera's offset from the
 * crest (small when the wave is in view) reaches the GPU. */
static void prepare_giant(const tl_scene *s, tl_frame_uniforms *u)
{
    tl_giant g;
    tl_giant_prepare(&g, &s->giant, s->time);
    if (!g.active)
        return;
    u->features |= TL_FEATURE_GIANT_WAVE;
    double rx = s->camera.position[0] - g.origin[0], rz = s->camera.position[2] - g.origin[1];
    u->giant_frame[0] = (float)g.dir[0];
    u->giant_frame[1] = (float)g.dir[1];
    u->giant_frame[2] = (float)(g.dir[0] * rx + g.dir[1] * rz);
    u->giant_frame[3] = (float)(g.across[0] * rx + g.across[1] * rz);
    u->giant_shape[0] = (float)g.k;
    u->giant_shape[1] = (float)g.amplitude;
    u->giant_shape[2] = (float)g.steepness;
    u->giant_shape[3] = (float)g.curl;
    u->giant_mask[0] = (float)g.half_length;
    u->giant_mask[1] = (float)g.falloff_along;
    u->giant_mask[2] = (float)g.half_width;
    u->giant_mask[3] = (float)g.falloff_across;
    u->giant_bounds[0] = (float)g.reach_along;
    u->giant_bounds[1] = (float)(TL_GIANT_BRACKET * g.max_displacement);
    u->giant_bounds[2] = (float)g.max_slope;
    u->giant_bounds[3] = (float)g.fade;
    u->giant_foam[0] = (float)s->giant.foam_compression;
    u->giant_foam[1] = (float)s->giant.foam_trail;
    u->giant_foam[2] = (float)s->water.foam;
    u->giant_foam[3] = (float)breaking(s->giant.foam_compression, g.min_jacobian);
    u->giant_scatter[0] = (float)s->giant.scatter;
    u->giant_scatter[1] = (float)s->giant.scatter_forward;
    u->giant_scatter[2] = (float)s->giant.scatter_back;
    to_float3(s->giant.scatter_color, u->giant_scatter_color);
    u->giant_iterations = s->quality.giant_iterations;
    for (int i = 0; i < TL_GIANT_SLOPE_BINS; i++)
        u->giant_slope[i] = (float)g.slope_bin[i];
    /* World-fixed texture coordinates for foam left behind, reduced in
     * double so the GPU sees small numbers wherever the wave is. */
    double along = g.dir[0] * g.origin[0] + g.dir[1] * g.origin[1];
    double across = g.across[0] * g.origin[0] + g.across[1] * g.origin[1];
    u->giant_world[0] = (float)(along - 65536.0 * floor(along / 65536.0));
    u->giant_world[1] = (float)(across - 65536.0 * floor(across / 65536.0));
}

void tl_prepare_frame(const tl_scene *s, const tl_waves *w, tl_frame_uniforms *u)
{
    memset(u, 0, sizeof *u);
    u->width = s->width;
    u->height = s->height;

    double right[3], up[3], forward[3];
    tl_scene_camera_basis(&s->camera, right, up, forward);
    to_float3(right, u->cam_right);
    to_float3(up, u->cam_up);
    to_float3(forward, u->cam_forward);
    u->tan_half_vfov = (float)tan(0.5 * s->camera.vfov);
    u->cam_height = (float)s->camera.position[1];

    const double cx = s->camera.position[0], cz = s->camera.position[2];
    double len = hypot(cx, cz);
    u->radial_len = (float)len;
    if (len > 0.0) {
        u->radial_dir[0] = (float)(cx / len);
        u->radial_dir[1] = (float)(cz / len);
    }
    u->radial_phase = (float)w->radial_phase;

    const tl_quality *q = &s->quality;
    int octaves = q->march_octaves > q->normal_octaves ? q->march_octaves : q->normal_octaves;
    u->octaves = octaves;
    double phase[TL_MAX_OCTAVES];
    tl_waves_phases(w, cx, cz, s->time, octaves, phase);
    for (int i = 0; i < octaves; i++) {
        const tl_wave_octave *o = &w->octave[i];
        u->wave[i][0] = (float)o->dir_x;
        u->wave[i][1] = (float)o->dir_z;
        u->wave[i][2] = (float)o->frequency;
        u->wave[i][3] = (float)phase[i];
        u->wave_weight[i] = (float)o->weight;
    }
    u->drag = (float)w->drag;
    u->depth = (float)w->depth;

    u->march_octaves = q->march_octaves;
    u->normal_octaves = q->normal_octaves;
    u->march_steps = q->march_steps;
    u->hit_epsilon = (float)q->hit_epsilon;
    u->normal_epsilon = (float)q->normal_epsilon;
    u->spp = q->spp < 1 ? 1 : q->spp;
    u->spp_step = rooks_step(u->spp);
    u->seed = 0;

    double sun[3];
    tl_scene_sun_direction(&s->sun, sun);
    to_float3(sun, u->sun_dir);
    u->sun_intensity = (float)s->sun.intensity;
    u->sun_sharpness = (float)s->sun.sharpness;
    u->sky_brightness = (float)s->sky.brightness;
    /* The disc lobe is invisible once the sun is well below the horizon:
     * the lobe's value at the horizon is cos(elevation)^sharpness. */
    if (s->sun.intensity > 0.0 && s->sun.elevation > -0.2)
        u->features |= TL_FEATURE_SUN_DISC;

    u->fresnel_f0 = (float)s->water.fresnel_f0;
    to_float3(s->water.scatter_color, u->scatter_color);
    u->scatter_strength = (float)s->water.scatter_strength;
    u->scatter_base = (float)s->water.scatter_base;
    u->normal_smooth_max = (float)s->water.normal_smooth_max;
    u->normal_smooth_rate = (float)s->water.normal_smooth_rate;
    u->normal_smooth_gain = (float)s->water.normal_smooth_gain;
    u->exposure = (float)s->exposure;
    prepare_giant(s, u);
}
