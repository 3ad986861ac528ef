/* Light shafts under water (shaders/shafts.glsl): the light they add has a
 * pattern, strongest looking toward the sun; it leaves the frame's mean
 * as it was (they move light, they make none); a strength of nearly 0 is
 * the frame without them; and far out at a late time they look as near
 * the origin. (The mean is kept only roughly: just under the surface the
 * focus averages a little over 1, test_caustics.) */
#include <string.h>

#include "core/tl_math.h"
#include "tl_gl_test.h"

enum { W = 96, H = 54, MOMENTS = 6 };

/* The camera 4 m down looks level to the south-south-west; the sun is at
 * azimuth `sun_deg`. */
static void shaft_scene(tl_scene *s, double sun_deg, double strength, double x, double t)
{
    tl_scene_defaults(s);
    s->width = W;
    s->height = H;
    s->time = t;
    s->camera.position[0] = x;
    s->camera.position[1] = -4.0;
    s->camera.yaw = 200.0 * TL_DEG;
    s->camera.pitch = 10.0 * TL_DEG;
    s->camera.vfov = 60.0 * TL_DEG;
    s->sun.elevation = 55.0 * TL_DEG;
    s->sun.azimuth = sun_deg * TL_DEG;
    s->underwater.shafts = strength;
}

static int shaft_luminance(tl_renderer *r, const tl_scene *s, double *lum)
{
    tl_frame_uniforms u;
    gl_test_prepare(r, s, &u);
    CHECK(!(u.features & TL_FEATURE_SHAFTS) == !(s->underwater.shafts > 0.0));
    tl_frame f;
    if (render_prepared(r, &u, s->width, s->height, &f))
        return -1;
    for (int i = 0; i < W * H; i++)
        lum[i] = luminance(f.color + 4 * (size_t)i);
    tl_frame_free(&f);
    return 0;
}

/* The shafts' share of a view: the std of (with - without), averaged
 * over blocks of 4 x 4 pixels (their dither's tile), over the frame's
 * lower two thirds (under the window): *strength absolute, *contrast
 * relative to the frame's mean without them; the mean change relative to
 * that mean too; and the largest change a strength of 1e-6 makes. */
static int shafts_of(tl_renderer *r, double sun_deg, double x, double t, double *strength,
                     double *contrast, double *mean_change, double *faint)
{
    static double on[W * H], off[W * H], weak[W * H];
    tl_scene s;
    shaft_scene(&s, sun_deg, 1.0, x, t);
    if (shaft_luminance(r, &s, on))
        return -1;
    s.underwater.shafts = 0.0;
    if (shaft_luminance(r, &s, off))
        return -1;
    s.underwater.shafts = 1e-6;
    if (shaft_luminance(r, &s, weak))
        return -1;
    double sum = 0.0, sq = 0.0, base = 0.0;
    int n = 0;
    *faint = 0.0;
    for (int i = 0; i < W * H; i++)
        *faint = fmax(*faint, fabs(weak[i] - off[i]) / off[i]);
    for (int by = H / 12; by < H / 4; by++)
        for (int bx = 0; bx < W / 4; bx++) {
            double d = 0.0;
            for (int k = 0; k < 16; k++) {
                int i = (4 * by + k / 4) * W + 4 * bx + k % 4;
                d += (on[i] - off[i]) / 16.0;
                base += off[i] / 16.0;
            }
            sum += d;
            sq += d * d;
            n++;
        }
    double mean = sum / n;
    base /= n;
    *strength = sqrt(fmax(sq / n - mean * mean, 0.0));
    *contrast = *strength / base;
    *mean_change = mean / base;
    return 0;
}

/* Each figure over MOMENTS moments a few seconds apart: one view of the
 * sea holds only a few of its waves' bundles. */
static int shafts_over_time(tl_renderer *r, double sun_deg, double x, double t, double *strength,
                            double *contrast, double *mean_change, double *faint)
{
    *strength = *contrast = *mean_change = *faint = 0.0;
    for (int k = 0; k < MOMENTS; k++) {
        double a, b, c, d;
        if (shafts_of(r, sun_deg, x, t + 3.7 * k, &a, &b, &c, &d))
            return -1;
        *strength += a / MOMENTS;
        *contrast += b / MOMENTS;
        *mean_change += c / MOMENTS;
        *faint = fmax(*faint, d);
    }
    return 0;
}

static void test_shafts(tl_renderer *r)
{
    double toward, away, far, c_toward, c_away, c_far, change, change_away, change_far, faint[3];
    if (shafts_over_time(r, 200.0, 0.0, 10.0, &toward, &c_toward, &change, &faint[0]) ||
        shafts_over_time(r, 20.0, 0.0, 10.0, &away, &c_away, &change_away, &faint[1]) ||
        shafts_over_time(r, 200.0, 1e4, 1e5, &far, &c_far, &change_far, &faint[2]))
        return;
    double weakest = fmax(faint[0], fmax(faint[1], faint[2]));
    printf(
        "light shafts: std %.3g toward the sun (contrast %.4f), %.3g with the sun behind (%.4f), "
        "%.3g at 1e4 m and 1e5 s (%.4f); mean change %+.4f %+.4f %+.4f; strength 1e-6 against "
        "off %.2g\n",
        toward, c_toward, away, c_away, far, c_far, change, change_away, change_far, weakest);
    CHECK(c_toward > 0.03);
    CHECK(toward > 3.0 * away);
    CHECK(fabs(far / toward - 1.0) < 0.3);
    CHECK(fabs(change) < 0.1 && fabs(change_far) < 0.1);
    CHECK(weakest < 1e-4);
}

/* The march's dither: the shafts drawn with the frame's steps against
 * the same with four times as many, pixel by pixel, over the lower two
 * thirds: the RMS of the difference over the std of the finer shafts.
 * Each 2 x 2 quad of pixels shares its samples (shafts_quad_mean); each
 * pixel alone, the frame kept a diagonal grid of dots, and the difference
 * was half as large again as the shafts themselves. Part of what is left
 * is no dither: the finer march draws the shafts sharper (its footprint
 * follows the step). */
static void test_shaft_dither(tl_renderer *r)
{
    static double coarse[W * H], fine[W * H], off[W * H];
    tl_scene s;
    shaft_scene(&s, 200.0, 1.0, 0.0, 10.0);
    int steps = s.quality.shaft_steps;
    if (shaft_luminance(r, &s, coarse))
        return;
    s.quality.shaft_steps = 4 * steps;
    if (shaft_luminance(r, &s, fine))
        return;
    s.underwater.shafts = 0.0;
    if (shaft_luminance(r, &s, off))
        return;
    double err = 0.0, sum = 0.0, sq = 0.0;
    int n = 0;
    for (int i = W * H / 3; i < W * H; i++) {
        double c = coarse[i] - off[i], f = fine[i] - off[i];
        err += (c - f) * (c - f);
        sum += f;
        sq += f * f;
        n++;
    }
    double rms = sqrt(err / n), spread = sqrt(fmax(sq / n - (sum / n) * (sum / n), 0.0));
    printf("shafts' dither: %d against %d steps, RMS %.3g over the shafts' std %.3g: %.3f\n", steps,
           4 * steps, rms, spread, rms / spread);
    CHECK(steps > 0 && spread > 0.0);
    CHECK(rms < spread);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_shafts(r);
    test_shaft_dither(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
