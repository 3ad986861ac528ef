/* The bench's results and their reports (terminal table, CSV, plot);
 * tl_cli_bench.c measures, tl_cli_bench_report.c reports. */
#ifndef TL_CLI_BENCH_H
#define TL_CLI_BENCH_H

#include <stdint.h>
#include <stdio.h>

#include "core/tl_error.h"
#include "render/tl_render.h"
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

/* --reference-cache DIR (tl_cli_bench_cache.c): `reference` frames kept
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
