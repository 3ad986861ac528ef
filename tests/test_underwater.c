/* Under water and fog on the GPU (llvmpipe on CI): Snell's window in a
 * frame, the exact Fresnel reflectance from the water side, Beer-Lambert
 * and fog transmittance against exp(-sigma d), the haze at the horizon
 * after sunset, the waterline of a frame across the surface, the auto
 * mode's flip, fog 0 as no fog, and the capillary ripples' softening of
 * the window's rim. */
#include <string.h>

#include "core/tl_math.h"
#include "optics/tl_optics.h"
#include "tl_gl_test.h"

static void prepare(const tl_scene *s, tl_frame_uniforms *u)
{
    tl_waves w;
    tl_waves_init(&w, &s->ocean);
    tl_prepare_frame(s, &w, u);
}

/* Reflectance from the Fresnel equations in their angle form, to check
 * the cosine form the code uses. */
static double fresnel_by_angles(double theta_i, double n1, double n2)
{
    double s = n1 / n2 * sin(theta_i);
    if (s >= 1.0)
        return 1.0;
    if (theta_i == 0.0) {
        double r = (n1 - n2) / (n1 + n2);
        return r * r;
    }
    double theta_t = asin(s);
    double rs = sin(theta_i - theta_t) / sin(theta_i + theta_t);
    double rp = tan(theta_i - theta_t) / tan(theta_i + theta_t);
    return 0.5 * (rs * rs + rp * rp);
}

static void test_fresnel(tl_renderer *r)
{
    const double angles[] = {0, 10, 25, 40, 45, 47, 48, 48.5, 48.7, 55, 70, 89};
    enum { N = sizeof angles / sizeof angles[0] };
    tl_scene s;
    tl_scene_defaults(&s);
    tl_frame_uniforms u;
    prepare(&s, &u);
    float in[2 * N], out[4 * N];
    for (int i = 0; i < N; i++) {
        in[2 * i] = (float)cos(angles[i] * TL_DEG);
        in[2 * i + 1] = 1.333f;
    }
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe(r, &u, 1, in, N, 1, out, &err) == 0);
    double worst_gpu = 0.0, worst_cpu = 0.0;
    for (int i = 0; i < N; i++) {
        double exact = fresnel_by_angles(angles[i] * TL_DEG, 1.333, 1.0);
        /* The GPU saw cos rounded to float: compare at that cosine. */
        double at = acos((double)in[2 * i]);
        worst_gpu = fmax(worst_gpu, fabs(out[4 * i] - fresnel_by_angles(at, 1.333, 1.0)));
        worst_cpu =
            fmax(worst_cpu, fabs(tl_optics_fresnel(cos(angles[i] * TL_DEG), 1.333, 1.0) - exact));
        if (angles[i] > 48.6) /* total internal reflection */
            CHECK(out[4 * i] == 1.0f);
    }
    double schlick48 = 0.02 + 0.98 * pow(1.0 - cos(48.0 * TL_DEG), 5.0);
    printf("Fresnel from the water side: |GPU - exact| <= %.2g, |CPU - exact| <= %.2g; at 48 deg "
           "exact %.3f, Schlick %.3f; window half-angle %.3f deg\n",
           worst_gpu, worst_cpu, fresnel_by_angles(48.0 * TL_DEG, 1.333, 1.0), schlick48,
           tl_optics_snell_window(1.333) / TL_DEG);
    CHECK(worst_gpu <= 1e-4);
    CHECK(worst_cpu <= 1e-12);
    CHECK_NEAR(tl_optics_snell_window(1.333) / TL_DEG, 48.6, 0.05);
}

/* The reflectance from the water side over rough facets: the GPU against
 * the CPU; a spread of nearly nothing is the smooth surface's; it rises
 * with the angle without a step (the largest rise over 0.05 deg against
 * the smooth surface's own last one before the critical angle); past the
 * critical angle by three spreads almost every facet reflects all. */
