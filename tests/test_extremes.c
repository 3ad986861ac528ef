/* Extremes (issue 15), as a table: every row renders or probes a scene at
 * an end of what tideline accepts and asserts finite pixels and depths, a
 * display image in [0, 1], no crash and no hang (ctest's timeout bounds the
 * whole), and where the row says so the same look as the scene near the
 * origin.
 *
 * - time and distance: the GPU's heights and slopes against the double CPU
 *   mirror at t in {0, 1e3, 1e5, 1e6, 1e7} s and camera offsets {0, 1e3,
 *   1e5, 1e6} m along x and along z, with and without the giant wave, and
 *   the rendered frame's look against the origin frame's; it prints the
 *   Markdown table of docs/precision.md;
 * - rays and lights: grazing rays, the camera on the water's planes, on a
 *   crest and in a trough, looking straight up and down, the sun from the
 *   zenith to far below the horizon, every field of view, images of 1x1,
 *   1x4096, 4096x1 and 16384x1;
 * - parameters at their ends: every channel of the registry at its minimum
 *   and maximum (enums and bools at each value), through a timeline; keys
 *   1e-6 s and 1e6 s apart; boat models of one and of 500k triangles. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "mesh/tl_mesh.h"
#include "timeline/tl_channels.h"
#include "timeline/tl_parse.h"
#include "timeline/tl_timeline.h"
#include "tl_gl_test.h"

#define DEG (M_PI / 180.0)

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---------------------------------------------------------------- frames */

/* Every plane finite; colour >= 0; display in [0, 1]; depth >= 0 (the
 * sky's is TL_FRAME_SKY_DEPTH; 0 where underwater.mode on puts a camera
 * that is above the water at the surface). Prints what is wrong, once. */
static int frame_ok(const tl_frame *f, int width, int height, const char *label)
{
    size_t n = (size_t)width * (size_t)height;
    size_t bad_color = 0, bad_display = 0, bad_depth = 0;
    for (size_t i = 0; i < n * 4; i++) {
        bad_color += !(isfinite(f->color[i]) && f->color[i] >= 0.0f);
        bad_display += !(f->display[i] >= 0.0f && f->display[i] <= 1.0f);
    }
    for (size_t i = 0; i < n; i++)
        bad_depth += !(isfinite(f->depth[i]) && f->depth[i] >= 0.0f);
    if (bad_color || bad_display || bad_depth)
        printf("  %s: %zu bad colour values, %zu bad display values, %zu bad depths\n", label,
               bad_color, bad_display, bad_depth);
    return !bad_color && !bad_display && !bad_depth;
}

static double slowest_render = 0.0;
static char slowest_label[160];
static int renders = 0;

/* Validates and renders `s` (one pass, as tl_render does) and checks the
 * frame; keeps the frame in *f when `keep`. Returns 1 when all is well. */
static int render_checked(tl_renderer *r, const tl_scene *s, const char *label, tl_frame *keep)
{
    tl_error err;
    tl_error_clear(&err);
    if (tl_scene_validate(s, &err)) {
        printf("  %s: scene refused: %s\n", label, err.message);
        CHECK(0);
        return 0;
    }
    tl_frame f;
    double t0 = now();
    if (render(r, s, &f)) {
        printf("  %s: render failed\n", label);
        return 0;
    }
    double dt = now() - t0;
    renders++;
    if (dt > slowest_render) {
        slowest_render = dt;
        snprintf(slowest_label, sizeof slowest_label, "%s", label);
    }
    int ok = frame_ok(&f, s->width, s->height, label);
    CHECK(ok);
    if (keep)
        *keep = f;
    else
        tl_frame_free(&f);
    return ok;
}

/* ------------------------------------------------- the look of a frame */

typedef struct look {
    double sky_mean, sky_spread;     /* display luma of sky pixels */
    double water_mean, water_spread; /* display luma of water pixels */
    double water_rgb[3];             /* mean display colour of the water */
    double detail;                   /* mean |Laplacian| of luma inside the water */
    int sky, water;                  /* pixel counts */
} look;

