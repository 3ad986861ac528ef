/* The boat's light on the GPU (llvmpipe on CI): its materials' formulas
 * against their CPU mirror (shaders/material.glsl, tl_mesh_shading.c); the
 * sun's shadows, of the wheelhouse on the deck by the factor the BRDF
 * says, of the boat on the water beside it and on the sand below it; the
 * hull seen from below,
 * dark against the surface and modelled by the water's light; above the
 * water, no part of it black; the bow wave of a boat under way; and all
 * of it 1e4 m out at t = 1e5 s as at the origin. */
#include <stdlib.h>
#include <string.h>

#include "core/tl_math.h"
#include "mesh/tl_mesh.h"
#include "optics/tl_optics.h"
#include "tl_gl_test.h"
#include "waves/tl_bow_spray.h"

/* The built-in boat, 9 m long, at the origin with its bow north (+z). */
static void boat_at_origin(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 320;
    s->height = 180;
    s->time = 3.0;
    s->boat.enabled = true;
    s->boat.size = 9.0;
    s->boat.scale = 9.0;
    s->boat.length = 9.0;
    s->boat.beam = 9.0 * TL_BOAT_BEAM_RATIO;
    s->boat.wake = 0.0;
    s->boat.heading = 0.0;
    /* Floating: its design waterline on the waves (the spring settled). */
    tl_waves w;
    tl_waves_init(&w, &s->ocean);
    s->boat.position[1] = tl_waves_height(&w, 0.0, 0.0, s->time, TL_MAX_OCTAVES);
}

/* Scene s rendered with the boat's shadows and without (both frames
 * freed on failure). */
static int render_shadows_on_off(tl_renderer *r, const tl_scene *s, tl_frame *lit, tl_frame *unlit)
{
    tl_scene off = *s;
    off.boat.shadows = false;
    if (render(r, s, lit))
        return -1;
    if (render(r, &off, unlit)) {
        tl_frame_free(lit);
        return -1;
    }
    return 0;
}

/* Model point m through the frame's matrices: camera-relative world w and
 * its pixel (top row first); 0 when it is behind the camera. */
