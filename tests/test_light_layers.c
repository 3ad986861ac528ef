/* The light layers on the GPU (shaders/layers.glsl): frames of the bundled
 * cutscenes drawn with their layers, where the giant wave breaks over the
 * boat under the sun (spray, foam, light through the crest, the hull),
 * where the dive looks at the boat from under the water (Snell's window,
 * shafts, motes, the floor), where the camera rides the waterline, and at
 * dusk in fog. In each the shaded layers add up to the colour; each is
 * finite and not negative; each holds light where its source is in view
 * (the boat's only on the boat); the glare's holds the bloom's share of
 * the light. Through the file, the layers are named as the passes say,
 * and an ACEScg file's are the Rec.709 ones through the AP1 matrix. */
#include <stdlib.h>
#include <unistd.h>

#include "cutscene/tl_cutscene.h"
#include "image/tl_image_io.h"
#include "ocio/tl_ocio.h"
#include "passes/tl_passes.h"
#include "tl_gl_test.h"
#include "tl_run.h"

#define W 96
#define H 54

/* The luminance-like sum of a pixel's RGB. */
static double rgb_sum(const float *p)
{
    return (double)p[0] + p[1] + p[2];
}

/* Renders frame `frame` of `name` with every light layer and the passes'
 * data, and checks what every frame must hold; returns the frame (freed
 * by the caller) and its scene. */
static int render_layers(tl_render *r, const char *dir, const char *name, long frame, tl_frame *out,
                         tl_scene *scene, tl_cutscene *cs)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    if (tl_cutscene_load(path, cs, &diags, &err)) {
        tl_cutscene_report(stderr, "test_light_layers", &diags, &err);
        CHECK(0);
        return -1;
    }
    CHECK(tl_render_use_cutscene(r, cs, &err) == 0);
    tl_render_settings settings = {.width = W, .height = H, .spp = 2};
    settings.planes = TL_PLANES_ALL | TL_PLANE_AOV;
    settings.layers = (1u << TL_FRAME_LAYERS) - 1u;
    int rc = tl_render_timeline_frame(r, &cs->timeline, frame, &settings, out, scene, &err);
    if (rc)
        fprintf(stderr, "%s frame %ld: %s\n", name, frame, err.message);
    CHECK(rc == 0);
    CHECK(tl_frame_layers(out) == (1u << TL_FRAME_LAYERS) - 1u);
    if (rc || tl_frame_layers(out) != (1u << TL_FRAME_LAYERS) - 1u)
        return -1;

    /* The shaded layers add up to the colour, pixel by pixel. */
    double worst = 0.0, total[TL_FRAME_LAYERS] = {0}, colour = 0.0;
    int bad = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        colour += rgb_sum(out->color + i * 4);
        for (int c = 0; c < 3; c++) {
            double sum = 0.0;
            for (int k = 0; k < TL_FRAME_LAYERS; k++) {
                float v = out->layer[k][i * 3 + (size_t)c];
                bad += !isfinite(v) || v < 0.0f;
                if (k < TL_LIGHT_SHADED)
                    sum += v;
                total[k] += v;
            }
            double want = out->color[i * 4 + (size_t)c];
            worst = fmax(worst, fabs(sum - want) / fmax(want, 1e-3));
        }
    }
    printf("%s frame %ld: the layers' sum against the colour, worst %.2e relative; layers:", name,
           frame, worst);
    for (int k = 0; k < TL_FRAME_LAYERS; k++)
        printf(" %s %.3g", tl_light_layer_name(k), total[k] / colour);
    printf(" of the colour\n");
    CHECK(worst <= 1e-3);
    CHECK(bad == 0);
    /* The glare is the bloom's share of the light, spread: about as much
     * light as the colour times render.bloom (a small frame spreads some off
     * its edges). */
    double bloom = scene->bloom, glare = total[TL_LIGHT_GLARE] / colour;
    CHECK(glare >= 0.5 * bloom && glare <= 1.05 * bloom);
    return 0;
}

/* The share of layer k in the pixels where the cover `g`.`c` of the aov
 * plane is over `at` least (or under it, with below). */
