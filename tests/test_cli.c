/* The command line as a user meets it: exit statuses, one-line error
 * messages that name the flag or path, and no file left behind by a
 * failed run; what still, check and eval print and write, on small draft
 * frames. The presets' image quality is test_presets_quality's. argv[1]
 * is the tideline binary, argv[2] the shaders folder. */
#include <dirent.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "image/tl_image_io.h"
#include "scene/tl_quality.h"
#include "tl_run.h"
#include "tl_test.h"

static const char *shader_src;
static char dir[] = "/tmp/tideline-cli-XXXXXX";
#define out_text tl_run_output

/* run(env, args..., NULL): the binary's exit status, output in out_text. */
#define run(env, ...) tl_run(&(tl_run_opts){env, 0}, __VA_ARGS__)
#define dir_entries   tl_dir_entries

static int count_lines(const char *s)
{
    int lines = 0;
    for (; *s; s++)
        lines += *s == '\n';
    return lines;
}

static char path_buf[8][512];
static const char *in_dir(int slot, const char *name)
{
    snprintf(path_buf[slot], sizeof path_buf[slot], "%s/%s", dir, name);
    return path_buf[slot];
}

/* A usage error: status 2, one line naming `needle`, nothing written. */
#define EXPECT_USAGE(needle, ...)                                                                  \
    do {                                                                                           \
        CHECK(run(NULL, __VA_ARGS__, NULL) == 2);                                                  \
        CHECK_STR_CONTAINS(out_text, needle);                                                      \
        CHECK(count_lines(out_text) == 1);                                                         \
        CHECK(dir_entries(dir) == 0);                                                              \
    } while (0)

