/* tl_bench: the speed-accuracy trade, measured (what `tideline bench`
 * runs). Renders chosen frames of one or more cutscenes with each preset
 * and with `reference`, in rounds, and gives per preset the median time
 * per frame (render, readback, PNG encoding) and the error against
 * `reference` (PSNR, SSIM, 99th-percentile pixel error, the worst frame).
 * tl_bench.c measures, tl_bench_presets.c reads preset lists,
 * tl_bench_report.c reports (table, CSV, plot) and tl_bench_cache.c keeps
 * `reference` frames between runs. The command parses flags and prints. */
#ifndef TL_BENCH_H
#define TL_BENCH_H

#include <stdint.h>
#include <stdio.h>

#include "core/tl_error.h"
#include "cutscene/tl_cutscene.h"
#include "render/tl_render.h"
#include "scene/tl_quality.h"
#include "shader/tl_shader_lib.h"

#define TL_BENCH_MAX_PRESETS 32
#define TL_BENCH_NAME        96 /* a preset, or a variant "final:lod=off" */
#define TL_BENCH_PASSES      TL_RENDER_PASSES

typedef struct tl_bench_row {
    char preset[TL_BENCH_NAME];
    int is_reference; /* the yardstick row: its own error is zero */
    int cached;       /* reference frames read from --reference-cache (not timed) */
    /* Medians over every frame and repeat, milliseconds. The parts are
     * medians too, so they need not add up to the total exactly. */
    double ms_total, ms_render, ms_readback, ms_encode;
    double psnr, ssim;    /* means over the frames, against `reference` */
    double p99;           /* the worst frame's 99th-percentile error, 8-bit levels */
    double worst_psnr;    /* the lowest PSNR of any frame, */
    char worst_shot[160]; /* and that frame: "voyage.tl:120" */
    int on_front;         /* no other preset is both faster and closer */
    /* --passes: ms of each kind of pass (tl_render_pass_name), then
     * of all of them, in the median frame by all of them; that frame's
     * render time, and the frame */
    int has_passes;
    double ms_pass[TL_BENCH_PASSES + 1];
    double ms_pass_render;
    char pass_shot[160];
} tl_bench_row;

/* Marks the Pareto front among the non-reference rows: a row is on it when
 * no other row is at least as fast and as accurate (PSNR) and better in
 * one of the two. */
void tl_bench_mark_front(tl_bench_row *rows, int count);
/* A Markdown table (it pastes into docs as it is). */
void tl_bench_print_table(FILE *to, const tl_bench_row *rows, int count);
/* A Markdown table of where each preset's GPU time goes (rows measured
 * with --passes; the others are left out). */
void tl_bench_print_passes(FILE *to, const tl_bench_row *rows, int count);
/* One row per preset, with a header; written atomically. */
int tl_bench_write_csv(const char *path, const tl_bench_row *rows, int count, int width, int height,
                       int frames, int repeat, tl_error *err);
/* PSNR against ms per frame, one labelled point per preset, the front as a
 * line, through gnuplot; an error says so when gnuplot is missing. */
int tl_bench_write_plot(const char *path, const tl_bench_row *rows, int count, int width,
                        int height, tl_error *err);

/* A row to measure: a preset, or a variant of one, with its shaders. */
typedef struct tl_bench_preset {
    char name[TL_BENCH_NAME]; /* as listed: "final:lod=off", "preview@edited" */
    tl_quality quality;
    const char *dir; /* the folder after '@' (in the parsed list), or NULL */
    int aov;         /* PRESET+passes: drawn with the compositing passes' data, read back */
    int lights;      /* PRESET+lights: with every light layer (the frame drawn again for each) */
    tl_shader_lib lib;
} tl_bench_preset;

/* Splits a preset list (tl_bench_presets.c), in place: each item a
 * preset's name, optionally with knobs changed (`final:refine_steps=2:
 * lod=off`: quality.* channels) and with another folder's shaders
 * (`preview@DIR`), and drawn with the compositing passes' data
 * (`final+passes`: what `--passes` adds to a frame before its file is
 * written). `reference` may not be listed (it is what the others
 * are measured against). Each preset's lib is left to the caller.
 * Errors (TL_ERR_USAGE) quote the item. */
int tl_bench_parse_presets(char *list, tl_bench_preset *out, int *count, tl_error *err);

