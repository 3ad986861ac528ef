/* Render tests on whatever EGL gives (llvmpipe on CI): the shader's wave
 * height against the double-precision CPU mirror, and the properties of a
 * rendered still (finite, sky above water, sun disc where it projects). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gl/tl_renderer_internal.h"
#include "tl_gl_test.h"

static void test_probe(tl_renderer *r)
{
    tl_scene s;
    tl_scene_defaults(&s);
    s.time = 10.0;
    double e12 = probe_error(r, &s, 12, 20.0, 24);
    double e36 = probe_error(r, &s, 36, 20.0, 24);
    printf("probe t=10 near origin: max |gpu-cpu| = %.3g (12 oct), %.3g (36 oct)\n", e12, e36);
    CHECK(e12 <= 1e-4);
    CHECK(e36 <= 1e-4);

    /* The precision strategy: far from the origin and late in time the GPU
     * must stay as accurate as at the origin. */
    s.time = 1.0e6;
    s.camera.position[0] = 1.0e6;
    s.camera.position[2] = -7.3e5;
    double far12 = probe_error(r, &s, 12, 20.0, 24);
    double far36 = probe_error(r, &s, 36, 20.0, 24);
    printf("probe t=1e6 at (1e6, -7.3e5): max |gpu-cpu| = %.3g (12), %.3g (36)\n", far12, far36);
    CHECK(far12 <= 1e-4);
    CHECK(far36 <= 1e-4);
}

static void small_scene(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 160;
    s->height = 96;
    s->time = 3.0;
    s->camera.pitch = 0.0; /* horizon across the middle row */
}

/* Finite everywhere; sky above is brighter and water below darker and
 * bluer, with the sun behind the camera so no glitter path is in view. */
static void test_sky_and_water(tl_renderer *r)
{
    tl_scene s;
    small_scene(&s);
    s.sun.azimuth = M_PI;
    s.sun.elevation = 0.5;
    tl_frame f;
    if (render(r, &s, &f))
        return;
    size_t n = (size_t)s.width * (size_t)s.height;
    int finite = 1;
    for (size_t i = 0; i < n * 4; i++)
        finite &= isfinite(f.color[i]) && isfinite(f.display[i]);
    for (size_t i = 0; i < n; i++)
        finite &= isfinite(f.depth[i]) && f.depth[i] > 0.0f;
    CHECK(finite);

    /* Sky: the top quarter; water: the bottom quarter (rows top first). */
    double sky[3] = {0}, water[3] = {0};
    int sky_depth_ok = 1, water_depth_ok = 1;
    int rows = s.height / 4;
    for (int y = 0; y < rows; y++)
        for (int x = 0; x < s.width; x++) {
            const float *top = f.color + ((size_t)y * s.width + x) * 4;
            const float *bottom = f.color + ((size_t)(s.height - 1 - y) * s.width + x) * 4;
            for (int c = 0; c < 3; c++) {
                sky[c] += top[c];
                water[c] += bottom[c];
            }
            sky_depth_ok &= f.depth[(size_t)y * s.width + x] == TL_FRAME_SKY_DEPTH;
            float wd = f.depth[(size_t)(s.height - 1 - y) * s.width + x];
            water_depth_ok &= wd > 1.0f && wd < 100.0f;
        }
    printf("sky mean rgb %.4f %.4f %.4f, water mean rgb %.4f %.4f %.4f\n",
           sky[0] / (rows * s.width), sky[1] / (rows * s.width), sky[2] / (rows * s.width),
           water[0] / (rows * s.width), water[1] / (rows * s.width), water[2] / (rows * s.width));
    CHECK(luminance((float[]){(float)sky[0], (float)sky[1], (float)sky[2]}) >
          2.0 * luminance((float[]){(float)water[0], (float)water[1], (float)water[2]}));
    CHECK(water[2] > water[0]); /* water is bluer than it is red */
    CHECK(sky[2] > sky[0]);
    CHECK(sky_depth_ok);
    CHECK(water_depth_ok);

    /* Display plane: tonemapped values in [0,1]. */
    int display_ok = 1;
    for (size_t i = 0; i < n * 4; i++)
        display_ok &= f.display[i] >= 0.0f && f.display[i] <= 1.0f;
    CHECK(display_ok);
    tl_frame_free(&f);
}

/* The default low sun in front of the camera: the brightest sky pixel is
 * where the sun direction projects. */