static void test_fresnel_rough(tl_renderer *r)
{
    enum { N = 1200 };
    const double spread = 0.04; /* radians: 2.3 deg */
    tl_scene s;
    tl_scene_defaults(&s);
    tl_frame_uniforms u;
    prepare(&s, &u);
    static float in[4 * N], out[4 * N];
    for (int i = 0; i < N; i++) {
        double angle = 30.0 + 30.0 * i / (N - 1); /* 30 .. 60 deg, 0.025 deg apart */
        in[4 * i] = (float)cos(angle * TL_DEG);
        in[4 * i + 1] = 1.333f;
        in[4 * i + 2] = (float)spread;
        in[4 * i + 3] = 0.0f;
    }
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe4(r, &u, 32, in, N, 1, out, &err) == 0);
    double worst_gpu = 0.0, rough_step = 0.0, smooth_step = 0.0, fall = 0.0, smooth_gap = 0.0;
    double critical = tl_optics_snell_window(1.333);
    for (int i = 0; i < N; i++) {
        double at = acos((double)in[4 * i]);
        double cpu = tl_optics_fresnel_rough(cos(at), 1.333, 1.0, spread);
        worst_gpu = fmax(worst_gpu, fabs(out[4 * i] - cpu));
        smooth_gap = fmax(smooth_gap, fabs(tl_optics_fresnel_rough(cos(at), 1.333, 1.0, 1e-7) -
                                           tl_optics_fresnel(cos(at), 1.333, 1.0)));
        if (i > 0) {
            double before = acos((double)in[4 * (i - 1)]);
            double rise = cpu - tl_optics_fresnel_rough(cos(before), 1.333, 1.0, spread);
            rough_step = fmax(rough_step, rise);
            fall = fmin(fall, rise);
            if (at < critical)
                smooth_step = fmax(smooth_step, tl_optics_fresnel(cos(at), 1.333, 1.0) -
                                                    tl_optics_fresnel(cos(before), 1.333, 1.0));
        }
    }
    double past = tl_optics_fresnel_rough(cos(critical + 3.0 * spread), 1.333, 1.0, spread);
    printf("Fresnel over rough facets (spread %.2f rad): |GPU - CPU| <= %.2g; largest rise per "
           "step %.4f (smooth %.4f); spread 1e-7 against smooth %.2g; 3 spreads past the edge "
           "%.5f\n",
           spread, worst_gpu, rough_step, smooth_step, smooth_gap, past);
    /* The GPU's float acos and asin: near the edge the reflectance rises
     * by up to 9 per radian. */
    CHECK(worst_gpu <= 1e-3);
    CHECK(fall >= -1e-12);
    CHECK(rough_step < 0.2 * smooth_step);
    CHECK(smooth_gap <= 1e-6);
    CHECK(past > 0.99 && past < 1.0);
}

/* The light through Snell's window on a face under the water, by its
 * tilt: the GPU against the CPU, and both against the cone's irradiance
 * summed over its directions (the closed form is an approximation). */
static void test_window_share(tl_renderer *r)
{
    enum { N = 41 };
    tl_scene s;
    tl_scene_defaults(&s);
    tl_frame_uniforms u;
    prepare(&s, &u);
    float in[2 * N], out[4 * N];
    for (int i = 0; i < N; i++) {
        in[2 * i] = (float)(-1.0 + 2.0 * i / (N - 1));
        in[2 * i + 1] = 1.333f;
    }
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe(r, &u, 25, in, N, 1, out, &err) == 0);
    double cone = tl_optics_snell_window(1.333), worst_gpu = 0.0, worst_sum = 0.0;
    for (int i = 0; i < N; i++) {
        double ny = in[2 * i], nx = sqrt(fmax(1.0 - ny * ny, 0.0));
        double cpu = tl_optics_window_share(ny, 1.333);
        worst_gpu = fmax(worst_gpu, fabs(out[4 * i] - cpu));
        /* The cone's directions, even in solid angle, cosine-weighted on
         * the face, against a face turned up. */
        double sum = 0.0, up = 0.0;
        for (int a = 0; a < 200; a++)
            for (int b = 0; b < 200; b++) {
                double cos_t = 1.0 - (1.0 - cos(cone)) * (a + 0.5) / 200.0;
                double sin_t = sqrt(1.0 - cos_t * cos_t), phi = 2.0 * M_PI * (b + 0.5) / 200.0;
                sum += fmax(nx * sin_t * cos(phi) + ny * cos_t, 0.0);
                up += cos_t;
            }
        worst_sum = fmax(worst_sum, fabs(cpu - sum / up));
        if (ny < -0.76)
            CHECK(cpu == 0.0 && out[4 * i] == 0.0f);
    }
    printf("Snell's window on a tilted face: |GPU - CPU| <= %.2g, |CPU - the cone summed| <= %.3f; "
           "a side %.3f, a face 45 deg down %.4f\n",
           worst_gpu, worst_sum, tl_optics_window_share(0.0, 1.333),
           tl_optics_window_share(-sqrt(0.5), 1.333));
    CHECK(worst_gpu <= 1e-6);
    CHECK(worst_sum <= 0.03);
}

