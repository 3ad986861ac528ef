/* The peaked, breaking crest through the `tideline` binary, on small
 * frames: a frame does not depend on the frames rendered before it (the
 * break's feature bit switches the program mid-sequence), and giant.fade 0
 * is the wave switched off. argv[1] is the tideline binary. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "image/tl_image_io.h"
#include "tl_run.h"
#include "tl_test.h"

static char dir[] = "/tmp/tideline-crest-XXXXXX";

static char path_buf[4][600];
static const char *in_dir(int slot, const char *name)
{
    snprintf(path_buf[slot], sizeof path_buf[slot], "%s/%s", dir, name);
    return path_buf[slot];
}

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    int ok = fputs(text, f) >= 0;
    return fclose(f) == 0 && ok;
}

/* A peaked, bowed crest 70 m ahead of a low camera, travelling toward it;
 * its break begins at 0.5 s (frame 12 at 24 fps: age 0, not yet broken)
 * and peels outward. Then `extra`, which switches it on or off. */
static void crest_timeline(const char *path, const char *extra)
{
    char text[2048];
    snprintf(text, sizeof text,
             "tideline 1\nfps 24\nduration 2s\nsize 48x28\nquality preview\n"
             "set camera.position 0 5 -70\nset camera.yaw 0deg\nset camera.pitch 2deg\n"
             "set sun.azimuth 160deg\nset sun.elevation 12deg\n"
             "set giant.angle 180deg\nset giant.center 0 0\n"
             "set giant.arrival 1s\nset giant.height 16\nset giant.peak 12\nset giant.bow 20\n"
             "set giant.variation 0.3\nset giant.seed 7\n"
             "set giant.breaking on\nset giant.break_time 0.5s\nset giant.break_drop 0.5\n%s",
             extra);
    CHECK(write_text(path, text));
}

/* Whether two EXR files hold the same pixels, colour and depth, bit for
 * bit (their headers differ: a sequence's frame records its frame number,
 * fps and shutter); *differ counts the values that do not. */
static int same_pixels(const char *a, const char *b, long *differ)
{
    tl_frame fa, fb;
    tl_error err;
    tl_error_clear(&err);
    *differ = -1;
    if (tl_exr_read(a, &fa, &err)) {
        printf("%s: %s\n", a, err.message);
        return 0;
    }
    if (tl_exr_read(b, &fb, &err)) {
        printf("%s: %s\n", b, err.message);
        tl_frame_free(&fa);
        return 0;
    }
    int same = fa.width == fb.width && fa.height == fb.height;
    if (same) {
        size_t n = (size_t)fa.width * fa.height;
        *differ = 0;
        for (size_t i = 0; i < n * 4; i++)
            *differ += memcmp(&fa.color[i], &fb.color[i], sizeof(float)) != 0;
        for (size_t i = 0; i < n; i++)
            *differ += memcmp(&fa.depth[i], &fb.depth[i], sizeof(float)) != 0;
        same = *differ == 0;
    }
    tl_frame_free(&fa);
    tl_frame_free(&fb);
    return same;
}

/* The line of `render -v` that lists frame `frame`'s features (to its
 * end, or to the next message), into out; 0 when there is none. */
static int feature_line(const char *log, int frame, char *out, size_t size)
{
    char key[48];
    snprintf(key, sizeof key, "frame %d: features:", frame);
    const char *at = strstr(log, key);
    if (!at)
        return 0;
    size_t n = 0;
    while (at[n] && at[n] != '\n' && n + 1 < size && (n < 8 || strncmp(at + n, "tideline", 8)))
        n++;
    memcpy(out, at, n);
    out[n] = '\0';
    return 1;
}

/* Frames 12-14 rendered as one sequence (12 before the break, 13 and 14
 * after: the break's program comes in mid-run) against each rendered alone
 * with `still --frame`: the same pixels, bit for bit. */
static void test_frame_independent(void)
{
    const char *tl = in_dir(0, "crest.tl");
    crest_timeline(tl, "set giant.enabled on\n");
    CHECK(tl_run(NULL, "render", tl, "--frames", "12-14", "-q", "-o", in_dir(1, "seq_##.exr"),
                 NULL) == 0);
    for (int f = 12; f <= 14; f++) {
        char frame[8], seq[32], one[32];
        snprintf(frame, sizeof frame, "%d", f);
        snprintf(seq, sizeof seq, "seq_%02d.exr", f);
        snprintf(one, sizeof one, "one_%02d.exr", f);
        CHECK(tl_run(NULL, "still", tl, "--frame", frame, "-o", in_dir(2, one), NULL) == 0);
        long differ;
        int same = same_pixels(in_dir(1, seq), in_dir(2, one), &differ);
        printf("frame %d in a sequence against alone: %ld values differ\n", f, differ);
        CHECK(same);
        unlink(in_dir(1, seq));
        unlink(in_dir(2, one));
    }
    /* The sequence did switch programs: frame 13 breaks, 12 does not. */
    CHECK(tl_run(NULL, "render", tl, "--frames", "12-13", "-v", "-o", in_dir(1, "v_##.exr"),
                 NULL) == 0);
    char line12[512], line13[512];
    CHECK(feature_line(tl_run_output, 12, line12, sizeof line12));
    CHECK(feature_line(tl_run_output, 13, line13, sizeof line13));
    CHECK(!strstr(line12, "breaking crest"));
    CHECK(strstr(line13, "breaking crest") != NULL);
    unlink(in_dir(1, "v_12.exr"));
    unlink(in_dir(1, "v_13.exr"));
    unlink(tl);
}

/* giant.fade 0 renders the same pixels as giant.enabled off, a broken,
 * peaked crest and all; at full fade the wave is in the frame (else the
 * comparison would show nothing). */
static void test_fade_zero_is_off(void)
{
    const char *faded = in_dir(0, "faded.tl"), *off = in_dir(1, "off.tl");
    const char *full = in_dir(2, "full.tl");
    crest_timeline(faded, "set giant.enabled on\nset giant.fade 0\n");
    crest_timeline(off, "set giant.enabled off\n");
    crest_timeline(full, "set giant.enabled on\n");
    CHECK(tl_run(NULL, "still", faded, "--time", "1.2", "-o", in_dir(3, "faded.exr"), NULL) == 0);
    char faded_exr[600];
    snprintf(faded_exr, sizeof faded_exr, "%s", in_dir(3, "faded.exr"));
    CHECK(tl_run(NULL, "still", off, "--time", "1.2", "-o", in_dir(3, "off.exr"), NULL) == 0);
    char off_exr[600];
    snprintf(off_exr, sizeof off_exr, "%s", in_dir(3, "off.exr"));
    CHECK(tl_run(NULL, "still", full, "--time", "1.2", "-o", in_dir(3, "full.exr"), NULL) == 0);
    long differ, shown;
    int same = same_pixels(faded_exr, off_exr, &differ);
    int shows = !same_pixels(in_dir(3, "full.exr"), off_exr, &shown);
    printf("giant.fade 0 against giant.enabled off: %ld values differ (the wave at full fade "
           "changes %ld)\n",
           differ, shown);
    CHECK(same);
    CHECK(shows && shown > 100);
    unlink(faded_exr);
    unlink(off_exr);
    unlink(in_dir(3, "full.exr"));
    unlink(faded);
    unlink(off);
    unlink(full);
}

int main(int argc, char **argv)
{
    if (argc < 2 || !mkdtemp(dir))
        return 1;
    tl_run_binary = argv[1];
    test_frame_independent();
    test_fade_zero_is_off();
    rmdir(dir);
    TEST_END();
}
