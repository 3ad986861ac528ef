/* The light on the giant wave, on the GPU (llvmpipe on CI): the light
 * through its crest (fading with the wave, coloured by the water it
 * crossed, netted by the far side's caustics), the lip against the sky with normals met from
 * behind, and the crest's shadow against its double CPU mirror, and the bubbles the broken crest
 * leaves behind it. */
#include <math.h>
#include <stdlib.h>

#include "optics/tl_optics.h"
#include "tl_giant_test.h"
#include "waves/tl_caustics.h"

/* facing_scene backlit by a low sun at `fade`. */
static void glow_scene(tl_scene *s, double fade)
{
    facing_scene(s);
    s->sun.azimuth = 0.0; /* behind the wave */
    s->sun.elevation = 0.15;
    s->giant.fade = fade;
}

/* `s` rendered with the light through the crest (`lit`) and without it
 * (`dark`); non-zero if a render failed (then neither frame holds
 * anything). */
static int glow_render(tl_renderer *r, const tl_scene *s, tl_frame *lit, tl_frame *dark)
{
    tl_scene off = *s;
    off.giant.scatter = 0.0;
    if (render(r, s, lit))
        return 1;
    if (render(r, &off, dark)) {
        tl_frame_free(lit);
        return 1;
    }
    return 0;
}

/* glow_scene at `fade` (into `s`), rendered by glow_render. */
static int glow_frames(tl_renderer *r, double fade, tl_scene *s, tl_frame *lit, tl_frame *dark)
{
    glow_scene(s, fade);
    return glow_render(r, s, lit, dark);
}

/* The linear colour pixel i gains from giant.scatter, and its luminance. */
static void glow_at(const tl_frame *lit, const tl_frame *dark, size_t i, double rgb[3])
{
    for (int c = 0; c < 3; c++)
        rgb[c] = lit->color[4 * i + c] - dark->color[4 * i + c];
}

