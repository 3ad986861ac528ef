#include "tl_prepare.h"
#include "tl_prepare_internal.h"

#include "core/tl_math.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <cglm/cglm.h>

#include "optics/tl_optics.h"
#include "prepare/tl_uniform_list.h"
#include "sky/tl_sky.h"
#include "waves/tl_bow_spray.h"
#include "waves/tl_caustics.h"
#include "waves/tl_giant.h"
#include "waves/tl_giant_spray.h"

static const char *const feature_defines[TL_FEATURE_COUNT] = {
    "TL_FEATURE_SUN_DISC",      "TL_FEATURE_GIANT_WAVE",
    "TL_FEATURE_BOAT",          "TL_FEATURE_WAKE",
    "TL_FEATURE_UNDERWATER",    "TL_FEATURE_WATERLINE",
    "TL_FEATURE_FOG",           "TL_FEATURE_SKY_PHYSICAL",
    "TL_FEATURE_LOD",           "TL_FEATURE_ANALYTIC_NORMALS",
    "TL_FEATURE_SUPERSAMPLE",   "TL_FEATURE_FILTERED_SHADING",
    "TL_FEATURE_REFINE",        "TL_FEATURE_POLISH",
    "TL_FEATURE_GIANT_BREAK",   "TL_FEATURE_GIANT_LIP",
    "TL_FEATURE_GIANT_SPRAY",   "TL_FEATURE_GIANT_GLOW",
    "TL_FEATURE_BOAT_SHADOW",   "TL_FEATURE_BOW_SPRAY",
    "TL_FEATURE_CAUSTICS",      "TL_FEATURE_SEA_FLOOR",
    "TL_FEATURE_SHAFTS",        "TL_FEATURE_PARTICLES",
    "TL_FEATURE_GIANT_CAUSTICS"};
static const char *const feature_labels[TL_FEATURE_COUNT] = {"sun disc",
                                                             "giant wave",
                                                             "boat",
                                                             "wake",
                                                             "underwater",
                                                             "waterline",
                                                             "fog",
                                                             "physical sky",
                                                             "level of detail",
                                                             "analytic normals",
                                                             "supersampling",
                                                             "filtered shading",
                                                             "root refinement",
                                                             "hit polish",
                                                             "breaking crest",
                                                             "lip",
                                                             "spray",
                                                             "crest glow",
                                                             "boat shadow",
                                                             "bow spray",
                                                             "caustics",
                                                             "sea floor",
                                                             "light shafts",
                                                             "particles",
                                                             "crest caustics"};

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

/* v reduced to [0, 65536): world texture coordinates that stay precise as
 * floats (8 mm steps) however far the scene is from the origin. */
static double wrap_period(double v, double period)
{
    return v - period * floor(v / period);
}