static int project(const tl_scene *s, const tl_frame_uniforms *u, const double m[3], double w[3],
                   int *px, int *py)
{
    for (int i = 0; i < 3; i++)
        w[i] = u->object_pass[0].model[i] * m[0] + u->object_pass[0].model[4 + i] * m[1] +
               u->object_pass[0].model[8 + i] * m[2] + u->object_pass[0].model[12 + i];
    double clip[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            clip[i] += u->view_proj[k * 4 + i] * (k < 3 ? w[k] : 1.0);
    if (clip[3] <= 0.0)
        return 0;
    *px = (int)((clip[0] / clip[3] * 0.5 + 0.5) * s->width);
    *py = s->height - 1 - (int)((clip[1] / clip[3] * 0.5 + 0.5) * s->height);
    return *px >= 0 && *px < s->width && *py >= 0 && *py < s->height;
}

static const float *pixel(const tl_frame *f, int x, int y)
{
    return f->color + ((size_t)y * f->width + x) * 4;
}

/* The GPU's BRDF, environment share and wetness against the CPU's. */
static void test_material_probe(tl_renderer *r)
{
    enum { N = 64 };
    tl_scene s;
    boat_at_origin(&s);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    float in[N * 4], brdf[N * 4], env[N * 4], wet[N * 4];
    srand(7);
    for (int i = 0; i < N; i++) {
        in[4 * i] = (float)(1.5 * rand() / RAND_MAX);      /* view from the normal */
        in[4 * i + 1] = (float)(1.5 * rand() / RAND_MAX);  /* light from the normal */
        in[4 * i + 2] = (float)(6.28 * rand() / RAND_MAX); /* azimuth between */
        float rough = (float)(0.02 + 0.98 * rand() / RAND_MAX);
        in[4 * i + 3] = i % 3 == 0 ? -rough : rough; /* every third a metal */
    }
    tl_error err;
    tl_error_clear(&err);
    float env_in[N * 4], wet_in[N * 4], wash_in[N * 4], wash[N * 4];
    for (int i = 0; i < N; i++) {
        env_in[4 * i] = (float)i / (N - 1);                  /* cos */
        env_in[4 * i + 1] = (float)((i * 37) % N) / (N - 1); /* roughness */
        wet_in[4 * i] = (float)(0.8 * i / (N - 1));          /* metres above */
        wet_in[4 * i + 1] = (float)((i * 11) % N) / (N - 1);
        env_in[4 * i + 2] = env_in[4 * i + 3] = wet_in[4 * i + 2] = wet_in[4 * i + 3] = 0.0f;
        wash_in[4 * i] = (float)(-0.4 + 1.4 * ((i * 29) % N) / (N - 1)); /* metres above */
        wash_in[4 * i + 1] = (float)i / (N - 1);                         /* along */
        wash_in[4 * i + 2] = (float)(8.0 * ((i * 13) % N) / (N - 1));    /* speed */
        wash_in[4 * i + 3] = (float)((i * 7) % N) / (N - 1);             /* lace */
    }
    int rc = tl_renderer_probe4(r, &u, 13, in, N, u.octaves, brdf, &err) ||
             tl_renderer_probe4(r, &u, 14, env_in, N, u.octaves, env, &err) ||
             tl_renderer_probe4(r, &u, 15, wet_in, N, u.octaves, wet, &err) ||
             tl_renderer_probe4(r, &u, 26, wash_in, N, u.octaves, wash, &err);
    if (rc) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    double worst = 0.0, worst_env = 0.0, worst_wet = 0.0, worst_wash = 0.0;
    const double base[3] = {0.8, 0.4, 0.1}, up[3] = {0.0, 1.0, 0.0};
    const double f0[3] = {0.04, 0.5, 0.9};
    for (int i = 0; i < N; i++) {
        double tv = in[4 * i], tl = in[4 * i + 1], az = in[4 * i + 2];
        double v[3] = {sin(tv), cos(tv), 0.0};
        double l[3] = {sin(tl) * cos(az), cos(tl), sin(tl) * sin(az)};
        double want[3], want_env[3];
        tl_mesh_brdf(up, v, l, base, fabs(in[4 * i + 3]), in[4 * i + 3] < 0.0f ? 1.0 : 0.0, want);
        tl_mesh_env_brdf(f0, env_in[4 * i + 1], env_in[4 * i], want_env);
        for (int c = 0; c < 3; c++) {
            /* Relative where the lobe is tall (the sun's highlight on a
             * smooth metal), absolute where it is small. */
            worst = fmax(worst, fabs(brdf[4 * i + c] - want[c]) / fmax(fabs(want[c]), 0.05));
            worst_env = fmax(worst_env, fabs(env[4 * i + c] - want_env[c]));
        }
        worst_wet =
            fmax(worst_wet, fabs(wet[4 * i] - tl_mesh_wetness(wet_in[4 * i], wet_in[4 * i + 1])));
        double top = tl_mesh_wash_top(wash_in[4 * i + 1], wash_in[4 * i + 2]);
        worst_wash =
            fmax(worst_wash,
                 fabs(wash[4 * i] - tl_mesh_wash_cover(wash_in[4 * i], top, wash_in[4 * i + 3])));
    }
    printf("materials, GPU against CPU over %d inputs: BRDF %.2g (relative), environment %.2g, "
           "wetness %.2g, wash %.2g\n",
           N, worst, worst_env, worst_wet, worst_wash);
    CHECK(worst_wash < 1e-5);
    /* The wash: a line at rest; at 6 m/s the bow wave climbs the stem to
     * TL_MESH_BOW_CLIMB of U^2 / 2g over the line, and not amidships. */
    CHECK_NEAR(tl_mesh_wash_top(1.0, 0.0), TL_MESH_WASH_LINE, 1e-12);
    CHECK_NEAR(tl_mesh_wash_top(1.0, 6.0), TL_MESH_WASH_LINE + TL_MESH_BOW_CLIMB * 36.0 / 19.62,
               1e-12);
    CHECK_NEAR(tl_mesh_wash_top(0.4, 6.0), TL_MESH_WASH_LINE, 1e-12);
    CHECK(tl_mesh_wash_cover(0.0, 0.5, 0.5) == 1.0 && tl_mesh_wash_cover(0.7, 0.5, 1.0) == 0.0);
    CHECK(worst < 1e-3);
    CHECK(worst_env < 1e-5);
    CHECK(worst_wet < 1e-5);
    /* Known values: a smooth surface seen head-on reflects its f0 of an
     * even environment (Karis's fit within 1%), and the hull is wet at its
     * waterline and dry well above it. */
    double head_on[3];
    tl_mesh_env_brdf(f0, 0.0, 1.0, head_on);
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(head_on[c], f0[c], 0.01);
    CHECK_NEAR(tl_mesh_wetness(0.0, 0.5), 1.0, 1e-12);
    CHECK_NEAR(tl_mesh_wetness(TL_MESH_WET_HIGH + 0.01, 1.0), 0.0, 1e-12);
}

/* Sun ahead of the bow, 40 degrees up: the wheelhouse shades the deck
 * behind it. There the shadowed frame is darker than the unshadowed one
 * by the sun's term the CPU's BRDF gives (what is left is the sky's);
 * out on the open aft deck the two agree. */
static void test_deck_shadow(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.sun.elevation = 40.0 * M_PI / 180.0;
    s.sun.azimuth = 0.0;
    s.camera.position[0] = 5.0;
    s.camera.position[1] = 12.0;
    s.camera.position[2] = -8.0;
    const double target[3] = {0.0, 0.5, -2.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    tl_frame lit, unlit;
    if (render_shadows_on_off(r, &s, &lit, &unlit))
        return;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_BOAT_SHADOW);
    tl_scene off = s;
    off.boat.shadows = false;
    tl_frame_uniforms u_off;
    gl_test_prepare(r, &off, &u_off);
    CHECK(!(u_off.features & TL_FEATURE_BOAT_SHADOW));
    /* The deck's crown, 0.05 units behind the wheelhouse's aft wall (in
     * its shadow, which reaches 0.18 units aft), and 0.38 units further
     * aft (in the sun). */
    const double deck_y = 0.1 + 0.07 * 0.3 * 0.3 - 0.03 + 0.005;
    const double shaded[3] = {0.0, deck_y, -0.21}, sunny[3] = {0.0, deck_y, -0.44};
    double ws[3], wu[3];
    int sx, sy, ux, uy;
    CHECK(project(&s, &u, shaded, ws, &sx, &sy));
    CHECK(project(&s, &u, sunny, wu, &ux, &uy));
    /* The sun's term there: the deck's material (grey non-slip, dry,
     * facing up) under the frame's sun, seen from the camera. */
    double n[3] = {0.0, 1.0, 0.0}, v[3], l[3], base[3] = {0.17, 0.17, 0.15}, sun_term[3];
    double len = sqrt(ws[0] * ws[0] + ws[1] * ws[1] + ws[2] * ws[2]);
    for (int k = 0; k < 3; k++) {
        v[k] = -ws[k] / len;
        l[k] = u.sun_dir[k];
    }
    tl_mesh_brdf(n, v, l, base, 0.85, 0.0, sun_term);
    double want = 0.0, on = 0.0, off_sh = 0.0;
    for (int c = 0; c < 3; c++) {
        want += sun_term[c] * u.sun_light[c] * u.object_pass[0].sunlit;
        on += pixel(&lit, sx, sy)[c];
        off_sh += pixel(&unlit, sx, sy)[c];
    }
    double on_sun = 0.0, off_sun = 0.0;
    for (int c = 0; c < 3; c++) {
        on_sun += pixel(&lit, ux, uy)[c];
        off_sun += pixel(&unlit, ux, uy)[c];
    }
    printf("deck in the wheelhouse's shadow (%d, %d): %.4f, unshadowed %.4f, the sun's term "
           "%.4f (CPU); in the sun (%d, %d): %.4f against %.4f\n",
           sx, sy, on, off_sh, want, ux, uy, on_sun, off_sun);
    CHECK(on < 0.6 * off_sh);
    CHECK(fabs((off_sh - on) - want) < 0.1 * want);
    CHECK(fabs(on_sun - off_sun) < 0.02 * off_sun);
    tl_frame_free(&lit);
    tl_frame_free(&unlit);
}

/* Sun from the east, 30 degrees up: the boat's shadow falls on the water
 * west of it. The water there is darker with shadows on; east of the boat
 * it is the same. */
static void test_water_shadow(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.sun.elevation = 30.0 * M_PI / 180.0;
    s.sun.azimuth = 90.0 * M_PI / 180.0;
    s.camera.position[0] = -2.0;
    s.camera.position[1] = 16.0;
    s.camera.position[2] = -14.0;
    const double target[3] = {-1.5, 0.0, 0.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    tl_frame lit, unlit;
    if (render_shadows_on_off(r, &s, &lit, &unlit))
        return;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    /* Where the wheelhouse's middle casts its shadow on the water plane,
     * and as far on the sunny side. */
    const double cabin[3] = {0.0, 0.16, -0.05};
    double w[3];
    int px, py;
    project(&s, &u, cabin, w, &px, &py);
    double along = (w[1] - u.objects[0].hull[1]) / u.sun_dir[1];
    double shadow_model_x = -along * u.sun_dir[0] / 9.0; /* heading 0: world x is model x */
    const double in_shadow[3] = {shadow_model_x, 0.0, -0.05},
                 sunny[3] = {-shadow_model_x, 0.0, -0.05};
    int ax, ay, bx, by;
    CHECK(project(&s, &u, in_shadow, w, &ax, &ay));
    CHECK(project(&s, &u, sunny, w, &bx, &by));
    double dark = 0.0, dark_off = 0.0, same_diff = 0.0, same = 0.0;
    int count = 0;
    for (int dy = -2; dy <= 2; dy++)
        for (int dx = -2; dx <= 2; dx++) {
            dark += luminance(pixel(&lit, ax + dx, ay + dy));
            dark_off += luminance(pixel(&unlit, ax + dx, ay + dy));
            same += luminance(pixel(&unlit, bx + dx, by + dy));
            same_diff += fabs(luminance(pixel(&lit, bx + dx, by + dy)) -
                              luminance(pixel(&unlit, bx + dx, by + dy)));
            count++;
        }
    printf("water in the boat's shadow (%d, %d), %.2f m west: %.4f against %.4f unshadowed; "
           "east of it (%d, %d): differs by %.2g of %.4f\n",
           ax, ay, shadow_model_x * 9.0, dark / count, dark_off / count, bx, by, same_diff / count,
           same / count);
    CHECK(dark < 0.85 * dark_off);
    CHECK(same_diff < 1e-3 * same);
    tl_frame_free(&lit);
    tl_frame_free(&unlit);
}

/* The boat's shadow on the sand (boat_shadow_below): a sand floor 6 m
 * down, the sun 60 degrees up in the east; from 3 m down, looking straight
 * down (the boat out of view), the sand where the sun's beam in the water
 * carries the boat's centre is darker with shadows on; away from it the
 * frame is the same. */
static void test_floor_shadow(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.width = s.height = 64;
    s.ocean.floor_depth = 6.0;
    s.sun.elevation = 60.0 * TL_DEG;
    s.sun.azimuth = 90.0 * TL_DEG;
    double sun[3], beam[3];
    tl_scene_sun_direction(&s.sun, sun);
    tl_optics_sun_in_water(sun, s.water.ior, beam);
    double run = 6.0 / -beam[1];
    s.camera.position[0] = run * beam[0];
    s.camera.position[1] = -3.0;
    s.camera.position[2] = run * beam[2];
    s.camera.pitch = -90.0 * TL_DEG;
    s.camera.vfov = 90.0 * TL_DEG;
    tl_frame lit, unlit;
    if (render_shadows_on_off(r, &s, &lit, &unlit))
        return;
    double dark = 0.0, dark_off = 0.0, far = 0.0, far_diff = 0.0;
    for (int dy = -2; dy <= 2; dy++)
        for (int dx = -2; dx <= 2; dx++) {
            dark += luminance(pixel(&lit, 32 + dx, 32 + dy));
            dark_off += luminance(pixel(&unlit, 32 + dx, 32 + dy));
            far += luminance(pixel(&unlit, 4 + dx + 2, 4 + dy + 2));
            far_diff += fabs(luminance(pixel(&lit, 4 + dx + 2, 4 + dy + 2)) -
                             luminance(pixel(&unlit, 4 + dx + 2, 4 + dy + 2)));
        }
    printf("sand 6 m down in the boat's shadow, %.2f m west of it: %.4f against %.4f "
           "unshadowed; a corner of the frame differs by %.2g of %.4f\n",
           -s.camera.position[0], dark / 25, dark_off / 25, far_diff / 25, far / 25);
    CHECK(dark < 0.8 * dark_off);
    CHECK(far_diff < 1e-3 * far);
    tl_frame_free(&lit);
    tl_frame_free(&unlit);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The hull's pixels: where the frame with the boat is nearer than the one
 * without. Their luminances sorted into *out (freed by the caller). */
static int hull_pixels(const tl_frame *with, const tl_frame *without, double **out, double *behind)
{
    size_t n = (size_t)with->width * with->height;
    double *l = malloc(n * sizeof *l), *b = malloc(n * sizeof *b);
    int count = 0;
    for (size_t i = 0; l && b && i < n; i++)
        if (with->depth[i] < without->depth[i] - 0.2) {
            l[count] = luminance(with->color + 4 * i);
            b[count++] = luminance(without->color + 4 * i);
        }
    if (l && b && count > 0) {
        qsort(l, (size_t)count, sizeof *l, by_value);
        qsort(b, (size_t)count, sizeof *b, by_value);
        *behind = b[count / 2];
    }
    free(b);
    *out = l;
    return count;
}

/* From below in daylight (the dive's view): the hull is darker than the
 * surface behind it, and its form shows: the spread of its luminance (10th
 * to 90th percentile over the median) is at least 0.5. */
static void test_hull_from_below(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.boat.size = s.boat.scale = s.boat.length = 8.0;
    s.sun.elevation = 40.0 * M_PI / 180.0;
    s.sun.azimuth = 200.0 * M_PI / 180.0;
    s.camera.position[0] = 2.5;
    s.camera.position[1] = -4.5;
    s.camera.position[2] = 0.0;
    s.camera.yaw = -90.0 * M_PI / 180.0;
    s.camera.pitch = 60.0 * M_PI / 180.0;
    s.camera.vfov = 75.0 * M_PI / 180.0;
    tl_frame with, without;
    if (render_boat_pair(r, &s, &with, &without))
        return;
    double *l = NULL, behind = 0.0;
    int count = hull_pixels(&with, &without, &l, &behind);
    CHECK(count > 500);
    if (count > 500) {
        double p10 = l[count / 10], median = l[count / 2], p90 = l[count * 9 / 10];
        double spread = (p90 - p10) / median;
        printf("hull from below, %d pixels: luminance 10th %.4f, median %.4f, 90th %.4f: spread "
               "%.2f; the surface behind it %.4f\n",
               count, p10, median, p90, spread, behind);
        CHECK(spread >= 0.5);
        CHECK(median < 0.7 * behind);
    }
    free(l);
    tl_frame_free(&with);
    tl_frame_free(&without);
}

/* Above the water in daylight no part of the hull is black: its darkest
 * twentieth (glass, shadowed recesses) is still over 3% of the frame's
 * mean, and its median well above that. */
static void test_hull_above(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.sun.elevation = 28.0 * M_PI / 180.0;
    s.sun.azimuth = 130.0 * M_PI / 180.0;
    s.camera.position[0] = 7.0;
    s.camera.position[1] = 2.2;
    s.camera.position[2] = -8.0;
    const double target[3] = {0.0, 1.0, 0.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    tl_frame with, without;
    if (render_boat_pair(r, &s, &with, &without))
        return;
    double mean = 0.0;
    for (size_t i = 0; i < (size_t)with.width * with.height; i++)
        mean += luminance(with.color + 4 * i);
    mean /= (double)with.width * with.height;
    double *l = NULL, behind = 0.0;
    int count = hull_pixels(&with, &without, &l, &behind);
    CHECK(count > 500);
    if (count > 500) {
        printf("hull above the water, %d pixels: 5th percentile %.4f, median %.4f, frame mean "
               "%.4f\n",
               count, l[count / 20], l[count / 2], mean);
        CHECK(l[count / 20] > 0.03 * mean);
        CHECK(l[count / 2] > 0.3 * mean);
    }
    free(l);
    tl_frame_free(&with);
    tl_frame_free(&without);
}

/* The boat under way (5 m/s over its last stretch) throws a bow wave: the
 * water round its bow is whiter than with the same boat drifting, and only
 * there: every pixel that changed lies within 3 m of the hull. */
static void test_bow_wave(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.sun.elevation = 35.0 * M_PI / 180.0;
    s.sun.azimuth = 200.0 * M_PI / 180.0;
    s.camera.position[0] = 3.0;
    s.camera.position[1] = 14.0;
    s.camera.position[2] = -4.0;
    const double target[3] = {0.0, 0.0, 2.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    s.boat.wake_step = 0.5;
    tl_scene drifting = s;
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        s.boat.wake_path[k][1] = -2.5 * k; /* 5 m/s */
        drifting.boat.wake_path[k][1] = 0.0;
    }
    tl_frame under_way, still;
    if (render(r, &s, &under_way))
        return;
    if (render(r, &drifting, &still)) {
        tl_frame_free(&under_way);
        return;
    }
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK_NEAR(u.objects[0].hull[2], 5.0, 1e-3);
    /* The hull's bounds 3 m out, on the water plane, on screen. */
    int x0 = s.width, y0 = s.height, x1 = -1, y1 = -1;
    for (int i = 0; i < 4; i++) {
        double c[3] = {(i & 1 ? 0.17 : -0.17) + (i & 1 ? 1.0 : -1.0) * 3.0 / 9.0, 0.0,
                       (i & 2 ? 0.5 : -0.5) + (i & 2 ? 1.0 : -1.0) * 3.0 / 9.0},
               w[3];
        int px = 0, py = 0;
        project(&s, &u, c, w, &px, &py);
        x0 = px < x0 ? px : x0, x1 = px > x1 ? px : x1;
        y0 = py < y0 ? py : y0, y1 = py > y1 ? py : y1;
    }
    long whiter = 0, outside = 0;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            double d = luminance(pixel(&under_way, x, y)) - luminance(pixel(&still, x, y));
            if (fabs(d) < 0.01)
                continue;
            whiter += d > 0.0;
            outside += x < x0 || x > x1 || y < y0 || y > y1;
        }
    printf("bow wave at 5 m/s: %ld pixels whiter than drifting, %ld changed outside the hull's "
           "bounds 3 m out (%d..%d, %d..%d)\n",
           whiter, outside, x0, x1, y0, y1);
    CHECK(whiter > 50);
    CHECK(outside == 0);
    tl_frame_free(&under_way);
    tl_frame_free(&still);
}

/* Beside the bow at 5 m/s against drifting: the bow wave's water climbs
 * the hull's forward half (a sheet of sea darkens the white paint, foam in
 * it whitens it), and the aft half keeps its paint (the wash line's
 * texture moves with the path there, brighter and darker alike). */
static void test_bow_wash(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.sun.elevation = 35.0 * M_PI / 180.0;
    s.sun.azimuth = 100.0 * M_PI / 180.0;
    s.camera.position[0] = 9.0;
    s.camera.position[1] = 1.5;
    s.camera.position[2] = 0.0;
    const double target[3] = {0.0, 0.2, 0.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    s.boat.wake_step = 0.5;
    tl_scene drifting = s, none = s;
    none.boat.enabled = false;
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        s.boat.wake_path[k][1] = -2.5 * k; /* 5 m/s */
        drifting.boat.wake_path[k][1] = none.boat.wake_path[k][1] = 0.0;
    }
    tl_frame under_way, still, empty;
    if (render(r, &s, &under_way))
        return;
    if (render(r, &drifting, &still) || render(r, &none, &empty)) {
        tl_frame_free(&under_way);
        return;
    }
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    const double stem[3] = {0.0, 0.0, 0.5}, transom[3] = {0.0, 0.0, -0.5};
    double w[3];
    int sx = 0, sy = 0, tx = 0, ty = 0;
    project(&s, &u, stem, w, &sx, &sy);
    project(&s, &u, transom, w, &tx, &ty);
    int mid = (sx + tx) / 2, forward_sign = sx > tx ? 1 : -1;
    long fore = 0, fore_whiter = 0, fore_changed = 0, aft = 0, aft_changed = 0;
    double aft_change = 0.0;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            size_t i = (size_t)y * s.width + x;
            if (!(under_way.depth[i] < empty.depth[i] - 0.2 &&
                  still.depth[i] < empty.depth[i] - 0.2))
                continue;
            double d = luminance(pixel(&under_way, x, y)) - luminance(pixel(&still, x, y));
            if ((x - mid) * forward_sign > 0) {
                fore++;
                fore_whiter += d > 0.05;
                fore_changed += fabs(d) > 0.05;
            } else {
                aft++;
                aft_change += d;
                aft_changed += fabs(d) > 0.05;
            }
        }
    printf("bow wash at 5 m/s, from beside: of %ld hull pixels forward, %ld changed against "
           "drifting, %ld whiter; aft, of %ld, %ld changed, mean change %.4f\n",
           fore, fore_changed, fore_whiter, aft, aft_changed, aft ? aft_change / aft : 0.0);
    CHECK(fore > 500 && aft > 500);
    CHECK(fore_changed > 4 * aft_changed + 50);
    CHECK(fore_whiter > 20); /* the foam in streaks in it */
    CHECK(aft > 0 && fabs(aft_change / aft) < 0.01);
    tl_frame_free(&under_way);
    tl_frame_free(&still);
    tl_frame_free(&empty);
}

/* The lamps: the built-in boat's four (masthead and stern white, all
 * round; red to port at -x and green to starboard, each to its side), their glint in the water on
 * the GPU as on the CPU and carrying the lamp's light (its integral over the sky is the lamp's
 * disc, pi size^2, however widened); at dusk with boat.lights on, the water beside the boat takes
 * their light and the hull's pixels are the ones the lamps themselves change. */
static void test_lamp_glints(tl_renderer *r, const tl_mesh *m)
{
    float where[TL_MESH_LAMPS][4], light[TL_MESH_LAMPS][4];
    int count = tl_mesh_lamps(m, where, light);
    int red = 0, green = 0, white = 0;
    for (int k = 0; k < count; k++) {
        /* The side lights shine to their own side only (w). */
        if (light[k][0] > 5.0 * light[k][1] && where[k][0] < 0.0f && light[k][3] == -1.0f)
            red++;
        else if (light[k][1] > 3.0 * light[k][0] && where[k][0] > 0.0f && light[k][3] == 1.0f)
            green++;
        else if (light[k][0] > 0.5 * light[k][1] && light[k][1] > 0.5 * light[k][0] &&
                 light[k][3] == 0.0f)
            white++;
    }
    printf("lamps of the built-in boat: %d (red to port %d, green to starboard %d, white %d)\n",
           count, red, green, white);
    CHECK(count == 4 && red == 1 && green == 1 && white == 2);

    enum { N = 32 };
    tl_scene s;
    boat_at_origin(&s);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    float in[2 * N], out[4 * N];
    for (int i = 0; i < N; i++) {
        in[2 * i] = (float)cos(0.04 * i / N);          /* up to 0.04 rad off its centre */
        in[2 * i + 1] = (float)(i % 2 ? 0.004 : 0.03); /* under and over the least spread */
    }
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe(r, &u, 27, in, N, 1, out, &err) == 0);
    double worst = 0.0;
    for (int i = 0; i < N; i++)
        worst = fmax(worst, fabs(out[4 * i] - tl_optics_lamp_glint(in[2 * i], in[2 * i + 1])));
    /* Its light over the sky, for a lamp under and over the least spread. */
    double carried[2];
    const double sizes[2] = {0.004, 0.03};
    for (int k = 0; k < 2; k++) {
        double sum = 0.0, step = 1e-5;
        for (double a = 0.5 * step; a < 0.3; a += step)
            sum += tl_optics_lamp_glint(cos(a), sizes[k]) * 2.0 * M_PI * sin(a) * step;
        carried[k] = sum / (M_PI * sizes[k] * sizes[k]);
    }
    printf("lamp glints: GPU against CPU %.2g; light carried against the lamp's disc %.4f (4 mrad) "
           "%.4f (30 mrad)\n",
           worst, carried[0], carried[1]);
    CHECK(worst < 1e-5);
    CHECK_NEAR(carried[0], 1.0, 0.01);
    CHECK_NEAR(carried[1], 1.0, 0.01);

    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    boat_at_origin(&s);
    s.sun.elevation = -2.0 * M_PI / 180.0;
    s.camera.position[0] = 14.0;
    s.camera.position[1] = 2.0;
    s.camera.position[2] = -6.0;
    const double target[3] = {0.0, 0.5, 0.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    tl_scene lit = s, none = s;
    s.boat.lights = 0.0;
    lit.boat.lights = 1.0;
    none.boat.enabled = false;
    tl_frame dark, bright, empty;
    if (render(r, &s, &dark))
        return;
    if (render(r, &lit, &bright) || render(r, &none, &empty)) {
        tl_frame_free(&dark);
        return;
    }
    long water = 0, hull = 0, lit_water = 0;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            size_t i = (size_t)y * s.width + x;
            bool on_hull = bright.depth[i] < empty.depth[i] - 0.2;
            double d = luminance(pixel(&bright, x, y)) - luminance(pixel(&dark, x, y));
            if (on_hull) {
                hull++;
                continue;
            }
            water++;
            lit_water += d > 1e-3 + 0.1 * luminance(pixel(&dark, x, y));
        }
    printf("lamps at dusk: %ld of %ld water pixels lit by them (over a tenth brighter)\n",
           lit_water, water);
    CHECK(hull > 300);
    CHECK(lit_water > 100);
    CHECK(lit_water < water / 2);
    tl_frame_free(&dark);
    tl_frame_free(&bright);
    tl_frame_free(&empty);
}

/* The bow's spray: compiled in only where the water rises against the bow
 * fast enough; its density on the GPU against the CPU's; drawn, it whitens
 * the water around the stem and nothing beyond the sheet's sphere. */
static void test_bow_spray(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    tl_scene s;
    boat_at_origin(&s);
    s.camera.position[0] = 9.0;
    s.camera.position[1] = 3.0;
    s.camera.position[2] = 6.0;
    const double target[3] = {0.0, 1.0, 3.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    tl_scene calm = s;
    calm.boat.impact = 0.3; /* riding the chop */
    s.boat.impact = 2.0;    /* slamming into a wave */
    tl_frame_uniforms u, u_calm;
    gl_test_prepare(r, &calm, &u_calm);
    CHECK(!(u_calm.features & TL_FEATURE_BOW_SPRAY));
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_BOW_SPRAY);
    tl_bow_spray sp;
    tl_bow_spray_prepare(&sp, &s.boat);
    CHECK(sp.active && sp.radius > 0.0);
    enum { N = 256 };
    float in[N * 4], out[N * 4];
    srand(5);
    for (int i = 0; i < N; i++) {
        for (int c = 0; c < 3; c++)
            in[4 * i + (c == 1   ? 2
                        : c == 2 ? 1
                                 : 0)] =
                (float)(sp.center[c] - (c == 1 ? 0.0 : s.camera.position[c]) +
                        1.2 * sp.radius * (2.0 * rand() / RAND_MAX - 1.0));
        in[4 * i + 3] = 0.0f;
    }
    if (tl_renderer_probe4(r, &u, 18, in, N, u.octaves, out, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    double worst = 0.0, most = 0.0, worst_shade = 0.0, most_shade = 0.0;
    int dense = 0;
    const double sun[3] = {u.sun_dir[0], u.sun_dir[1], u.sun_dir[2]};
    for (int i = 0; i < N; i++) {
        double x = in[4 * i] + s.camera.position[0], y = in[4 * i + 2],
               z = in[4 * i + 1] + s.camera.position[2];
        double want = tl_bow_spray_density(&sp, x, y, z);
        double shade = tl_bow_spray_shade(&sp, x, y, z, sun);
        worst = fmax(worst, fabs(out[4 * i] - want));
        worst_shade = fmax(worst_shade, fabs(out[4 * i + 1] - shade) / fmax(shade, 1.0));
        most = fmax(most, want);
        most_shade = fmax(most_shade, shade);
        dense += want > 0.1 * sp.amount;
    }
    printf("bow spray: radius %.2f m, amount %.2f; GPU against CPU over %d points: %.2g (the "
           "densest %.2f, %d over a tenth of the amount); its shade %.2g (up to %.2f)\n",
           sp.radius, sp.amount, N, worst, most, dense, worst_shade, most_shade);
    CHECK(dense > 10);
    CHECK(worst < 1e-3 * sp.amount);
    CHECK(most_shade > 0.05);
    CHECK(worst_shade < 2e-3);
    /* Drawn: whiter around the stem, nothing beyond the sheet's sphere. */
    tl_frame with, without;
    if (render(r, &s, &with))
        return;
    if (render(r, &calm, &without)) {
        tl_frame_free(&with);
        return;
    }
    const double reach = tl_bow_spray_reach(sp.radius, 0.0);
    long whiter = 0, outside = 0;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            double d = luminance(pixel(&with, x, y)) - luminance(pixel(&without, x, y));
            if (fabs(d) < 0.005)
                continue;
            whiter += d > 0.0;
            /* The pixel's ray's closest approach to the sphere's centre. */
            double ray[3], c[3], along = 0.0, c2 = 0.0;
            pixel_ray(&s, x, y, ray);
            for (int k = 0; k < 3; k++) {
                c[k] = sp.center[k] - s.camera.position[k];
                along += c[k] * ray[k];
                c2 += c[k] * c[k];
            }
            outside += c2 - along * along > (reach + 0.5) * (reach + 0.5);
        }
    printf("bow spray drawn: %ld pixels whiter, %ld changed beyond its sphere\n", whiter, outside);
    CHECK(whiter > 200);
    CHECK(outside == 0);
    tl_frame_free(&with);
    tl_frame_free(&without);
}

/* The boat's look where it is drawn at (x0 + dx, z0 + dz) at time t: its
 * hull's pixels and their mean luminance, the pixels its bow wave whitens
 * (under way at 5 m/s against drifting) and those its shadow darkens
 * (against the water plate, boat.visible off). */
typedef struct boat_look {
    long hull, whiter, darker;
    double hull_mean;
} boat_look;

static int look_at(tl_renderer *r, double dx, double dz, double t, boat_look *out)
{
    tl_scene s;
    boat_at_origin(&s);
    s.time = t;
    s.boat.position[0] = dx;
    s.boat.position[1] = 0.0; /* posed alike wherever it is */
    s.boat.position[2] = dz;
    s.boat.pitch = 0.02;
    s.boat.roll = -0.03;
    s.sun.elevation = 35.0 * M_PI / 180.0;
    s.sun.azimuth = 200.0 * M_PI / 180.0;
    s.camera.position[0] = dx + 6.0;
    s.camera.position[1] = 10.0;
    s.camera.position[2] = dz - 9.0;
    const double target[3] = {dx, 0.0, dz + 1.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    s.boat.wake = 0.6;
    s.boat.wake_step = 0.5;
    tl_scene drifting = s, plate = s;
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        s.boat.wake_path[k][0] = drifting.boat.wake_path[k][0] = dx;
        s.boat.wake_path[k][1] = dz - 2.5 * k;
        drifting.boat.wake_path[k][1] = dz;
    }
    memcpy(plate.boat.wake_path, s.boat.wake_path, sizeof s.boat.wake_path);
    plate.boat.visible = false;
    tl_frame f[3];
    const tl_scene *scenes[3] = {&s, &drifting, &plate};
    for (int i = 0; i < 3; i++)
        if (render(r, scenes[i], &f[i])) {
            for (int k = 0; k < i; k++)
                tl_frame_free(&f[k]);
            return 1;
        }
    memset(out, 0, sizeof *out);
    for (size_t i = 0; i < (size_t)s.width * s.height; i++) {
        const double lw = luminance(f[0].color + 4 * i), ld = luminance(f[1].color + 4 * i),
                     lp = luminance(f[2].color + 4 * i);
        if (f[0].depth[i] < f[2].depth[i] - 0.05f) {
            out->hull++;
            out->hull_mean += lw;
            continue;
        }
        out->whiter += lw > ld + 0.01;
        out->darker += ld < lp - 0.003;
    }
    out->hull_mean /= out->hull ? out->hull : 1;
    for (int k = 0; k < 3; k++)
        tl_frame_free(&f[k]);
    return 0;
}

/* A boat 1e4 m out at t = 1e5 s looks as at the origin at t = 10 s: its
 * hull alike (the same pose, sun and sky), its bow wave and shadow of a
 * like extent (the waves under them differ). */
static void test_boat_far(tl_renderer *r, const tl_mesh *m)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, m, &err) == 0);
    boat_look near, far;
    if (look_at(r, 0.0, 0.0, 10.0, &near) || look_at(r, 1e4, -1e4, 1e5, &far))
        return;
    printf("boat at the origin at 10 s: hull %ld pixels, mean %.4f; bow wave and wake %ld pixels "
           "whiter, "
           "shadow %ld darker\n",
           near.hull, near.hull_mean, near.whiter, near.darker);
    printf("boat 1e4 m out at 1e5 s:    hull %ld pixels, mean %.4f; bow wave and wake %ld pixels "
           "whiter, "
           "shadow %ld darker\n",
           far.hull, far.hull_mean, far.whiter, far.darker);
    CHECK(near.hull > 1000 && near.whiter > 50 && near.darker > 50);
    CHECK(labs(far.hull - near.hull) <= 0.03 * near.hull);
    CHECK(fabs(far.hull_mean - near.hull_mean) <= 0.03 * near.hull_mean);
    CHECK(labs(far.whiter - near.whiter) <= 0.35 * near.whiter);
    CHECK(labs(far.darker - near.darker) <= 0.35 * near.darker);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    tl_error err;
    tl_error_clear(&err);
    tl_mesh boat;
    CHECK(tl_mesh_default_boat(&boat, &err) == 0);
    test_material_probe(r);
    test_deck_shadow(r, &boat);
    test_water_shadow(r, &boat);
    test_floor_shadow(r, &boat);
    test_hull_from_below(r, &boat);
    test_hull_above(r, &boat);
    test_bow_wave(r, &boat);
    test_bow_wash(r, &boat);
    test_lamp_glints(r, &boat);
    test_boat_far(r, &boat);
    test_bow_spray(r, &boat);
    tl_mesh_free(&boat);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