static double luma_at(const tl_frame *f, int w, int x, int y)
{
    const float *p = f->display + ((size_t)y * w + x) * 4;
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

static void look_of(const tl_frame *f, int w, int h, look *out)
{
    memset(out, 0, sizeof *out);
    double s2 = 0.0, w2 = 0.0, lap = 0.0;
    int lap_n = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double l = luma_at(f, w, x, y);
            if (f->depth[(size_t)y * w + x] == TL_FRAME_SKY_DEPTH) {
                out->sky_mean += l;
                s2 += l * l;
                out->sky++;
                continue;
            }
            out->water_mean += l;
            w2 += l * l;
            out->water++;
            for (int c = 0; c < 3; c++)
                out->water_rgb[c] += f->display[((size_t)y * w + x) * 4 + c];
            if (x == 0 || y == 0 || x == w - 1 || y == h - 1)
                continue;
            int all_water = 1;
            for (int k = 0; k < 4; k++) {
                int xx = x + (k == 0) - (k == 1), yy = y + (k == 2) - (k == 3);
                all_water &= f->depth[(size_t)yy * w + xx] != TL_FRAME_SKY_DEPTH;
            }
            if (!all_water)
                continue;
            lap += fabs(4.0 * l - luma_at(f, w, x - 1, y) - luma_at(f, w, x + 1, y) -
                        luma_at(f, w, x, y - 1) - luma_at(f, w, x, y + 1));
            lap_n++;
        }
    if (out->sky) {
        out->sky_mean /= out->sky;
        out->sky_spread = sqrt(fmax(s2 / out->sky - out->sky_mean * out->sky_mean, 0.0));
    }
    if (out->water) {
        out->water_mean /= out->water;
        out->water_spread = sqrt(fmax(w2 / out->water - out->water_mean * out->water_mean, 0.0));
        for (int c = 0; c < 3; c++)
            out->water_rgb[c] /= out->water;
    }
    out->detail = lap_n ? lap / lap_n : 0.0;
}

/* The tolerances of "the same look" (display values in [0, 1]). Frames of
 * the same sea at another time or place differ as much as two moments of
 * one shot do; these bounds hold for ordinary moments near the origin
 * with a margin and fail for a sea without its fine waves (the control in
 * test_time_and_distance). */
#define LOOK_SKY_MEAN     0.01 /* absolute */
#define LOOK_SKY_SPREAD   0.01 /* absolute */
#define LOOK_WATER_MEAN   0.25 /* relative */
#define LOOK_WATER_SPREAD 0.5  /* relative */
#define LOOK_WATER_RGB    0.25 /* relative, per channel */
#define LOOK_DETAIL       0.35 /* relative */
#define LOOK_PIXELS       0.05 /* relative change of the sky/water split */

static double rel(double a, double b)
{
    return fabs(a - b) / fmax(fabs(b), 1e-6);
}

static double worst_look = 0.0; /* the largest share of a tolerance any frame used */

/* 1 when `a` has the look of `ref`; prints the worst measure. */
static int same_look(const look *a, const look *ref, const char *label, int quiet)
{
    double e[7] = {
        fabs(a->sky_mean - ref->sky_mean) / LOOK_SKY_MEAN,
        fabs(a->sky_spread - ref->sky_spread) / LOOK_SKY_SPREAD,
        rel(a->water_mean, ref->water_mean) / LOOK_WATER_MEAN,
        rel(a->water_spread, ref->water_spread) / LOOK_WATER_SPREAD,
        fmax(fmax(rel(a->water_rgb[0], ref->water_rgb[0]), rel(a->water_rgb[1], ref->water_rgb[1])),
             rel(a->water_rgb[2], ref->water_rgb[2])) /
            LOOK_WATER_RGB,
        rel(a->detail, ref->detail) / LOOK_DETAIL,
        rel(a->water, ref->water) / LOOK_PIXELS,
    };
    static const char *const names[7] = {"sky mean",  "sky spread", "water mean",  "water spread",
                                         "water rgb", "detail",     "water pixels"};
    int worst = 0;
    for (int i = 1; i < 7; i++)
        if (e[i] > e[worst])
            worst = i;
    if (quiet)
        worst_look = fmax(worst_look, e[worst]);
    if (!quiet || e[worst] > 1.0)
        printf("  %s: look: sky %.4f±%.4f water %.4f±%.4f detail %.4f; worst %s at %.2f of its "
               "tolerance\n",
               label, a->sky_mean, a->sky_spread, a->water_mean, a->water_spread, a->detail,
               names[worst], e[worst]);
    return e[worst] <= 1.0;
}

/* ------------------------------------------------- time and distance */

static void table_scene(tl_scene *s, double t, const double offset[2], int giant)
{
    tl_scene_defaults(s);
    s->width = 64;
    s->height = 36;
    s->time = t;
    s->camera.position[0] = offset[0];
    s->camera.position[2] = offset[1];
    s->sun.azimuth = M_PI; /* behind the camera: no glitter path to dominate */
    s->sun.elevation = 0.5;
    if (giant) { /* 12 m, 49 m ahead and coming: the same view wherever */
        s->giant.enabled = true;
        s->giant.center[0] = offset[0];
        s->giant.center[1] = offset[1] + 60.0;
        s->giant.angle = M_PI;
        s->giant.arrival = t - 1.0;
    }
}

