/* The giant wave on the GPU (llvmpipe on CI): the shader's surface height
 * (and, for a breaking crest, its gradient) against the double CPU
 * mirror, fade 0 against the wave switched off, and
 * a frame that looks at the wave (depth, crest against the horizon, hits
 * on the surface, finite pixels), and the screen rectangle the renderer
 * draws the wave's program in (it holds every ray that can show the wave;
 * the split frame equals the frame drawn in one program). The light on the
 * wave (its glow, its shadow, the lip against the sky): test_giant_light.c. */
#include <string.h>

#include "tl_giant_test.h"

/* |GPU - CPU| <= 1e-3 m with the wave at full height near the camera, also
 * late and far from the origin; steep knobs, so the clamps are active. */
static void test_probe(tl_renderer *r)
{
    const double heights[] = {12.0, 40.0};
    const double near[3] = {3.0, 1.5, -4.0}, far[3] = {7.0e3, 2.0, -7.1e3};
    for (int h = 0; h < 2; h++)
        for (int where = 0; where < 2; where++) {
            tl_scene s;
            wave_scene(&s, heights[h], where ? 1.0e5 : 10.0, where ? far : near);
            s.giant.steepness = 1.0;
            s.giant.curve_strength = 1.0;
            double e12 = probe_error(r, &s, 12, 90.0, 64);
            double e36 = probe_error(r, &s, 36, 90.0, 64);
            printf("probe, %g m wave, t = %g s, %.0f m from the origin: max |gpu-cpu| = %.3g m "
                   "(12 octaves), %.3g m (36)\n",
                   heights[h], s.time, hypot(s.camera.position[0], s.camera.position[2]), e12, e36);
            CHECK(e12 <= 1e-3);
            CHECK(e36 <= 1e-3);
        }
    /* The probe really sees the wave: its heights reach far above the
     * ocean's 1 m band. */
    tl_scene s;
    wave_scene(&s, 40.0, 10.0, near);
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_frame_uniforms u;
    tl_prepare_frame(&s, &w, &u);
    CHECK(u.features & TL_FEATURE_GIANT_WAVE);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    float xz[2] = {(float)(g.origin[0] - near[0]), (float)(g.origin[1] - near[2])}, height = 0.0f;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe_heights(r, &u, xz, 1, 12, &height, &err) == 0);
    CHECK(height > 20.0f);
}

/* The peaked, bowed crest in mid-break (the shader's TL_FEATURE_GIANT_BREAK
 * code: the settling envelope) against the CPU mirror: heights (mode 0,
 * the march's path) within 1e-3 m, and the wave's own gradient and height
 * on the normals' path (mode 6, less the same probe without the wave)
 * against tl_giant_sample_at's (to 1e-3 m, and 5e-3 of the slope where it
 * exceeds 1); at t = 10 s near the origin, and at
 * t = 1e5 s with the wave 1e4 m from it. */
static void test_probe_breaking_crest(tl_renderer *r)
{
    const double near[3] = {3.0, 1.5, -4.0}, far[3] = {7.0e3, 2.0, -7.1e3};
    enum { N = 48 };
    for (int where = 0; where < 2; where++) {
        tl_scene s;
        wave_scene(&s, 20.0, where ? 1.0e5 : 10.0, where ? far : near);
        s.giant.peak = 15.0;
        s.giant.bow = 30.0;
        s.giant.variation = 0.5;
        s.giant.breaking = true;
        s.giant.break_time = s.time - 4.0; /* the peak has landed and settles */
        s.giant.break_drop = 0.5;
        s.giant.ride = 0.0; /* the ocean stays put: with - without is the wave's own */
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        tl_frame_uniforms u, calm_u;
        tl_prepare_frame(&s, &w, &u);
        CHECK(u.features & TL_FEATURE_GIANT_WAVE);
        CHECK(u.features & TL_FEATURE_GIANT_BREAK);
        tl_scene calm = s;
        calm.giant.enabled = false;
        tl_prepare_frame(&calm, &w, &calm_u);
        double e_height = probe_error(r, &s, 12, 90.0, 64);
        /* Mode 6 over the wave: camera-relative points 180 m square. */
        float xz[N * N * 2], with[N * N * 4], without[N * N * 4];
        for (int j = 0; j < N; j++)
            for (int i = 0; i < N; i++) {
                xz[(j * N + i) * 2 + 0] = (float)(-90.0 + 180.0 * i / (N - 1));
                xz[(j * N + i) * 2 + 1] = (float)(-90.0 + 180.0 * j / (N - 1));
            }
        tl_error err;
        tl_error_clear(&err);
        const int no = s.quality.normal_octaves;
        if (tl_renderer_probe(r, &u, 6, xz, N * N, no, with, &err) ||
            tl_renderer_probe(r, &calm_u, 6, xz, N * N, no, without, &err)) {
            printf("probe failed: %s\n", err.message);
            CHECK(0);
            return;
        }
        double e_wave = 0.0, e_grad = 0.0, steepest = 0.0, tallest = 0.0;
        for (int k = 0; k < N * N; k++) {
            double x = s.camera.position[0] + (double)xz[k * 2];
            double z = s.camera.position[2] + (double)xz[k * 2 + 1];
            tl_giant_sample smp;
            tl_giant_sample_at(&g, x, z, s.quality.giant_iterations, &smp);
            double gh = (double)with[k * 4 + 2] - without[k * 4 + 2];
            double gx = (double)with[k * 4 + 0] - without[k * 4 + 0];
            double gz = (double)with[k * 4 + 1] - without[k * 4 + 1];
            e_wave = fmax(e_wave, fabs(gh - smp.height));
            e_grad = fmax(e_grad, hypot(gx - smp.grad[0], gz - smp.grad[1]) /
                                      fmax(1.0, hypot(smp.grad[0], smp.grad[1])));
            steepest = fmax(steepest, hypot(smp.grad[0], smp.grad[1]));
            tallest = fmax(tallest, smp.height);
        }
        printf("breaking crest, t = %g s, %.0f m from the origin: max |gpu-cpu| height %.3g m "
               "(mode 0), the wave's height %.3g m and gradient %.3g relative (mode 6; steepest "
               "%.2f, tallest %.1f m)\n",
               s.time, hypot(s.camera.position[0], s.camera.position[2]), e_height, e_wave, e_grad,
               steepest, tallest);
        CHECK(tallest > 10.0 && steepest > 1.0); /* the probes saw the crest */
        CHECK(e_height <= 1e-3);
        CHECK(e_wave <= 1e-3);
        /* The shader's Newton loop stops once the height is within
         * TL_GIANT_CONVERGED (0.1 mm); where the profile is flat along (the
         * crest's top, the mask's foot) that leaves s0 a few centimetres
         * off, and the gradient a little more than 1e-3 (the normal less
         * than 0.1 degree). */
        CHECK(e_grad <= 5e-3);
    }
}

