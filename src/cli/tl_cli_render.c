/* tideline render: a timeline to frame files and/or a movie, headless.
 *
 * Built for long unattended runs and render farms: frames are selected by
 * number only (never by the clock), every file is written atomically,
 * --skip-existing resumes, SIGINT/SIGTERM stop cleanly after discarding the
 * frame in flight, and the exit status is 0 only when every requested frame
 * exists. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "core/tl_clock.h"
#include "image/tl_atomic.h"
#include "image/tl_image_io.h"
#include "job/tl_job.h"
#include "job/tl_writer.h"
#include "movie/tl_movie.h"
#include "movie/tl_movie_frames.h"
#include "prepare/tl_prepare.h"
#include "render/tl_render.h"
#include "run/tl_run.h"
#include "shader/tl_shader_lib.h"
#include "timeline/tl_parse.h"

#define EXIT_INTERRUPTED 130

static const char usage[] =
    "Usage: tideline render TIMELINE.tl -o PATTERN [options]\n"
    "       tideline render TIMELINE.tl --movie FILE.mp4 [options]\n"
    "\n"
    "Render a timeline's frames headless. In PATTERN the last run of '#' in the\n"
    "file name becomes the zero-padded frame number (shot_####.exr ->\n"
    "shot_0042.exr); the extension picks the format (.exr: linear half RGBA +\n"
    "float Z + metadata, or with --passes layers named as Blender names them;\n"
    ".png: tonemapped sRGB, or an OpenColorIO view). Folders are created.\n"
    "A frame's time is frame / fps; the same frame is identical on every run.\n"
    "\n"
    "Options:\n"
    "  -o, --output PATTERN   frame files (needs '#' when rendering several frames);\n"
    "                         up to 4, each frame written to every one (-o f_####.png\n"
    "                         -o f_####.exr)\n"
    "  --frames SPEC          frames to render: 0-239, 5, 1-3,5,7-20:2 (default: all)\n"
    "  --chunk I/N            render only chunk I (0-based) of N even chunks of the\n"
    "                         selected frames (render farms: --chunk $TASK/$COUNT)\n"
    "  --size WxH             override the timeline's size (1..16384 each)\n"
    "  --quality PRESET       draft, preview, final, reference, seed\n"
    "  --spp N                stratified samples per pixel (1..1024)\n"
    "  --shutter DEG          motion blur: shutter angle in degrees (180 = half the\n"
    "                         frame interval; never blurs across a camera cut)\n"
    "  --shutter-samples N    sub-frames averaged for motion blur (default 8)\n"
    "  --movie FILE           also encode a movie with ffmpeg: .mp4 (H.264, yuv420p)\n"
    "                         or .mov (ProRes 422 HQ), at the timeline's fps, with the\n"
    "                         timeline's `audio` (AAC in .mp4, PCM in .mov) cut to the\n"
    "                         frames; with --skip-existing made from the PNG frames on\n"
    "                         disk once all exist (with --chunk: see tideline movie)\n"
    "  --png-bits 8|16        PNG bit depth (default 8)\n"
    "  --png-compression N    zlib level 1 (fast, the default) .. 9 (smallest files)\n"
    "  --dither on|off        8-bit PNGs and movies: dither to the code below or above\n"
    "                         so smooth skies do not band (default on; off rounds, for\n"
    "                         smaller files and a faster encode)\n"
    "  --exr-compression N    zlib level of EXR's ZIP chunks, 1 (fast) .. 9 (default 4)\n"
    "  --passes LIST          EXR frames: compositing passes as layers named as Blender\n"
    "                         names them (combined, depth, normal, position, mask_water,\n"
    "                         mask_foam, mask_giant, mask_boat, mask_sky, mask_underwater,\n"
    "                         cryptomatte, vector, light_sky, light_reflection,\n"
    "                         light_body, light_glitter, light_foam, light_spray,\n"
    "                         light_boat, light_glare, cryptomatte_material; masks,\n"
    "                         lights, all; none); each light layer but the glare\n"
    "                         draws the frame again; overrides the timeline's\n"
    "                         `passes` line (docs/compositing.md)\n" TL_CLI_COLOR_USAGE
    "  --writers N            frames encoded and written side by side, 1..8 (default:\n"
    "                         half the processors, at most 8)\n"
    "  --skip-existing        keep frames whose file is already complete (resume)\n"
    "  --shader-dir DIR       load shaders from DIR instead of the built-in copies\n"
    "  -q, --quiet            no progress display\n"
    "  -v, --verbose          log the GL platform and renderer, and each frame's shader\n"
    "                         features when they change (ocean, sun disc, giant wave)\n"
    "  -h, --help             show this help\n"
    "\n"
    "Exit status: 0 every requested frame exists, 1 failure, 2 usage error,\n"
    "130 interrupted (SIGINT/SIGTERM; completed frames are kept, none is partial;\n"
    "    a --movie is discarded, never left short).\n";

/* The most -o patterns a run writes (a PNG and an EXR of each frame, ...). */
#define MAX_PATTERNS 4