/* Snell's window: 5 m under a flat sea, looking straight up with a wide
 * lens; the bright window's edge sits at 48.6 deg from the zenith, and
 * outside it no pixel carries the sky's light. */
static void test_snell_window(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = s.height = 241;
    s.ocean.depth = 0.001;
    s.camera.position[1] = -5.0;
    s.camera.pitch = 90.0 * TL_DEG;
    s.camera.vfov = 130.0 * TL_DEG;
    s.sun.elevation = 60.0 * TL_DEG;
    s.sun.azimuth = 0.0;
    /* The window's optics, not the sky's: the seed sky's dim sun keeps the
     * water body's glow toward it below the window's light. */
    s.sky.model = TL_SKY_SEED;
    tl_frame_uniforms u;
    prepare(&s, &u);
    CHECK((u.features & TL_FEATURE_UNDERWATER) && !(u.features & TL_FEATURE_WATERLINE));
    tl_frame f;
    if (render(r, &s, &f))
        return;
    int c = s.width / 2;
    double focal = 0.5 * s.height / tan(0.5 * s.camera.vfov);
    /* Along the four half-axes from the centre (the sun lies elsewhere). */
    const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    double worst = 0.0;
    for (int d = 0; d < 4; d++) {
        double inside = luminance(
            f.color +
            ((size_t)(c + 10 * dirs[d][1]) * s.width + (size_t)(c + 10 * dirs[d][0])) * 4);
        double outside = luminance(
            f.color +
            ((size_t)(c + 115 * dirs[d][1]) * s.width + (size_t)(c + 115 * dirs[d][0])) * 4);
        double half = 0.5 * (inside + outside);
        int k = 10;
        while (k < 118 && luminance(f.color + ((size_t)(c + k * dirs[d][1]) * s.width +
                                               (size_t)(c + k * dirs[d][0])) *
                                                  4) > half)
            k++;
        double edge = atan((k - 0.5) / focal) / TL_DEG;
        printf("Snell's window along (%d, %d): edge at %.2f deg (inside %.3f, outside %.4f)\n",
               dirs[d][0], dirs[d][1], edge, inside, outside);
        worst = fmax(worst, fabs(edge - 48.6));
        CHECK(outside < 0.2 * inside);
    }
    CHECK(worst <= 1.0);
    /* Outside the window (beyond 49.6 deg, past the taps of a pixel's own
     * facet spread) no pixel holds sky light (the reflectance there is
     * exactly 1, test_fresnel): all are the water
     * body's in-scattered light, dimmer than the window, bluer than red. */
    double brightest = 0.0;
    int blue = 1;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++) {
            double angle = atan(hypot(x - c, y - c) / focal) / TL_DEG;
            if (angle < 49.6)
                continue;
            const float *p = f.color + ((size_t)y * s.width + x) * 4;
            brightest = fmax(brightest, luminance(p));
            blue &= p[2] > p[0];
        }
    double window = luminance(f.color + ((size_t)c * s.width + c + 10) * 4);
    printf("outside the window: brightest %.4f (the window %.3f)\n", brightest, window);
    CHECK(brightest < 0.5 * window);
    CHECK(blue);
    tl_frame_free(&f);
}

/* Beer-Lambert per channel, and the friendly form: white light after
 * color_distance metres has the colour asked for. */
