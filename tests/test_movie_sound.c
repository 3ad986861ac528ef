/* The soundtrack (src/audio) and movies made from frames on disk
 * (src/movie/tl_movie_frames): a sound whose every sample tells where in
 * the file it is goes into a .mov as PCM and comes back shifted by the
 * placement asked for, silence-padded to the picture's length; frames
 * read back from PNGs make the same movie as the frames piped directly;
 * a missing frame, an EXR pattern and a frame of another size are refused
 * without leaving a movie. */
#include <math.h>
#include <sndfile.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "audio/tl_audio.h"
#include "image/tl_frame.h"
#include "image/tl_image_io.h"
#include "job/tl_job.h"
#include "movie/tl_movie.h"
#include "movie/tl_movie_frames.h"
#include "tl_test.h"

#define RATE    48000
#define SECONDS 2.0
#define W       64
#define H       48

static char dir[] = "/tmp/tideline-sound-XXXXXX";

/* Sample i of the test sound: a 440 Hz tone whose amplitude rises from
 * 0.1 to 0.9 over the file, so that a shift shows. */
static double source_sample(long i)
{
    const long n = (long)(SECONDS * RATE);
    return (0.1 + 0.8 * (double)i / (double)n) * sin(2.0 * M_PI * 440.0 * (double)i / RATE);
}

static void write_sound(const char *path)
{
    SF_INFO info = {.samplerate = RATE, .channels = 1, .format = SF_FORMAT_WAV | SF_FORMAT_FLOAT};
    SNDFILE *f = sf_open(path, SFM_WRITE, &info);
    CHECK(f != NULL);
    if (!f)
        return;
    const long n = (long)(SECONDS * RATE);
    float *s = malloc((size_t)n * sizeof *s);
    for (long i = 0; i < n; i++)
        s[i] = (float)source_sample(i);
    CHECK(sf_writef_float(f, s, n) == n);
    sf_close(f);
    free(s);
}