static double glow_luminance(const double rgb[3])
{
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

/* The light through the crest at `fade`: the linear luminance a frame
 * gains from giant.scatter, averaged over the pixels where it is at least
 * 1% of its largest; -1 if a render failed. */
static double crest_glow(tl_renderer *r, double fade)
{
    tl_scene s;
    tl_frame a, b;
    if (glow_frames(r, fade, &s, &a, &b))
        return -1.0;
    size_t n = (size_t)s.width * (size_t)s.height;
    double peak = 0.0, sum = 0.0, rgb[3];
    int count = 0;
    for (int pass = 0; pass < 2; pass++)
        for (size_t i = 0; i < n; i++) {
            glow_at(&a, &b, i, rgb);
            double glow = glow_luminance(rgb);
            if (pass == 0)
                peak = fmax(peak, glow);
            else if (glow >= 0.01 * peak) {
                sum += glow;
                count++;
            }
        }
    tl_frame_free(&a);
    tl_frame_free(&b);
    return count > 0 ? sum / count : 0.0;
}

/* The light through the crest takes the colour of the water it crossed:
 * under the lip, where the crest is thin, more of the sun's red comes
 * through than lower down the face, where it is deeper green (a single
 * colour gave a flat, saturated band). Over the rows the glow lights, the
 * top quarter's red-to-green ratio is well above the bottom quarter's; and
 * the glow is graded, not cut off: it still lights the rows well below
 * its brightest one. */
static void test_glow_graded(tl_renderer *r)
{
    tl_scene s;
    tl_frame a, b;
    if (glow_frames(r, 1.0, &s, &a, &b)) {
        CHECK(0);
        return;
    }
    double peak = 0.0, rgb[3];
    for (size_t i = 0; i < (size_t)s.width * (size_t)s.height; i++) {
        glow_at(&a, &b, i, rgb);
        peak = fmax(peak, glow_luminance(rgb));
    }
    /* The band: rows (top first) with a sixteenth of their pixels at 1%
     * of the peak or more (a few ripples' facets on the sea in front,
     * turned toward the sun, are not the band). */
    int first = -1, last = -1;
    for (int y = 0; y < s.height; y++) {
        int lit = 0;
        for (int x = 0; x < s.width; x++) {
            glow_at(&a, &b, (size_t)y * s.width + x, rgb);
            lit += glow_luminance(rgb) >= 0.01 * peak;
        }
        if (lit * 16 >= s.width) {
            first = first < 0 ? y : first;
            last = y;
        }
    }
    double sums[2][3] = {{0}};
    int quarter = (last - first + 1) / 4;
    for (int y = first; quarter > 0 && y <= last; y++) {
        int part = y < first + quarter ? 0 : y > last - quarter ? 1 : -1;
        for (int x = 0; part >= 0 && x < s.width; x++) {
            glow_at(&a, &b, (size_t)y * s.width + x, rgb);
            for (int c = 0; c < 3; c++)
                sums[part][c] += fmax(rgb[c], 0.0);
        }
    }
    double top_ratio = sums[0][0] / fmax(sums[0][1], 1e-12);
    double low_ratio = sums[1][0] / fmax(sums[1][1], 1e-12);
    printf("light through the crest: rows %d-%d, red/green top quarter %.3f, bottom %.3f\n", first,
           last, top_ratio, low_ratio);
    CHECK(quarter >= 2);
    CHECK(top_ratio > 1.5 * low_ratio);
    tl_frame_free(&a);
    tl_frame_free(&b);
}

/* The light through the crest is uneven along it (a displacement noise,
 * as seed 003 weights its displacement by one): along the row it lights
 * most, the glow's luminance has a standard deviation above 0.18 of its
 * mean (measured 0.24; the even band before had 0.12, from the ripples'
 * refraction alone). */
static void test_glow_uneven(tl_renderer *r)
{
    tl_scene s;
    tl_frame a, b;
    if (glow_frames(r, 1.0, &s, &a, &b)) {
        CHECK(0);
        return;
    }
    double rgb[3], best = 0.0;
    int row = -1;
    for (int y = 0; y < s.height; y++) {
        double sum = 0.0;
        for (int x = 0; x < s.width; x++) {
            glow_at(&a, &b, (size_t)y * s.width + x, rgb);
            sum += glow_luminance(rgb);
        }
        if (sum > best) {
            best = sum;
            row = y;
        }
    }
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    /* The middle half of the row: the wave's ends taper the glow anyway. */
    for (int x = s.width / 4; row >= 0 && x < 3 * s.width / 4; x++) {
        glow_at(&a, &b, (size_t)row * s.width + x, rgb);
        double l = glow_luminance(rgb);
        sum += l;
        sum2 += l * l;
        n++;
    }
    double mean = n ? sum / n : 0.0, sd = n ? sqrt(fmax(sum2 / n - mean * mean, 0.0)) : 0.0;
    printf("light through the crest along row %d: mean %.4g, sd %.4g (%.2f of the mean)\n", row,
           mean, sd, mean > 0.0 ? sd / mean : 0.0);
    CHECK(mean > 0.0);
    CHECK(sd > 0.18 * mean);
    tl_frame_free(&a);
    tl_frame_free(&b);
}

/* The crest's caustics (giant.caustics, feature `crest caustics`): the
 * ripples on the crest's far side focus the light through it into a web.
 * Over the glow's pixels, the glow with them over the glow without them
 * keeps the light on average (the mean ratio within 15% of 1); it varies
 * from pixel to pixel where the light crossed little water (the top third
 * of the glowing rows, under the crest: a standard deviation above 0.04
 * in this small frame, whose pixels average the web)
 * and far less where it crossed more (the bottom third: under half the
 * top's; TL_CAUSTIC_CREST_REACH); the web rides the wave's water, drawn
 * out down the face, so it changes less from row to row than from column
 * to column (in the still sea's coordinates, with giant.ride 0, the
 * face's foreshortening made it the other way round); at 0 the feature
 * is not compiled in. */
struct ratio_stats {
    double sum, sum2;
    int n;
};

static void ratio_add(struct ratio_stats *st, double v)
{
    st->sum += v;
    st->sum2 += v * v;
    st->n++;
}

static double ratio_sd(const struct ratio_stats *st)
{
    if (!st->n)
        return 0.0;
    double mean = st->sum / st->n;
    return sqrt(fmax(st->sum2 / st->n - mean * mean, 0.0));
}

static void test_glow_caustics(tl_renderer *r)
{
    tl_scene s;
    tl_frame a, b, flat;
    glow_scene(&s, 1.0);
    s.giant.caustics = 1.0;
    if (glow_render(r, &s, &a, &b)) {
        CHECK(0);
        return;
    }
    tl_scene off = s;
    off.giant.caustics = 0.0;
    tl_waves w;
    tl_frame_uniforms u;
    gl_test_uniforms(&s, &w, &u);
    CHECK(u.features & TL_FEATURE_GIANT_CAUSTICS);
    gl_test_uniforms(&off, &w, &u);
    CHECK(!(u.features & TL_FEATURE_GIANT_CAUSTICS));
    CHECK(u.features & TL_FEATURE_GIANT_GLOW);
    if (render(r, &off, &flat)) {
        CHECK(0);
        tl_frame_free(&a);
        tl_frame_free(&b);
        return;
    }
    double rgb[3], peak = 0.0;
    size_t count = (size_t)s.width * s.height;
    for (size_t i = 0; i < count; i++) {
        glow_at(&flat, &b, i, rgb);
        peak = fmax(peak, glow_luminance(rgb));
    }
    double *ratio = malloc(count * sizeof *ratio);
    struct ratio_stats all = {0}, top = {0}, bottom = {0};
    int first_row = s.height, last_row = -1;
    for (size_t i = 0; ratio && i < count; i++) {
        glow_at(&flat, &b, i, rgb);
        double without = glow_luminance(rgb);
        ratio[i] = NAN;
        if (without < 0.1 * peak)
            continue;
        glow_at(&a, &b, i, rgb);
        ratio[i] = glow_luminance(rgb) / without;
        ratio_add(&all, ratio[i]);
        int row = (int)(i / (size_t)s.width);
        first_row = row < first_row ? row : first_row;
        last_row = row > last_row ? row : last_row;
    }
    /* Rows top first: the crest's top is the first glowing row. */
    int third = (last_row - first_row + 1) / 3;
    for (size_t i = 0; ratio && i < count; i++) {
        int row = (int)(i / (size_t)s.width);
        if (isnan(ratio[i]))
            continue;
        if (row < first_row + third)
            ratio_add(&top, ratio[i]);
        else if (row > last_row - third)
            ratio_add(&bottom, ratio[i]);
    }
    /* Neighbours down the face (rows) and along the crest (columns). */
    double down = 0.0, along = 0.0;
    int pairs = 0;
    for (int y = 0; ratio && y + 1 < s.height; y++)
        for (int x = 0; x + 1 < s.width; x++) {
            double r0 = ratio[y * s.width + x], r1 = ratio[(y + 1) * s.width + x],
                   r2 = ratio[y * s.width + x + 1];
            if (isnan(r0) || isnan(r1) || isnan(r2))
                continue;
            down += fabs(r1 - r0);
            along += fabs(r2 - r0);
            pairs++;
        }
    free(ratio);
    double mean = all.n ? all.sum / all.n : 0.0;
    printf("crest caustics over %d glowing pixels (rows %d-%d): glow with them over without, "
           "mean %.3f, sd %.3f; top third sd %.3f (%d), bottom third %.3f (%d); mean step down "
           "the face %.3f, along the crest %.3f\n",
           all.n, first_row, last_row, mean, ratio_sd(&all), ratio_sd(&top), top.n,
           ratio_sd(&bottom), bottom.n, pairs ? down / pairs : 0.0, pairs ? along / pairs : 0.0);
    CHECK(all.n > 100 && top.n > 30 && bottom.n > 30);
    CHECK(fabs(mean - 1.0) < 0.15);
    CHECK(ratio_sd(&top) > 0.04);
    CHECK(ratio_sd(&bottom) < 0.5 * ratio_sd(&top));
    CHECK(pairs > 100 && down < along);
    tl_frame_free(&a);
    tl_frame_free(&b);
    tl_frame_free(&flat);
}

/* The crest's caustics on the GPU (caustic_crest) against the CPU's
 * double (tl_caustic_crest), near the origin and far out at a late time;
 * and giant.caustics 0 leaves the light as it is. */
static void test_crest_caustics_probe(tl_renderer *r, double x, double z, double t)
{
    enum { N = 512 };
    tl_scene s;
    facing_scene(&s);
    s.sun.azimuth = 0.0;
    s.sun.elevation = 0.2;
    s.camera.position[0] = x;
    s.camera.position[2] = z;
    s.time = t;
    s.giant.arrival = t;
    s.giant.caustics = 0.4;
    tl_waves w;
    tl_frame_uniforms u;
    gl_test_uniforms(&s, &w, &u);
    CHECK(u.features & TL_FEATURE_GIANT_CAUSTICS);
    static float in[4 * N], out[4 * N];
    const float paths[] = {0.3f, 1.0f, 3.0f, 8.0f, 20.0f};
    srand(11);
    for (int i = 0; i < N; i++) {
        in[4 * i] = (float)(-15.0 + 30.0 * rand() / RAND_MAX);
        in[4 * i + 1] = (float)(-15.0 + 30.0 * rand() / RAND_MAX);
        in[4 * i + 2] = paths[i % 5];
        in[4 * i + 3] = i % 10 < 5 ? 0.0f : 0.05f;
    }
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe4(r, &u, 21, in, N, s.quality.normal_octaves, out, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    tl_caustic_light l;
    tl_scene_sun_direction(&s.sun, l.sun_dir);
    l.ior = s.water.ior;
    l.scattering = s.water.scattering;
    tl_optics_sun_in_water(l.sun_dir, l.ior, l.sun_water);
    int close = 0;
    double worst = 0.0, spread = 0.0;
    for (int i = 0; i < N; i++) {
        double want = tl_caustic_crest(&w, &l, x + in[4 * i], z + in[4 * i + 1], in[4 * i + 2], t,
                                       s.quality.normal_octaves, in[4 * i + 3], s.giant.caustics);
        double d = fabs(out[4 * i] - want) / fmax(want, 1.0);
        worst = fmax(worst, d);
        close += d <= 0.01;
        spread = fmax(spread, fabs(want - 1.0));
    }
    printf("crest caustics at (%g, %g) t = %g s: GPU within 1%% of CPU at %d of %d points, worst "
           "%.3g; largest departure from 1: %.2f\n",
           x, z, t, close, N, worst, spread);
    CHECK(close >= N * 98 / 100);
    CHECK(worst <= 0.25);
    CHECK(spread > 0.3);
    CHECK(tl_caustic_crest(&w, &l, x, z, 3.0, t, s.quality.normal_octaves, 0.0, 0.0) == 1.0);
}

/* The crest's inner light fades with the wave: a wave fading into a low
 * swell kept its full glow over the swell's whole top (voyage's last
 * frames showed a flat teal field). At fade 0.3 the glow per lit pixel is
 * at most 0.4 of a full wave's (0.3 by the fade, a little less or more as
 * the lower crest moves the surface less and spreads over other pixels). */
static void test_glow_fades(tl_renderer *r)
{
    double full = crest_glow(r, 1.0), low = crest_glow(r, 0.3);
    printf("light through the crest, per lit pixel: fade 1 %.4g, fade 0.3 %.4g (%.2f)\n", full, low,
           low / full);
    CHECK(full > 1e-3);
    CHECK(low >= 0.0 && low <= 0.4 * full);
}

/* Of the columns whose top water pixel (the first below the sky) lies on
 * the wave, those where it is darker than half the pixel two rows below;
 * *columns gets how many columns have such a pixel. */
static int dark_lip_columns(const tl_frame *f, int w, int h, int *columns)
{
    int dark = 0;
    *columns = 0;
    for (int x = 0; x < w; x++)
        for (int y = 1; y + 2 < h; y++) {
            size_t k = (size_t)y * w + x;
            if (f->depth[k] == TL_FRAME_SKY_DEPTH)
                continue;
            if (f->depth[k - w] != TL_FRAME_SKY_DEPTH || f->depth[k] > 300.0f)
                break; /* not a silhouette against the sky, or the far sea */
            (*columns)++;
            dark += luminance(f->color + 4 * k) < 0.5 * luminance(f->color + 4 * (k + 2 * w));
            break;
        }
    return dark;
}

/* The top of the wave's silhouette, seen from the crest's height with the
 * sun behind it: the march lands a hair past the crest's top, where the
 * shading normal (finer octaves than the marched surface) faces away
 * from the ray. Reflected as it was, the ray turned steeply up into the
 * dark zenith: a row of blue dashes along the lip (voyage 180).
 * quality.facing_normals turns such a normal to face the ray, so the lip
 * mirrors the bright sky near the horizon. */
static void test_lip_facing(tl_renderer *r)
{
    tl_scene s;
    facing_scene(&s);
    s.width = 640;
    s.height = 384;
    s.camera.position[1] = 18.0;
    s.camera.position[2] = -60.0;
    s.camera.pitch = -0.09;
    s.giant.steepness = 0.7;
    s.giant.curve_strength = 0.6;
    s.sun.azimuth = 0.0; /* behind the wave */
    s.sun.elevation = 0.15;
    /* Most of those rays were ones that ran out of steps along the crest
     * and stopped there; since a step in the wave's box counts by its
     * share of an ocean step (march.glsl) they reach the surface with
     * final's 96, and 3 columns of 640 stay dark. 24 steps bring the
     * stopped rays back (77 columns), whose normals must still face. */
    s.quality.march_steps = 24;
    /* The surface alone: the spindrift's veil over the crest's top hides
     * the dashes as much with the normals turned as without. */
    s.giant.spray = 0.0;
    int dark[2], columns[2];
    for (int on = 0; on < 2; on++) {
        s.quality.facing_normals = on;
        tl_frame f;
        if (render(r, &s, &f)) {
            CHECK(0);
            return;
        }
        dark[on] = dark_lip_columns(&f, s.width, s.height, &columns[on]);
        tl_frame_free(&f);
    }
    printf("lip against the sky: dark top pixels in %d of %d columns facing, %d of %d not\n",
           dark[1], columns[1], dark[0], columns[0]);
    CHECK(columns[1] >= s.width / 2);
    CHECK(dark[0] >= 5);
    CHECK(dark[1] <= dark[0] / 5);
}

/* The scene's waves, its giant wave and the frame's uniforms: what the
 * probes against the double mirror need. */
static void prepare_wave(const tl_scene *s, tl_waves *w, tl_giant *g, tl_frame_uniforms *u)
{
    tl_waves_init(w, &s->ocean);
    tl_giant_prepare(g, &s->giant, s->time);
    tl_prepare_frame(s, w, u);
}

/* The crest's shadow (giant_sunlit, probe mode 7) against its double
 * mirror along the wave's centre line, and what it must be: with a low sun
 * behind a 20 m wave, the water in front of the crest is in its shadow out
 * to about height / tan(elevation) and in the sun beyond, and behind the
 * crest it is in the sun; with the sun in front of the wave the back near
 * the crest is in the shadow and the front in the sun; with the sun set,
 * nothing is shadowed (there is no sunlight to take away). */
static void test_sun_shadow(tl_renderer *r)
{
    const double cam[3] = {3.0, 6.0, -4.0}, elevation = 8.0 * M_PI / 180.0;
    const double azimuths[2] = {0.3 + M_PI, 0.3}; /* behind the wave, in front of it */
    enum { N = 64 };
    for (int k = 0; k < 3; k++) {
        tl_scene s;
        wave_scene(&s, 20.0, 10.0, cam);
        s.giant.fade = 1.0;
        s.sun.azimuth = azimuths[k == 1];
        s.sun.elevation = k == 2 ? -3.0 * M_PI / 180.0 : elevation;
        tl_waves w;
        tl_giant g;
        tl_frame_uniforms u;
        prepare_wave(&s, &w, &g, &u);
        double sun[3];
        tl_scene_sun_direction(&s.sun, sun);
        double crest = g.fade * g.curl / g.k; /* s of the crest line on the centre line */
        double reach = 20.0 / tan(elevation);
        /* s from 60 m behind the crest to 2.5 shadow lengths in front */
        float xz[2 * N], gpu[4 * N];
        double at[N];
        for (int i = 0; i < N; i++) {
            at[i] = crest - 60.0 + (60.0 + 2.5 * reach) * i / (N - 1);
            xz[2 * i] = (float)(g.origin[0] + g.dir[0] * at[i] - cam[0]);
            xz[2 * i + 1] = (float)(g.origin[1] + g.dir[1] * at[i] - cam[2]);
        }
        tl_error err;
        tl_error_clear(&err);
        CHECK(tl_renderer_probe(r, &u, 7, xz, N, s.quality.march_octaves, gpu, &err) == 0);
        /* the least and most sun seen in front of the crest (5 m to half
         * the shadow's length), and behind it (5 to 40 m) */
        double worst = 0.0, front_min = 1.0, front_max = 0.0, back_min = 1.0, back_max = 0.0;
        double front_far = 0.0;
        for (int i = 0; i < N; i++) {
            double x = cam[0] + (double)xz[2 * i], z = cam[2] + (double)xz[2 * i + 1];
            double y = tl_waves_surface_height(&w, &g, x, z, s.time, s.quality.march_octaves,
                                               s.quality.giant_iterations);
            double cpu = tl_giant_sunlit(&g, x, z, y, sun);
            worst = fmax(worst, fabs(cpu - gpu[4 * i]));
            double ahead = at[i] - crest, lit = gpu[4 * i];
            if (ahead > 5.0 && ahead < 0.5 * reach) {
                front_min = fmin(front_min, lit);
                front_max = fmax(front_max, lit);
            }
            if (ahead < -5.0 && ahead > -40.0) {
                back_min = fmin(back_min, lit);
                back_max = fmax(back_max, lit);
            }
            if (ahead > 1.5 * reach)
                front_far = fmax(front_far, 1.0 - lit);
        }
        printf("sun shadow, sun %s: |gpu-cpu| <= %.4f; sun seen in front %.3f..%.3f, behind "
               "%.3f..%.3f, beyond 1.5 shadow lengths >= %.3f\n",
               k == 0   ? "behind the wave"
               : k == 1 ? "in front of it"
                        : "set",
               worst, front_min, front_max, back_min, back_max, 1.0 - front_far);
        CHECK(worst <= 0.02);
        CHECK(front_far <= 0.01);
        CHECK(k == 0 ? front_max <= 0.05 : front_min >= 0.99);
        CHECK(k == 1 ? back_max <= 0.05 : back_min >= 0.99);
        /* Beside the wave, 20 m past its width, there is no crest to cast
         * a shadow: the same line is in the sun on the GPU and the CPU
         * (the penumbra of a crest of no height shaded the troughs there). */
        const double beside =
            g.half_width + 20.0 +
            fabs(sun[0] * g.across[0] + sun[2] * g.across[1]) / hypot(sun[0], sun[2]) * 2.5 * reach;
        for (int i = 0; i < N; i++) {
            xz[2 * i] += (float)(g.across[0] * beside);
            xz[2 * i + 1] += (float)(g.across[1] * beside);
        }
        CHECK(tl_renderer_probe(r, &u, 7, xz, N, s.quality.march_octaves, gpu, &err) == 0);
        double beside_min = 1.0;
        for (int i = 0; i < N; i++) {
            double x = cam[0] + (double)xz[2 * i], z = cam[2] + (double)xz[2 * i + 1];
            beside_min = fmin(beside_min, fmin(gpu[4 * i], tl_giant_sunlit(&g, x, z, -1.0, sun)));
        }
        printf("  beside the wave: sun seen >= %.3f\n", beside_min);
        CHECK(beside_min >= 0.999);
    }
}

/* What the water mirrors past the crest (giant_clear, probe mode 24, rays
 * spread by 0.1 rad) against its double mirror: along the centre line
 * from 40 m behind the crest to 120 m in front of a 20 m wave, in twelve
 * directions around and at 3 to 30 degrees up, within 0.02; and what it
 * must be: 30 m in front of the crest, a ray toward the wave 5 degrees up
 * meets the crest (it sees under a twentieth of the sky), one away from it
 * sees all of it. */
static void test_mirror_clear(tl_renderer *r)
{
    const double cam[3] = {3.0, 6.0, -4.0};
    enum { N = 96 };
    tl_scene s;
    wave_scene(&s, 20.0, 10.0, cam);
    s.giant.fade = 1.0;
    tl_waves w;
    tl_giant g;
    tl_frame_uniforms u;
    prepare_wave(&s, &w, &g, &u);
    double crest = g.fade * g.curl / g.k;
    float in[4 * N], gpu[4 * N];
    double dirs[N][3];
    for (int i = 0; i < N; i++) {
        double at = crest - 40.0 + 160.0 * (i % 24) / 23.0;
        double el = (3.0 + 27.0 * ((i * 7) % 11) / 10.0) * M_PI / 180.0;
        double az = 2.0 * M_PI * (i % 12) / 12.0 + 0.1;
        if (i == N - 2 || i == N - 1) { /* toward the wave and away, 30 m in front */
            at = crest + 30.0;
            el = 5.0 * M_PI / 180.0;
            az = 0.0;
        }
        double toward = i == N - 2 ? -1.0 : 1.0; /* the wave lies toward -dir */
        double flat[2] = {cos(az) * g.dir[0] - sin(az) * g.across[0],
                          cos(az) * g.dir[1] - sin(az) * g.across[1]};
        if (i >= N - 2) {
            flat[0] = toward * g.dir[0];
            flat[1] = toward * g.dir[1];
        }
        dirs[i][0] = cos(el) * flat[0];
        dirs[i][1] = sin(el);
        dirs[i][2] = cos(el) * flat[1];
        in[4 * i + 0] = (float)(g.origin[0] + g.dir[0] * at - cam[0]);
        in[4 * i + 1] = (float)(g.origin[1] + g.dir[1] * at - cam[2]);
        in[4 * i + 2] = (float)dirs[i][0];
        in[4 * i + 3] = (float)dirs[i][2];
    }
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_renderer_probe4(r, &u, 24, in, N, s.quality.march_octaves, gpu, &err) == 0);
    double worst = 0.0, least = 1.0, most = 0.0, toward = 1.0, away = 0.0;
    for (int i = 0; i < N; i++) {
        double x = cam[0] + (double)in[4 * i], z = cam[2] + (double)in[4 * i + 1];
        double y = tl_waves_surface_height(&w, &g, x, z, s.time, s.quality.march_octaves,
                                           s.quality.giant_iterations);
        /* the direction as the GPU has it: y from the float x and z */
        double fx = in[4 * i + 2], fz = in[4 * i + 3];
        const double dir[3] = {fx, sqrt(fmax(1.0 - fx * fx - fz * fz, 0.0)), fz};
        double cpu = tl_giant_clear(&g, x, z, y, dir, 0.1);
        worst = fmax(worst, fabs(cpu - gpu[4 * i]));
        least = fmin(least, gpu[4 * i]);
        most = fmax(most, gpu[4 * i]);
        if (i == N - 2)
            toward = gpu[4 * i];
        if (i == N - 1)
            away = gpu[4 * i];
    }
    printf("mirrored sky past the crest: |gpu-cpu| <= %.4f over %d rays (%.3f .. %.3f); 30 m in "
           "front, toward the wave %.3f, away %.3f\n",
           worst, N, least, most, toward, away);
    CHECK(worst <= 0.02);
    CHECK(least < 0.05 && most > 0.99); /* the rays span hidden and clear */
    CHECK(toward < 0.05);
    CHECK(away > 0.99);
}

/* The small waves' steepening on the wave (probe mode 23) against its
 * double mirror, along the centre line from 60 m behind the crest to 60 m
 * in front, at (x, z) and time t: within 1e-4; 1 in the trough ahead and
 * off the wave; most near the crest, where it reaches its cap for a wave as
 * steep as this one (k·A = 1.4). */
static void test_short_wave_gain(tl_renderer *r, double x, double z, double t)
{
    enum { N = 64 };
    centre_line c;
    centre_line_open(&c, x, z, t);
    float xz[2 * N], gpu[4 * N];
    double at[N];
    for (int i = 0; i < N; i++) {
        at[i] = c.crest - 60.0 + 120.0 * i / (N - 1);
        /* the last point is 400 m beside the wave, off it */
        centre_line_point(&c.g, c.cam, at[i], i == N - 1 ? 400.0 : 0.0, xz + 2 * i);
    }
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe(r, &c.u, 23, xz, N, c.s.quality.march_octaves, gpu, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    double worst = 0.0, most = 0.0, most_at = 0.0, ahead = 0.0;
    for (int i = 0; i < N; i++) {
        tl_giant_sample smp;
        tl_giant_sample_at(&c.g, c.cam[0] + (double)xz[2 * i], c.cam[2] + (double)xz[2 * i + 1],
                           c.s.quality.giant_iterations, &smp);
        double cpu = tl_giant_short_wave_gain(&c.g, &smp);
        worst = fmax(worst, fabs(cpu - gpu[4 * i]));
        if (i < N - 1 && cpu > most) {
            most = cpu;
            most_at = at[i] - c.crest;
        }
        if (at[i] - c.crest > 40.0 && i < N - 1)
            ahead = fmax(ahead, fabs(cpu - 1.0));
    }
    printf("short-wave gain at (%g, %g), t = %g: |gpu-cpu| <= %.2e; most %.3f at %.1f m from "
           "the crest; ahead |gain-1| <= %.2e; off the wave %.6f\n",
           x, z, t, worst, most, most_at, ahead, gpu[4 * (N - 1)]);
    CHECK(worst <= 1e-4);
    CHECK(fabs(most - TL_GIANT_SHORT_WAVE_GAIN_MAX) <= 1e-9);
    CHECK(fabs(most_at) <= 10.0);
    CHECK(ahead <= 1e-9);
    CHECK(gpu[4 * (N - 1)] == 1.0f);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median of channel c (3: luminance) over the frame's lower half. */
static double lower_median(const tl_frame *f, int w, int h, int c)
{
    size_t n = (size_t)w * (size_t)(h - h / 2), k = 0;
    double *v = malloc(n * sizeof *v);
    if (!v)
        return -1.0;
    for (int y = h / 2; y < h; y++)
        for (int x = 0; x < w; x++) {
            const float *p = f->color + 4 * ((size_t)y * w + x);
            v[k++] = c < 3 ? p[c] : luminance(p);
        }
    qsort(v, n, sizeof *v, by_value);
    double m = v[n / 2];
    free(v);
    return m;
}

/* Behind a broken crest the water is full of bubbles that scatter light
 * back up; the web of spent foam on top covers only part of it. On dark
 * water facing away from a low sun the web alone read as cracks in mud
 * (giant_wave 310). Looking down on the trail, the water between the
 * veins (the lower half's median pixel) is more than twice as light with
 * foam as without, and what it gains is tinted toward giant.scatter_color
 * (green above red; without the bubbles the median rose 1.6 times, by the
 * web's warm, sunlit white). */
static void test_trail_aerated(tl_renderer *r)
{
    tl_scene s;
    facing_scene(&s);
    s.giant.steepness = 0.75; /* giant_wave.tl's breaking crest */
    s.giant.curve_strength = 0.6;
    s.time = 9.0; /* the crest has run 2 s (about 24 m) toward -z */
    s.camera.position[1] = 25.0;
    s.camera.position[2] = -10.0; /* above the back, looking down the trail */
    s.camera.pitch = -0.7;
    s.sun.azimuth = 0.0; /* in front of the camera, low */
    s.sun.elevation = 0.16;
    double median[2][4];
    for (int on = 0; on < 2; on++) {
        s.water.foam = on;
        tl_frame f;
        if (render(r, &s, &f)) {
            CHECK(0);
            return;
        }
        for (int c = 0; c < 4; c++)
            median[on][c] = lower_median(&f, s.width, s.height, c);
        tl_frame_free(&f);
    }
    double gain[3];
    for (int c = 0; c < 3; c++)
        gain[c] = median[1][c] - median[0][c];
    printf("trail's median pixel: luminance %.4g with foam, %.4g without; gain r %.3g g %.3g b "
           "%.3g\n",
           median[1][3], median[0][3], gain[0], gain[1], gain[2]);
    CHECK(median[0][3] > 0.0);
    CHECK(median[1][3] > 2.0 * median[0][3]);
    CHECK(gain[1] > 1.5 * fmax(gain[0], 0.0));
}

/* Stringers: a scripted crest that has not broken yet spills foam that
 * runs down its upper face in thin lines. Looking at the face from 50 m,
 * foam whitens some pixels of the face's upper half and none of its
 * lower half; once the crest is breaking there, the tumbling whitewater
 * takes their place (they fade with the break). */
static void test_stringers(tl_renderer *r)
{
    tl_scene s;
    facing_scene(&s);
    s.camera.position[2] = -50.0;
    s.camera.position[1] = 6.0;
    s.camera.pitch = 0.15;
    s.giant.breaking = true;
    s.giant.break_time = s.time + 5.0; /* not yet */
    tl_frame f[2];
    for (int on = 0; on < 2; on++) {
        s.water.foam = on;
        if (render(r, &s, &f[on])) {
            CHECK(0);
            if (on)
                tl_frame_free(&f[0]);
            return;
        }
    }
    /* The face's rows: where the frame without foam is water nearer than
     * the crest's far side (its depth under 80 m), split at their middle. */
    int top = -1, bottom = -1;
    for (int y = 0; y < s.height; y++)
        for (int x = 0; x < s.width; x++)
            if (f[0].depth[(size_t)y * s.width + x] < 80.0f) {
                if (top < 0)
                    top = y;
                bottom = y;
            }
    int upper = 0, lower = 0, middle = (top + bottom) / 2;
    for (int y = top; top >= 0 && y <= bottom; y++)
        for (int x = 0; x < s.width; x++) {
            size_t i = (size_t)y * s.width + x;
            if (f[0].depth[i] >= 80.0f)
                continue;
            double gain = 0.0;
            for (int c = 0; c < 3; c++)
                gain += (f[1].color[4 * i + c] - f[0].color[4 * i + c]) / 3.0;
            if (gain > 0.002)
                *(y < middle ? &upper : &lower) += 1;
        }
    printf("stringers before the break: %d foam pixels on the face's upper half (rows %d-%d), %d "
           "on its lower half\n",
           upper, top, middle, lower);
    CHECK(upper > 10);
    CHECK(lower == 0);
    tl_frame_free(&f[0]);
    tl_frame_free(&f[1]);
}

/* Mean and standard deviation of foam_detail (probe mode 8) over n points
 * along a 200 m line, for a pixel footprint of `footprint` metres; the
 * largest |value| in *peak. Non-zero if the probe failed. */
static int detail_stats(tl_renderer *r, const tl_frame_uniforms *u, double footprint, double *mean,
                        double *sd, double *peak)
{
    enum { N = 4096 };
    static float in[2 * N], out[4 * N];
    for (int i = 0; i < N; i++) {
        in[2 * i] = (float)(200.0 * i / N);
        in[2 * i + 1] = (float)footprint;
    }
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe(r, u, 8, in, N, 1, out, &err))
        return 1;
    double sum = 0.0, sum2 = 0.0;
    *peak = 0.0;
    for (int i = 0; i < N; i++) {
        sum += out[4 * i];
        sum2 += (double)out[4 * i] * out[4 * i];
        *peak = fmax(*peak, fabs(out[4 * i]));
    }
    *mean = sum / N;
    *sd = sqrt(fmax(sum2 / N - *mean * *mean, 0.0));
    return 0;
}

/* The crest's foam close up takes detail finer than its lace (cells 50 cm
 * down to 12 cm; without it the whitewater read as a smooth, blurred
 * sheet), and only where the pixel is small enough to hold it: each octave
 * fades out as its cell shrinks from one pixel's footprint to half of one,
 * so far foam cannot alias into sparkle. Centred on zero (the coverage far
 * off stays what the lace gives) and within +-0.5. */
static void test_foam_detail(tl_renderer *r)
{
    tl_scene s;
    const double cam[3] = {0.0, 3.0, 0.0};
    wave_scene(&s, 10.0, 5.0, cam);
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_frame_uniforms u;
    tl_prepare_frame(&s, &w, &u);
    const double footprints[4] = {0.0, 0.2, 0.6, 1.0};
    double mean[4], sd[4], peak[4];
    for (int k = 0; k < 4; k++)
        if (detail_stats(r, &u, footprints[k], &mean[k], &sd[k], &peak[k])) {
            CHECK(0);
            return;
        }
    printf("foam detail, sd at footprint 0 / 0.2 / 0.6 / 1 m: %.4f %.4f %.4f %.4f (mean %.4f, "
           "peak %.3f)\n",
           sd[0], sd[1], sd[2], sd[3], mean[0], peak[0]);
    CHECK(fabs(mean[0]) < 0.04);
    CHECK(peak[0] <= 0.5);
    CHECK(sd[0] > 0.05);
    CHECK(sd[1] < sd[0] && sd[1] > 0.5 * sd[0]); /* the 12 cm octave fading */
    CHECK(sd[2] > 0.0 && sd[2] < 0.7 * sd[1]);   /* the 50 cm octave alone, fading */
    CHECK(peak[3] == 0.0);                       /* every cell is half a pixel or less */
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_glow_fades(r);
    test_glow_graded(r);
    test_glow_uneven(r);
    test_glow_caustics(r);
    test_crest_caustics_probe(r, 0.0, 0.0, 10.0);
    test_crest_caustics_probe(r, 1e4, -7e3, 1e5);
    test_lip_facing(r);
    test_sun_shadow(r);
    test_mirror_clear(r);
    test_short_wave_gain(r, 3.0, -4.0, 10.0);
    test_short_wave_gain(r, 1e4, -7e3, 1e5);
    test_trail_aerated(r);
    test_stringers(r);
    test_foam_detail(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