/* The double-precision mirror of the scene's surface. */
static void cpu_mirror(const tl_scene *s, tl_giant *giant, tl_waves *waves)
{
    tl_giant_prepare(giant, &s->giant, s->time);
    tl_waves_init(waves, &s->ocean);
}

/* Renders `s` into `f` and prepares its CPU mirror; non-zero if the render
 * failed (then `f` holds nothing). */
static int render_mirrored(tl_renderer *r, const tl_scene *s, tl_frame *f, tl_giant *giant,
                           tl_waves *waves)
{
    if (render(r, s, f))
        return 1;
    cpu_mirror(s, giant, waves);
    return 0;
}

/* facing_scene over the full-detail surface the CPU mirror computes (level
 * of detail would smooth the far ocean the march sees, by design), with a
 * budget of march steps; the march's own hits (the polish would move them
 * onto the normals' finer surface). */
static void facing_mirror_scene(tl_scene *s, int steps)
{
    facing_scene(s);
    s->quality.lod = false;
    s->quality.polish = false;
    s->quality.march_steps = steps;
}

/* fade 0 is the ocean without the wave, byte for byte: the same program
 * (no giant feature bit) and the same uniforms. */
static void test_fade_zero(tl_renderer *r)
{
    tl_scene on, off;
    facing_scene(&on);
    on.giant.fade = 0.0;
    off = on;
    off.giant.enabled = false;
    off.giant.fade = 1.0;
    tl_waves w;
    tl_waves_init(&w, &on.ocean);
    tl_frame_uniforms uon, uoff;
    tl_prepare_frame(&on, &w, &uon);
    tl_prepare_frame(&off, &w, &uoff);
    CHECK(!(uon.features & TL_FEATURE_GIANT_WAVE));
    CHECK(uon.features == uoff.features);
    tl_frame a, b;
    if (render(r, &on, &a))
        return;
    if (render(r, &off, &b)) {
        tl_frame_free(&a);
        return;
    }
    size_t n = (size_t)on.width * (size_t)on.height;
    CHECK(memcmp(a.color, b.color, n * 4 * sizeof(float)) == 0);
    CHECK(memcmp(a.depth, b.depth, n * sizeof(float)) == 0);
    CHECK(memcmp(a.display, b.display, n * 4 * sizeof(float)) == 0);
    tl_frame_free(&a);
    tl_frame_free(&b);
}

/* Image row (top first) where the world point p projects. */
static double project_row(const tl_scene *s, const double p[3])
{
    double right[3], up[3], fwd[3];
    tl_scene_camera_basis(&s->camera, right, up, fwd);
    double d[3] = {p[0] - s->camera.position[0], p[1] - s->camera.position[1],
                   p[2] - s->camera.position[2]};
    double y = d[0] * up[0] + d[1] * up[1] + d[2] * up[2];
    double z = d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2];
    double row_up = ((y / z) / tan(0.5 * s->camera.vfov) + 1.0) * 0.5 * s->height - 0.5;
    return (s->height - 1) - row_up;
}