typedef struct probe_result {
    double height; /* max |GPU - CPU| of the surface height, metres */
    double normal; /* max angle between the GPU's and the CPU's normals, degrees */
} probe_result;

/* Heights (the march's path, mode 0, march octaves) and slopes (the
 * normal's path, mode 6, normal octaves) on a grid of camera-relative
 * points 80 m wide and 80 m ahead, against the CPU mirror in double: its
 * normal from central differences of tl_waves_surface_height. */
static probe_result probe_scene(tl_renderer *r, const tl_scene *s)
{
    enum { N = 24 };
    probe_result res = {INFINITY, INFINITY};
    tl_waves w;
    tl_waves_init(&w, &s->ocean);
    tl_giant g;
    tl_giant_prepare(&g, &s->giant, s->time);
    tl_frame_uniforms u;
    tl_prepare_frame(s, &w, &u);
    float xz[N * N * 2], out[N * N * 4], slope[N * N * 4];
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            xz[(j * N + i) * 2 + 0] = (float)(-40.0 + 80.0 * i / (N - 1));
            xz[(j * N + i) * 2 + 1] = (float)(-5.0 + 85.0 * j / (N - 1));
        }
    const int mo = s->quality.march_octaves, no = s->quality.normal_octaves;
    const int it = s->quality.giant_iterations;
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe(r, &u, 0, xz, N * N, mo, out, &err) ||
        tl_renderer_probe(r, &u, 6, xz, N * N, no, slope, &err)) {
        printf("  probe failed: %s\n", err.message);
        return res;
    }
    res.height = res.normal = 0.0;
    const double e = 1e-4; /* the CPU's difference step, metres */
    for (int k = 0; k < N * N; k++) {
        double x = s->camera.position[0] + (double)xz[k * 2];
        double z = s->camera.position[2] + (double)xz[k * 2 + 1];
        double h = tl_waves_surface_height(&w, &g, x, z, s->time, mo, it);
        double d = fabs(h - (double)out[k * 4]);
        if (!(d <= res.height))
            res.height = d; /* NaN stays */
        double gx = (tl_waves_surface_height(&w, &g, x + e, z, s->time, no, it) -
                     tl_waves_surface_height(&w, &g, x - e, z, s->time, no, it)) /
                    (2.0 * e);
        double gz = (tl_waves_surface_height(&w, &g, x, z + e, s->time, no, it) -
                     tl_waves_surface_height(&w, &g, x, z - e, s->time, no, it)) /
                    (2.0 * e);
        double a[3] = {-gx, 1.0, -gz}, b[3] = {-slope[k * 4], 1.0, -slope[k * 4 + 1]};
        double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                       a[0] * b[1] - a[1] * b[0]};
        double angle = atan2(sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                             a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) /
                       DEG;
        if (!(angle <= res.normal))
            res.normal = angle;
    }
    return res;
}