static double wrap65536(double v)
{
    return wrap_period(v, 65536.0);
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

/* The giant wave's spray (TL_FEATURE_GIANT_SPRAY), the bow's burst
 * relative to the camera. */
static void prepare_spray(const tl_scene *s, const tl_giant *g, tl_frame_uniforms *u)
{
    const tl_boat *b = &s->boat;
    tl_giant_hull hull;
    tl_giant_hull_of(&hull, b);
    tl_giant_spray sp;
    tl_giant_spray_prepare(&sp, g, s->giant.spray, s->giant.spray_wind, s->time, s->ocean.depth,
                           b->enabled ? &hull : NULL);
    if (!sp.active)
        return;
    u->features |= TL_FEATURE_GIANT_SPRAY;
    u->giant_spray[0] = (float)sp.amount;
    u->giant_spray[1] = (float)sp.reach;
    u->giant_spray[2] = (float)sp.drift;
    u->giant_spray[3] = (float)sp.bow_radius;
    for (int i = 0; i < 4; i++)
        u->giant_spray_box[i] = (float)sp.box[i];
    u->giant_spray_bow[0] = (float)(sp.bow[0] - s->camera.position[0]);
    u->giant_spray_bow[1] = (float)sp.bow[1];
    u->giant_spray_bow[2] = (float)(sp.bow[2] - s->camera.position[2]);
    u->giant_spray_bow[3] = (float)sp.bow_amount;
    u->giant_spray_heading[0] = (float)sp.heading[0];
    u->giant_spray_heading[1] = (float)sp.heading[1];
    u->giant_spray_heading[2] = (float)sp.bow_split;
    u->giant_spray_heading[3] = (float)sp.shelter;
}

/* The sun's light below a flat surface (the way it travels, refracted)
 * and the water's scattering: for the caustics under water and through
 * the giant wave's crest. */
static void sun_in_water(const tl_scene *s, const double sun[3], tl_frame_uniforms *u)
{
    double dir[3];
    tl_optics_sun_in_water(sun, s->water.ior, dir);
    to_float3(dir, u->sun_water);
    u->water_scattering = (float)s->water.scattering;
}

/* The ocean's RMS slope over its first `octaves` octaves (per axis, as
 * waves_faded_slope_variance counts it). */
static double ride_slope(const tl_waves *w, int octaves)
{
    double variance = 0.0, weights = 0.0;
    for (int i = 0; i < octaves && i < w->count; i++) {
        double wk = w->octave[i].weight * w->octave[i].frequency;
        variance += TL_WAVE_SLOPE_MEAN_SQ * wk * wk;
        weights += w->octave[i].weight;
    }
    return weights > 0.0 ? w->depth * sqrt(variance) / weights : 0.0;
}

/* The giant wave relative to the camera: only the camera's offset from the
 * crest (small when the wave is in view) reaches the GPU. */
static void prepare_giant(const tl_scene *s, const tl_waves *w, const tl_giant *wave,
                          tl_frame_uniforms *u)
{
    const tl_giant g = *wave;
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
    u->giant_bounds[3] = (float)g.lambda_max;
    u->giant_crest[0] = (float)g.peak;
    u->giant_crest[1] = (float)g.taper;
    u->giant_crest[2] = (float)g.bow;
    u->giant_crest[3] = (float)g.variation;
    to_float3(g.vary_k, u->giant_vary_k);
    to_float3(g.vary_phase, u->giant_vary_phase);
    u->giant_fade = (float)g.fade;
    double sun[3];
    tl_scene_sun_direction(&s->sun, sun);
    if (s->giant.scatter > 0.0 && sun[1] > -0.05) { /* giant_scatter's daylight */
        u->features |= TL_FEATURE_GIANT_GLOW;
        /* What of the light through the crest is still the sun's beam. */
        u->water_scattering = (float)s->water.scattering;
    }
    /* The far side's ripples focus the light through the crest only while
     * the sun is up (caustic_focus is 1 below the horizon). */
    if ((u->features & TL_FEATURE_GIANT_GLOW) && sun[1] > 0.0 && s->giant.caustics > 0.0) {
        u->features |= TL_FEATURE_GIANT_CAUSTICS;
        sun_in_water(s, sun, u);
    }
    double sigma[3], fall[3];
    tl_optics_water_extinction(&s->water, sigma);
    tl_optics_water_fall(&s->water, sigma, fall);
    to_float3(fall, u->giant_sigma);
    if (g.breaks) {
        u->features |= TL_FEATURE_GIANT_BREAK;
        u->giant_break[0] = (float)g.break_age;
        u->giant_break[1] = (float)g.peel_speed;
        u->giant_break[2] = (float)g.throw_time;
        u->giant_break[3] = (float)g.break_drop;
        u->giant_speed = (float)g.speed;
        double box[4], across[2];
        if (tl_giant_lip_bounds(&g, -0.5 * s->ocean.depth, box, across)) {
            u->features |= TL_FEATURE_GIANT_LIP;
            for (int i = 0; i < 4; i++)
                u->giant_lip_box[i] = (float)box[i];
            u->giant_lip_w[0] = (float)across[0];
            u->giant_lip_w[1] = (float)across[1];
        }
    }
    u->giant_foam[0] = (float)s->giant.foam_compression;
    u->giant_foam[1] = (float)s->giant.foam_trail;
    u->giant_foam[2] = (float)s->water.foam;
    /* A scripted crest has not broken before its break (breaking then
     * comes from the break's age, TL_FEATURE_GIANT_BREAK). */
    u->giant_foam[3] =
        g.scripted ? 0.0f : (float)breaking(s->giant.foam_compression, g.min_jacobian);
    u->giant_compression_foam = g.scripted ? (float)TL_GIANT_UNBROKEN_FOAM : 1.0f;
    u->giant_scatter[0] = (float)s->giant.scatter;
    u->giant_scatter[1] = (float)s->giant.scatter_forward;
    u->giant_scatter[2] = (float)s->giant.scatter_back;
    u->giant_scatter[3] = (float)s->giant.caustics;
    to_float3(s->giant.scatter_color, u->giant_scatter_color);
    u->giant_iterations = s->quality.giant_iterations;
    u->spray_step = (float)s->quality.spray_step;
    u->giant_ride = (float)g.ride;
    /* The small waves riding the wave's water steepen where it is
     * compressed, by ride·|grad displacement| times their own slope: the
     * march's bound takes that share of the ocean's RMS slope. The march
     * steps by the height above the small waves, as over the open sea,
     * where their slope is not in the bound either. */
    double ocean_slope = ride_slope(w, s->quality.march_octaves);
    for (int i = 0; i < TL_GIANT_SLOPE_BINS; i++)
        u->giant_slope[i] = (float)(g.slope_bin[i] + g.ride * g.squeeze_bin[i] * ocean_slope);
    /* A rising ray stays at or above the camera; the ocean's crests are at
     * 0, so it can meet the surface only in bins where the wave alone
     * reaches the camera's height (a centimetre of margin for the float
     * camera height). */
    const double cam_y = s->camera.position[1], bin = 2.0 * g.reach_along / TL_GIANT_SLOPE_BINS;
    int first = 0, last = TL_GIANT_SLOPE_BINS - 1;
    if (cam_y > 0.0) {
        while (first < TL_GIANT_SLOPE_BINS && g.height_bin[first] < cam_y - 0.01)
            first++;
        while (last >= first && g.height_bin[last] < cam_y - 0.01)
            last--;
    }
    u->giant_rise[0] = first > last ? 0.0f : (float)(-g.reach_along + first * bin);
    u->giant_rise[1] = first > last ? 0.0f : (float)(-g.reach_along + (last + 1) * bin);
    /* World-fixed texture coordinates for foam left behind, reduced in
     * double so the GPU sees small numbers wherever the wave is. */
    double world[2];
    tl_giant_world_origin(&g, world);
    prepare_spray(s, &g, u);
    u->giant_world[0] = (float)world[0];
    u->giant_world[1] = (float)world[1];
    tl_prepare_giant_rect(s, u);
}

/* Whether a sphere (camera-relative centre c, radius r) can show in the
 * view: in front of the camera and within the four side planes. */
static int sphere_in_view(const tl_scene *s, const double c[3], double r)
{
    double right[3], up[3], fwd[3];
    tl_scene_camera_basis(&s->camera, right, up, fwd);
    double x = c[0] * right[0] + c[1] * right[1] + c[2] * right[2];
    double y = c[0] * up[0] + c[1] * up[1] + c[2] * up[2];
    double z = c[0] * fwd[0] + c[1] * fwd[1] + c[2] * fwd[2];
    double ty = tan(0.5 * s->camera.vfov), tx = ty * s->width / s->height;
    return z + r > TL_BOAT_NEAR && fabs(x) <= z * tx + r * sqrt(1.0 + tx * tx) &&
           fabs(y) <= z * ty + r * sqrt(1.0 + ty * ty);
}

/* The sun's orthographic view of an object's bounding sphere (centre c,
 * radius r, camera-relative): shadow map coordinates s, t across the
 * sun's beam and depth along it, each 0 to 1 over the sphere. Every point
 * in that beam projects into the map, the water under the object's shadow
 * too; past the sphere, away from the sun, depth is clamped by the lookup. */
static void prepare_shadow(const tl_scene *s, const double c[3], double r, const double sun[3],
                           int layer, tl_object_uniforms *o, tl_object_pass *pass)
{
    /* Texels: twice the pixels the object spans on screen, a power of two
     * from TL_BOAT_SHADOW_LEAST to TL_BOAT_SHADOW_SIZE (an object far off,
     * or a thumbnail, does not raster a full map). The map's part in use is
     * the corner of that many texels: its share `extent` of the layer. */
    double dist = fmax(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) - r, r);
    double across = 2.0 * r / (2.0 * dist * tan(0.5 * s->camera.vfov)) * s->height;
    int size = TL_BOAT_SHADOW_LEAST;
    while (size < TL_BOAT_SHADOW_SIZE && size < 2.0 * across)
        size *= 2;
    double extent = (double)size / TL_BOAT_SHADOW_SIZE;
    double a[3] = {0.0, 1.0, 0.0};
    if (fabs(sun[1]) > 0.99)
        a[0] = 1.0, a[1] = 0.0;
    double e1[3] = {a[1] * sun[2] - a[2] * sun[1], a[2] * sun[0] - a[0] * sun[2],
                    a[0] * sun[1] - a[1] * sun[0]};
    double l = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (int k = 0; k < 3; k++)
        e1[k] /= l;
    double e2[3] = {sun[1] * e1[2] - sun[2] * e1[1], sun[2] * e1[0] - sun[0] * e1[2],
                    sun[0] * e1[1] - sun[1] * e1[0]};
    /* Rows of the map: s = 0.5 + e1.(p - c) / 2r, t likewise with e2,
     * depth = 0.5 - sun.(p - c) / 2r; stored column-major. */
    const double *rows[3] = {e1, e2, sun};
    const double sign[3] = {1.0, 1.0, -1.0};
    memset(o->shadow, 0, sizeof o->shadow);
    for (int i = 0; i < 3; i++) {
        double scale = i < 2 ? extent : 1.0, offset = 0.5 * scale;
        for (int k = 0; k < 3; k++) {
            double m = scale * sign[i] * rows[i][k] / (2.0 * r);
            o->shadow[4 * k + i] = (float)m;
            offset -= m * c[k];
        }
        o->shadow[12 + i] = (float)offset;
    }
    o->shadow[15] = 1.0f;
    o->hull[3] = (float)layer;
    o->shadow_map[0] = (float)(2.0 * r / size);
    o->shadow_map[1] = (float)extent;
    pass->shadow_size = size;
}