static void test_sun_disc(tl_renderer *r)
{
    tl_scene s;
    small_scene(&s);
    tl_frame f;
    if (render(r, &s, &f))
        return;

    /* Sun disc: the brightest sky pixel is where the sun projects. */
    double sun[3], right[3], up[3], fwd[3];
    tl_scene_sun_direction(&s.sun, sun);
    tl_scene_camera_basis(&s.camera, right, up, fwd);
    double sx = sun[0] * right[0] + sun[1] * right[1] + sun[2] * right[2];
    double sy = sun[0] * up[0] + sun[1] * up[1] + sun[2] * up[2];
    double sz = sun[0] * fwd[0] + sun[1] * fwd[1] + sun[2] * fwd[2];
    double th = tan(0.5 * s.camera.vfov), aspect = (double)s.width / s.height;
    double px = ((sx / sz) / (th * aspect) + 1.0) * 0.5 * s.width - 0.5;
    double py_up = ((sy / sz) / th + 1.0) * 0.5 * s.height - 0.5;
    double py = (s.height - 1) - py_up; /* image row */
    int best = 0;
    double best_l = -1.0;
    for (int y = 0; y < s.height / 2; y++)
        for (int x = 0; x < s.width; x++) {
            double l = luminance(f.color + ((size_t)y * s.width + x) * 4);
            if (l > best_l) {
                best_l = l;
                best = y * s.width + x;
            }
        }
    int bx = best % s.width, by = best / s.width;
    printf("sun projects to (%.2f, %.2f), brightest sky pixel (%d, %d), radiance %.1f\n", px, py,
           bx, by, best_l);
    CHECK(fabs(bx - px) <= 1.0);
    CHECK(fabs(by - py) <= 1.0);
    CHECK(best_l > 50.0); /* the disc, not just bright sky */
    tl_frame_free(&f);
}

/* The device platform must be tried on both drivers' extension lists:
 * NVIDIA names only EGL_EXT_device_base, Mesa the two parts of it. */
static void test_device_platform_extensions(void)
{
    CHECK(tl_gl_egl_lists_devices("EGL_EXT_platform_base EGL_EXT_device_base "
                                  "EGL_EXT_platform_device EGL_MESA_platform_surfaceless"));
    CHECK(tl_gl_egl_lists_devices("EGL_EXT_device_enumeration EGL_EXT_device_query "
                                  "EGL_EXT_platform_device"));
    CHECK(!tl_gl_egl_lists_devices("EGL_EXT_device_base EGL_MESA_platform_surfaceless"));
    CHECK(!tl_gl_egl_lists_devices("EGL_EXT_platform_device EGL_EXT_device_query"));
    CHECK(!tl_gl_egl_lists_devices("EGL_EXT_device_base_x EGL_EXT_platform_device"));
    CHECK(!tl_gl_egl_lists_devices(""));
}

/* The readback in two halves (tideline render): two frames queued, then
 * collected oldest first, are the frames tl_renderer_render gives, every
 * plane bit for bit; a third queued frame, a collection with none queued
 * and a frame of the wrong size are errors. */
