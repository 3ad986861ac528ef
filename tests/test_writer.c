/* render's writer threads: frames written side by side still reach the
 * ordered step (the movie) in submission order, are reported in order, and
 * each writer writes the frame it was given; an error stops the run
 * without a writer waiting forever. */
#include <stdlib.h>
#include <unistd.h>

#include "job/tl_writer.h"
#include "tl_test.h"

#define FRAMES 40

typedef struct writer_log {
    int files[FRAMES];    /* times each frame's files were written */
    long ordered[FRAMES]; /* frame numbers in the order the ordered step saw them */
    int ordered_count;
    long fail_at; /* the frame whose files fail, or -1 */
    int wrong_pixels;
} writer_log;

static int write_files(void *ctx, long n, const tl_scene *scene, const tl_frame *f,
                       const char *path, tl_error *err)
{
    (void)scene;
    (void)path;
    writer_log *l = ctx;
    /* Later frames finish first within a batch: out of order on purpose. */
    usleep((useconds_t)(4000 - (n % 4) * 1000));
    if (f->color[0] != (float)n)
        __atomic_add_fetch(&l->wrong_pixels, 1, __ATOMIC_SEQ_CST);
    if (n == l->fail_at)
        return tl_error_set(err, TL_ERR_RUNTIME, "frame %ld: disk full", n);
    __atomic_add_fetch(&l->files[n], 1, __ATOMIC_SEQ_CST);
    return TL_OK;
}

static int write_ordered(void *ctx, long n, const tl_scene *scene, const tl_frame *f,
                         const char *path, tl_error *err)
{
    (void)scene;
    (void)f;
    (void)path;
    (void)err;
    writer_log *l = ctx;
    l->ordered[l->ordered_count++] = n; /* the writer serialises this step */
    return TL_OK;
}

/* Submits frames 0..FRAMES-1 to `count` writers; returns the status of
 * the run and fills reported[] with the frames waited for, in order. */
static int run(writer_log *l, int count, long *reported, int *reported_count, tl_error *err)
{
    tl_writer w;
    tl_writer_init(&w, write_files, write_ordered, l, count);
    tl_scene scene = {0};
    tl_frame frame = {0};
    int rc = TL_OK;
    long done;
    *reported_count = 0;
    for (long n = 0; !rc && n < FRAMES; n++) {
        if (!frame.color && tl_frame_alloc(&frame, 2, 2, err))
            return TL_ERR_RUNTIME;
        frame.color[0] = (float)n;
        rc = tl_writer_submit(&w, &frame, n, &scene, "", &done, err);
        if (done >= 0)
            reported[(*reported_count)++] = done;
    }
    for (int i = 0; i < w.count; i++) {
        tl_error ignored;
        int wrc = tl_writer_wait(&w, &done, rc ? &ignored : err);
        if (!rc)
            rc = wrc;
        if (done >= 0)
            reported[(*reported_count)++] = done;
    }
    tl_writer_free(&w);
    tl_frame_free(&frame);
    return rc;
}

static void test_in_order(int count)
{
    writer_log l = {.fail_at = -1};
    long reported[FRAMES];
    int reported_count;
    tl_error err;
    CHECK(run(&l, count, reported, &reported_count, &err) == TL_OK);
    CHECK(l.wrong_pixels == 0);
    CHECK(l.ordered_count == FRAMES);
    CHECK(reported_count == FRAMES);
    for (int n = 0; n < FRAMES; n++) {
        CHECK(l.files[n] == 1);
        CHECK(l.ordered[n] == n);
        CHECK(reported[n] == n);
    }
}

static void test_error_stops(int count)
{
    writer_log l = {.fail_at = 9};
    long reported[FRAMES];
    int reported_count;
    tl_error err;
    tl_error_clear(&err);
    CHECK(run(&l, count, reported, &reported_count, &err) == TL_ERR_RUNTIME);
    CHECK_STR_CONTAINS(err.message, "frame 9: disk full");
    /* Frames before the failed one are reported, then those after it that
     * were already in flight (written, so counted), in order; at most
     * `count` were started after it, and none reached the movie out of
     * order. */
    CHECK(reported_count >= 9);
    for (int n = 0; n < reported_count; n++)
        CHECK(reported[n] == (n < 9 ? n : n + 1));
    int started = 0;
    for (int n = 10; n < FRAMES; n++)
        started += l.files[n];
    CHECK(started <= count);
    CHECK(l.files[9] == 0);
    for (int i = 1; i < l.ordered_count; i++)
        CHECK(l.ordered[i] > l.ordered[i - 1]);
    for (int i = 0; i < l.ordered_count; i++)
        CHECK(l.ordered[i] != 9);
}

int main(void)
{
    tl_writer w;
    tl_writer_init(&w, write_files, NULL, NULL, 0);
    CHECK(w.count == 1);
    tl_writer_free(&w);
    tl_writer_init(&w, write_files, NULL, NULL, 100);
    CHECK(w.count == TL_WRITER_MAX);
    tl_writer_free(&w);
    int d = tl_writer_default_count();
    CHECK(d >= 1 && d <= TL_WRITER_MAX);
    for (int count = 1; count <= TL_WRITER_MAX; count *= 2) {
        test_in_order(count);
        test_error_stops(count);
    }
    TEST_END();
}