static void test_wave_in_view(tl_renderer *r)
{
    tl_scene s, calm;
    facing_scene(&s);
    calm = s;
    calm.giant.enabled = false;
    tl_frame f, g;
    if (render(r, &s, &f))
        return;
    if (render(r, &calm, &g)) {
        tl_frame_free(&f);
        return;
    }
    const int w = s.width, h = s.height;
    size_t n = (size_t)w * (size_t)h;
    int finite = 1;
    for (size_t i = 0; i < n * 4; i++)
        finite &= isfinite(f.color[i]) && f.color[i] >= 0.0f;
    CHECK(finite);

    /* The crest's top, from the CPU model, and where it projects. */
    tl_giant giant;
    tl_giant_prepare(&giant, &s.giant, s.time);
    tl_waves waves;
    tl_waves_init(&waves, &s.ocean);
    double best = -1e9, top[3] = {0, 0, 0};
    for (int i = -400; i <= 400; i++) { /* along the centre line, every 0.1 m */
        double x = giant.origin[0] + giant.dir[0] * i * 0.1;
        double z = giant.origin[1] + giant.dir[1] * i * 0.1;
        double y = tl_waves_surface_height(&waves, &giant, x, z, s.time, 12, 6);
        if (y > best) {
            best = y;
            top[0] = x;
            top[1] = y;
            top[2] = z;
        }
    }
    double crest_row = project_row(&s, top);
    double horizon = 0.5 * (h - 1); /* pitch 0: the horizon crosses the middle */
    printf("crest top %.2f m at z = %.2f projects to row %.1f; horizon row %.1f\n", top[1], top[2],
           crest_row, horizon);
    CHECK(crest_row < horizon - 5.0);

    /* Centre column: sky well above the crest, the wave just below it and
     * nearer than whatever the calm frame had there. */
    int cx = w / 2, above = (int)floor(crest_row) - 3, below = (int)ceil(crest_row) + 3;
    CHECK(above >= 0);
    CHECK(f.depth[(size_t)above * w + cx] == TL_FRAME_SKY_DEPTH);
    int nearer = 1, rows = 0;
    for (int y = below; y < (int)horizon; y++) {
        float d = f.depth[(size_t)y * w + cx];
        nearer &= d < 200.0f && d < g.depth[(size_t)y * w + cx];
        rows++;
    }
    CHECK(rows > 5);
    CHECK(nearer);

    tl_frame_free(&f);
    tl_frame_free(&g);
}

/* Marching is exact: hits lie on the CPU surface. Rays that graze the crest
 * can run out of steps (quality.march_steps) and stop short, as grazing
 * rays at the ocean's horizon do; they are counted, not excused. */
static void test_hits_on_surface(tl_renderer *r)
{
    const int budgets[] = {96, 400};
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        facing_mirror_scene(&s, budgets[k]);
        tl_frame f;
        tl_giant giant;
        tl_waves waves;
        if (render_mirrored(r, &s, &f, &giant, &waves))
            return;
        int hits = 0, off = 0, below = 0, off_wave = 0;
        double worst = 0.0;
        for (int y = 0; y < s.height; y++)
            for (int x = 0; x < s.width; x++) {
                float d = f.depth[(size_t)y * s.width + x];
                if (d > 1000.0f)
                    continue; /* sky, or the far ocean's grazing rays */
                double ray[3], p[3];
                pixel_ray(&s, x, y, ray);
                for (int i = 0; i < 3; i++)
                    p[i] = s.camera.position[i] + ray[i] * d;
                double surf =
                    tl_waves_surface_height(&waves, &giant, p[0], p[2], s.time,
                                            s.quality.march_octaves, s.quality.giant_iterations);
                double e = fabs(p[1] - surf);
                /* Above the surface by at most the hit epsilon plus float
                 * rounding of the distance; never below it. */
                off += e > 0.02;
                below += p[1] < surf - 0.02;
                /* Stopped short within the wave's reach (not at the
                 * ocean's horizon beyond it). */
                double rx = p[0] - giant.origin[0], rz = p[2] - giant.origin[1];
                off_wave += e > 0.02 &&
                            fabs(giant.dir[0] * rx + giant.dir[1] * rz) < giant.reach_along &&
                            fabs(giant.across[0] * rx + giant.across[1] * rz) < giant.half_width;
                if (e <= 0.02)
                    worst = fmax(worst, e);
                hits++;
            }
        printf("%d steps: %d of %d water hits within 1 km lie on the surface to 0.02 m (worst "
               "of those %.3g m); %d stop short, %d of them on the wave's reach, %d below the "
               "surface\n",
               budgets[k], hits - off, hits, worst, off, off_wave, below);
        CHECK(hits > 8000);
        CHECK(below == 0);
        /* The wave's rays within the bound; grazing rays at the horizon
         * whose path crosses a corner of the wave's box, far from the
         * crest (w about 100 to 130 m, where the width mask has let it
         * down), spend their steps there: the slope bound is kept per bin
         * of s, over the whole width, and the bow widens each bin's reach
         * by its 10 m. With 400 steps 17 of 8746 such rays stop short,
         * 0.3 to 1.3 m above the ocean 650 to 880 m away, and 1 on the
         * wave's reach (2 in all with a level crest). */
        CHECK(off_wave <= hits / (k == 0 ? 100 : 1000));
        CHECK(off <= hits / (k == 0 ? 100 : 400));
        tl_frame_free(&f);
    }
}

