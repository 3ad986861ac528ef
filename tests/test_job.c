/* Frame specs, chunks and output name patterns (src/job). */
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "image/tl_image_io.h"
#include "job/tl_job.h"
#include "tl_test.h"

/* Parses `spec` against `frame_count` frames and compares with `want`. */
static int parses_to(const char *spec, long frame_count, const long *want, size_t n)
{
    tl_frame_list list;
    tl_error err;
    tl_error_clear(&err);
    if (tl_frame_list_parse(spec, frame_count, "--frames", &list, &err) != 0) {
        fprintf(stderr, "'%s': unexpected error: %s\n", spec ? spec : "(null)", err.message);
        return 0;
    }
    int same = list.count == n;
    for (size_t i = 0; same && i < n; i++)
        same = list.frames[i] == want[i];
    if (!same) {
        fprintf(stderr, "'%s' gave %zu frames:", spec ? spec : "(null)", list.count);
        for (size_t i = 0; i < list.count && i < 40; i++)
            fprintf(stderr, " %ld", list.frames[i]);
        fprintf(stderr, "\n");
    }
    tl_frame_list_free(&list);
    return same;
}

/* Expects `spec` to fail with TL_ERR_USAGE, an empty list and `message` in
 * the error. */
static void check_parse_error(const char *spec, long frame_count, const char *message, int line)
{
    tl_frame_list list = {(long *)&list, 99};
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_frame_list_parse(spec, frame_count, "--frames", &list, &err);
    if (rc != TL_ERR_USAGE || list.frames != NULL || list.count != 0 ||
        !strstr(err.message, message))
        fprintf(stderr, "line %d: '%s': rc %d, message \"%s\"\n", line, spec, rc, err.message);
    CHECK(rc == TL_ERR_USAGE);
    CHECK(err.status == TL_ERR_USAGE);
    CHECK(list.frames == NULL && list.count == 0);
    CHECK_STR_CONTAINS(err.message, message);
}
#define PARSE_ERROR(spec, count, message) check_parse_error(spec, count, message, __LINE__)

