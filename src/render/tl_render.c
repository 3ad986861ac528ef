#include "render/tl_render.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/tl_clock.h"
#include "gl/tl_gl_context.h"
#include "gl/tl_renderer.h"
#include "prepare/tl_prepare.h"
#include "render/tl_render_internal.h"
#include "sky/tl_sky.h"
#include "waves/tl_waves.h"

/* The renderer's pixel samples as the share of the frame drawn. The
 * sky's rows cost next to nothing: they leave the count, so that the
 * share follows the time. */
static void count_pixel_samples(void *ctx, double pixel_samples, int sky_only)
{
    tl_render *r = ctx;
    if (sky_only)
        r->progress_total -= pixel_samples;
    else
        r->progress_done += pixel_samples;
    if (r->progress_total > 0.0)
        r->progress(r->progress_ctx, fmin(1.0, r->progress_done / r->progress_total));
}

void tl_render_set_progress(tl_render *r, tl_render_progress_fn fn, void *ctx)
{
    r->progress = fn;
    r->progress_ctx = ctx;
    tl_renderer_set_progress(r->renderer, fn ? count_pixel_samples : NULL, r);
}

/* A new frame of `samples` pixel samples in all (0: none to report). */
static void progress_begin(tl_render *r, double samples)
{
    r->progress_done = 0.0;
    r->progress_total = samples;
}

