/* The whole headless pipeline: render a still, write EXR and PNG, read
 * both back with OpenEXR's C API and libpng and compare with the frame
 * buffer that was rendered. */
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "image/tl_image_io.h"
#include "render/tl_render.h"
#include "tl_gl_test.h"

static float half_round_trip_tolerance(float v)
{
    /* Half floats keep 11 significant bits: relative error <= 2^-11. */
    return fabsf(v) * (1.0f / 2048.0f) + 1e-7f;
}

int main(void)
{
    char dir[] = "/tmp/tideline-still-XXXXXX";
    if (!mkdtemp(dir))
        return 1;
    char exr_path[256], png_path[256];
    snprintf(exr_path, sizeof exr_path, "%s/still.exr", dir);
    snprintf(png_path, sizeof png_path, "%s/still.png", dir);

    tl_error err;
    tl_error_clear(&err);
    tl_render *r = render_test_open();
    if (!r)
        return 1;
    tl_scene s;
    tl_scene_defaults(&s);
    s.width = 96;
    s.height = 54;
    s.time = 7.5;
    tl_frame f = {0};
    CHECK(tl_render_frame(r, &s, &f, &err) == 0);
    const tl_meta meta[] = {{"tideline/time", TL_META_DOUBLE, NULL, 7.5, 0, NULL},
                            {"tideline/quality", TL_META_STRING, "final", 0, 0, NULL}};
    tl_image_options opt = {.meta = meta, .meta_count = 2};
    CHECK(tl_image_write(exr_path, &f, &opt, &err) == 0);
    CHECK(tl_image_write(png_path, &f, &opt, &err) == 0);

    tl_frame e = {0};
    CHECK(tl_exr_read(exr_path, &e, &err) == 0);
    CHECK(e.width == s.width && e.height == s.height);
    int color_ok = 1, depth_ok = 1;
    size_t n = (size_t)s.width * (size_t)s.height;
    for (size_t i = 0; e.color && i < n * 4; i++) {
        float want = fminf(f.color[i], 65504.0f);
        color_ok &= fabsf(e.color[i] - want) <= half_round_trip_tolerance(want);
    }
    for (size_t i = 0; e.depth && i < n; i++)
        depth_ok &= e.depth[i] == f.depth[i]; /* Z is stored as 32-bit float */
    CHECK(color_ok);
    CHECK(depth_ok);
    double t = 0.0;
    CHECK(tl_exr_read_attr_double(exr_path, "tideline/time", &t, &err) == 0);
    CHECK(t == 7.5);
    tl_frame_free(&e);

    tl_frame p = {0};
    int bits = 0;
    CHECK(tl_png_read(png_path, &p, &bits, &err) == 0);
    CHECK(bits == 8);
    CHECK(p.width == s.width && p.height == s.height);
    int png_ok = 1;
    unsigned char row[3 * 96];
    for (int y = 0; p.display && s.width <= 96 && y < s.height; y++) {
        /* The writer's codes: the display plane dithered to 8 bits. */
        tl_frame_display_row8(&f, y, 1, row);
        for (int x = 0; x < s.width; x++)
            for (int c = 0; c < 3; c++) {
                float got = p.display[((size_t)y * s.width + x) * 4 + c];
                png_ok &= fabsf(got - row[x * 3 + c] / 255.0f) < 1e-6f;
            }
    }
    CHECK(s.width <= 96);
    CHECK(png_ok);
    tl_frame_free(&p);

    tl_frame_free(&f);
    tl_render_close(r);
    unlink(exr_path);
    unlink(png_path);
    rmdir(dir);
    TEST_END();
}
