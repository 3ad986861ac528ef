/* A render run through the library (tl_run_frames): every frame written
 * and reported in order, a second run with skip_existing skips them all,
 * and a stop after the first frame written ends the run interrupted with
 * the frames drawn before it written and nothing half-made. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "run/tl_run.h"
#include "shader/tl_shader_lib.h"
#include "timeline/tl_parse.h"
#include "tl_test.h"

typedef struct seen {
    long written[16], skipped[16];
    int written_count, skipped_count, started;
    volatile sig_atomic_t *stop_after_first;
} seen;

static void record(void *ctx, const tl_run_status *st)
{
    seen *s = ctx;
    if (st->event == TL_RUN_STARTED)
        s->started++;
    if (st->event == TL_RUN_WRITTEN && s->written_count < 16)
        s->written[s->written_count++] = st->frame;
    if (st->event == TL_RUN_SKIPPED && s->skipped_count < 16)
        s->skipped[s->skipped_count++] = st->frame;
    if (st->event == TL_RUN_WRITTEN && s->stop_after_first)
        *s->stop_after_first = 1;
}

static int count_files(const char *dir)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "ls -A '%s' | wc -l", dir);
    FILE *p = popen(cmd, "r");
    int n = -1;
    if (p) {
        if (fscanf(p, "%d", &n) != 1)
            n = -1;
        pclose(p);
    }
    return n;
}

int main(void)
{
    const char *text = "tideline 1\nduration 1s\nfps 8\nsize 32x18\nquality draft\n";
    tl_timeline tl;
    tl_diags diags;
    tl_error err;
    tl_error_clear(&err);
    if (tl_timeline_parse_text("run.tl", text, strlen(text), &tl, &diags, &err)) {
        printf("run.tl: %s\n", err.message);
        return 1;
    }
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    tl_render *render = NULL;
    if (tl_render_open(&render, &lib, &err)) {
        printf("no GL: %s\n", err.message);
        return 1;
    }
    char dir[] = "/tmp/tideline-run-XXXXXX", pattern[256];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(pattern, sizeof pattern, "%s/f_##.png", dir);
    tl_frame_list frames = {0};
    CHECK(tl_frame_list_parse("0-5", tl_timeline_frame_count(&tl), "--frames", &frames, &err) == 0);

    seen s = {0};
    tl_run_config cfg = {.timeline = &tl,
                         .timeline_path = "run.tl",
                         .frames = &frames,
                         .pattern = pattern,
                         .writers = 2,
                         .report = record,
                         .report_ctx = &s};
    tl_run_result r;
    CHECK(tl_run_frames(render, &cfg, &r, &err) == 0);
    CHECK(s.started == 1);
    CHECK(r.written == 6 && r.skipped == 0 && r.drawn == 6 && !r.interrupted);
    CHECK(s.written_count == 6);
    for (int i = 0; i < s.written_count; i++)
        CHECK(s.written[i] == i); /* reported in order */
    CHECK(count_files(dir) == 6);

    seen again = {0};
    cfg.report_ctx = &again;
    cfg.skip_existing = 1;
    CHECK(tl_run_frames(render, &cfg, &r, &err) == 0);
    CHECK(r.written == 0 && r.skipped == 6 && r.drawn == 0);
    CHECK(again.skipped_count == 6 && again.skipped[5] == 5);

    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -f '%s'/f_*.png", dir);
    CHECK(system(cmd) == 0);
    volatile sig_atomic_t stop = 0;
    seen stopped = {.stop_after_first = &stop};
    cfg.report_ctx = &stopped;
    cfg.skip_existing = 0;
    cfg.stop = &stop;
    CHECK(tl_run_frames(render, &cfg, &r, &err) == 0);
    printf("stopped after the first frame written: %zu written\n", r.written);
    CHECK(r.interrupted);
    CHECK(r.written >= 1 && r.written < 6);
    CHECK(count_files(dir) == (int)r.written); /* no temporary left */

    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
    tl_frame_list_free(&frames);
    tl_render_close(render);
    tl_timeline_free(&tl);
    TEST_END();
}