/* Whether the ray (unit, from the camera) can show the wave, in double
 * from the same uniforms: it meets the wave's box (the shader's
 * giant_ray_interval) before the ocean's own water, which it has met
 * once it has crossed the trough plane outside the box from a camera
 * above the crest plane; or the water it meets may lie in the crest's
 * shadow (tl_giant_sunlit at the trough plane's depth, where a shadow
 * reaches furthest, between where the ray crosses the crest and trough
 * planes). */
typedef struct wave_view {
    const tl_scene *s;
    const tl_frame_uniforms *u;
    const tl_giant *g;
} wave_view;

static int ray_sees_wave(const void *ctx, const double ray[3])
{
    const wave_view *v = ctx;
    const tl_scene *s = v->s;
    const tl_frame_uniforms *u = v->u;
    const tl_giant *g = v->g;
    const double d[2] = {u->giant_frame[0], u->giant_frame[1]};
    const double o[3] = {u->giant_frame[2], u->cam_height, u->giant_frame[3]};
    const double r[3] = {d[0] * ray[0] + d[1] * ray[2], ray[1], d[1] * ray[0] - d[0] * ray[2]};
    const double top = (double)u->giant_bounds[3] * u->giant_shape[1];
    const double lo[3] = {-(double)u->giant_bounds[0], -(double)u->depth - top,
                          -(double)u->giant_mask[2]};
    const double hi[3] = {u->giant_bounds[0], top, u->giant_mask[2]};
    double t0 = 0.0, t1 = 1.0e7;
    int meets = 1;
    for (int i = 0; i < 3 && meets; i++) {
        if (fabs(r[i]) < 1e-12) {
            meets = o[i] >= lo[i] && o[i] <= hi[i];
            continue;
        }
        double a = (lo[i] - o[i]) / r[i], b = (hi[i] - o[i]) / r[i];
        t0 = fmax(t0, fmin(a, b));
        t1 = fmin(t1, fmax(a, b));
    }
    meets = meets && t0 <= t1;
    if (ray[1] >= 0.0 || u->cam_height <= 0.0)
        return meets;
    const double t_crest = u->cam_height / -ray[1];
    const double t_trough = (u->cam_height + u->depth) / -ray[1];
    if (meets && t0 < t_trough)
        return 1;
    double sun[3];
    tl_scene_sun_direction(&s->sun, sun);
    for (int k = 0; k <= 16; k++) {
        double t = t_crest + (t_trough - t_crest) * k / 16.0;
        double x = s->camera.position[0] + ray[0] * t, z = s->camera.position[2] + ray[2] * t;
        if (tl_giant_sunlit(g, x, z, -u->depth, sun) < 1.0)
            return 1;
    }
    return 0;
}

/* The pixels that can show the wave (u.plan.giant_rect), where the renderer
 * draws the giant wave's program: every ray through every pixel outside
 * it, at the pixel's centre, corners and edge midpoints, cannot show the
 * wave (ray_sees_wave); inside, some ray can. Cameras beside, above,
 * facing away from and inside the box, and low in front of it with the
 * crest's shadow reaching past the box toward the camera. */
