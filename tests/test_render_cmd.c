/* tideline render end to end (small frames on llvmpipe): files, frame
 * selection, reproducibility, motion blur and cuts, movies, interruption
 * and resume, a full disk, and bad input. ARGS: the tideline binary, and
 * optionally which half (see main). */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <sys/stat.h>
#include <time.h>

#include "image/tl_image_io.h"
#include "render/tl_render.h"
#include "timeline/tl_parse.h"
#include "tl_run.h"
#include "tl_test.h"

#ifndef F_SETPIPE_SZ
#define F_SETPIPE_SZ 1031 /* Linux's; <fcntl.h> has it only with _GNU_SOURCE */
#endif

static char dir[] = "/tmp/tideline-render-XXXXXX";
static char six_path[600], cut_path[600];

/* Six frames at 24 fps: the camera turns, so every frame differs. */
static const char six_frames[] = "tideline 1\n"
                                 "fps 24\n"
                                 "duration 6f\n"
                                 "size 48x28\n"
                                 "quality draft\n"
                                 "key camera.yaw linear\n"
                                 "  0s  0\n"
                                 "  6f  30\n";

/* A cut at 0.1 s, between frame 2 (0.0833 s) and frame 3 (0.125 s): before
 * it the camera looks up at the sky, after it down at the water. */
static const char with_cut[] = "tideline 1\n"
                               "fps 24\n"
                               "duration 6f\n"
                               "size 48x28\n"
                               "quality draft\n"
                               /* The seed sky's broad sun lobe: the physical sun's
                                * glitter is a few very bright pixels, which make a
                                * 48x28 frame's mean luminance jump between sub-frames. */
                               "set sky.model seed\n"
                               "key camera.pitch\n"
                               "  0s      50deg\n"
                               "  0.1s    cut -50deg\n";

static const char *in_dir(char *buf, size_t size, const char *name)
{
    snprintf(buf, size, "%s/%s", dir, name);
    return buf;
}

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return 1;
    fputs(text, f);
    return fclose(f);
}

static int exists(const char *path)
{
    return access(path, F_OK) == 0;
}

static void rm_rf(const char *path)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", path);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", path);
}

static double mean_luminance_rows(const tl_frame *f, int row0, int rows)
{
    double sum = 0.0;
    for (int y = row0; y < row0 + rows; y++)
        for (int x = 0; x < f->width; x++) {
            const float *c = f->color + ((size_t)y * f->width + x) * 4;
            sum += 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
        }
    return sum / (rows * f->width);
}

