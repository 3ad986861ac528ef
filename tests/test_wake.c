/* The boat's wake's foam (shaders/wake.glsl), probed on the GPU (probe mode
 * 9) behind boats that ran straight: fresh foam behind the stern is mostly
 * white but open in places, and thicker inside its patches than at their
 * edges; old foam lies in streaks drawn out along the path; bubbles lie
 * under all of it; outside the wedge, and behind a drifting boat, there is
 * nothing; and seen from under the water the foam is there too. Each figure sums LANES boats in
 * different places (the foam's textures are fixed to the world and the path, and one wake's few
 * metres hold only a few of their cells). */
#include <string.h>

#include "tl_gl_test.h"
#include "waves/tl_kelvin.h"

enum { NX = 48, NB = 120, LANES = 8 };

/* Boat `lane` has run straight along +z at `speed` m/s to (97 lane, 0), its
 * path's distances starting 131 lane m apart; the camera 25 m above looks
 * down the wake. */
static void straight_wake(tl_scene *s, double speed, int lane)
{
    tl_scene_defaults(s);
    s->width = 160;
    s->height = 90;
    s->boat.enabled = true;
    s->boat.heading = 0.0;
    s->boat.position[0] = 97.0 * lane;
    s->boat.wake_step = 2.0 * s->boat.wake_time / (TL_WAKE_POINTS - 1);
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        s->boat.wake_path[k][0] = 97.0 * lane;
        s->boat.wake_path[k][1] = -speed * s->boat.wake_step * k;
        s->boat.wake_along[k] = 500.0 + 131.0 * lane - speed * s->boat.wake_step * k;
    }
    s->camera.position[0] = 97.0 * lane + 5.0;
    s->camera.position[1] = 25.0;
    s->camera.position[2] = 10.0;
    const double target[3] = {97.0 * lane, 0.0, -20.0};
    tl_scene_camera_look_at(&s->camera, target, NULL);
}

static float grid[NB][NX][4];
static double half_beam; /* of the last boat probed, metres */

/* Foam, thickness and bubbles behind boat `lane` into `grid`, on an NX x NB
 * grid: x across the path from x0 by dx (in half beams), metres behind the
 * boat from b0 by db. 0 when probed. */
static int probe_lane(tl_renderer *r, double speed, int lane, double x0, double dx, double b0,
                      double db)
{
    tl_scene s;
    straight_wake(&s, speed, lane);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_WAKE); /* else the probe has no wake to return */
    half_beam = u.objects[0].wake_params[0];
    static float xz[NB * NX * 2];
    for (int j = 0; j < NB; j++)
        for (int i = 0; i < NX; i++) {
            double x = 97.0 * lane + (x0 + dx * i) * half_beam;
            xz[(j * NX + i) * 2 + 0] = (float)(x - s.camera.position[0]);
            xz[(j * NX + i) * 2 + 1] = (float)(-(b0 + db * j) - s.camera.position[2]);
        }
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_renderer_probe(r, &u, 9, xz, NB * NX, 1, &grid[0][0][0], &err);
    if (rc) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
    }
    return rc;
}

/* Right behind the stern (3 to 9 m, the middle half of the band): white
 * over half the water or more, never a solid sheet, and the foam thicker
 * inside its patches than at their edges (a threshold that saturated drew
 * flat sheets with hard outlines there: 0.41 thick at their edges, 0.44
 * inside). */
