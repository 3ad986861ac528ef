/* Colour management: the ACEScg working space against the AP1 matrix of the
 * ACES documents (typed here, independent of OpenColorIO), through a file;
 * an OpenColorIO display and view baked into the display pass's table
 * against OpenColorIO's own transform of the frame's radiance; the errors
 * that name a config, display or view. */
#include <stdlib.h>
#include <unistd.h>

#include "image/tl_image_io.h"
#include "ocio/tl_ocio.h"
#include "passes/tl_passes.h"
#include "tl_gl_test.h"

/* Linear Rec.709 (D65) to ACES AP1 (the ACES white), with Bradford
 * adaptation, as the ACES reference implementation gives it. */
static const double rec709_to_ap1[9] = {0.6130974024, 0.3395231462, 0.0473794514,
                                        0.0701937225, 0.9163538791, 0.0134523985,
                                        0.0206155929, 0.1095697729, 0.8698146342};

static void test_working_space(tl_render *r)
{
    double m[9];
    tl_error err;
    CHECK(tl_ocio_working_matrix(TL_WORKING_ACESCG, m, &err) == 0);
    double worst = 0.0;
    for (int i = 0; i < 9; i++)
        worst = fmax(worst, fabs(m[i] - rec709_to_ap1[i]));
    printf("OpenColorIO's Rec.709 -> ACEScg against the ACES matrix: %.2e\n", worst);
    CHECK(worst < 1e-6);
    CHECK(tl_ocio_working_matrix(TL_WORKING_REC709, m, &err) == 0);
    CHECK(fabs(m[0] - 1.0) < 1e-7 && fabs(m[1]) < 1e-7 && fabs(m[4] - 1.0) < 1e-7);

    /* A rendered frame written in each space: the ACEScg file is the
     * Rec.709 radiance through the matrix, to the half's rounding. */
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 96;
    s.height = 54;
    tl_frame f = {0};
    CHECK(tl_render_frame(r, &s, &f, &err) == 0);
    CHECK(tl_ocio_working_matrix(TL_WORKING_ACESCG, m, &err) == 0);
    char path[] = "/tmp/tideline_test_color_XXXXXX.exr";
    int fd = mkstemps(path, 4);
    close(fd);
    const char *names[1] = {"boat"};
    tl_passes_frame info = {0,    &s.camera,         names, 1,   24.0, &s, NULL,
                            NULL, TL_WORKING_ACESCG, m,     NULL};
    CHECK(tl_passes_write_frame(path, &f, &info, NULL, &err) == 0);
    tl_frame back;
    CHECK(tl_exr_read(path, &back, &err) == 0);
    double rel = 0.0;
    for (int i = 0; back.color && i < f.width * f.height; i++)
        for (int c = 0; c < 3; c++) {
            const float *x = f.color + i * 4;
            double want = rec709_to_ap1[c * 3] * x[0] + rec709_to_ap1[c * 3 + 1] * x[1] +
                          rec709_to_ap1[c * 3 + 2] * x[2];
            rel = fmax(rel, fabs(back.color[i * 4 + c] - want) / fmax(fabs(want), 1e-3));
        }
    printf("ACEScg frame against the Rec.709 one through the matrix: %.2e relative\n", rel);
    CHECK(rel <= 1e-3);
    char space[32];
    CHECK(tl_exr_read_attr_string(path, "tideline/working_space", space, sizeof space, &err) == 0);
    CHECK_STR_EQ(space, "acescg");
    tl_frame_free(&back);
    unlink(path);
    tl_frame_free(&f);
}