static void test_six_frames(void)
{
    char out[256], pattern[600], a[600], b[600];
    in_dir(out, sizeof out, "six");
    snprintf(pattern, sizeof pattern, "%s/shot_####.exr", out);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "-q", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "6 frames written, 0 skipped");
    CHECK(tl_dir_entries(out) == 6);
    tl_frame frames[6];
    for (int i = 0; i < 6; i++) {
        snprintf(a, sizeof a, "%s/shot_%04d.exr", out, i);
        tl_error err;
        memset(&frames[i], 0, sizeof frames[i]);
        CHECK(tl_exr_read(a, &frames[i], &err) == 0);
        CHECK(frames[i].width == 48 && frames[i].height == 28);
        double t = -1.0, fps = 0.0;
        CHECK(tl_exr_read_attr_double(a, "tideline/time", &t, &err) == 0);
        CHECK(tl_exr_read_attr_double(a, "tideline/fps", &fps, &err) == 0);
        CHECK(t == i / 24.0 && fps == 24.0); /* frame / fps, exactly */
        char name[600];
        CHECK(tl_exr_read_attr_string(a, "tideline/timeline", name, sizeof name, &err) == 0);
        CHECK(strcmp(name, six_path) == 0);
    }
    for (int i = 1; i < 6; i++) /* consecutive frames differ */
        CHECK(memcmp(frames[i].color, frames[i - 1].color, 48 * 28 * 4 * sizeof(float)) != 0);
    for (int i = 0; i < 6; i++)
        tl_frame_free(&frames[i]);

    /* The same frames again, separately and as PNG: identical bytes. */
    char again[256];
    in_dir(again, sizeof again, "again");
    snprintf(pattern, sizeof pattern, "%s/shot_####.exr", again);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "3-5", "-q", NULL) == 0);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "0-2", "-q", NULL) == 0);
    for (int i = 0; i < 6; i++) {
        snprintf(a, sizeof a, "%s/shot_%04d.exr", out, i);
        snprintf(b, sizeof b, "%s/shot_%04d.exr", again, i);
        CHECK(tl_same_bytes(a, b));
    }
    /* Four frames encoded side by side: the same files. */
    snprintf(pattern, sizeof pattern, "%s/w4/shot_####.exr", again);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--writers", "4", "-q", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "6 frames written");
    for (int i = 0; i < 6; i++) {
        snprintf(a, sizeof a, "%s/shot_%04d.exr", out, i);
        snprintf(b, sizeof b, "%s/w4/shot_%04d.exr", again, i);
        CHECK(tl_same_bytes(a, b));
    }
    snprintf(pattern, sizeof pattern, "%s/png/f_##.png", out);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "4", "--png-bits", "16", "-q",
                 NULL) == 0);
    snprintf(a, sizeof a, "%s/png/f_04.png", out);
    tl_frame p = {0};
    int bits = 0;
    tl_error err;
    CHECK(tl_png_read(a, &p, &bits, &err) == 0 && bits == 16 && p.width == 48);
    /* 8 bits, dithered (the default) and not: each code within one of
     * the 16-bit value, the same file twice, and --dither off the nearest
     * code. */
    tl_frame q[2] = {{0}, {0}};
    const char *dither[2] = {"on", "off"};
    for (int k = 0; k < 2; k++) {
        snprintf(pattern, sizeof pattern, "%s/png8%s/f_##.png", out, dither[k]);
        CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "4", "--dither",
                     dither[k], "-q", NULL) == 0);
        snprintf(b, sizeof b, "%s/png8%s/f_04.png", out, dither[k]);
        CHECK(tl_png_read(b, &q[k], &bits, &err) == 0 && bits == 8);
    }
    int within = 1, nearest = 1, differ = 0;
    for (size_t i = 0; p.display && q[0].display && q[1].display && i < 48 * 28 * 4; i++) {
        if (i % 4 == 3)
            continue;
        double exact = p.display[i] * 255.0;
        within &= fabs(q[0].display[i] * 255.0 - exact) < 1.0 + 1e-3;
        nearest &= fabs(q[1].display[i] * 255.0 - floor(exact + 0.5)) < 0.01 ||
                   fabs(exact - floor(exact) - 0.5) < 0.01; /* a tie either way */
        differ += q[0].display[i] != q[1].display[i];
    }
    printf("8-bit PNG against 16-bit: dithered within a code %d, --dither off the nearest %d, "
           "%d samples differ\n",
           within, nearest, differ);
    CHECK(within && nearest && differ > 0);
    tl_frame_free(&q[0]);
    tl_frame_free(&q[1]);
    tl_frame_free(&p);
    rm_rf(out);
    rm_rf(again);
}

/* Every -o is written: a PNG and an EXR (with its passes) of each frame.
 * --skip-existing renders a frame again when any of its files is missing,
 * and two patterns naming the same files are a usage error. */