static void test_probe(const char *wav)
{
    tl_error err;
    tl_audio_info info;
    CHECK(tl_audio_probe(wav, &info, &err) == 0);
    CHECK(info.sample_rate == RATE && info.channels == 1);
    CHECK(info.frames == (long long)(SECONDS * RATE));
    CHECK_NEAR(info.duration, SECONDS, 1e-12);

    tl_audio_clip clip;
    CHECK(tl_audio_read(wav, &clip, &err) == 0);
    CHECK(clip.info.frames == info.frames);
    CHECK_NEAR(clip.samples[12345], source_sample(12345), 1e-6);
    /* The waveform's column over the last tenth: near the final amplitude. */
    CHECK_NEAR(tl_audio_peak(&clip, 1.8, 2.0), 0.9, 0.02);
    CHECK_NEAR(tl_audio_peak(&clip, 0.0, 0.2), 0.18, 0.02);
    CHECK(tl_audio_peak(&clip, 5.0, 6.0) == 0.0f);
    tl_audio_free(&clip);

    /* FLAC and Ogg Vorbis, as ffmpeg writes them, decode too. */
    const char *kinds[2] = {"flac", "ogg"};
    for (int k = 0; k < 2; k++) {
        char other[512], cmd[1400];
        snprintf(other, sizeof other, "%s/ramp.%s", dir, kinds[k]);
        snprintf(cmd, sizeof cmd, "ffmpeg -v error -y -i '%s' %s '%s'", wav,
                 k ? "-c:a libvorbis" : "", other);
        CHECK(system(cmd) == 0);
        tl_audio_info o;
        CHECK(tl_audio_probe(other, &o, &err) == 0);
        CHECK(o.sample_rate == RATE && o.channels == 1);
        CHECK_NEAR(o.duration, SECONDS, 0.03);
        tl_audio_clip c;
        CHECK(tl_audio_read(other, &c, &err) == 0);
        CHECK_NEAR(tl_audio_peak(&c, 1.8, 2.0), 0.9, 0.05);
        tl_audio_free(&c);
    }

    char path[512];
    snprintf(path, sizeof path, "%s/none.wav", dir);
    CHECK(tl_audio_probe(path, &info, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "none.wav': No such file");
    CHECK(tl_audio_probe(dir, &info, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "' is not a regular file");
    snprintf(path, sizeof path, "%s/text.wav", dir);
    tl_test_write_file(path, "not a sound\n");
    CHECK(tl_audio_probe(path, &info, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "text.wav' cannot be decoded");
}

/* The movie's audio as mono floats (PCM in a .mov comes back exactly, to
 * 24 bits). */
static float *decode_audio(const char *movie, size_t *count)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "ffmpeg -v error -i '%s' -map 0:a -f f32le -ac 1 -", movie);
    size_t len = 0;
    float *s = (float *)tl_test_output(cmd, &len);
    *count = s ? len / sizeof *s : 0;
    return s;
}

static void encode_grey(const char *movie, int frames, const tl_movie_sound *sound)
{
    tl_error err;
    static uint8_t rgb[W * H * 3];
    memset(rgb, 128, sizeof rgb);
    tl_movie *m = NULL;
    CHECK(tl_movie_open(&m, movie, W, H, 24.0, sound, &err) == 0);
    for (int f = 0; m && f < frames; f++)
        CHECK(tl_movie_write(m, rgb, &err) == 0);
    CHECK(m && tl_movie_finish(m, &err) == 0);
}

/* Worst difference between the movie's samples and the source's moved by
 * `shift` samples (source index = movie index + shift; zero outside it). */
static double worst_error(const float *got, size_t count, long shift)
{
    const long n = (long)(SECONDS * RATE);
    double worst = 0.0;
    for (size_t k = 0; k < count; k++) {
        long i = (long)k + shift;
        double want = i >= 0 && i < n ? source_sample(i) : 0.0;
        worst = fmax(worst, fabs(got[k] - want));
    }
    return worst;
}

static void test_placement(const char *wav)
{
    char mov[512];
    snprintf(mov, sizeof mov, "%s/placed.mov", dir);
    /* Starting half a second into the file, one second long (24 frames). */
    tl_movie_sound sound = {.path = wav, .start = 0.5, .duration = 1.0, .sample_rate = RATE};
    encode_grey(mov, 24, &sound);
    size_t count;
    float *got = decode_audio(mov, &count);
    CHECK(got != NULL && count == RATE);
    if (got)
        CHECK(worst_error(got, count, RATE / 2) < 1e-5);
    free(got);

    /* A quarter of a second of silence first, and past the file's end
     * (2 s) silence again up to the picture's 2.5 s. */
    sound = (tl_movie_sound){.path = wav, .start = -0.25, .duration = 2.5, .sample_rate = RATE};
    encode_grey(mov, 60, &sound);
    got = decode_audio(mov, &count);
    CHECK(got != NULL && count == (size_t)(2.5 * RATE));
    if (got) {
        CHECK(worst_error(got, count, -RATE / 4) < 1e-5);
        CHECK(got[RATE / 4 - 1] == 0.0f && got[count - 1] == 0.0f);
    }
    free(got);

    /* AAC in .mp4: an audio stream as long as the picture. */
    char mp4[512], cmd[1024];
    snprintf(mp4, sizeof mp4, "%s/placed.mp4", dir);
    sound = (tl_movie_sound){.path = wav, .start = 0.0, .duration = 1.5, .sample_rate = RATE};
    encode_grey(mp4, 36, &sound);
    snprintf(cmd, sizeof cmd,
             "ffprobe -v error -select_streams a:0 -show_entries stream=codec_name,duration "
             "-of csv=p=0 '%s'",
             mp4);
    char *out = tl_test_output(cmd, NULL);
    CHECK(out != NULL);
    if (out) {
        CHECK_STR_CONTAINS(out, "aac,");
        CHECK_NEAR(atof(strchr(out, ',') + 1), 1.5, 1.0 / 24.0);
    }
    free(out);
}

/* Frame f as a display image on exact 8-bit codes (a gradient that moves
 * with f, so frames differ). */
static void make_frame(tl_frame *fr, int f, int w, int h)
{
    tl_error err;
    CHECK(tl_frame_alloc(fr, w, h, &err) == 0);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float *p = fr->display + ((size_t)y * w + x) * 4;
            p[0] = (float)((3 * x + 7 * f) % 256) / 255.0f;
            p[1] = (float)((5 * y + 11 * f) % 256) / 255.0f;
            p[2] = (float)((x + y) % 256) / 255.0f;
            p[3] = 1.0f;
        }
}