/* The bow's spray where it meets rising water (TL_FEATURE_BOW_SPRAY), with
 * the object's hull in view and its sheet's sphere too; the giant wave's
 * spray throws the boat's own where its bow meets the face. */
static void prepare_bow_spray(const tl_scene *s, const tl_boat *b, int k, tl_object_uniforms *o,
                              tl_frame_uniforms *u)
{
    if (k == 0 && (u->features & TL_FEATURE_GIANT_SPRAY) && u->giant_spray_bow[3] > 0.0f)
        return;
    tl_bow_spray sp;
    tl_bow_spray_prepare(&sp, b);
    double c[3];
    for (int i = 0; i < 3; i++)
        c[i] = sp.center[i] - s->camera.position[i];
    if (!sp.active || !sphere_in_view(s, c, tl_bow_spray_reach(sp.radius, 0.0)))
        return;
    u->features |= TL_FEATURE_BOW_SPRAY;
    o->bow_spray[0] = (float)c[0];
    o->bow_spray[1] = (float)sp.center[1];
    o->bow_spray[2] = (float)c[2];
    o->bow_spray[3] = (float)sp.amount;
    o->bow_spray_shape[0] = (float)sp.heading[0];
    o->bow_spray_shape[1] = (float)sp.heading[1];
    o->bow_spray_shape[2] = (float)sp.radius;
    o->bow_spray_shape[3] = 0.0f;
}

/* Whether an object's shadow on the sea floor (its bounding sphere carried
 * down the sun's beam in the water to the floor, widened by a tenth of the
 * way: the beam spreads by a few hundredths of a radian) is in view. */
