/* Caustics (shaders/caustics.glsl, src/waves/tl_caustics.c): the GPU's
 * focus estimate against the CPU's in double, near the origin and far out
 * at a late time; and the estimate's physics: a flat sea and a set sun
 * focus nothing, the light is conserved on average, the pattern has
 * contrast that softens with depth, and it moves with the waves; its lines
 * differ in brightness; on the
 * sea floor in a frame, where the CPU says; and on the boat's hull. */
#include <string.h>

#include "core/tl_math.h"
#include "mesh/tl_mesh.h"
#include "optics/tl_optics.h"
#include "tl_gl_test.h"
#include "waves/tl_caustics.h"

enum { N = 1024 };

/* The least spatial contrast (std / mean of luminance) caustics give the
 * sand 5 m down under the default sea; the sand's own mottle has under
 * half of it. */
#define TL_TEST_FLOOR_CONTRAST 0.6

static void underwater_scene(tl_scene *s, double x, double z, double t)
{
    tl_scene_defaults(s);
    s->width = 64;
    s->height = 36;
    s->camera.position[0] = x;
    s->camera.position[1] = -4.0;
    s->camera.position[2] = z;
    s->camera.pitch = 0.5;
    s->time = t;
    s->sun.elevation = 50.0 * TL_DEG;
    s->sun.azimuth = 30.0 * TL_DEG;
}

static void light_of(const tl_scene *s, tl_caustic_light *l)
{
    tl_scene_sun_direction(&s->sun, l->sun_dir);
    l->ior = s->water.ior;
    l->scattering = s->water.scattering;
    tl_optics_sun_in_water(l->sun_dir, l->ior, l->sun_water);
}

/* The default sea at t = 10 s under the test's sun, and its light. */
static void sunny_sea(tl_waves *w, tl_caustic_light *l)
{
    tl_scene s;
    underwater_scene(&s, 0.0, 0.0, 10.0);
    tl_waves_init(w, &s.ocean);
    light_of(&s, l);
}

/* The focus at the N points of `in` (x, z camera-relative, depth,
 * footprint), on the CPU. */
static void cpu_focus(const tl_scene *s, const float *in, double *out)
{
    tl_waves w;
    tl_waves_init(&w, &s->ocean);
    tl_caustic_light l;
    light_of(s, &l);
    for (int i = 0; i < N; i++)
        out[i] = tl_caustic_focus(&w, &l, s->camera.position[0] + (double)in[4 * i],
                                  s->camera.position[2] + (double)in[4 * i + 1], in[4 * i + 2],
                                  s->time, s->quality.normal_octaves, in[4 * i + 3]);
}

static void points(float *in)
{
    srand(7);
    const float depths[] = {0.3f, 1.0f, 2.5f, 5.0f, 12.0f, 30.0f};
    for (int i = 0; i < N; i++) {
        in[4 * i] = (float)(-10.0 + 20.0 * rand() / RAND_MAX);
        in[4 * i + 1] = (float)(-10.0 + 20.0 * rand() / RAND_MAX);
        in[4 * i + 2] = depths[i % 6];
        in[4 * i + 3] = i % 12 < 6 ? 0.0f : 0.08f;
    }
}

/* The finer waves' web (TL_CAUSTIC_FINE_*): 9 m down, along a line of
 * points 2 cm apart, the focus changes from point to point more with it
 * than with the coarse web alone (water that scatters so much that none
 * of the beam is left unscattered turns it off), and about the same
 * light falls there. */
static void test_fine_web(void)
{
    enum { M = 1024 };
    tl_waves w;
    tl_caustic_light fine, coarse;
    sunny_sea(&w, &fine);
    coarse = fine;
    coarse.scattering = 1e3;
    double step[2] = {0.0, 0.0}, mean[2] = {0.0, 0.0};
    for (int k = 0; k < 2; k++) {
        const tl_caustic_light *l = k ? &coarse : &fine;
        double last = 0.0;
        for (int i = 0; i < M; i++) {
            double f = tl_caustic_focus(&w, l, 0.02 * i, 0.37 * 0.02 * i, 9.0, 10.0, 36, 0.0);
            mean[k] += f / M;
            if (i > 0)
                step[k] += fabs(f - last) / (M - 1);
            last = f;
        }
    }
    printf("caustics 9 m down, 2 cm apart: mean step %.4f with the finer web, %.4f without; "
           "mean %.3f against %.3f\n",
           step[0], step[1], mean[0], mean[1]);
    CHECK(step[0] > 1.2 * step[1]);
    CHECK(fabs(mean[0] / mean[1] - 1.0) < 0.15);
}

