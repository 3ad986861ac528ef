/* tideline eval's giant-wave report and --probe, through the binary: the
 * crest's speed over the water measured from two times equals the model's
 * (deep-water speed times giant.speed) with and without `follow
 * giant.center boat`, whichever way the boat moves; a wave that follows the
 * boat meets it at giant.arrival; a probe reports the same water as the
 * report, a unit upward normal and foam in [0, 1] where a crest breaks;
 * bad --probe values are usage errors. No GL: eval renders nothing.
 * argv[1] is the tideline binary, argv[2] the bundled timelines' folder. */
#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tl_run.h"
#include "tl_test.h"

static const char *timelines;
static char dir[] = "/tmp/tideline-eval-XXXXXX";
#define out_text tl_run_output
#define run(...) tl_run(NULL, __VA_ARGS__)

static char path_buf[4][512];
static const char *in_dir(int slot, const char *name)
{
    snprintf(path_buf[slot], sizeof path_buf[slot], "%s/%s", dir, name);
    return path_buf[slot];
}

static int count_lines(const char *s)
{
    int lines = 0;
    for (; *s; s++)
        lines += *s == '\n';
    return lines;
}

/* The `index`th number of `"key": ` in `json` (a number or an array of
 * numbers); NAN when the key is missing or its value is not a number
 * (null). */
static double json_num(const char *json, const char *key, int index)
{
    char needle[96];
    snprintf(needle, sizeof needle, "\"%s\": ", key);
    const char *p = strstr(json, needle);
    if (!p)
        return NAN;
    p += strlen(needle);
    if (*p == '[')
        p++;
    for (int i = 0; i < index; i++) {
        p = strchr(p, ',');
        if (!p)
            return NAN;
        p++;
    }
    char *end = NULL;
    double v = strtod(p, &end);
    return end == p ? NAN : v;
}

/* Runs the binary with its output thrown away (more than out_text holds);
 * returns the exit status. */