static int shadow_on_floor_in_view(const tl_scene *s, const tl_boat *b, const double c[3], double r)
{
    double sun[3], beam[3];
    tl_scene_sun_direction(&s->sun, sun);
    if (!b->shadows || !(s->ocean.floor_depth > 0.0) || !(sun[1] > 0.0))
        return 0;
    tl_optics_sun_in_water(sun, s->water.ior, beam);
    double floor_y = -s->ocean.floor_depth - s->camera.position[1];
    double run = (floor_y - c[1]) / fmin(beam[1], -TL_CAUSTIC_MIN_DOWN);
    if (!(run > 0.0))
        return 0;
    double at[3] = {c[0] + run * beam[0], floor_y, c[2] + run * beam[2]};
    return sphere_in_view(s, at, r + 0.1 * run);
}

/* An object's matrices in camera-relative space, and whether its bounding
 * sphere (or its mirror image's) is in view; how much of the sun its hull
 * sees past the giant wave's crest, at the hull's centre (the shadow's
 * edge is soft over metres, the hull is a few long). Returns 1 when it is
 * in view: its mirror rectangle joins the frame's. */
static int prepare_hull(const tl_scene *s, const tl_giant *giant, const tl_boat *b,
                        tl_object_uniforms *o, tl_object_pass *pass, tl_frame_uniforms *u)
{
    double rel[3];
    for (int i = 0; i < 3; i++)
        rel[i] = b->position[i] - s->camera.position[i];
    mat4 model;
    glm_translate_make(model, (vec3){(float)rel[0], (float)rel[1], (float)rel[2]});
    glm_rotate_y(model, (float)b->heading, model);
    glm_rotate_x(model, (float)-b->pitch, model); /* bow up */
    glm_rotate_z(model, (float)-b->roll, model);  /* starboard down */
    glm_rotate_y(model, (float)b->model_yaw, model);
    glm_scale_uni(model, (float)b->scale);
    mat4 inverse;
    glm_mat4_inv(model, inverse);
    memcpy(pass->model, model, sizeof pass->model);
    memcpy(o->to_model, inverse, sizeof o->to_model);
    o->hull[0] = (float)b->model_max[1];
    o->hull[1] = (float)rel[1];
    o->hull[3] = -1.0f; /* no shadow map until one is made */
    /* Over the last stretch of its path the wake keeps. */
    if (b->wake_step > 0.0)
        o->hull[2] = (float)(hypot(b->wake_path[0][0] - b->wake_path[1][0],
                                   b->wake_path[0][1] - b->wake_path[1][1]) /
                             b->wake_step);
    pass->lights = (float)b->lights;

    double centre[3], half = 0.0;
    for (int i = 0; i < 3; i++) {
        double mid = 0.5 * (b->model_min[i] + b->model_max[i]);
        double ext = 0.5 * (b->model_max[i] - b->model_min[i]);
        centre[i] = mid;
        half += ext * ext;
    }
    vec4 c = {(float)centre[0], (float)centre[1], (float)centre[2], 1.0f}, cw;
    glm_mat4_mulv(model, c, cw);
    /* In view itself, or mirrored in the water at its waterline, or its
     * shadow on the sea floor. */
    double world[3] = {cw[0], cw[1], cw[2]};
    double mirrored[3] = {cw[0], 2.0 * rel[1] - cw[1], cw[2]};
    double radius = sqrt(half) * b->scale;
    if (!sphere_in_view(s, world, radius) && !sphere_in_view(s, mirrored, radius) &&
        !shadow_on_floor_in_view(s, b, world, radius))
        return 0;
    double corner[8][3];
    for (int i = 0; i < 8; i++) {
        vec4 m = {(float)(i & 1 ? b->model_max[0] : b->model_min[0]),
                  (float)(i & 2 ? b->model_max[1] : b->model_min[1]),
                  (float)(i & 4 ? b->model_max[2] : b->model_min[2]), 1.0f},
             w;
        glm_mat4_mulv(model, m, w);
        for (int k = 0; k < 3; k++)
            corner[i][k] = w[k];
    }
    tl_prepare_mirror_rect(s, corner, rel[1], u);
    double sun[3];
    tl_scene_sun_direction(&s->sun, sun);
    pass->sunlit =
        (float)tl_giant_sunlit(giant, cw[0] + s->camera.position[0], cw[2] + s->camera.position[2],
                               cw[1] + s->camera.position[1], sun);
    if (b->shadows && sun[1] > 0.0) {
        int layer = 0;
        for (int i = 0; i < u->object_count; i++)
            layer += u->object_pass[i].shadow_size > 0;
        prepare_shadow(s, world, radius, sun, layer, o, pass);
        u->features |= TL_FEATURE_BOAT_SHADOW;
    }
    return 1;
}

/* The view's projection (camera-relative world -> clip) for the meshes. */
static void prepare_view_proj(const tl_scene *s, tl_frame_uniforms *u)
{
    double right[3], up[3], fwd[3];
    tl_scene_camera_basis(&s->camera, right, up, fwd);
    mat4 view = GLM_MAT4_IDENTITY_INIT, proj, view_proj;
    for (int i = 0; i < 3; i++) { /* rows: right, up, -forward */
        view[i][0] = (float)right[i];
        view[i][1] = (float)up[i];
        view[i][2] = (float)-fwd[i];
    }
    glm_perspective((float)s->camera.vfov, (float)s->width / (float)s->height, (float)TL_BOAT_NEAR,
                    (float)TL_BOAT_FAR, proj);
    glm_mat4_mul(proj, view, view_proj);
    memcpy(u->view_proj, view_proj, sizeof u->view_proj);
}

