/* The bench's engine without a GPU (src/bench/): preset lists, the
 * rounds' order, medians, the Pareto front, the CSV and the reference
 * cache. tests/test_bench.sh runs the whole command on llvmpipe. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench/tl_bench.h"
#include "tl_test.h"

static tl_bench_preset presets[TL_BENCH_MAX_PRESETS + 2];

static int parse(const char *text, int *count, tl_error *err)
{
    static char list[4096];
    snprintf(list, sizeof list, "%s", text);
    tl_error_clear(err);
    return tl_bench_parse_presets(list, presets, count, err);
}

static void test_presets(void)
{
    tl_error err;
    int n = 0;
    CHECK(parse("draft,final:lod=off:refine_steps=2,preview@edited", &n, &err) == 0);
    CHECK(n == 3);
    CHECK_STR_EQ(presets[0].name, "draft");
    CHECK(presets[0].dir == NULL);
    tl_quality final, draft;
    CHECK(tl_quality_preset("final", &final, &err) == 0);
    CHECK(tl_quality_preset("draft", &draft, &err) == 0);
    CHECK(memcmp(&presets[0].quality, &draft, sizeof draft) == 0);
    CHECK_STR_EQ(presets[1].name, "final:lod=off:refine_steps=2");
    CHECK(presets[1].quality.lod == 0 && final.lod != 0);
    CHECK(presets[1].quality.refine_steps == 2);
    CHECK_STR_EQ(presets[2].name, "preview@edited");
    CHECK(presets[2].dir && strcmp(presets[2].dir, "edited") == 0);

    const struct {
        const char *list, *message;
    } bad[] = {
        {"reference", "'reference' is always rendered (it is the yardstick)"},
        {"fast", "fast"},
        {"final:nope=1", "'final:nope=1': no quality knob 'nope'"},
        {"final:lod", "'final:lod': 'lod' is not KNOB=VALUE"},
        {"final:lod=maybe", "lod=maybe is not on or off"},
        {"final:refine_steps=1.5", "refine_steps=1.5 is not a whole number"},
        {"draft@", "'draft@' names no folder after '@'"},
        {"", "no preset named"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        CHECK(parse(bad[i].list, &n, &err) == TL_ERR_USAGE);
        CHECK_STR_CONTAINS(err.message, bad[i].message);
    }
    char many[4096] = "draft";
    for (int i = 1; i <= TL_BENCH_MAX_PRESETS; i++)
        strcat(many, ",draft");
    CHECK(parse(many, &n, &err) == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, "more than 32 presets");
}

/* Each round starts one preset further along; every round takes each
 * preset once. */
static void test_turns(void)
{
    CHECK(tl_bench_preset_turn(0, 0, 3) == 0 && tl_bench_preset_turn(0, 2, 3) == 2);
    CHECK(tl_bench_preset_turn(1, 0, 3) == 1 && tl_bench_preset_turn(1, 2, 3) == 0);
    for (int count = 1; count <= 5; count++)
        for (int r = 0; r < 7; r++) {
            int seen = 0;
            for (int j = 0; j < count; j++)
                seen |= 1 << tl_bench_preset_turn(r, j, count);
            CHECK(seen == (1 << count) - 1);
        }
}

static void test_medians(void)
{
    double odd[] = {5, 1, 3};
    CHECK(tl_bench_median(odd, 3) == 3.0);
    double even[] = {4, 1, 3, 2};
    CHECK(tl_bench_median(even, 4) == 2.5);
    /* Frames' pass times: the median frame by their sums (the lower of the
     * middle two), its passes kept together. */
    static double pass[TL_BENCH_PASSES + 1][4];
    double *rows[TL_BENCH_PASSES + 1];
    const double sums[4] = {10, 40, 20, 30};
    for (int i = 0; i <= TL_BENCH_PASSES; i++) {
        rows[i] = pass[i];
        for (int k = 0; k < 4; k++)
            pass[i][k] = i == TL_BENCH_PASSES ? sums[k] : sums[k] / TL_BENCH_PASSES + i;
    }
    double out[TL_BENCH_PASSES + 1];
    CHECK(tl_bench_median_frame(rows, 4, out) == 2);
    CHECK(out[TL_BENCH_PASSES] == 20.0);
    CHECK(out[1] == 20.0 / TL_BENCH_PASSES + 1);
}

