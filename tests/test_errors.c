/* The bad-input catalogue of docs/errors.md, through `tideline render`: each
 * case exits with its status and message, never crashes, and leaves the good
 * frame already in the output folder byte for byte, with no temporary and no
 * new file beside it. Big inputs are generated here, never committed.
 * ARGS: the tideline binary, the shaders folder. */
#include <fcntl.h>
#include <stdint.h>
#include <sys/stat.h>
#include <time.h>

#include "image/tl_image_io.h"
#include "tl_run.h"
#include "tl_test.h"

static char dir[] = "/tmp/tideline-errors-XXXXXX";
static const char *shaders;
static char out[600], good[700], saved[700], second[700], pattern[700], tiny[600];

/* Two frames at 16x9, draft: the frame the cases must not touch is 0. */
static const char tiny_text[] = "tideline 1\nfps 24\nduration 2f\nsize 16x9\nquality draft\n"
                                "key camera.yaw linear\n  0s 0\n  2f 10\n";

static const char *in_dir(char *buf, size_t size, const char *name)
{
    snprintf(buf, size, "%s/%s", dir, name);
    return buf;
}

static int write_bytes(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 1;
    size_t put = fwrite(data, 1, n, f);
    return (fclose(f) != 0) | (put != n);
}

static int write_text(const char *path, const char *text)
{
    return write_bytes(path, text, strlen(text));
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The promise every case keeps: the good frame is intact, nothing else. */
static void check_untouched(const char *what)
{
    int same = tl_same_bytes(good, saved), hidden = tl_dir_hidden_entries(out);
    int others = tl_dir_entries(out);
    if (!same || hidden != 0 || others != 1)
        fprintf(stderr, "%s: good frame %s, %d temporaries, %d entries\n", what,
                same ? "intact" : "CHANGED", hidden, others);
    CHECK(same && hidden == 0 && others == 1);
}

/* render `timeline` over the good frame with env `env`; expects `status`
 * and `needle` in the output. */
static void expect_render(const char *env, const char *timeline, int status, const char *needle,
                          const char *extra_flag, const char *extra_value)
{
    int got = tl_run(&(tl_run_opts){env, 0}, "render", timeline, "-o", pattern, "-q",
                     extra_flag ? extra_flag : NULL, extra_value, NULL);
    if (got != status || !strstr(tl_run_output, needle))
        fprintf(stderr, "%s: status %d (expected %d), output:\n%.2000s\n", timeline, got, status,
                tl_run_output);
    CHECK(got == status);
    CHECK_STR_CONTAINS(tl_run_output, needle);
    check_untouched(timeline);
}

static void test_timeline_files(void)
{
    char path[700];
    expect_render(NULL, in_dir(path, sizeof path, "missing.tl"), 1,
                  "missing.tl: cannot open timeline: No such file or directory", NULL, NULL);
    in_dir(path, sizeof path, "folder.tl");
    mkdir(path, 0755);
    expect_render(NULL, path, 1, "folder.tl: not a regular file", NULL, NULL);

    /* Binary garbage (a fixed pseudo-random 64 KiB). */
    static unsigned char noise[65536];
    uint32_t x = 15;
    for (size_t i = 0; i < sizeof noise; i++) {
        x = x * 1664525u + 1013904223u;
        noise[i] = (unsigned char)(x >> 24);
    }
    in_dir(path, sizeof path, "garbage.tl");
    CHECK(write_bytes(path, noise, sizeof noise) == 0);
    /* One error where the binary data begins, not one a line. */
    expect_render(NULL, path, 1, "error: not a timeline (binary data at byte ", NULL, NULL);
    CHECK(strstr(tl_run_output, "more errors not shown") == NULL);
    CHECK(strstr(tl_run_output, "plain ASCII") == NULL);

    in_dir(path, sizeof path, "empty.tl");
    CHECK(write_text(path, "") == 0);
    expect_render(NULL, path, 1,
                  "empty.tl:1: error: the file is empty: a timeline starts with the line "
                  "'tideline 1'",
                  NULL, NULL);

    /* 100 MB (sparse: cheap to make) is refused by its size, at once (the
     * times are printed, not checked: a slow machine or a sanitizer build
     * must not fail, and a hang is the test's ctest TIMEOUT). */
    in_dir(path, sizeof path, "huge.tl");
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    CHECK(fd >= 0 && ftruncate(fd, 100 * 1000 * 1000) == 0);
    if (fd >= 0)
        close(fd);
    double t0 = now();
    expect_render(NULL, path, 1,
                  "huge.tl: 95.4 MiB is too large for a timeline (the limit is 16 MiB)", NULL,
                  NULL);
    printf("a 100 MB timeline refused in %.2f s\n", now() - t0);
    unlink(path);

    /* A million-character line: one located error, in bounded time. */
    in_dir(path, sizeof path, "long.tl");
    size_t n = 1000000;
    char *text = malloc(n + 64);
    CHECK(text != NULL);
    if (text) {
        int head = snprintf(text, 64, "tideline 1\nset render.exposure 1 # ");
        memset(text + head, 'x', n);
        text[head + n] = '\n';
        CHECK(write_bytes(path, text, head + n + 1) == 0);
        free(text);
    }
    t0 = now();
    expect_render(NULL, path, 1, "long.tl:2:4097: error: line is longer than 4096 characters", NULL,
                  NULL);
    printf("a million-character line refused in %.2f s\n", now() - t0);
    unlink(path);

    /* Values and sizes the language refuses stop render as they stop check
     * (the golden cases of test_timeline_errors hold every message). */
    in_dir(path, sizeof path, "nan.tl");
    CHECK(write_text(path, "tideline 1\nset render.exposure nan\n") == 0);
    expect_render(NULL, path, 1, "nan.tl:2:21: error: 'nan' is not a finite number", NULL, NULL);
    in_dir(path, sizeof path, "size.tl");
    CHECK(write_text(path, "tideline 1\nsize 100000x100000\n") == 0);
    expect_render(NULL, path, 1,
                  "size.tl:2:6: error: size '100000x100000' is not WIDTHxHEIGHT with each side "
                  "1..16384",
                  NULL, NULL);
    expect_render(NULL, tiny, 2, "--size: 100000x9 is out of range", "--size", "100000x9");
}

/* A UTF-8 byte-order mark with CRLF line ends renders the same pixels as
 * the plain file. */
static void test_bom_and_crlf(void)
{
    char path[700], png_a[700], png_b[700];
    in_dir(path, sizeof path, "windows.tl");
    char text[512] = "\xef\xbb\xbf";
    for (const char *c = tiny_text; *c; c++) {
        size_t len = strlen(text);
        if (*c == '\n')
            text[len++] = '\r';
        text[len++] = *c;
        text[len] = '\0';
    }
    CHECK(write_text(path, text) == 0);
    in_dir(png_a, sizeof png_a, "plain.png");
    in_dir(png_b, sizeof png_b, "windows.png");
    CHECK(tl_run(NULL, "render", tiny, "-o", png_a, "--frames", "1", "-q", NULL) == 0);
    CHECK(tl_run(NULL, "render", path, "-o", png_b, "--frames", "1", "-q", NULL) == 0);
    tl_frame a = {0}, b = {0};
    tl_error err;
    CHECK(tl_png_read(png_a, &a, NULL, &err) == 0 && tl_png_read(png_b, &b, NULL, &err) == 0);
    CHECK(a.width == 16 && b.width == 16 && a.height == 9 && b.height == 9);
    if (a.display && b.display)
        CHECK(memcmp(a.display, b.display, 16 * 9 * 4 * sizeof(float)) == 0);
    tl_frame_free(&a);
    tl_frame_free(&b);
    unlink(png_a);
    unlink(png_b);
}

static void test_outputs(void)
{
    /* A folder no file can be made in, even by root. */
    CHECK(tl_run(NULL, "render", tiny, "-o", "/proc/f_####.png", "-q", NULL) == 2);
    CHECK_STR_CONTAINS(tl_run_output, "/proc/f_0000.png: folder '/proc' is not writable");
    if (geteuid() != 0) { /* and the good frame's own folder made read-only */
        chmod(out, 0555);
        expect_render(NULL, tiny, 2, "is not writable: Permission denied", NULL, NULL);
        chmod(out, 0755);
    }

    /* The output folder removed mid-run: status 1 and a message, no crash. */
    char vanish[700], vpattern[800], first[800], tl[700];
    in_dir(tl, sizeof tl, "long.tl");
    CHECK(write_text(tl, "tideline 1\nfps 24\nduration 2000f\nsize 16x9\nquality draft\n"
                         "key camera.yaw linear\n  0s 0\n  2000f 90\n") == 0);
    in_dir(vanish, sizeof vanish, "vanish");
    snprintf(vpattern, sizeof vpattern, "%s/f_####.png", vanish);
    snprintf(first, sizeof first, "%s/f_0001.png", vanish);
    int fds[2];
    CHECK(pipe(fds) == 0);
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], 2);
        close(fds[0]);
        execl(tl_run_binary, tl_run_binary, "render", tl, "-o", vpattern, "-q", (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    for (int i = 0; i < 6000 && access(first, F_OK) != 0; i++) /* up to 60 s */
        usleep(10000);
    /* Moved away in one step, then removed: rm -rf alone races with the
     * files the run keeps adding. */
    char gone[800], cmd[1000];
    snprintf(gone, sizeof gone, "%s.gone", vanish);
    CHECK(rename(vanish, gone) == 0);
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", gone);
    CHECK(system(cmd) == 0);
    /* Everything it writes, to the end: closing the pipe early would kill
     * it with SIGPIPE as it writes its summary line after the error. */
    char log[4096];
    size_t used = 0;
    ssize_t got;
    while ((got = read(fds[0], log + used, sizeof log - 1 - used)) > 0 &&
           used + (size_t)got < sizeof log - 1)
        used += (size_t)got;
    if (got > 0)
        used += (size_t)got;
    log[used] = '\0';
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    printf("folder removed mid-run: %s", log);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 1);
    CHECK_STR_CONTAINS(log, "No such file or directory");
    CHECK(access(vanish, F_OK) != 0); /* not silently recreated */
}

