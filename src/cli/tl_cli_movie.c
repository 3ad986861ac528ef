/* tideline movie: a movie from frames rendered earlier, by one run or by a
 * farm's chunks, with the timeline's soundtrack when the timeline is given
 * (tl_movie_frames does the work; `render --movie --skip-existing` too). */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "job/tl_job.h"
#include "movie/tl_movie_frames.h"
#include "timeline/tl_timeline.h"

static const char usage[] =
    "Usage: tideline movie PATTERN.png -o FILE.mp4 [options]\n"
    "\n"
    "Make a movie from PNG frames on disk (e.g. written by render --chunk on a\n"
    "farm). In PATTERN the last run of '#' is the frame number, as render names\n"
    "its frames. Every frame must exist before encoding starts; a frame missing\n"
    "is named and no movie is written. The movie equals the one `render --movie`\n"
    "makes of the same frames (8-bit frames go in as they are).\n"
    "\n"
    "Options:\n"
    "  -o, --output FILE      the movie: .mp4 (H.264, yuv420p) or .mov (ProRes 422 HQ)\n"
    "  --timeline FILE.tl     take the frame range, fps and `audio` soundtrack from\n"
    "                         the timeline (AAC in .mp4, PCM in .mov, aligned to the\n"
    "                         frames and cut to them)\n"
    "  --frames SPEC          frames to use: 0-239, 1-3,5 (default: the timeline's\n"
    "                         frames, else every frame from the lowest number found\n"
    "                         to the highest)\n"
    "  --fps N                frame rate (default: the timeline's, else 24)\n"
    "  --dither on|off        16-bit frames to 8 bits: dithered (default) or rounded\n"
    "  -q, --quiet            no progress lines\n"
    "  -h, --help             show this help\n"
    "\n"
    "Exit status: 0 written, 1 failure (a frame missing or unreadable, ffmpeg\n"
    "failed; no movie is left, an earlier one untouched), 2 usage error,\n"
    "130 interrupted.\n";

static volatile sig_atomic_t stop_signal = 0;

static void on_signal(int sig)
{
    stop_signal = sig;
}

typedef struct movie_options {
    const char *pattern, *movie, *timeline, *frames;
    double fps;
    int dither, quiet;
} movie_options;

static int parse(int argc, char **argv, movie_options *o, int *help, tl_error *err)
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
        } else if (tl_args_match(&a, "--output", "-o", true, err)) {
            o->movie = a.value;
        } else if (tl_args_match(&a, "--timeline", NULL, true, err)) {
            o->timeline = a.value;
        } else if (tl_args_match(&a, "--frames", NULL, true, err)) {
            o->frames = a.value;
        } else if (tl_args_match(&a, "--fps", NULL, true, err)) {
            rc = a.value ? tl_args_double(a.flag, a.value, &o->fps, err) : 0;
            if (!rc && a.value && !(o->fps >= 1.0 && o->fps <= 1000.0))
                rc = tl_error_set(err, TL_ERR_USAGE, "--fps: '%s' is outside 1..1000", a.value);
        } else if (tl_args_match(&a, "--dither", NULL, true, err)) {
            rc = a.value ? tl_args_on_off(a.flag, a.value, &o->dither, err) : 0;
        } else if (!o->pattern && tl_args_positional(&a, &pos)) {
            o->pattern = pos;
        } else {
            return tl_args_unknown(&a, "movie", err);
        }
        if (err->status)
            return err->status;
        if (rc)
            return rc;
    }
    if (!o->pattern)
        return tl_error_set(err, TL_ERR_USAGE, "no frame pattern given (e.g. out/shot_####.png)");
    if (!o->movie)
        return tl_error_set(err, TL_ERR_USAGE, "no movie given: -o FILE.mp4 or -o FILE.mov");
    if (!tl_pattern_has_frame(o->pattern))
        return tl_error_set(err, TL_ERR_USAGE,
                            "'%s' has no '#' for the frame number (e.g. out/shot_####.png)",
                            o->pattern);
    return TL_OK;
}