/* How far from its path, `behind` metres back from the object, the wake's
 * foam reaches: shaders/wake.glsl skips a segment farther than 1.3 times
 * the wedge's half width there plus 2 m (tan 19.47 deg = 0.35355). */
static double wake_reach(const tl_boat *b, double behind)
{
    return (0.5 * b->beam + behind * 0.35355) * 1.3 + 2.0;
}

/* A circle around each group of the wake's segments that holds every point
 * of the water its foam can reach (the reach grows along the path), so
 * that a pixel loops only over the groups that reach it. Camera-relative,
 * from o->wake; the slack covers the shader's float rounding. */
static void wake_groups(const tl_boat *b, tl_object_uniforms *o)
{
    for (int g = 0; g < TL_WAKE_GROUPS; g++) {
        int k0 = g * TL_WAKE_GROUP, k1 = k0 + TL_WAKE_GROUP;
        if (k1 > TL_WAKE_POINTS - 1)
            k1 = TL_WAKE_POINTS - 1;
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (int k = k0; k <= k1; k++)
            for (int i = 0; i < 2; i++) {
                lo[i] = fmin(lo[i], o->wake[k][i]);
                hi[i] = fmax(hi[i], o->wake[k][i]);
            }
        double cx = 0.5 * (lo[0] + hi[0]), cz = 0.5 * (lo[1] + hi[1]), spread = 0.0;
        for (int k = k0; k <= k1; k++)
            spread = fmax(spread, hypot(o->wake[k][0] - cx, o->wake[k][1] - cz));
        double radius = spread + wake_reach(b, o->wake[k1][3]);
        o->wake_groups[g][0] = (float)cx;
        o->wake_groups[g][1] = (float)cz;
        o->wake_groups[g][2] = (float)(radius * 1.001 + 0.1);
        o->wake_groups[g][3] = 0.0f;
    }
}

/* How much white water a boat churns at `speed` m/s, 0 to 1: the shader's
 * smoothstep (shaders/wake.glsl). */
static double wake_churn(double speed)
{
    double t = (speed - TL_WAKE_SPEED_NONE) / (TL_WAKE_SPEED_FULL - TL_WAKE_SPEED_NONE);
    t = fmin(fmax(t, 0.0), 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/* An object's past positions relative to the camera, for its wake; 1 when
 * it is under way and the wedge can be in view (else the wake's strength
 * stays 0 and its groups empty: the shader skips it). */
static int prepare_wake(const tl_scene *s, const tl_boat *b, tl_object_uniforms *o)
{
    if (!(b->wake > 0.0))
        return 0;
    const double *cam = s->camera.position;
    double behind = 0.0, lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300}, churn = 0.0;
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        double x = b->wake_path[k][0], z = b->wake_path[k][1];
        if (k > 0) {
            double step = hypot(x - b->wake_path[k - 1][0], z - b->wake_path[k - 1][1]);
            behind += step;
            double speed = b->wake_step > 0.0 ? step / b->wake_step : 0.0;
            churn = fmax(churn, wake_churn(speed));
        }
        o->wake[k][0] = (float)(x - cam[0]);
        o->wake[k][1] = (float)(z - cam[2]);
        o->wake[k][2] = (float)(k * b->wake_step);
        o->wake[k][3] = (float)behind;
        /* Half a wrap on: before the path's first point the distance is
         * negative, and the wrap's seam (a jump in the streaks' texture)
         * would lie at the path's start, often in view; it lies 32 km away. */
        o->wake_along[k] = (float)wrap65536(b->wake_along[k] + 32768.0);
        lo[0] = fmin(lo[0], x);
        lo[1] = fmin(lo[1], z);
        hi[0] = fmax(hi[0], x);
        hi[1] = fmax(hi[1], z);
    }
    /* An object at rest, or drifting, leaves no white water. */
    if (behind < 0.1 || b->wake * churn < TL_WAKE_LEAST)
        return 0;
    /* The wedge's reach: the path's box widened by its widest arm. */
    double reach = wake_reach(b, behind);
    double centre[3] = {0.5 * (lo[0] + hi[0]) - cam[0], b->position[1] - cam[1],
                        0.5 * (lo[1] + hi[1]) - cam[2]};
    double radius = hypot(0.5 * (hi[0] - lo[0]), 0.5 * (hi[1] - lo[1])) + reach;
    if (!sphere_in_view(s, centre, radius))
        return 0;
    wake_groups(b, o);
    o->wake_params[0] = (float)(0.5 * b->beam);
    o->wake_params[1] = (float)b->wake_time;
    o->wake_params[2] = (float)b->wake;
    o->wake_params[3] = (float)b->length;
    return 1;
}

/* The floating objects: each one whose hull, mirror image or wake is in
 * view takes the next slot of the ocean pass's block and the mesh pass;
 * the others cost nothing. */
