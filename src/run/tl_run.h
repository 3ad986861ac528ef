/* tl_run: a render run, as `tideline render` runs one: frames of a
 * timeline through the headless pipeline into frame files and a movie.
 *
 * Frame n draws while frame n-1's planes travel to the CPU
 * (tl_render_timeline_frame_queue) and writer threads (tl_writer) encode
 * the frames before it, each file atomically. A frame whose file is
 * already complete is skipped (skip_existing). When `*stop` becomes
 * non-zero (a signal handler sets it) the frame just drawn is discarded,
 * those before it are written, and the run ends interrupted. */
#ifndef TL_RUN_H
#define TL_RUN_H

#include <signal.h>
#include <stddef.h>

#include "color/tl_color.h"
#include "core/tl_error.h"
#include "image/tl_image_io.h"
#include "job/tl_job.h"
#include "movie/tl_movie.h"
#include "render/tl_render.h"
#include "scene/tl_quality.h"
#include "timeline/tl_timeline.h"

typedef enum tl_run_event {
    TL_RUN_STARTED,  /* `writers` threads will write */
    TL_RUN_FEATURES, /* `frame` drew with `features`, unlike the one before */
    TL_RUN_WRITTEN,  /* `frame` is written (`path`, or "" for a movie frame) */
    TL_RUN_SKIPPED,  /* `frame`'s file was complete already */
} tl_run_event;

typedef struct tl_run_status {
    tl_run_event event;
    long frame;
    const char *path;
    unsigned features; /* tl_feature bits */
    int writers;
    size_t done, total;  /* frames written or skipped, of the run's */
    double ms_per_frame; /* the time spent drawing, per frame drawn so far */
} tl_run_status;

typedef void (*tl_run_report_fn)(void *ctx, const tl_run_status *status);

/* Writer threads by default for frames with the passes' data (about 190
 * bytes a pixel each in flight: a 4K frame's are 1.5 GB). */
#define TL_RUN_PASSES_WRITERS 2

typedef struct tl_run_config {
    const tl_timeline *timeline;
    const char *timeline_path;   /* recorded in every frame's metadata */
    tl_render_settings settings; /* `planes` is the run's: what the outputs use */
    const tl_frame_list *frames;
    const char *pattern; /* frame files ('#'s: the frame number), or NULL */
    /* More frame files: each frame is written to every pattern (a PNG and
     * an EXR, say); a frame counts as there for --skip-existing when all
     * are. Reports name `pattern`'s file. */
    const char *const *more_patterns;
    int more_count;
    tl_movie *movie;        /* an open movie that takes every frame in order, or NULL */
    tl_image_options image; /* PNG bits, dither, compression (metadata: the run's) */
    unsigned passes;        /* EXR frames: the compositing passes (TL_PASSES_*; 0: none) */
    tl_working_space space; /* EXR frames: the colour's working space, */
    const double *working;  /* the matrix from linear Rec.709 to it (NULL: as rendered) */
    int skip_existing;
    int writers; /* 0: tl_writer_default_count(), at most TL_RUN_PASSES_WRITERS with passes */
    volatile sig_atomic_t *stop;
    tl_run_report_fn report; /* NULL: none */
    void *report_ctx;
} tl_run_config;

typedef struct tl_run_result {
    size_t written, skipped;
    long drawn;          /* frames drawn */
    double busy_seconds; /* spent drawing and handing frames over */
    int interrupted;     /* *stop ended the run */
} tl_run_result;

/* Renders cfg->frames with `render` (open, its cutscene uploaded).
 * Returns the first failure; the frames drawn before it are written
 * anyway. */
int tl_run_frames(tl_render *render, const tl_run_config *cfg, tl_run_result *out, tl_error *err);

/* The effective quality knobs (the preset's name and every value) as
 * image metadata entries, so that a frame records how it was made.
 * Returns the count, TL_RUN_QUALITY_META. */
#define TL_RUN_QUALITY_META 25
int tl_run_quality_meta(const tl_quality *q, tl_meta *out);

#endif