/* Where a run is, for a progress line. */
typedef enum tl_bench_stage {
    TL_BENCH_STARTED,   /* the renderer is open: `renderer`, `shots` */
    TL_BENCH_REFERENCE, /* a `reference` frame starts or draws (share) */
    TL_BENCH_MEASURING, /* a preset's frame starts, in round `round` */
    TL_BENCH_WARNING,   /* `warning`: the run goes on (a cache that cannot keep a frame) */
} tl_bench_stage;

typedef struct tl_bench_progress {
    tl_bench_stage stage;
    const char *renderer; /* tl_render_describe */
    const char *preset;   /* the row; "reference" */
    const char *timeline; /* the shot's timeline, its file name */
    long frame;
    int shot, shots;     /* shot is 0-based */
    int round, rounds;   /* rounds 0 for `reference` */
    double share;        /* of a reference frame drawn, or -1 */
    double seconds_left; /* the whole run's rest for `reference`, or -1 */
    const char *warning;
} tl_bench_progress;

typedef void (*tl_bench_progress_fn)(void *ctx, const tl_bench_progress *p);

/* One of the timelines a run measures. */
typedef struct tl_bench_timeline {
    const char *path;
    const tl_cutscene *cutscene;
} tl_bench_timeline;

struct tl_bench_cache;

typedef struct tl_bench_config {
    int width, height;
    int rounds;                         /* each round times every preset on every shot once */
    int time_only;                      /* no `reference`: no errors, times only */
    int passes;                         /* time each kind of pass too (fenced; slower) */
    const char *frames;                 /* the frames of every timeline (a tl_frame_list spec);
                                           NULL: its first, middle and last */
    const tl_shader_lib *reference_lib; /* the shaders `reference` draws with */
    const struct tl_bench_cache *cache; /* NULL: every `reference` frame drawn */
    tl_bench_progress_fn progress;      /* NULL: none */
    void *progress_ctx;
    int reference_shares; /* report a `reference` frame's share as it draws
                             (the renderer then waits for each draw) */
} tl_bench_config;

/* Measures: `reference` first (unless time_only; its row is rows[0]),
 * then every preset. rows holds 1 + count rows; *row_count gets how many
 * were filled, *shots how many frames each measured. A failed render
 * names the row and the timeline. */
int tl_bench_run(const tl_bench_config *cfg, const tl_bench_timeline *timelines, int timeline_count,
                 const tl_bench_preset *presets, int count, tl_bench_row *rows, int *row_count,
                 int *shots, tl_error *err);

/* The preset the j-th turn of round r takes, of `count`: each round starts
 * one preset further along, so that a host's slow spell falls on every
 * preset alike. */
int tl_bench_preset_turn(int round, int j, int count);
/* The median of v[0..n-1] (sorted in place). */
double tl_bench_median(double *v, int n);
/* The frame whose time summed over all passes is the median (the lower
 * of the middle two): pass[i][k] is frame k's time in pass i, and
 * pass[TL_BENCH_PASSES][k] its sum; out gets that frame's passes. Returns
 * the frame. */
int tl_bench_median_frame(double *const *pass, int n, double *out);

/* --reference-cache DIR (tl_bench_cache.c): `reference` frames kept
 * between runs, each under a hash of everything that draws it. */
typedef struct tl_bench_cache {
    char dir[4096];
    uint64_t base; /* this program and the --shader-dir shaders */
} tl_bench_cache;

/* Creates `dir` if needed (it must be a writable folder) and hashes what
 * every frame shares. */
int tl_bench_cache_open(tl_bench_cache *c, const char *dir, const tl_shader_lib *lib,
                        tl_error *err);
/* A frame's key: the shared part, the GL renderer's description, the
 * timeline's text and its boat model (model: a path, or NULL or "" for
 * the built-in boat), frame and size. */
uint64_t tl_bench_cache_key(const tl_bench_cache *c, const char *renderer, const char *timeline,
                            const char *model, long frame, int width, int height);
/* 1 and the display plane (RGBA floats) when the cache holds the frame, 0
 * when it does not (or holds a short or foreign file). */
int tl_bench_cache_load(const tl_bench_cache *c, uint64_t key, int width, int height,
                        float *pixels);
/* Keeps a frame, written atomically. */
int tl_bench_cache_store(const tl_bench_cache *c, uint64_t key, int width, int height,
                         const float *pixels, tl_error *err);

#endif
