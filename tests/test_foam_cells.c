/* The foam's cellular noise (foam_cells, probe mode 31) on the GPU
 * (llvmpipe on CI) against its double mirror (tl_noise_cells), and what it
 * is: a net of borders between cells, zero on them, a few per cent of the
 * plane near them. The spent foam's film is drawn along it. */
#include <math.h>

#include "tl_gl_test.h"
#include "waves/tl_noise.h"

/* N points over 12 cells square from (x0, y0): the GPU within `tolerance`
 * of the CPU. */
static void test_cells_probe(tl_renderer *r, double x0, double y0, double tolerance)
{
    enum { N = 1024 };
    float xz[2 * N], gpu[4 * N];
    for (int i = 0; i < N; i++) {
        xz[2 * i] = (float)(x0 + 12.0 * (i % 32) / 31.0 + 0.013 * i);
        xz[2 * i + 1] = (float)(y0 + 12.0 * (i / 32) / 31.0);
    }
    tl_scene s;
    tl_scene_defaults(&s);
    tl_waves w;
    tl_waves_init(&w, &s.ocean);
    tl_frame_uniforms u;
    tl_prepare_frame(&s, &w, &u);
    tl_error err;
    tl_error_clear(&err);
    if (tl_renderer_probe(r, &u, 31, xz, N, s.quality.march_octaves, gpu, &err)) {
        fprintf(stderr, "probe: %s\n", err.message);
        CHECK(0);
        return;
    }
    double worst = 0.0;
    for (int i = 0; i < N; i++)
        worst = fmax(worst, fabs(tl_noise_cells(xz[2 * i], xz[2 * i + 1]) - gpu[4 * i]));
    printf("foam cells from (%g, %g): |gpu-cpu| <= %.2e\n", x0, y0, worst);
    CHECK(worst <= tolerance);
}

/* Over 20 x 20 cells, 100 points a cell across: within 0.05 of a border
 * lie 2 to 20% of the points (a net of thin lines), the least value is
 * under 0.01 (it reaches the borders), the largest under 1.5, the mean
 * between 0.2 and 0.6. */
static void test_cells_net(void)
{
    enum { SIDE = 2000 };
    long near = 0;
    double least = 1e9, most = 0.0, sum = 0.0;
    for (int j = 0; j < SIDE; j++)
        for (int i = 0; i < SIDE; i++) {
            double v = tl_noise_cells(-7.0 + 0.01 * i, 3.0 + 0.01 * j);
            near += v < 0.05;
            least = fmin(least, v);
            most = fmax(most, v);
            sum += v;
        }
    double share = (double)near / ((double)SIDE * SIDE), mean = sum / ((double)SIDE * SIDE);
    printf("foam cells: %.1f%% of the plane within 0.05 of a border, values %.4f .. %.3f, "
           "mean %.3f\n",
           100.0 * share, least, most, mean);
    CHECK(share >= 0.02 && share <= 0.2);
    CHECK(least < 0.01);
    CHECK(most < 1.5);
    CHECK(mean >= 0.2 && mean <= 0.6);
}

int main(void)
{
    test_cells_net();
    tl_gl_context *ctx = NULL;
    tl_renderer *r = gl_test_open(&ctx);
    if (!r)
        return 1;
    test_cells_probe(r, 0.0, 0.0, 1e-5);
    test_cells_probe(r, -3.1e3, 7.7e3, 1e-4);
    tl_renderer_destroy(r);
    tl_gl_context_destroy(ctx);
    TEST_END();
}