/* The web's lines differ in brightness (TL_CAUSTIC_BAND): 9 m down, over a
 * 6.4 m square at 4 cm, the focus's local peaks above 1.5 spread by more
 * than this share of their mean. With every line rounded off by det
 * changing 1 across the step (the crest's glow and the shafts still do
 * so) they spread by half as much: each line reached one peak, and the
 * sea floor read as a pool's. */
#define TL_TEST_LINE_SPREAD 0.3

static void test_lines_differ(void)
{
    enum { G = 160 };
    static double v[G * G];
    tl_waves w;
    tl_caustic_light l;
    sunny_sea(&w, &l);
    for (int j = 0; j < G; j++)
        for (int i = 0; i < G; i++)
            v[j * G + i] = tl_caustic_focus(&w, &l, 0.04 * i, 0.04 * j, 9.0, 10.0, 36, 0.0);
    double sum = 0.0, sq = 0.0;
    int peaks = 0;
    for (int j = 1; j < G - 1; j++)
        for (int i = 1; i < G - 1; i++) {
            double c = v[j * G + i];
            int peak = c > 1.5;
            for (int k = 0; k < 9; k++)
                if (k != 4 && v[(j + k / 3 - 1) * G + i + k % 3 - 1] >= c)
                    peak = 0;
            if (peak) {
                sum += c;
                sq += c * c;
                peaks++;
            }
        }
    double mean = peaks ? sum / peaks : 0.0;
    double spread = peaks ? sqrt(fmax(sq / peaks - mean * mean, 0.0)) / mean : 0.0;
    printf("caustics 9 m down: %d peaks, mean %.3f, sd/mean %.3f\n", peaks, mean, spread);
    CHECK(peaks > 50);
    CHECK(spread > TL_TEST_LINE_SPREAD);
}

/* GPU (float, analytic gradients) against CPU (double, differences). */
static void test_gpu_matches_cpu(tl_renderer *r, double x, double z, double t)
{
    tl_scene s;
    underwater_scene(&s, x, z, t);
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_frame_uniforms u;
    tl_prepare_frame(&s, &w, &u);
    CHECK(u.features & TL_FEATURE_CAUSTICS);
    static float in[4 * N], out[4 * N];
    static double want[N];
    points(in);
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe4(r, &u, 19, in, N, s.quality.normal_octaves, out, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    cpu_focus(&s, in, want);
    int close = 0;
    double worst = 0.0, brightest = 0.0;
    for (int i = 0; i < N; i++) {
        double d = fabs(out[4 * i] - want[i]) / fmax(want[i], 1.0);
        worst = fmax(worst, d);
        close += d <= 0.01;
        brightest = fmax(brightest, want[i]);
    }
    printf("caustics at (%g, %g) t = %g s: GPU within 1%% of CPU at %d of %d points, worst %.3g "
           "(relative); brightest %.2f\n",
           x, z, t, close, N, worst, brightest);
    CHECK(close >= N * 98 / 100);
    CHECK(worst <= 0.25);
    CHECK(brightest > 2.0);
}

static double mean_std(const double *v, int n, double *std)
{
    double sum = 0.0, sq = 0.0;
    for (int i = 0; i < n; i++) {
        sum += v[i];
        sq += v[i] * v[i];
    }
    double mean = sum / n;
    *std = sqrt(fmax(sq / n - mean * mean, 0.0));
    return mean;
}

/* Over a 6 m square at several depths: the mean stays near a flat sea's
 * (light is moved, not made), the pattern has contrast near the surface
 * and softens deep down, and half a second later it is another. */
static void test_physics(void)
{
    enum { G = 96 };
    static double a[G * G], b[G * G];
    tl_waves w;
    tl_caustic_light l;
    sunny_sea(&w, &l);
    const double depths[] = {1.0, 5.0, 40.0};
    double contrast[3];
    for (int d = 0; d < 3; d++) {
        for (int j = 0; j < G; j++)
            for (int i = 0; i < G; i++) {
                double x = 6.0 * i / G, z = 6.0 * j / G;
                a[j * G + i] = tl_caustic_focus(&w, &l, x, z, depths[d], 10.0, 36, 0.0);
                b[j * G + i] = tl_caustic_focus(&w, &l, x, z, depths[d], 10.5, 36, 0.0);
            }
        double std, mean = mean_std(a, G * G, &std);
        double cov = 0.0, std_b, mean_b = mean_std(b, G * G, &std_b);
        for (int k = 0; k < G * G; k++)
            cov += (a[k] - mean) * (b[k] - mean_b);
        double corr = cov / (G * G) / (std * std_b);
        printf("caustics %g m down: mean %.3f, std/mean %.3f, correlation with 0.5 s later %.3f\n",
               depths[d], mean, std / mean, corr);
        CHECK(mean > 0.85 && mean < 1.15);
        CHECK(fabs(corr) < 0.5 || d == 2);
        contrast[d] = std / mean;
    }
    CHECK(contrast[0] > 0.3 && contrast[1] > 0.3);
    CHECK(contrast[2] < 0.5 * contrast[1]);
    /* Nothing to focus: a flat sea, a sun below the horizon, the surface. */
    tl_scene flat;
    underwater_scene(&flat, 0.0, 0.0, 10.0);
    flat.ocean.depth = 1e-6;
    tl_waves wf;
    tl_waves_init(&wf, &flat.ocean);
    CHECK_NEAR(tl_caustic_focus(&wf, &l, 1.0, 2.0, 5.0, 10.0, 36, 0.0), 1.0, 1e-4);
    CHECK(tl_caustic_focus(&w, &l, 1.0, 2.0, 0.0, 10.0, 36, 0.0) == 1.0);
    tl_caustic_light night = l;
    night.sun_dir[1] = -0.1;
    CHECK(tl_caustic_focus(&w, &night, 1.0, 2.0, 5.0, 10.0, 36, 0.0) == 1.0);
}

/* The sand 5 m down under a sunny sea, seen from 1.5 m under the surface
 * looking straight down (80 x 80 px, 60 deg). */
static void floor_scene(tl_scene *s, double t, double caustics)
{
    tl_scene_defaults(s);
    s->width = s->height = 80;
    s->time = t;
    s->camera.position[1] = -1.5;
    s->camera.pitch = -90.0 * TL_DEG;
    s->camera.vfov = 60.0 * TL_DEG;
    s->sun.elevation = 60.0 * TL_DEG;
    s->sun.azimuth = 30.0 * TL_DEG;
    s->ocean.floor_depth = 5.0;
    s->underwater.caustics = caustics;
}

static int floor_luminance(tl_renderer *r, double t, double caustics, double *lum)
{
    tl_scene s;
    floor_scene(&s, t, caustics);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_SEA_FLOOR);
    CHECK(!(u.features & TL_FEATURE_CAUSTICS) == !(caustics > 0.0));
    tl_frame f;
    if (render_prepared(r, &u, s.width, s.height, &f))
        return -1;
    for (int i = 0; i < s.width * s.height; i++)
        lum[i] = luminance(f.color + 4 * (size_t)i);
    tl_frame_free(&f);
    return 0;
}

