/* tideline bench: the speed-accuracy trade, measured. Renders chosen frames
 * of one or more timelines with each quality preset and with `reference`,
 * and reports per preset the median time per frame (split into render,
 * readback and PNG encoding) and the error against `reference` (PSNR,
 * SSIM, 99th-percentile pixel error, the worst frame). Table on stdout; a
 * CSV and a gnuplot plot on request (tl_cli_bench_report.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "cli/tl_cli_bench.h"
#include "core/tl_clock.h"
#include "image/tl_image_io.h"
#include "job/tl_job.h"
#include "mesh/tl_mesh.h"
#include "metrics/tl_metrics.h"
#include "render/tl_render.h"
#include "timeline/tl_channels.h"
#include "timeline/tl_timeline.h"

static const char usage[] =
    "Usage: tideline bench TIMELINE.tl... [options]\n"
    "\n"
    "Measure the speed-accuracy trade: render frames of each timeline with each\n"
    "preset and with `reference`, then print per preset the median ms per frame\n"
    "(after a warm-up), split into render (until the GPU finishes), readback and\n"
    "PNG encoding, and the error against `reference` of the display image: mean\n"
    "PSNR and SSIM, the worst 99th-percentile pixel error (8-bit levels), and the\n"
    "worst frame. Presets no other beats in both time and PSNR form the Pareto\n"
    "front (marked *).\n"
    "\n"
    "Options:\n"
    "  --frames LIST     frames of every timeline, e.g. 0,120,239 or 0-239:60\n"
    "                    (default: first, middle and last)\n"
    "  --size WxH        frame size (default 640x360)\n"
    "  --presets LIST    comma-separated presets (default draft,preview,final,seed);\n"
    "                    PRESET:KNOB=V:... is a variant with quality knobs changed,\n"
    "                    e.g. final:lod=off or final:refine_steps=2:hit_epsilon=0.02;\n"
    "                    PRESET@DIR renders with the shaders in DIR, timed in the\n"
    "                    same rounds as the rest (a shader edit against the shaders\n"
    "                    it changes: preview,preview@my-shaders)\n"
    "  --repeat N        rounds, 1..100 (default 3): each times every preset on\n"
    "                    every frame once, the presets taking turns, so that a\n"
    "                    slow spell of the machine falls on all of them alike\n"
    "  --time-only       time the presets only: no `reference` render, no error\n"
    "                    columns (to time a change quickly)\n"
    "  --shader-dir DIR  render with the shaders in DIR instead of the built-in\n"
    "                    copies (to measure a shader edit before rebuilding)\n"
    "  --reference-cache DIR\n"
    "                    keep the `reference` frames in DIR and reuse them in\n"
    "                    later runs (each 16 bytes a pixel, named by a hash of\n"
    "                    this program, the shaders, the GL renderer, the\n"
    "                    timeline and its boat model, the frame and the size:\n"
    "                    any change renders afresh; delete DIR to free it)\n"
    "  --passes          also print where each preset's render time goes: the ms\n"
    "                    of each kind of pass in its median frame (boat, march\n"
    "                    prepass, ocean, giant wave, glare, display, pixel\n"
    "                    filter, all of them), each pass fenced with glFinish\n"
    "  --csv FILE        write the table as CSV (one row per preset)\n"
    "  --plot FILE.png   plot PSNR against ms per frame with the Pareto front\n"
    "                    (needs gnuplot: Debian package gnuplot-nox)\n"
    "  -q, --quiet       no progress lines\n"
    "  -h, --help        show this help\n"
    "\n"
    "Timings depend on everything else the machine is doing: compare presets\n"
    "within one run. Exit status: 0, 1 when a render, the CSV or the plot\n"
    "fails, 2 usage error.\n";

#define MAX_TIMELINES 16

typedef struct bench_options {
    const char *timelines[MAX_TIMELINES];
    int timeline_count;
    const char *frames, *csv, *plot, *shader_dir, *cache_dir;
    char presets[2048];
    int width, height, repeat, quiet, time_only, passes;
} bench_options;

static int parse(int argc, char **argv, bench_options *o, int *help, tl_error *err)
{
    tl_args a;
    tl_args_init(&a, argc, argv);
    a.index = 1;
    while (!tl_args_done(&a)) {
        int rc = TL_OK;
        const char *pos;
        if (tl_args_match(&a, "--help", "-h", false, err)) {
            *help = 1;
            return TL_OK;
        } else if (tl_args_match(&a, "--quiet", "-q", false, err)) {
            o->quiet = 1;
        } else if (tl_args_match(&a, "--frames", NULL, true, err)) {
            o->frames = a.value;
        } else if (tl_args_match(&a, "--size", NULL, true, err)) {
            rc = a.value ? tl_args_size(a.flag, a.value, &o->width, &o->height, err) : 0;
        } else if (tl_args_match(&a, "--presets", NULL, true, err)) {
            if (a.value &&
                snprintf(o->presets, sizeof o->presets, "%s", a.value) >= (int)sizeof o->presets)
                rc = tl_error_set(err, TL_ERR_USAGE, "--presets: the list is too long");
        } else if (tl_args_match(&a, "--repeat", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 1, 100, &o->repeat, err) : 0;
        } else if (tl_args_match(&a, "--time-only", NULL, false, err)) {
            o->time_only = 1;
        } else if (tl_args_match(&a, "--passes", NULL, false, err)) {
            o->passes = 1;
        } else if (tl_args_match(&a, "--shader-dir", NULL, true, err)) {
            o->shader_dir = a.value;
        } else if (tl_args_match(&a, "--reference-cache", NULL, true, err)) {
            o->cache_dir = a.value;
        } else if (tl_args_match(&a, "--csv", NULL, true, err)) {
            o->csv = a.value;
        } else if (tl_args_match(&a, "--plot", NULL, true, err)) {
            o->plot = a.value;
            if (a.value && tl_image_format_from_path(a.value) != TL_IMAGE_PNG)
                rc = tl_error_set(err, TL_ERR_USAGE, "--plot: '%s' is not a .png file", a.value);
        } else if (!err->status && tl_args_positional(&a, &pos)) {
            if (o->timeline_count == MAX_TIMELINES)
                rc = tl_error_set(err, TL_ERR_USAGE, "more than %d timelines", MAX_TIMELINES);
            else
                o->timelines[o->timeline_count++] = pos;
        } else if (!err->status) {
            rc = tl_args_unknown(&a, "bench", err);
        }
        if (err->status)
            return err->status;
        if (rc)
            return rc;
    }
    if (o->timeline_count == 0)
        return tl_error_set(err, TL_ERR_USAGE, "no timeline given (see --help)");
    if (o->time_only && o->plot)
        return tl_error_set(err, TL_ERR_USAGE,
                            "--plot: the plot needs the error against `reference`, which "
                            "--time-only does not measure");
    if (o->time_only && o->cache_dir)
        return tl_error_set(err, TL_ERR_USAGE,
                            "--reference-cache: --time-only renders no `reference` to keep");
    return TL_OK;
}

/* One `KNOB=VALUE` of a variant: a quality.* channel of one component. */
static int apply_knob(const char *spec, char *knob, tl_quality *q, tl_error *err)
{
    char *eq = strchr(knob, '=');
    char name[96];
    if (!eq || eq == knob)
        return tl_error_set(err, TL_ERR_USAGE, "--presets: '%s': '%s' is not KNOB=VALUE", spec,
                            knob);
    *eq = '\0';
    snprintf(name, sizeof name, "quality.%s", knob);
    const tl_channel *ch = tl_channel_find(name);
    if (!ch)
        return tl_error_set(err, TL_ERR_USAGE, "--presets: '%s': no quality knob '%s'", spec, knob);
    const char *text = eq + 1;
    double v;
    char *end = NULL;
    if (ch->kind == TL_CH_BOOL) {
        if (strcmp(text, "on") && strcmp(text, "off"))
            return tl_error_set(err, TL_ERR_USAGE, "--presets: '%s': %s=%s is not on or off", spec,
                                knob, text);
        v = !strcmp(text, "on");
    } else {
        v = strtod(text, &end);
        if (end == text || *end || !(v >= ch->min && v <= ch->max) ||
            (ch->kind != TL_CH_REAL && v != (double)(long)v))
            return tl_error_set(
                err, TL_ERR_USAGE, "--presets: '%s': %s=%s is not a %s in %g..%g", spec, knob, text,
                ch->kind == TL_CH_REAL ? "number" : "whole number", ch->min, ch->max);
    }
    tl_scene s;
    tl_scene_defaults(&s);
    s.quality = *q;
    const double in[3] = {v, v, v};
    tl_channel_set(ch, &s, in);
    *q = s.quality;
    return TL_OK;
}