static void test_screen_rect(void)
{
    struct {
        const char *what;
        double pos[3], yaw, pitch, roll, sun_azimuth;
        int expect;     /* 0: empty, 1: part of the frame, 2: all of it */
        int before_box; /* pos z is metres in front of the wave's box, not a position */
    } cases[] = {
        {"600 m away, the wave off to the left", {0.0, 4.0, -600.0}, 0.45, 0.0, 0.0, M_PI, 1, 0},
        {"600 m away, rolled, looking down", {0.0, 4.0, -600.0}, 0.2, -0.15, 0.3, M_PI, 1, 0},
        {"300 m above, looking down at it", {60.0, 300.0, -250.0}, 0.3, -0.9, 0.0, M_PI, 1, 0},
        {"2 m beside it, looking along it", {132.0, 4.0, -50.0}, 0.0, 0.0, 0.0, M_PI, 1, 0},
        {"facing away", {0.0, 4.0, -600.0}, M_PI, 0.0, 0.0, M_PI, 0, 0},
        {"inside the box", {5.0, 4.0, -10.0}, 0.0, 0.0, 0.0, M_PI, 2, 0},
        /* z: 30 m in front of the box, whose reach the loop takes from the
         * wave (it grows with the mask's falloff and the bow). */
        {"low, 30 m in front of the box", {0.0, 2.0, 30.0}, 0.6, 0.0, 0.0, M_PI, 1, 1},
        /* The crest's shadow reaches ~160 m toward the camera, past it. */
        {"the same, the sun behind the wave", {0.0, 2.0, -120.0}, 0.6, 0.0, 0.0, 0.0, 2, 0},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        tl_scene s;
        facing_scene(&s);
        memcpy(s.camera.position, cases[c].pos, sizeof s.camera.position);
        if (cases[c].before_box) {
            tl_giant box;
            tl_giant_prepare(&box, &s.giant, s.time);
            s.camera.position[2] = -(box.reach_along + cases[c].pos[2]);
        }
        s.camera.yaw = cases[c].yaw;
        s.camera.pitch = cases[c].pitch;
        s.camera.roll = cases[c].roll;
        s.sun.azimuth = cases[c].sun_azimuth;
        s.sun.elevation = 0.15;
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &w, &u);
        CHECK(u.features & TL_FEATURE_GIANT_WAVE);
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, s.time);
        const int *rect = u.plan.giant_rect;
        int missed, inside_hits, area;
        const wave_view view = {&s, &u, &g};
        rect_rays(&s, rect, ray_sees_wave, &view, &missed, &inside_hits, &area);
        int total = u.width * u.height;
        printf("wave's rectangle, %s: x %d-%d, y %d-%d (%.0f%% of the frame); rays outside it "
               "that can show the wave: %d\n",
               cases[c].what, rect[0], rect[2], rect[1], rect[3], 100.0 * area / total, missed);
        CHECK(missed == 0);
        if (cases[c].expect == 0)
            CHECK(area == 0);
        if (cases[c].expect == 1)
            CHECK(area > 0 && area < total * 3 / 4 && inside_hits > 0);
        if (cases[c].expect == 2)
            CHECK(area == total);
    }
}

/* split_matches_whole's scene `sp`, `what` for its line. */
static void split_matches_whole(tl_renderer *r, const tl_scene *sp, const char *what)
{
    tl_scene s = *sp;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    const int w = u.width, h = u.height;
    int area = (u.plan.giant_rect[2] - u.plan.giant_rect[0]) *
               (u.plan.giant_rect[3] - u.plan.giant_rect[1]);
    CHECK(area > 0 && area < w * h);
    int differ;
    double worst = split_against_whole(r, &u, u.plan.giant_rect, &differ, NULL);
    printf("split against whole, %s (rectangle %.0f%% of the frame): %d of %d display values "
           "differ, by at most %.3g\n",
           what, 100.0 * area / (w * h), differ, w * h * 4, worst);
    /* The two programs round differently (6e-8 here); a pixel drawn by
     * the lean one in the crest's shadow was 3e-3 too bright. */
    CHECK(worst < 1e-4);
}

/* The frame drawn in two programs (the lean ocean around the wave's
 * rectangle) matches the frame drawn all in the giant wave's program: far
 * off, and low in front of the wave with its crest's shadow on the water
 * (the rectangle leaves out the water below the box's top that a ray
 * meets before the box). 140 m from the centre: at 120 m the peaked
 * crest (up to lambda_max = 1.12 of its 20 m) casts its shadow past the
 * camera at this low sun, and the rectangle is the whole frame, which
 * would compare the frame with itself. */
static void test_split_matches_whole(tl_renderer *r)
{
    for (int view = 0; view < 2; view++) {
        tl_scene s;
        facing_scene(&s);
        s.camera.position[2] = view == 0 ? -600.0 : -140.0;
        s.camera.position[1] = view == 0 ? 4.0 : 2.0;
        s.camera.yaw = view == 0 ? 0.45 : 0.6;
        s.sun.azimuth = view == 0 ? M_PI : 0.5;
        s.sun.elevation = view == 0 ? 0.4 : 0.2;
        split_matches_whole(r, &s, view == 0 ? "far off" : "low in front, in its shadow");
    }
}

/* Every extreme the channels allow renders finite, non-negative pixels in
 * bounded time (the march's step budget holds whatever the slope). */
