/* Movies through ffmpeg (src/movie): encode small synthetic clips, read them
 * back with ffprobe and ffmpeg, and check that failures and aborts never
 * leave a partial movie or a temporary file behind. */
#include <dirent.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "movie/tl_movie.h"
#include "tl_test.h"

#define W 64
#define H 48

static char dir[] = "/tmp/tideline-movie-XXXXXX";

/* Frame f: top half red, bottom half blue, green ramps left to right and
 * brightens with f, so that rows and frames can be told apart. */
static void make_frame(uint8_t *rgb, int f)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            uint8_t *p = rgb + ((size_t)y * W + x) * 3;
            p[0] = y < H / 2 ? 200 : 40;
            p[1] = (uint8_t)(2 * x + 4 * f);
            p[2] = y < H / 2 ? 40 : 200;
        }
}

static int encode(const char *path, double fps, int frames, tl_error *err)
{
    uint8_t rgb[W * H * 3];
    tl_movie *m = NULL;
    int rc = tl_movie_open(&m, path, W, H, fps, NULL, err);
    for (int f = 0; !rc && f < frames; f++) {
        make_frame(rgb, f);
        rc = tl_movie_write(m, rgb, err);
    }
    if (rc) {
        tl_movie_abort(m);
        return rc;
    }
    return tl_movie_finish(m, err);
}

/* The value of "key=value" on its own line, or "" when missing. */
static const char *field(const char *text, const char *key, char *value, size_t size)
{
    value[0] = '\0';
    size_t klen = strlen(key);
    for (const char *line = text; line && *line;) {
        const char *nl = strchr(line, '\n');
        size_t len = nl ? (size_t)(nl - line) : strlen(line);
        if (len > klen && strncmp(line, key, klen) == 0 && line[klen] == '=')
            snprintf(value, size, "%.*s", (int)(len - klen - 1), line + klen + 1);
        line = nl ? nl + 1 : NULL;
    }
    return value;
}

static void probe(const char *path, const char *codec, const char *pix_fmt, const char *rate)
{
    char cmd[1024], v[64];
    snprintf(cmd, sizeof cmd,
             "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
             "stream=width,height,r_frame_rate,nb_read_frames,codec_name,pix_fmt "
             "-of default=nw=1 '%s'",
             path);
    char *out = tl_test_output(cmd, NULL);
    CHECK(out != NULL);
    if (!out)
        return;
    CHECK(strcmp(field(out, "width", v, sizeof v), "64") == 0);
    CHECK(strcmp(field(out, "height", v, sizeof v), "48") == 0);
    CHECK(strcmp(field(out, "nb_read_frames", v, sizeof v), "12") == 0);
    CHECK(strcmp(field(out, "r_frame_rate", v, sizeof v), rate) == 0);
    CHECK(strcmp(field(out, "codec_name", v, sizeof v), codec) == 0);
    CHECK(strcmp(field(out, "pix_fmt", v, sizeof v), pix_fmt) == 0);
    if (tl_test_failures)
        fprintf(stderr, "ffprobe %s:\n%s", path, out);
    free(out);
}

/* Mean of channel c over rows y0..y0+7 and columns 0..7. */
static double region_mean(const uint8_t *rgb, int y0, int c)
{
    double sum = 0;
    for (int y = y0; y < y0 + 8; y++)
        for (int x = 0; x < 8; x++)
            sum += rgb[((size_t)y * W + x) * 3 + c];
    return sum / 64.0;
}

/* Decodes the first frame and compares corners with what was written:
 * colours close, and the red top above the blue bottom. */
static void check_first_frame(const char *path)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             "ffmpeg -v error -i '%s' -frames:v 1 -f rawvideo -pix_fmt rgb24 - </dev/null", path);
    size_t len = 0;
    uint8_t *got = (uint8_t *)tl_test_output(cmd, &len);
    CHECK(got != NULL && len == W * H * 3);
    if (!got || len != W * H * 3) {
        free(got);
        return;
    }
    uint8_t want[W * H * 3];
    make_frame(want, 0);
    for (int c = 0; c < 3; c++) {
        CHECK_NEAR(region_mean(got, 0, c), region_mean(want, 0, c), 8);
        CHECK_NEAR(region_mean(got, H - 8, c), region_mean(want, H - 8, c), 8);
    }
    CHECK(region_mean(got, 0, 0) > 150 && region_mean(got, 0, 2) < 90);
    CHECK(region_mean(got, H - 8, 2) > 150 && region_mean(got, H - 8, 0) < 90);
    free(got);
}

/* The names in the test folder other than `keep`, as one string. */
static void others_in_dir(const char *keep, char *out, size_t size)
{
    out[0] = '\0';
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0 ||
            (keep && strcmp(e->d_name, keep) == 0) || strcmp(e->d_name, "fake-ffmpeg") == 0)
            continue;
        size_t n = strlen(out);
        snprintf(out + n, size - n, "%s ", e->d_name);
    }
    closedir(d);
}