static void test_queued_readback(tl_renderer *r)
{
    tl_scene s[2];
    tl_frame sync[2], queued[2];
    tl_frame_uniforms u[2];
    tl_error err;
    tl_error_clear(&err);
    for (int k = 0; k < 2; k++) {
        small_scene(&s[k]);
        s[k].time = 2.0 + 5.0 * k;
        s[k].sun.azimuth = 0.4 * k; /* a different sky-view table too */
        gl_test_prepare(r, &s[k], &u[k]);
        if (render(r, &s[k], &sync[k]))
            return;
        CHECK(tl_frame_alloc(&queued[k], s[k].width, s[k].height, &err) == 0);
    }
    for (int k = 0; k < 2; k++) {
        gl_test_prepare(r, &s[k], &u[k]);
        CHECK(tl_renderer_begin(r, u[k].width, u[k].height, u[k].out_width, u[k].out_height,
                                &err) == 0);
        CHECK(tl_renderer_accumulate(r, &u[k], 1.0f, 1, &err) == 0);
        const tl_display_settings display = tl_display_of(&u[k]);
        CHECK(tl_renderer_finish_begin(r, &display, TL_PLANES_ALL, &err) == 0);
    }
    CHECK(tl_renderer_finish_begin(r, &(tl_display_settings){1, 0, 0, {1, 1, 1}}, TL_PLANES_ALL,
                                   &err) != 0);
    CHECK_STR_CONTAINS(err.message, "collect one first");
    int w = 0, h = 0;
    CHECK(tl_renderer_queued_size(r, &w, &h) == 2 && w == 160 && h == 96);
    size_t n = (size_t)160 * 96;
    for (int k = 0; k < 2; k++) {
        CHECK(tl_renderer_finish_end(r, &queued[k], &err) == 0);
        CHECK(memcmp(queued[k].color, sync[k].color, n * 4 * sizeof(float)) == 0);
        CHECK(memcmp(queued[k].depth, sync[k].depth, n * sizeof(float)) == 0);
        CHECK(memcmp(queued[k].display, sync[k].display, n * 4 * sizeof(float)) == 0);
    }
    CHECK(memcmp(sync[0].display, sync[1].display, n * 4 * sizeof(float)) != 0);
    CHECK(tl_renderer_finish_end(r, &queued[0], &err) != 0);
    CHECK_STR_CONTAINS(err.message, "no frame waits");
    /* Only the display plane, into a frame of another size: refused. */
    tl_frame small;
    CHECK(tl_frame_alloc(&small, 80, 48, &err) == 0);
    CHECK(tl_renderer_begin(r, 160, 96, 160, 96, &err) == 0);
    CHECK(tl_renderer_accumulate(r, &u[0], 1.0f, 1, &err) == 0);
    CHECK(tl_renderer_finish_begin(r, &(tl_display_settings){1, 0, 0, {1, 1, 1}}, TL_PLANE_DISPLAY,
                                   &err) == 0);
    CHECK(tl_renderer_finish_end(r, &small, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "does not match");
    CHECK(tl_renderer_queued_size(r, &w, &h) == 0);
    tl_frame_free(&small);
    for (int k = 0; k < 2; k++) {
        tl_frame_free(&sync[k]);
        tl_frame_free(&queued[k]);
    }
}

/* A compiler's log names source strings by number; tideline names them by
 * file, the same way for Mesa's "0:12(5): " and NVIDIA's "0(12) : ". */
static void test_shader_log_names(void)
{
    tl_shader_source src = {.file_count = 2};
    snprintf(src.files[0], sizeof src.files[0], "ocean.frag");
    snprintf(src.files[1], sizeof src.files[1], "water.glsl");
    const char *logs[][2] = {
        {"0:12(5): error: x\n1:3(1): error: y\n",
         "ocean.frag:12(5): error: x\nwater.glsl:3(1): error: y\n"},
        {"1(142) : error C0000: syntax error\n0(7) : warning C7050: z",
         "water.glsl:142: error C0000: syntax error\nocean.frag:7: warning C7050: z"},
        /* Not a known string number, or not a location: left as it is. */
        {"2(4) : error\nerror: no location\n1(x) : odd\n",
         "2(4) : error\nerror: no location\nwater.glsl(x) : odd\n"},
    };
    for (size_t i = 0; i < sizeof logs / sizeof logs[0]; i++) {
        char *got = tl_shader_annotate_log(&src, logs[i][0]);
        CHECK(got != NULL);
        if (got)
            CHECK_STR_EQ(got, logs[i][1]);
        free(got);
    }
}

/* The shared #defines of a program with every feature on leave room for
 * a program's own lines (about a tenth of the buffer), and a buffer they
 * do not fit is refused, not cut short (a frame with every feature under
 * water once found the limit only in the slow extremes test). */
static void test_defines_fit(void)
{
    char defines[TL_DEFINES_SIZE];
    unsigned all = (1u << TL_FEATURE_COUNT) - 1u;
    CHECK(tl_renderer_defines(all, defines, sizeof defines) == 0);
    size_t n = strlen(defines);
    printf("shared #defines with every feature: %zu of %d bytes\n", n, TL_DEFINES_SIZE);
    CHECK(n + TL_DEFINES_SIZE / 10 < sizeof defines);
    CHECK(strstr(defines, "#define TL_GIANT_TROUGH_LIFT ") != NULL);
    CHECK(tl_renderer_defines(all, defines, n) != 0);
}

/* The pixel filter (quality.pixel_filter): the display image is the 3x3
 * Gaussian of the unfiltered display values, edges clamped, glare included
 * (llvmpipe: to 3e-6), at full size and after a half-size render's
 * upscale; the colour plane (EXR) keeps the raw radiance. */
static void test_pixel_filter(tl_renderer *r)
{
    const double scales[2] = {1.0, 0.5};
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        small_scene(&s);
        s.bloom = 0.05;
        s.quality.render_scale = scales[k];
        s.quality.pixel_filter = 0.0;
        tl_frame raw, filtered;
        if (render(r, &s, &raw))
            return;
        s.quality.pixel_filter = 0.7;
        if (render(r, &s, &filtered)) {
            tl_frame_free(&raw);
            return;
        }
        const int w = s.width, h = s.height;
        double side = exp(-0.5 / (0.7 * 0.7));
        side /= 1.0 + 2.0 * side;
        const double weight[3] = {side, 1.0 - 2.0 * side, side};
        double worst = 0.0, moved = 0.0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                for (int c = 0; c < 3; c++) {
                    double sum = 0.0;
                    for (int j = -1; j <= 1; j++)
                        for (int i = -1; i <= 1; i++) {
                            int xx = x + i < 0 ? 0 : x + i >= w ? w - 1 : x + i;
                            int yy = y + j < 0 ? 0 : y + j >= h ? h - 1 : y + j;
                            sum += weight[i + 1] * weight[j + 1] *
                                   raw.display[((size_t)yy * w + xx) * 4 + c];
                        }
                    size_t at = ((size_t)y * w + x) * 4 + c;
                    worst = fmax(worst, fabs(sum - filtered.display[at]));
                    moved = fmax(moved, fabs((double)raw.display[at] - filtered.display[at]));
                }
        printf("pixel filter 0.7 px, render scale %.1f: largest difference from the CPU's filter "
               "%.2g, largest change %.3f\n",
               scales[k], worst, moved);
        /* A GPU's bilinear weights have 8-bit fractions: up to a level. */
        CHECK(worst < 4e-3);
        CHECK(moved > 0.02);
        CHECK(memcmp(raw.color, filtered.color, (size_t)w * h * 4 * sizeof(float)) == 0);
        tl_frame_free(&raw);
        tl_frame_free(&filtered);
    }
}