static void test_extremes(tl_renderer *r)
{
    const double cases[][6] = {
        /* height, wavelength, width, falloff, steepness, curl */
        {1000.0, 80.0, 120.0, 30.0, 1.0, 1.0}, {1000.0, 0.01, 0.01, 0.0, 1.0, 1.0},
        {0.001, 1e5, 1e5, 1e5, 1.0, 1.0},      {40.0, 10.0, 1e5, 0.0, 1.0, 1.0},
        {12.0, 1e5, 0.01, 1e5, 0.0, 0.0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tl_scene s;
        facing_scene(&s);
        s.width = 64;
        s.height = 40;
        s.giant.height = cases[i][0];
        s.giant.wavelength = cases[i][1];
        s.giant.width = cases[i][2];
        s.giant.falloff = cases[i][3];
        s.giant.steepness = cases[i][4];
        s.giant.curve_strength = cases[i][5];
        tl_frame f;
        if (render(r, &s, &f))
            return;
        int ok = 1;
        for (size_t k = 0; k < (size_t)s.width * s.height * 4; k++)
            ok &= isfinite(f.color[k]) && f.color[k] >= 0.0f;
        for (size_t k = 0; k < (size_t)s.width * s.height; k++)
            ok &= isfinite(f.depth[k]) && f.depth[k] >= 0.0f;
        if (!ok)
            printf("extreme case %zu: non-finite or negative pixels\n", i);
        CHECK(ok);
        tl_frame_free(&f);
    }
}

/* The march's over-relaxation outside the wave's box (quality.march_relax;
 * inside it the slope-bounded steps relax by their own 1.3) steps through
 * neither the ocean nor the wave: along each water ray the CPU mirror
 * finds the first point below the surface (10 cm apart) no nearer than
 * the GPU's hit, at the knob's largest factor. */
static void test_relaxed_march(tl_renderer *r)
{
    /* Budget 0: the march itself, exact; then the preset's budget, which
     * takes regula falsi where the wave is gentle (march.glsl) and may
     * clip an ocean crest there as on the open sea, never the wave. */
    for (int pass = 0; pass < 2; pass++) {
        tl_scene s;
        facing_mirror_scene(&s, 400);
        s.width = 64;
        s.height = 40;
        s.quality.march_relax = 2.0;
        if (pass == 0)
            s.quality.prepass_budget = 0;
        tl_frame f;
        tl_giant giant;
        tl_waves waves;
        if (render_mirrored(r, &s, &f, &giant, &waves))
            return;
        int checked = 0, through = 0, wave = 0, on_wave = 0;
        for (int y = 0; y < s.height; y++)
            for (int x = 0; x < s.width; x++) {
                double d = f.depth[(size_t)y * s.width + x];
                if (d > 160.0)
                    continue; /* sky, and the far ocean */
                double ray[3], p[3];
                pixel_ray(&s, x, y, ray);
                double t = 0.0;
                for (; t < d - 0.25; t += 0.1) {
                    for (int i = 0; i < 3; i++)
                        p[i] = s.camera.position[i] + ray[i] * t;
                    if (p[1] < tl_waves_surface_height(&waves, &giant, p[0], p[2], s.time,
                                                       s.quality.march_octaves,
                                                       s.quality.giant_iterations))
                        break;
                }
                through += t < d - 0.25;
                wave += t < d - 0.25 && fabs(tl_giant_height(&giant, p[0], p[2],
                                                             s.quality.giant_iterations)) > 1e-3;
                on_wave += d > 100.0;
                checked++;
            }
        printf("march_relax 2.0 before the wave, budget %d: %d of %d water rays (%d on the wave) "
               "cross the surface 0.25 m or more before their hit, %d of them the wave\n",
               s.quality.prepass_budget, through, checked, on_wave, wave);
        CHECK(on_wave > 300);
        CHECK(wave == 0);
        CHECK(pass == 0 ? through == 0 : through <= checked / 50);
        tl_frame_free(&f);
    }
}

/* A crossing this share of its distance short of the hit is a small wave's
 * crest the ray grazed. */
#define TL_TEST_GRAZED 0.03

/* Pixels whose ray crosses the surface 0.25 m or more before the distance
 * the frame reports (the sky: within 400 m), walked on the CPU 5 cm at a
 * time. Crossing is going under it by more than the march's hit epsilon
 * (quality.hit_epsilon): a ray that grazes a crest's top stays within it
 * for a metre or more, and the march may stop anywhere along that stretch
 * (the peaked crest's top at 140 m, 72 m across, met by a ray that dips
 * 0.4 mm under it at 139.6 m and stays within 9 mm above it to 140.6 m,
 * hit at 140.2 m). Only pixels next to a jump in distance (an edge of the wave) are
 * walked: that is where a march that starts from its neighbours'
 * distances could step over a crest. A crossing within TL_TEST_GRAZED of
 * the hit is a small wave's crest the ray grazed, on the wave too (they
 * ride it), not the wave stepped over. Returns those that crossed the wave
 * first; *ocean counts those that crossed an ocean crest where the wave
 * is not (past its box the prepass's budget may clip one, as on the open
 * sea: test_render bounds that). */
static int stepped_over(const tl_scene *s, const tl_frame *f, int *walked, int *ocean)
{
    tl_giant giant;
    tl_waves waves;
    cpu_mirror(s, &giant, &waves);
    int over = 0;
    *walked = 0;
    *ocean = 0;
    for (int y = 1; y + 1 < s->height; y++)
        for (int x = 1; x + 1 < s->width; x++) {
            double d = f->depth[(size_t)y * s->width + x], lo = d, hi = d;
            for (int j = -1; j <= 1; j++)
                for (int i = -1; i <= 1; i++) {
                    double n = f->depth[(size_t)(y + j) * s->width + x + i];
                    lo = fmin(lo, n);
                    hi = fmax(hi, n);
                }
            if (lo > 0.8 * hi || lo > 400.0)
                continue; /* no edge here, or only far water */
            double ray[3], until = fmin(d, 400.0) - 0.25;
            pixel_ray(s, x, y, ray);
            for (double t = 0.0; t < until; t += 0.05) {
                double p[3];
                for (int i = 0; i < 3; i++)
                    p[i] = s->camera.position[i] + ray[i] * t;
                if (p[1] > s->giant.height + 2.0)
                    continue; /* above everything */
                if (p[1] < tl_waves_surface_height(&waves, &giant, p[0], p[2], s->time,
                                                   s->quality.march_octaves,
                                                   s->quality.giant_iterations) -
                               s->quality.hit_epsilon) {
                    /* Over the wave: into its water far short of the hit,
                     * where the ray went on to another part of the surface
                     * (a crest's silhouette stepped over). Within
                     * TL_TEST_GRAZED of the hit it grazed the top of a
                     * small wave (on the wave, too: they ride it) and met
                     * that wave's back: an ocean crest. */
                    if (fabs(tl_giant_height(&giant, p[0], p[2], s->quality.giant_iterations)) >
                            1e-3 &&
                        t < (1.0 - TL_TEST_GRAZED) * d)
                        over++;
                    else
                        (*ocean)++;
                    break;
                }
            }
            (*walked)++;
        }
    return over;
}

/* The march prepass (quality.march_prepass) keeps the wave's silhouette:
 * the scene's rays start from the distances coarser rays found, and a
 * crest edge thinner than those rays' spacing must not be stepped over.
 * Facing the wave from near the water (its crest against the sky) and
 * from above it (against the sea beyond), no pixel along its edges
 * reports a surface behind one its ray crosses. */
/* Renders `s` and walks the pixels along the wave's edges: none may step
 * over the wave, at most `ocean_share` of them over an ocean crest. */
static void check_edges(tl_renderer *r, const tl_scene *s, const char *label, double ocean_share)
{
    tl_frame f;
    if (render(r, s, &f))
        return;
    int walked = 0, ocean = 0, over = stepped_over(s, &f, &walked, &ocean);
    printf("%s, camera %.0f m up: %d of %d pixels along the wave's edges cross the wave before "
           "their hit, %d an ocean crest\n",
           label, s->camera.position[1], over, walked, ocean);
    CHECK(walked > 100);
    CHECK(over == 0);
    CHECK(ocean <= ocean_share * walked);
    tl_frame_free(&f);
}

static void test_prepass_silhouette(tl_renderer *r)
{
    const double heights[2] = {4.0, 30.0}, pitches[2] = {0.0, -8.0};
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        facing_mirror_scene(&s, 400);
        s.camera.position[1] = heights[k];
        s.camera.pitch = pitches[k] * M_PI / 180.0;
        s.quality.march_prepass = true;
        /* 3%: with the default bow (10 m) 29 of 1122 edge pixels from 4 m
         * up cross an ocean crest 1 to 27 cm deep, 1 to 4 m before their
         * hit, all 77 to 86 m ahead of the crest inside the wave's box,
         * where the wave is under a millimetre; 5 with a level crest, 2
         * with the taper and variation but no bow. */
        check_edges(r, &s, "march prepass", 0.03);
    }
}