static void test_time_and_distance(tl_renderer *r)
{
    static const double times[] = {0.0, 1e3, 1e5, 1e6, 1e7};
    static const double offsets[] = {0.0, 1e3, 1e5, 1e6};
    enum { NT = 5, NO = 4 };
    probe_result table[NT][NO][2]; /* the worse of the x and z offsets */
    look ref[2];
    int looks_ok = 1, looks = 0;
    for (int giant = 0; giant < 2; giant++) {
        tl_scene s;
        tl_frame f;
        table_scene(&s, 0.0, (double[]){0.0, 0.0}, giant);
        if (!render_checked(r, &s, "origin", &f))
            return;
        look_of(&f, s.width, s.height, &ref[giant]);
        tl_frame_free(&f);
        printf("origin frame, giant wave %s: sky %.4f±%.4f water %.4f±%.4f detail %.4f\n",
               giant ? "on" : "off", ref[giant].sky_mean, ref[giant].sky_spread,
               ref[giant].water_mean, ref[giant].water_spread, ref[giant].detail);
        /* The control: the look test fails for a sea without its fine
         * waves (one octave), as it would for waves whose phases lost their
         * precision far out (blurred or blocky detail). */
        tl_scene flat = s;
        flat.quality.march_octaves = flat.quality.normal_octaves = 1;
        if (render_checked(r, &flat, "control: one octave", &f)) {
            look l;
            look_of(&f, s.width, s.height, &l);
            CHECK(!same_look(&l, &ref[giant], "control: one octave", 0));
            tl_frame_free(&f);
        }
    }
    for (int ti = 0; ti < NT; ti++)
        for (int oi = 0; oi < NO; oi++)
            for (int giant = 0; giant < 2; giant++) {
                probe_result worst = {0.0, 0.0};
                for (int axis = 0; axis < (oi ? 2 : 1); axis++) {
                    double off[2] = {axis ? 0.0 : offsets[oi], axis ? offsets[oi] : 0.0};
                    tl_scene s;
                    table_scene(&s, times[ti], off, giant);
                    probe_result p = probe_scene(r, &s);
                    worst.height = !(p.height <= worst.height) ? p.height : worst.height;
                    worst.normal = !(p.normal <= worst.normal) ? p.normal : worst.normal;
                    char label[160];
                    snprintf(label, sizeof label, "t = %g s, camera at (%g, %g), giant %s",
                             times[ti], off[0], off[1], giant ? "on" : "off");
                    tl_frame f;
                    if (!render_checked(r, &s, label, &f))
                        continue;
                    look l;
                    look_of(&f, s.width, s.height, &l);
                    tl_frame_free(&f);
                    looks++;
                    looks_ok &= same_look(&l, &ref[giant], label, 1);
                }
                table[ti][oi][giant] = worst;
                /* 1e-3 of the wave depth (ocean.depth, 1 m); 0.5 degrees. */
                CHECK(worst.height <= 1e-3 * 1.0);
                CHECK(worst.normal <= 0.5);
            }
    printf("%d frames at every time and distance keep the origin frame's look: %s (the worst "
           "measure at %.2f of its tolerance)\n",
           looks, looks_ok ? "yes" : "NO", worst_look);
    CHECK(looks_ok);

    printf("\n| t (s) | offset (m) | height error (m) | normal error (deg) | height error, giant "
           "wave (m) | normal error, giant wave (deg) |\n|---:|---:|---:|---:|---:|---:|\n");
    for (int ti = 0; ti < NT; ti++)
        for (int oi = 0; oi < NO; oi++)
            printf("| %g | %g | %.2e | %.3f | %.2e | %.3f |\n", times[ti], offsets[oi],
                   table[ti][oi][0].height, table[ti][oi][0].normal, table[ti][oi][1].height,
                   table[ti][oi][1].normal);
    printf("\n");
}

/* ------------------------------------------------- rays and lights */

static void ray_scene(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 64;
    s->height = 36;
    s->time = 3.0;
}

/* Share of the frame's pixels that see the sky. */
static double sky_share(const tl_frame *f, int w, int h)
{
    size_t n = (size_t)w * (size_t)h, sky = 0;
    for (size_t i = 0; i < n; i++)
        sky += f->depth[i] == TL_FRAME_SKY_DEPTH;
    return (double)sky / (double)n;
}

static double mean_luma(const tl_frame *f, int w, int h)
{
    double sum = 0.0;
    for (int i = 0; i < w * h; i++)
        sum += luminance(f->color + (size_t)i * 4);
    return sum / (w * h);
}