/* A half-size render's upscale (quality.render_scale 0.5) keeps each
 * output pixel's radiance between the darkest and the brightest of the
 * four scene texels around it (each axis is held between its two nearest
 * taps): the Catmull-Rom kernel's negative lobes rang around the sun's
 * glitter, a dark ring with bright corners. The texels are the same frame
 * rendered at the half size, the sun ahead and its glitter in view. */
static void test_upscale_holds(tl_renderer *r)
{
    tl_scene half, scaled;
    small_scene(&half);
    half.width = 80;
    half.height = 48;
    half.bloom = 0.0;
    half.quality.pixel_filter = 0.0;
    scaled = half;
    scaled.width = 160;
    scaled.height = 96;
    scaled.quality.render_scale = 0.5;
    tl_frame a, b;
    if (render(r, &half, &a))
        return;
    if (render(r, &scaled, &b)) {
        tl_frame_free(&a);
        return;
    }
    const int w = half.width, h = half.height, W = scaled.width, H = scaled.height;
    double worst = 0.0, peak = 0.0;
    for (int row = 0; row < H; row++)
        for (int x = 0; x < W; x++) {
            /* Rows are stored top first; the upscale works in GL's rows. */
            double sx = (x + 0.5) * w / W - 0.5, sy = (H - 1 - row + 0.5) * h / H - 0.5;
            int x0 = (int)floor(sx), y0 = (int)floor(sy);
            int xs[2] = {x0 < 0 ? 0 : x0, x0 + 1 > w - 1 ? w - 1 : x0 + 1};
            int ys[2] = {y0 < 0 ? 0 : y0, y0 + 1 > h - 1 ? h - 1 : y0 + 1};
            for (int c = 0; c < 3; c++) {
                double lo = INFINITY, hi = -INFINITY;
                for (int j = 0; j < 2; j++)
                    for (int i = 0; i < 2; i++) {
                        double v = a.color[((size_t)(h - 1 - ys[j]) * w + xs[i]) * 4 + c];
                        lo = fmin(lo, v);
                        hi = fmax(hi, v);
                    }
                double v = b.color[((size_t)row * W + x) * 4 + c];
                peak = fmax(peak, hi);
                worst = fmax(worst, fmax(lo - v, v - hi) / fmax(hi, 1e-3));
            }
        }
    printf("upscale of a half-size render: brightest texel %.3g, furthest outside its four "
           "texels' range %.2g of their brightest\n",
           peak, worst);
    CHECK(peak > 10.0); /* the glitter is in view */
    CHECK(worst < 1e-4);
    tl_frame_free(&a);
    tl_frame_free(&b);
}

/* The first point below the surface along pixel (x, y)'s ray, walked on
 * the CPU 5 cm at a time from the crest plane up to `until`; `until` when
 * there is none before it. */
static double first_crossing(const tl_scene *s, const tl_waves *waves, int x, int y, double until)
{
    double ray[3];
    pixel_ray(s, x, y, ray);
    double t = -s->camera.position[1] / ray[1];
    for (; t < until; t += 0.05) {
        double px = s->camera.position[0] + ray[0] * t;
        double pz = s->camera.position[2] + ray[2] * t;
        double py = s->camera.position[1] + ray[1] * t;
        if (py < tl_waves_height(waves, px, pz, s->time, s->quality.march_octaves))
            return t;
    }
    return until;
}

/* A steep sea (twice the default's slopes) seen at grazing angles, over
 * the full-detail surface the CPU mirror computes, with steps to spare;
 * the march's own hits (no polish onto the normals' surface). */
static void steep_sea(tl_scene *s)
{
    tl_scene_defaults(s);
    s->width = 96;
    s->height = 54;
    s->time = 3.0;
    s->camera.pitch = -4.0 * M_PI / 180.0;
    s->ocean.depth = 2.0;
    s->quality.lod = false;
    s->quality.march_steps = 400;
    s->quality.polish = false;
}

