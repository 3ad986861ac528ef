/* Helpers shared by the render tests: a headless renderer, the GPU height
 * probe against the CPU mirror, one-pass renders. */
#ifndef TL_GL_TEST_H
#define TL_GL_TEST_H

#include <math.h>
#include <stdlib.h>

#include "gl/tl_gl_context.h"
#include "gl/tl_renderer.h"
#include "prepare/tl_prepare.h"
#include "render/tl_render.h"
#include "scene/tl_scene.h"
#include "sky/tl_sky.h"
#include "tl_test.h"
#include "waves/tl_giant.h"
#include "waves/tl_waves.h"

/* A headless context and a renderer on the embedded shaders, or NULL. */
static inline tl_renderer *gl_test_open(tl_gl_context **ctx)
{
    tl_error err;
    tl_error_clear(&err);
    if (tl_gl_context_create_headless(ctx, &err)) {
        fprintf(stderr, "no GL context: %s\n", err.message);
        return NULL;
    }
    printf("%s\n", tl_gl_context_describe(*ctx));
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    tl_renderer *r = NULL;
    if (tl_renderer_create(&r, &lib, &err)) {
        fprintf(stderr, "renderer: %s\n", err.message);
        tl_gl_context_destroy(*ctx);
        return NULL;
    }
    return r;
}

/* The whole headless pipeline (tl_render) on the embedded shaders, or NULL. */
static inline tl_render *render_test_open(void)
{
    tl_error err;
    tl_error_clear(&err);
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    tl_render *r = NULL;
    if (tl_render_open(&r, &lib, &err)) {
        fprintf(stderr, "no pipeline: %s\n", err.message);
        return NULL;
    }
    return r;
}

/* Max |GPU - CPU| of the surface height (ocean plus giant wave) over an
 * n x n grid of points within half_extent of the camera. */
static inline double probe_error(tl_renderer *r, const tl_scene *s, int octaves, double half_extent,
                                 int n)
{
    tl_waves w;
    tl_waves_init(&w, &s->ocean);
    tl_giant g;
    tl_giant_prepare(&g, &s->giant, s->time);
    tl_frame_uniforms u;
    tl_prepare_frame(s, &w, &u);
    float *xz = malloc(sizeof(float) * 2 * (size_t)(n * n));
    float *gpu = malloc(sizeof(float) * (size_t)(n * n));
    if (!xz || !gpu) {
        free(xz);
        free(gpu);
        return INFINITY;
    }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            xz[(j * n + i) * 2 + 0] = (float)(-half_extent + 2.0 * half_extent * i / (n - 1));
            xz[(j * n + i) * 2 + 1] = (float)(-half_extent + 2.0 * half_extent * j / (n - 1));
        }
    tl_error err;
    tl_error_clear(&err);
    double worst = INFINITY;
    if (tl_renderer_probe_heights(r, &u, xz, n * n, octaves, gpu, &err)) {
        fprintf(stderr, "probe failed: %s\n", err.message);
    } else {
        worst = 0.0;
        for (int k = 0; k < n * n; k++) {
            /* The CPU mirror takes absolute positions: the camera's plus the
             * (exactly representable) float offset the GPU saw. */
            double x = s->camera.position[0] + (double)xz[k * 2];
            double z = s->camera.position[2] + (double)xz[k * 2 + 1];
            double cpu = tl_waves_surface_height(&w, &g, x, z, s->time, octaves,
                                                 s->quality.giant_iterations);
            double d = fabs(cpu - (double)gpu[k]);
            if (!(d <= worst))
                worst = d;
        }
    }
    free(xz);
    free(gpu);
    return worst;
}

/* The unit view ray through the point (gx, gy) of the frame, in pixels
 * from its lower-left corner (GL's, as gl_FragCoord), as the ocean shader
 * sees it. */
static inline void frame_ray(const tl_scene *s, double gx, double gy, double ray[3])
{
    double right[3], up[3], fwd[3];
    tl_scene_camera_basis(&s->camera, right, up, fwd);
    double th = tan(0.5 * s->camera.vfov), aspect = (double)s->width / s->height;
    double nx = gx / s->width * 2.0 - 1.0, ny = gy / s->height * 2.0 - 1.0, len = 0.0;
    for (int i = 0; i < 3; i++) {
        ray[i] = fwd[i] + nx * aspect * th * right[i] + ny * th * up[i];
        len += ray[i] * ray[i];
    }
    for (int i = 0; i < 3; i++)
        ray[i] /= sqrt(len);
}

/* The unit view ray through the centre of pixel (x, y), top row first, as
 * the ocean shader and the rasteriser see it. */
static inline void pixel_ray(const tl_scene *s, int x, int y, double ray[3])
{
    frame_ray(s, x + 0.5, s->height - 1 - y + 0.5, ray);
}

/* A screen rectangle (x0 y0 x1 y1, GL's rows) that should hold every ray
 * `reaches` says can show a feature, checked at nine points of every
 * pixel (centre, corners, edge midpoints): such rays through pixels
 * outside it into *outside, inside into *inside; the pixels inside into
 * *area. */