/* Whether two paths name one file: the same name in the same folder (the
 * folders exist by now: tl_cli_make_parent_dirs). */
static int same_file(const char *a, const char *b)
{
    char dir[2][4096], real[2][PATH_MAX];
    const char *base[2];
    const char *path[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        const char *slash = strrchr(path[k], '/');
        snprintf(dir[k], sizeof dir[k], "%.*s", slash ? (int)(slash - path[k]) : 1,
                 slash ? path[k] : ".");
        if (slash == path[k])
            snprintf(dir[k], sizeof dir[k], "/");
        base[k] = slash ? slash + 1 : path[k];
        if (!realpath(dir[k], real[k]))
            return strcmp(a, b) == 0;
    }
    return strcmp(real[0], real[1]) == 0 && strcmp(base[0], base[1]) == 0;
}

typedef struct render_options {
    const char *timeline;
    const char *pattern;                /* the first -o */
    const char *more[MAX_PATTERNS - 1]; /* the other -o's */
    int more_count;
    const char *frames;
    const char *chunk;
    const char *movie;
    const char *shader_dir;
    int width, height;
    tl_quality quality;
    int has_quality;
    int spp;
    double shutter;
    int shutter_samples;
    int png_bits;
    int png_compression; /* 0: the writer's default (fast) */
    int dither;          /* 8-bit PNG and movie frames dithered (default) */
    int exr_compression; /* 0: the writer's default (zlib level 4) */
    unsigned passes;     /* --passes (TL_PASSES_*), when has_passes */
    tl_cli_color color;  /* --working-space, --ocio, --display, --view */
    int has_passes;
    int writers; /* 0: tl_writer_default_count() */
    int skip_existing;
    int quiet, verbose;
} render_options;

static volatile sig_atomic_t stop_signal = 0;

static void on_signal(int sig)
{
    stop_signal = sig;
}