static void test_front_and_csv(void)
{
    tl_bench_row rows[4];
    memset(rows, 0, sizeof rows);
    snprintf(rows[0].preset, TL_BENCH_NAME, "reference");
    rows[0].is_reference = 1;
    const double ms[3] = {10, 20, 30}, db[3] = {30, 28, 35};
    for (int i = 1; i < 4; i++) {
        snprintf(rows[i].preset, TL_BENCH_NAME, "p%d", i);
        rows[i].ms_total = ms[i - 1];
        rows[i].psnr = db[i - 1];
    }
    tl_bench_mark_front(rows, 4);
    /* p2 is slower and worse than p1. */
    CHECK(!rows[0].on_front && rows[1].on_front && !rows[2].on_front && rows[3].on_front);

    char dir[] = "/tmp/tideline-bench-test-XXXXXX", path[256];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/rows.csv", dir);
    tl_error err;
    CHECK(tl_bench_write_csv(path, rows, 4, 64, 36, 3, 2, &err) == 0);
    FILE *f = fopen(path, "r");
    char text[4096] = "";
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    text[n] = '\0';
    if (f)
        fclose(f);
    CHECK_STR_CONTAINS(text, "\np1,");
    CHECK_STR_CONTAINS(text, "\np3,");
    int lines = 0;
    for (char *c = text; *c; c++)
        lines += *c == '\n';
    CHECK(lines == 5); /* a header and one line a row */
    unlink(path);
    rmdir(dir);
}

/* Reference frames under a key of everything that draws them. */
static void test_cache(void)
{
    char dir[] = "/tmp/tideline-cache-test-XXXXXX", timeline[256];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(timeline, sizeof timeline, "%s/shot.tl", dir);
    FILE *f = fopen(timeline, "w");
    if (f) {
        fputs("tideline 1\n", f);
        fclose(f);
    }
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    tl_bench_cache cache;
    tl_error err;
    CHECK(tl_bench_cache_open(&cache, dir, &lib, &err) == 0);
    uint64_t key = tl_bench_cache_key(&cache, "gpu A", timeline, "", 4, 8, 2);
    CHECK(key != tl_bench_cache_key(&cache, "gpu B", timeline, "", 4, 8, 2));
    CHECK(key != tl_bench_cache_key(&cache, "gpu A", timeline, "", 5, 8, 2));
    CHECK(key != tl_bench_cache_key(&cache, "gpu A", timeline, "", 4, 16, 1));
    CHECK(key == tl_bench_cache_key(&cache, "gpu A", timeline, "", 4, 8, 2));
    float pixels[8 * 2 * 4], back[8 * 2 * 4];
    for (int i = 0; i < 64; i++)
        pixels[i] = (float)i / 64.0f;
    CHECK(tl_bench_cache_load(&cache, key, 8, 2, back) == 0); /* not kept yet */
    CHECK(tl_bench_cache_store(&cache, key, 8, 2, pixels, &err) == 0);
    CHECK(tl_bench_cache_load(&cache, key, 8, 2, back) == 1);
    CHECK(memcmp(pixels, back, sizeof back) == 0);
    CHECK(tl_bench_cache_load(&cache, key, 16, 1, back) == 0); /* another size */
    /* The timeline's text is part of the key. */
    f = fopen(timeline, "w");
    if (f) {
        fputs("tideline 1\nduration 2s\n", f);
        fclose(f);
    }
    CHECK(key != tl_bench_cache_key(&cache, "gpu A", timeline, "", 4, 8, 2));
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
}

int main(void)
{
    test_presets();
    test_turns();
    test_medians();
    test_front_and_csv();
    test_cache();
    TEST_END();
}
