/* The water body's light with depth (shaders/water_light.glsl): the GPU's
 * in-scattered light along a ray against tl_optics_water_inscatter in
 * double; a horizontal view darkens from 3 m to 40 m as Beer-Lambert of
 * the downwelling light predicts; after sunset the water under the
 * surface is as dark as its sky; and from above, shallow water shows its
 * floor. */
#include <string.h>

#include "core/tl_math.h"
#include "optics/tl_optics.h"
#include "tl_gl_test.h"

static void light_of(const tl_frame_uniforms *u, tl_water_light *l)
{
    for (int c = 0; c < 3; c++) {
        l->sigma[c] = u->water_sigma[c];
        l->fall[c] = u->water_fall[c];
        l->sun_water[c] = u->sun_water[c];
        l->sun_light[c] = (u->features & TL_FEATURE_SUN_DISC) ? u->sun_light[c] : 0.0;
        l->sky_ambient[c] = u->sky_ambient[c];
    }
    l->scattering = u->water_scattering;
    l->sun_water_trans = u->sun_water_trans;
}

static void under(tl_scene *s, double depth, double sun_elevation)
{
    tl_scene_defaults(s);
    s->width = 64;
    s->height = 36;
    s->camera.position[1] = -depth;
    s->camera.pitch = 0.0;
    s->camera.vfov = 20.0 * TL_DEG;
    s->sun.elevation = sun_elevation * TL_DEG;
    s->sun.azimuth = 40.0 * TL_DEG;
}

static void test_inscatter_probe(tl_renderer *r)
{
    tl_scene s;
    under(&s, 4.0, 35.0);
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_UNDERWATER);
    tl_water_light l;
    light_of(&u, &l);
    const float depths[] = {0.0f, 3.0f, 40.0f}, ys[] = {-1.0f, -0.5f, 0.0f, 0.3f, 0.9f, 1.0f};
    const float dists[] = {0.5f, 20.0f, 1e10f};
    enum { N = 3 * 6 * 3 * 2 };
    float in[4 * N], out[4 * N];
    int n = 0;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 6; b++)
            for (int c = 0; c < 3; c++)
                for (int az = 0; az < 2; az++, n++) {
                    in[4 * n] = depths[a];
                    in[4 * n + 1] = ys[b];
                    in[4 * n + 2] = az ? 2.5f : 0.7f;
                    in[4 * n + 3] = dists[c];
                }
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe4(r, &u, 20, in, N, 1, out, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    double worst = 0.0;
    int finite = 1;
    for (int i = 0; i < N; i++) {
        double y = in[4 * i + 1], flat = sqrt(fmax(1.0 - y * y, 0.0)), want[3];
        double ray[3] = {flat * cos((double)in[4 * i + 2]), y, flat * sin((double)in[4 * i + 2])};
        tl_optics_water_inscatter(&l, in[4 * i], ray, in[4 * i + 3], want);
        for (int c = 0; c < 3; c++) {
            finite &= isfinite(out[4 * i + c]) && out[4 * i + c] >= 0.0f;
            worst = fmax(worst, fabs(out[4 * i + c] - want[c]) / fmax(want[c], 1e-6));
        }
    }
    printf("in-scattered light: GPU against CPU, worst relative error %.2g over %d rays\n", worst,
           N);
    CHECK(finite);
    CHECK(worst <= 2e-3);
}

static double frame_luminance(tl_renderer *r, const tl_scene *s)
{
    tl_frame_uniforms u;
    gl_test_prepare(r, s, &u);
    tl_frame f;
    if (render_prepared(r, &u, s->width, s->height, &f))
        return NAN;
    double sum = 0.0;
    for (int i = 0; i < s->width * s->height; i++)
        sum += luminance(f.color + 4 * (size_t)i);
    tl_frame_free(&f);
    return sum / (s->width * s->height);
}

/* A horizontal view at 40 m against 3 m: the ratio of the frames' mean
 * luminance within 20% of the ratio Beer-Lambert gives for a level ray
 * into the depths at each (the CPU's in-scatter, per colour). */