static void test_several_outputs(void)
{
    char out[256], png[600], exr[600], f[600];
    in_dir(out, sizeof out, "both");
    snprintf(png, sizeof png, "%s/p/f_####.png", out);
    snprintf(exr, sizeof exr, "%s/e/f_####.exr", out);
    CHECK(tl_run(NULL, "render", six_path, "-o", png, "-o", exr, "--passes", "depth", "--frames",
                 "1-3", "-q", NULL) == 0);
    for (int i = 1; i <= 3; i++) {
        snprintf(f, sizeof f, "%s/p/f_%04d.png", out, i);
        CHECK(exists(f));
        snprintf(f, sizeof f, "%s/e/f_%04d.exr", out, i);
        CHECK(exists(f));
    }
    float *depth = NULL;
    int w = 0, h = 0;
    tl_error err;
    CHECK(tl_exr_read_channel(f, "ViewLayer.Depth.Z", &w, &h, &depth, &err) == 0 && w > 0);
    free(depth);
    snprintf(f, sizeof f, "%s/e/f_0002.exr", out);
    CHECK(unlink(f) == 0);
    CHECK(tl_run(NULL, "render", six_path, "-o", png, "-o", exr, "--passes", "depth", "--frames",
                 "1-3", "--skip-existing", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "1 frame written, 2 skipped");
    CHECK(exists(f));
    CHECK(tl_run(NULL, "render", six_path, "-o", png, "-o", png, NULL) == 2);
    CHECK_STR_CONTAINS(tl_run_output, "name the same file");
    rm_rf(out);
}

static void test_selection(void)
{
    char out[256], pattern[600], f[600];
    in_dir(out, sizeof out, "sel");
    snprintf(pattern, sizeof pattern, "%s/s_####.png", out);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "0-1,4,3-5:2", "-q", NULL) ==
          0);
    const int expect[6] = {1, 1, 0, 1, 1, 1}; /* 0,1,4 and 3,5 */
    for (int i = 0; i < 6; i++) {
        snprintf(f, sizeof f, "%s/s_%04d.png", out, i);
        CHECK(exists(f) == expect[i]);
    }
    rm_rf(out);
    /* Chunks 0/4..3/4 of 6 frames: 1, 2, 1, 2 frames, together all six. */
    const int sizes[4] = {1, 2, 1, 2};
    for (int c = 0; c < 4; c++) {
        char chunk[16];
        snprintf(chunk, sizeof chunk, "%d/4", c);
        CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--chunk", chunk, "-q", NULL) == 0);
        CHECK(tl_dir_entries(out) == sizes[0] + (c >= 1 ? sizes[1] : 0) + (c >= 2 ? sizes[2] : 0) +
                                         (c >= 3 ? sizes[3] : 0));
    }
    snprintf(f, sizeof f, "%s/s_0000.png", out);
    CHECK(exists(f));
    snprintf(f, sizeof f, "%s/s_0005.png", out);
    CHECK(exists(f));
    rm_rf(out);
}