/* Splits the preset list. Each item is a preset's name, optionally with
 * knobs changed (a variant): `final:refine_steps=2:lod=off`, and with
 * another folder's shaders: `preview@DIR` (dirs[i]: DIR, in `list`, or
 * NULL). `reference` may not be listed (it is what the others are
 * measured against). */
static int parse_presets(char *list, tl_quality *out, char names[][TL_BENCH_NAME],
                         const char **dirs, int *count, tl_error *err)
{
    *count = 0;
    for (char *save = NULL, *item = strtok_r(list, ",", &save); item;
         item = strtok_r(NULL, ",", &save)) {
        if (*count == TL_BENCH_MAX_PRESETS)
            return tl_error_set(err, TL_ERR_USAGE, "--presets: more than %d presets",
                                TL_BENCH_MAX_PRESETS);
        if (snprintf(names[*count], TL_BENCH_NAME, "%s", item) >= TL_BENCH_NAME)
            return tl_error_set(err, TL_ERR_USAGE, "--presets: '%s' is too long", item);
        char *at = strchr(item, '@');
        dirs[*count] = NULL;
        if (at) {
            *at++ = '\0';
            if (!*at)
                return tl_error_set(err, TL_ERR_USAGE, "--presets: '%s' names no folder after '@'",
                                    names[*count]);
            dirs[*count] = at;
        }
        char *rest = strchr(item, ':');
        if (rest)
            *rest++ = '\0';
        if (strcmp(item, "reference") == 0)
            return tl_error_set(err, TL_ERR_USAGE,
                                "--presets: 'reference' is always rendered (it is the yardstick)");
        if (tl_quality_preset(item, &out[*count], err)) {
            tl_error_prefix(err, "--presets");
            return TL_ERR_USAGE;
        }
        for (char *knob = rest; knob;) {
            char *next = strchr(knob, ':');
            if (next)
                *next++ = '\0';
            if (apply_knob(names[*count], knob, &out[*count], err))
                return TL_ERR_USAGE;
            knob = next;
        }
        (*count)++;
    }
    if (*count == 0)
        return tl_error_set(err, TL_ERR_USAGE, "--presets: no preset named");
    return TL_OK;
}