static void test_fresh(tl_renderer *r)
{
    long n = 0, foam = 0, edge = 0, inner = 0;
    double aerated = 0.0, thick_edge = 0.0, thick_inner = 0.0;
    for (int lane = 0; lane < LANES; lane++) {
        if (probe_lane(r, 6.0, lane, -0.5, 1.0 / NX, 3.0, 6.0 / NB))
            return;
        for (int j = 1; j + 1 < NB; j++)
            for (int i = 1; i + 1 < NX; i++) {
                const float *c = grid[j][i];
                n++;
                aerated += c[2];
                if (c[0] <= 0.5f)
                    continue;
                foam++;
                /* Next to open water (within one cell), or inside a patch. */
                bool open = grid[j - 1][i][0] <= 0.5f || grid[j + 1][i][0] <= 0.5f ||
                            grid[j][i - 1][0] <= 0.5f || grid[j][i + 1][0] <= 0.5f;
                if (open) {
                    edge++;
                    thick_edge += c[1];
                } else {
                    inner++;
                    thick_inner += c[1];
                }
            }
    }
    double share = (double)foam / (double)n;
    printf("fresh wake: %.3f of the water foam, thickness %.3f at patches' edges, %.3f inside; "
           "bubbles %.3f\n",
           share, edge ? thick_edge / edge : 0.0, inner ? thick_inner / inner : 0.0, aerated / n);
    CHECK(share > 0.45);
    CHECK(share < 0.95);
    CHECK(edge > 0 && inner > 0);
    if (edge > 0 && inner > 0)
        CHECK(thick_inner / inner > thick_edge / edge + 0.15);
    CHECK(aerated / n > 0.3);
}

/* 20 to 44 m behind (3 to 7 s old, the foam's e-fold 6 s): thinner, in
 * streaks drawn out along the path: foam a metre further along is foam
 * more often than foam a metre across. */
static void test_old(tl_renderer *r)
{
    long n = 0, foam = 0, along = 0, across = 0;
    for (int lane = 0; lane < LANES; lane++) {
        if (probe_lane(r, 6.0, lane, -1.0, 2.0 / NX, 20.0, 24.0 / NB))
            return;
        int a = 5, c = (int)lround(NX / (2.0 * half_beam)); /* cells in a metre */
        for (int j = 0; j < NB; j++)
            for (int i = 0; i < NX; i++) {
                n++;
                if (grid[j][i][0] <= 0.5f)
                    continue;
                foam++;
                along += j + a < NB && grid[j + a][i][0] > 0.5f;
                across += i + c < NX && grid[j][i + c][0] > 0.5f;
            }
    }
    double share = (double)foam / (double)n;
    double kept_along = foam ? (double)along / foam : 0.0;
    double kept_across = foam ? (double)across / foam : 0.0;
    printf("old wake: %.3f of the water foam; foam 1 m on is foam %.2f along, %.2f across\n", share,
           kept_along, kept_across);
    CHECK(share > 0.01 && share < 0.4);
    CHECK(kept_along > kept_across + 0.1);
}

/* Beside the wedge (its arm about 0.35 of the distance behind, out from
 * the half beam) the function returns zeros without computing the foam. */
static void test_outside(tl_renderer *r)
{
    if (probe_lane(r, 6.0, 0, 15.0, 0.25, 3.0, 0.1))
        return;
    long lit = 0;
    for (int j = 0; j < NB; j++)
        for (int i = 0; i < NX; i++)
            lit += grid[j][i][0] != 0.0f || grid[j][i][1] != 0.0f || grid[j][i][2] != 0.0f;
    printf("beside the wake: %ld of %d points with foam, thickness or bubbles\n", lit, NB * NX);
    CHECK(lit == 0);
}

/* A boat drifting at 0.25 m/s churns nothing white: its wake's feature is
 * off (the foam and bubbles came at any speed, and a drifting boat
 * trailed white blobs); at 1.5 m/s there is foam, less than at 6. */
static void test_slow(tl_renderer *r)
{
    tl_scene s;
    straight_wake(&s, 0.25, 0);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(!(u.features & TL_FEATURE_WAKE));
    const double speeds[2] = {1.5, 6.0};
    long foam[2] = {0, 0}, bubbles[2] = {0, 0};
    for (int v = 0; v < 2; v++)
        for (int lane = 0; lane < LANES; lane++) {
            if (probe_lane(r, speeds[v], lane, -1.0, 2.0 / NX, 0.5, 6.0 / NB))
                return;
            for (int j = 0; j < NB; j++)
                for (int i = 0; i < NX; i++) {
                    foam[v] += grid[j][i][0] > 0.5f;
                    bubbles[v] += grid[j][i][2] > 0.0f;
                }
        }
    for (int v = 0; v < 2; v++)
        printf("0.5 to 6.5 m behind boats at %.2f m/s: %ld of %d points foam, %ld bubbles\n",
               speeds[v], foam[v], LANES * NB * NX, bubbles[v]);
    CHECK(bubbles[0] > LANES * NB * NX / 4);
    CHECK(foam[0] > 0 && foam[0] < foam[1]);
}