static double correlation(const double *a, const double *b, int n)
{
    double sa, sb, ma = mean_std(a, n, &sa), mb = mean_std(b, n, &sb), cov = 0.0;
    for (int i = 0; i < n; i++)
        cov += (a[i] - ma) * (b[i] - mb);
    return cov / n / (sa * sb);
}

/* On the sea floor: with caustics the sand's light has a pattern, which
 * moves with the waves and lies where the CPU's estimate says the light
 * is focused; without them the sand is near even (its own mottle); a
 * strength of nearly 0 is the frame without them. */
static void test_floor(tl_renderer *r)
{
    enum { P = 80 * 80 };
    static double on[P], later[P], off[P], faint[P], focus[P], ratio[P];
    if (floor_luminance(r, 10.0, 1.0, on) || floor_luminance(r, 10.5, 1.0, later) ||
        floor_luminance(r, 10.0, 0.0, off) || floor_luminance(r, 10.0, 1e-6, faint))
        return;
    tl_scene s;
    floor_scene(&s, 10.0, 1.0);
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_caustic_light l;
    light_of(&s, &l);
    double worst_faint = 0.0;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            int i = y * s.width + x;
            double ray[3];
            pixel_ray(&s, x, y, ray);
            double t = (s.camera.position[1] + s.ocean.floor_depth) / -ray[1];
            double footprint = t * 2.0 * tan(0.5 * s.camera.vfov) / s.height;
            focus[i] = tl_caustic_focus(&w, &l, t * ray[0], t * ray[2], s.ocean.floor_depth, s.time,
                                        s.quality.normal_octaves, footprint);
            ratio[i] = on[i] / off[i];
            worst_faint = fmax(worst_faint, fabs(faint[i] - off[i]) / off[i]);
        }
    double std_on, std_off, mean_on = mean_std(on, P, &std_on),
                            mean_off = mean_std(off, P, &std_off);
    double moved = correlation(on, later, P), placed = correlation(ratio, focus, P);
    printf("sea floor 5 m down: std/mean %.3f with caustics, %.3f without; mean %.4f against "
           "%.4f; correlation with 0.5 s later %.3f, of on/off with the CPU's focus %.3f; "
           "strength 1e-6 against off: %.2g\n",
           std_on / mean_on, std_off / mean_off, mean_on, mean_off, moved, placed, worst_faint);
    CHECK(std_on / mean_on > TL_TEST_FLOOR_CONTRAST);
    CHECK(std_off / mean_off < 0.5 * TL_TEST_FLOOR_CONTRAST);
    CHECK(moved < 0.5);
    CHECK(placed > 0.9);
    CHECK(worst_faint < 1e-4);
}