/* The march's over-relaxation (quality.march_relax) never steps through a
 * wave: along each water pixel's ray the CPU mirror finds the first point
 * below the surface (5 cm apart) no nearer than the hit the GPU reports.
 * Grazing rays over full-detail water, at the presets' factor and at the
 * knob's largest. */
static void test_relaxed_march(tl_renderer *r)
{
    const double factors[] = {1.3, 2.0};
    for (int k = 0; k < 2; k++) {
        /* Without the check that takes a relaxed step back, 150 of these
         * rays step through a crest at 2.0; at the default's depth of
         * 1 m, none. */
        tl_scene s;
        steep_sea(&s);
        s.quality.march_relax = factors[k];
        s.quality.march_prepass = false; /* the march alone */
        tl_frame f;
        if (render(r, &s, &f))
            return;
        tl_waves waves;
        tl_waves_init(&waves, &s.ocean);
        int checked = 0, through = 0;
        for (int y = 0; y < s.height; y++)
            for (int x = 0; x < s.width; x++) {
                double d = f.depth[(size_t)y * s.width + x];
                if (d > 40.0)
                    continue; /* sky, and far water the walk would take long over */
                through += first_crossing(&s, &waves, x, y, d - 0.25) < d - 0.25;
                checked++;
            }
        printf("march_relax %.1f: %d of %d water rays cross the surface 0.25 m or more before "
               "their hit\n",
               factors[k], through, checked);
        CHECK(checked > 1500);
        CHECK(through == 0);
        tl_frame_free(&f);
    }
}

/* How deep along pixel (x, y)'s ray, from `from` to `to`, the CPU's
 * surface rises above the ray: how deep a crest the ray clips there is. */
static double clip_depth(const tl_scene *s, const tl_waves *waves, int x, int y, double from,
                         double to)
{
    double ray[3], deepest = 0.0;
    pixel_ray(s, x, y, ray);
    for (double t = from; t < to; t += 0.01) {
        const double *c = s->camera.position;
        double h = tl_waves_height(waves, c[0] + ray[0] * t, c[2] + ray[2] * t, s->time,
                                   s->quality.march_octaves);
        deepest = fmax(deepest, h - (c[1] + ray[1] * t));
    }
    return deepest;
}

/* The march prepass (quality.march_prepass): pixels that start from their
 * neighbours' distances find the same first crossing of the surface as the
 * march alone. On a steep sea seen at grazing angles, against the CPU's
 * walk along each ray, without the budget (quality.prepass_budget 0): at
 * most one hit in 1000 lies 0.25 m or more past the first crossing, past a
 * crest it clips by under a tenth of a pixel (where the four neighbours
 * agree, the walk splits their bracket at their blend and searches the
 * half that holds a crossing: one such ray of 2588 here, 0.03 pixel deep),
 * and the hits agree with the march alone's to its hit epsilon. With a
 * preset's budget (final's 8 steps, draft's and preview's 6), a ray may
 * pass a crest tip it clips after its budget's steps: few do, and by less
 * than a pixel (on this sea, twice the default's slopes, 59 and 79 rays of
 * about 2570, 0.95 of a pixel deep at most; with 12 steps 37, 0.71). */
static void test_march_prepass(tl_renderer *r)
{
    tl_scene s;
    steep_sea(&s);
    /* The budgets to walk with: none, final's, and the faster presets'. */
    int budgets[3] = {0, 0, 0};
    const char *const presets[2] = {"final", "preview"};
    for (int i = 0; i < 2; i++) {
        tl_quality q;
        CHECK(tl_quality_preset(presets[i], &q, NULL) == 0);
        budgets[i + 1] = q.prepass_budget;
        CHECK(q.prepass_budget > 0);
    }
    s.quality.march_prepass = false;
    tl_frame alone, hinted;
    if (render(r, &s, &alone))
        return;
    tl_waves waves;
    tl_waves_init(&waves, &s.ocean);
    const double pixel = 2.0 * tan(0.5 * s.camera.vfov) / s.height; /* radians */
    for (int pass = 0; pass < 3; pass++) {
        s.quality.march_prepass = true;
        s.quality.prepass_budget = budgets[pass];
        if (render(r, &s, &hinted))
            break;
        int checked = 0, through = 0, moved = 0, sky = 0;
        double deepest = 0.0; /* of the crests passed, in pixels at their distance */
        for (int y = 0; y < s.height; y++)
            for (int x = 0; x < s.width; x++) {
                size_t at = (size_t)y * s.width + x;
                double a = alone.depth[at], d = hinted.depth[at];
                sky += (a >= TL_FRAME_SKY_DEPTH) != (d >= TL_FRAME_SKY_DEPTH);
                if (d > 40.0)
                    continue;
                double first = first_crossing(&s, &waves, x, y, d - 0.25);
                if (first < d - 0.25) {
                    through++;
                    deepest =
                        fmax(deepest, clip_depth(&s, &waves, x, y, first, d) / (pixel * first));
                }
                /* The march alone stops within its epsilon above the surface,
                 * which along a ray at a few degrees is up to ~0.2 m. */
                moved += fabs(a - d) > 0.02 * a + 0.25;
                checked++;
            }
        printf("march prepass, budget %d: %d of %d water rays hit 0.25 m or more past the first "
               "crossing (the deepest crest passed %.2f pixel), %d moved from the march alone's "
               "hit, %d changed between water and sky\n",
               s.quality.prepass_budget, through, checked, deepest, moved, sky);
        CHECK(checked > 1500);
        CHECK(sky == 0);
        if (pass == 0) {
            CHECK(through <= checked / 1000);
            CHECK(deepest < 0.1);
            CHECK(moved <= checked / 100);
        } else {
            CHECK(through <= checked / 25);
            CHECK(deepest < 1.0);
        }
        tl_frame_free(&hinted);
    }
    tl_frame_free(&alone);
}