/* One frame to measure: a timeline's frame and its reference image. */
typedef struct bench_shot {
    int timeline;
    long frame;
    float *reference; /* display plane of the `reference` render */
} bench_shot;

typedef struct bench_state {
    bench_options *o;
    tl_timeline tl[MAX_TIMELINES];
    tl_mesh boat[MAX_TIMELINES];
    bench_shot *shots;
    int shot_count;
    tl_render *render;
    tl_shader_lib lib;                              /* built in, or --shader-dir */
    tl_shader_lib preset_lib[TL_BENCH_MAX_PRESETS]; /* each preset's: lib, or its @DIR */
    tl_bench_cache cache;                           /* --reference-cache (dir empty: none) */
    int boat_of;                                    /* the timeline whose boat is uploaded, or -1 */
    char scratch[64];                               /* folder for the encoded PNGs */
    double last_progress;
    /* The `reference` frame drawing (its share shown on a terminal): its
     * shot, when it began, and the seconds the frames after it will take
     * (-1: not known until one has been timed). */
    int drawing_shot;
    double drawing_start, drawing_after;
} bench_state;

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* A progress line, at most two a second. `left`: seconds to go, printed
 * as an ETA when >= 0; a line that has one is always printed (the
 * `reference` frames, each a long render). `round` of `rounds` (0: none,
 * the references). `share`: of the frame drawn, printed when >= 0. */