static void test_runtime(void)
{
    /* No EGL at all. */
    expect_render("__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json", tiny, 1,
                  "no headless OpenGL 3.3 context", NULL, NULL);
    /* A shader that does not compile, from --shader-dir. */
    char broken[700], cmd[4000];
    in_dir(broken, sizeof broken, "shaders");
    snprintf(cmd, sizeof cmd, "mkdir '%s' && cp '%s'/* '%s'/ && echo 'not glsl;' >> '%s/sky.glsl'",
             broken, shaders, broken, broken);
    CHECK(system(cmd) == 0);
    expect_render(NULL, tiny, 1, "failed to compile", "--shader-dir", broken);
    CHECK_STR_CONTAINS(tl_run_output, "sky.glsl:");
    /* A boat model that is not one. */
    char model[700], tl[700], text[1000];
    in_dir(model, sizeof model, "boat.glb");
    CHECK(write_text(model, "glTF? no: a text file with the wrong name\n") == 0);
    in_dir(tl, sizeof tl, "boat.tl");
    snprintf(text, sizeof text, "tideline 1\npath boat\n  0s 0 0\n  5s 0 20\nset boat.model %s\n",
             model);
    CHECK(write_text(tl, text) == 0);
    expect_render(NULL, tl, 1, "boat.tl:5:16: error: boat model ", NULL, NULL);

    /* ffmpeg missing, or dying mid-movie: the good movie stays. */
    char movie[700], movie_saved[700], fake[700], env[800];
    in_dir(movie, sizeof movie, "clip.mp4");
    in_dir(movie_saved, sizeof movie_saved, "clip.saved");
    CHECK(write_text(movie, "a good movie from an earlier run\n") == 0);
    CHECK(write_text(movie_saved, "a good movie from an earlier run\n") == 0);
    CHECK(tl_run(&(tl_run_opts){"TIDELINE_FFMPEG=/nonexistent/ffmpeg", 0}, "render", tiny,
                 "--movie", movie, "--size", "16x8", "-q", NULL) == 2);
    CHECK_STR_CONTAINS(tl_run_output, "ffmpeg not found");
    CHECK(tl_same_bytes(movie, movie_saved));
    in_dir(fake, sizeof fake, "fake-ffmpeg");
    CHECK(write_text(fake, "#!/bin/sh\nhead -c 10 >/dev/null\necho 'fake ffmpeg: gone' >&2\n"
                           "exit 9\n") == 0);
    chmod(fake, 0755);
    snprintf(env, sizeof env, "TIDELINE_FFMPEG=%s", fake);
    CHECK(tl_run(&(tl_run_opts){env, 0}, "render", tiny, "--movie", movie, "--size", "16x8", "-q",
                 NULL) == 1);
    CHECK_STR_CONTAINS(tl_run_output, "ffmpeg stopped (exit status 9)");
    CHECK_STR_CONTAINS(tl_run_output, "the earlier file is untouched");
    CHECK(tl_same_bytes(movie, movie_saved));
    CHECK(tl_dir_hidden_entries(dir) == 0);
}

int main(int argc, char **argv)
{
    if (argc < 3 || !mkdtemp(dir))
        return 1;
    tl_run_binary = argv[1];
    shaders = argv[2];
    in_dir(out, sizeof out, "out");
    in_dir(tiny, sizeof tiny, "tiny.tl");
    snprintf(good, sizeof good, "%s/f_0000.png", out);
    snprintf(second, sizeof second, "%s/f_0001.png", out);
    snprintf(pattern, sizeof pattern, "%s/f_####.png", out);
    in_dir(saved, sizeof saved, "good.saved");
    CHECK(write_text(tiny, tiny_text) == 0);
    /* The good frame every case runs over. */
    CHECK(tl_run(NULL, "render", tiny, "-o", pattern, "--frames", "0", "-q", NULL) == 0);
    char cmd[2000];
    snprintf(cmd, sizeof cmd, "cp '%s' '%s'", good, saved);
    CHECK(system(cmd) == 0);
    test_timeline_files();
    test_bom_and_crlf();
    test_outputs();
    test_runtime();
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
    TEST_END();
}