static void test_depth(tl_renderer *r)
{
    double got[2], want[2];
    const double depths[2] = {3.0, 40.0};
    for (int k = 0; k < 2; k++) {
        tl_scene s;
        under(&s, depths[k], 50.0);
        got[k] = frame_luminance(r, &s);
        tl_frame_uniforms u;
        gl_test_prepare(r, &s, &u);
        tl_water_light l;
        light_of(&u, &l);
        double fwd[3], right[3], up[3], rgb[3];
        tl_scene_camera_basis(&s.camera, right, up, fwd);
        tl_optics_water_inscatter(&l, depths[k], fwd, TL_FRAME_SKY_DEPTH, rgb);
        want[k] = luminance((const float[3]){(float)rgb[0], (float)rgb[1], (float)rgb[2]});
    }
    double ratio = got[1] / got[0], predicted = want[1] / want[0];
    printf("a level view at 40 m against 3 m: %.4f (%.4g against %.4g), Beer-Lambert %.4f\n", ratio,
           got[1], got[0], predicted);
    CHECK(fabs(ratio / predicted - 1.0) <= 0.2);
    CHECK(ratio < 0.5);
}

/* After sunset the water 5 m down is lit only by the twilight sky: far
 * darker than by day. */
static void test_dusk(tl_renderer *r)
{
    tl_scene day, dusk;
    under(&day, 5.0, 40.0);
    under(&dusk, 5.0, -3.0);
    double a = frame_luminance(r, &day), b = frame_luminance(r, &dusk);
    printf("5 m down: luminance %.4g by day, %.4g after sunset (%.2g of it)\n", a, b, b / a);
    CHECK(b < 0.02 * a);
    CHECK(b > 0.0);
}

/* From above, shallow water shows its floor: a view straight down over a
 * gently rippled sea brightens with a sand floor under it, less the deeper
 * it lies, and bluer (the water takes more red on the longer way down and
 * back). The frame stays above the water: no under-water code. */
static void test_floor_from_above(tl_renderer *r)
{
    const double floors[3] = {0.0, 2.0, 8.0};
    double rgb[3][3];
    for (int k = 0; k < 3; k++) {
        tl_scene s;
        tl_scene_defaults(&s);
        s.width = 64;
        s.height = 36;
        s.ocean.depth = 0.3;
        s.camera.position[1] = 3.0;
        s.camera.pitch = -80.0 * TL_DEG;
        s.camera.vfov = 30.0 * TL_DEG;
        s.sun.elevation = 50.0 * TL_DEG;
        s.ocean.floor_depth = floors[k];
        tl_frame_uniforms u;
        gl_test_prepare(r, &s, &u);
        CHECK(!(u.features & TL_FEATURE_UNDERWATER));
        CHECK(!(u.features & TL_FEATURE_SEA_FLOOR) == (floors[k] == 0.0));
        tl_frame f;
        if (render_prepared(r, &u, s.width, s.height, &f))
            return;
        for (int c = 0; c < 3; c++) {
            double sum = 0.0;
            for (int i = 0; i < s.width * s.height; i++)
                sum += f.color[4 * (size_t)i + c];
            rgb[k][c] = sum / (s.width * s.height);
        }
        tl_frame_free(&f);
    }
    double lum[3], blue[3];
    for (int k = 0; k < 3; k++) {
        lum[k] = luminance((const float[3]){(float)rgb[k][0], (float)rgb[k][1], (float)rgb[k][2]});
        blue[k] = rgb[k][2] / rgb[k][0];
    }
    printf("looking down from 3 m: luminance %.4g without a floor, %.4g over 2 m, %.4g over 8 m; "
           "blue/red %.2f, %.2f, %.2f\n",
           lum[0], lum[1], lum[2], blue[0], blue[1], blue[2]);
    CHECK(lum[1] > 1.5 * lum[0]);
    CHECK(lum[2] > lum[0] && lum[2] < lum[1]);
    CHECK(blue[2] > blue[1]);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_inscatter_probe(r);
    test_depth(r);
    test_dusk(r);
    test_floor_from_above(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
