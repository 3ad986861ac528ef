/* Exposure that meters itself (render.auto_exposure), end to end through
 * the binary on small frames: calm.tl and dusk.tl without their hand-set
 * exposure come out near mid-grey; a frame is the same in `still`, in a
 * `render` of a few frames and in a farm chunk; after a cut from the sky
 * to the water the exposure adapts over the time constant (at once with
 * render.adapt_time 0); render.ev stays a compensation on top, and a
 * fixed --exposure turns the meter off. ARGS: the binary, timelines/. */
#include <math.h>
#include <sys/stat.h>

#include "image/tl_frame.h"
#include "image/tl_image_io.h"
#include "tl_run.h"
#include "tl_test.h"

static char dir[] = "/tmp/tideline-exposure-XXXXXX";
static const char *timelines;

/* The band a metered frame's mean display luminance (sRGB-encoded, 0..1)
 * lies in: the meter brings the log-average scene luminance to mid-grey
 * (0.18) before the tonemap, which a frame of sky and sea shows as a
 * mean of about 0.3 to 0.4 (docs/rendering.md#exposure). */
#define MEAN_LOW  0.22
#define MEAN_HIGH 0.50

static double mean_display(const char *png)
{
    tl_frame f;
    tl_error err;
    if (tl_png_read(png, &f, NULL, &err) != 0) {
        CHECK(!"readable PNG");
        return -1.0;
    }
    double sum = 0.0;
    size_t n = (size_t)f.width * (size_t)f.height;
    for (size_t i = 0; i < n; i++)
        sum += 0.2126 * f.display[4 * i] + 0.7152 * f.display[4 * i + 1] +
               0.0722 * f.display[4 * i + 2];
    tl_frame_free(&f);
    return sum / (double)n;
}

static int same_pixels(const char *a, const char *b)
{
    tl_frame fa, fb;
    tl_error err;
    int same = tl_png_read(a, &fa, NULL, &err) == 0 && tl_png_read(b, &fb, NULL, &err) == 0 &&
               fa.width == fb.width && fa.height == fb.height &&
               memcmp(fa.display, fb.display,
                      sizeof(float) * 4 * (size_t)fa.width * (size_t)fa.height) == 0;
    tl_frame_free(&fa);
    tl_frame_free(&fb);
    return same;
}

/* The bundled timeline `name` without its render.exposure and render.ev
 * lines (and keys), metered instead: written to dir/NAME_auto.tl. */
static void metered_copy(const char *name, char *out, size_t size)
{
    char src[1024], line[4096];
    snprintf(src, sizeof src, "%s/%s.tl", timelines, name);
    snprintf(out, size, "%s/%s_auto.tl", dir, name);
    FILE *in = fopen(src, "r"), *to = fopen(out, "w");
    CHECK(in && to);
    if (!in || !to)
        return;
    int skipping = 0;
    while (fgets(line, sizeof line, in)) {
        if (skipping && line[0] == ' ')
            continue;
        skipping = strncmp(line, "key render.", 11) == 0;
        if (skipping || strncmp(line, "set render.ev", 13) == 0 ||
            strncmp(line, "set render.exposure", 19) == 0)
            continue;
        fputs(line, to);
    }
    fputs("set render.exposure auto\n", to);
    fclose(in);
    fclose(to);
}

static double still_mean(const char *timeline, const char *time, const char *extra)
{
    char png[1024];
    snprintf(png, sizeof png, "%s/still.png", dir);
    int rc =
        extra ? tl_run(NULL, "still", timeline, "--time", time, "--size", "96x54", extra, "-o", png,
                       NULL)
              : tl_run(NULL, "still", timeline, "--time", time, "--size", "96x54", "-o", png, NULL);
    CHECK(rc == 0);
    if (rc)
        fprintf(stderr, "%s", tl_run_output);
    return mean_display(png);
}