static void test_rays(tl_renderer *r)
{
    const tl_channel *fov = tl_channel_find("camera.fov");
    char label[160];
    tl_frame f;
    /* Rays grazing the horizon from above and from below it, through the
     * narrowest lens; from above the water and from under it. */
    const double pitches[] = {1e-6, -1e-6, 1e-3, -1e-3};
    for (int under = 0; under < 2; under++)
        for (int i = 0; i < 4; i++) {
            tl_scene s;
            ray_scene(&s);
            s.camera.vfov = fov->min;
            s.camera.pitch = pitches[i];
            s.camera.position[1] = under ? -3.0 : 1.5;
            snprintf(label, sizeof label, "grazing, pitch %g rad, camera %s the water", pitches[i],
                     under ? "under" : "above");
            render_checked(r, &s, label, NULL);
        }

    /* The camera on the water: the crest plane (y = 0), the trough plane
     * (y = -depth), the mean level, exactly on the surface, on a crest and
     * in a trough (found with the CPU mirror near the origin). */
    tl_scene base;
    ray_scene(&base);
    tl_waves w;
    tl_waves_init(&w, &base.ocean);
    const int oct = base.quality.march_octaves;
    double mean = 0.0, hi = -1e9, lo = 1e9, hi_xz[2] = {0, 0}, lo_xz[2] = {0, 0};
    int count = 0;
    for (int j = 0; j <= 200; j++)
        for (int i = 0; i <= 200; i++) {
            double x = -2.0 + 0.02 * i, z = -2.0 + 0.02 * j;
            double h = tl_waves_height(&w, x, z, base.time, oct);
            mean += h;
            count++;
            if (h > hi) {
                hi = h;
                hi_xz[0] = x;
                hi_xz[1] = z;
            }
            if (h < lo) {
                lo = h;
                lo_xz[0] = x;
                lo_xz[1] = z;
            }
        }
    mean /= count;
    double on = tl_waves_height(&w, 0.0, 0.0, base.time, oct);
    const struct {
        const char *name;
        double x, y, z;
    } spots[] = {
        {"crest plane", 0.0, 0.0, 0.0},         {"trough plane", 0.0, -base.ocean.depth, 0.0},
        {"mean level", 0.0, mean, 0.0},         {"on the surface", 0.0, on, 0.0},
        {"on a crest", hi_xz[0], hi, hi_xz[1]}, {"in a trough", lo_xz[0], lo, lo_xz[1]},
    };
    printf("the water near the origin at t = %g s: mean %.4f m, crest %.4f m, trough %.4f m\n",
           base.time, mean, hi, lo);
    for (size_t k = 0; k < sizeof spots / sizeof spots[0]; k++)
        for (int look_up = 0; look_up < 2; look_up++) {
            tl_scene s = base;
            s.camera.position[0] = spots[k].x;
            s.camera.position[1] = spots[k].y;
            s.camera.position[2] = spots[k].z;
            s.camera.pitch = look_up ? 20.0 * DEG : -20.0 * DEG;
            snprintf(label, sizeof label, "camera %s (y = %.4f m), pitch %+.0f deg", spots[k].name,
                     spots[k].y, s.camera.pitch / DEG);
            render_checked(r, &s, label, NULL);
        }

    /* Straight up and straight down, above and under the water: above it
     * the view up is all sky and the view down all water within a few
     * metres; under it the view up meets the surface within a few metres
     * (the view down meets nothing: its depth is the sky's, by design). */
    for (int under = 0; under < 2; under++)
        for (int up = 0; up < 2; up++) {
            tl_scene s;
            ray_scene(&s);
            const tl_channel *pitch = tl_channel_find("camera.pitch");
            s.camera.pitch = up ? pitch->max : pitch->min;
            s.camera.position[1] = under ? -3.0 : 1.5;
            snprintf(label, sizeof label, "looking straight %s, camera %s the water",
                     up ? "up" : "down", under ? "under" : "above");
            if (!render_checked(r, &s, label, &f))
                continue;
            double share = sky_share(&f, s.width, s.height);
            float far = 0.0f;
            for (int i = 0; i < s.width * s.height; i++)
                far = fmaxf(far, f.depth[i]);
            printf("  %s: sky share %.2f, farthest depth %g\n", label, share, far);
            if (!under && up)
                CHECK(share == 1.0);
            if (!under && !up)
                CHECK(far < 10.0f);
            if (under && up)
                CHECK(share == 0.0 && far < 10.0f);
            tl_frame_free(&f);
        }

    /* Fields of view from the channel's minimum to its maximum. */
    const double fovs[] = {fov->min, 60.0 * DEG, fov->max};
    for (int i = 0; i < 3; i++) {
        tl_scene s;
        ray_scene(&s);
        s.camera.vfov = fovs[i];
        snprintf(label, sizeof label, "field of view %g deg", fovs[i] / DEG);
        render_checked(r, &s, label, NULL);
    }

    /* Image sizes down to one pixel and up to the longest row the limits
     * allow; one more pixel is refused. */
    const int sizes[][2] = {{1, 1}, {1, 4096}, {4096, 1}, {16384, 1}, {1, 16384}};
    for (int i = 0; i < 5; i++) {
        tl_scene s;
        ray_scene(&s);
        s.width = sizes[i][0];
        s.height = sizes[i][1];
        snprintf(label, sizeof label, "%dx%d image", s.width, s.height);
        render_checked(r, &s, label, NULL);
    }
    tl_scene big;
    ray_scene(&big);
    big.width = 16385;
    big.height = 1;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_scene_validate(&big, &err) == TL_ERR_USAGE);
}

static void test_sun(tl_renderer *r)
{
    const double elevations[] = {90.0 * DEG, 0.0, -0.5 * DEG, -90.0 * DEG};
    const char *const names[] = {"at the zenith", "on the horizon", "just below the horizon",
                                 "far below the horizon"};
    for (int model = 0; model < 2; model++) {
        double light[4];
        for (int i = 0; i < 4; i++) {
            tl_scene s;
            ray_scene(&s);
            s.camera.pitch = 0.0;
            s.sky.model = model ? TL_SKY_SEED : TL_SKY_PHYSICAL;
            s.sun.elevation = elevations[i];
            char label[160];
            snprintf(label, sizeof label, "%s sky, sun %s", model ? "seed" : "physical", names[i]);
            tl_frame f;
            light[i] = NAN;
            if (!render_checked(r, &s, label, &f))
                continue;
            light[i] = mean_luma(&f, s.width, s.height);
            tl_frame_free(&f);
        }
        printf("  %s sky: mean radiance with the sun at 90, 0, -0.5, -90 deg: %.4g %.4g %.4g "
               "%.4g\n",
               model ? "seed" : "physical", light[0], light[1], light[2], light[3]);
        /* The physical sky darkens as the sun sets (the seed's sky does not
         * follow the sun below the horizon: only its lobe does). */
        if (!model) {
            CHECK(light[0] > light[1]);
            CHECK(light[1] > light[2]);
            CHECK(light[2] > light[3]);
        }
    }
}