static void progress_eta(bench_state *s, const char *preset, int shot, int round, int rounds,
                         double share, double left)
{
    if (s->o->quiet)
        return;
    double now = tl_clock_seconds();
    /* Throttled: a frame's share, and lines without an ETA after the first. */
    if (now - s->last_progress < 0.5 * tl_cli_progress_delay() &&
        (share >= 0.0 || (shot > 0 && left < 0.0)))
        return;
    s->last_progress = now;
    const bench_shot *b = &s->shots[shot];
    char eta[48] = "", of[32] = "", drawn[16] = "";
    if (left >= 0.0) {
        char took[32];
        tl_cli_format_duration(left, took, sizeof took);
        snprintf(eta, sizeof eta, " ETA %s", took);
    }
    if (rounds > 1)
        snprintf(of, sizeof of, " round %d/%d", round + 1, rounds);
    if (share >= 0.0)
        snprintf(drawn, sizeof drawn, " %3.0f%%", share * 100.0);
    fprintf(stderr, "bench: %-9s %s frame %ld (%d/%d)%s%s%s%s", preset,
            base_name(s->o->timelines[b->timeline]), b->frame, shot + 1, s->shot_count, of, drawn,
            eta, isatty(STDERR_FILENO) ? "        \r" : "\n");
}

/* A `reference` frame's share drawn, on a terminal (tl_render_set_progress):
 * a minute or more a frame on a CPU renderer. The ETA counts this frame's
 * rest at its pace so far and the frames after it. */
static void reference_drawn(void *ctx, double share)
{
    bench_state *s = ctx;
    double spent = tl_clock_seconds() - s->drawing_start;
    double frame = share > 0.0 ? spent / share : 0.0;
    double after =
        s->drawing_after >= 0.0 ? s->drawing_after : frame * (s->shot_count - s->drawing_shot - 1);
    progress_eta(s, "reference", s->drawing_shot, 0, 0, share,
                 share > 0.0 ? frame - spent + after : -1.0);
}

static int render_shot(bench_state *s, int shot, const tl_quality *q, tl_frame *frame,
                       tl_error *err)
{
    const bench_shot *b = &s->shots[shot];
    int t = b->timeline;
    int rc = TL_OK;
    if (s->boat_of != t)
        rc = tl_render_set_boat(s->render, s->boat[t].index_count ? &s->boat[t] : NULL, err);
    s->boat_of = rc ? -1 : t;
    tl_render_settings settings = {
        .width = s->o->width, .height = s->o->height, .quality = q, .planes = TL_PLANE_DISPLAY};
    if (!rc)
        rc = tl_render_timeline_frame(s->render, &s->tl[t], b->frame, &settings, frame, NULL, err);
    if (rc)
        tl_error_prefix(err, base_name(s->o->timelines[t]));
    return rc;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The passes of the median frame by all passes together (the lower of
 * the middle two), so that they add up: a median per pass would mix
 * frames with and without a boat or a giant wave. pass[i][k]: frame k's
 * time in pass i, pass[TL_BENCH_PASSES][k] its sum. */
static int median_frame_passes(double *const *pass, int n, double *out)
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

/* A preset's timings while the rounds run, per shot and round (index
 * shot * rounds + round): total, render, readback, encode, then each kind
 * of pass and all passes; and its errors' sums. */
enum { PARTS = 4 + TL_BENCH_PASSES + 1 };
typedef struct preset_times {
    double *t[PARTS];
    int timed_passes;
    double psnr_sum, ssim_sum;
} preset_times;

/* Shot k with preset q in round r: a render untimed, then one timed. The
 * untimed render takes what a change of preset or shot costs once (each
 * preset compiles its own programs, since octave counts are compiled in,
 * each shot its feature set; the sky's tables follow the shot's sun; the
 * render targets the preset's scale; a preset with another folder's
 * shaders compiles them again). In the first round the frame is
 * then encoded `rounds` times and scored against the reference. The
 * encodes come after the timed render, not between renders: a GPU left
 * idle while the CPU encodes lowers its clock (an H100 timed 16 ms a frame
 * back to back and up to 77 ms with encodes in between). */
static int measure_shot(bench_state *s, const tl_quality *q, const tl_shader_lib *lib,
                        const char *name, int k, int r, int rounds, preset_times *pt,
                        tl_bench_row *row, tl_frame *frame, tl_error *err)
{
    progress_eta(s, name, k, r, rounds, -1.0, -1.0);
    int rc = tl_render_use_shaders(s->render, lib, err);
    if (!rc)
        rc = render_shot(s, k, q, frame, err);
    if (!rc)
        rc = render_shot(s, k, q, frame, err);
    if (rc) {
        tl_error_prefix(err, "%s", name); /* which row's shaders or knobs */
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
                 base_name(s->o->timelines[s->shots[k].timeline]), s->shots[k].frame);
    }
    return TL_OK;
}