/* quality.giant_prepass (seed's): with march_prepass off the prepass runs
 * over the giant wave's rectangle alone. Outside it the frame is the one
 * without any prepass, value for value (seed's open water stays the
 * shader's own march); the prepass ran (its pass took time) so the pixels
 * inside start from it, and along the wave's edges none steps over the wave, as with final's
 * prepass over the whole frame (test_prepass_silhouette). */
static void test_giant_prepass(tl_renderer *r)
{
    tl_scene s;
    facing_mirror_scene(&s, 400);
    s.camera.position[2] = -600.0;
    s.camera.yaw = 0.45;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_quality_preset("seed", &s.quality, &err) == 0);
    s.quality.lod = false;
    s.quality.march_steps = 400;
    CHECK(!s.quality.march_prepass && s.quality.giant_prepass);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    const int w = u.width, h = u.height, *rect = u.plan.giant_rect;
    CHECK(rect[0] > 0 || rect[1] > 0 || rect[2] < w || rect[3] < h);
    tl_frame with, without;
    CHECK(tl_frame_alloc(&with, w, h, &err) == 0);
    CHECK(tl_frame_alloc(&without, w, h, &err) == 0);
    /* The prepass's own time says it ran. */
    double with_s[TL_TIMED_COUNT], without_s[TL_TIMED_COUNT];
    tl_renderer_time_passes(r, 1);
    CHECK(tl_renderer_render(r, &u, &with, &err) == 0);
    CHECK(tl_renderer_pass_seconds(r, with_s) == 1);
    u.plan.giant_prepass = 0;
    CHECK(tl_renderer_render(r, &u, &without, &err) == 0);
    CHECK(tl_renderer_pass_seconds(r, without_s) == 1);
    tl_renderer_time_passes(r, 0);
    CHECK(with_s[TL_TIMED_PREPASS] > 0.0 && without_s[TL_TIMED_PREPASS] == 0.0);
    int outside = 0, outside_differ = 0, inside_differ = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int in = x >= rect[0] && x < rect[2] && y >= rect[1] && y < rect[3];
            /* Frames are read back top row first; the rectangle is in GL's rows. */
            size_t i = ((size_t)(h - 1 - y) * w + x) * 4;
            int differ = memcmp(&with.color[i], &without.color[i], 4 * sizeof(float)) != 0;
            outside += !in;
            outside_differ += !in && differ;
            inside_differ += in && differ;
        }
    printf("giant_prepass: %d of %d pixels outside the wave's rectangle differ, %d inside\n",
           outside_differ, outside, inside_differ);
    CHECK(outside > w * h / 4);
    CHECK(outside_differ == 0);
    CHECK(inside_differ > 0);
    tl_frame_free(&with);
    tl_frame_free(&without);
    /* Facing the wave from near the water, its crest against the sky. */
    facing_mirror_scene(&s, 400);
    CHECK(tl_quality_preset("seed", &s.quality, &err) == 0);
    s.quality.lod = false;
    s.quality.march_steps = 400;
    check_edges(r, &s, "giant_prepass, seed", 0.0);
}