static void prepare_objects(const tl_scene *s, const tl_waves *w, const tl_giant *giant,
                            tl_frame_uniforms *u)
{
    for (int k = 0; k < s->objects && k < TL_OBJECT_MAX; k++) {
        const tl_boat *b = tl_scene_object_const(s, k);
        if (!b->enabled || !b->visible)
            continue;
        tl_object_uniforms *o = &u->objects[u->object_count];
        tl_object_pass *pass = &u->object_pass[u->object_count];
        memset(o, 0, sizeof *o);
        memset(pass, 0, sizeof *pass);
        pass->object = k;
        pass->mesh = b->model;
        pass->drawn = prepare_hull(s, giant, b, o, pass, u);
        int wake = prepare_wake(s, b, o);
        if (!pass->drawn && !wake)
            continue;
        if (pass->drawn) {
            u->features |= TL_FEATURE_BOAT;
            prepare_bow_spray(s, b, k, o, u);
            tl_prepare_wash_water(s, w, giant, b, pass->model, o);
        } else {
            pass->shadow_size = 0;
            o->hull[3] = -1.0f;
        }
        if (wake)
            u->features |= TL_FEATURE_WAKE;
        u->object_count++;
    }
    if (u->features & TL_FEATURE_BOAT) {
        prepare_view_proj(s, u);
        /* With several samples a pixel each sample's pass draws the hulls
         * at its own offset (tl_prepare_boat_sample): one sample each. */
        u->mesh_scale = s->quality.spp > 1 || s->quality.mesh_scale < 1 ? 1 : s->quality.mesh_scale;
    }
    if (u->features & TL_FEATURE_WAKE) {
        u->world_offset[0] = (float)wrap65536(s->camera.position[0]);
        u->world_offset[1] = (float)wrap65536(s->camera.position[2]);
    }
}

tl_water_side tl_prepare_water_side(const tl_scene *s, const tl_waves *w, const tl_giant *giant,
                                    double *gap)
{
    const double *c = s->camera.position;
    double h = tl_waves_surface_height(w, giant, c[0], c[2], s->time, s->quality.march_octaves,
                                       s->quality.giant_iterations);
    if (gap)
        *gap = c[1] - h;
    if (s->underwater.mode == TL_UNDERWATER_ON)
        return TL_WATER_BELOW;
    if (s->underwater.mode == TL_UNDERWATER_OFF)
        return TL_WATER_ABOVE;
    /* The lens: image-plane points TL_LENS_DISTANCE ahead of the camera,
     * within `r` of it; the surface under them differs from the camera's
     * by at most its slope times r (the ocean's slope is taken as 2). */
    double ty = tan(0.5 * s->camera.vfov), tx = ty * s->width / s->height;
    double r = TL_LENS_DISTANCE * sqrt(1.0 + tx * tx + ty * ty);
    /* The ocean's part changes by at most the larger of 2r and its band
     * (it stays within ocean.depth): riding the giant wave's compressed
     * water steepens it, but cannot move it further than that. */
    double ocean = 2.0 * r;
    if (giant->active)
        ocean = fmin(ocean * (1.0 + giant->ride * giant->max_squeeze), fmax(ocean, w->depth));
    double margin = r * (1.0 + (giant->active ? giant->max_slope : 0.0)) + ocean;
    if (c[1] - h > margin)
        return TL_WATER_ABOVE;
    if (h - c[1] > margin)
        return TL_WATER_BELOW;
    return TL_WATER_STRADDLES;
}

/* Under water: which pixels (feature bits), and the water body's
 * extinction, scattering and the sun's light in it; those too when the
 * sea floor shows through the surface from above. */
static void prepare_water_body(const tl_scene *s, const tl_waves *w, const tl_giant *giant,
                               tl_frame_uniforms *u)
{
    /* Above the water too: the giant wave's crest refracts the sun with it. */
    u->water_ior = (float)s->water.ior;
    double gap;
    tl_water_side side = tl_prepare_water_side(s, w, giant, &gap);
    int floor = s->ocean.floor_depth > 0.0, under = side != TL_WATER_ABOVE;
    if (!under && !floor)
        return;
    if (under)
        u->features |= TL_FEATURE_UNDERWATER;
    if (side == TL_WATER_STRADDLES)
        u->features |= TL_FEATURE_WATERLINE;
    double sigma[3], fall[3];
    tl_optics_water_extinction(&s->water, sigma);
    tl_optics_water_fall(&s->water, sigma, fall);
    to_float3(sigma, u->water_sigma);
    to_float3(fall, u->water_fall);
    u->beam_spread = (float)tl_caustic_beam_spread(w, s->water.ior, s->quality.normal_octaves);
    u->capillary_slope_var = (float)tl_waves_capillary_slope_variance(w, s->quality.normal_octaves,
                                                                      s->water.capillaries);
    u->cam_depth = (float)fmax(-gap, 0.0);
    u->lens = (float)TL_LENS_DISTANCE;
    double sun[3];
    tl_scene_sun_direction(&s->sun, sun);
    sun_in_water(s, sun, u);
    /* The share of the sun that crossed a flat surface (none below the
     * horizon). */
    u->sun_water_trans =
        sun[1] > 0.0 ? (float)(1.0 - tl_optics_fresnel(fmax(sun[1], 0.0), 1.0, s->water.ior))
                     : 0.0f;
    if (sun[1] > 0.0 && s->underwater.caustics > 0.0) {
        u->features |= TL_FEATURE_CAUSTICS;
        u->caustics = (float)s->underwater.caustics;
    }
    if (under && sun[1] > 0.0 && s->underwater.shafts > 0.0 && s->quality.shaft_steps > 0) {
        u->features |= TL_FEATURE_SHAFTS;
        u->shafts = (float)s->underwater.shafts;
        u->shaft_steps = s->quality.shaft_steps;
    }
    if (under && s->underwater.particles > 0.0) {
        u->features |= TL_FEATURE_PARTICLES;
        u->particles = (float)s->underwater.particles;
        for (int i = 0; i < 3; i++)
            u->particle_offset[i] = (float)wrap_period(s->camera.position[i], TL_PARTICLE_PERIOD);
    }
    if (floor) {
        u->features |= TL_FEATURE_SEA_FLOOR;
        u->floor_depth = (float)s->ocean.floor_depth;
        u->floor_offset[0] = (float)wrap_period(s->camera.position[0], TL_FLOOR_PERIOD);
        u->floor_offset[1] = (float)wrap_period(s->camera.position[2], TL_FLOOR_PERIOD);
    }
}