static inline void rect_rays(const tl_scene *s, const int rect[4],
                             int (*reaches)(const void *ctx, const double ray[3]), const void *ctx,
                             int *outside, int *inside, int *area)
{
    *outside = *inside = *area = 0;
    for (int y = 0; y < s->height; y++)
        for (int x = 0; x < s->width; x++) {
            int in = x >= rect[0] && x < rect[2] && y >= rect[1] && y < rect[3];
            *area += in;
            for (int k = 0; k < 9; k++) {
                double ray[3];
                frame_ray(s, x + 0.5 * (k % 3), y + 0.5 * (k / 3), ray);
                int hit = reaches(ctx, ray);
                *outside += hit && !in;
                *inside += hit && in;
            }
        }
}

/* The prepared frame `u` rendered as it is (split at one of its screen
 * rectangles, `rect`, which is u's) and again with `rect` the whole frame:
 * the largest difference of a display value between the two, their count
 * in *differ. *whole keeps the second render when not NULL (the caller
 * frees it). */
static inline double split_against_whole(tl_renderer *r, tl_frame_uniforms *u, int rect[4],
                                         int *differ, tl_frame *whole)
{
    const int w = u->width, h = u->height;
    tl_error err;
    tl_error_clear(&err);
    tl_frame split, all_of_it;
    CHECK(tl_frame_alloc(&split, w, h, &err) == 0);
    CHECK(tl_frame_alloc(&all_of_it, w, h, &err) == 0);
    CHECK(tl_renderer_render(r, u, &split, &err) == 0);
    const int all[4] = {0, 0, w, h};
    memcpy(rect, all, sizeof all);
    CHECK(tl_renderer_render(r, u, &all_of_it, &err) == 0);
    double worst = 0.0;
    *differ = 0;
    for (size_t i = 0; i < (size_t)w * h * 4; i++) {
        double e = fabs((double)split.display[i] - all_of_it.display[i]);
        worst = fmax(worst, e);
        *differ += e > 0.0;
    }
    tl_frame_free(&split);
    if (whole)
        *whole = all_of_it;
    else
        tl_frame_free(&all_of_it);
    return worst;
}

static inline double luminance(const float *rgb)
{
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

/* The ocean of `scene` (into w) and its frame's uniforms. */
static inline void gl_test_uniforms(const tl_scene *scene, tl_waves *w, tl_frame_uniforms *u)
{
    tl_waves_init(w, &scene->ocean);
    tl_prepare_frame(scene, w, u);
}

/* Prepares `scene` as tl_render does: uniforms, and the physical sky's
 * tables brought up to date. */
static inline void gl_test_prepare(tl_renderer *r, const tl_scene *scene, tl_frame_uniforms *u)
{
    static tl_sky_luts luts; /* ~0.5 MB: kept between calls like tl_render's */
    tl_waves w;
    gl_test_uniforms(scene, &w, u);
    tl_error err;
    tl_error_clear(&err);
    if (tl_render_prepare_sky(r, scene, &luts, u, &err))
        fprintf(stderr, "the sky's tables: %s\n", err.message);
}

/* Renders the prepared uniforms `u` in one pass into `f` (allocated
 * here, width x height); 0 when it rendered. */
static inline int render_prepared(tl_renderer *r, const tl_frame_uniforms *u, int width, int height,
                                  tl_frame *f)
{
    tl_error err;
    tl_error_clear(&err);
    CHECK(tl_frame_alloc(f, width, height, &err) == 0);
    int rc = tl_renderer_render(r, u, f, &err);
    CHECK(rc == 0);
    if (rc) {
        fprintf(stderr, "render failed: %s\n", err.message);
        tl_frame_free(f);
    }
    return rc;
}

/* Renders `scene` in one pass into `f` (allocated here). */
static inline int render(tl_renderer *r, const tl_scene *scene, tl_frame *f)
{
    tl_frame_uniforms u;
    gl_test_prepare(r, scene, &u);
    return render_prepared(r, &u, scene->width, scene->height, f);
}

/* Renders `a` into `fa` and `b` into `fb` (both allocated here, both
 * freed on failure); 0 when both rendered. */
static inline int render_pair(tl_renderer *r, const tl_scene *a, const tl_scene *b, tl_frame *fa,
                              tl_frame *fb)
{
    if (render(r, a, fa))
        return 1;
    if (render(r, b, fb)) {
        tl_frame_free(fa);
        return 1;
    }
    return 0;
}

/* `scene` with its boat and without it (the same sea). */
static inline int render_boat_pair(tl_renderer *r, const tl_scene *scene, tl_frame *with,
                                   tl_frame *without)
{
    tl_scene none = *scene;
    none.boat.enabled = false;
    return render_pair(r, scene, &none, with, without);
}

/* `scene` with its wake and with the wake's strength at 0. */
static inline int render_wake_pair(tl_renderer *r, const tl_scene *scene, tl_frame *with,
                                   tl_frame *without)
{
    tl_scene dry = *scene;
    dry.boat.wake = 0.0;
    return render_pair(r, scene, &dry, with, without);
}

/* Pixels of `a` lighter than `b`'s by more than 0.01 (foam over water). */
static inline long lighter_pixels(const tl_frame *a, const tl_frame *b)
{
    long n = 0;
    for (size_t i = 0; i < (size_t)a->width * a->height * 4; i += 4)
        n += luminance(a->color + i) > luminance(b->color + i) + 0.01;
    return n;
}

#endif