/* A preset's row from its timings: medians over every shot and round. */
static void finish_row(bench_state *s, preset_times *pt, int rounds, tl_bench_row *row)
{
    const int n = s->shot_count * rounds;
    for (int i = 0; i < n; i++)
        pt->t[0][i] = pt->t[1][i] + pt->t[2][i] + pt->t[3][i];
    /* Before the medians below, which sort their arrays. */
    row->has_passes = s->o->passes && pt->timed_passes;
    if (row->has_passes) {
        int pick = median_frame_passes(pt->t + 4, n, row->ms_pass);
        const bench_shot *b = &s->shots[pick / rounds];
        row->ms_pass_render = pt->t[1][pick];
        snprintf(row->pass_shot, sizeof row->pass_shot, "%s:%ld",
                 base_name(s->o->timelines[b->timeline]), b->frame);
    }
    row->ms_total = median(pt->t[0], n);
    row->ms_render = median(pt->t[1], n);
    row->ms_readback = median(pt->t[2], n);
    row->ms_encode = median(pt->t[3], n);
    row->psnr = s->o->time_only ? NAN : pt->psnr_sum / s->shot_count;
    row->ssim = s->o->time_only ? NAN : pt->ssim_sum / s->shot_count;
}

/* Every preset over every shot, in `repeat` rounds: each round takes the
 * presets in turn, each preset every shot once, and the next round starts
 * one preset further along. The host's slow spells then fall on every
 * preset alike, where preset after preset (each with all its renders)
 * gave one of them a whole spell. */