/* Progressive refinement (tl_renderer_refine, the paused preview): samples
 * 0..7 added one at a time into a running mean give the frame one pass of
 * all 8 gives, colour and display; depth is sample 0's. */
static void test_refine(tl_renderer *r)
{
    tl_scene s;
    small_scene(&s);
    s.quality.spp = 8;
    tl_frame whole, steps;
    if (render(r, &s, &whole))
        return;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_frame_alloc(&steps, s.width, s.height, &err) == 0);
    int rc = tl_renderer_begin(r, u.width, u.height, u.out_width, u.out_height, &err);
    for (int k = 0; !rc && k < 8; k++)
        rc = tl_renderer_refine(r, &u, k, &err);
    const tl_display_settings settings = tl_display_of(&u);
    if (!rc)
        rc = tl_renderer_finish(r, &settings, TL_PLANES_ALL, &steps, &err);
    CHECK(rc == 0);
    CHECK(tl_renderer_refine(r, &u, 8, &err) != 0); /* past the last sample */
    size_t n = (size_t)s.width * s.height;
    double color = 0.0, display = 0.0;
    for (size_t i = 0; i < n * 4; i++) {
        color = fmax(color, fabs(steps.color[i] - whole.color[i]) / fmax(whole.color[i], 1e-3));
        display = fmax(display, fabs(steps.display[i] - whole.display[i]));
    }
    printf("8 samples refined one by one against one pass: colour %.2g (relative), display "
           "%.2g\n",
           color, display);
    CHECK(color <= 1e-5);
    CHECK(display <= 1e-5);
    tl_frame_free(&whole);
    tl_frame_free(&steps);
}

/* A renderer on the embedded shaders written into `dir`, with ocean.frag's
 * sample trace line replaced by `trace`; NULL if that fails. */
static const char TRACE_LINE[] = "        vec3 c = trace(camera_ray(g_pixel), dist);\n";

static tl_renderer *patched_renderer(const char *dir, const char *trace)
{
    for (int i = 0; i < tl_embedded_shader_count; i++) {
        const tl_shader_file *f = &tl_embedded_shaders[i];
        char path[1200];
        snprintf(path, sizeof path, "%s/%s", dir, f->name);
        FILE *out = fopen(path, "w");
        if (!out)
            return NULL;
        const char *at = strcmp(f->name, "ocean.frag") == 0 ? strstr(f->text, TRACE_LINE) : NULL;
        if (at) {
            fwrite(f->text, 1, (size_t)(at - f->text), out);
            fputs(trace, out);
            fputs(at + strlen(TRACE_LINE), out);
        } else {
            fputs(f->text, out);
        }
        if (fclose(out) || (strcmp(f->name, "ocean.frag") == 0 && !at))
            return NULL;
    }
    tl_shader_lib lib;
    tl_error err;
    tl_error_clear(&err);
    tl_renderer *r = NULL;
    if (tl_shader_lib_from_dir(&lib, dir, &err) || tl_renderer_create(&r, &lib, &err)) {
        fprintf(stderr, "patched renderer: %s\n", err.message);
        return NULL;
    }
    return r;
}

/* Frame `s` through `path`: 0 one pass of all samples, 1 a pass per sample
 * (as with the boat), 2 the preview's refinement, a sample at a time. */