static int parse(int argc, char **argv, render_options *o, int *help, tl_error *err)
{
    tl_args a;
    tl_args_init(&a, argc, argv);
    a.index = 1;
    while (!tl_args_done(&a)) {
        int rc = TL_OK;
        const char *pos;
        int color = tl_cli_color_flag(&a, &o->color, err);
        if (color < 0)
            return err->status ? (int)err->status : TL_ERR_USAGE;
        if (color > 0)
            continue;
        if (tl_args_match(&a, "--help", "-h", false, err)) {
            *help = 1;
            return TL_OK;
        } else if (tl_args_match(&a, "--quiet", "-q", false, err)) {
            o->quiet = 1;
        } else if (tl_args_match(&a, "--verbose", "-v", false, err)) {
            o->verbose = 1;
        } else if (tl_args_match(&a, "--skip-existing", NULL, false, err)) {
            o->skip_existing = 1;
        } else if (tl_args_match(&a, "--output", "-o", true, err)) {
            if (a.value && !o->pattern)
                o->pattern = a.value;
            else if (a.value && o->more_count < MAX_PATTERNS - 1)
                o->more[o->more_count++] = a.value;
            else if (a.value)
                return tl_error_set(err, TL_ERR_USAGE, "-o: at most %d patterns", MAX_PATTERNS);
        } else if (tl_args_match(&a, "--frames", NULL, true, err)) {
            o->frames = a.value;
        } else if (tl_args_match(&a, "--chunk", NULL, true, err)) {
            o->chunk = a.value;
        } else if (tl_args_match(&a, "--movie", NULL, true, err)) {
            o->movie = a.value;
        } else if (tl_args_match(&a, "--shader-dir", NULL, true, err)) {
            o->shader_dir = a.value;
        } else if (tl_args_match(&a, "--size", NULL, true, err)) {
            rc = a.value ? tl_args_size(a.flag, a.value, &o->width, &o->height, err) : 0;
        } else if (tl_args_match(&a, "--quality", NULL, true, err)) {
            rc = a.value ? tl_quality_preset(a.value, &o->quality, err) : 0;
            if (rc)
                tl_error_prefix(err, "--quality");
            o->has_quality = 1;
        } else if (tl_args_match(&a, "--spp", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 1, TL_MAX_SPP, &o->spp, err) : 0;
        } else if (tl_args_match(&a, "--shutter", NULL, true, err)) {
            rc = a.value ? tl_args_double(a.flag, a.value, &o->shutter, err) : 0;
            if (!rc && a.value && !(o->shutter >= 0.0 && o->shutter <= 360.0))
                rc = tl_error_set(err, TL_ERR_USAGE, "--shutter: '%s' is outside 0..360 degrees",
                                  a.value);
        } else if (tl_args_match(&a, "--shutter-samples", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 1, 256, &o->shutter_samples, err) : 0;
        } else if (tl_args_match(&a, "--png-compression", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 1, 9, &o->png_compression, err) : 0;
        } else if (tl_args_match(&a, "--writers", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 1, TL_WRITER_MAX, &o->writers, err)
                         : 0;
        } else if (tl_args_match(&a, "--passes", NULL, true, err)) {
            rc = a.value ? tl_cli_passes(a.flag, a.value, &o->passes, err) : 0;
            o->has_passes = 1;
        } else if (tl_args_match(&a, "--exr-compression", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 1, 9, &o->exr_compression, err) : 0;
        } else if (tl_args_match(&a, "--dither", NULL, true, err)) {
            rc = a.value ? tl_args_on_off(a.flag, a.value, &o->dither, err) : 0;
        } else if (tl_args_match(&a, "--png-bits", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 8, 16, &o->png_bits, err) : 0;
            if (!rc && a.value && o->png_bits != 8 && o->png_bits != 16)
                rc = tl_error_set(err, TL_ERR_USAGE, "--png-bits: '%s' is not 8 or 16", a.value);
        } else if (!o->timeline && tl_args_positional(&a, &pos)) {
            o->timeline = pos;
        } else {
            return tl_args_unknown(&a, "render", err);
        }
        if (err->status)
            return err->status; /* a flag without its value */
        if (rc)
            return rc;
    }
    if (!o->timeline)
        return tl_error_set(err, TL_ERR_USAGE, "no timeline file given");
    if (!o->pattern && !o->movie)
        return tl_error_set(err, TL_ERR_USAGE,
                            "nothing to write: give -o PATTERN and/or --movie FILE");
    if (o->movie && o->chunk)
        return tl_error_set(err, TL_ERR_USAGE,
                            "--movie cannot be combined with --chunk: a chunk renders part of "
                            "the frames; once every chunk is done, make the movie with "
                            "'tideline movie PATTERN.png -o %s --timeline %s'",
                            o->movie, o->timeline ? o->timeline : "TIMELINE.tl");
    return TL_OK;
}

typedef struct progress {
    int tty, quiet;
    size_t total, done;
    double start;
    double ms; /* drawing time per frame drawn so far */
} progress;

static void progress_update(progress *p, long frame, const char *what)
{
    if (p->quiet)
        return;
    double ms = p->ms;
    double remaining = ms * 1e-3 * (double)(p->total - p->done);
    char eta[32];
    tl_cli_format_duration(remaining, eta, sizeof eta);
    if (p->tty) {
        int width = 30, filled = (int)(width * (double)p->done / (double)p->total);
        char bar[64];
        for (int i = 0; i < width; i++)
            bar[i] = i < filled ? '#' : '-';
        bar[width] = '\0';
        fprintf(stderr, "\r[%s] %zu/%zu  frame %ld  %.0f ms/frame  ETA %s   ", bar, p->done,
                p->total, frame, ms, eta);
    } else {
        fprintf(stderr, "tideline render: frame %ld %s (%zu/%zu, %.0f ms/frame, ETA %s)\n", frame,
                what, p->done, p->total, ms, eta);
    }
    fflush(stderr);
}

