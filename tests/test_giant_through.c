/* The water a ray crosses through the giant wave (giant_water_along, probe
 * mode 30) on the GPU (llvmpipe on CI) against its double mirror
 * (tl_giant_water_along): the sun's light through the crest to the lip's
 * sheet and the view through the sheet come along it. Near the origin and
 * 1e4 m out at t = 1e5 s. */
#include <math.h>

#include "tl_giant_test.h"

/* Rays from points on the centre line of a 20 m wave, from 30 m behind its
 * crest to 30 m in front and from the sea's level to 8 m over the crest,
 * at elevations all around the vertical plane of the travel: on the GPU
 * and the CPU within 2 cm and half a per cent. And what they must cross: a
 * ray up from over the crest, none; a level ray back into the face from
 * 3 m in front of it at half the wave's height, several metres (it runs
 * through the crest); the same ray turned forward, away from the wave,
 * none. */
static void test_water_along(tl_renderer *r, double x, double z, double t)
{
    enum { ALONG = 13, UP = 6, TURNS = 8, N = ALONG * UP * TURNS + 3 };
    centre_line c;
    centre_line_open(&c, x, z, t);
    float in4[4 * N], gpu[4 * N];
    for (int i = 0; i < ALONG * UP * TURNS; i++) {
        int a = i / (UP * TURNS), u = i / TURNS % UP, k = i % TURNS;
        centre_line_point(&c.g, c.cam, c.crest - 30.0 + 60.0 * a / (ALONG - 1), 0.0, in4 + 4 * i);
        in4[4 * i + 2] = (float)(28.0 * u / (UP - 1));
        in4[4 * i + 3] = (float)(2.0 * M_PI * (k + 0.5) / TURNS);
    }
    /* The level of the face at half the wave's height, from the double
     * mirror: where the sea's height along the centre line first falls
     * under 10 m in front of the crest. */
    double face = c.crest;
    for (double s = c.crest; s < c.crest + 60.0; s += 0.05) {
        double px = c.g.origin[0] + c.g.dir[0] * s, pz = c.g.origin[1] + c.g.dir[1] * s;
        if (tl_giant_height(&c.g, px, pz, c.s.quality.giant_iterations) < 10.0) {
            face = s;
            break;
        }
    }
    const double probes[3][3] = {
        {c.crest, 28.0, 0.5 * M_PI}, /* over the crest, straight up */
        {face + 3.0, 10.0, M_PI},    /* in front of the face, level, back into it */
        {face + 3.0, 10.0, 0.0},     /* the same, forward */
    };
    for (int k = 0; k < 3; k++) {
        float *p = in4 + 4 * (ALONG * UP * TURNS + k);
        centre_line_point(&c.g, c.cam, probes[k][0], 0.0, p);
        p[2] = (float)probes[k][1];
        p[3] = (float)probes[k][2];
    }
    if (!centre_line_probe4(r, &c, 30, in4, N, gpu))
        return;
    double worst = 0.0, cpu[N];
    for (int i = 0; i < N; i++) {
        const float *p = in4 + 4 * i;
        double e = (double)p[3];
        double from[3] = {c.cam[0] + (double)p[0], (double)p[2], c.cam[2] + (double)p[1]};
        double dir[3] = {cos(e) * c.g.dir[0], sin(e), cos(e) * c.g.dir[1]};
        cpu[i] = tl_giant_water_along(&c.g, from, dir, c.s.quality.giant_iterations);
        worst = fmax(worst, fabs(cpu[i] - gpu[4 * i]) / (0.02 + 0.005 * cpu[i]));
    }
    const double *end = cpu + ALONG * UP * TURNS;
    printf("water along rays at (%g, %g), t = %g: |gpu-cpu| <= %.3f of the tolerance; up from "
           "over the crest %.3f m, back into the face %.2f m, away from it %.3f m\n",
           x, z, t, worst, end[0], end[1], end[2]);
    CHECK(worst <= 1.0);
    CHECK(end[0] == 0.0);
    CHECK(end[1] >= 5.0);
    CHECK(end[2] == 0.0);
}

int main(void)
{
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_water_along(r, 0.0, 0.0, 10.0);
    test_water_along(r, 1e4, -7e3, 1e5);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