static char *read_file(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *buf = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (buf && fread(buf, 1, (size_t)n, fp) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(fp);
    *len = (size_t)n;
    return buf;
}

static void test_frame_rate(void)
{
    long num = 0, den = 0;
    CHECK(tl_movie_frame_rate(24, &num, &den) == 0 && num == 24 && den == 1);
    CHECK(tl_movie_frame_rate(23.976, &num, &den) == 0 && num == 24000 && den == 1001);
    CHECK(tl_movie_frame_rate(24000.0 / 1001.0, &num, &den) == 0 && num == 24000 && den == 1001);
    CHECK(tl_movie_frame_rate(29.97, &num, &den) == 0 && num == 30000 && den == 1001);
    CHECK(tl_movie_frame_rate(59.94, &num, &den) == 0 && num == 60000 && den == 1001);
    CHECK(tl_movie_frame_rate(12.5, &num, &den) == 0 && num == 25 && den == 2);
    CHECK(tl_movie_frame_rate(23.5, &num, &den) == 0 && num == 47 && den == 2);
    CHECK(tl_movie_frame_rate(0, &num, &den) != 0);
    CHECK(tl_movie_frame_rate(-24, &num, &den) != 0);
    CHECK(tl_movie_frame_rate(NAN, &num, &den) != 0);
    CHECK(tl_movie_frame_rate(1e9, &num, &den) != 0);
}

static void test_encode(void)
{
    tl_error err;
    tl_error_clear(&err);
    char mp4[256], mov[256], others[1024];
    snprintf(mp4, sizeof mp4, "%s/clip.mp4", dir);
    snprintf(mov, sizeof mov, "%s/clip.mov", dir);

    CHECK(encode(mp4, 24, 12, &err) == 0);
    if (err.message[0])
        fprintf(stderr, "%s\n", err.message);
    probe(mp4, "h264", "yuv420p", "24/1");
    check_first_frame(mp4);

    CHECK(encode(mov, 30000.0 / 1001.0, 12, &err) == 0);
    if (err.message[0])
        fprintf(stderr, "%s\n", err.message);
    probe(mov, "prores", "yuv422p10le", "30000/1001");
    check_first_frame(mov);

    /* A movie is written like any file, not left private to the user. */
    struct stat st;
    CHECK(stat(mp4, &st) == 0 && (st.st_mode & 0444) == 0444);
    unlink(mov);
    others_in_dir("clip.mp4", others, sizeof others);
    CHECK(strcmp(others, "") == 0);
}

static void test_abort(void)
{
    char mp4[256], fresh[256], others[1024];
    snprintf(mp4, sizeof mp4, "%s/clip.mp4", dir);
    snprintf(fresh, sizeof fresh, "%s/fresh.mp4", dir);
    uint8_t rgb[W * H * 3];
    make_frame(rgb, 0);
    tl_error err;

    /* A new movie aborted half-way: nothing left. */
    tl_movie *m = NULL;
    CHECK(tl_movie_open(&m, fresh, W, H, 24, NULL, &err) == 0);
    others_in_dir("clip.mp4", others, sizeof others);
    CHECK(strstr(others, ".fresh.mp4.tmp-") != NULL); /* encoding into a hidden temporary */
    for (int f = 0; m && f < 5; f++)
        CHECK(tl_movie_write(m, rgb, &err) == 0);
    tl_movie_abort(m);
    CHECK(access(fresh, F_OK) != 0);
    others_in_dir("clip.mp4", others, sizeof others);
    CHECK(strcmp(others, "") == 0);
    tl_movie_abort(NULL);

    /* Over an existing movie: it survives byte for byte. */
    size_t before_len = 0, after_len = 0;
    char *before = read_file(mp4, &before_len);
    CHECK(before != NULL && before_len > 0);
    m = NULL;
    CHECK(tl_movie_open(&m, mp4, W, H, 24, NULL, &err) == 0);
    for (int f = 0; m && f < 3; f++)
        CHECK(tl_movie_write(m, rgb, &err) == 0);
    tl_movie_abort(m);
    char *after = read_file(mp4, &after_len);
    CHECK(after != NULL && after_len == before_len && memcmp(before, after, before_len) == 0);
    others_in_dir("clip.mp4", others, sizeof others);
    CHECK(strcmp(others, "") == 0);
    free(before);
    free(after);
}

static void test_ffmpeg_fails(void)
{
    char script[256], mp4[256], fresh[256], others[1024];
    snprintf(script, sizeof script, "%s/fake-ffmpeg", dir);
    snprintf(mp4, sizeof mp4, "%s/clip.mp4", dir);
    snprintf(fresh, sizeof fresh, "%s/fresh.mp4", dir);
    FILE *fp = fopen(script, "w");
    CHECK(fp != NULL);
    if (!fp)
        return;
    fputs("#!/bin/sh\nhead -c 100 >/dev/null\n"
          "echo 'fake ffmpeg (test_movie): failing on purpose' >&2\nexit 3\n",
          fp);
    fclose(fp);
    chmod(script, 0755);
    setenv("TIDELINE_FFMPEG", script, 1);

    size_t before_len = 0, after_len = 0;
    char *before = read_file(mp4, &before_len);
    const char *targets[] = {fresh, mp4};
    for (int t = 0; t < 2; t++) {
        /* 2 frames usually fit in the pipe's buffer, so the failure shows in
         * finish; 200 do not, so it shows in write. Either way: an error
         * naming the status, and no file. */
        int counts[] = {2, 200};
        for (int k = 0; k < 2; k++) {
            tl_error err;
            tl_error_clear(&err);
            CHECK(encode(targets[t], 24, counts[k], &err) == TL_ERR_RUNTIME);
            CHECK_STR_CONTAINS(err.message, "ffmpeg stopped (exit status 3)");
            CHECK(access(fresh, F_OK) != 0);
            others_in_dir("clip.mp4", others, sizeof others);
            CHECK(strcmp(others, "") == 0);
        }
    }
    char *after = read_file(mp4, &after_len);
    CHECK(before && after && after_len == before_len && memcmp(before, after, before_len) == 0);
    free(before);
    free(after);

    char path[4096];
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_movie_find_ffmpeg(path, sizeof path, &err) == 0 && strcmp(path, script) == 0);
    unlink(script);

    setenv("TIDELINE_FFMPEG", "/nonexistent", 1);
    CHECK(tl_movie_find_ffmpeg(path, sizeof path, &err) == TL_ERR_RUNTIME);
    CHECK_STR_CONTAINS(err.message, "ffmpeg not found");
    CHECK_STR_CONTAINS(err.message, "/nonexistent");
    CHECK_STR_CONTAINS(err.message, "install the Debian package 'ffmpeg'");
    tl_error_clear(&err);
    CHECK(tl_movie_check(fresh, W, H, &err) == TL_ERR_RUNTIME);
    CHECK_STR_CONTAINS(err.message, "Debian package 'ffmpeg'");
    tl_movie *m = NULL;
    CHECK(tl_movie_open(&m, fresh, W, H, 24, NULL, &err) != 0 && m == NULL);
    unsetenv("TIDELINE_FFMPEG");

    /* Without the variable: found on PATH, or not at all. */
    const char *saved = getenv("PATH");
    char saved_path[4096];
    snprintf(saved_path, sizeof saved_path, "%s", saved ? saved : "");
    CHECK(tl_movie_find_ffmpeg(path, sizeof path, &err) == 0 && strstr(path, "ffmpeg"));
    CHECK(tl_movie_find_ffmpeg(NULL, 0, &err) == 0);
    setenv("PATH", dir, 1);
    tl_error_clear(&err);
    CHECK(tl_movie_find_ffmpeg(path, sizeof path, &err) == TL_ERR_RUNTIME);
    CHECK_STR_CONTAINS(err.message, "ffmpeg not found: install the Debian package 'ffmpeg' (or set "
                                    "TIDELINE_FFMPEG)");
    setenv("PATH", saved_path, 1);
}