static void test_water_transmittance(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.camera.position[1] = -4.0;
    for (int friendly = 0; friendly < 2; friendly++) {
        if (friendly) {
            s.water.color_distance = 12.0;
            s.water.color_at_distance[0] = 0.2;
            s.water.color_at_distance[1] = 0.6;
            s.water.color_at_distance[2] = 0.7;
        }
        tl_frame_uniforms u;
        prepare(&s, &u);
        double sigma[3];
        tl_optics_water_extinction(&s.water, sigma);
        const float dist[] = {0.0f, 1.0f, 5.0f, 12.0f, 40.0f, 150.0f};
        enum { N = sizeof dist / sizeof dist[0] };
        float in[2 * N], out[4 * N];
        for (int i = 0; i < N; i++) {
            in[2 * i] = dist[i];
            in[2 * i + 1] = 0.0f;
        }
        tl_error err;
        tl_error_clear(&err);
        CHECK(tl_renderer_probe(r, &u, 2, in, N, 1, out, &err) == 0);
        int monotone = 1;
        double worst = 0.0;
        for (int i = 0; i < N; i++)
            for (int ch = 0; ch < 3; ch++) {
                double want = exp(-sigma[ch] * dist[i]);
                worst = fmax(worst, fabs(out[4 * i + ch] - want) / fmax(want, 1e-30));
                if (i > 0)
                    monotone &= out[4 * i + ch] <= out[4 * (i - 1) + ch];
            }
        printf("water transmittance (%s): max relative error %.2g\n",
               friendly ? "colour at distance" : "absorption + scattering", worst);
        CHECK(worst <= 1e-4);
        CHECK(monotone);
        if (friendly)
            for (int ch = 0; ch < 3; ch++)
                CHECK_NEAR(out[4 * 3 + ch], s.water.color_at_distance[ch], 1e-5);
    }
}

static void test_fog_transmittance(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.camera.position[1] = 7.0;
    s.fog.density = 0.02;
    s.fog.height = 40.0;
    tl_frame_uniforms u;
    prepare(&s, &u);
    CHECK(u.features & TL_FEATURE_FOG);
    const float slopes[] = {-0.3f, -0.01f, 0.0f, 0.05f, 0.5f, 1.0f};
    const float dist[] = {0.0f, 2.0f, 10.0f, 50.0f, 200.0f, 1000.0f, 5000.0f};
    enum { NS = 6, ND = 7 };
    float in[2 * NS * ND], out[4 * NS * ND];
    for (int a = 0; a < NS; a++)
        for (int b = 0; b < ND; b++) {
            in[2 * (a * ND + b)] = dist[b];
            in[2 * (a * ND + b) + 1] = slopes[a];
        }
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe(r, &u, 3, in, NS * ND, 1, out, &err) == 0);
    double worst = 0.0;
    int monotone = 1;
    for (int a = 0; a < NS; a++)
        for (int b = 0; b < ND; b++) {
            double want = exp(-tl_optics_fog_depth(0.02, 40.0, 7.0, slopes[a], dist[b]));
            worst = fmax(worst, fabs(out[4 * (a * ND + b)] - want));
            if (b > 0)
                monotone &= out[4 * (a * ND + b)] <= out[4 * (a * ND + b - 1)];
        }
    /* A uniform layer (a level ray) is exp(-density · exp(-y/H) · d). */
    double level = exp(-0.02 * exp(-7.0 / 40.0) * 50.0);
    printf("fog transmittance: max |GPU - CPU| %.2g; level ray over 50 m %.5f (exp form %.5f)\n",
           worst, out[4 * (2 * ND + 3)], level);
    CHECK(worst <= 1e-4);
    CHECK(monotone);
    CHECK_NEAR(out[4 * (2 * ND + 3)], level, 1e-5);
}

/* Each row's mean luminance over the frame's width, top row first; the
 * first row of water. */
static int row_luminance(const tl_scene *s, const tl_frame *f, double *row)
{
    int horizon = -1;
    for (int y = 0; y < s->height; y++) {
        row[y] = 0.0;
        for (int x = 0; x < s->width; x++)
            row[y] += luminance(f->color + ((size_t)y * s->width + (size_t)x) * 4) / s->width;
        if (horizon < 0 && f->depth[(size_t)y * s->width] < TL_FRAME_SKY_DEPTH)
            horizon = y;
    }
    return horizon;
}

/* Haze after sunset (dusk.tl's fog): looking toward where the sun went
 * down, the haze glows with the horizon behind it. Lit by the hemisphere's
 * mean alone it hid that glow behind a dark band: the sky's rows within
 * 5 deg of the horizon fell to 0.15 of the same rows without fog (0.47 now). */