/* ------------------------------------------------- parameters at their ends */

typedef struct setting {
    const char *name, *value;
} setting;

/* Two scenes where every channel matters: the giant wave 49 m ahead and
 * coming, the boat 25 m ahead on its path, a light fog, the sun ahead;
 * once from 3 m above the water, once from 4 m under it looking up. */
static const setting above[] = {
    {"giant.enabled", "on"},   {"giant.center", "0 60"}, {"giant.angle", "180deg"},
    {"giant.arrival", "4s"},   {"fog.density", "0.002"}, {"camera.position", "0 3 0"},
    {"camera.pitch", "-6deg"},
};
static const setting under[] = {
    {"giant.enabled", "on"},   {"giant.center", "0 60"}, {"giant.angle", "180deg"},
    {"giant.arrival", "4s"},   {"fog.density", "0.002"}, {"camera.position", "0 -4 0"},
    {"camera.pitch", "20deg"},
};
#define BASE_COUNT ((int)(sizeof above / sizeof above[0]))

static char boat_dir[] = "/tmp/tideline-extremes-XXXXXX";
static tl_mesh builtin_boat;

/* Parses `text` as a timeline in boat_dir, loads its boat (the built-in
 * one unless it names a model) onto the renderer, evaluates it at t. */
static int eval_text(tl_renderer *r, const char *text, double t, tl_scene *s, tl_timeline *keep)
{
    char name[256];
    snprintf(name, sizeof name, "%s/extreme.tl", boat_dir);
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    if (tl_timeline_parse_text(name, text, strlen(text), &tl, &diags, &err)) {
        tl_diags_write(&diags, stdout);
        return -1;
    }
    tl_mesh mesh, *m = &builtin_boat;
    if (tl.boat_model[0]) {
        if (tl_mesh_load(tl.boat_model, &mesh, &err)) {
            printf("  %s\n", err.message);
            tl_timeline_free(&tl);
            return -1;
        }
        m = &mesh;
    }
    tl_timeline_set_boat_bounds(&tl, m->bounds_min, m->bounds_max);
    int rc = tl_renderer_set_mesh(r, m, &err);
    if (rc)
        printf("  mesh: %s\n", err.message);
    if (m != &builtin_boat)
        tl_mesh_free(&mesh);
    tl_timeline_eval(&tl, t, s);
    if (keep)
        *keep = tl;
    else
        tl_timeline_free(&tl);
    return rc;
}

/* The value `v` (stored units) as the language writes it. */
static void format_value(const tl_channel *ch, double v, char *out, size_t size)
{
    const char *unit = ch->unit == TL_UNIT_ANGLE ? "rad" : ch->unit == TL_UNIT_TIME ? "s" : "";
    if (ch->kind == TL_CH_INT)
        snprintf(out, size, "%d", (int)v);
    else
        snprintf(out, size, "%.17g%s", v, unit);
}

/* One timeline per channel end: the base scene with `name` set to
 * `value` (its base setting, if any, left out). */
static void channel_end(tl_renderer *r, const setting *base, const char *where,
                        const tl_channel *ch, const char *value, const double expect[3])
{
    char text[4096];
    int n = snprintf(text, sizeof text,
                     "tideline 1\nduration 10s\nsize 16x9\npath boat\n  0s 0 20\n  10s 0 30\n");
    for (int i = 0; i < BASE_COUNT; i++)
        if (strcmp(base[i].name, ch->name) != 0)
            n += snprintf(text + n, sizeof text - (size_t)n, "set %s %s\n", base[i].name,
                          base[i].value);
    snprintf(text + n, sizeof text - (size_t)n, "set %s %s\n", ch->name, value);
    char label[200];
    snprintf(label, sizeof label, "%s %s (%s)", ch->name, value, where);
    tl_scene s;
    if (eval_text(r, text, 5.0, &s, NULL)) {
        printf("  %s: the timeline is refused\n", label);
        CHECK(0);
        return;
    }
    /* The scene holds the value as written: nothing clamps a channel's
     * value inside its documented range. */
    double got[3];
    tl_channel_get(ch, &s, got);
    int same = 1;
    for (int c = 0; c < ch->components; c++)
        same &= fabs(got[c] - expect[c]) <= 1e-12 * fmax(1.0, fabs(expect[c]));
    if (!same)
        printf("  %s: the scene holds %.17g\n", label, got[0]);
    CHECK(same);
    render_checked(r, &s, label, NULL);
}

