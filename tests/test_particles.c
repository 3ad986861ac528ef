/* Suspended particles under water (shaders/particles.glsl): the light the
 * motes add to a frame is on average what a cloud of them scatters (the
 * CPU's in-scatter with their scattering, in double), over the same
 * rays; it sits in specks, not a haze; it is far brighter looking toward
 * the sun; far out at a late time it is the same; and without them, or
 * above the water, none of their code is compiled. */
#include <stdlib.h>
#include <string.h>

#include "core/tl_math.h"
#include "optics/tl_optics.h"
#include "tl_gl_test.h"

enum { W = 96, H = 54 };

#define DENSITY 60.0

/* The camera 5 m down looks level toward azimuth `yaw_deg` with a view
 * `vfov_deg` high; the sun at azimuth 200 deg, 55 deg up; no shafts
 * (their noise would hide the motes'). */
static void mote_scene(tl_scene *s, double yaw_deg, double density, double x, double t,
                       double vfov_deg)
{
    tl_scene_defaults(s);
    s->width = W;
    s->height = H;
    s->time = t;
    s->camera.position[0] = x;
    s->camera.position[1] = -5.0;
    s->camera.yaw = yaw_deg * TL_DEG;
    s->camera.pitch = 0.0;
    s->camera.vfov = vfov_deg * TL_DEG;
    s->sun.elevation = 55.0 * TL_DEG;
    s->sun.azimuth = 200.0 * TL_DEG;
    s->underwater.shafts = 0.0;
    s->underwater.particles = density;
}

static int render_luminance(tl_renderer *r, const tl_scene *s, double *lum, unsigned *features)
{
    tl_frame_uniforms u;
    gl_test_prepare(r, s, &u);
    *features = u.features;
    tl_frame f;
    if (render_prepared(r, &u, s->width, s->height, &f))
        return -1;
    for (int i = 0; i < W * H; i++)
        lum[i] = luminance(f.color + 4 * (size_t)i);
    tl_frame_free(&f);
    return 0;
}

static int descending(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

/* The motes' light in a view: its mean over the frame (*got) and the
 * CPU's (*want), and the share of the pixels that hold half of it. */
static int motes_of(tl_renderer *r, double yaw_deg, double x, double t, double vfov_deg,
                    double *got, double *want, double *share)
{
    static double on[W * H], off[W * H], added[W * H];
    tl_scene s;
    unsigned with, without;
    mote_scene(&s, yaw_deg, 0.0, x, t, vfov_deg);
    if (render_luminance(r, &s, off, &without))
        return -1;
    mote_scene(&s, yaw_deg, DENSITY, x, t, vfov_deg);
    if (render_luminance(r, &s, on, &with))
        return -1;
    CHECK(with & TL_FEATURE_PARTICLES);
    CHECK(!(without & TL_FEATURE_PARTICLES));
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    tl_water_light l;
    for (int c = 0; c < 3; c++) {
        l.sigma[c] = u.water_sigma[c];
        l.fall[c] = u.water_fall[c];
        l.sun_water[c] = u.sun_water[c];
        l.sun_light[c] = u.sun_light[c];
        l.sky_ambient[c] = u.sky_ambient[c];
    }
    l.scattering = tl_optics_particle_scattering(DENSITY);
    l.sun_water_trans = u.sun_water_trans;
    double total = 0.0;
    *want = 0.0;
    for (int y = 0; y < H; y++)
        for (int px = 0; px < W; px++) {
            double ray[3], far[3], near[3];
            pixel_ray(&s, px, y, ray);
            /* Level at 5 m down with a view under 90 deg high, every ray
             * runs its whole range under the surface. */
            tl_optics_water_inscatter(&l, 5.0, ray, TL_PARTICLE_RANGE, far);
            tl_optics_water_inscatter(&l, 5.0, ray, TL_PARTICLE_NEAR, near);
            float rgb[3] = {(float)(far[0] - near[0]), (float)(far[1] - near[1]),
                            (float)(far[2] - near[2])};
            *want += luminance(rgb) / (W * H);
            int i = y * W + px;
            added[i] = fmax(on[i] - off[i], 0.0);
            total += added[i];
        }
    *got = total / (W * H);
    qsort(added, W * H, sizeof added[0], descending);
    double sum = 0.0;
    int n = 0;
    while (n < W * H && sum < 0.5 * total)
        sum += added[n++];
    *share = (double)n / (W * H);
    return 0;
}

/* A wide view (many motes in it) for the mean; a narrow one (a pixel's
 * cone holds a mote in a few per cent of them) for the specks. */
static void test_motes(tl_renderer *r)
{
    double got[3], want[3], share[3];
    if (motes_of(r, 200.0, 0.0, 10.0, 60.0, &got[0], &want[0], &share[0]) ||
        motes_of(r, 20.0, 0.0, 10.0, 60.0, &got[1], &want[1], &share[1]) ||
        motes_of(r, 200.0, 1e4, 1e5, 60.0, &got[2], &want[2], &share[2]))
        return;
    const char *name[3] = {"toward the sun", "the sun behind", "at 1e4 m and 1e5 s"};
    for (int k = 0; k < 3; k++) {
        printf("motes %s: mean %.4g against the CPU's %.4g (%.3f)\n", name[k], got[k], want[k],
               got[k] / want[k]);
        CHECK(fabs(got[k] / want[k] - 1.0) < 0.2);
    }
    /* The phase function: forward scattering by a third of the sky's
     * light and the sun's beam at 52 deg, against 128 deg. */
    CHECK(got[0] > 2.0 * got[1]);
    double g, w, narrow;
    if (motes_of(r, 200.0, 0.0, 10.0, 10.0, &g, &w, &narrow))
        return;
    printf("motes in a 10 deg view: half their light in %.2f%% of the pixels\n", 100.0 * narrow);
    CHECK(narrow < 0.05);
}

/* None compiled above the water, or with the sun down still there. */
static void test_compiled_only_under_water(tl_renderer *r)
{
    tl_scene s;
    mote_scene(&s, 200.0, DENSITY, 0.0, 10.0, 60.0);
    s.camera.position[1] = 3.0;
    tl_frame_uniforms u;
    gl_test_prepare(r, &s, &u);
    CHECK(!(u.features & TL_FEATURE_PARTICLES));
    mote_scene(&s, 200.0, DENSITY, 0.0, 10.0, 60.0);
    s.sun.elevation = -5.0 * TL_DEG;
    gl_test_prepare(r, &s, &u);
    CHECK(u.features & TL_FEATURE_PARTICLES);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_motes(r);
    test_compiled_only_under_water(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