double tl_prepare_sky_altitude(const tl_scene *s)
{
    return 100.0 * floor(fmax(s->camera.position[1], 0.0) / 100.0);
}

int tl_prepare_sky_tables(const tl_scene *s, tl_sky_luts *luts, const tl_frame_uniforms *u,
                          double *sun_elevation, double *altitude)
{
    if (!(u->features & TL_FEATURE_SKY_PHYSICAL))
        return 0;
    tl_atmosphere a;
    tl_sky_atmosphere_of(s, &a);
    tl_sky_luts_update_atmosphere(luts, &a);
    *sun_elevation = s->sun.elevation;
    *altitude = tl_prepare_sky_altitude(s);
    return 1;
}

void tl_prepare_sky_ambient(const tl_scene *s, const tl_sky_luts *luts, tl_frame_uniforms *u)
{
    for (int c = 0; c < 3; c++)
        u->sky_ambient[c] = (float)(luts->ambient[c] * s->sky.sun_illuminance);
}

/* The physical sky: the sun's light at the camera and its disc. */
static void prepare_sky(const tl_scene *s, tl_frame_uniforms *u)
{
    if (s->sky.model != TL_SKY_PHYSICAL)
        return;
    u->features |= TL_FEATURE_SKY_PHYSICAL;
    tl_atmosphere a;
    tl_sky_atmosphere_of(s, &a);
    double light[3];
    tl_sky_sun_light(&a, s->sun.elevation, tl_prepare_sky_altitude(s), s->sky.sun_illuminance,
                     light);
    to_float3(light, u->sun_light);
    u->sky_scale = (float)s->sky.sun_illuminance;
    u->sun_cos_radius = (float)cos(0.5 * s->sun.angular_diameter);
    /* The disc: only while any of its light gets through the air. */
    if (light[0] + light[1] + light[2] > 0.0)
        u->features |= TL_FEATURE_SUN_DISC;
    else
        u->features &= ~(unsigned)TL_FEATURE_SUN_DISC;
}

/* Fog above the water: its feature only when it is there. */
static void prepare_fog(const tl_scene *s, tl_frame_uniforms *u)
{
    if (!(s->fog.density > 0.0))
        return;
    u->features |= TL_FEATURE_FOG;
    u->fog[0] = (float)s->fog.density;
    u->fog[1] = (float)s->fog.height;
    to_float3(s->fog.color, u->fog_color);
}

/* The top rows whose every ray rises (u->plan.sky_rows). From a camera above
 * the water such a ray meets neither the ocean, whose crests lie at
 * y <= 0, nor the boat (composited from its own pass) nor anything else
 * the lean program marches; the giant wave's box has its own rectangle.
 * The rays are built as shaders/ocean.frag builds them, from the same
 * float uniforms, over each row's whole span (a supersampled ray lies
 * anywhere in its pixel); one rising by less than TL_SKY_MARGIN stays
 * with the march. Worth it because llvmpipe charges a ray that skips the
 * march one pass of its loop anyway: a surface evaluation per sky pixel. */
#define TL_SKY_MARGIN 1e-4
static void sky_rows(tl_frame_uniforms *u)
{
    u->plan.sky_rows = 0;
    if (!(u->cam_height > 0.0f) || (u->features & TL_FEATURE_UNDERWATER) || !(u->cam_up[1] > 0.0f))
        return;
    double ty = u->tan_half_vfov, tx = ty * u->width / u->height;
    /* With the camera's up above the horizontal, a ray rises more the
     * higher its row: count down from the top until a row has a ray that
     * does not rise (enough) at its lower edge, left or right. */
    for (int row = u->height - 1; row >= 0; row--) {
        double ny = 2.0 * row / u->height - 1.0;
        for (int side = -1; side <= 1; side += 2) {
            double d[3];
            for (int i = 0; i < 3; i++)
                d[i] = u->cam_forward[i] + side * tx * u->cam_right[i] + ny * ty * u->cam_up[i];
            if (!(d[1] >= TL_SKY_MARGIN * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])))
                return;
        }
        u->plan.sky_rows = u->height - row;
    }
}

void tl_prepare_render_size(const tl_scene *s, int *width, int *height)
{
    double k = s->quality.render_scale > 0.0 && s->quality.render_scale < 1.0
                   ? s->quality.render_scale
                   : 1.0;
    *width = (int)fmax(1.0, floor(s->width * k + 0.5));
    *height = (int)fmax(1.0, floor(s->height * k + 0.5));
}

