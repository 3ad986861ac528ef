/* The hero cutscene, timelines/giant_wave.tl: the boat floats through the
 * wave's passage (finite pose, dry deck, no jitter, lifted high), the
 * camera never dips under the water, a frame rendered alone equals the
 * same frame of a longer run, and a broken boat model stops the commands
 * before any frame. ARGS: the tideline binary, timelines/, tests/meshes/. */
#include <math.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "core/tl_math.h"
#include "timeline/tl_parse.h"
#include "tl_run.h"
#include "tl_test.h"
#include "waves/tl_giant.h"
#include "waves/tl_waves.h"

static const char *timelines, *meshes;
static char dir[] = "/tmp/tideline-cutscene-XXXXXX";

#define run(...) tl_run(&(tl_run_opts){NULL, 0}, __VA_ARGS__)

static void test_floating(void)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/giant_wave.tl", timelines);
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_timeline_parse_file(path, &tl, &diags, &err) == TL_OK);
    long frames = tl_timeline_frame_count(&tl);
    double prev_pitch = 0.0, prev_roll = 0.0, step = 0.0, sink = 0.0, highest = -1e9;
    double camera_clearance = 1e9, tilt = 0.0;
    int finite = 1;
    for (long f = 0; f < frames; f++) {
        double t = tl_timeline_frame_time(&tl, f);
        tl_scene s;
        tl_timeline_eval(&tl, t, &s);
        const tl_boat *b = &s.boat;
        finite &= isfinite(b->position[1]) && isfinite(b->pitch) && isfinite(b->roll);
        tl_waves w;
        tl_waves_init(&w, &s.ocean);
        tl_giant g;
        tl_giant_prepare(&g, &s.giant, t);
        int oct = s.quality.march_octaves, it = s.quality.giant_iterations;
        double water = tl_waves_surface_height(&w, &g, b->position[0], b->position[2], t, oct, it);
        sink = fmax(sink, water - b->position[1]);
        highest = fmax(highest, b->position[1]);
        double under =
            tl_waves_surface_height(&w, &g, s.camera.position[0], s.camera.position[2], t, oct, it);
        camera_clearance = fmin(camera_clearance, s.camera.position[1] - under);
        if (f > 0)
            step = fmax(step, fmax(fabs(b->pitch - prev_pitch), fabs(b->roll - prev_roll)));
        tilt = fmax(tilt, fmax(fabs(b->pitch), fabs(b->roll)));
        prev_pitch = b->pitch;
        prev_roll = b->roll;
    }
    printf("giant_wave.tl, %ld frames: boat up to %.2f m, waterline at most %.3f m under the "
           "water at its centre, largest pitch/roll step %.2f deg and tilt %.1f deg, camera at "
           "least %.2f m above the water\n",
           frames, highest, sink, step / TL_DEG, tilt / TL_DEG, camera_clearance);
    CHECK(finite);
    /* The deck (8% of the built-in hull's length above its waterline) stays
     * above the water: the waterline sinks at most 5% of the length. */
    CHECK(sink <= TL_FLOAT_MAX_SINK * 9.0 + 1e-9);
    CHECK(step < 8.0 * TL_DEG);
    CHECK(tilt < TL_FLOAT_MAX_TILT); /* it does not stand on its stern at the crest */
    CHECK(highest > 10.0);           /* the wave lifts it */
    CHECK(camera_clearance > 1.0);
    tl_timeline_free(&tl);
}

/* Frame 265 (11.04 s, the boat on the wave, with the wake) rendered alone
 * equals frame 265 of a run of 264-266: floating and the wake depend on
 * the frame's time alone. */
