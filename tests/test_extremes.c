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
 *   1x4096, 4096x1 and 16384x1.
 * The parameters at their ends are in test_extremes_params.c. */
#include <stdlib.h>
#include <string.h>

#include "timeline/tl_channels.h"
#include "tl_extremes.h"

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
                       TL_DEG;
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
            s.camera.pitch = look_up ? 20.0 * TL_DEG : -20.0 * TL_DEG;
            snprintf(label, sizeof label, "camera %s (y = %.4f m), pitch %+.0f deg", spots[k].name,
                     spots[k].y, s.camera.pitch / TL_DEG);
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
    const double fovs[] = {fov->min, 60.0 * TL_DEG, fov->max};
    for (int i = 0; i < 3; i++) {
        tl_scene s;
        ray_scene(&s);
        s.camera.vfov = fovs[i];
        snprintf(label, sizeof label, "field of view %g deg", fovs[i] / TL_DEG);
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
    const double elevations[] = {90.0 * TL_DEG, 0.0, -0.5 * TL_DEG, -90.0 * TL_DEG};
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
    printf("%d frames; slowest %.2f s (%s); %.1f s in all\n", renders, slowest_render,
           slowest_label, now() - start);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