static int run_quiet(const char *const *args)
{
    pid_t pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execv(tl_run_binary, (char *const *)args);
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/* One sample of `eval --json` at `at` (seconds), extra arguments after;
 * the output stays in out_text. Returns the exit status. */
static int eval_json(const char *file, double at, const char *const *extra, int n_extra)
{
    char t[64];
    snprintf(t, sizeof t, "%.17g", at);
    const char *args[48] = {tl_run_binary, "eval", file, "--at", t, "--json"};
    int n = 6;
    for (int i = 0; i < n_extra && n < 47; i++)
        args[n++] = extra[i];
    args[n] = NULL;
    return tl_run_argv(NULL, args);
}

/* What a sample says about the wave, read back from its JSON. */
typedef struct wave_state {
    double crest[2], center[2], dir[2];
    double past_center, model_speed, speed_over_water;
    double to_boat[2]; /* NAN without a boat */
    double expected;   /* sqrt(g/k)·giant.speed from the channels */
} wave_state;

static int wave_at(const char *file, double t, wave_state *w)
{
    if (eval_json(file, t, NULL, 0) != 0)
        return 0;
    const double angle = json_num(out_text, "giant.angle", 0) * M_PI / 180.0;
    const double k = 2.0 * M_PI / json_num(out_text, "giant.wavelength", 0);
    w->dir[0] = sin(angle);
    w->dir[1] = cos(angle);
    w->crest[0] = json_num(out_text, "crest", 0);
    w->crest[1] = json_num(out_text, "crest", 1);
    w->center[0] = json_num(out_text, "giant.center", 0);
    w->center[1] = json_num(out_text, "giant.center", 1);
    w->past_center = json_num(out_text, "past_center", 0);
    w->model_speed = json_num(out_text, "speed", 0);
    w->speed_over_water = json_num(out_text, "speed_over_water", 0);
    w->to_boat[0] = json_num(out_text, "to_boat", 0);
    w->to_boat[1] = json_num(out_text, "to_boat", 1);
    w->expected = sqrt(9.81 / k) * json_num(out_text, "giant.speed", 0);
    return isfinite(w->crest[0]) && isfinite(w->crest[1]);
}

/* (a) The crest's speed over the water, from `crest` at t and t + 1 s,
 * along the travel direction, equals the model's within 1%; so does the
 * report's own speed_over_water (1 ms). (b) With `arrival` >= 0 (a wave
 * that follows the boat) the crest meets the boat then: along its travel
 * the boat is within the crest's own forward displacement of it, and on
 * its centre line across. */
static void check_speed(const char *name, const char *file, double t, double arrival)
{
    wave_state a, b;
    CHECK(wave_at(file, t, &a));
    CHECK(wave_at(file, t + 1.0, &b));
    double measured = a.dir[0] * (b.crest[0] - a.crest[0]) + a.dir[1] * (b.crest[1] - a.crest[1]);
    printf("%-44s crest over the water %.4f m/s (1 s), %.4f m/s (report), model %.4f m/s\n", name,
           measured, a.speed_over_water, a.expected);
    CHECK_NEAR(measured, a.expected, 0.01 * a.expected);
    CHECK_NEAR(a.speed_over_water, a.expected, 0.01 * a.expected);
    CHECK_NEAR(a.model_speed, a.expected, 1e-9 * a.expected); /* "speed" is the model's */
    if (arrival < 0.0)
        return;
    wave_state m;
    CHECK(wave_at(file, arrival, &m));
    /* The crest's top is `forward` ahead of the wave's origin: the curl. */
    double forward = m.dir[0] * (m.crest[0] - m.center[0]) + m.dir[1] * (m.crest[1] - m.center[1]) -
                     m.past_center;
    printf("%-44s at arrival the boat is %.4f m along, %.4g m across from the crest (curl %.4f "
           "m)\n",
           "", m.to_boat[0], m.to_boat[1], forward);
    CHECK(fabs(m.past_center) < 1e-9);
    CHECK(fabs(m.to_boat[0]) <= fabs(forward) + 1e-6);
    CHECK(fabs(m.to_boat[1]) < 1e-6);
}

static void test_speed_over_water(void)
{
    const char *alone = in_dir(0, "alone.tl");
    tl_test_write_file(alone, "tideline 1\nduration 20s\nset giant.enabled on\n"
                              "set giant.speed 1.2\nset giant.arrival 10s\n");
    check_speed("no boat, no follow", alone, 5.0, -1.0);

    /* The boat at 10 m/s against the wave's travel (+z), then across it. */
    const char *against = in_dir(1, "against.tl");
    tl_test_write_file(against, "tideline 1\nduration 20s\nset giant.enabled on\n"
                                "set giant.speed 1.2\nset giant.arrival 10s\n"
                                "path boat\n  0s 0 200\n  20s 0 0\n");
    check_speed("boat against the wave, no follow", against, 5.0, -1.0);
    CHECK(wave_at(against, 5.0, &(wave_state){0}));
    CHECK(isfinite(json_num(out_text, "to_boat", 0)));

    const char *against_f = in_dir(2, "against_follow.tl");
    tl_test_write_file(against_f, "tideline 1\nduration 20s\nset giant.enabled on\n"
                                  "set giant.speed 1.2\nset giant.arrival 10s\n"
                                  "path boat\n  0s 0 200\n  20s 0 0\nfollow giant.center boat\n");
    check_speed("boat against the wave, follow", against_f, 5.0, 10.0);

    const char *across_f = in_dir(3, "across_follow.tl");
    tl_test_write_file(across_f, "tideline 1\nduration 20s\nset giant.enabled on\n"
                                 "set giant.angle 90deg\nset giant.arrival 8s\n"
                                 "path boat\n  0s 300 -100\n  20s 300 100\n"
                                 "follow giant.center boat\n");
    check_speed("boat across the wave (from the side), follow", across_f, 3.0, 8.0);
    /* ... and against it at a slant: the boat's speed has parts along and
     * across the wave's travel. */
    const char *slant_f = in_dir(0, "slant_follow.tl");
    tl_test_write_file(slant_f, "tideline 1\nduration 20s\nset giant.enabled on\n"
                                "set giant.angle 30deg\nset giant.wavelength 120\n"
                                "set giant.speed 0.8\nset giant.arrival 12s\n"
                                "path boat\n  0s 100 300\n  20s -50 -100\n"
                                "follow giant.center boat\n");
    check_speed("boat against the wave at a slant, follow", slant_f, 4.0, 12.0);
    unlink(slant_f);
    unlink(alone);
    unlink(against);
    unlink(against_f);
    unlink(across_f);

    /* The bundled cutscenes, where the fade is steady: a wave with a
     * fixed centre that a boat turns to meet (giant_wave.tl), and one that
     * follows a boat on a curving course (voyage.tl). */
    char file[600];
    snprintf(file, sizeof file, "%s/giant_wave.tl", timelines);
    check_speed("giant_wave.tl (fixed centre)", file, 5.0, -1.0);
    snprintf(file, sizeof file, "%s/voyage.tl", timelines);
    check_speed("voyage.tl (boat on a curve), follow", file, 6.0, 10.5);
}

static int eval_probe(const char *file, double t, double x, double z)
{
    char p[96];
    snprintf(p, sizeof p, "%.17g,%.17g", x, z);
    const char *extra[2] = {"--probe", p};
    return eval_json(file, t, extra, 2);
}

/* A probe's normal is unit and up, its foam in [0, 1]; returns the foam. */
static double check_probe_shape(void)
{
    const char *probes = strstr(out_text, "\"probes\": [");
    CHECK(probes != NULL);
    if (!probes)
        return NAN;
    double n[3];
    for (int i = 0; i < 3; i++)
        n[i] = json_num(probes, "normal", i);
    CHECK_NEAR(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-12);
    CHECK(n[1] > 0.0);
    double foam = json_num(probes, "foam", 0);
    CHECK(foam >= 0.0 && foam <= 1.0);
    return foam;
}

static void test_probes(void)
{
    const char *file = in_dir(0, "probe.tl");
    tl_test_write_file(file, "tideline 1\nduration 20s\nset giant.enabled on\n"
                             "set giant.arrival 10s\nset camera.position 3 2 -40\n"
                             "path boat\n  0s 5 100\n  20s 5 -100\n");
    const double t = 9.0;
    /* heights[0] is the water the report gives under the camera, the boat
     * and the crest: the same function at the same point, to the bit. */
    CHECK(eval_json(file, t, NULL, 0) == 0);
    const double cam[2] = {json_num(out_text, "camera.position", 0),
                           json_num(out_text, "camera.position", 2)};
    const double boat[2] = {json_num(out_text, "position", 0), json_num(out_text, "position", 2)};
    const double crest[2] = {json_num(out_text, "crest", 0), json_num(out_text, "crest", 1)};
    const double under[3] = {json_num(out_text, "under_camera", 0),
                             json_num(out_text, "under_boat", 0),
                             json_num(out_text, "under_crest", 0)};
    const double *at[3] = {cam, boat, crest};
    const char *names[3] = {"camera", "boat", "crest"};
    for (int i = 0; i < 3; i++) {
        CHECK(eval_probe(file, t, at[i][0], at[i][1]) == 0);
        const char *probes = strstr(out_text, "\"probes\": [");
        double h = probes ? json_num(probes, "heights", 0) : NAN;
        double foam = check_probe_shape();
        printf("probe under the %-6s at %.6g %.6g: %.9g m (report %.9g m), foam %.3g\n", names[i],
               at[i][0], at[i][1], h, under[i], foam);
        CHECK(h == under[i]);
    }
    /* Without --probe the key is absent. */
    CHECK(eval_json(file, t, NULL, 0) == 0);
    CHECK(strstr(out_text, "\"probes\"") == NULL);
    /* Several probes, with --frames and in text. */
    CHECK(run("eval", file, "--frames", "0-1", "--probe", "1,2", "--probe", "-3.5,4e2", NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "  probe 1 2                  water ");
    CHECK_STR_CONTAINS(out_text, "  probe -3.5 400             water ");
    CHECK_STR_CONTAINS(out_text, ", normal ");
    CHECK_STR_CONTAINS(out_text, ", foam ");
    CHECK_STR_CONTAINS(out_text, "crest over the water       11.1761 m/s");
    CHECK_STR_CONTAINS(out_text, "boat from the crest        ");
    unlink(file);

    /* A breaking crest foams near its top; far from the wave, and without
     * one, there is none. */
    const char *breaking = in_dir(1, "breaking.tl");
    tl_test_write_file(breaking, "tideline 1\nduration 20s\nset giant.enabled on\n"
                                 "set giant.arrival 10s\nset giant.breaking on\n"
                                 "set giant.break_time 7s\n");
    CHECK(eval_json(breaking, 10.0, NULL, 0) == 0);
    const double top[2] = {json_num(out_text, "crest", 0), json_num(out_text, "crest", 1)};
    CHECK(eval_probe(breaking, 10.0, top[0], top[1]) == 0);
    double foam = check_probe_shape();
    printf("breaking crest: foam %.4g at its top\n", foam);
    CHECK(foam > 0.0);
    CHECK(eval_probe(breaking, 10.0, top[0] + 2000.0, top[1]) == 0);
    CHECK(check_probe_shape() == 0.0);
    CHECK(eval_probe(breaking, 10.0, top[0], top[1] - 2000.0) == 0);
    CHECK(check_probe_shape() == 0.0);
    const char *calm = in_dir(2, "calm.tl");
    tl_test_write_file(calm, "tideline 1\n");
    CHECK(eval_probe(calm, 1.0, 0.0, 0.0) == 0);
    CHECK(check_probe_shape() == 0.0);
    CHECK_STR_CONTAINS(out_text, "\"giant\": null");
    unlink(breaking);
    unlink(calm);
}

/* (d) A bad --probe: status 2, one line naming the flag. */
#define EXPECT_USAGE(needle, ...)                                                                  \
    do {                                                                                           \
        CHECK(run(__VA_ARGS__, NULL) == 2);                                                        \
        CHECK_STR_CONTAINS(out_text, needle);                                                      \
        CHECK(count_lines(out_text) == 1);                                                         \
    } while (0)

static void test_usage(void)
{
    const char *file = in_dir(0, "u.tl");
    tl_test_write_file(file, "tideline 1\n");
    EXPECT_USAGE("tideline eval: --probe: expected X,Z, got '1'", "eval", file, "--at", "0",
                 "--probe", "1");
    EXPECT_USAGE("tideline eval: --probe: expected X,Z, got 'a,b'", "eval", file, "--at", "0",
                 "--probe", "a,b");
    EXPECT_USAGE("tideline eval: --probe: expected X,Z, got '1,2,3'", "eval", file, "--at", "0",
                 "--probe", "1,2,3");
    EXPECT_USAGE("tideline eval: --probe: expected X,Z, got '1,'", "eval", file, "--at", "0",
                 "--probe=1,");
    EXPECT_USAGE("tideline eval: --probe: 'nan,0' holds a non-finite number", "eval", file, "--at",
                 "0", "--probe", "nan,0");
    EXPECT_USAGE("tideline eval: --probe: '0,inf' holds a non-finite number", "eval", file, "--at",
                 "0", "--probe", "0,inf");
    EXPECT_USAGE("tideline eval: --probe: '1e999,0' holds a non-finite number", "eval", file,
                 "--at", "0", "--probe", "1e999,0");
    EXPECT_USAGE("tideline eval: --probe needs a value", "eval", file, "--at", "0", "--probe");
    /* At most 1024 points: 1024 pass, 1025 do not. */
    static const char *args[2 * 1025 + 8];
    int n = 0;
    args[n++] = tl_run_binary;
    args[n++] = "eval";
    args[n++] = file;
    args[n++] = "--at";
    args[n++] = "0";
    for (int i = 0; i < 1024; i++) {
        args[n++] = "--probe";
        args[n++] = "0,0";
    }
    args[n] = NULL;
    CHECK(run_quiet(args) == 0);
    args[n++] = "--probe";
    args[n++] = "0,0";
    args[n] = NULL;
    CHECK(tl_run_argv(NULL, args) == 2);
    CHECK_STR_CONTAINS(out_text, "tideline eval: --probe: at most 1024 points at once");
    CHECK(count_lines(out_text) == 1);
    /* --help says so. */
    CHECK(run("eval", "--help", NULL) == 0);
    CHECK_STR_CONTAINS(out_text, "--probe X,Z");
    CHECK_STR_CONTAINS(out_text, "at most 1024");
    unlink(file);
}

/* Several floating objects (timelines/rescue.tl): `eval --json` lists each
 * with its name, channels and pose, the text output each one's position,
 * and `check` lists them. */
static void test_objects(void)
{
    char file[512];
    snprintf(file, sizeof file, "%s/rescue.tl", timelines);
    CHECK(eval_json(file, 12.0, NULL, 0) == 0);
    const char *boat = strstr(out_text, "\"objects\": [{\"name\": \"boat\"");
    const char *rescue = strstr(out_text, "{\"name\": \"rescue\"");
    CHECK(boat != NULL && rescue != NULL && rescue > boat);
    if (rescue) {
        /* At 12 s the rescue boat is at its path's last point, -4.8 5. */
        CHECK_NEAR(json_num(rescue, "position", 0), -4.8, 1e-9);
        CHECK_NEAR(json_num(rescue, "position", 2), 5.0, 1e-9);
        CHECK_NEAR(json_num(rescue, "cabin_paint", 0), 0.85, 1e-12);
        CHECK_NEAR(json_num(rescue, "size", 0), 11.0, 1e-12);
        CHECK_NEAR(json_num(rescue, "lights", 0), 1.0, 1e-12);
        CHECK_NEAR(json_num(rescue, "length", 0), 11.0, 1e-9);
    }
    if (boat)
        CHECK_NEAR(json_num(boat, "position", 2), 6.0, 1e-9);
    const char *text[] = {tl_run_binary, "eval", file, "--at", "12", NULL};
    CHECK(tl_run_argv(NULL, text) == 0);
    CHECK(strstr(out_text, "rescue.size                11 m") != NULL);
    CHECK(strstr(out_text, "rescue.position            -4.8 ") != NULL);
    CHECK(strstr(out_text, "rescue pose") != NULL);
    CHECK(run("check", file, NULL) == 0);
    CHECK(strstr(out_text, "objects   2 floating: boat (built-in boat), rescue (built-in boat)") !=
          NULL);
    /* One boat with a model: check names the file it loads and its real
     * length (the skiff is 4 units long, at 1.5 m a unit). */
    char skiff[512], text_file[1024];
    snprintf(skiff, sizeof skiff, "%s/../tests/meshes/skiff.gltf", timelines);
    snprintf(text_file, sizeof text_file,
             "tideline 1\nduration 2s\npath boat\n  0s 0 0\n  2s 0 4\nset boat.model %s\n"
             "set boat.model_scale 1.5\n",
             skiff);
    snprintf(file, sizeof file, "%s/skiff.tl", dir);
    tl_test_write_file(file, text_file);
    CHECK(run("check", file, NULL) == 0);
    CHECK(strstr(out_text, "objects   1 floating: boat (skiff.gltf, 6 m long)") != NULL);
}

int main(int argc, char **argv)
{
    if (argc < 3 || !mkdtemp(dir))
        return 1;
    tl_run_binary = argv[1];
    timelines = argv[2];
    test_speed_over_water();
    test_probes();
    test_usage();
    test_objects();
    rmdir(dir);
    TEST_END();
}