static void test_parse(void)
{
    const long example[] = {1, 2, 3, 5, 7, 9, 11, 13, 15, 17, 19};
    CHECK(parses_to("1-3,5,7-20:2", 240, example, sizeof example / sizeof *example));
    const long merged[] = {0, 1, 2, 3, 4, 5, 6, 8, 10};
    CHECK(parses_to("4-10:2,0-5,3,5,0", 240, merged, sizeof merged / sizeof *merged));
    const long spaced[] = {1, 2, 3, 10, 12};
    CHECK(parses_to("  1 - 3 , 12,10 - 12 : 2 ", 240, spaced, 5));
    const long single[] = {239};
    CHECK(parses_to("239", 240, single, 1));
    CHECK(parses_to("007", 240, (const long[]){7}, 1));
    /* The step starts at A: the end need not be on it. */
    CHECK(parses_to("2-9:3", 240, (const long[]){2, 5, 8}, 3));
    CHECK(parses_to("5-5:7", 240, (const long[]){5}, 1));
    /* Steps on different progressions interleave. */
    CHECK(parses_to("0-12:4,0-12:3,1", 240, (const long[]){0, 1, 3, 4, 6, 8, 9, 12}, 8));
    CHECK(parses_to("3-5,0-2", 240, (const long[]){0, 1, 2, 3, 4, 5}, 6));
    /* A huge step selects only the start. */
    CHECK(parses_to("4-9:99999999999999999999", 240, (const long[]){4}, 1));

    long all[5] = {0, 1, 2, 3, 4};
    CHECK(parses_to(NULL, 5, all, 5));
    CHECK(parses_to("", 5, all, 5));
    CHECK(parses_to("   ", 5, all, 5));
    CHECK(parses_to(NULL, 0, NULL, 0));

    /* Many repeats of a large range merge instead of costing memory or time. */
    char big[4000] = "";
    for (int i = 0; i < 300; i++)
        strcat(big, i ? ",0-9999999" : "0-9999999");
    tl_frame_list list;
    tl_error err;
    CHECK(tl_frame_list_parse(big, 1000000000L, "--frames", &list, &err) == 0);
    CHECK(list.count == 10000000);
    CHECK(list.count == 10000000 && list.frames[9999999] == 9999999);
    tl_frame_list_free(&list);
    CHECK(list.frames == NULL && list.count == 0);

    PARSE_ERROR("7-3", 240, "--frames: '7-3' is reversed (7 > 3)");
    PARSE_ERROR("1,7-3", 240, "--frames: '7-3' in '1,7-3' is reversed (7 > 3)");
    PARSE_ERROR("300", 240, "--frames: frame 300 is outside the timeline's frames 0-239");
    PARSE_ERROR("200-300", 240, "--frames: frame 300 is outside the timeline's frames 0-239");
    PARSE_ERROR("0-5,200-300", 240, "(item '200-300' of '0-5,200-300')");
    PARSE_ERROR("240", 240, "frame 240 is outside the timeline's frames 0-239");
    PARSE_ERROR("99999999999999999999", 240,
                "frame 99999999999999999999 is outside the timeline's frames 0-239");
    PARSE_ERROR("0-99999999999999999999", 240, "frame 99999999999999999999 is outside");
    PARSE_ERROR("3", 0, "frame 3 is outside the timeline, which has no frames");
    PARSE_ERROR("1,,2", 240, "--frames: empty item in '1,,2'");
    PARSE_ERROR("1,", 240, "empty item in '1,'");
    PARSE_ERROR(",1", 240, "empty item in ',1'");
    PARSE_ERROR("1, ,2", 240, "empty item");
    PARSE_ERROR("-5", 240, "--frames: '-5' is not N, A-B or A-B:STEP");
    PARSE_ERROR("+5", 240, "'+5' is not N, A-B or A-B:STEP");
    PARSE_ERROR("1--3", 240, "'1--3' is not N, A-B or A-B:STEP");
    PARSE_ERROR("5x", 240, "'5x' is not N");
    PARSE_ERROR("1,5x", 240, "'5x' in '1,5x' is not N");
    PARSE_ERROR("abc", 240, "'abc' is not N");
    PARSE_ERROR("5-", 240, "'5-' is not N");
    PARSE_ERROR("1 2", 240, "'1 2' is not N");
    PARSE_ERROR("3:2", 240, "'3:2' is not N");
    PARSE_ERROR("1-3:2:4", 240, "'1-3:2:4' is not N");
    PARSE_ERROR("1-3:", 240, "'1-3:' is not N");
    PARSE_ERROR("1.5", 240, "'1.5' is not N");
    PARSE_ERROR("1-9:0", 240, "--frames: '1-9:0' has a step of 0; it must be 1 or more");
    PARSE_ERROR("1-9:-2", 240, "'1-9:-2' is not N");
    /* Bounded memory: selections beyond 10,000,000 frames fail cleanly. */
    PARSE_ERROR("0-2000000000", 1000000000L, "frame 2000000000 is outside");
    PARSE_ERROR("0-999999999", 1000000000L,
                "'0-999999999' selects 1000000000 frames, more than the 10000000");
    PARSE_ERROR("0-9999999,10000000", 1000000000L,
                "'0-9999999,10000000' selects more than the 10000000 frames");
    PARSE_ERROR("0-9999999,1-20000000:2", 1000000000L, "selects more than the 10000000");
    PARSE_ERROR(NULL, 1000000000L, "the timeline has 1000000000 frames, more than the 10000000");

    /* Exactly the limit is fine. */
    CHECK(tl_frame_list_parse("0-9999999,0-9999999:2", 1000000000L, "--frames", &list, &err) == 0);
    CHECK(list.count == 10000000);
    tl_frame_list_free(&list);
}

/* Chunks of `n` frames: each chunk is a run of consecutive items, chunk i
 * holds items [floor(i*n/c), floor((i+1)*n/c)), together they are the list. */
static void check_chunks(long n, int chunks, const size_t *sizes)
{
    long next = 0;
    for (int i = 0; i < chunks; i++) {
        tl_frame_list list;
        tl_error err;
        CHECK(tl_frame_list_parse(NULL, n, "--frames", &list, &err) == 0);
        char spec[32];
        snprintf(spec, sizeof spec, "%d/%d", i, chunks);
        CHECK(tl_frame_list_chunk(&list, spec, "--chunk", &err) == 0);
        CHECK(list.count == sizes[i]);
        for (size_t k = 0; k < list.count; k++)
            CHECK(list.frames[k] == next++);
        tl_frame_list_free(&list);
    }
    CHECK(next == n);
}