static void test_motion_blur(void)
{
    char out[256], pattern[600], sharp[600], blurred[600];
    in_dir(out, sizeof out, "blur");
    snprintf(pattern, sizeof pattern, "%s/sharp_####.exr", out);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "3", "-q", NULL) == 0);
    snprintf(pattern, sizeof pattern, "%s/blur_####.exr", out);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "3", "--shutter", "180",
                 "--shutter-samples", "4", "-q", NULL) == 0);
    snprintf(sharp, sizeof sharp, "%s/sharp_0003.exr", out);
    snprintf(blurred, sizeof blurred, "%s/blur_0003.exr", out);
    tl_frame s = {0}, b = {0};
    tl_error err;
    CHECK(tl_exr_read(sharp, &s, &err) == 0 && tl_exr_read(blurred, &b, &err) == 0);
    if (s.color && b.color)
        CHECK(memcmp(s.color, b.color, 48 * 28 * 4 * sizeof(float)) != 0);
    tl_frame_free(&s);
    tl_frame_free(&b);

    /* Frame 2's shutter (360 deg: 0.0625..0.104 s) contains the cut at
     * 0.1 s: it must show only the sky shot, exactly as the sharp frame
     * does in its top rows (sky, bright) -- no water from after the cut. */
    snprintf(pattern, sizeof pattern, "%s/cut_####.exr", out);
    CHECK(tl_run(NULL, "render", cut_path, "-o", pattern, "--frames", "2-3", "--shutter", "360",
                 "-q", NULL) == 0);
    snprintf(pattern, sizeof pattern, "%s/cutsharp_####.exr", out);
    CHECK(tl_run(NULL, "render", cut_path, "-o", pattern, "--frames", "2-3", "-q", NULL) == 0);
    for (int frame = 2; frame <= 3; frame++) {
        snprintf(sharp, sizeof sharp, "%s/cutsharp_%04d.exr", out, frame);
        snprintf(blurred, sizeof blurred, "%s/cut_%04d.exr", out, frame);
        CHECK(tl_exr_read(sharp, &s, &err) == 0 && tl_exr_read(blurred, &b, &err) == 0);
        if (s.color && b.color) {
            double ls = mean_luminance_rows(&s, 0, 28), lb = mean_luminance_rows(&b, 0, 28);
            printf("frame %d: sharp luminance %.4f, blurred %.4f\n", frame, ls, lb);
            CHECK(fabs(ls - lb) < 0.05 * ls); /* a blur across the cut would mix the shots */
        }
        tl_frame_free(&s);
        tl_frame_free(&b);
    }

    /* The shutter interval itself, through the library. */
    tl_timeline tl;
    tl_diags diags;
    CHECK(tl_timeline_parse_text("cut.tl", with_cut, strlen(with_cut), &tl, &diags, &err) == 0);
    double open, close;
    tl_timeline_shutter_interval(&tl, 2, 360.0, &open, &close);
    CHECK_NEAR(open, 2.0 / 24 - 0.5 / 24, 1e-12);
    CHECK(close < 0.1 && close > 0.1 - 1e-9);
    /* Frame 3 (0.104..0.146 s) does not contain the cut: untouched. */
    tl_timeline_shutter_interval(&tl, 3, 360.0, &open, &close);
    CHECK_NEAR(open, 3.0 / 24 - 0.5 / 24, 1e-12);
    CHECK_NEAR(close, 3.0 / 24 + 0.5 / 24, 1e-12);
    /* A frame just after a cut opens at the cut: frame 3 at 720 deg would
     * open at 0.0833 s, before the cut at 0.1 s. */
    tl_timeline_shutter_interval(&tl, 3, 720.0, &open, &close);
    CHECK(open >= 0.1 && open < 0.1 + 1e-9);
    tl_timeline_shutter_interval(&tl, 0, 180.0, &open, &close);
    CHECK_NEAR(open, -0.25 / 24, 1e-15);
    CHECK_NEAR(close, 0.25 / 24, 1e-15);
    tl_timeline_free(&tl);
    rm_rf(out);
}