int tl_render_open_with(tl_render **out, const tl_shader_lib *lib, tl_error *err,
                        int (*open_context)(tl_render *r, void *arg, tl_error *err), void *arg)
{
    *out = NULL;
    tl_render *r = calloc(1, sizeof *r);
    if (r)
        r->sky = calloc(1, sizeof *r->sky);
    if (!r || !r->sky) {
        free(r);
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    int rc = open_context(r, arg, err);
    if (!rc)
        rc = tl_renderer_create(&r->renderer, lib, err);
    if (rc) {
        tl_render_close(r);
        return rc;
    }
    *out = r;
    return TL_OK;
}

static int open_headless(tl_render *r, void *arg, tl_error *err)
{
    (void)arg;
    return tl_gl_context_create_headless(&r->context, err);
}

int tl_render_open(tl_render **out, const tl_shader_lib *lib, tl_error *err)
{
    return tl_render_open_with(out, lib, err, open_headless, NULL);
}

int tl_render_reload_shaders(tl_render *r, tl_error *err)
{
    return tl_renderer_reload_shaders(r->renderer, err);
}

int tl_render_use_shaders(tl_render *r, const tl_shader_lib *lib, tl_error *err)
{
    return tl_renderer_use_shaders(r->renderer, lib, err);
}

void tl_render_close(tl_render *r)
{
    if (!r)
        return;
    tl_renderer_destroy(r->renderer);
    if (r->window)
        r->close_window(r->window);
    tl_gl_context_destroy(r->context);
    free(r->sky);
    free(r);
}

int tl_render_set_boat(tl_render *r, const tl_mesh *mesh, tl_error *err)
{
    return tl_renderer_set_mesh(r->renderer, mesh, err);
}

int tl_render_set_models(tl_render *r, const tl_models *models, tl_error *err)
{
    return tl_renderer_set_meshes(r->renderer, models->mesh, models->count, err);
}

int tl_render_use_cutscene(tl_render *r, const tl_cutscene *cs, tl_error *err)
{
    return tl_render_set_models(r, &cs->models, err);
}

int tl_render_set_display_lut(tl_render *r, const float *rgb, int n, tl_error *err)
{
    return tl_renderer_set_display_lut(r->renderer, rgb, n, err);
}

unsigned tl_render_last_features(const tl_render *r)
{
    return r->last_features;
}

const char *tl_render_describe(const tl_render *r)
{
    return r->window ? r->describe_window(r->window) : tl_gl_context_describe(r->context);
}

/* The octave table depends only on the ocean parameters: rebuild it when
 * they change (keyed ocean channels), not every frame. */
static const tl_waves *waves_for(tl_render *r, const tl_ocean *ocean)
{
    if (!r->waves_valid || memcmp(&r->waves_ocean, ocean, sizeof *ocean) != 0) {
        tl_waves_init(&r->waves, ocean);
        r->waves_ocean = *ocean;
        r->waves_valid = 1;
    }
    return &r->waves;
}

/* `frame` at the size, with a plane for the passes' data when `planes`
 * reads them back. */
static int ensure_frame(tl_frame *frame, int width, int height, unsigned planes, tl_error *err)
{
    if (frame->width != width || frame->height != height || !frame->color) {
        tl_frame_free(frame);
        int rc = tl_frame_alloc(frame, width, height, err);
        if (rc)
            return rc;
    }
    return (planes & TL_PLANE_AOV) ? tl_frame_alloc_aov(frame, err) : TL_OK;
}

/* One (sub-)frame's passes. With the boat in view and several samples a
 * pixel, a pass per sample, the hull drawn at each sample's offset: its
 * edges are then anti-aliased like the water's (one pass would draw it at
 * the pixels' centres for every sample). */
static int accumulate(tl_render *r, const tl_frame_uniforms *u, float weight, int write_depth,
                      tl_error *err)
{
    if (!(u->features & TL_FEATURE_BOAT) || u->spp <= 1)
        return tl_renderer_accumulate(r->renderer, u, weight, write_depth, err);
    int rc = TL_OK;
    for (int s = 0; !rc && s < u->spp; s++) {
        tl_frame_uniforms pass = *u;
        tl_prepare_boat_sample(&pass, s);
        rc = tl_renderer_accumulate_sample(r->renderer, &pass, weight / (float)u->spp, write_depth,
                                           s, err);
    }
    return rc;
}

int tl_render_prepare_sky(tl_renderer *renderer, const tl_scene *scene, tl_sky_luts *luts,
                          tl_frame_uniforms *u, tl_error *err)
{
    double sun_elevation, altitude;
    if (!tl_prepare_sky_tables(scene, luts, u, &sun_elevation, &altitude))
        return TL_OK;
    int rc = tl_renderer_prepare_sky(renderer, luts, sun_elevation, altitude, err);
    if (!rc)
        tl_prepare_sky_ambient(scene, luts, u);
    return rc;
}

int tl_render_frame(tl_render *r, const tl_scene *scene, tl_frame *frame, tl_error *err)
{
    return tl_render_frame_planes(r, scene, TL_PLANES_ALL, frame, err);
}

/* Draws the frame again (with the renderer's light layer set). */
typedef int (*redraw_fn)(tl_render *r, void *ctx, tl_error *err);

static int count_layers(unsigned layers)
{
    int n = 0;
    for (int k = 0; k < TL_FRAME_LAYERS; k++)
        n += (layers >> k) & 1u;
    return n;
}

/* A frame drawn smaller than its output (quality.render_scale < 1) is
 * upscaled with each value held between its two nearest texels (against
 * ringing), which is not linear: upscaled alone, the layers would not add
 * up to the upscaled colour. With every shaded layer at hand, each pixel's
 * are scaled by the colour over their sum (a subset is left as upscaled). */
static void layers_hold_sum(tl_frame *out, unsigned layers)
{
    const unsigned shaded = (1u << TL_LIGHT_SHADED) - 1u;
    if ((layers & shaded) != shaded)
        return;
    const size_t px = (size_t)out->width * (size_t)out->height;
    for (size_t i = 0; i < px * 3; i++) {
        double sum = 0.0;
        for (int k = 0; k < TL_LIGHT_SHADED; k++)
            sum += out->layer[k][i];
        double colour = out->color[i / 3 * 4 + i % 3];
        if (sum > 0.0)
            for (int k = 0; k < TL_LIGHT_SHADED; k++)
                out->layer[k][i] = (float)(out->layer[k][i] * (colour / sum));
    }
}

/* The light layers in `layers` of the frame just drawn and read back, into
 * out's layer planes: the glare's from the frame as it stands, then each
 * shaded layer drawn again alone by `redraw` and its colour read back.
 * `upscaled`: the frame was drawn smaller than its output and its colour
 * read back (layers_hold_sum scales them to it). */
static int read_layers(tl_render *r, unsigned layers, const tl_display_settings *display,
                       redraw_fn redraw, void *ctx, int upscaled, tl_frame *out, tl_error *err)
{
    if (!layers)
        return TL_OK;
    const size_t px = (size_t)out->width * (size_t)out->height;
    tl_frame scratch = {0};
    int rc = tl_frame_alloc_layers(out, layers, err);
    if (!rc)
        rc = tl_frame_alloc(&scratch, out->width, out->height, err);
    tl_renderer_want_aov(r->renderer, 0); /* the passes' data came with the frame */
    for (int k = TL_FRAME_LAYERS - 1; !rc && k >= 0; k--) { /* the glare first */
        if (!(layers & (1u << k)))
            continue;
        if (k == TL_LIGHT_GLARE) {
            rc = tl_renderer_finish_glare(r->renderer, display, &scratch, err);
        } else {
            tl_renderer_light_layer(r->renderer, k);
            rc = redraw(r, ctx, err);
            if (!rc)
                rc = tl_renderer_finish(r->renderer, display, TL_PLANE_COLOR, &scratch, err);
        }
        for (size_t i = 0; !rc && i < px; i++)
            for (int c = 0; c < 3; c++)
                out->layer[k][i * 3 + (size_t)c] = scratch.color[i * 4 + (size_t)c];
    }
    tl_renderer_light_layer(r->renderer, -1);
    tl_frame_free(&scratch);
    if (!rc && upscaled)
        layers_hold_sum(out, layers);
    return rc;
}

typedef struct scene_draw {
    const tl_frame_uniforms *u;
} scene_draw;

static int redraw_scene(tl_render *r, void *ctx, tl_error *err)
{
    const tl_frame_uniforms *u = ((const scene_draw *)ctx)->u;
    int rc = tl_renderer_begin(r->renderer, u->width, u->height, u->out_width, u->out_height, err);
    return rc ? rc : accumulate(r, u, 1.0f, 1, err);
}

int tl_render_frame_planes(tl_render *r, const tl_scene *scene, unsigned planes, tl_frame *frame,
                           tl_error *err)
{
    return tl_render_frame_layers(r, scene, planes, 0, frame, err);
}

int tl_render_frame_layers(tl_render *r, const tl_scene *scene, unsigned planes, unsigned layers,
                           tl_frame *frame, tl_error *err)
{
    int rc = tl_scene_validate(scene, err);
    if (!rc)
        rc = ensure_frame(frame, scene->width, scene->height, planes, err);
    if (rc)
        return rc;
    tl_renderer_want_aov(r->renderer, (planes & TL_PLANE_AOV) != 0);
    tl_frame_uniforms u;
    tl_prepare_frame(scene, waves_for(r, &scene->ocean), &u);
    r->last_features = u.features;
    /* Each shaded layer draws the frame again. */
    const int draws = 1 + count_layers(layers & ((1u << TL_LIGHT_SHADED) - 1u));
    progress_begin(r, (double)u.width * u.height * (u.spp < 1 ? 1 : u.spp) * draws);
    rc = tl_render_prepare_sky(r->renderer, scene, r->sky, &u, err);
    scene_draw draw = {&u};
    if (!rc)
        rc = redraw_scene(r, &draw, err);
    const tl_display_settings display = tl_display_of(&u);
    if (!rc)
        rc = tl_renderer_finish(r->renderer, &display, planes, frame, err);
    if (!rc)
        rc = read_layers(r, layers, &display, redraw_scene, &draw,
                         (planes & TL_PLANE_COLOR) &&
                             (u.width != u.out_width || u.height != u.out_height),
                         frame, err);
    return rc;
}

void tl_render_frame_scene(const tl_timeline *tl, double t, const tl_render_settings *settings,
                           tl_scene *scene)
{
    tl_timeline_eval(tl, t, scene);
    if (settings->width > 0 && settings->height > 0) {
        scene->width = settings->width;
        scene->height = settings->height;
    }
    if (settings->quality)
        scene->quality = *settings->quality;
    if (settings->spp > 0)
        scene->quality.spp = settings->spp;
    if (settings->camera)
        scene->camera = *settings->camera;
}

/* The display pass's settings from the scene's exposure, glare, pixel
 * filter and white balance. */
static tl_display_settings display_of(const tl_scene *scene)
{
    tl_display_settings d = {(float)(scene->exposure * exp2(-scene->ev)),
                             (float)scene->bloom,
                             (float)scene->quality.pixel_filter,
                             {1.0f, 1.0f, 1.0f}};
    tl_prepare_white_gain(scene, d.white_gain);
    return d;
}

/* The display pass with the scene's settings, then the planes read back
 * into `out`, or (out NULL) the frame left on the GPU for the window. */
static int show_or_read(tl_render *r, const tl_scene *scene, const tl_render_settings *settings,
                        tl_frame *out, tl_error *err)
{
    const tl_display_settings display = display_of(scene);
    if (!out)
        return tl_renderer_display(r->renderer, &display, err);
    int rc = tl_renderer_finish(r->renderer, &display,
                                settings->planes ? settings->planes : TL_PLANES_ALL, out, err);
    if (!rc)
        r->readback_seconds = tl_renderer_last_readback(r->renderer);
    return rc;
}

/* Frame `frame` of `tl` drawn, its sub-frames accumulated, but not yet
 * shown or read back; its scene in *scene. */
static int draw_timeline_frame(tl_render *r, const tl_timeline *tl, long frame,
                               const tl_render_settings *settings, int meter, tl_frame *out,
                               tl_scene *scene, tl_error *err)
{
    double t = tl_timeline_frame_time(tl, frame);
    tl_render_frame_scene(tl, t, settings, scene);
    /* The shot's exposure: metered from the timeline's camera, also under
     * the preview's free camera (whose every move would draw the meters
     * again). */
    int rc = meter ? tl_render_meter_exposure(r, tl, t, NULL, settings->meter, scene, err) : TL_OK;
    if (!rc)
        rc = tl_scene_validate(scene, err);
    if (!rc && out)
        rc = ensure_frame(out, scene->width, scene->height, settings->planes, err);
    int rw, rh;
    tl_prepare_render_size(scene, &rw, &rh);
    tl_renderer_want_aov(r->renderer, (settings->planes & TL_PLANE_AOV) != 0);
    if (!rc)
        rc = tl_renderer_begin(r->renderer, rw, rh, scene->width, scene->height, err);
    if (rc)
        return rc;
    /* The timeline gives the sub-frames' times (never across a cut);
     * depth comes from the one nearest t. */
    int samples = 1;
    if (settings->shutter_deg > 0.0)
        samples = settings->shutter_samples > 0 ? settings->shutter_samples : 8;
    double *times = malloc(sizeof *times * (size_t)samples);
    if (!times)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    int depth_sample = tl_timeline_shutter_times(tl, frame, settings->shutter_deg, samples, times);
    progress_begin(r,
                   (double)rw * rh * (scene->quality.spp < 1 ? 1 : scene->quality.spp) * samples);
    r->last_features = 0;
    for (int k = 0; !rc && k < samples; k++) {
        double tk = times[k];
        tl_scene sub;
        if (samples == 1)
            sub = *scene;
        else
            tl_render_frame_scene(tl, tk, settings, &sub);
        rc = tl_scene_validate(&sub, err);
        if (rc)
            break;
        tl_frame_uniforms u;
        tl_prepare_frame(&sub, waves_for(r, &sub.ocean), &u);
        rc = tl_render_prepare_sky(r->renderer, &sub, r->sky, &u, err);
        if (rc)
            break;
        u.seed = (unsigned)k * 0x9E3779B9u; /* new jitter per sub-frame */
        r->last_features |= u.features;
        rc = accumulate(r, &u, 1.0f / (float)samples, k == depth_sample, err);
    }
    free(times);
    return rc;
}

typedef struct timeline_draw {
    const tl_timeline *tl;
    long frame;
    tl_render_settings settings; /* the colour alone */
} timeline_draw;

static int redraw_timeline_frame(tl_render *r, void *ctx, tl_error *err)
{
    const timeline_draw *d = ctx;
    tl_scene scene;
    return draw_timeline_frame(r, d->tl, d->frame, &d->settings, 0, NULL, &scene, err);
}

int tl_render_timeline_frame(tl_render *r, const tl_timeline *tl, long frame,
                             const tl_render_settings *settings, tl_frame *out, tl_scene *scene_out,
                             tl_error *err)
{
    double t0 = tl_clock_seconds();
    r->render_seconds = r->readback_seconds = 0.0;
    tl_scene scene;
    int rc = draw_timeline_frame(r, tl, frame, settings, 1, out, &scene, err);
    if (!rc)
        rc = show_or_read(r, &scene, settings, out, err);
    if (!rc && out && settings->layers) {
        timeline_draw draw = {tl, frame, *settings};
        draw.settings.planes = TL_PLANE_COLOR;
        draw.settings.layers = 0;
        const tl_display_settings display = display_of(&scene);
        int rw, rh;
        tl_prepare_render_size(&scene, &rw, &rh);
        const unsigned planes = settings->planes ? settings->planes : TL_PLANES_ALL;
        rc = read_layers(r, settings->layers, &display, redraw_timeline_frame, &draw,
                         (planes & TL_PLANE_COLOR) && (rw != scene.width || rh != scene.height),
                         out, err);
    }
    if (!rc && scene_out)
        *scene_out = scene;
    r->render_seconds = tl_clock_seconds() - t0 - r->readback_seconds;
    return rc;
}

int tl_render_timeline_frame_queue(tl_render *r, const tl_timeline *tl, long frame,
                                   const tl_render_settings *settings, tl_scene *scene_out,
                                   tl_error *err)
{
    if (settings->layers)
        return tl_error_set(err, TL_ERR_RUNTIME,
                            "light layers are not queued: render the frame with "
                            "tl_render_timeline_frame");
    tl_scene scene;
    int rc = draw_timeline_frame(r, tl, frame, settings, 1, NULL, &scene, err);
    tl_display_settings display = display_of(&scene);
    if (!rc)
        rc = tl_renderer_finish_begin(r->renderer, &display,
                                      settings->planes ? settings->planes : TL_PLANES_ALL, err);
    if (!rc && scene_out)
        *scene_out = scene;
    return rc;
}

int tl_render_collect(tl_render *r, tl_frame *out, tl_error *err)
{
    int w, h;
    if (!tl_renderer_queued_size(r->renderer, &w, &h))
        return tl_error_set(err, TL_ERR_RUNTIME, "no frame is queued");
    int rc = ensure_frame(out, w, h, tl_renderer_queued_planes(r->renderer), err);
    if (rc) {
        tl_frame dummy = {0}; /* the queue moves on all the same */
        tl_renderer_finish_end(r->renderer, &dummy, &(tl_error){0});
        return rc;
    }
    return tl_renderer_finish_end(r->renderer, out, err);
}

int tl_render_timeline_refine(tl_render *r, const tl_timeline *tl, long frame,
                              const tl_render_settings *settings, int sample, int samples,
                              tl_frame *out, tl_error *err)
{
    double t0 = tl_clock_seconds();
    r->render_seconds = r->readback_seconds = 0.0;
    tl_render_settings pass = *settings;
    pass.spp = samples;
    tl_scene scene;
    const double t = tl_timeline_frame_time(tl, frame);
    tl_render_frame_scene(tl, t, &pass, &scene);
    /* Metered before the first sample only: the meters' drawing would
     * overwrite the running mean; the later samples keep its exposure. */
    int rc = TL_OK;
    if (sample == 0) {
        rc = tl_render_meter_exposure(r, tl, t, NULL, settings->meter, &scene, err);
        r->refine_exposure = scene.exposure;
    } else {
        scene.exposure = r->refine_exposure;
    }
    if (!rc)
        rc = tl_scene_validate(&scene, err);
    if (!rc && out)
        rc = ensure_frame(out, scene.width, scene.height, 0, err);
    int rw, rh;
    tl_prepare_render_size(&scene, &rw, &rh);
    tl_renderer_want_aov(r->renderer, 0); /* the preview's: no passes */
    if (!rc && sample == 0)
        rc = tl_renderer_begin(r->renderer, rw, rh, scene.width, scene.height, err);
    progress_begin(r, 0.0); /* the preview's refinement: a sample a call */
    tl_frame_uniforms u;
    if (!rc) {
        tl_prepare_frame(&scene, waves_for(r, &scene.ocean), &u);
        rc = tl_render_prepare_sky(r->renderer, &scene, r->sky, &u, err);
    }
    if (!rc) {
        u.seed = 0; /* the pattern tl_render_timeline_frame's one pass uses */
        r->last_features = u.features;
        if (u.features & TL_FEATURE_BOAT)
            tl_prepare_boat_sample(&u, sample); /* as accumulate draws it */
        rc = tl_renderer_refine(r->renderer, &u, sample, err);
    }
    if (!rc)
        rc = show_or_read(r, &scene, settings, out, err);
    r->render_seconds = tl_clock_seconds() - t0 - r->readback_seconds;
    return rc;
}

void tl_render_last_timing(const tl_render *r, double *render_seconds, double *readback_seconds)
{
    *render_seconds = r->render_seconds;
    *readback_seconds = r->readback_seconds;
}

_Static_assert(TL_RENDER_PASSES == TL_TIMED_COUNT, "tl_render.h's pass count is the renderer's");

void tl_render_time_passes(tl_render *r, int on)
{
    tl_renderer_time_passes(r->renderer, on);
}

int tl_render_pass_seconds(const tl_render *r, double out[TL_RENDER_PASSES])
{
    return tl_renderer_pass_seconds(r->renderer, out);
}

const char *tl_render_pass_name(int pass)
{
    return tl_renderer_pass_name(pass);
}
