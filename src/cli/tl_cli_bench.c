/* tideline bench: the speed-accuracy trade, measured (src/bench/). This
 * file reads the flags, loads the timelines, prints progress on stderr
 * and the table on stdout, and writes the CSV and the plot on request. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "bench/tl_bench.h"
#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "core/tl_clock.h"
#include "cutscene/tl_cutscene.h"
#include "image/tl_image_io.h"
#include "shader/tl_shader_lib.h"

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
    "                    it changes: preview,preview@my-shaders); PRESET+passes\n"
    "                    draws the compositing passes' data too and reads it back\n"
    "                    (what render --passes adds before the file: final,final+passes);\n"
    "                    PRESET+lights draws every light layer too (final,final+lights)\n"
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

/* Progress lines on stderr, at most two a second: a line with a time
 * left is always printed (the `reference` frames, each a long render), and
 * so is each shot's first line. */
typedef struct bench_lines {
    int quiet, tty;
    int width, height;
    double last;
} bench_lines;

static void show_progress(void *ctx, const tl_bench_progress *p)
{
    bench_lines *l = ctx;
    if (p->stage == TL_BENCH_WARNING) {
        fprintf(stderr, "bench: warning: --reference-cache: %s\n", p->warning);
        return;
    }
    if (l->quiet)
        return;
    if (p->stage == TL_BENCH_STARTED) {
        fprintf(stderr, "bench: %d frames at %dx%d on %s\n", p->shots, l->width, l->height,
                p->renderer);
        return;
    }
    double now = tl_clock_seconds();
    if (now - l->last < 0.5 * tl_cli_progress_delay() &&
        (p->share >= 0.0 || (p->shot > 0 && p->seconds_left < 0.0)))
        return;
    l->last = now;
    char eta[48] = "", of[32] = "", drawn[16] = "";
    if (p->seconds_left >= 0.0) {
        char took[32];
        tl_cli_format_duration(p->seconds_left, took, sizeof took);
        snprintf(eta, sizeof eta, " ETA %s", took);
    }
    if (p->rounds > 1)
        snprintf(of, sizeof of, " round %d/%d", p->round + 1, p->rounds);
    if (p->share >= 0.0)
        snprintf(drawn, sizeof drawn, " %3.0f%%", p->share * 100.0);
    fprintf(stderr, "bench: %-9s %s frame %ld (%d/%d)%s%s%s%s", p->preset, p->timeline, p->frame,
            p->shot + 1, p->shots, of, drawn, eta, l->tty ? "        \r" : "\n");
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
    static tl_bench_preset presets[TL_BENCH_MAX_PRESETS];
    int preset_count = 0;
    if (!rc && tl_bench_parse_presets(o.presets, presets, &preset_count, &err)) {
        tl_error_prefix(&err, "--presets");
        rc = TL_ERR_USAGE;
    }
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    if (!rc && o.shader_dir && tl_shader_lib_from_dir(&lib, o.shader_dir, &err)) {
        tl_error_prefix(&err, "--shader-dir");
        rc = TL_ERR_USAGE;
    }
    for (int p = 0; !rc && p < preset_count; p++) {
        presets[p].lib = lib;
        if (presets[p].dir && tl_shader_lib_from_dir(&presets[p].lib, presets[p].dir, &err)) {
            tl_error_prefix(&err, "--presets: %s", presets[p].name);
            rc = TL_ERR_USAGE;
        }
    }
    if (!rc && o.csv && tl_cli_make_parent_dirs(o.csv, &err))
        rc = TL_ERR_USAGE;
    if (!rc && o.plot &&
        (tl_cli_make_parent_dirs(o.plot, &err) || tl_image_check_writable(o.plot, &err)))
        rc = TL_ERR_USAGE;
    tl_bench_cache cache = {0};
    if (!rc && o.cache_dir && tl_bench_cache_open(&cache, o.cache_dir, &lib, &err))
        rc = TL_ERR_USAGE;
    if (rc) {
        tl_cli_print_error("bench", &err);
        return 2;
    }

    static tl_cutscene cutscenes[MAX_TIMELINES];
    tl_bench_timeline timelines[MAX_TIMELINES];
    int loaded = 0;
    for (; loaded < o.timeline_count; loaded++) {
        if (tl_cli_load_cutscene("bench", o.timelines[loaded], &cutscenes[loaded]))
            break;
        timelines[loaded] = (tl_bench_timeline){o.timelines[loaded], &cutscenes[loaded]};
    }
    int status = loaded < o.timeline_count ? 1 : 0;

    bench_lines lines = {
        .quiet = o.quiet, .tty = isatty(STDERR_FILENO), .width = o.width, .height = o.height};
    tl_bench_config cfg = {.width = o.width,
                           .height = o.height,
                           .rounds = o.repeat,
                           .time_only = o.time_only,
                           .passes = o.passes,
                           .frames = o.frames,
                           .reference_lib = &lib,
                           .cache = o.cache_dir ? &cache : NULL,
                           .progress = show_progress,
                           .progress_ctx = &lines,
                           .reference_shares = !o.quiet && lines.tty};
    tl_bench_row rows[1 + TL_BENCH_MAX_PRESETS];
    int row_count = 0, shots = 0;
    if (!status && tl_bench_run(&cfg, timelines, loaded, presets, preset_count, rows, &row_count,
                                &shots, &err)) {
        if (!o.quiet && lines.tty)
            fprintf(stderr, "%60s\r", "");
        tl_cli_print_error("bench", &err);
        status = err.status == TL_ERR_USAGE ? 2 : 1;
    }
    if (!status) {
        if (!o.quiet && lines.tty)
            fprintf(stderr, "%60s\r", "");
        if (!o.quiet && !o.time_only && rows[0].cached)
            fprintf(stderr, "bench: %d of %d reference frames from %s\n", rows[0].cached, shots,
                    cache.dir);
        tl_bench_mark_front(rows, row_count);
        tl_bench_print_table(stdout, rows, row_count);
        if (o.passes)
            tl_bench_print_passes(stdout, rows, row_count);
        if (o.csv &&
            tl_bench_write_csv(o.csv, rows, row_count, o.width, o.height, shots, o.repeat, &err)) {
            tl_cli_print_error("bench", &err);
            status = 1;
        }
        if (o.plot && tl_bench_write_plot(o.plot, rows, row_count, o.width, o.height, &err)) {
            tl_cli_print_error("bench", &err);
            status = 1;
        }
    }
    for (int t = 0; t < loaded; t++)
        tl_cutscene_free(&cutscenes[t]);
    return status;
}