/* From 3 m under the water, looking up the wake behind a boat at 6 m/s:
 * the foam shows (it hid from below, the window's sky or the surface's
 * reflection of the depths in its place), lighter than the surface around
 * it where that reflects the depths, and every pixel stays finite. */
static void test_from_below(tl_renderer *r)
{
    tl_scene s;
    straight_wake(&s, 6.0, 0);
    s.camera.position[0] = 3.0;
    s.camera.position[1] = -3.0;
    s.camera.position[2] = -6.0;
    s.camera.yaw = M_PI;
    s.camera.pitch = 35.0 * M_PI / 180.0;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_UNDERWATER);
    CHECK(u.features & TL_FEATURE_WAKE);
    tl_frame with, without;
    if (render_wake_pair(r, &s, &with, &without))
        return;
    long lighter = lighter_pixels(&with, &without), bad = 0;
    size_t n = (size_t)s.width * s.height;
    for (size_t i = 0; i < n * 4; i++)
        bad += !isfinite(with.color[i]);
    printf("from below: %ld of %zu pixels lighter with the wake, %ld values not finite\n", lighter,
           n, bad);
    CHECK(lighter > (long)n / 50);
    CHECK(bad == 0);
    tl_frame_free(&without);
    tl_frame_free(&with);
}

typedef struct wake_view {
    const tl_scene *s;
    const tl_frame_uniforms *u;
} wake_view;

/* Whether a ray from the camera (camera-relative, unit `ray`) meets the
 * ocean's band (between the crest plane and the trough plane) over water
 * some wake group's circle holds: its stretch through the band, in x z,
 * comes within a circle. */
static int ray_reaches_wake(const void *ctx, const double ray[3])
{
    const tl_scene *s = ((const wake_view *)ctx)->s;
    const tl_frame_uniforms *u = ((const wake_view *)ctx)->u;
    if (!(ray[1] < 0.0))
        return 0;
    double t0 = s->camera.position[1] / -ray[1], t1 = (s->camera.position[1] + u->depth) / -ray[1];
    double a[2] = {ray[0] * t0, ray[2] * t0}, d[2] = {ray[0] * (t1 - t0), ray[2] * (t1 - t0)};
    for (int g = 0; g < TL_WAKE_GROUPS; g++) {
        const float *c = u->objects[0].wake_groups[g];
        double q[2] = {c[0] - a[0], c[1] - a[1]}, len2 = d[0] * d[0] + d[1] * d[1];
        double k = len2 > 0.0 ? fmin(fmax((q[0] * d[0] + q[1] * d[1]) / len2, 0.0), 1.0) : 0.0;
        if (hypot(q[0] - k * d[0], q[1] - k * d[1]) <= c[2])
            return 1;
    }
    return 0;
}

/* The pixels whose rays can meet the wake's foam (u.plan.wake_rect), where the
 * renderer draws the programs with the wake: every ray through every pixel
 * outside it, at the pixel's centre, corners and edge midpoints, meets
 * water no group's circle holds; inside, some ray meets such water. From
 * far off the wake is a small part of the frame; from a camera down in
 * it, all of it. */
