/* The bench's measurement: `reference` frames, then every preset over
 * every shot in rounds (tl_bench.h). */
#include "bench/tl_bench.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/tl_clock.h"
#include "image/tl_image_io.h"
#include "job/tl_job.h"
#include "metrics/tl_metrics.h"

/* One frame to measure: a timeline's frame and its reference image. */
typedef struct bench_shot {
    int timeline;
    long frame;
    float *reference; /* display plane of the `reference` render */
} bench_shot;

typedef struct bench_state {
    const tl_bench_config *cfg;
    const tl_bench_timeline *timelines;
    bench_shot *shots;
    int shot_count;
    tl_render *render;
    int boat_of;      /* the timeline whose boat is uploaded, or -1 */
    char scratch[64]; /* folder for the encoded PNGs */
    /* The `reference` frame drawing: its shot, when it began, and the
     * seconds the frames after it will take (-1: not known until one has
     * been timed). */
    int drawing_shot;
    double drawing_start, drawing_after;
} bench_state;

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static void report(bench_state *s, tl_bench_stage stage, const char *preset, int shot, int round,
                   double share, double left)
{
    if (!s->cfg->progress)
        return;
    const bench_shot *b = &s->shots[shot];
    tl_bench_progress p = {.stage = stage,
                           .renderer = s->render ? tl_render_describe(s->render) : "",
                           .preset = preset,
                           .timeline = base_name(s->timelines[b->timeline].path),
                           .frame = b->frame,
                           .shot = shot,
                           .shots = s->shot_count,
                           .round = round,
                           .rounds = stage == TL_BENCH_MEASURING ? s->cfg->rounds : 0,
                           .share = share,
                           .seconds_left = left};
    s->cfg->progress(s->cfg->progress_ctx, &p);
}

/* A `reference` frame's share drawn (tl_render_set_progress): a minute or
 * more a frame on a CPU renderer. The time left counts this frame's rest
 * at its pace so far and the frames after it. */
static void reference_drawn(void *ctx, double share)
{
    bench_state *s = ctx;
    double spent = tl_clock_seconds() - s->drawing_start;
    double frame = share > 0.0 ? spent / share : 0.0;
    double after =
        s->drawing_after >= 0.0 ? s->drawing_after : frame * (s->shot_count - s->drawing_shot - 1);
    report(s, TL_BENCH_REFERENCE, "reference", s->drawing_shot, 0, share,
           share > 0.0 ? frame - spent + after : -1.0);
}

/* `planes`: TL_PLANE_DISPLAY, and TL_PLANE_AOV for a preset with the
 * compositing passes (PRESET+passes); `layers`: the light layers
 * (PRESET+lights). */