static double share_where(const tl_frame *f, int k, int g, int c, float at, int below)
{
    double in = 0.0, all = 0.0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        float cover = f->aov[((size_t)g * W * H + i) * 4 + (size_t)c];
        double v = rgb_sum(f->layer[k] + i * 3);
        all += v;
        in += (below ? cover < at : cover > at) ? v : 0.0;
    }
    return all > 0.0 ? in / all : 0.0;
}

static double layer_total(const tl_frame *f, int k)
{
    double sum = 0.0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        sum += rgb_sum(f->layer[k] + i * 3);
    return sum;
}

/* The layers through the file: named ViewLayer.light_<name>.R G B, and in
 * an ACEScg file the Rec.709 layers through the AP1 matrix. */
static void check_file(const tl_frame *f, const tl_scene *scene)
{
    double to_ap1[9];
    tl_error err;
    CHECK(tl_ocio_working_matrix(TL_WORKING_ACESCG, to_ap1, &err) == 0);
    tl_passes_frame info = {TL_PASSES_COMBINED | TL_PASSES_LIGHTS,
                            &scene->camera,
                            NULL,
                            0,
                            24.0,
                            scene,
                            NULL,
                            NULL,
                            TL_WORKING_ACESCG,
                            to_ap1,
                            NULL};
    char out[] = "/tmp/tideline_test_light_layers_XXXXXX.exr";
    int fd = mkstemps(out, 4);
    close(fd);
    CHECK(tl_passes_write_frame(out, f, &info, NULL, &err) == 0);
    double worst = 0.0;
    for (int k = 0; k < TL_FRAME_LAYERS; k++)
        for (int c = 0; c < 3; c++) {
            char name[64];
            snprintf(name, sizeof name, "ViewLayer.light_%s.%c", tl_light_layer_name(k), "RGB"[c]);
            int w = 0, h = 0;
            float *data = NULL;
            CHECK(tl_exr_read_channel(out, name, &w, &h, &data, &err) == 0);
            CHECK(w == W && h == H);
            for (size_t i = 0; data && i < (size_t)W * H; i++) {
                const float *p = f->layer[k] + i * 3;
                double want =
                    to_ap1[c * 3] * p[0] + to_ap1[c * 3 + 1] * p[1] + to_ap1[c * 3 + 2] * p[2];
                /* Half floats: 2^-11 relative. */
                worst = fmax(worst, fabs(data[i] - want) / fmax(fabs(want), 1e-2));
            }
            free(data);
        }
    printf("ACEScg file: its layers against the frame's through AP1, worst %.2e relative\n", worst);
    CHECK(worst < 1e-3);
    unlink(out);
}

/* `tideline render --passes lights` writes the layers into each frame
 * (drawn and read back one by one, not queued), and in the file they add
 * up to Combined to the half floats' rounding. */