static void test_frame_alone(void)
{
    char tl[1024], a[1200], b[1200];
    snprintf(tl, sizeof tl, "%s/giant_wave.tl", timelines);
    snprintf(a, sizeof a, "%s/run_####.exr", dir);
    CHECK(run("render", tl, "-o", a, "--frames", "264-266", "--size", "48x28", "--quality", "draft",
              "-q", NULL) == 0);
    snprintf(a, sizeof a, "%s/alone_####.exr", dir);
    CHECK(run("render", tl, "-o", a, "--frames", "265", "--size", "48x28", "--quality", "draft",
              "-q", NULL) == 0);
    snprintf(a, sizeof a, "%s/run_0265.exr", dir);
    snprintf(b, sizeof b, "%s/alone_0265.exr", dir);
    CHECK(tl_same_bytes(a, b));
    char cmd[1300];
    snprintf(cmd, sizeof cmd, "rm -f %s/*.exr", dir);
    CHECK(system(cmd) == 0);
    /* eval --json prints the pose. */
    CHECK(run("eval", tl, "--at", "11s", "--json", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "\"pitch\": ");
    CHECK_STR_CONTAINS(tl_run_output, "\"roll\": ");
    CHECK_STR_CONTAINS(tl_run_output, "\"under_boat\": ");
}

/* A timeline naming a model that cannot be used: one line naming the
 * timeline's line and the model file, status 1, nothing written. */
static void expect_model_error(const char *model, const char *why)
{
    char tl[1200], png[1200];
    snprintf(tl, sizeof tl, "%s/boat.tl", dir);
    snprintf(png, sizeof png, "%s/x.png", dir);
    FILE *f = fopen(tl, "w");
    CHECK(f != NULL);
    if (!f)
        return;
    fprintf(f, "tideline 1\npath boat\n  0s 0 0\n  5s 0 20\nset boat.model %s\n", model);
    fclose(f);
    for (int c = 0; c < 2; c++) { /* still, then render */
        int status = c == 0 ? run("still", tl, "-o", png, NULL)
                            : run("render", tl, "-o", png, "--frames", "0", NULL);
        CHECK(status == 1);
        CHECK_STR_CONTAINS(tl_run_output, "boat.tl:5:16: error: boat model ");
        CHECK_STR_CONTAINS(tl_run_output, model);
        CHECK_STR_CONTAINS(tl_run_output, why);
        /* Then the timeline's line, and a caret under the model's path. */
        char shown[1400];
        snprintf(shown, sizeof shown, "\n     5 | set boat.model %s\n       |                ^",
                 model);
        CHECK_STR_CONTAINS(tl_run_output, shown);
        CHECK(strstr(tl_run_output, "^~") != NULL);
        int lines = 0;
        for (const char *c = tl_run_output; *c; c++)
            lines += *c == '\n';
        CHECK(lines == 3);               /* the error, the line, the caret */
        CHECK(tl_dir_entries(dir) == 1); /* the timeline only: no image */
    }
    CHECK(run("check", tl, NULL) == 1);
    CHECK_STR_CONTAINS(tl_run_output, why);
    unlink(tl);
}

static void test_bad_models(void)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/nowhere.glb", meshes);
    expect_model_error(path, "no such file");
    snprintf(path, sizeof path, "%s/corrupt.glb", meshes);
    expect_model_error(path, "cannot be read");
    snprintf(path, sizeof path, "%s/lines_only.obj", meshes);
    expect_model_error(path, "has no triangles");
    /* A good one loads and renders. */
    char tl[1200], png[1200];
    snprintf(tl, sizeof tl, "%s/boat.tl", dir);
    snprintf(png, sizeof png, "%s/ok.png", dir);
    FILE *f = fopen(tl, "w");
    if (f) {
        fprintf(f, "tideline 1\npath boat\n  0s 0 0\n  5s 0 20\nset boat.model %s/skiff.gltf\n",
                meshes);
        fclose(f);
    }
    /* At 0 s, the path's start, the boat is under way: its wake is there. */
    CHECK(run("still", tl, "-o", png, "--size", "32x18", "-v", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output,
                       "features: ocean, sun disc, boat, wake, physical sky, level "
                       "of detail, analytic normals, filtered shading, hit polish, boat shadow\n");
    /* The water plate: the boat still floats but nothing of it is drawn. */
    f = fopen(tl, "a");
    if (f) {
        fputs("set boat.visible off\n", f);
        fclose(f);
    }
    CHECK(run("still", tl, "-o", png, "--size", "32x18", "-v", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "features: ocean, sun disc, physical sky, level of detail, "
                                      "analytic normals, filtered shading, hit polish\n");
    unlink(png);
    unlink(tl);
}

/* A soundtrack missing or undecodable: at the `audio` line, naming the
 * file and why, before any frame (still, render and movie alike). */
static void test_bad_audio(void)
{
    char tl[1200], png[1200], text[1200], mp4[1200];
    snprintf(tl, sizeof tl, "%s/sound.tl", dir);
    snprintf(png, sizeof png, "%s/x.png", dir);
    snprintf(mp4, sizeof mp4, "%s/x.mp4", dir);
    snprintf(text, sizeof text, "%s/noise.wav", dir);
    tl_test_write_file(text, "RIFF but not really a sound\n");
    const char *cases[2][3] = {
        {"gone.wav", "sound.tl:2:7: error: sound file '", "gone.wav': No such file"},
        {"noise.wav", "sound.tl:2:7: error: sound file '", "noise.wav' cannot be decoded"}};
    for (int k = 0; k < 2; k++) {
        snprintf(text, sizeof text, "tideline 1\naudio %s 1s\n", cases[k][0]);
        tl_test_write_file(tl, text);
        CHECK(run("still", tl, "-o", png, NULL) == 1);
        CHECK_STR_CONTAINS(tl_run_output, cases[k][1]);
        CHECK_STR_CONTAINS(tl_run_output, cases[k][2]);
        CHECK_STR_CONTAINS(tl_run_output, "\n     2 | audio ");
        CHECK(run("render", tl, "--movie", mp4, NULL) == 1);
        CHECK_STR_CONTAINS(tl_run_output, cases[k][2]);
        CHECK(run("check", tl, NULL) == 1);
        CHECK_STR_CONTAINS(tl_run_output, cases[k][2]);
        CHECK(access(png, F_OK) != 0 && access(mp4, F_OK) != 0);
    }
    snprintf(text, sizeof text, "%s/noise.wav", dir);
    unlink(text);
    unlink(tl);
}

int main(int argc, char **argv)
{
    if (argc < 4 || !mkdtemp(dir))
        return 1;
    tl_run_binary = argv[1];
    timelines = argv[2];
    meshes = argv[3];
    test_floating();
    test_frame_alone();
    test_bad_models();
    test_bad_audio();
    rmdir(dir);
    TEST_END();
}