static void test_channel_ends(tl_renderer *r)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_mesh_default_boat(&builtin_boat, &err) == 0);
    int ends = 0, channels = 0;
    for (int b = 0; b < 2; b++) {
        const setting *base = b ? under : above;
        const char *where = b ? "under water" : "above water";
        for (int i = 0; tl_channel_at(i); i++) {
            const tl_channel *ch = tl_channel_at(i);
            char value[160];
            double v[3];
            channels += b == 0;
            switch (ch->kind) {
            case TL_CH_BOOL:
                for (int k = 0; k < 2; k++) {
                    v[0] = k;
                    channel_end(r, base, where, ch, k ? "on" : "off", v);
                    ends++;
                }
                break;
            case TL_CH_ENUM:
                for (int k = 0; ch->names[k]; k++) {
                    v[0] = k;
                    channel_end(r, base, where, ch, ch->names[k], v);
                    ends++;
                }
                break;
            case TL_CH_INT:
            case TL_CH_REAL:
                for (int end = 0; end < 2; end++) {
                    double x = end ? ch->max : ch->min;
                    char one[64];
                    format_value(ch, x, one, sizeof one);
                    value[0] = '\0';
                    for (int c = 0; c < ch->components; c++) {
                        v[c] = ch->kind == TL_CH_INT ? (double)(int)x : x;
                        strcat(value, c ? " " : "");
                        strcat(value, one);
                    }
                    channel_end(r, base, where, ch, value, v);
                    ends++;
                }
                break;
            }
        }
    }
    printf("%d channels: %d ends and values rendered above and under the water\n", channels, ends);
    tl_mesh_free(&builtin_boat);
}

/* Keys a microsecond apart and a million seconds apart, with every kind of
 * segment: the curves stay finite and inside their channel's range, the
 * ones that do not overshoot by design stay between their keys (elastic
 * eases swing even a component whose keys are equal, as Blender's do; a
 * spline's Bessel tangent at a key between a 1e-6 s and a 5 s segment is
 * the short one's slope, and the long segment bulges by about that slope
 * times its length: documented in docs/precision.md), and the frames
 * between them render. */
static void test_keys(tl_renderer *r)
{
    const char *const interps[] = {
        "bezier", "linear", "spline", "ease-out-back", "ease-in-out-elastic", "ease-in-out-expo"};
    const struct {
        const char *name, *k1, *k2, *duration;
        double t[5];
    } spans[] = {
        {"1e-6 s", "0.000001s", "5s", "10s", {0.0, 2.5e-7, 5e-7, 1e-6, 3.0}},
        {"1e6 s", "1000000s", "10000000s", "10000000s", {0.0, 5e5, 1e6, 5e6, 1e7}},
    };
    const tl_channel *pos = tl_channel_find("camera.position");
    const tl_channel *sun = tl_channel_find("sun.elevation");
    for (int k = 0; k < 2; k++)
        for (size_t i = 0; i < sizeof interps / sizeof interps[0]; i++) {
            char text[1024];
            snprintf(text, sizeof text,
                     "tideline 1\nduration %s\nsize 32x18\n"
                     "key camera.position %s\n  0s 0 2 0\n  %s 0 2 1\n  %s 0 3 2\n"
                     "key sun.elevation %s\n  0s 10deg\n  %s 40deg\n  %s -10deg\n",
                     spans[k].duration, interps[i], spans[k].k1, spans[k].k2, interps[i],
                     spans[k].k1, spans[k].k2);
            int spline = strcmp(interps[i], "spline") == 0;
            int overshoots = spline || strstr(interps[i], "elastic") || strstr(interps[i], "back");
            double reach = 0.0;
            for (int j = 0; j < 5; j++) {
                tl_scene s;
                if (eval_text(r, text, spans[k].t[j], &s, NULL)) {
                    CHECK(0);
                    break;
                }
                const double *p = s.camera.position;
                int ok = isfinite(s.sun.elevation) && s.sun.elevation >= sun->min &&
                         s.sun.elevation <= sun->max;
                for (int c = 0; c < 3; c++)
                    ok &= isfinite(p[c]) && p[c] >= pos->min && p[c] <= pos->max;
                if (!overshoots)
                    ok &= p[0] == 0.0 && p[1] >= 2.0 && p[1] <= 3.0 && p[2] >= 0.0 && p[2] <= 2.0;
                else if (!spline) /* the eases swing by less than their keys' span */
                    ok &= fabs(p[0]) < 1.0 && fabs(p[1] - 2.5) < 1.5 && fabs(p[2] - 1.0) < 2.0;
                reach = fmax(reach, fabs(p[2] - 1.0));
                char label[160];
                snprintf(label, sizeof label, "keys %s apart, %s, t = %g s", spans[k].name,
                         interps[i], spans[k].t[j]);
                if (!ok)
                    printf("  %s: camera at %g %g %g, sun at %g\n", label, p[0], p[1], p[2],
                           s.sun.elevation);
                CHECK(ok);
                if (j == 1 || j == 4)
                    render_checked(r, &s, label, NULL);
            }
            if (spline)
                printf("  keys %s apart, spline: the camera's z strays up to %.3g m from the "
                       "keys' middle\n",
                       spans[k].name, reach);
        }
}