static int measure(bench_state *s, const tl_quality *presets, char names[][TL_BENCH_NAME],
                   int count, tl_bench_row *rows, tl_error *err)
{
    const int rounds = s->o->repeat, n = s->shot_count * rounds;
    preset_times *pt = calloc((size_t)count, sizeof *pt);
    int rc = pt ? TL_OK : tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    for (int p = 0; !rc && p < count; p++) {
        memset(&rows[p], 0, sizeof rows[p]);
        memcpy(rows[p].preset, names[p], TL_BENCH_NAME); /* both TL_BENCH_NAME, terminated */
        rows[p].worst_psnr = TL_METRICS_PSNR_MAX + 1.0;
        pt[p].timed_passes = 1;
        for (int i = 0; !rc && i < PARTS; i++)
            if (!(pt[p].t[i] = calloc((size_t)n, sizeof(double))))
                rc = tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    tl_frame frame = {0};
    for (int r = 0; !rc && r < rounds; r++)
        for (int j = 0; !rc && j < count; j++) {
            const int p = (j + r) % count;
            for (int k = 0; !rc && k < s->shot_count; k++)
                rc = measure_shot(s, &presets[p], &s->preset_lib[p], names[p], k, r, rounds, &pt[p],
                                  &rows[p], &frame, err);
        }
    for (int p = 0; !rc && p < count; p++)
        finish_row(s, &pt[p], rounds, &rows[p]);
    tl_frame_free(&frame);
    for (int p = 0; pt && p < count; p++)
        for (int i = 0; i < PARTS; i++)
            free(pt[p].t[i]);
    free(pt);
    return rc;
}

/* The shots: each timeline's frames from --frames, or its first, middle
 * and last frame. */
static int make_shots(bench_state *s, tl_error *err)
{
    int rc = TL_OK;
    for (int t = 0; !rc && t < s->o->timeline_count; t++) {
        long count = tl_timeline_frame_count(&s->tl[t]);
        char spec[96];
        snprintf(spec, sizeof spec, "0,%ld,%ld", count / 2, count - 1);
        tl_frame_list list = {0};
        rc = tl_frame_list_parse(s->o->frames ? s->o->frames : spec, count, "--frames", &list, err);
        if (rc) {
            tl_error_prefix(err, base_name(s->o->timelines[t]));
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

/* Shot k's reference from --reference-cache: 1 when found. */
static int cached_reference(bench_state *s, int k, uint64_t *key)
{
    const bench_shot *b = &s->shots[k];
    *key =
        tl_bench_cache_key(&s->cache, tl_render_describe(s->render), s->o->timelines[b->timeline],
                           s->tl[b->timeline].boat_model, b->frame, s->o->width, s->o->height);
    return tl_bench_cache_load(&s->cache, *key, s->o->width, s->o->height, b->reference);
}

static int render_references(bench_state *s, tl_bench_row *row, tl_error *err)
{
    tl_quality ref;
    tl_quality_preset("reference", &ref, err);
    if (tl_render_use_shaders(s->render, &s->lib, err))
        return err->status;
    if (!s->o->quiet && isatty(STDERR_FILENO))
        tl_render_set_progress(s->render, reference_drawn, s);
    tl_frame frame = {0};
    int rc = TL_OK, timed = 0;
    double *ms = calloc((size_t)s->shot_count, sizeof(double));
    if (!ms)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    memset(row, 0, sizeof *row);
    size_t bytes = sizeof(float) * 4 * (size_t)s->o->width * (size_t)s->o->height;
    for (int k = 0; !rc && k < s->shot_count; k++) {
        if (!(s->shots[k].reference = malloc(bytes))) {
            rc = tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
            break;
        }
        uint64_t key = 0;
        if (s->cache.dir[0] && cached_reference(s, k, &key)) {
            row->cached++;
            continue;
        }
        /* The frames to go at the mean of those rendered (the cached ones
         * among them are not known yet). */
        double sum = 0.0;
        for (int i = 0; i < timed; i++)
            sum += ms[i];
        progress_eta(s, "reference", k, 0, 0, -1.0,
                     timed ? sum / timed * 1e-3 * (s->shot_count - k) : -1.0);
        s->drawing_shot = k;
        s->drawing_start = tl_clock_seconds();
        s->drawing_after = timed ? sum / timed * 1e-3 * (s->shot_count - k - 1) : -1.0;
        rc = render_shot(s, k, &ref, &frame, err);
        if (rc)
            break;
        memcpy(s->shots[k].reference, frame.display, bytes);
        double render, readback;
        tl_render_last_timing(s->render, &render, &readback);
        ms[timed++] = (render + readback) * 1e3;
        tl_error keep;
        tl_error_clear(&keep);
        /* The cache only saves time: a frame it cannot keep is a warning. */
        if (s->cache.dir[0] &&
            tl_bench_cache_store(&s->cache, key, frame.width, frame.height, frame.display, &keep))
            fprintf(stderr, "bench: warning: --reference-cache: %s\n", keep.message);
    }
    snprintf(row->preset, sizeof row->preset, "reference");
    row->is_reference = 1;
    if (!rc) {
        row->ms_total = timed ? median(ms, timed) : NAN; /* NAN: every frame from the cache */
        row->ms_render = row->ms_total;
        row->psnr = TL_METRICS_PSNR_MAX;
        row->ssim = 1.0;
        if (row->cached && !s->o->quiet)
            fprintf(stderr, "bench: %d of %d reference frames from %s\n", row->cached,
                    s->shot_count, s->cache.dir);
    }
    free(ms);
    tl_frame_free(&frame);
    return rc;
}

static int run(bench_state *s, tl_bench_row *rows, int *row_count, const tl_quality *presets,
               char names[][TL_BENCH_NAME], int preset_count, tl_error *err)
{
    int rc = tl_render_open(&s->render, &s->lib, err);
    if (!rc && s->o->passes)
        tl_render_time_passes(s->render, 1);
    if (!rc && !mkdtemp(strcpy(s->scratch, "/tmp/tideline-bench-XXXXXX")))
        rc = tl_error_set(err, TL_ERR_RUNTIME, "cannot create a scratch folder in /tmp");
    if (!rc && !s->o->quiet)
        fprintf(stderr, "bench: %d frames at %dx%d on %s\n", s->shot_count, s->o->width,
                s->o->height, tl_render_describe(s->render));
    int first = s->o->time_only ? 0 : 1; /* row 0: `reference`, when measured */
    if (!rc && !s->o->time_only)
        rc = render_references(s, &rows[0], err);
    /* The presets are timed without the waits a frame's share costs. */
    if (s->render)
        tl_render_set_progress(s->render, NULL, NULL);
    if (!rc)
        rc = measure(s, presets, names, preset_count, rows + first, err);
    if (!s->o->quiet && isatty(STDERR_FILENO))
        fprintf(stderr, "%60s\r", "");
    if (s->scratch[0]) {
        char png[128];
        snprintf(png, sizeof png, "%s/frame.png", s->scratch);
        unlink(png);
        rmdir(s->scratch);
    }
    *row_count = first + preset_count;
    return rc;
}

int tl_cli_bench(int argc, char **argv)
{
    tl_error err;
    tl_error_clear(&err);
    bench_options o = {.width = 640, .height = 360, .repeat = 3};
    snprintf(o.presets, sizeof o.presets, "draft,preview,final,seed");
    int help = 0;
    int rc = parse(argc, argv, &o, &help, &err);
    if (help) {
        fputs(usage, stdout);
        return 0;
    }
    tl_quality presets[TL_BENCH_MAX_PRESETS];
    static char names[TL_BENCH_MAX_PRESETS][TL_BENCH_NAME];
    int preset_count = 0;
    const char *dirs[TL_BENCH_MAX_PRESETS];
    if (!rc)
        rc = parse_presets(o.presets, presets, names, dirs, &preset_count, &err);
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    if (!rc && o.shader_dir && tl_shader_lib_from_dir(&lib, o.shader_dir, &err)) {
        tl_error_prefix(&err, "--shader-dir");
        rc = TL_ERR_USAGE;
    }
    static tl_shader_lib preset_lib[TL_BENCH_MAX_PRESETS];
    for (int p = 0; !rc && p < preset_count; p++) {
        preset_lib[p] = lib;
        if (dirs[p] && tl_shader_lib_from_dir(&preset_lib[p], dirs[p], &err)) {
            tl_error_prefix(&err, "--presets: %s", names[p]);
            rc = TL_ERR_USAGE;
        }
    }
    if (!rc && o.csv && tl_cli_make_parent_dirs(o.csv, &err))
        rc = TL_ERR_USAGE;
    if (!rc && o.plot &&
        (tl_cli_make_parent_dirs(o.plot, &err) || tl_image_check_writable(o.plot, &err)))
        rc = TL_ERR_USAGE;
    static bench_state s;
    memset(&s, 0, sizeof s);
    if (!rc && o.cache_dir && tl_bench_cache_open(&s.cache, o.cache_dir, &lib, &err))
        rc = TL_ERR_USAGE;
    if (rc) {
        tl_cli_print_error("bench", &err);
        return 2;
    }
    s.o = &o;
    s.lib = lib;
    memcpy(s.preset_lib, preset_lib, sizeof s.preset_lib);
    s.boat_of = -1;
    int loaded = 0;
    for (; loaded < o.timeline_count; loaded++)
        if (tl_cli_load_timeline("bench", o.timelines[loaded], &s.tl[loaded], &s.boat[loaded]))
            break;
    int status = loaded < o.timeline_count ? 1 : 0;
    if (!status && make_shots(&s, &err)) {
        tl_cli_print_error("bench", &err);
        status = err.status == TL_ERR_USAGE ? 2 : 1;
    }

    tl_bench_row rows[1 + TL_BENCH_MAX_PRESETS];
    int row_count = 0;
    if (!status && run(&s, rows, &row_count, presets, names, preset_count, &err)) {
        tl_cli_print_error("bench", &err);
        status = 1;
    }
    if (!status) {
        tl_bench_mark_front(rows, row_count);
        tl_bench_print_table(stdout, rows, row_count);
        if (o.passes)
            tl_bench_print_passes(stdout, rows, row_count);
        if (o.csv && tl_bench_write_csv(o.csv, rows, row_count, o.width, o.height, s.shot_count,
                                        o.repeat, &err)) {
            tl_cli_print_error("bench", &err);
            status = 1;
        }
        if (o.plot && tl_bench_write_plot(o.plot, rows, row_count, o.width, o.height, &err)) {
            tl_cli_print_error("bench", &err);
            status = 1;
        }
    }
    if (s.render)
        tl_render_close(s.render);
    for (int k = 0; k < s.shot_count; k++)
        free(s.shots[k].reference);
    free(s.shots);
    for (int t = 0; t < loaded; t++) {
        tl_timeline_free(&s.tl[t]);
        tl_mesh_free(&s.boat[t]);
    }
    return status;
}