static char *video_md5(const char *movie)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "ffmpeg -v error -i '%s' -map 0:v -f md5 -", movie);
    return tl_test_output(cmd, NULL);
}

static void test_from_frames(void)
{
    tl_error err;
    char pattern[512], direct[512], from_disk[512], path[512];
    snprintf(pattern, sizeof pattern, "%s/f_####.png", dir);
    snprintf(direct, sizeof direct, "%s/direct.mp4", dir);
    snprintf(from_disk, sizeof from_disk, "%s/disk.mp4", dir);

    /* Frames 0..5 piped straight in, and written as PNGs. */
    tl_movie *m = NULL;
    CHECK(tl_movie_open(&m, direct, W, H, 24.0, NULL, &err) == 0);
    static uint8_t rgb[W * H * 3];
    for (int f = 0; f < 6; f++) {
        tl_frame fr;
        make_frame(&fr, f, W, H);
        snprintf(path, sizeof path, "%s/f_%04d.png", dir, f);
        CHECK(tl_png_write(path, &fr, NULL, &err) == 0);
        for (int y = 0; y < H; y++)
            tl_frame_display_row8(&fr, y, 1, rgb + (size_t)y * W * 3);
        CHECK(m && tl_movie_write(m, rgb, &err) == 0);
        tl_frame_free(&fr);
    }
    CHECK(m && tl_movie_finish(m, &err) == 0);

    long frames[6] = {0, 1, 2, 3, 4, 5};
    tl_movie_frames job = {.pattern = pattern,
                           .frames = frames,
                           .count = 6,
                           .movie = from_disk,
                           .fps = 24.0,
                           .dither = 1};
    CHECK(tl_movie_from_frames(&job, &err) == 0);
    char *a = video_md5(direct), *b = video_md5(from_disk);
    CHECK(a && b && strcmp(a, b) == 0);
    free(a);
    free(b);

    long first = -1, last = -1;
    CHECK(tl_pattern_scan(pattern, &first, &last, &err) == 0 && first == 0 && last == 5);

    /* Frame 3 missing: named, with the count; the earlier movie stays. */
    struct stat before, after;
    CHECK(stat(from_disk, &before) == 0);
    snprintf(path, sizeof path, "%s/f_0003.png", dir);
    unlink(path);
    long more[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    job.frames = more;
    job.count = 8;
    CHECK(tl_movie_from_frames(&job, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "f_0003.png' is missing (and 2 more of the 8 frames are)");
    CHECK(stat(from_disk, &after) == 0 && after.st_size == before.st_size &&
          after.st_mtime == before.st_mtime);

    /* A frame of another size. */
    tl_frame small;
    make_frame(&small, 3, W / 2, H / 2);
    CHECK(tl_png_write(path, &small, NULL, &err) == 0);
    tl_frame_free(&small);
    job.count = 6;
    CHECK(tl_movie_from_frames(&job, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "f_0003.png' is 32x24; the first frame is 64x48");

    /* EXR frames are scene-linear: refused, saying what to do. */
    snprintf(pattern, sizeof pattern, "%s/f_####.exr", dir);
    CHECK(tl_movie_from_frames(&job, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, "a movie is made from PNG frames");
    snprintf(pattern, sizeof pattern, "%s/g_####.png", dir);
    CHECK(tl_pattern_scan(pattern, &first, &last, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "no frames match");
}

int main(void)
{
    if (!mkdtemp(dir))
        return 1;
    char wav[512];
    snprintf(wav, sizeof wav, "%s/ramp.wav", dir);
    write_sound(wav);
    test_probe(wav);
    test_placement(wav);
    test_from_frames();

    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    TEST_END();
}