static void test_display(tl_render *r)
{
    tl_error err;
    tl_ocio_display *d = NULL;
    CHECK(tl_ocio_display_open(NULL, "sRGB", "ACES 1.0 - SDR Video", &d, &err) == 0);
    if (!d)
        return;
    float *lut =
        malloc(sizeof(float) * 3 * TL_COLOR_LUT_SIZE * TL_COLOR_LUT_SIZE * TL_COLOR_LUT_SIZE);
    CHECK(lut && tl_ocio_display_bake(d, TL_COLOR_LUT_SIZE, lut, &err) == 0);
    CHECK(tl_render_set_display_lut(r, lut, TL_COLOR_LUT_SIZE, &err) == 0);
    /* The display image against OpenColorIO's transform of the radiance
     * (no glare or pixel filter: they act on the display values). */
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 96;
    s.height = 54;
    s.bloom = 0.0;
    s.quality.pixel_filter = 0.0;
    tl_frame f = {0};
    CHECK(tl_render_frame(r, &s, &f, &err) == 0);
    double worst = 0.0, mean = 0.0, exposure = s.exposure * exp2(-s.ev);
    for (int i = 0; f.display && i < f.width * f.height; i++) {
        float in[3], want[3];
        for (int c = 0; c < 3; c++)
            in[c] = (float)(f.color[i * 4 + c] * exposure);
        tl_ocio_display_apply(d, in, want);
        for (int c = 0; c < 3; c++) {
            double e = 255.0 * fabs(f.display[i * 4 + c] - fmin(fmax(want[c], 0.0f), 1.0f));
            worst = fmax(worst, e);
            mean += e / (3.0 * f.width * f.height);
        }
    }
    printf("display table against OpenColorIO: worst %.2f, mean %.3f of 255 levels\n", worst, mean);
    CHECK(worst < 1.5);
    /* Back to the ACES fit: the image changes (the two differ a little). */
    CHECK(tl_render_set_display_lut(r, NULL, 0, &err) == 0);
    tl_frame g = {0};
    CHECK(tl_render_frame(r, &s, &g, &err) == 0);
    double apart = 0.0;
    for (int i = 0; g.display && i < g.width * g.height * 4; i++)
        apart = fmax(apart, fabs(g.display[i] - f.display[i]));
    CHECK(apart > 1.0 / 255.0);
    tl_frame_free(&f);
    tl_frame_free(&g);
    free(lut);
    tl_ocio_display_close(d);

    /* Errors name what is missing and what there is. */
    CHECK(tl_ocio_display_open(NULL, "P3", NULL, &d, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, "built-in: no display 'P3' (displays: sRGB)");
    CHECK(tl_ocio_display_open(NULL, NULL, "Film", &d, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message,
                       "display 'sRGB' has no view 'Film' (views: ACES 1.0 - SDR Video, "
                       "Un-tone-mapped, Raw)");
    CHECK(tl_ocio_display_open("/nonexistent/studio.ocio", NULL, NULL, &d, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, "OpenColorIO config /nonexistent/studio.ocio:");
}

/* The preview's false colour zones (the shader's mirror), stop by stop. */
static void test_false_zones(void)
{
    CHECK(tl_color_false_zone(-8.0) == TL_FALSE_CRUSHED);
    CHECK(tl_color_false_zone(NAN) == TL_FALSE_CRUSHED);
    CHECK(tl_color_false_zone(-5.0) == TL_FALSE_SHADOW);
    CHECK(tl_color_false_zone(-2.0) == TL_FALSE_GREY);
    CHECK(tl_color_false_zone(0.1) == TL_FALSE_MID);
    CHECK(tl_color_false_zone(-0.24) == TL_FALSE_MID);
    CHECK(tl_color_false_zone(0.5) == TL_FALSE_GREY);
    CHECK(tl_color_false_zone(1.2) == TL_FALSE_SKIN);
    CHECK(tl_color_false_zone(3.0) == TL_FALSE_GREY);
    CHECK(tl_color_false_zone(4.5) == TL_FALSE_NEAR_WHITE);
    CHECK(tl_color_false_zone(5.5) == TL_FALSE_CLIPPED);
    CHECK(tl_color_false_zone(INFINITY) == TL_FALSE_CLIPPED);
}

int main(void)
{
    test_false_zones();
    tl_render *r = render_test_open();
    CHECK(r != NULL);
    if (!r)
        TEST_END();
    unsetenv("OCIO"); /* the built-in config, whatever the machine says */
    test_working_space(r);
    test_display(r);
    tl_render_close(r);
    TEST_END();
}