void tl_prepare_boat_sample(tl_frame_uniforms *u, int sample)
{
    int n = u->spp < 1 ? 1 : u->spp;
    /* The stratum's centre in pixels from the pixel's (ocean.frag's
     * sample_offset with its jitter at 0.5). */
    double ox = (sample + 0.5) / n - 0.5, oy = ((sample * u->spp_step) % n + 0.5) / n - 0.5;
    /* A pixel shows what lies `o` from its centre: the image moves by -o,
     * 2o/size in normalised device coordinates (clip x, y less that times w). */
    float dx = (float)(-2.0 * ox / u->width), dy = (float)(-2.0 * oy / u->height);
    for (int c = 0; c < 4; c++) {
        u->view_proj[c * 4 + 0] += dx * u->view_proj[c * 4 + 3];
        u->view_proj[c * 4 + 1] += dy * u->view_proj[c * 4 + 3];
    }
}

/* Every row of the uniform table names a field of its size: the renderer
 * uploads that many bytes from it. */
#define CHECK_ROW(kind, field, array, feature, doc)                                                \
    _Static_assert(sizeof(((tl_frame_uniforms *)0)->field) ==                                      \
                       TL_UNIFORM_BYTES_##kind * TL_UNIFORM_COUNT(array),                          \
                   "tl_uniform_list.h: u_" #field " does not match its field");
TL_FRAME_UNIFORMS(CHECK_ROW)
#undef CHECK_ROW

void tl_prepare_white_gain(const tl_scene *s, float gain[3])
{
    double sigma[3], fall[3], white[3];
    tl_optics_water_extinction(&s->water, sigma);
    tl_optics_water_fall(&s->water, sigma, fall);
    for (int c = 0; c < 3; c++)
        white[c] = s->white_point[c] * exp(-fall[c] * s->white_depth);
    double y = 0.2126 * white[0] + 0.7152 * white[1] + 0.0722 * white[2];
    for (int c = 0; c < 3; c++)
        gain[c] = (float)fmin(fmax(y / white[c], 1.0 / TL_WHITE_GAIN_MAX), TL_WHITE_GAIN_MAX);
}

void tl_prepare_frame(const tl_scene *s, const tl_waves *w, tl_frame_uniforms *u)
{
    memset(u, 0, sizeof *u);
    tl_prepare_render_size(s, &u->width, &u->height);
    u->resolution[0] = (float)u->width;
    u->resolution[1] = (float)u->height;
    u->out_width = s->width;
    u->out_height = s->height;

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
    double tail = 0.0, slope_tail = 0.0;
    u->wave_weight_tail[TL_MAX_OCTAVES] = 0.0f;
    u->wave_slope_tail[TL_MAX_OCTAVES] = 0.0f;
    for (int i = TL_MAX_OCTAVES - 1; i >= 0; i--) {
        tail += w->octave[i].weight;
        u->wave_weight_tail[i] = (float)tail;
        double wk = w->octave[i].weight * w->octave[i].frequency;
        slope_tail += TL_WAVE_SLOPE_MEAN_SQ * wk * wk;
        u->wave_slope_tail[i] = (float)slope_tail;
    }
    u->drag = (float)w->drag;
    u->depth = (float)w->depth;

    u->march_octaves = q->march_octaves;
    u->normal_octaves = q->normal_octaves;
    u->march_steps = q->march_steps;
    u->hit_epsilon = (float)q->hit_epsilon;
    u->normal_epsilon = (float)q->normal_epsilon;
    u->refine_steps = q->refine_steps;
    if (q->refine_steps > 0)
        u->features |= TL_FEATURE_REFINE;
    if (q->polish)
        u->features |= TL_FEATURE_POLISH;
    u->miss_at_start = q->miss_at_start;
    u->march_relax = (float)q->march_relax;
    u->plan.march_prepass = q->march_prepass;
    u->prepass_budget = q->prepass_budget;
    u->plan.giant_prepass = q->giant_prepass;
    u->normalize_smoothed = q->normalize_smoothed;
    u->facing_normals = q->facing_normals;
    if (q->analytic_normals)
        u->features |= TL_FEATURE_ANALYTIC_NORMALS;
    if (q->lod) {
        u->features |= TL_FEATURE_LOD;
        if (q->filtered_shading)
            u->features |= TL_FEATURE_FILTERED_SHADING;
        u->lod_angle = (float)(2.0 * tan(0.5 * s->camera.vfov) / u->height /
                               sqrt((double)(q->spp < 1 ? 1 : q->spp)));
    }
    u->spp = q->spp < 1 ? 1 : q->spp;
    if (u->spp > 1)
        u->features |= TL_FEATURE_SUPERSAMPLE;
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
    u->exposure = (float)(s->exposure * exp2(-s->ev));
    u->bloom = (float)s->bloom;
    u->pixel_filter = (float)s->quality.pixel_filter;
    tl_prepare_white_gain(s, u->white_gain);
    tl_giant giant;
    tl_giant_prepare(&giant, &s->giant, s->time);
    prepare_giant(s, w, &giant, u);
    prepare_objects(s, w, &giant, u);
    prepare_water_body(s, w, &giant, u);
    prepare_fog(s, u);
    prepare_sky(s, u);
    sky_rows(u);
    tl_prepare_wake_rect(s, u);
}