static void test_check(void)
{
    char path[256];
    tl_error err;
    tl_error_clear(&err);
    snprintf(path, sizeof path, "%s/ok.mp4", dir);
    CHECK(tl_movie_check(path, W, H, &err) == 0);
    CHECK(tl_movie_check(path, 63, 48, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, "H.264 (yuv420p) needs an even width and height, got 63x48");
    CHECK(tl_movie_check(path, 64, 47, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, "got 64x47");
    snprintf(path, sizeof path, "%s/ok.mov", dir);
    CHECK(tl_movie_check(path, 63, 47, &err) == 0); /* ProRes takes odd sizes */
    snprintf(path, sizeof path, "%s/clip.avi", dir);
    CHECK(tl_movie_check(path, W, H, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, "clip.avi");
    CHECK_STR_CONTAINS(err.message, ".mp4");
    CHECK_STR_CONTAINS(err.message, ".mov");
    CHECK(tl_movie_check("noextension", W, H, &err) == TL_ERR_USAGE);
    snprintf(path, sizeof path, "%s/missing/clip.mp4", dir);
    CHECK(tl_movie_check(path, W, H, &err) != 0);
    CHECK_STR_CONTAINS(err.message, "missing");
    CHECK_STR_CONTAINS(err.message, "does not exist");
    tl_movie *m = NULL;
    CHECK(tl_movie_open(&m, path, W, H, 24, NULL, &err) != 0 && m == NULL);

    CHECK(tl_movie_codec_from_path("a/b.MP4") == TL_MOVIE_H264);
    CHECK(tl_movie_codec_from_path("b.mov") == TL_MOVIE_PRORES);
    CHECK(tl_movie_codec_from_path("b.mov/x") == TL_MOVIE_UNKNOWN);
    CHECK(tl_movie_codec_from_path("b.mkv") == TL_MOVIE_UNKNOWN);
}

int main(void)
{
    if (!mkdtemp(dir))
        return 1;
    test_frame_rate();
    test_check();
    test_encode();
    test_abort();
    test_ffmpeg_fails();

    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", dir);
    TEST_END();
}