static void test_haze_after_sunset(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 16;
    s.height = 180;
    s.camera.position[1] = 3.0;
    s.camera.yaw = 0.0;
    s.camera.pitch = 0.0;
    s.camera.vfov = 20.0 * TL_DEG;
    s.sky.model = TL_SKY_PHYSICAL;
    s.sun.elevation = -3.0 * TL_DEG;
    s.sun.azimuth = 0.0;
    tl_scene fogged = s;
    fogged.fog.density = 0.002;
    fogged.fog.height = 40.0;
    fogged.fog.color[0] = 0.62;
    fogged.fog.color[1] = 0.52;
    fogged.fog.color[2] = 0.45;
    tl_frame clear, hazy;
    if (render(r, &s, &clear))
        return;
    if (render(r, &fogged, &hazy)) {
        tl_frame_free(&clear);
        return;
    }
    double a[180], b[180];
    int horizon = row_luminance(&s, &clear, a);
    CHECK(row_luminance(&fogged, &hazy, b) == horizon);
    double focal = 0.5 * s.height / tan(0.5 * s.camera.vfov);
    int up5 = (int)(0.5 * s.height - focal * tan(5.0 * TL_DEG));
    CHECK(horizon > up5 && horizon < s.height);
    double least = INFINITY;
    for (int y = up5; y < horizon; y++)
        least = fmin(least, b[y] / a[y]);
    printf("haze after sunset: the sky within 5 deg of the horizon at >= %.2f of its light "
           "without fog\n",
           least);
    CHECK(least >= 0.4);
    tl_frame_free(&clear);
    tl_frame_free(&hazy);
}

/* A camera at the surface: the frame straddles it, every pixel is finite,
 * and the waterline (the sign change of each pixel's lens gap) is one
 * connected curve across the frame. */
static void test_waterline(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 128;
    s.height = 72;
    s.time = 4.0;
    s.camera.pitch = 0.0;
    s.camera.roll = 0.05; /* the waterline slightly tilted, across the whole frame */
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    /* The camera level with the surface at the centre pixel's lens point. */
    s.camera.position[1] =
        tl_waves_height(&w, 0.0, TL_LENS_DISTANCE, s.time, s.quality.march_octaves);
    tl_frame_uniforms u;
    prepare(&s, &u);
    CHECK((u.features & TL_FEATURE_WATERLINE) && (u.features & TL_FEATURE_UNDERWATER));
    tl_frame f;
    if (render(r, &s, &f))
        return;
    int finite = 1;
    for (size_t i = 0; i < (size_t)s.width * s.height * 4; i++)
        finite &= isfinite(f.color[i]) && f.color[i] >= 0.0f;
    CHECK(finite);
    tl_frame_free(&f);

    enum { W = 128, H = 72 };
    static float in[2 * W * H], out[4 * W * H];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            in[2 * (y * W + x)] = (float)((x + 0.5) / W * 2.0 - 1.0);
            in[2 * (y * W + x) + 1] = (float)((y + 0.5) / H * 2.0 - 1.0); /* bottom row first */
        }
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe(r, &u, 4, in, W * H, s.quality.march_octaves, out, &err) == 0);
    int one_change = 1, connected = 1, prev = -1, under = 0;
    for (int x = 0; x < W; x++) {
        int changes = 0, row = -1;
        for (int y = 1; y < H; y++)
            if ((out[4 * (y * W + x)] < 0.0f) != (out[4 * ((y - 1) * W + x)] < 0.0f)) {
                changes++;
                row = y;
            }
        under += out[4 * x] < 0.0f; /* bottom row under water */
        one_change &= changes == 1;
        if (prev >= 0 && row >= 0)
            connected &= abs(row - prev) <= 3;
        prev = row;
    }
    printf("waterline: one crossing per column %s, connected %s, %d of %d bottom pixels under\n",
           one_change ? "yes" : "no", connected ? "yes" : "no", under, W);
    CHECK(one_change);
    CHECK(connected);
    CHECK(under == W);
}

/* auto: the side flips exactly where the camera crosses the CPU surface;
 * the lens decides each pixel from the same heights. */