/* Writes an OBJ of `rings` x `segments` quads (two triangles each) on an
 * ellipsoid 8 m long, 3 m wide and 2 m high, its middle on the
 * waterline; rings = 0 writes one triangle. */
static int write_obj(const char *path, int rings, int segments)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    if (rings == 0) {
        fprintf(f, "v -1 0 -2\nv 1 0 -2\nv 0 1 2\nf 1 2 3\n");
    } else {
        for (int i = 0; i <= rings; i++) {
            double th = M_PI * i / rings;
            for (int j = 0; j < segments; j++) {
                double ph = 2.0 * M_PI * j / segments;
                fprintf(f, "v %.6f %.6f %.6f\n", 1.5 * sin(th) * cos(ph), 1.0 * sin(th) * sin(ph),
                        4.0 * cos(th));
            }
        }
        for (int i = 0; i < rings; i++)
            for (int j = 0; j < segments; j++) {
                int a = i * segments + j + 1, b = i * segments + (j + 1) % segments + 1;
                int c = a + segments, d = b + segments;
                fprintf(f, "f %d %d %d\nf %d %d %d\n", a, c, b, b, c, d);
            }
    }
    return fclose(f);
}

static void test_boats(tl_renderer *r)
{
    const struct {
        const char *file;
        int rings, segments;
        long triangles;
    } boats[] = {{"one.obj", 0, 0, 1}, {"many.obj", 500, 500, 500000}};
    for (int b = 0; b < 2; b++) {
        char path[256];
        snprintf(path, sizeof path, "%s/%s", boat_dir, boats[b].file);
        double t0 = now();
        CHECK(write_obj(path, boats[b].rings, boats[b].segments) == 0);
        char text[1024];
        snprintf(text, sizeof text,
                 "tideline 1\nduration 10s\nsize 64x36\npath boat\n  0s 0 20\n  10s 0 30\n"
                 "set boat.model %s\nset camera.position 0 3 0\nset camera.pitch -6deg\n",
                 boats[b].file);
        tl_scene s;
        tl_timeline tl;
        if (eval_text(r, text, 5.0, &s, &tl)) {
            CHECK(0);
            continue;
        }
        tl_timeline_free(&tl);
        tl_mesh mesh;
        tl_error err;
        tl_error_clear(&err);
        if (tl_mesh_load(path, &mesh, &err) == 0) {
            CHECK((long)mesh.index_count == 3 * boats[b].triangles);
            int finite = 1;
            for (size_t i = 0; i < mesh.vertex_count * 3; i++)
                finite &= isfinite(mesh.positions[i]) && isfinite(mesh.normals[i]);
            CHECK(finite);
            tl_mesh_free(&mesh);
        } else {
            CHECK(0);
        }
        /* The boat is in view: the frame draws it. */
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &w, &u);
        CHECK(u.features & TL_FEATURE_BOAT);
        char label[160];
        snprintf(label, sizeof label, "a boat of %ld triangles", boats[b].triangles);
        render_checked(r, &s, label, NULL);
        printf("  %s: written, loaded, floated and rendered in %.1f s\n", label, now() - t0);
        CHECK(isfinite(s.boat.position[1]) && isfinite(s.boat.pitch) && isfinite(s.boat.roll));
        remove(path);
    }
    tl_renderer_set_mesh(r, NULL, NULL);
}

int main(void)
{
    double start = now();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    double t0 = now();
    test_time_and_distance(r);
    printf("[time and distance: %.1f s]\n", now() - t0);
    t0 = now();
    test_rays(r);
    test_sun(r);
    printf("[rays and lights: %.1f s]\n", now() - t0);
    if (mkdtemp(boat_dir)) {
        t0 = now();
        test_channel_ends(r);
        printf("[channel ends: %.1f s]\n", now() - t0);
        t0 = now();
        test_keys(r);
        test_boats(r);
        printf("[keys and boats: %.1f s]\n", now() - t0);
        rmdir(boat_dir);
    } else {
        CHECK(0);
    }
    printf("%d frames; slowest %.2f s (%s); %.1f s in all\n", renders, slowest_render,
           slowest_label, now() - start);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