static void test_render_command(void)
{
    char dir[] = "/tmp/tideline-light-layers-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char tl[256], pattern[256], second[256];
    snprintf(tl, sizeof tl, "%s/shot.tl", dir);
    snprintf(pattern, sizeof pattern, "%s/f_##.exr", dir);
    snprintf(second, sizeof second, "%s/f_02.exr", dir);
    tl_test_write_file(tl, "tideline 1\nfps 24\nduration 1s\nsize 64x36\nquality preview\n"
                           "set camera.position 0 4 0\nset camera.pitch -5deg\n"
                           "set sun.elevation 12deg\nset sun.azimuth 180deg\n");
    CHECK(tl_run(&(tl_run_opts){0}, "render", tl, "--frames", "1-2", "--passes", "lights", "-o",
                 pattern, "-q", NULL) == 0);
    float *combined = NULL, *layer[TL_LIGHT_SHADED] = {0};
    int w = 0, h = 0, read = 1;
    tl_error err;
    read &= tl_exr_read_channel(second, "ViewLayer.Combined.G", &w, &h, &combined, &err) == 0;
    for (int k = 0; k < TL_LIGHT_SHADED; k++) {
        char name[64];
        snprintf(name, sizeof name, "ViewLayer.light_%s.G", tl_light_layer_name(k));
        read &= tl_exr_read_channel(second, name, &w, &h, &layer[k], &err) == 0;
    }
    CHECK(read && w == 64 && h == 36);
    double worst = 0.0;
    for (int i = 0; read && i < 64 * 36; i++) {
        double sum = 0.0;
        for (int k = 0; k < TL_LIGHT_SHADED; k++)
            sum += layer[k][i];
        worst = fmax(worst, fabs(sum - combined[i]) / fmax(combined[i], 1e-2));
    }
    printf("render --passes lights: the layers against Combined, worst %.2e relative\n", worst);
    CHECK(read && worst < 4e-3); /* eight half floats' rounding */
    free(combined);
    for (int k = 0; k < TL_LIGHT_SHADED; k++)
        free(layer[k]);
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: test_light_layers TIMELINES_DIR TIDELINE\n");
        return 2;
    }
    tl_run_binary = argv[2];
    test_render_command();
    tl_render *r = render_test_open();
    CHECK(r != NULL);
    if (!r)
        TEST_END();
    tl_frame f = {0};
    tl_scene scene;
    tl_cutscene cs;

    /* The hero frame: the boat on the breaking wave's face, in its spray. */
    if (render_layers(r, argv[1], "giant_wave.tl", 250, &f, &scene, &cs) == 0) {
        /* The sky's light is the sky's pixels' (and the fog's, none here);
         * the boat's on the boat; spray, foam, the water's body and its
         * reflection all in view. */
        double sky_on_sky = share_where(&f, TL_LIGHT_SKY, 1, 0, 0.5f, 0);
        double boat_on_boat = share_where(&f, TL_LIGHT_BOAT, 2, 0, 0.0f, 0);
        printf("sky light on the sky's pixels %.4f, the boat's on the boat's %.4f\n", sky_on_sky,
               boat_on_boat);
        CHECK(sky_on_sky > 0.98);
        CHECK(boat_on_boat > 0.999);
        for (int k = 0; k < TL_LIGHT_SHADED; k++)
            if (k != TL_LIGHT_GLITTER) { /* the sun is behind the wave */
                CHECK(layer_total(&f, k) > 0.0);
            }
        check_file(&f, &scene);
    }
    tl_frame_free(&f);
    tl_cutscene_free(&cs);

    /* Under the water, the boat above: no glitter or reflection of the sky
     * from below (the only reflection is the hull's part below the water
     * mirrored in the surface's underside), the water's body most of the
     * light. */
    if (render_layers(r, argv[1], "dive.tl", 200, &f, &scene, &cs) == 0) {
        double all = 0.0;
        for (int k = 0; k < TL_LIGHT_SHADED; k++)
            all += layer_total(&f, k);
        CHECK(layer_total(&f, TL_LIGHT_BODY) > 0.5 * all);
        CHECK(layer_total(&f, TL_LIGHT_GLITTER) == 0.0);
        CHECK(layer_total(&f, TL_LIGHT_REFLECTION) < 0.01 * all);
        CHECK(layer_total(&f, TL_LIGHT_SKY) > 0.0); /* Snell's window */
        CHECK(layer_total(&f, TL_LIGHT_BOAT) > 0.0);
    }
    tl_frame_free(&f);
    tl_cutscene_free(&cs);

    /* The waterline, half above and half below; and dusk in fog, whose
     * haze is the sky's light. */
    if (render_layers(r, argv[1], "dive.tl", 72, &f, &scene, &cs) == 0)
        CHECK(share_where(&f, TL_LIGHT_BODY, 1, 3, 0.5f, 0) > 0.5);
    tl_frame_free(&f);
    tl_cutscene_free(&cs);
    if (render_layers(r, argv[1], "dusk.tl", 48, &f, &scene, &cs) == 0)
        CHECK(share_where(&f, TL_LIGHT_SKY, 1, 0, 0.5f, 1) > 0.0); /* the haze on the water */
    tl_frame_free(&f);
    tl_cutscene_free(&cs);

    tl_render_close(r);
    TEST_END();
}