static void test_auto_flip(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.time = 7.0;
    s.camera.pitch = 0.0;
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_giant none;
    tl_giant_prepare(&none, &s.giant, s.time);
    /* The centre pixel's lens point, 0.25 m ahead: where the surface is. */
    double right[3], up[3], fwd[3];
    tl_scene_camera_basis(&s.camera, right, up, fwd);
    double lx = fwd[0] * TL_LENS_DISTANCE, lz = fwd[2] * TL_LENS_DISTANCE;
    double h = tl_waves_height(&w, lx, lz, s.time, s.quality.march_octaves);
    const double offsets[2] = {-2e-3, 2e-3};
    for (int k = 0; k < 2; k++) {
        s.camera.position[1] = h + offsets[k] - fwd[1] * TL_LENS_DISTANCE;
        tl_frame_uniforms u;
        prepare(&s, &u);
        float in[2] = {0.0f, 0.0f}, out[4];
        tl_error err;
        tl_error_clear(&err);
        CHECK(tl_renderer_probe(r, &u, 4, in, 1, s.quality.march_octaves, out, &err) == 0);
        printf("lens %+.0f mm from the surface: GPU gap %+.5f m\n", offsets[k] * 1e3, out[0]);
        CHECK((out[0] < 0.0f) == (offsets[k] < 0.0));
        CHECK_NEAR(out[0], offsets[k], 2e-4);
    }
    /* Far from the surface the whole frame is one side. */
    double hc = tl_waves_height(&w, 0.0, 0.0, s.time, s.quality.march_octaves);
    s.camera.position[1] = hc + 3.0;
    CHECK(tl_prepare_water_side(&s, &w, &none, NULL) == TL_WATER_ABOVE);
    s.camera.position[1] = hc - 3.0;
    CHECK(tl_prepare_water_side(&s, &w, &none, NULL) == TL_WATER_BELOW);
    s.camera.position[1] = hc + 1e-6;
    CHECK(tl_prepare_water_side(&s, &w, &none, NULL) == TL_WATER_STRADDLES);
    s.underwater.mode = TL_UNDERWATER_OFF;
    CHECK(tl_prepare_water_side(&s, &w, &none, NULL) == TL_WATER_ABOVE);
    s.underwater.mode = TL_UNDERWATER_ON;
    s.camera.position[1] = hc + 30.0;
    CHECK(tl_prepare_water_side(&s, &w, &none, NULL) == TL_WATER_BELOW);
}

/* fog.density 0 compiles no fog: the frame is byte-identical whatever the
 * other fog knobs say. */
/* A bay's frame under the water with the sea floor and its caustics but
 * no shafts (`underwater.shafts 0`, or the seed preset): llvmpipe took
 * minutes to compile that program when the caustics inlined the waves'
 * loop once per difference (caustics.glsl now loops over them), so the
 * test's time limit guards it. The frame is finite and lit, the sand
 * below brighter than the water toward the surface's edge. */
static void test_floor_without_shafts(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 160;
    s.height = 90;
    s.camera.position[0] = -4.0;
    s.camera.position[1] = -1.7;
    s.camera.yaw = 75.0 * TL_DEG;
    s.camera.pitch = -20.0 * TL_DEG;
    s.camera.vfov = 75.0 * TL_DEG;
    s.sun.elevation = 50.0 * TL_DEG;
    s.sun.azimuth = 250.0 * TL_DEG;
    s.underwater.shafts = 0.0;
    s.ocean.floor_depth = 9.0;
    s.water.scattering = 0.08;
    tl_frame_uniforms u;
    prepare(&s, &u);
    CHECK((u.features & TL_FEATURE_CAUSTICS) && (u.features & TL_FEATURE_SEA_FLOOR) &&
          !(u.features & TL_FEATURE_SHAFTS));
    tl_frame f;
    if (render(r, &s, &f))
        return;
    size_t n = (size_t)s.width * s.height;
    int finite = 1;
    double bottom = 0.0, top = 0.0;
    for (size_t i = 0; i < n; i++) {
        const float *p = f.color + 4 * i;
        finite &= isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]) && p[0] >= 0.0f;
        size_t row = i / (size_t)s.width;
        if (row >= (size_t)s.height * 3 / 4)
            bottom += luminance(p);
        else if (row < (size_t)s.height / 8)
            top += luminance(p);
    }
    bottom /= (double)n / 4;
    top /= (double)n / 8;
    printf("a bay under the water without shafts: sand %.4f, water above it %.4f\n", bottom, top);
    CHECK(finite);
    CHECK(bottom > top && top > 0.0);
    tl_frame_free(&f);
}

