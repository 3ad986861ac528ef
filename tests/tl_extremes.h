/* Shared by the two extremes suites (test_extremes.c: time, distance,
 * rays and lights; test_extremes_params.c: every channel at its ends, keys,
 * boats): render a scene and check every plane of the frame. */
#ifndef TL_EXTREMES_H
#define TL_EXTREMES_H

#include <stdio.h>
#include <time.h>

#include "core/tl_math.h"
#include "tl_gl_test.h"

static inline double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---------------------------------------------------------------- frames */

/* Every plane finite; colour >= 0; display in [0, 1]; depth >= 0 (the
 * sky's is TL_FRAME_SKY_DEPTH; 0 where underwater.mode on puts a camera
 * that is above the water at the surface). Prints what is wrong, once. */
static inline int frame_ok(const tl_frame *f, int width, int height, const char *label)
{
    size_t n = (size_t)width * (size_t)height;
    size_t bad_color = 0, bad_display = 0, bad_depth = 0;
    for (size_t i = 0; i < n * 4; i++) {
        bad_color += !(isfinite(f->color[i]) && f->color[i] >= 0.0f);
        bad_display += !(f->display[i] >= 0.0f && f->display[i] <= 1.0f);
    }
    for (size_t i = 0; i < n; i++)
        bad_depth += !(isfinite(f->depth[i]) && f->depth[i] >= 0.0f);
    if (bad_color || bad_display || bad_depth)
        printf("  %s: %zu bad colour values, %zu bad display values, %zu bad depths\n", label,
               bad_color, bad_display, bad_depth);
    return !bad_color && !bad_display && !bad_depth;
}

static double slowest_render = 0.0;
static char slowest_label[160];
static int renders = 0;

/* Validates and renders `s` (one pass, as tl_render does) and checks the
 * frame; keeps the frame in *f when `keep`. Returns 1 when all is well. */
static inline int render_checked(tl_renderer *r, const tl_scene *s, const char *label,
                                 tl_frame *keep)
{
    tl_error err;
    tl_error_clear(&err);
    if (tl_scene_validate(s, &err)) {
        printf("  %s: scene refused: %s\n", label, err.message);
        CHECK(0);
        return 0;
    }
    tl_frame f;
    double t0 = now();
    if (render(r, s, &f)) {
        printf("  %s: render failed\n", label);
        return 0;
    }
    double dt = now() - t0;
    renders++;
    if (dt > slowest_render) {
        slowest_render = dt;
        snprintf(slowest_label, sizeof slowest_label, "%s", label);
    }
    int ok = frame_ok(&f, s->width, s->height, label);
    CHECK(ok);
    if (keep)
        *keep = f;
    else
        tl_frame_free(&f);
    return ok;
}

#endif