static void check_chunk_error(const char *spec, int line)
{
    tl_frame_list list;
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_frame_list_parse(NULL, 10, "--frames", &list, &err) == 0);
    int rc = tl_frame_list_chunk(&list, spec, "--chunk", &err);
    char want[256];
    snprintf(want, sizeof want, "--chunk: expected INDEX/COUNT with 0 <= INDEX < COUNT, got '%s'",
             spec ? spec : "");
    if (rc != TL_ERR_USAGE || !strstr(err.message, want))
        fprintf(stderr, "line %d: chunk '%s': rc %d, \"%s\"\n", line, spec, rc, err.message);
    CHECK(rc == TL_ERR_USAGE);
    CHECK_STR_CONTAINS(err.message, want);
    CHECK(list.count == 10); /* untouched */
    tl_frame_list_free(&list);
}
#define CHUNK_ERROR(spec) check_chunk_error(spec, __LINE__)

static void test_chunk(void)
{
    check_chunks(10, 3, (const size_t[]){3, 3, 4});
    check_chunks(2, 5, (const size_t[]){0, 0, 1, 0, 1});
    check_chunks(7, 1, (const size_t[]){7});
    check_chunks(0, 2, (const size_t[]){0, 0});
    check_chunks(12, 4, (const size_t[]){3, 3, 3, 3});

    /* A sparse list is split by position, not by frame number. */
    tl_frame_list list;
    tl_error err;
    CHECK(tl_frame_list_parse("1-3,5,7-20:2", 240, "--frames", &list, &err) == 0);
    CHECK(tl_frame_list_chunk(&list, " 1 / 2 ", "--chunk", &err) == 0);
    CHECK(list.count == 6 && list.frames[0] == 9 && list.frames[5] == 19);
    tl_frame_list_free(&list);

    /* Huge counts do not overflow: 3 frames over 2^62 chunks. */
    CHECK(tl_frame_list_parse(NULL, 3, "--frames", &list, &err) == 0);
    CHECK(tl_frame_list_chunk(&list, "4611686018427387903/4611686018427387904", "--chunk", &err) ==
          0);
    CHECK(list.count == 1 && list.frames[0] == 2);
    tl_frame_list_free(&list);

    CHUNK_ERROR("3/3");
    CHUNK_ERROR("0/0");
    CHUNK_ERROR("-1/3");
    CHUNK_ERROR("1/-3");
    CHUNK_ERROR("1");
    CHUNK_ERROR("1/");
    CHUNK_ERROR("/3");
    CHUNK_ERROR("1/3x");
    CHUNK_ERROR("1/3/4");
    CHUNK_ERROR("a/b");
    CHUNK_ERROR("");
    CHUNK_ERROR(NULL);
    CHUNK_ERROR("1/99999999999999999999");
    CHUNK_ERROR("99999999999999999999/3");
}

static void check_format(const char *pattern, long frame, int single, const char *want, int line)
{
    char out[256];
    tl_error err;
    tl_error_clear(&err);
    int rc = tl_pattern_format(pattern, frame, single, out, sizeof out, &err);
    if (rc != 0 || strcmp(out, want) != 0)
        fprintf(stderr, "line %d: '%s' frame %ld: rc %d, '%s' (want '%s') %s\n", line, pattern,
                frame, rc, rc ? "" : out, want, err.message);
    CHECK(rc == 0 && strcmp(out, want) == 0);
}
#define FORMAT(pattern, frame, single, want) check_format(pattern, frame, single, want, __LINE__)

static void test_pattern(void)
{
    FORMAT("shot_####.exr", 7, 0, "shot_0007.exr");
    FORMAT("shot_####.exr", 7, 1, "shot_0007.exr");
    FORMAT("a/b_##.png", 123, 0, "a/b_123.png");
    FORMAT("f####_v2_##.exr", 5, 0, "f####_v2_05.exr");
    FORMAT("#", 0, 0, "0");
    FORMAT("name.exr", 7, 0, "name_0007.exr");
    FORMAT("out/name.exr", 12345, 0, "out/name_12345.exr");
    FORMAT("out.v1/name", 7, 0, "out.v1/name_0007");
    FORMAT("name.exr", 7, 1, "name.exr");
    FORMAT("renders/#/shot.exr", 7, 1, "renders/#/shot.exr");
    FORMAT("renders/#/shot.exr", 7, 0, "renders/#/shot_0007.exr");
    FORMAT("renders/#/s_###.exr", 7, 0, "renders/#/s_007.exr");

    CHECK(tl_pattern_has_frame("shot_####.exr"));
    CHECK(tl_pattern_has_frame("a/b#.png"));
    CHECK(!tl_pattern_has_frame("shot.exr"));
    CHECK(!tl_pattern_has_frame("renders/#/shot.exr"));
    CHECK(!tl_pattern_has_frame(NULL));

    char small[8];
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_pattern_format("shot_####.exr", 7, 0, small, sizeof small, &err) == TL_ERR_USAGE);
    CHECK(small[0] == '\0');
    CHECK_STR_CONTAINS(err.message, "shot_####.exr");
    /* Exactly fitting (12 characters and the terminator) works. */
    char exact[14];
    CHECK(tl_pattern_format("shot_####.exr", 7, 0, exact, sizeof exact, &err) == 0);
    CHECK(strcmp(exact, "shot_0007.exr") == 0);
    CHECK(tl_pattern_format("shot_####.exr", 7, 0, exact, sizeof exact - 1, &err) != 0);
}