static void test_movie(void)
{
    char out[256], movie[600], cmd[1400];
    in_dir(out, sizeof out, "movie");
    snprintf(movie, sizeof movie, "%s/clip.mp4", out);
    CHECK(tl_run(NULL, "render", six_path, "--movie", movie, "-q", NULL) == 0);
    snprintf(cmd, sizeof cmd,
             "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
             "stream=width,height,r_frame_rate,nb_read_frames,pix_fmt -of default=nw=1 '%s'",
             movie);
    FILE *p = popen(cmd, "r");
    char probe[1024] = "";
    if (p) {
        size_t n = fread(probe, 1, sizeof probe - 1, p);
        probe[n] = '\0';
        pclose(p);
    }
    CHECK_STR_CONTAINS(probe, "width=48");
    CHECK_STR_CONTAINS(probe, "height=28");
    CHECK_STR_CONTAINS(probe, "r_frame_rate=24/1");
    CHECK_STR_CONTAINS(probe, "nb_read_frames=6");
    CHECK_STR_CONTAINS(probe, "pix_fmt=yuv420p");
    CHECK(tl_dir_entries(out) == 1); /* no temporary left */

    /* Three writers: frames still reach the movie in order (the decoded
     * frames are identical to the one-writer movie's). */
    char movie3[600], sums[2][4096];
    snprintf(movie3, sizeof movie3, "%s/clip3.mp4", out);
    CHECK(tl_run(NULL, "render", six_path, "--movie", movie3, "--writers", "3", "-q", NULL) == 0);
    for (int i = 0; i < 2; i++) {
        snprintf(cmd, sizeof cmd, "ffmpeg -v error -i '%s' -f framemd5 - | grep -v '^#'",
                 i ? movie3 : movie);
        sums[i][0] = '\0';
        p = popen(cmd, "r");
        if (p) {
            size_t n = fread(sums[i], 1, sizeof sums[i] - 1, p);
            sums[i][n] = '\0';
            pclose(p);
        }
    }
    CHECK(strlen(sums[0]) > 100 && strcmp(sums[0], sums[1]) == 0);
    unlink(movie3);

    /* ffmpeg failing mid-run: a clear error, no movie, nothing partial. */
    char fake[256], env[700];
    in_dir(fake, sizeof fake, "fake-ffmpeg");
    write_text(fake, "#!/bin/sh\nhead -c 100 >/dev/null\necho 'fake ffmpeg: disk on fire' >&2\n"
                     "exit 3\n");
    chmod(fake, 0755);
    snprintf(env, sizeof env, "TIDELINE_FFMPEG=%s", fake);
    snprintf(movie, sizeof movie, "%s/broken.mp4", out);
    CHECK(tl_run(&(tl_run_opts){env, 0}, "render", six_path, "--movie", movie, "-q", NULL) == 1);
    CHECK_STR_CONTAINS(tl_run_output, "disk on fire");
    CHECK_STR_CONTAINS(tl_run_output,
                       "broken.mp4 not written: a movie missing frames is discarded");
    CHECK(!exists(movie));
    CHECK(tl_dir_hidden_entries(out) == 0);

    /* No ffmpeg: refused before any frame is rendered. */
    char pattern[600];
    snprintf(pattern, sizeof pattern, "%s/frames/f_####.png", out);
    CHECK(tl_run(&(tl_run_opts){"TIDELINE_FFMPEG=/nonexistent/ffmpeg", 0}, "render", six_path, "-o",
                 pattern, "--movie", movie, NULL) == 2);
    CHECK_STR_CONTAINS(tl_run_output, "ffmpeg");
    CHECK(tl_dir_entries(out) <= 3); /* clip.mp4, fake-ffmpeg, maybe frames/ but empty */
    char frames_dir[600];
    snprintf(frames_dir, sizeof frames_dir, "%s/frames", out);
    CHECK(tl_dir_entries(frames_dir) <= 0);
    rm_rf(out);
}

static char *frame_sums(const char *movie)
{
    char cmd[1400];
    snprintf(cmd, sizeof cmd, "ffmpeg -v error -i '%s' -map 0:v -f framemd5 - | grep -v '^#'",
             movie);
    return tl_test_output(cmd, NULL);
}

static int same_pictures(const char *a, const char *b)
{
    char *x = frame_sums(a), *y = frame_sums(b);
    int same = x && y && strlen(x) > 100 && strcmp(x, y) == 0;
    free(x);
    free(y);
    return same;
}

/* A farm's movie: chunks write the frames, `tideline movie` assembles
 * them (refusing while one is missing); `render --movie --skip-existing`
 * makes the same movie from the frames on disk; the soundtrack goes in at
 * its offset, cut to the frames. */