static int render_shot(bench_state *s, int shot, const tl_quality *q, unsigned planes,
                       unsigned layers, tl_frame *frame, tl_error *err)
{
    const bench_shot *b = &s->shots[shot];
    const tl_bench_timeline *t = &s->timelines[b->timeline];
    int rc = TL_OK;
    if (s->boat_of != b->timeline)
        rc = tl_render_use_cutscene(s->render, t->cutscene, err);
    s->boat_of = rc ? -1 : b->timeline;
    tl_render_settings settings = {.width = s->cfg->width,
                                   .height = s->cfg->height,
                                   .quality = q,
                                   .planes = planes,
                                   .layers = layers};
    if (!rc)
        rc = tl_render_timeline_frame(s->render, &t->cutscene->timeline, b->frame, &settings, frame,
                                      NULL, err);
    if (rc)
        tl_error_prefix(err, "%s", base_name(t->path));
    return rc;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

double tl_bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The median frame by all passes together, so that its passes add up: a
 * median per pass would mix frames with and without a boat or a giant
 * wave. */
int tl_bench_median_frame(double *const *pass, int n, double *out)
{
    int pick = 0, below_target = (n - 1) / 2;
    for (int k = 0; k < n; k++) {
        int below = 0, equal_before = 0;
        for (int j = 0; j < n; j++) {
            below += pass[TL_BENCH_PASSES][j] < pass[TL_BENCH_PASSES][k];
            equal_before += j < k && pass[TL_BENCH_PASSES][j] == pass[TL_BENCH_PASSES][k];
        }
        if (below + equal_before == below_target) {
            pick = k;
            break;
        }
    }
    for (int i = 0; i <= TL_BENCH_PASSES; i++)
        out[i] = pass[i][pick];
    return pick;
}

int tl_bench_preset_turn(int round, int j, int count)
{
    return (j + round) % count;
}

/* A preset's timings while the rounds run, per shot and round (index
 * shot * rounds + round): total, render, readback, encode, then each kind
 * of pass and all passes; and its errors' sums. */
enum { PARTS = 4 + TL_BENCH_PASSES + 1 };
typedef struct preset_times {
    double *t[PARTS];
    int timed_passes;
    double psnr_sum, ssim_sum;
} preset_times;

/* Shot k with preset p in round r: a render untimed, then one timed. The
 * untimed render takes what a change of preset or shot costs once (each
 * preset compiles its own programs, since octave counts are compiled in,
 * each shot its feature set; the sky's tables follow the shot's sun; the
 * render targets the preset's scale; a preset with another folder's
 * shaders compiles them again). In the first round the frame is
 * then encoded `rounds` times and scored against the reference. The
 * encodes come after the timed render, not between renders: a GPU left
 * idle while the CPU encodes lowers its clock, and its next render is
 * several times slower. */
static int measure_shot(bench_state *s, const tl_bench_preset *p, int k, int r, preset_times *pt,
                        tl_bench_row *row, tl_frame *frame, tl_error *err)
{
    const int rounds = s->cfg->rounds;
    report(s, TL_BENCH_MEASURING, p->name, k, r, -1.0, -1.0);
    int rc = tl_render_use_shaders(s->render, &p->lib, err);
    const unsigned planes = TL_PLANE_DISPLAY | (p->aov ? TL_PLANE_AOV : 0u),
                   layers = p->lights ? (1u << TL_FRAME_LAYERS) - 1u : 0u;
    if (!rc)
        rc = render_shot(s, k, &p->quality, planes, layers, frame, err);
    if (!rc)
        rc = render_shot(s, k, &p->quality, planes, layers, frame, err);
    if (rc) {
        tl_error_prefix(err, "%s", p->name); /* which row's shaders or knobs */
        return rc;
    }
    const int i = k * rounds + r;
    double render = 0.0, readback = 0.0, pass[TL_BENCH_PASSES];
    tl_render_last_timing(s->render, &render, &readback);
    pt->t[1][i] = render * 1e3;
    pt->t[2][i] = readback * 1e3;
    pt->timed_passes = tl_render_pass_seconds(s->render, pass) && pt->timed_passes;
    for (int j = 0; j < TL_BENCH_PASSES; j++) {
        pt->t[4 + j][i] = pass[j] * 1e3;
        pt->t[4 + TL_BENCH_PASSES][i] += pass[j] * 1e3;
    }
    if (r > 0)
        return TL_OK;
    char png[128];
    snprintf(png, sizeof png, "%s/frame.png", s->scratch);
    for (int e = 0; !rc && e < rounds; e++) {
        double t0 = tl_clock_seconds();
        rc = tl_png_write(png, frame, NULL, err);
        pt->t[3][k * rounds + e] = (tl_clock_seconds() - t0) * 1e3;
    }
    if (rc || !s->shots[k].reference)
        return rc;
    tl_metrics m;
    if (tl_metrics_compare(frame->display, s->shots[k].reference, frame->width, frame->height, &m))
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    pt->psnr_sum += m.psnr;
    pt->ssim_sum += m.ssim;
    row->p99 = m.p99 > row->p99 ? m.p99 : row->p99;
    if (m.psnr < row->worst_psnr) {
        row->worst_psnr = m.psnr;
        snprintf(row->worst_shot, sizeof row->worst_shot, "%s:%ld",
                 base_name(s->timelines[s->shots[k].timeline].path), s->shots[k].frame);
    }
    return TL_OK;
}

/* A preset's row from its timings: medians over every shot and round. */
static void finish_row(bench_state *s, preset_times *pt, tl_bench_row *row)
{
    const int rounds = s->cfg->rounds, n = s->shot_count * rounds;
    for (int i = 0; i < n; i++)
        pt->t[0][i] = pt->t[1][i] + pt->t[2][i] + pt->t[3][i];
    /* Before the medians below, which sort their arrays. */
    row->has_passes = s->cfg->passes && pt->timed_passes;
    if (row->has_passes) {
        int pick = tl_bench_median_frame(pt->t + 4, n, row->ms_pass);
        const bench_shot *b = &s->shots[pick / rounds];
        row->ms_pass_render = pt->t[1][pick];
        snprintf(row->pass_shot, sizeof row->pass_shot, "%s:%ld",
                 base_name(s->timelines[b->timeline].path), b->frame);
    }
    row->ms_total = tl_bench_median(pt->t[0], n);
    row->ms_render = tl_bench_median(pt->t[1], n);
    row->ms_readback = tl_bench_median(pt->t[2], n);
    row->ms_encode = tl_bench_median(pt->t[3], n);
    row->psnr = s->cfg->time_only ? NAN : pt->psnr_sum / s->shot_count;
    row->ssim = s->cfg->time_only ? NAN : pt->ssim_sum / s->shot_count;
}

/* Every preset over every shot, in rounds: each round takes the presets
 * in turn (tl_bench_preset_turn), each preset every shot once. */
static int measure(bench_state *s, const tl_bench_preset *presets, int count, tl_bench_row *rows,
                   tl_error *err)
{
    const int rounds = s->cfg->rounds, n = s->shot_count * rounds;
    preset_times *pt = calloc((size_t)count, sizeof *pt);
    int rc = pt ? TL_OK : tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    for (int p = 0; !rc && p < count; p++) {
        memset(&rows[p], 0, sizeof rows[p]);
        memcpy(rows[p].preset, presets[p].name, TL_BENCH_NAME); /* both terminated */
        rows[p].worst_psnr = TL_METRICS_PSNR_MAX + 1.0;
        pt[p].timed_passes = 1;
        for (int i = 0; !rc && i < PARTS; i++)
            if (!(pt[p].t[i] = calloc((size_t)n, sizeof(double))))
                rc = tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    tl_frame frame = {0};
    for (int r = 0; !rc && r < rounds; r++)
        for (int j = 0; !rc && j < count; j++) {
            const int p = tl_bench_preset_turn(r, j, count);
            for (int k = 0; !rc && k < s->shot_count; k++)
                rc = measure_shot(s, &presets[p], k, r, &pt[p], &rows[p], &frame, err);
        }
    for (int p = 0; !rc && p < count; p++)
        finish_row(s, &pt[p], &rows[p]);
    tl_frame_free(&frame);
    for (int p = 0; pt && p < count; p++)
        for (int i = 0; i < PARTS; i++)
            free(pt[p].t[i]);
    free(pt);
    return rc;
}

/* The shots: each timeline's frames from cfg->frames, or its first,
 * middle and last frame. */
static int make_shots(bench_state *s, int timeline_count, tl_error *err)
{
    int rc = TL_OK;
    for (int t = 0; !rc && t < timeline_count; t++) {
        long count = tl_timeline_frame_count(&s->timelines[t].cutscene->timeline);
        char spec[96];
        snprintf(spec, sizeof spec, "0,%ld,%ld", count / 2, count - 1);
        tl_frame_list list = {0};
        rc = tl_frame_list_parse(s->cfg->frames ? s->cfg->frames : spec, count, "--frames", &list,
                                 err);
        if (rc) {
            tl_error_prefix(err, "%s", base_name(s->timelines[t].path));
            break;
        }
        bench_shot *more =
            realloc(s->shots, sizeof(bench_shot) * ((size_t)s->shot_count + list.count));
        if (!more) {
            tl_frame_list_free(&list);
            return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
        }
        s->shots = more;
        for (size_t i = 0; i < list.count; i++)
            s->shots[s->shot_count++] = (bench_shot){t, list.frames[i], NULL};
        tl_frame_list_free(&list);
    }
    return rc;
}

/* Shot k's reference from the cache: 1 when found. */
static int cached_reference(bench_state *s, int k, uint64_t *key)
{
    const bench_shot *b = &s->shots[k];
    const tl_bench_timeline *t = &s->timelines[b->timeline];
    *key = tl_bench_cache_key(s->cfg->cache, tl_render_describe(s->render), t->path,
                              t->cutscene->timeline.objects[0].model, b->frame, s->cfg->width,
                              s->cfg->height);
    return tl_bench_cache_load(s->cfg->cache, *key, s->cfg->width, s->cfg->height, b->reference);
}

static int render_references(bench_state *s, tl_bench_row *row, tl_error *err)
{
    tl_quality ref;
    tl_quality_preset("reference", &ref, err);
    if (tl_render_use_shaders(s->render, s->cfg->reference_lib, err))
        return err->status;
    if (s->cfg->progress && s->cfg->reference_shares)
        tl_render_set_progress(s->render, reference_drawn, s);
    tl_frame frame = {0};
    int rc = TL_OK, timed = 0;
    double *ms = calloc((size_t)s->shot_count, sizeof(double));
    if (!ms)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    memset(row, 0, sizeof *row);
    size_t bytes = sizeof(float) * 4 * (size_t)s->cfg->width * (size_t)s->cfg->height;
    for (int k = 0; !rc && k < s->shot_count; k++) {
        if (!(s->shots[k].reference = malloc(bytes))) {
            rc = tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
            break;
        }
        uint64_t key = 0;
        if (s->cfg->cache && cached_reference(s, k, &key)) {
            row->cached++;
            continue;
        }
        /* The frames to go at the mean of those rendered (the cached ones
         * among them are not known yet). */
        double sum = 0.0;
        for (int i = 0; i < timed; i++)
            sum += ms[i];
        report(s, TL_BENCH_REFERENCE, "reference", k, 0, -1.0,
               timed ? sum / timed * 1e-3 * (s->shot_count - k) : -1.0);
        s->drawing_shot = k;
        s->drawing_start = tl_clock_seconds();
        s->drawing_after = timed ? sum / timed * 1e-3 * (s->shot_count - k - 1) : -1.0;
        rc = render_shot(s, k, &ref, TL_PLANE_DISPLAY, 0u, &frame, err);
        if (rc)
            break;
        memcpy(s->shots[k].reference, frame.display, bytes);
        double render, readback;
        tl_render_last_timing(s->render, &render, &readback);
        ms[timed++] = (render + readback) * 1e3;
        tl_error keep;
        tl_error_clear(&keep);
        /* The cache only saves time: a frame it cannot keep is a warning. */
        if (s->cfg->cache &&
            tl_bench_cache_store(s->cfg->cache, key, frame.width, frame.height, frame.display,
                                 &keep) &&
            s->cfg->progress) {
            tl_bench_progress p = {.stage = TL_BENCH_WARNING, .warning = keep.message};
            s->cfg->progress(s->cfg->progress_ctx, &p);
        }
    }
    snprintf(row->preset, sizeof row->preset, "reference");
    row->is_reference = 1;
    if (!rc) {
        /* NAN: every frame from the cache */
        row->ms_total = timed ? tl_bench_median(ms, timed) : NAN;
        row->ms_render = row->ms_total;
        row->psnr = TL_METRICS_PSNR_MAX;
        row->ssim = 1.0;
    }
    free(ms);
    tl_frame_free(&frame);
    return rc;
}

int tl_bench_run(const tl_bench_config *cfg, const tl_bench_timeline *timelines, int timeline_count,
                 const tl_bench_preset *presets, int count, tl_bench_row *rows, int *row_count,
                 int *shots, tl_error *err)
{
    bench_state s = {.cfg = cfg, .timelines = timelines, .boat_of = -1};
    *row_count = 0;
    *shots = 0;
    int rc = make_shots(&s, timeline_count, err);
    if (!rc)
        rc = tl_render_open(&s.render, cfg->reference_lib, err);
    if (!rc && cfg->passes)
        tl_render_time_passes(s.render, 1);
    if (!rc && !mkdtemp(strcpy(s.scratch, "/tmp/tideline-bench-XXXXXX")))
        rc = tl_error_set(err, TL_ERR_RUNTIME, "cannot create a scratch folder in /tmp");
    if (!rc && s.shot_count)
        report(&s, TL_BENCH_STARTED, "", 0, 0, -1.0, -1.0);
    int first = cfg->time_only ? 0 : 1; /* row 0: `reference`, when measured */
    if (!rc && !cfg->time_only)
        rc = render_references(&s, &rows[0], err);
    /* The presets are timed without the waits a frame's share costs. */
    if (s.render)
        tl_render_set_progress(s.render, NULL, NULL);
    if (!rc)
        rc = measure(&s, presets, count, rows + first, err);
    if (s.scratch[0]) {
        char png[128];
        snprintf(png, sizeof png, "%s/frame.png", s.scratch);
        unlink(png);
        rmdir(s.scratch);
    }
    if (!rc) {
        *row_count = first + count;
        *shots = s.shot_count;
    }
    tl_render_close(s.render);
    for (int k = 0; k < s.shot_count; k++)
        free(s.shots[k].reference);
    free(s.shots);
    return rc;
}