static int render_path(tl_renderer *r, const tl_scene *s, int path, tl_frame *f)
{
    tl_frame_uniforms u;
    gl_test_prepare(r, s, &u);
    tl_error err;
    tl_error_clear(&err);
    if (tl_frame_alloc(f, s->width, s->height, &err))
        return 1;
    int rc = tl_renderer_begin(r, u.width, u.height, u.out_width, u.out_height, &err);
    for (int k = 0; !rc && k < (path ? u.spp : 1); k++)
        rc = path == 0   ? tl_renderer_accumulate(r, &u, 1.0f, 1, &err)
             : path == 1 ? tl_renderer_accumulate_sample(r, &u, 1.0f / (float)u.spp, 1, k, &err)
                         : tl_renderer_refine(r, &u, k, &err);
    const tl_display_settings display = tl_display_of(&u);
    if (!rc)
        rc = tl_renderer_finish(r, &display, TL_PLANES_ALL, f, &err);
    if (rc)
        fprintf(stderr, "render path %d: %s\n", path, err.message);
    return rc;
}

/* A non-finite sample is dropped alone, whichever pass takes it: with every
 * odd sample made NaN, each pixel is the mean of its even samples, as when
 * every odd sample retraces the even one before it. (A pass per sample and
 * the refinement once averaged a bad sample in as black.) */
static void test_bad_samples(tl_renderer *plain)
{
    char nan_dir[] = "/tmp/tl_nan_XXXXXX", dup_dir[] = "/tmp/tl_dup_XXXXXX";
    CHECK(mkdtemp(nan_dir) && mkdtemp(dup_dir));
    tl_renderer *nan =
        patched_renderer(nan_dir, "        vec3 c = trace(camera_ray(g_pixel), dist);\n"
                                  "        if (s % 2 == 1)\n"
                                  "            c = vec3(uintBitsToFloat(0x7fc00000u));\n");
    tl_renderer *dup =
        patched_renderer(dup_dir, "        if (s % 2 == 1)\n"
                                  "            g_pixel = gl_FragCoord.xy + sample_offset(s - 1);\n"
                                  "        vec3 c = trace(camera_ray(g_pixel), dist);\n");
    CHECK(nan && dup);
    tl_scene s;
    small_scene(&s);
    s.quality.spp = 4;
    const char *const names[] = {"one pass", "a pass per sample", "refinement"};
    for (int path = 0; nan && dup && path < 3; path++) {
        tl_frame a = {0}, b = {0}, all = {0};
        if (render_path(nan, &s, path, &a) || render_path(dup, &s, path, &b) ||
            render_path(plain, &s, path, &all)) {
            CHECK(!"render");
            tl_frame_free(&a);
            tl_frame_free(&b);
            tl_frame_free(&all);
            break;
        }
        size_t n = (size_t)s.width * s.height * 4;
        double color = 0.0, display = 0.0, patched = 0.0;
        int finite = 1;
        for (size_t i = 0; i < n; i++) {
            finite &= isfinite(a.color[i]) && isfinite(a.display[i]);
            color = fmax(color, fabs(a.color[i] - b.color[i]) / fmax(b.color[i], 1e-3));
            display = fmax(display, fabs(a.display[i] - b.display[i]));
            patched = fmax(patched, fabs(b.display[i] - all.display[i]));
        }
        printf("%s, odd samples NaN against odd samples repeated: colour %.2g (relative), "
               "display %.2g; all samples differ by %.2g\n",
               names[path], color, display, patched);
        CHECK(finite);
        CHECK(color <= 1e-4);
        CHECK(display <= 1e-4);
        CHECK(patched > 0.01); /* the patch took: the even samples alone are another image */
        tl_frame_free(&a);
        tl_frame_free(&b);
        tl_frame_free(&all);
    }
    if (nan)
        tl_renderer_destroy(nan);
    if (dup)
        tl_renderer_destroy(dup);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s %s", nan_dir, dup_dir);
    CHECK(system(cmd) == 0);
}

/* Whether every ray through row `row` (counted from the bottom, as GL
 * does) rises, wherever in its pixel a sample lies: its four corners'
 * rays, which bound the rest. */
static int row_rises(const tl_scene *s, int row)
{
    double right[3], up[3], fwd[3];
    tl_scene_camera_basis(&s->camera, right, up, fwd);
    double th = tan(0.5 * s->camera.vfov), aspect = (double)s->width / s->height;
    for (int c = 0; c < 4; c++) {
        double nx = c & 1 ? 1.0 : -1.0, ny = (row + (c & 2 ? 1.0 : 0.0)) / s->height * 2.0 - 1.0;
        if (!(fwd[1] + nx * aspect * th * right[1] + ny * th * up[1] > 0.0))
            return 0;
    }
    return 1;
}

/* The rows above the horizon are shaded with the sky alone
 * (tl_frame_uniforms.plan.sky_rows): every ray there rises, nearly every row
 * that rises is counted, and the frame is bit for bit the frame the march
 * gives everywhere: with and without the prepass, supersampled, rolled,
 * and at half the render size. A camera under the water, upside down or
 * looking straight down gets none. */