static void test_movie_from_frames(void)
{
    char out[256], pattern[600], direct[600], farm[600], resumed[600], exr[600];
    in_dir(out, sizeof out, "farm");
    snprintf(pattern, sizeof pattern, "%s/f_####.png", out);
    snprintf(exr, sizeof exr, "%s/f_####.exr", out);
    snprintf(direct, sizeof direct, "%s/direct.mp4", out);
    snprintf(farm, sizeof farm, "%s/farm.mp4", out);
    snprintf(resumed, sizeof resumed, "%s/resumed.mp4", out);
    CHECK(tl_run(NULL, "render", six_path, "--movie", direct, "-q", NULL) == 0);

    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--chunk", "0/2", "-q", NULL) == 0);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--chunk", "1/2", "--movie", farm,
                 NULL) == 2);
    CHECK_STR_CONTAINS(tl_run_output, "once every chunk is done, make the movie with "
                                      "'tideline movie PATTERN.png");
    CHECK(tl_run(NULL, "movie", pattern, "-o", farm, "--timeline", six_path, NULL) == 1);
    CHECK_STR_CONTAINS(tl_run_output, "f_0003.png' is missing (and 2 more of the 6 frames are)");
    CHECK(!exists(farm));
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--chunk", "1/2", "-q", NULL) == 0);
    CHECK(tl_run(NULL, "movie", pattern, "-o", farm, "--timeline", six_path, "-q", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "wrote");
    CHECK(same_pictures(direct, farm));

    /* Resumed: every frame is on disk, the movie is made from them. */
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--movie", resumed, "--skip-existing",
                 NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "0 frames written, 6 skipped");
    CHECK(same_pictures(direct, resumed));
    CHECK(tl_run(NULL, "render", six_path, "-o", exr, "--movie", resumed, "--skip-existing",
                 NULL) == 2);
    CHECK_STR_CONTAINS(tl_run_output, "give -o PATTERN.png too");

    /* The soundtrack: a tone placed 0.1 s into the timeline. */
    char tone[600], timeline[600], text[1200], mov[600], cmd[1600];
    snprintf(tone, sizeof tone, "%s/tone.wav", out);
    snprintf(cmd, sizeof cmd,
             "ffmpeg -v error -f lavfi -i 'sine=frequency=300:sample_rate=48000:duration=1' "
             "-y '%s'",
             tone);
    CHECK(system(cmd) == 0);
    in_dir(timeline, sizeof timeline, "farm/sound.tl");
    snprintf(text, sizeof text, "%saudio tone.wav 0.1s\n", six_frames);
    write_text(timeline, text);
    CHECK(tl_run(NULL, "check", timeline, NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "audio     tone.wav: 1.000 s, 48000 Hz, 1 channel, from "
                                      "0.1 s on the timeline (its last 0.850 s lie past the "
                                      "end: movies cut it there)");
    snprintf(mov, sizeof mov, "%s/sound.mov", out);
    CHECK(tl_run(NULL, "render", timeline, "--movie", mov, "-q", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output,
                       "with the sound of tone.wav, its start 0.100 s into the movie");
    CHECK(tl_run(NULL, "help", "movie", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "Usage: tideline movie PATTERN.png -o FILE.mp4");
    snprintf(cmd, sizeof cmd, "ffmpeg -v error -i '%s' -map 0:a -f s16le -ac 1 -", mov);
    size_t len = 0;
    short *pcm = (short *)tl_test_output(cmd, &len);
    CHECK(pcm != NULL && len / 2 == 6 * 48000 / 24); /* the six frames' 0.25 s */
    if (pcm && len / 2 == 6 * 48000 / 24) {
        int silent = 1, loud = 0;
        for (int i = 0; i < 4800; i++) /* the first 0.1 s */
            silent &= pcm[i] == 0;
        for (int i = 4800; i < 12000; i++)
            loud |= abs(pcm[i]) > 2000; /* lavfi's sine peaks at 1/8 */
        CHECK(silent && loud);
    }
    free(pcm);
    /* Frames 3-5 alone: the sound from 0.125 s, with no silence. */
    CHECK(tl_run(NULL, "render", timeline, "--frames", "3-5", "--movie", mov, "-q", NULL) == 0);
    pcm = (short *)tl_test_output(cmd, &len);
    CHECK(pcm != NULL && len / 2 == 3 * 48000 / 24 && abs(pcm[100]) + abs(pcm[101]) > 0);
    free(pcm);
    rm_rf(out);
}

/* Starts a long render, interrupts it once the first frame exists, then
 * resumes it; the result equals an uninterrupted run byte for byte. */
static void test_interrupt_and_resume(void)
{
    char out[256], ref[256], pattern[600], first[700];
    in_dir(out, sizeof out, "int");
    in_dir(ref, sizeof ref, "ref");
    char long_tl[256];
    in_dir(long_tl, sizeof long_tl, "long.tl");
    write_text(long_tl, "tideline 1\nfps 24\nduration 80f\nsize 128x72\nquality preview\n"
                        "key camera.yaw linear\n  0s 0\n  80f 40\n");
    snprintf(pattern, sizeof pattern, "%s/f_####.exr", out);
    snprintf(first, sizeof first, "%s/f_0000.exr", out);
    /* The 80 frames take 1.5 s here and a fraction of that on a GPU: the
     * signal must not race the run's end. The run prints a line a frame
     * (about 90 bytes, 7 KiB in all) into a pipe of one page that is not
     * read until the signal is sent, so it stops about half way, however
     * fast the machine, until the pipe is drained after the signal. */
    int fds[2];
    CHECK(pipe(fds) == 0);
    CHECK(fcntl(fds[0], F_SETPIPE_SZ, 4096) == 4096);
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], 2);
        close(fds[0]);
        close(fds[1]);
        execl(tl_run_binary, tl_run_binary, "render", long_tl, "-o", pattern, (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    for (int i = 0; i < 6000 && !exists(first); i++) /* up to 60 s */
        usleep(10000);
    kill(pid, SIGINT);
    char drain[4096];
    while (read(fds[0], drain, sizeof drain) > 0)
        ;
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 130);
    int done = tl_dir_entries(out);
    printf("interrupted after %d frames\n", done);
    CHECK(done >= 1 && done < 80);
    CHECK(tl_dir_hidden_entries(out) == 0); /* nothing partial */

    CHECK(tl_run(NULL, "render", long_tl, "-o", pattern, "--skip-existing", NULL) == 0);
    CHECK_STR_CONTAINS(tl_run_output, "skipped (complete)");
    CHECK(tl_dir_entries(out) == 80);
    snprintf(pattern, sizeof pattern, "%s/f_####.exr", ref);
    CHECK(tl_run(NULL, "render", long_tl, "-o", pattern, "-q", NULL) == 0);
    int identical = 1;
    for (int i = 0; i < 80; i++) {
        char a[700], b[700];
        snprintf(a, sizeof a, "%s/f_%04d.exr", out, i);
        snprintf(b, sizeof b, "%s/f_%04d.exr", ref, i);
        identical &= tl_same_bytes(a, b);
    }
    CHECK(identical);
    rm_rf(out);
    rm_rf(ref);
}

static void test_full_disk(void)
{
    char out[256], pattern[600], good[600], saved[600];
    in_dir(out, sizeof out, "disk");
    snprintf(pattern, sizeof pattern, "%s/d_####.exr", out);
    CHECK(tl_run(NULL, "render", six_path, "-o", pattern, "--frames", "0-1", "-q", NULL) == 0);
    snprintf(good, sizeof good, "%s/d_0001.exr", out);
    snprintf(saved, sizeof saved, "%s/saved.bin", out);
    char cmd[1400];
    snprintf(cmd, sizeof cmd, "cp '%s' '%s'", good, saved);
    CHECK(system(cmd) == 0);
    /* Different frames at a bigger size no longer fit in 4 KiB files. */
    CHECK(tl_run(&(tl_run_opts){NULL, 4096}, "render", six_path, "-o", pattern, "--frames", "1-2",
                 "--size", "200x120", "-q", NULL) == 1);
    CHECK_STR_CONTAINS(tl_run_output, "File too large");
    CHECK(tl_same_bytes(good, saved)); /* the good frame 1 is untouched */
    snprintf(good, sizeof good, "%s/d_0002.exr", out);
    CHECK(!exists(good));
    CHECK(tl_dir_hidden_entries(out) == 0);
    rm_rf(out);
}

#define EXPECT(code, needle, ...)                                                                  \
    do {                                                                                           \
        CHECK(tl_run(NULL, __VA_ARGS__, NULL) == code);                                            \
        CHECK_STR_CONTAINS(tl_run_output, needle);                                                 \
    } while (0)

static void test_bad_input(void)
{
    char out[256], pattern[600], blocker[256];
    in_dir(out, sizeof out, "bad");
    snprintf(pattern, sizeof pattern, "%s/b_####.png", out);
    EXPECT(2, "frame 6 is outside", "render", six_path, "-o", pattern, "--frames", "2-6");
    EXPECT(2, "reversed", "render", six_path, "-o", pattern, "--frames", "5-2");
    EXPECT(2, "--frames", "render", six_path, "-o", pattern, "--frames", "1-x");
    EXPECT(2, "--chunk", "render", six_path, "-o", pattern, "--chunk", "4/4");
    char single[400];
    snprintf(single, sizeof single, "%s/one.png", out);
    EXPECT(2, "has no '#'", "render", six_path, "-o", single);
    EXPECT(2, "unknown image format", "render", six_path, "-o", "x_####.tiff");
    EXPECT(2, "nothing to write", "render", six_path);
    EXPECT(2, "--shutter", "render", six_path, "-o", pattern, "--shutter", "400");
    EXPECT(2, "--spp", "render", six_path, "-o", pattern, "--spp", "0");
    EXPECT(2, "--exr-compression", "render", six_path, "-o", pattern, "--exr-compression", "0");
    EXPECT(2, "--png-compression", "render", six_path, "-o", pattern, "--png-compression", "10");
    EXPECT(2, "--dither: 'yes' is not on or off", "render", six_path, "-o", pattern, "--dither",
           "yes");
    EXPECT(1, "cannot open timeline", "render", "/nonexistent.tl", "-o", pattern);
    CHECK(tl_dir_entries(out) <= 0); /* nothing rendered by any of them */
    /* A folder that cannot be created: its parent is a file. */
    mkdir(out, 0755);
    in_dir(blocker, sizeof blocker, "bad/file");
    write_text(blocker, "x");
    snprintf(pattern, sizeof pattern, "%s/sub/b_####.png", blocker);
    EXPECT(2, "cannot create folder", "render", six_path, "-o", pattern);
    /* One frame may use a plain name. */
    CHECK(tl_run(NULL, "render", six_path, "-o", single, "--frames", "2", "-q", NULL) == 0);
    CHECK(exists(single));
    rm_rf(out);
}

/* argv[2], when given, runs half the cases: `files` (the six frames,
 * selection, a full disk) or `runs` (motion blur and cuts, movies,
 * interruption and resume, bad input). ctest runs the halves as two tests
 * of about 10 s each here, so that neither is a slow test. */
int main(int argc, char **argv)
{
    const char *part = argc > 2 ? argv[2] : "all";
    int files = !strcmp(part, "all") || !strcmp(part, "files");
    int runs = !strcmp(part, "all") || !strcmp(part, "runs");
    if (argc < 2 || (!files && !runs)) {
        fprintf(stderr, "usage: test_render_cmd TIDELINE [files|runs]\n");
        return 2;
    }
    if (!mkdtemp(dir))
        return 1;
    tl_run_binary = argv[1];
    in_dir(six_path, sizeof six_path, "six.tl");
    in_dir(cut_path, sizeof cut_path, "cut.tl");
    if (write_text(six_path, six_frames) || write_text(cut_path, with_cut))
        return 1;
    if (files) {
        test_six_frames();
        test_selection();
        test_several_outputs();
        test_full_disk();
    }
    if (runs) {
        test_motion_blur();
        test_movie();
        test_movie_from_frames();
        test_interrupt_and_resume();
        test_bad_input();
    }
    rm_rf(dir);
    TEST_END();
}
