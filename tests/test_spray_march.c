/* The lip's spray: the droplets its free edge tears off while it throws
 * (TL_SPRAY_TIP_*, in double; the GPU's density against it is
 * test_giant_lip's), and the march on the GPU (llvmpipe on CI): the
 * whitewater where the lip lands, marched at final's quality.spray_step,
 * is close to the same cloud marched four times finer. Its billows' edges
 * are sharper than a step; sampled once per step at each pixel's own
 * offset, they fell in or out of each pixel's samples and the cloud's
 * edges were a grain of white dots (spray.glsl refines the steps inside
 * it, TL_SPRAY_CLOUD_*). */
#include <math.h>

#include "tl_breaking_test.h"
#include "waves/tl_giant.h"
#include "waves/tl_giant_spray.h"

/* The densest spray within `reach` of the lip's tip at the peak (its
 * offset from the tip `ahead` lip radii along the travel), `age` seconds
 * into the break; the lip's throw there in *progress. */
static double tip_spray(double age, double ahead, double reach, double *progress)
{
    tl_scene s;
    breaking_scene(&s, 10.0, age, 0.0, 0.0);
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    const double base = -0.5 * s.ocean.depth;
    tl_giant_lip lip;
    tl_giant_lip_at(&g, s.giant.peak, base, &lip);
    *progress = lip.progress;
    tl_giant_spray sp;
    tl_giant_spray_prepare(&sp, &g, s.giant.spray, s.giant.spray_wind, s.time, s.ocean.depth, NULL);
    double tip_s = lip.center[0] + lip.radius * (TL_GIANT_LIP_THROW * sin(lip.to) + ahead);
    double tip_y = lip.center[1] + lip.radius * cos(lip.to), most = 0.0;
    for (int j = -10; j <= 10; j++)
        for (int i = -10; i <= 10; i++)
            for (int k = -2; k <= 2; k++) {
                double sv = tip_s + reach * i / 10.0, y = tip_y + reach * j / 10.0;
                double w = s.giant.peak + 0.4 * k;
                double x = g.origin[0] + g.dir[0] * sv + g.across[0] * w;
                double z = g.origin[1] + g.dir[1] * sv + g.across[1] * w;
                most = fmax(most, tl_giant_spray_density(&sp, &g, x, y, z, 0.0));
            }
    return most;
}

/* While the lip throws, droplets lie round its tip: at AGE seconds into
 * the break (the throw between TL_SPRAY_TIP_FULL and _FADE) the densest
 * within a metre of the tip is over a tenth of TL_SPRAY_TIP_GAIN ·
 * giant.spray; a lip's radius ahead of the tip there is none (the tube is
 * TL_SPRAY_TIP_RADIUS across). */
#define AGE 1.2
static void test_torn_edge(void)
{
    double thrown;
    double near = tip_spray(AGE, 0.0, 1.0, &thrown);
    double ahead = tip_spray(AGE, 1.0, 0.05, &thrown);
    printf("lip's torn edge, throw %.2f: densest %.2f round the tip, %.2e a radius ahead\n", thrown,
           near, ahead);
    CHECK(thrown > TL_SPRAY_TIP_FULL && thrown < TL_SPRAY_TIP_FADE);
    CHECK(near > 0.1 * TL_SPRAY_TIP_GAIN * 1.5);
    CHECK(ahead < 1e-3 * near);
}

/* The landing's whitewater 3.5 s into the break, seen from 45 m in front
 * of the crest at its peak, 6 m up: rendered at final's step (1 m) and at
 * a quarter of it, and without spray. Over the pixels the cloud changes by
 * at least a tenth of its mean change (it is opaque: its shaded billows
 * are darker than the sky behind them), the RMS difference between the
 * two steps' luminance is at most 0.12 of the cloud's mean luminance
 * (with one sample per step it was 0.17), and the cloud covers a few
 * hundred pixels. */
static void test_landing_converged(tl_renderer *r)
{
    tl_scene s;
    breaking_scene(&s, 10.0, 3.5, 0.0, 0.0);
    s.width = 192;
    s.height = 108;
    tl_giant g;
    tl_giant_prepare(&g, &s.giant, s.time);
    tl_giant_lip lip;
    tl_giant_lip_at(&g, s.giant.peak, -0.5 * s.ocean.depth, &lip);
    CHECK(lip.present && lip.progress > 0.9);
    /* Where the lip lands: about a radius ahead of its centre. */
    const double land_s = lip.center[0] + lip.radius, land_y = lip.center[1];
    const double cam_s = land_s + 45.0;
    for (int i = 0; i < 2; i++)
        s.camera.position[i == 0 ? 0 : 2] =
            g.origin[i] + g.dir[i] * cam_s + g.across[i] * s.giant.peak;
    s.camera.position[1] = 6.0;
    s.camera.yaw = atan2(-g.dir[0], -g.dir[1]);
    s.camera.pitch = atan2(land_y - 6.0, 45.0);
    s.camera.vfov = 40.0 * M_PI / 180.0;
    tl_frame coarse, fine, none;
    tl_scene sc = s, sf = s, sn = s;
    sc.quality.spray_step = 1.0;
    sf.quality.spray_step = 0.25;
    sn.giant.spray = 0.0;
    if (render(r, &sc, &coarse))
        return;
    if (render(r, &sf, &fine)) {
        tl_frame_free(&coarse);
        return;
    }
    if (render(r, &sn, &none)) {
        tl_frame_free(&coarse);
        tl_frame_free(&fine);
        return;
    }
    size_t n = (size_t)s.width * (size_t)s.height;
    double change_sum = 0.0;
    int change_n = 0;
    for (size_t i = 0; i < n; i++) {
        double change = fabs(luminance(fine.color + 4 * i) - luminance(none.color + 4 * i));
        if (change > 0.0) {
            change_sum += change;
            change_n++;
        }
    }
    double mean_change = change_n > 0 ? change_sum / change_n : 0.0, sq = 0.0, lum = 0.0;
    int cloud = 0;
    for (size_t i = 0; i < n; i++) {
        double change = fabs(luminance(fine.color + 4 * i) - luminance(none.color + 4 * i));
        if (change < 0.1 * mean_change)
            continue;
        double d = luminance(coarse.color + 4 * i) - luminance(fine.color + 4 * i);
        sq += d * d;
        lum += luminance(fine.color + 4 * i);
        cloud++;
    }
    double rms = cloud > 0 ? sqrt(sq / cloud) / (lum / cloud) : 1.0;
    printf("landing's cloud: %d pixels, mean change %.4f, mean %.4f; 1 m steps against 0.25 m: "
           "RMS %.3f of the mean\n",
           cloud, mean_change, lum / (cloud > 0 ? cloud : 1), rms);
    CHECK(cloud >= 300);
    CHECK(rms <= 0.12);
    tl_frame_free(&coarse);
    tl_frame_free(&fine);
    tl_frame_free(&none);
}

int main(void)
{
    test_torn_edge();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_landing_converged(r);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