/* --skip-existing's test of a frame file: complete and of the run's size,
 * or rendered again. */
static void test_frame_complete(void)
{
    char dir[] = "/tmp/tideline-job-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char png[256], exr[256], cut[256], none[256];
    snprintf(png, sizeof png, "%s/f.png", dir);
    snprintf(exr, sizeof exr, "%s/f.exr", dir);
    snprintf(cut, sizeof cut, "%s/cut.png", dir);
    snprintf(none, sizeof none, "%s/none.png", dir);
    tl_error err;
    tl_frame f;
    CHECK(tl_frame_alloc(&f, 8, 4, &err) == 0);
    CHECK(tl_image_write(png, &f, NULL, &err) == 0);
    CHECK(tl_image_write(exr, &f, NULL, &err) == 0);
    CHECK(tl_job_frame_complete(png, 8, 4, NULL, NULL) == 1);
    CHECK(tl_job_frame_complete(exr, 8, 4, NULL, NULL) == 1);
    /* An EXR without the run's passes, or with passes the run does not
     * write, is rendered again. */
    CHECK(tl_job_frame_complete(exr, 8, 4, "combined,depth", NULL) == 0);
    const tl_meta layered = {"tideline/passes", TL_META_STRING, "combined,depth", 0, 0, NULL};
    CHECK(tl_image_write(exr, &f, &(tl_image_options){.meta = &layered, .meta_count = 1}, &err) ==
          0);
    CHECK(tl_job_frame_complete(exr, 8, 4, "combined,depth", NULL) == 1);
    CHECK(tl_job_frame_complete(exr, 8, 4, "combined,depth", "rec709") == 1);
    CHECK(tl_job_frame_complete(exr, 8, 4, "combined,depth", "acescg") == 0);
    const tl_meta aces[2] = {{"tideline/passes", TL_META_STRING, "combined,depth", 0, 0, NULL},
                             {"tideline/working_space", TL_META_STRING, "acescg", 0, 0, NULL}};
    CHECK(tl_image_write(exr, &f, &(tl_image_options){.meta = aces, .meta_count = 2}, &err) == 0);
    CHECK(tl_job_frame_complete(exr, 8, 4, "combined,depth", "acescg") == 1);
    CHECK(tl_job_frame_complete(exr, 8, 4, "combined,depth", NULL) == 0);
    CHECK(tl_job_frame_complete(exr, 8, 4, "combined,normal", NULL) == 0);
    CHECK(tl_job_frame_complete(exr, 8, 4, NULL, NULL) == 0);
    CHECK(tl_job_frame_complete(png, 8, 5, NULL, NULL) == 0); /* another size */
    CHECK(tl_job_frame_complete(exr, 4, 4, NULL, NULL) == 0);
    CHECK(tl_job_frame_complete(none, 8, 4, NULL, NULL) == 0);
    /* A file cut short, as a killed writer without atomic files leaves. */
    FILE *in = fopen(png, "rb"), *out = fopen(cut, "wb");
    char bytes[4096];
    size_t n = in ? fread(bytes, 1, sizeof bytes, in) : 0;
    CHECK(n > 40);
    if (out)
        fwrite(bytes, 1, n / 2, out);
    if (in)
        fclose(in);
    if (out)
        fclose(out);
    CHECK(tl_job_frame_complete(cut, 8, 4, NULL, NULL) == 0);
    tl_frame_free(&f);
    unlink(png);
    unlink(exr);
    unlink(cut);
    rmdir(dir);
}

int main(void)
{
    test_parse();
    test_chunk();
    test_pattern();
    test_frame_complete();
    TEST_END();
}