static void test_no_fog(tl_renderer *r)
{
    tl_scene a, b;
    tl_scene_defaults(&a);
    a.width = 96;
    a.height = 54;
    b = a;
    b.fog.color[0] = 9.0;
    b.fog.height = 3.0;
    tl_frame_uniforms u;
    prepare(&b, &u);
    CHECK(!(u.features & TL_FEATURE_FOG));
    tl_frame fa, fb;
    if (render(r, &a, &fa))
        return;
    if (render(r, &b, &fb)) {
        tl_frame_free(&fa);
        return;
    }
    size_t n = (size_t)a.width * a.height;
    CHECK(memcmp(fa.color, fb.color, n * 4 * sizeof(float)) == 0);
    CHECK(memcmp(fa.depth, fb.depth, n * sizeof(float)) == 0);
    tl_frame_free(&fa);
    tl_frame_free(&fb);
}

/* The capillary ripples (water.capillaries): 3 m under the default sea,
 * looking straight up, more of the rim of Snell's window (40 to 56 deg
 * from the zenith) lies between the window's light and the water's with
 * them than without (the shards' hard edges softened). The uniform is the
 * CPU's variance; a calm sea has none. */
static int rim_middle(tl_renderer *r, double capillaries, double *middle)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = s.height = 161;
    s.camera.position[1] = -3.0;
    s.camera.pitch = 90.0 * TL_DEG;
    s.camera.vfov = 130.0 * TL_DEG;
    s.sun.elevation = 60.0 * TL_DEG;
    s.water.capillaries = capillaries;
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_frame_uniforms u;
    tl_prepare_frame(&s, &w, &u);
    CHECK_NEAR(u.capillary_slope_var,
               tl_waves_capillary_slope_variance(&w, s.quality.normal_octaves, capillaries), 1e-9);
    tl_frame f;
    if (render(r, &s, &f))
        return -1;
    int c = s.width / 2, n_inside = 0, n_rim = 0, n_middle = 0;
    double focal = 0.5 * s.height / tan(0.5 * s.camera.vfov), inside = 0.0;
    for (int pass = 0; pass < 2; pass++) {
        for (int y = 0; y < s.height; y++)
            for (int x = 0; x < s.width; x++) {
                double zenith = atan(hypot(x - c, y - c) / focal) / TL_DEG;
                double l = luminance(f.color + ((size_t)y * s.width + x) * 4);
                if (pass == 0 && zenith < 30.0) {
                    inside += l;
                    n_inside++;
                } else if (pass == 1 && zenith > 40.0 && zenith < 56.0) {
                    n_rim++;
                    n_middle += l > 0.15 * inside && l < 0.6 * inside;
                }
            }
        if (pass == 0)
            inside /= n_inside;
    }
    tl_frame_free(&f);
    *middle = (double)n_middle / n_rim;
    return 0;
}

static void test_window_capillaries(tl_renderer *r)
{
    double with, without;
    if (rim_middle(r, 0.5, &with) || rim_middle(r, 0.0, &without)) {
        CHECK(0);
        return;
    }
    printf("Snell's window's rim, 3 m under the default sea: %.3f of its pixels between the "
           "window's light and the water's with the capillaries, %.3f without\n",
           with, without);
    CHECK(with > 1.15 * without);
    tl_scene calm;
    tl_scene_defaults(&calm);
    calm.ocean.depth = 0.001;
    tl_waves w;
    tl_waves_init(&w, &calm.ocean);
    CHECK(tl_waves_capillary_slope_variance(&w, calm.quality.normal_octaves, 0.5) < 1e-8);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_fresnel(r);
    test_fresnel_rough(r);
    test_window_share(r);
    test_snell_window(r);
    test_window_capillaries(r);
    test_water_transmittance(r);
    test_fog_transmittance(r);
    test_haze_after_sunset(r);
    test_waterline(r);
    test_auto_flip(r);
    test_no_fog(r);
    test_floor_without_shafts(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