static void test_mid_grey(void)
{
    const char *names[2] = {"calm", "dusk"};
    const char *times[3] = {"1s", "6s", "11s"};
    for (int k = 0; k < 2; k++) {
        char tl[1024];
        metered_copy(names[k], tl, sizeof tl);
        for (int i = 0; i < 3; i++) {
            double m = still_mean(tl, times[i], NULL);
            printf("%s at %s: mean display %.3f\n", names[k], times[i], m);
            CHECK(m > MEAN_LOW && m < MEAN_HIGH);
        }
    }
    /* render.ev on top: a stop less light; --exposure 2 is a fixed
     * exposure, as if no meter were there. */
    char tl[1024];
    metered_copy("calm", tl, sizeof tl);
    double metered = still_mean(tl, "6s", NULL), darker = still_mean(tl, "6s", "--ev=1");
    CHECK(darker < metered - 0.05);
    char fixed[1024], plain[1024];
    snprintf(fixed, sizeof fixed, "%s/fixed.png", dir);
    snprintf(plain, sizeof plain, "%s/plain.png", dir);
    char plain_tl[1024];
    snprintf(plain_tl, sizeof plain_tl, "%s/calm.tl", timelines);
    CHECK(tl_run(NULL, "still", tl, "--time", "6s", "--size", "96x54", "--exposure", "2", "--ev",
                 "0", "-o", fixed, NULL) == 0);
    CHECK(tl_run(NULL, "still", plain_tl, "--time", "6s", "--size", "96x54", "--exposure", "2",
                 "--ev", "0", "-o", plain, NULL) == 0);
    CHECK(same_pixels(fixed, plain));
}

/* Frame 100 of the metered dusk: alone, among its neighbours, in a chunk. */
static void test_same_everywhere(void)
{
    char tl[1024], alone[1024], run[1024], chunk[1024], p[1024];
    metered_copy("dusk", tl, sizeof tl);
    snprintf(alone, sizeof alone, "%s/alone.png", dir);
    snprintf(run, sizeof run, "%s/run/f_####.png", dir);
    snprintf(chunk, sizeof chunk, "%s/chunk/f_####.png", dir);
    CHECK(tl_run(NULL, "still", tl, "--frame", "100", "--size", "96x54", "-o", alone, NULL) == 0);
    CHECK(tl_run(NULL, "render", tl, "--frames", "97-101", "--size", "96x54", "-o", run, "-q",
                 NULL) == 0);
    /* 384 frames in 32 chunks: chunk 8 holds frames 96..107. */
    CHECK(tl_run(NULL, "render", tl, "--chunk", "8/32", "--size", "96x54", "-o", chunk, "-q",
                 NULL) == 0);
    snprintf(p, sizeof p, "%s/run/f_0100.png", dir);
    CHECK(same_pixels(alone, p));
    snprintf(p, sizeof p, "%s/chunk/f_0100.png", dir);
    CHECK(same_pixels(alone, p));
}

/* Looking at the bright sky until 2 s, then cut to the dark water. */
static void test_adapts_after_a_cut(void)
{
    char tl[1024], text[1024];
    snprintf(tl, sizeof tl, "%s/cut.tl", dir);
    for (int instant = 0; instant < 2; instant++) {
        snprintf(text, sizeof text,
                 "tideline 1\nduration 8s\nset render.exposure auto\n%s"
                 "set sun.elevation 40deg\nset camera.position 0 3 0\n"
                 "key camera.pitch\n  0s 35deg\n  2s cut -70deg\n",
                 instant ? "set render.adapt_time 0\n" : "");
        tl_test_write_file(tl, text);
        double after = still_mean(tl, "2.05s", NULL), settled = still_mean(tl, "6s", NULL);
        double sky = still_mean(tl, "1.9s", NULL);
        printf("adapt_time %s: sky %.3f, just after the cut %.3f, 4 s on %.3f\n",
               instant ? "0" : "1 s", sky, after, settled);
        if (instant)
            CHECK(fabs(after - settled) < 0.02);
        else
            CHECK(after < settled - 0.1); /* still exposed for the sky */
        CHECK(settled > MEAN_LOW && settled < MEAN_HIGH);
    }
}

int main(int argc, char **argv)
{
    if (argc < 3 || !mkdtemp(dir))
        return 1;
    tl_run_binary = argv[1];
    timelines = argv[2];
    test_mid_grey();
    test_same_everywhere();
    test_adapts_after_a_cut();
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    TEST_END();
}