typedef struct progress {
    int tty, quiet;
    size_t shown; /* the last tenth reported off a terminal */
} progress;

static void show_progress(void *ctx, size_t done, size_t total)
{
    progress *p = ctx;
    if (p->quiet)
        return;
    if (p->tty) {
        fprintf(stderr, "\rtideline movie: frame %zu/%zu", done, total);
        if (done == total)
            fputc('\n', stderr);
    } else if (done * 10 / total > p->shown || done == total) {
        p->shown = done * 10 / total;
        fprintf(stderr, "tideline movie: %zu/%zu frames encoded\n", done, total);
    }
    fflush(stderr);
}

int tl_cli_movie(int argc, char **argv)
{
    tl_error err;
    tl_error_clear(&err);
    movie_options o = {.dither = 1};
    int help = 0;
    if (parse(argc, argv, &o, &help, &err)) {
        tl_cli_print_error("movie", &err);
        return 2;
    }
    if (help) {
        fputs(usage, stdout);
        return 0;
    }
    tl_timeline tl;
    int have_timeline = 0;
    if (o.timeline) {
        if (tl_cli_load_timeline("movie", o.timeline, &tl, NULL))
            return 1;
        have_timeline = 1;
    }
    double fps = o.fps > 0.0 ? o.fps : have_timeline ? tl.fps : 24.0;

    /* The frames: the timeline's, or those on disk. */
    long frame_count = have_timeline ? tl_timeline_frame_count(&tl) : 0, first = 0, last = -1;
    int rc = TL_OK;
    if (!have_timeline) {
        rc = tl_pattern_scan(o.pattern, &first, &last, &err);
        frame_count = last + 1;
    }
    tl_frame_list frames = {0};
    if (!rc) {
        char range[64];
        const char *spec = o.frames;
        if (!spec && !have_timeline) {
            snprintf(range, sizeof range, "%ld-%ld", first, last);
            spec = range;
        }
        rc = tl_frame_list_parse(spec, frame_count, "--frames", &frames, &err);
    }
    if (!rc)
        rc = tl_cli_make_parent_dirs(o.movie, &err);

    tl_movie_sound sound = {0};
    if (!rc && have_timeline && tl.audio[0] && frames.count > 0)
        sound = (tl_movie_sound){.path = tl.audio,
                                 .start = (double)frames.frames[0] / fps - tl.audio_offset,
                                 .duration = (double)frames.count / fps,
                                 .sample_rate = tl.audio_rate};

    tl_cli_signals signals;
    tl_cli_catch_stop(on_signal, &signals);
    progress prog = {isatty(STDERR_FILENO), o.quiet, 0};
    tl_movie_frames job = {.pattern = o.pattern,
                           .frames = frames.frames,
                           .count = frames.count,
                           .movie = o.movie,
                           .fps = fps,
                           .sound = sound.path ? &sound : NULL,
                           .dither = o.dither,
                           .progress = show_progress,
                           .progress_ctx = &prog,
                           .stop = &stop_signal};
    if (!rc)
        rc = tl_movie_from_frames(&job, &err);
    tl_cli_restore_stop(&signals);

    int status = 0;
    if (stop_signal) {
        fprintf(stderr, "tideline movie: interrupted; %s not written\n", o.movie);
        status = 130;
    } else if (rc) {
        tl_cli_print_error("movie", &err);
        status = rc == TL_ERR_USAGE ? 2 : 1;
    } else {
        fprintf(stderr, "tideline movie: wrote %s: %zu frames at %g fps, %.3f s", o.movie,
                frames.count, fps, (double)frames.count / fps);
        if (sound.path)
            tl_cli_describe_sound(stderr, &sound);
        fputc('\n', stderr);
    }
    tl_frame_list_free(&frames);
    if (have_timeline)
        tl_timeline_free(&tl);
    return status;
}