/* The boat's starboard side in the sun from the east, seen from 2.5 m
 * under water 6 m off it: its hull pixels (nearer than the frame without
 * the boat), their luminance with the caustics at `caustics`. */
static int hull_luminance(tl_renderer *r, double caustics, double t, double *lum, int *mask)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 160;
    s.height = 90;
    s.time = t;
    s.boat.enabled = true;
    s.boat.size = s.boat.scale = s.boat.length = 9.0;
    s.boat.beam = 9.0 * TL_BOAT_BEAM_RATIO;
    s.boat.wake = 0.0;
    s.boat.heading = 0.0;
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    s.boat.position[1] = tl_waves_height(&w, 0.0, 0.0, s.time, TL_MAX_OCTAVES);
    s.sun.elevation = 45.0 * TL_DEG;
    s.sun.azimuth = 90.0 * TL_DEG;
    s.camera.position[0] = 6.0;
    s.camera.position[1] = -2.5;
    s.camera.yaw = -90.0 * TL_DEG;
    s.camera.pitch = 12.0 * TL_DEG;
    s.camera.vfov = 60.0 * TL_DEG;
    s.underwater.caustics = caustics;
    s.underwater.shafts = 0.0;
    tl_frame with, without;
    if (render_boat_pair(r, &s, &with, &without))
        return -1;
    int count = 0;
    for (int i = 0; i < s.width * s.height; i++) {
        mask[i] = with.depth[i] < 0.99f * without.depth[i];
        lum[i] = luminance(with.color + 4 * (size_t)i);
        count += mask[i];
    }
    tl_frame_free(&with);
    tl_frame_free(&without);
    return count;
}

/* Caustics on the hull: where the sun reaches it under water its light
 * has the waves' pattern (the ratio with caustics to without spreads),
 * about the same on average; a strength of nearly 0 is the frame without. */
static void test_hull(tl_renderer *r, const tl_mesh *boat)
{
    enum { P = 160 * 90 };
    static double on[P], off[P], faint[P], ratio[P];
    static int mask[P], mask_off[P], mask_faint[P];
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_set_mesh(r, boat, &err) == 0);
    int count = hull_luminance(r, 1.0, 10.0, on, mask);
    if (count < 0 || hull_luminance(r, 0.0, 10.0, off, mask_off) < 0 ||
        hull_luminance(r, 1e-6, 10.0, faint, mask_faint) < 0)
        return;
    /* The sunlit part: the hull pixels the caustics change at all (they
     * scale the sun's beam alone; the bottom's flat and the shadowed side
     * are lit by the water, and the beam does not reach them). */
    int n = 0, shaded = 0;
    double worst_faint = 0.0;
    for (int i = 0; i < P; i++) {
        if (!mask[i] || !mask_off[i])
            continue;
        if (fabs(on[i] - off[i]) <= 1e-4 * off[i]) {
            shaded++;
            continue;
        }
        ratio[n++] = on[i] / off[i];
        worst_faint = fmax(worst_faint, fabs(faint[i] - off[i]) / off[i]);
    }
    double std, mean = mean_std(ratio, n, &std);
    printf("caustics on the hull: %d sunlit of %d hull pixels (%d in shade); with against without "
           "mean %.3f, "
           "std %.3f; "
           "strength 1e-6 against off %.2g\n",
           n, count, shaded, mean, std, worst_faint);
    CHECK(n > 300);
    CHECK(shaded > 100);
    CHECK(std > 0.08);
    CHECK(mean > 0.8 && mean < 1.3);
    CHECK(worst_faint < 1e-4);
}

int main(void)
{
    test_physics();
    test_fine_web();
    test_lines_differ();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_gpu_matches_cpu(r, 0.0, 0.0, 10.0);
    test_gpu_matches_cpu(r, 1e4, -7e3, 1e5);
    test_floor(r);
    tl_error err;
    tl_error_clear(&err);
    tl_mesh boat;
    CHECK(tl_mesh_default_boat(&boat, &err) == 0);
    test_hull(r, &boat);
    tl_mesh_free(&boat);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