/* A line of its own among the progress output (-v notes). On a terminal it
 * clears the bar first; the next update redraws it. */
static void progress_note(const progress *p, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static void progress_note(const progress *p, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs(p->tty ? "\r\033[K" : "", stderr);
    fputs("tideline render: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

/* The run's progress on stderr: a bar on a terminal, a line a frame
 * elsewhere; -v adds the writers and each new feature set. */
typedef struct run_lines {
    progress *prog;
    int verbose;
} run_lines;

static void run_report(void *ctx, const tl_run_status *st)
{
    run_lines *l = ctx;
    progress *p = l->prog;
    p->done = st->done;
    p->ms = st->ms_per_frame;
    switch (st->event) {
    case TL_RUN_STARTED:
        if (l->verbose)
            fprintf(stderr, "tideline render: %d writer thread%s\n", st->writers,
                    st->writers == 1 ? "" : "s");
        break;
    case TL_RUN_FEATURES:
        if (l->verbose) {
            char words[256];
            tl_feature_describe(st->features, words, sizeof words);
            progress_note(p, "frame %ld: features: %s", st->frame, words);
        }
        break;
    case TL_RUN_WRITTEN: progress_update(p, st->frame, st->path[0] ? st->path : "encoded"); break;
    case TL_RUN_SKIPPED: progress_update(p, st->frame, "skipped (complete)"); break;
    }
}

int tl_cli_render(int argc, char **argv)
{
    tl_error err;
    tl_error_clear(&err);
    render_options o = {0};
    o.png_bits = 8;
    o.dither = 1;
    int help = 0;
    int rc = parse(argc, argv, &o, &help, &err);
    if (help) {
        fputs(usage, stdout);
        return 0;
    }
    if (rc) {
        tl_cli_print_error("render", &err);
        return 2;
    }
    tl_timeline tl;
    tl_models models;
    if (tl_cli_load_timeline("render", o.timeline, &tl, &models))
        return 1;

    tl_render_settings settings = {.width = o.width,
                                   .height = o.height,
                                   .quality = o.has_quality ? &o.quality : NULL,
                                   .spp = o.spp,
                                   .shutter_deg = o.shutter,
                                   .shutter_samples = o.shutter_samples};
    tl_scene first_scene;
    tl_render_frame_scene(&tl, 0.0, &settings, &first_scene);
    int width = first_scene.width, height = first_scene.height;

    /* Everything that can be checked is checked before the first frame. */
    tl_frame_list frames = {0};
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    rc = tl_frame_list_parse(o.frames, tl_timeline_frame_count(&tl), "--frames", &frames, &err);
    if (!rc && o.chunk)
        rc = tl_frame_list_chunk(&frames, o.chunk, "--chunk", &err);
    /* Every -o: a frame number where several frames are written, a known
     * format, a writable place; no two name the same files. */
    const char *patterns[MAX_PATTERNS] = {o.pattern};
    int pattern_count = o.pattern ? 1 : 0;
    for (int k = 0; k < o.more_count; k++)
        patterns[pattern_count++] = o.more[k];
    char path[4096] = "";
    int any_exr = 0, any_png = 0;
    for (int k = 0; !rc && k < pattern_count; k++) {
        const char *pat = patterns[k];
        if (frames.count > 1 && !tl_pattern_has_frame(pat))
            rc = tl_error_set(&err, TL_ERR_USAGE,
                              "-o %s has no '#' for the frame number, and this run writes %zu "
                              "frames (e.g. -o shot_####.exr)",
                              pat, frames.count);
        char p[4096] = "";
        if (!rc && frames.count > 0) {
            rc = tl_pattern_format(pat, frames.frames[0], frames.count == 1, p, sizeof p, &err);
            if (!rc && tl_image_format_from_path(p) == TL_IMAGE_UNKNOWN)
                rc = tl_error_set(&err, TL_ERR_USAGE,
                                  "-o %s: unknown image format (use .exr or .png)", pat);
            if (!rc)
                rc = tl_cli_make_parent_dirs(p, &err);
            if (!rc && tl_image_check_writable(p, &err))
                rc = TL_ERR_USAGE;
            any_exr |= tl_image_format_from_path(p) == TL_IMAGE_EXR;
            any_png |= tl_image_format_from_path(p) == TL_IMAGE_PNG;
            /* The same files by another name: f.png and ./f.png, or
             * f_##.png and f_###.png from frame 100 on. */
            for (int j = 0; !rc && j < k; j++) {
                const long ends[2] = {frames.frames[0], frames.frames[frames.count - 1]};
                for (int e = 0; !rc && e < 2; e++) {
                    char mine[4096], theirs[4096];
                    tl_error ignored;
                    if (!tl_pattern_format(pat, ends[e], frames.count == 1, mine, sizeof mine,
                                           &ignored) &&
                        !tl_pattern_format(patterns[j], ends[e], frames.count == 1, theirs,
                                           sizeof theirs, &ignored) &&
                        same_file(mine, theirs))
                        rc = tl_error_set(&err, TL_ERR_USAGE,
                                          "-o %s and -o %s name the same file %s", patterns[j], pat,
                                          mine);
                }
            }
        }
        if (k == 0)
            memcpy(path, p, sizeof path);
    }
    const unsigned passes = o.has_passes ? o.passes : tl.passes;
    if (!rc && o.has_passes && passes && !any_exr)
        rc = tl_error_set(&err, TL_ERR_USAGE,
                          "--passes: the passes are layers of EXR frames; give -o PATTERN.exr");
    /* --movie with --skip-existing: the movie is made from the PNG frames
     * on disk once they all exist, so a resumed run ends with it too. */
    const char *movie_frames = NULL;
    for (int k = 0; k < pattern_count && !movie_frames; k++) {
        char p[4096];
        tl_error ignored;
        if (frames.count > 0 &&
            !tl_pattern_format(patterns[k], frames.frames[0], frames.count == 1, p, sizeof p,
                               &ignored) &&
            tl_image_format_from_path(p) == TL_IMAGE_PNG)
            movie_frames = patterns[k];
    }
    if (!rc && o.movie && o.skip_existing && !movie_frames)
        rc = tl_error_set(&err, TL_ERR_USAGE,
                          "--movie with --skip-existing makes the movie from the PNG frames on "
                          "disk: give -o PATTERN.png too");
    if (!rc && o.movie) {
        rc = tl_cli_make_parent_dirs(o.movie, &err);
        if (!rc && tl_movie_check(o.movie, width, height, &err))
            rc = TL_ERR_USAGE;
    }
    if (!rc && o.shader_dir && (rc = tl_shader_lib_from_dir(&lib, o.shader_dir, &err)))
        tl_error_prefix(&err, "--shader-dir");
    if (!rc)
        rc = tl_cli_color_prepare(&o.color, tl.working_space, o.movie || any_png, &err);
    if (rc) {
        tl_cli_color_free(&o.color);
        tl_cli_print_error("render", &err);
        tl_frame_list_free(&frames);
        tl_timeline_free(&tl);
        tl_models_free(&models);
        return rc == TL_ERR_RUNTIME ? 1 : 2;
    }

    for (int k = 0; k < pattern_count && frames.count > 0; k++) {
        /* A process killed mid-write (SIGKILL, a node lost) leaves its
         * hidden temporary behind; a resumed run ends with the files alone. */
        char p[4096];
        tl_error ignored;
        if (tl_pattern_format(patterns[k], frames.frames[0], frames.count == 1, p, sizeof p,
                              &ignored))
            continue;
        int removed = tl_job_remove_stale_temporaries(patterns[k], &frames, p);
        if (removed && !o.quiet)
            fprintf(stderr,
                    "tideline render: removed %d temporary file%s left by an interrupted run\n",
                    removed, removed == 1 ? "" : "s");
    }

    tl_render *render = NULL;
    tl_movie *movie = NULL;
    rc = tl_render_open(&render, &lib, &err);
    if (!rc && models.count)
        rc = tl_render_set_models(render, &models, &err);
    if (!rc)
        rc = tl_cli_color_use(&o.color, render, &err);
    if (!rc && o.verbose)
        fprintf(stderr, "tideline render: %s\ntideline render: display: %s\n",
                tl_render_describe(render), tl_cli_color_describe(&o.color));
    tl_movie_sound sound = {0}, *soundtrack = NULL;
    if (tl.audio[0] && frames.count > 0) {
        sound = (tl_movie_sound){.path = tl.audio,
                                 .start = tl_timeline_frame_time(&tl, frames.frames[0]) -
                                          tl.audio_offset,
                                 .duration = (double)frames.count / tl.fps,
                                 .sample_rate = tl.audio_rate};
        soundtrack = &sound;
    }
    if (!rc && o.movie && !o.skip_existing)
        rc = tl_movie_open(&movie, o.movie, width, height, tl.fps, soundtrack, &err);

    stop_signal = 0;
    tl_cli_signals signals;
    tl_cli_catch_stop(on_signal, &signals);

    progress prog = {isatty(STDERR_FILENO), o.quiet, frames.count, 0, tl_clock_seconds(), 0.0};
    run_lines lines = {&prog, o.verbose};
    tl_run_config run = {.timeline = &tl,
                         .timeline_path = o.timeline,
                         .settings = settings,
                         .frames = &frames,
                         .pattern = o.pattern,
                         .more_patterns = o.more,
                         .more_count = o.more_count,
                         .movie = movie,
                         .image = {.png_bits = o.png_bits,
                                   .no_dither = !o.dither,
                                   .png_compression = o.png_compression,
                                   .exr_compression = o.exr_compression},
                         .passes = passes,
                         .space = o.color.space,
                         .working = o.color.convert ? o.color.matrix : NULL,
                         .skip_existing = o.skip_existing,
                         .writers = o.writers,
                         .stop = &stop_signal,
                         .report = run_report,
                         .report_ctx = &lines};
    tl_run_result result = {0};
    if (!rc)
        rc = tl_run_frames(render, &run, &result, &err);
    size_t written = result.written, skipped = result.skipped;
    if (prog.tty && !o.quiet && prog.done)
        fputc('\n', stderr);

    int interrupted = result.interrupted;
    if (movie) {
        if (!rc && !interrupted)
            rc = tl_movie_finish(movie, &err);
        else
            tl_movie_abort(movie); /* a movie missing frames is not kept */
        movie = NULL;
    }
    if (!rc && !interrupted && o.movie && o.skip_existing) {
        if (!o.quiet)
            fprintf(stderr, "tideline render: encoding %s from the %zu frames on disk\n", o.movie,
                    frames.count);
        tl_movie_frames job = {.pattern = movie_frames,
                               .frames = frames.frames,
                               .count = frames.count,
                               .movie = o.movie,
                               .fps = tl.fps,
                               .sound = soundtrack,
                               .dither = o.dither,
                               .stop = &stop_signal};
        rc = tl_movie_from_frames(&job, &err);
        interrupted = stop_signal != 0;
    }
    tl_cli_restore_stop(&signals);

    double total = tl_clock_seconds() - prog.start;
    char took[32];
    tl_cli_format_duration(total, took, sizeof took);
    if (rc)
        tl_cli_print_error("render", &err);
    fprintf(stderr, "tideline render: %s: %zu frame%s written, %zu skipped, %zu of %zu done in %s",
            interrupted ? "interrupted"
            : rc        ? "failed"
                        : "done",
            written, written == 1 ? "" : "s", skipped, written + skipped, frames.count, took);
    if (result.drawn)
        fprintf(stderr, " (%.0f ms/frame)", result.busy_seconds / (double)result.drawn * 1e3);
    fprintf(stderr, "\n");
    if (!rc && !interrupted && o.movie) {
        fprintf(stderr, "tideline render: wrote %s", o.movie);
        if (soundtrack)
            tl_cli_describe_sound(stderr, soundtrack);
        fputc('\n', stderr);
    } else if (o.movie)
        fprintf(stderr, "tideline render: %s not written: a movie missing frames is discarded%s\n",
                o.movie, access(o.movie, F_OK) == 0 ? " (the earlier file is untouched)" : "");

    tl_render_close(render);
    tl_cli_color_free(&o.color);
    tl_models_free(&models);
    tl_frame_list_free(&frames);
    tl_timeline_free(&tl);
    if (interrupted)
        return EXIT_INTERRUPTED;
    return rc ? 1 : 0;
}