static void test_rect(void)
{
    struct {
        const char *what;
        double pos[3], target[3];
        int expect; /* 0: under half the frame, 1: all of it, 2: any */
    } cases[] = {
        {"160 m to the side", {160.0, 25.0, 20.0}, {0.0, 0.0, -60.0}, 0},
        {"300 m behind, low", {-40.0, 4.0, -400.0}, {0.0, 0.0, -40.0}, 0},
        {"25 m over the wake", {5.0, 25.0, 10.0}, {0.0, 0.0, -20.0}, 2},
        {"in the wake, 0.4 m up", {3.0, 0.4, -10.0}, {0.0, 0.0, -60.0}, 1},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        tl_scene s;
        straight_wake(&s, 6.0, 0);
        memcpy(s.camera.position, cases[c].pos, sizeof s.camera.position);
        tl_scene_camera_look_at(&s.camera, cases[c].target, NULL);
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_frame_uniforms u;
        tl_prepare_frame(&s, &w, &u);
        CHECK(u.features & TL_FEATURE_WAKE);
        const int *rect = u.plan.wake_rect;
        int missed, inside_hits, area;
        const wake_view view = {&s, &u};
        rect_rays(&s, rect, ray_reaches_wake, &view, &missed, &inside_hits, &area);
        int total = u.width * u.height;
        printf("wake's rectangle, %s: x %d-%d, y %d-%d (%.0f%% of the frame); rays outside it "
               "that reach the wake: %d\n",
               cases[c].what, rect[0], rect[2], rect[1], rect[3], 100.0 * area / total, missed);
        CHECK(missed == 0);
        CHECK(inside_hits > 0);
        if (cases[c].expect == 0)
            CHECK(area < total / 2);
        if (cases[c].expect == 1)
            CHECK(area == total);
    }
}

/* The frame drawn with the wake's programs inside its rectangle and
 * without them around it matches the frame drawn with them everywhere. */
static void test_split_matches_whole(tl_renderer *r)
{
    tl_scene s;
    straight_wake(&s, 6.0, 0);
    s.camera.position[0] = 160.0;
    s.camera.position[2] = 20.0;
    const double target[3] = {0.0, 0.0, -60.0};
    tl_scene_camera_look_at(&s.camera, target, NULL);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    const int w = u.width, h = u.height;
    int area =
        (u.plan.wake_rect[2] - u.plan.wake_rect[0]) * (u.plan.wake_rect[3] - u.plan.wake_rect[1]);
    CHECK(area > 0 && area < w * h);
    int differ;
    tl_frame whole;
    double worst = split_against_whole(r, &u, u.plan.wake_rect, &differ, &whole), foam = 0.0;
    /* The wake is in the picture: the rectangle's pixels are brighter with it. */
    tl_frame none;
    tl_scene calm = s;
    calm.boat.wake = 0.0;
    if (render(r, &calm, &none) == 0) {
        for (size_t i = 0; i < (size_t)w * h * 4; i++)
            foam = fmax(foam, (double)whole.display[i] - none.display[i]);
        tl_frame_free(&none);
    }
    printf("wake's split against whole (rectangle %.0f%% of the frame): %d of %d display values "
           "differ, by at most %.3g; the wake brightens a value by up to %.3f\n",
           100.0 * area / (w * h), differ, w * h * 4, worst, foam);
    CHECK(worst < 1e-4);
    CHECK(foam > 0.1);
    tl_frame_free(&whole);
}

/* The Kelvin wake's waves: the GPU's slope against the CPU's
 * (tl_kelvin_slope) behind a boat at 4 m/s; none outside the wedge; on the
 * track the transverse waves' crests come every 2 pi U^2 / g (10.2 m). */