static void test_sky_rows(tl_renderer *r)
{
    const char *const names[] = {"final", "roll 20 deg", "4 spp, no prepass", "draft"};
    for (int k = 0; k < 4; k++) {
        tl_scene s;
        small_scene(&s);
        s.camera.pitch = 0.1;
        if (k == 1)
            s.camera.roll = 0.35;
        if (k == 2) {
            s.quality.spp = 4;
            s.quality.march_prepass = false;
        }
        tl_error err;
        tl_error_clear(&err);
        if (k == 3)
            CHECK(tl_quality_preset("draft", &s.quality, &err) == 0);
        tl_frame_uniforms u;
        gl_test_prepare(r, &s, &u);
        tl_scene at_render = s; /* rows of the render target, not the output */
        at_render.width = u.width;
        at_render.height = u.height;
        int rising = 0;
        for (int row = u.height - 1; row >= 0 && row_rises(&at_render, row); row--)
            rising++;
        int wrong = 0;
        for (int row = u.height - u.plan.sky_rows; row < u.height; row++) /* GL's rows */
            wrong += !row_rises(&at_render, row);
        tl_frame split, marched;
        CHECK(tl_frame_alloc(&split, s.width, s.height, &err) == 0);
        CHECK(tl_frame_alloc(&marched, s.width, s.height, &err) == 0);
        CHECK(tl_renderer_render(r, &u, &split, &err) == 0);
        const int sky_rows = u.plan.sky_rows;
        u.plan.sky_rows = 0;
        CHECK(tl_renderer_render(r, &u, &marched, &err) == 0);
        size_t n = (size_t)s.width * s.height;
        int same = memcmp(split.color, marched.color, n * 4 * sizeof(float)) == 0 &&
                   memcmp(split.display, marched.display, n * 4 * sizeof(float)) == 0 &&
                   memcmp(split.depth, marched.depth, n * sizeof(float)) == 0;
        printf("sky rows, %s: %d of %d rows (%d rise), %d wrong; frame %s the march's\n", names[k],
               sky_rows, u.height, rising, wrong, same ? "is" : "is not");
        CHECK(wrong == 0);
        CHECK(sky_rows >= rising - 1 && sky_rows > u.height / 4);
        CHECK(same);
        tl_frame_free(&split);
        tl_frame_free(&marched);
    }
    /* The sky's own program draws exactly those rows: marked, they are
     * the top sky_rows rows of the frame and no others. */
    char dir[] = "/tmp/tl_sky_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    tl_renderer *marked =
        patched_renderer(dir, "        vec3 c = trace(camera_ray(g_pixel), dist);\n"
                              "#ifdef TL_SKY_ONLY\n"
                              "        c = vec3(1000.0, 0.0, 0.0);\n"
                              "#endif\n");
    CHECK(marked != NULL);
    if (marked) {
        tl_scene s;
        small_scene(&s);
        s.camera.pitch = 0.1;
        s.quality.spp = 4;
        tl_frame_uniforms u;
        gl_test_prepare(marked, &s, &u);
        tl_frame f;
        tl_error err;
        tl_error_clear(&err);
        CHECK(tl_frame_alloc(&f, s.width, s.height, &err) == 0);
        CHECK(tl_renderer_render(marked, &u, &f, &err) == 0);
        int misplaced = 0; /* frame rows run top down */
        for (int y = 0; y < s.height; y++)
            for (int x = 0; x < s.width; x++)
                misplaced +=
                    (f.color[((size_t)y * s.width + x) * 4] == 1000.0f) != (y < u.plan.sky_rows);
        printf("sky rows, marked: %d pixels misplaced\n", misplaced);
        CHECK(u.plan.sky_rows > 0 && misplaced == 0);
        tl_frame_free(&f);
        tl_renderer_destroy(marked);
    }
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
    const char *const none[] = {"under the water", "upside down", "looking down"};
    for (int k = 0; k < 3; k++) {
        tl_scene s;
        small_scene(&s);
        if (k == 0)
            s.camera.position[1] = -2.0;
        if (k == 1)
            s.camera.roll = M_PI;
        if (k == 2)
            s.camera.pitch = -1.2;
        tl_frame_uniforms u;
        gl_test_prepare(r, &s, &u);
        printf("sky rows, %s: %d\n", none[k], u.plan.sky_rows);
        CHECK(u.plan.sky_rows == 0);
    }
}

int main(void)
{
    test_device_platform_extensions();
    test_shader_log_names();
    test_defines_fit();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_probe(r);
    test_sky_and_water(r);
    test_sun_disc(r);
    test_pixel_filter(r);
    test_upscale_holds(r);
    test_relaxed_march(r);
    test_march_prepass(r);
    test_refine(r);
    test_bad_samples(r);
    test_sky_rows(r);
    test_queued_readback(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
