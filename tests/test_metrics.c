/* tl_metrics against known values: closed forms, and an independent
 * implementation in plain Python, tests/metrics_reference.py, whose
 * numbers this test reads from the fixture it wrote,
 * tests/fixtures/metrics_reference.txt (argv[1]). After changing the
 * script, regenerate the fixture from the repository root:
 *     python3 tests/metrics_reference.py > tests/fixtures/metrics_reference.txt */
#include "metrics/tl_metrics.h"
#include "tl_fixture.h"
#include "tl_test.h"

#include <math.h>
#include <stdlib.h>

enum { W = 16, H = 12 };

static void fill_grey(float *img, int pixels, double v)
{
    for (int i = 0; i < pixels; i++)
        img[4 * i] = img[4 * i + 1] = img[4 * i + 2] = (float)v, img[4 * i + 3] = 1.0f;
}

/* The two patterns of metrics_reference.py (grey: R = G = B). */
static double pattern_a(int x, int y)
{
    return 0.5 + 0.4 * sin(0.7 * x + 0.3 * y) * cos(0.5 * y);
}

static double pattern_b(int x, int y)
{
    double v = pattern_a(x, y) * 0.9 + 0.05 + 0.03 * sin(2.1 * x * y);
    return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
}

int main(int argc, char **argv)
{
    static float a[W * H * 4], b[W * H * 4];
    if (!tl_fixture_load(argc > 1 ? argv[1] : NULL))
        TEST_END();

    /* Identical images: the PSNR cap, SSIM 1, no error. */
    fill_grey(a, W * H, 0.3);
    tl_metrics m;
    CHECK(tl_metrics_compare(a, a, W, H, &m) == 0);
    CHECK(m.psnr == TL_METRICS_PSNR_MAX);
    CHECK_NEAR(m.ssim, 1.0, 1e-12);
    CHECK(m.p99 == 0.0 && m.max_error == 0.0);

    /* Flat 0.5 against flat 0.6: MSE 0.01 is 20 dB; SSIM is the luminance
     * term alone, (2·0.5·0.6 + C1) / (0.5² + 0.6² + C1). */
    fill_grey(a, W * H, 0.5);
    fill_grey(b, W * H, 0.6);
    CHECK(tl_metrics_compare(a, b, W, H, &m) == 0);
    CHECK_NEAR(m.psnr, 20.0, 1e-5);
    CHECK_NEAR(m.ssim, tl_fixture("flat_ssim"), 1e-6);
    CHECK_NEAR(m.p99, 25.5, 1e-4);
    CHECK_NEAR(m.max_error, 25.5, 1e-4);

    /* Alpha is not compared. */
    b[3] = 0.0f;
    CHECK_NEAR(tl_metrics_psnr(a, b, W * H), 20.0, 1e-5);

    /* Textured images: values from the fixture. */
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float *pa = a + 4 * (y * W + x), *pb = b + 4 * (y * W + x);
            pa[0] = pa[1] = pa[2] = (float)pattern_a(x, y);
            pb[0] = pb[1] = pb[2] = (float)pattern_b(x, y);
            pa[3] = pb[3] = 1.0f;
        }
    CHECK(tl_metrics_compare(a, b, W, H, &m) == 0);
    CHECK_NEAR(m.ssim, tl_fixture("ssim"), 2e-6);
    CHECK_NEAR(m.psnr, tl_fixture("psnr"), 1e-4);
    CHECK_NEAR(m.p99, tl_fixture("p99"), 1e-3);
    CHECK_NEAR(m.max_error, tl_fixture("max_error"), 1e-3);
    /* Symmetric. */
    tl_metrics back;
    CHECK(tl_metrics_compare(b, a, W, H, &back) == 0);
    CHECK_NEAR(back.ssim, m.ssim, 1e-12);
    CHECK_NEAR(back.psnr, m.psnr, 1e-12);

    /* Nearest-rank percentile: 100 pixels with errors of 0..99 levels; 99%
     * of them are at most 98 levels off. One red channel each. */
    static float c[100 * 4], d[100 * 4];
    for (int i = 0; i < 100; i++) {
        c[4 * i] = 0.0f;
        d[4 * i] = (float)(i / 255.0);
    }
    double p99, max_error;
    CHECK(tl_metrics_pixel_error(c, d, 100, &p99, &max_error) == 0);
    CHECK_NEAR(p99, 98.0, 1e-4);
    CHECK_NEAR(max_error, 99.0, 1e-4);

    /* An inverted texture is structurally unlike the original. */
    for (int i = 0; i < W * H; i++)
        for (int k = 0; k < 3; k++)
            b[4 * i + k] = 1.0f - a[4 * i + k];
    CHECK(tl_metrics_ssim(a, b, W, H) < 0.0);
    TEST_END();
}