/* A rising ray stays at or above the camera, so its part of the wave's box
 * holds only the s where the wave reaches the camera's height
 * (tl_frame_uniforms.giant_rise). A camera below the crest, facing it and
 * looking a little up: the range is the crest's alone, and on the CPU
 * no rising ray the frame calls sky crosses the surface, and every rising
 * ray that goes a metre under it is a hit. A camera above the crest gets
 * no range, one under the still water the whole reach. */
static void test_rising_rays(tl_renderer *r)
{
    tl_scene s;
    facing_mirror_scene(&s, 400);
    s.camera.position[1] = 12.0; /* the crest is 20 m */
    s.camera.pitch = 0.05;
    s.width = 96;
    s.height = 60;
    tl_waves waves;
    tl_frame_uniforms u;
    tl_waves_init(&waves, &s.ocean);
    tl_prepare_frame(&s, &waves, &u);
    const double reach = u.giant_bounds[0];
    printf("rising rays, camera 12 m up: the box's s from %.1f to %.1f m (the reach: %.1f m)\n",
           u.giant_rise[0], u.giant_rise[1], reach);
    CHECK(u.giant_rise[0] < u.giant_rise[1]);
    CHECK(u.giant_rise[1] - u.giant_rise[0] < reach);
    tl_frame f;
    if (render(r, &s, &f))
        return;
    tl_giant giant;
    cpu_mirror(&s, &giant, &waves);
    int rising = 0, hits = 0, missed = 0, false_sky = 0, under = 0;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            double ray[3];
            pixel_ray(&s, x, y, ray);
            if (ray[1] < 0.0)
                continue;
            rising++;
            double deepest = 0.0; /* how far under the surface the ray goes */
            for (double t = 0.0; t < 400.0; t += 0.05) {
                double p[3];
                for (int i = 0; i < 3; i++)
                    p[i] = s.camera.position[i] + ray[i] * t;
                if (p[1] > s.giant.height + 2.0)
                    break;
                deepest = fmax(deepest, tl_waves_surface_height(&waves, &giant, p[0], p[2], s.time,
                                                                s.quality.march_octaves,
                                                                s.quality.giant_iterations) -
                                            p[1]);
            }
            int sky = f.depth[(size_t)y * s.width + x] >= TL_FRAME_SKY_DEPTH;
            hits += !sky;
            false_sky += sky && deepest > 0.0;
            missed += sky && deepest > 1.0;
            under += deepest > 1.0;
        }
    printf("rising rays: %d, %d of them on the wave, %d go a metre under it; %d the frame calls "
           "sky cross the surface, %d by a metre or more\n",
           rising, hits, under, false_sky, missed);
    /* Enough of them meet the crest to tell (the peaked crest tapers below
     * the camera toward its ends: fewer than a level one's 250). */
    CHECK(rising > 1000 && under > 100 && hits >= under);
    CHECK(missed == 0);
    CHECK(false_sky <= rising / 100);
    tl_frame_free(&f);

    s.camera.position[1] = 30.0;
    tl_prepare_frame(&s, &waves, &u);
    CHECK(u.giant_rise[0] >= u.giant_rise[1]);
    s.camera.position[1] = -3.0;
    tl_prepare_frame(&s, &waves, &u);
    CHECK(u.giant_rise[0] <= -reach + 1e-3 && u.giant_rise[1] >= reach - 1e-3);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_probe(r);
    test_probe_breaking_crest(r);
    test_fade_zero(r);
    test_wave_in_view(r);
    test_hits_on_surface(r);
    test_relaxed_march(r);
    test_prepass_silhouette(r);
    test_giant_prepass(r);
    test_rising_rays(r);
    test_extremes(r);
    test_screen_rect();
    test_split_matches_whole(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