static void test_help_and_version(void)
{
    CHECK(run(NULL, "--help", NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "still");
    CHECK(run(NULL, "still", "--help", NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "--size WxH");
    CHECK_STR_CONTAINS(out_text, "--look-at");
    CHECK(run(NULL, "--version", NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "tideline " TL_VERSION);
    CHECK(run(NULL, NULL) == 2);
    CHECK(run(NULL, "paint", NULL) == 2);
    CHECK_STR_CONTAINS(out_text, "unknown command 'paint'");
}

static void test_bad_flags(void)
{
    const char *png = in_dir(0, "x.png");
    EXPECT_USAGE("unknown option '--bogus'", "still", "--bogus", "-o", png);
    EXPECT_USAGE("--size: 0x5 is out of range", "still", "--size", "0x5", "-o", png);
    EXPECT_USAGE("--size: 20000x10 is out of range", "still", "--size", "20000x10", "-o", png);
    EXPECT_USAGE("--size: expected WIDTHxHEIGHT, got '12'", "still", "--size", "12", "-o", png);
    EXPECT_USAGE("--size: -4x3 is out of range", "still", "--size=-4x3", "-o", png);
    EXPECT_USAGE("--time: 'nan' is not a finite number", "still", "--time", "nan", "-o", png);
    EXPECT_USAGE("--time: 'inf' is not a finite number", "still", "--time", "inf", "-o", png);
    EXPECT_USAGE("--time: unknown time unit 's4' (use s, ms or f)", "still", "--time", "3s4", "-o",
                 png);
    EXPECT_USAGE("--time: '1e999' is too large", "still", "--time", "1e999", "-o", png);
    EXPECT_USAGE("--time needs a value", "still", "-o", png, "--time");
    EXPECT_USAGE("--camera: '0,inf,0' holds a non-finite number", "still", "--camera", "0,inf,0",
                 "-o", png);
    EXPECT_USAGE("--camera: expected X,Y,Z, got '1,2'", "still", "--camera", "1,2", "-o", png);
    EXPECT_USAGE("--fov: '0' is outside (0, 180) degrees", "still", "--fov", "0", "-o", png);
    EXPECT_USAGE("--fov: '180' is outside (0, 180) degrees", "still", "--fov", "180", "-o", png);
    EXPECT_USAGE("--exposure: '-1' is negative", "still", "--exposure", "-1", "-o", png);
    EXPECT_USAGE("--ev: '30' is outside -20..20 stops", "still", "--ev", "30", "-o", png);
    /* The largest frame the language takes: a device that cannot hold it
     * (llvmpipe caps a texture's bytes) says so before drawing anything;
     * one that can renders it. */
    int big = run(NULL, "still", "--size", "16384x16384", "--quality", "draft", "-o", png, NULL);
    CHECK(big == 0 || big == 2);
    if (big == 2) {
        CHECK_STR_CONTAINS(out_text, "tideline still: a 16384x16384 frame is larger than the GPU "
                                     "holds");
        CHECK(access(png, F_OK) != 0);
    }
    unlink(png);
    EXPECT_USAGE("--quality: unknown quality preset 'ultra'", "still", "--quality", "ultra", "-o",
                 png);
    EXPECT_USAGE("look-at target coincides with the camera", "still", "--look-at", "0,1.5,0", "-o",
                 png);
    EXPECT_USAGE("--dither: 'maybe' is not on or off", "still", "--dither", "maybe", "-o", png);
    EXPECT_USAGE("no output file", "still");
    /* The passes: an unknown name lists the valid ones; they are an EXR's
     * layers, so a PNG alone is refused. */
    const char *exr = in_dir(1, "x.exr");
    EXPECT_USAGE("--passes: unknown pass 'vectors' in 'depth,vectors' (passes: combined, depth,",
                 "still", "--passes", "depth,vectors", "-o", exr);
    EXPECT_USAGE("cryptomatte_material, masks (every mask), lights (every light layer), all, none",
                 "still", "--passes", "mask", "-o", exr);
    EXPECT_USAGE("--passes: the passes are layers of an EXR; give -o FILE.exr", "still", "--passes",
                 "depth", "-o", png);
    EXPECT_USAGE("--passes: 'none' stands alone (in 'none,depth')", "render", "x.tl", "--passes",
                 "none,depth", "-o", exr);
    EXPECT_USAGE("cam.txt: unknown format (use .gltf or .glb)", "export-camera", "x.tl", "-o",
                 in_dir(2, "cam.txt"));
    EXPECT_USAGE("nothing to write: give -o FILE.gltf", "export-camera", "x.tl");
    EXPECT_USAGE("-o needs a value", "export-camera", "x.tl", "-o");
    /* Colour: a working space, a display or view the config lacks, a
     * config that cannot be read (named, here and through $OCIO). */
    EXPECT_USAGE("--working-space: 'p3' is not rec709 or acescg", "still", "--working-space", "p3",
                 "-o", exr);
    EXPECT_USAGE("built-in: display 'sRGB' has no view 'Film' (views: ACES 1.0 - SDR Video, "
                 "Un-tone-mapped, Raw)",
                 "still", "--view", "Film", "-o", png);
    EXPECT_USAGE("built-in: no display 'P3' (displays: sRGB)", "still", "--display", "P3", "-o",
                 png);
    EXPECT_USAGE("--ocio: OpenColorIO config /nonexistent/studio.ocio:", "still", "--ocio",
                 "/nonexistent/studio.ocio", "-o", png);
    CHECK(run("OCIO=/nonexistent/env.ocio", "still", "-o", png, NULL) == 2);
    CHECK_STR_CONTAINS(out_text, "OpenColorIO config /nonexistent/env.ocio:");
    CHECK(dir_entries(dir) == 0);
}

/* still --dither off rounds each code, on (the default) takes the code
 * below or above: the two files differ, by one code at most. */
static void test_still_dither(void)
{
    const char *a = in_dir(0, "dither_on.png"), *b = in_dir(1, "dither_off.png");
    CHECK(run(NULL, "still", "--size", "48x27", "-o", a, NULL) == 0);
    CHECK(run(NULL, "still", "--size", "48x27", "--dither", "off", "-o", b, NULL) == 0);
    tl_frame on = {0}, off = {0};
    tl_error err;
    CHECK(tl_png_read(a, &on, NULL, &err) == 0);
    CHECK(tl_png_read(b, &off, NULL, &err) == 0);
    int differ = 0, far = 0;
    for (size_t i = 0; on.display && off.display && i < 48 * 27 * 4; i++) {
        double d = fabs((double)on.display[i] - off.display[i]) * 255.0;
        differ += d > 0.5;
        far += d > 1.5;
    }
    printf("still --dither on against off: %d samples differ, %d by more than a code\n", differ,
           far);
    CHECK(differ > 0 && far == 0);
    tl_frame_free(&on);
    tl_frame_free(&off);
    unlink(a);
    unlink(b);
}

/* still --ev: a stop more halves the light the display shows (a darker
 * frame), and it combines with --exposure as exposure x 2^-ev: --exposure
 * 4 --ev 0 is --exposure 2 --ev -1, pixel for pixel. */
static void test_still_ev(void)
{
    const char *a = in_dir(0, "ev_a.png"), *b = in_dir(1, "ev_b.png"), *c = in_dir(2, "ev_c.png");
    CHECK(run(NULL, "still", "--size", "48x27", "--exposure", "4", "--ev", "0", "-o", a, NULL) ==
          0);
    CHECK(run(NULL, "still", "--size", "48x27", "--exposure", "2", "--ev", "-1", "-o", b, NULL) ==
          0);
    CHECK(run(NULL, "still", "--size", "48x27", "--exposure", "2", "--ev", "1", "-o", c, NULL) ==
          0);
    tl_frame fa = {0}, fb = {0}, fc = {0};
    tl_error err;
    CHECK(tl_png_read(a, &fa, NULL, &err) == 0);
    CHECK(tl_png_read(b, &fb, NULL, &err) == 0);
    CHECK(tl_png_read(c, &fc, NULL, &err) == 0);
    double same = 0.0, bright = 0.0, dark = 0.0;
    for (size_t i = 0; fa.display && fb.display && fc.display && i < 48 * 27 * 4; i++) {
        same = fmax(same, fabs((double)fa.display[i] - fb.display[i]));
        bright += fa.display[i];
        dark += fc.display[i];
    }
    printf("still --ev: --exposure 4 --ev 0 against --exposure 2 --ev -1 differ by %.3g; "
           "--ev 1's mean %.3f of --ev -1's\n",
           same, dark / fmax(bright, 1e-9));
    CHECK(fa.display && same == 0.0 && dark < 0.8 * bright);
    tl_frame_free(&fa);
    tl_frame_free(&fb);
    tl_frame_free(&fc);
    unlink(a);
    unlink(b);
    unlink(c);
}

static void test_bad_outputs(void)
{
    const char *jpg = in_dir(0, "x.jpg");
    EXPECT_USAGE(jpg, "still", "-o", jpg);
    /* A missing folder is made, as render makes it... */
    const char *missing = in_dir(1, "no/such/folder/x.png");
    CHECK(run(NULL, "still", "--size", "8x8", "-o", missing, NULL) == 0);
    CHECK(access(missing, R_OK) == 0);
    char cmd[700];
    snprintf(cmd, sizeof cmd, "rm -rf %s/no", dir);
    CHECK(system(cmd) == 0);
    /* ...but not when another output is bad, and nothing is written. */
    EXPECT_USAGE(jpg, "still", "--size", "8x8", "-o", in_dir(2, "good.png"), "-o", missing, "-o",
                 jpg);
    /* A folder that cannot be written to (root may write anywhere). */
    const char *ro = in_dir(3, "ro");
    mkdir(ro, 0555);
    if (geteuid() != 0) {
        const char *target = in_dir(4, "ro/x.png");
        CHECK(run(NULL, "still", "-o", target, NULL) == 2);
        CHECK_STR_CONTAINS(out_text, target);
        CHECK(dir_entries(ro) == 0);
    } else {
        printf("skipped the read-only folder case: running as root\n");
    }
    rmdir(ro);
    const char *as_dir = in_dir(5, "adir.png");
    mkdir(as_dir, 0755);
    CHECK(run(NULL, "still", "-o", as_dir, NULL) == 2);
    CHECK_STR_CONTAINS(out_text, as_dir);
    rmdir(as_dir);
}

static void test_runtime_failures(void)
{
    /* No EGL vendor at all: every platform fails and the message lists them. */
    const char *png = in_dir(0, "x.png");
    CHECK(run("__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/vendor.json", "still", "--size", "8x8",
              "-o", png, NULL) == 1);
    CHECK_STR_CONTAINS(out_text, "no headless OpenGL 3.3 context");
    CHECK_STR_CONTAINS(out_text, "device:");
    CHECK_STR_CONTAINS(out_text, "surfaceless:");
    CHECK_STR_CONTAINS(out_text, "default:");
    CHECK(dir_entries(dir) == 0);

    CHECK(run("TIDELINE_EGL_PLATFORM=vulkan", "still", "-o", png, NULL) == 2);
    CHECK_STR_CONTAINS(out_text, "TIDELINE_EGL_PLATFORM='vulkan'");

    /* A broken shader from --shader-dir: the compiler's message names the
     * file it came from, and nothing is written. */
    const char *shaders = in_dir(1, "shaders");
    mkdir(shaders, 0755);
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "cp %s/* %s/ && printf 'this is not glsl;\\n' >> %s/water.glsl",
             shader_src, shaders, shaders);
    CHECK(system(cmd) == 0);
    CHECK(run(NULL, "still", "--size", "8x8", "--shader-dir", shaders, "-o", png, NULL) == 1);
    CHECK_STR_CONTAINS(out_text, "failed to compile");
    CHECK_STR_CONTAINS(out_text, "water.glsl:");
    snprintf(cmd, sizeof cmd, "rm -rf %s", shaders);
    CHECK(system(cmd) == 0);
    CHECK(dir_entries(dir) == 0);
    EXPECT_USAGE("is not a folder", "still", "--shader-dir", in_dir(2, "nope"), "-o", png);
}

static void test_success(void)
{
    const char *png = in_dir(0, "ok.png");
    const char *exr = in_dir(1, "ok.exr");
    CHECK(run(NULL, "still", "--size", "32x18", "--time", "2.5", "--yaw", "0.3rad", "-o", png, "-o",
              exr, NULL) == 0);
    CHECK(access(png, R_OK) == 0);
    CHECK(access(exr, R_OK) == 0);
    CHECK(dir_entries(dir) == 2); /* no temporary files left */
    CHECK(run(NULL, "still", "-v", "--size", "16x16", "-o", png, NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "OpenGL");
    CHECK_STR_CONTAINS(out_text, "features: ocean, sun disc, physical sky, level of detail, "
                                 "analytic normals, filtered shading, hit polish\n");
    /* A timeline's giant wave joins the feature set only while it is there. */
    const char *tl = in_dir(2, "wave.tl");
    FILE *f = fopen(tl, "w");
    CHECK(f != NULL);
    if (f) {
        /* The camera well above the 12 m crest, 100 m before it. */
        fputs("tideline 1\nset giant.enabled on\nset giant.arrival 1s\n"
              "set camera.position 0 30 -100\nkey giant.fade\n  0s 0\n  1s 1\n",
              f);
        fclose(f);
    }
    CHECK(run(NULL, "still", tl, "-v", "--time", "0", "--size", "16x16", "-o", png, NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "features: ocean, sun disc, physical sky, level of detail, "
                                 "analytic normals, filtered shading, hit polish\n");
    CHECK(run(NULL, "still", tl, "-v", "--time", "0.5", "--size", "16x16", "-o", png, NULL) == 0);
    /* The wave's spindrift, glow and the glow's caustics come with it (a
     * 6 m crest at half fade is tall enough to shed spray; the sun is up). */
    CHECK_STR_CONTAINS(out_text, "features: ocean, sun disc, giant wave, physical sky, level of "
                                 "detail, analytic normals, filtered shading, hit polish, spray, "
                                 "crest glow, crest caustics\n");
    /* eval reports the wave and the water under the camera and the crest. */
    CHECK(run(NULL, "eval", tl, "--at", "1s", NULL) == 0);
    /* The crest reaches the centre at giant.arrival, at the deep-water
     * speed of an 80 m wave, sqrt(9.81 * 80 / 2pi) = 11.1761 m/s. */
    CHECK_STR_CONTAINS(out_text, ", 0 m past the centre, 11.1761 m/s\n");
    const char *crest = strstr(out_text, "water under crest");
    double height = 0.0;
    CHECK(crest && sscanf(crest, "water under crest %lf m", &height) == 1);
    CHECK(height > 11.0 && height < 13.0); /* 12 m crest on a 1 m ocean band */
    CHECK_STR_CONTAINS(out_text, "water under camera");
    CHECK(run(NULL, "eval", tl, "--at", "0s", "--json", NULL) == 0);
    CHECK_STR_CONTAINS(out_text,
                       "\"giant\": null, \"underwater\": \"no\", \"water\": {\"under_camera\": ");
    /* The timeline's `passes` line makes a multilayer EXR; --passes none
     * the plain one. The sky's mask is 1 in the top row, the water's in
     * the bottom one (the default camera looks at the horizon). */
    f = fopen(tl, "w");
    if (f) {
        fputs("tideline 1\npasses mask_sky mask_water,depth\n", f);
        fclose(f);
    }
    CHECK(run(NULL, "still", tl, "--size", "32x18", "-o", exr, NULL) == 0);
    int w = 0, h = 0;
    float *sky = NULL, *water = NULL, *plain = NULL;
    tl_error err;
    CHECK(tl_exr_read_channel(exr, "ViewLayer.mask_sky.X", &w, &h, &sky, &err) == 0);
    CHECK(tl_exr_read_channel(exr, "ViewLayer.mask_water.X", &w, &h, &water, &err) == 0);
    if (sky && water)
        CHECK(sky[0] == 1.0f && water[0] == 0.0f && sky[32 * 17] == 0.0f && water[32 * 17] == 1.0f);
    CHECK(tl_exr_read_channel(exr, "ViewLayer.mask_boat.X", &w, &h, &plain, &err) != 0);
    CHECK(run(NULL, "still", tl, "--size", "32x18", "--passes", "none", "-o", exr, NULL) == 0);
    CHECK(tl_exr_read_channel(exr, "R", &w, &h, &plain, &err) == 0);
    free(sky);
    free(water);
    free(plain);
    /* export-camera: a binary glTF (its magic and version 2), and the JSON
     * one naming the camera, the sun and the boat's node. */
    const char *glb = in_dir(3, "cam.glb"), *gltf = in_dir(4, "cam.gltf");
    f = fopen(tl, "w");
    if (f) {
        fputs("tideline 1\nduration 1s\npath boat\n  0s 0 10\n  1s 0 14\n", f);
        fclose(f);
    }
    CHECK(run(NULL, "export-camera", tl, "-o", glb, NULL) == 0);
    CHECK(run(NULL, "export-camera", tl, "-o", gltf, NULL) == 0);
    unsigned char head[8] = {0};
    FILE *g = fopen(glb, "rb");
    CHECK(g && fread(head, 1, 8, g) == 8);
    if (g)
        fclose(g);
    CHECK(memcmp(head, "glTF", 4) == 0 && head[4] == 2);
    static char json[1 << 16];
    g = fopen(gltf, "rb");
    size_t got = g ? fread(json, 1, sizeof json - 1, g) : 0;
    if (g)
        fclose(g);
    json[got] = '\0';
    CHECK_STR_CONTAINS(json, "\"name\": \"camera\"");
    CHECK_STR_CONTAINS(json, "\"KHR_lights_punctual\"");
    CHECK_STR_CONTAINS(json, "\"name\": \"boat\"");
    CHECK_STR_CONTAINS(json, "data:application/octet-stream;base64,");
    unlink(glb);
    unlink(gltf);
    unlink(tl);
    unlink(png);
    unlink(exr);
}

/* check on several files, warnings and --strict; eval's number format;
 * the quality knobs recorded in an EXR. */
static void test_papercuts(void)
{
    const char *good = in_dir(0, "good.tl");
    const char *warn = in_dir(1, "warn.tl");
    const char *bad = in_dir(2, "bad.tl");
    tl_test_write_file(good, "tideline 1\nset camera.fov 60\nset camera.position 0 2.5 0\n");
    tl_test_write_file(warn, "tideline 1\nduration 2s\nset camera.pitch 0.2\n"
                             "key camera.yaw\n  0s 0\n  5s 10\n");
    tl_test_write_file(bad, "tideline 1\nset camera.fovv 60\n");

    CHECK(run(NULL, "check", good, warn, NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "good.tl: ok\n");
    CHECK_STR_CONTAINS(out_text, "warn.tl: ok (with warnings)\n");
    CHECK_STR_CONTAINS(out_text, "warn.tl:3:18: warning: camera.pitch 0.2 is read as degrees");
    CHECK_STR_CONTAINS(out_text, "radians");
    CHECK_STR_CONTAINS(out_text, "warn.tl:6:3: warning: key at 5 s lies past the end of the "
                                 "timeline (2 s)\n");
    /* A bare number that fits as frames: the warning says what it would be. */
    const char *frames = in_dir(4, "frames.tl");
    tl_test_write_file(frames, "tideline 1\nfps 24\nduration 10s\nkey camera.fov\n  0s 50\n"
                               "  192 40\n  200 30\n");
    CHECK(run(NULL, "check", frames, NULL) == 0);
    CHECK_STR_CONTAINS(out_text,
                       "frames.tl:6:3: warning: key at 192 s lies past the end of the "
                       "timeline (10 s); 192 is read as seconds: 192f is frame 192 = 8 s");
    CHECK(strstr(out_text, "frames.tl:7") == NULL); /* once a channel */
    CHECK(run(NULL, "check", "--strict", good, warn, NULL) == 1);
    CHECK_STR_CONTAINS(out_text, "warn.tl: failed (--strict");
    CHECK(run(NULL, "check", good, bad, warn, NULL) == 1); /* the worst file wins */
    CHECK_STR_CONTAINS(out_text, "good.tl: ok\n");
    CHECK_STR_CONTAINS(out_text, "bad.tl:2:5: error: unknown channel 'camera.fovv'");
    CHECK_STR_CONTAINS(out_text, "warn.tl: ok (with warnings)\n");

    /* Values as the language writes them: 60 deg, not 59.99999999999999
     * or 6e+01; 2.5 m, not 2.5000000000000004. */
    CHECK(run(NULL, "eval", good, "--at", "0", NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "camera.fov                 60 deg\n");
    CHECK_STR_CONTAINS(out_text, "camera.position            0 2.5 0 m\n");
    CHECK(strstr(out_text, "warning") == NULL);

    /* A time outside the timeline renders (the keys' ends hold), with a
     * word: a frame past the end is usually a typo or the wrong fps. */
    const char *png = in_dir(3, "past.png");
    CHECK(run(NULL, "still", warn, "--frame", "96", "--size", "16x16", "--quality", "draft", "-o",
              png, NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "tideline still: warning: --frame 96 (4 s) is past the end of the "
                                 "timeline (0 to 2 s, frames 0-47 at 24 fps)");
    CHECK(access(png, F_OK) == 0);
    unlink(png);
    CHECK(run(NULL, "eval", warn, "--at", "-1s", NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "tideline eval: warning: --at -1s (-1 s) is before the timeline");
    CHECK(run(NULL, "eval", warn, "--at", "2s", NULL) == 0);
    CHECK(strstr(out_text, "is past the end") == NULL);

    const char *exr = in_dir(3, "q.exr");
    CHECK(run(NULL, "still", good, "--size", "16x16", "--quality", "draft", "-o", exr, NULL) == 0);
    char name[32] = "";
    double v = 0.0;
    tl_error err;
    CHECK(tl_exr_read_attr_string(exr, "tideline/quality", name, sizeof name, &err) == 0);
    CHECK(strcmp(name, "draft") == 0);
    tl_quality q;
    CHECK(tl_quality_preset("draft", &q, &err) == 0);
    CHECK(tl_exr_read_attr_double(exr, "tideline/march_octaves", &v, &err) == 0);
    CHECK(v == q.march_octaves);
    CHECK(tl_exr_read_attr_double(exr, "tideline/march_steps", &v, &err) == 0);
    CHECK(v == q.march_steps);
    CHECK(tl_exr_read_attr_double(exr, "tideline/hit_epsilon", &v, &err) == 0);
    CHECK(v == q.hit_epsilon);
    CHECK(tl_exr_read_attr_double(exr, "tideline/spp", &v, &err) == 0);
    CHECK(v == q.spp);
    CHECK(tl_exr_read_attr_double(exr, "tideline/giant_iterations", &v, &err) == 0);
    CHECK(v == q.giant_iterations);
    CHECK(tl_exr_read_attr_double(exr, "tideline/facing_normals", &v, &err) == 0);
    CHECK(v == q.facing_normals && v == 1.0);
    unlink(good);
    unlink(warn);
    unlink(bad);
    unlink(exr);
}

int main(int argc, char **argv)
{
    if (argc < 3 || !mkdtemp(dir))
        return 1;
    tl_run_binary = argv[1];
    shader_src = argv[2];
    test_help_and_version();
    test_bad_flags();
    test_still_dither();
    test_still_ev();
    test_bad_outputs();
    test_runtime_failures();
    test_success();
    test_papercuts();
    rmdir(dir);
    TEST_END();
}