static void test_kelvin(tl_renderer *r)
{
    enum { N = 96 };
    tl_scene s;
    straight_wake(&s, 4.0, 0);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_WAKE);
    const double length = u.objects[0].wake_params[3];
    CHECK(length > 1.0);
    float in[N * 4], out[N * 4];
    srand(11);
    for (int i = 0; i < N; i++) {
        double behind = 1.0 + 60.0 * rand() / RAND_MAX;
        in[4 * i] = (float)behind;
        in[4 * i + 1] = (float)(behind * (1.2 * rand() / RAND_MAX - 0.6)); /* out past the wedge */
        if (i % 4 == 1) { /* near a cusp line, where the crests break */
            behind = length * (1.0 + 2.0 * rand() / RAND_MAX);
            in[4 * i] = (float)behind;
            in[4 * i + 1] =
                (float)(behind * (i % 8 == 1 ? 1.0 : -1.0) * (0.3 + 0.05 * rand() / RAND_MAX));
        }
        in[4 * i + 2] =
            (float)((i % 4 == 1 ? 4.0 : 1.0) + (i % 4 == 1 ? 3.0 : 6.0) * rand() / RAND_MAX);
        in[4 * i + 3] = i % 2 ? 0.0f : (float)(0.2 * rand() / RAND_MAX);
    }
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe4(r, &u, 16, in, N, u.octaves, out, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    double worst = 0.0, largest = 0.0, worst_cap = 0.0;
    int outside = 0, outside_zero = 1, capped = 0;
    for (int i = 0; i < N; i++) {
        double want[2];
        tl_kelvin_slope(in[4 * i], in[4 * i + 1], in[4 * i + 2], length, in[4 * i + 3], want);
        for (int c = 0; c < 2; c++) {
            worst = fmax(worst, fabs(out[4 * i + c] - want[c]));
            largest = fmax(largest, fabs(want[c]));
        }
        double cap = tl_kelvin_whitecap(in[4 * i], in[4 * i + 1], in[4 * i + 2], length);
        worst_cap = fmax(worst_cap, fabs(out[4 * i + 2] - cap));
        capped += cap > 0.05;
        double ratio = in[4 * i + 1] / in[4 * i];
        if (ratio * ratio > 1.0 / 8.0) {
            outside++;
            outside_zero &=
                want[0] == 0.0 && want[1] == 0.0 && out[4 * i] == 0.0f && out[4 * i + 1] == 0.0f;
        }
    }
    /* The track: zero crossings of the transverse waves' slope. */
    double last = 0.0, first_cross = -1.0, last_cross = -1.0;
    int crossings = 0;
    for (double b = 20.0; b <= 80.0; b += 0.01) {
        double sl[2];
        tl_kelvin_slope(b, 0.0, 4.0, length, 0.0, sl);
        if (b > 20.0 && (sl[0] > 0.0) != (last > 0.0)) {
            if (first_cross < 0.0)
                first_cross = b;
            last_cross = b;
            crossings++;
        }
        last = sl[0];
    }
    double spacing = 2.0 * (last_cross - first_cross) / (crossings - 1);
    printf("Kelvin waves: GPU against CPU at %d points, worst %.2g of slopes up to %.3f; %d points "
           "outside the wedge, all flat: %d; crest spacing on the track %.3f m (2 pi U^2 / g = "
           "%.3f)\n",
           N, worst, largest, outside, outside_zero, spacing, 2.0 * M_PI * 16.0 / 9.81);
    printf("Kelvin whitecaps: GPU against CPU, worst %.2g; %d of %d points white\n", worst_cap,
           capped, N);
    CHECK(worst_cap < 2e-3);
    CHECK(worst < 2e-3 * fmax(largest, 0.01));
    CHECK(largest > 0.01);
    CHECK(outside > 10 && outside_zero);
    CHECK_NEAR(spacing, 2.0 * M_PI * 16.0 / 9.81, 0.02);
    CHECK(capped > 3);

    /* The whitecaps: bars along each cusp line near the boat (white on
     * part of the line, not all of it), none on the track or far behind. */
    long white = 0, samples = 0;
    double brightest = 0.0, on_track = 0.0, far = 0.0;
    for (double b = length; b <= 3.0 * length; b += 0.01) {
        double cap = tl_kelvin_whitecap(b, b * 0.34, 4.0, length);
        brightest = fmax(brightest, cap);
        white += cap > 0.1;
        samples++;
        on_track = fmax(on_track, tl_kelvin_whitecap(b, 0.0, 4.0, length));
        far = fmax(far,
                   tl_kelvin_whitecap(b + 20.0 * length, (b + 20.0 * length) * 0.34, 4.0, length));
    }
    printf("Kelvin whitecaps along the cusp line 1-3 hull lengths behind: brightest %.2f, white "
           "on %.2f of it; on the track %.2g; 20 lengths on %.2g\n",
           brightest, (double)white / samples, on_track, far);
    CHECK(brightest > 0.3);
    CHECK(white > samples / 20 && white < samples / 2);
    CHECK(on_track == 0.0);
    CHECK(far < 0.01);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_fresh(r);
    test_old(r);
    test_outside(r);
    test_slow(r);
    test_from_below(r);
    test_rect();
    test_split_matches_whole(r);
    test_kelvin(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
