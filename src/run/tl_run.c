/* A render run's loop (tl_run.h): draw, collect, hand to the writers. */
#include "run/tl_run.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/tl_clock.h"
#include "job/tl_writer.h"
#include "passes/tl_passes.h"

int tl_run_quality_meta(const tl_quality *q, tl_meta *out)
{
    const tl_meta m[TL_RUN_QUALITY_META] = {
        {"tideline/quality", TL_META_STRING, q->name, 0, 0, NULL},
        {"tideline/spp", TL_META_INT, NULL, 0, q->spp, NULL},
        {"tideline/march_octaves", TL_META_INT, NULL, 0, q->march_octaves, NULL},
        {"tideline/normal_octaves", TL_META_INT, NULL, 0, q->normal_octaves, NULL},
        {"tideline/march_steps", TL_META_INT, NULL, 0, q->march_steps, NULL},
        {"tideline/hit_epsilon", TL_META_DOUBLE, NULL, q->hit_epsilon, 0, NULL},
        {"tideline/normal_epsilon", TL_META_DOUBLE, NULL, q->normal_epsilon, 0, NULL},
        {"tideline/giant_iterations", TL_META_INT, NULL, 0, q->giant_iterations, NULL},
        {"tideline/spray_step", TL_META_DOUBLE, NULL, q->spray_step, 0, NULL},
        {"tideline/shaft_steps", TL_META_INT, NULL, 0, q->shaft_steps, NULL},
        {"tideline/mesh_scale", TL_META_INT, NULL, 0, q->mesh_scale, NULL},
        {"tideline/refine_steps", TL_META_INT, NULL, 0, q->refine_steps, NULL},
        {"tideline/polish", TL_META_INT, NULL, 0, q->polish, NULL},
        {"tideline/lod", TL_META_INT, NULL, 0, q->lod, NULL},
        {"tideline/analytic_normals", TL_META_INT, NULL, 0, q->analytic_normals, NULL},
        {"tideline/filtered_shading", TL_META_INT, NULL, 0, q->filtered_shading, NULL},
        {"tideline/render_scale", TL_META_DOUBLE, NULL, q->render_scale, 0, NULL},
        {"tideline/pixel_filter", TL_META_DOUBLE, NULL, q->pixel_filter, 0, NULL},
        {"tideline/march_relax", TL_META_DOUBLE, NULL, q->march_relax, 0, NULL},
        {"tideline/march_prepass", TL_META_INT, NULL, 0, q->march_prepass, NULL},
        {"tideline/prepass_budget", TL_META_INT, NULL, 0, q->prepass_budget, NULL},
        {"tideline/giant_prepass", TL_META_INT, NULL, 0, q->giant_prepass, NULL},
        {"tideline/miss_at_start", TL_META_INT, NULL, 0, q->miss_at_start, NULL},
        {"tideline/normalize_smoothed", TL_META_INT, NULL, 0, q->normalize_smoothed, NULL},
        {"tideline/facing_normals", TL_META_INT, NULL, 0, q->facing_normals, NULL},
    };
    memcpy(out, m, sizeof m);
    return TL_RUN_QUALITY_META;
}

typedef struct run_state {
    const tl_run_config *cfg;
    tl_run_result *result;
    size_t done;
    uint8_t *rgb; /* the movie's frame, 8-bit RGB */
} run_state;

static void report(run_state *s, tl_run_event event, long frame, const char *path,
                   unsigned features, int writers)
{
    if (!s->cfg->report)
        return;
    const tl_run_result *r = s->result;
    tl_run_status status = {.event = event,
                            .frame = frame,
                            .path = path,
                            .features = features,
                            .writers = writers,
                            .done = s->done,
                            .total = s->cfg->frames->count,
                            .ms_per_frame =
                                r->drawn ? r->busy_seconds / (double)r->drawn * 1e3 : 0.0};
    s->cfg->report(s->cfg->report_ctx, &status);
}

static int write_frame_files(const run_state *s, long frame, const tl_scene *scene,
                             const tl_frame *f, const char *path, tl_error *err)
{
    const tl_run_config *cfg = s->cfg;
    char camera[256];
    const tl_camera *c = &scene->camera;
    snprintf(camera, sizeof camera,
             "position %.17g %.17g %.17g yaw %.17g pitch %.17g roll %.17g vfov %.17g (radians)",
             c->position[0], c->position[1], c->position[2], c->yaw, c->pitch, c->roll, c->vfov);
    tl_meta meta[7 + TL_RUN_QUALITY_META] = {
        {"tideline/version", TL_META_STRING, TL_VERSION, 0, 0, NULL},
        {"tideline/timeline", TL_META_STRING, cfg->timeline_path, 0, 0, NULL},
        {"tideline/frame", TL_META_INT, NULL, 0, (int)frame, NULL},
        {"tideline/time", TL_META_DOUBLE, NULL, scene->time, 0, NULL},
        {"tideline/fps", TL_META_DOUBLE, NULL, cfg->timeline->fps, 0, NULL},
        {"tideline/camera", TL_META_STRING, camera, 0, 0, NULL},
        {"tideline/shutter", TL_META_DOUBLE, NULL, cfg->settings.shutter_deg, 0, NULL},
    };
    tl_image_options opt = cfg->image;
    opt.meta = meta;
    opt.meta_count = 7 + tl_run_quality_meta(&scene->quality, meta + 7);
    if (tl_image_format_from_path(path) != TL_IMAGE_EXR)
        return tl_image_write(path, f, &opt, err);
    /* An EXR carries the camera as OpenEXR's standard attributes, and the
     * passes asked for. */
    const char *object[TL_OBJECT_MAX], *model[TL_OBJECT_MAX];
    for (int k = 0; k < cfg->timeline->object_count && k < TL_OBJECT_MAX; k++) {
        object[k] = cfg->timeline->objects[k].name;
        model[k] = cfg->timeline->objects[k].model;
    }
    tl_passes_frame info = {cfg->passes,        &scene->camera, object, cfg->timeline->object_count,
                            cfg->timeline->fps, scene,          NULL,   NULL,
                            cfg->space,         cfg->working,   model};
    /* The Vector pass: the scenes a frame before and after, none across a cut. */
    tl_scene prev, next;
    if (cfg->passes & TL_PASSES_VECTOR) {
        const tl_timeline *tl = cfg->timeline;
        double t0 = tl_timeline_frame_time(tl, frame - 1),
               t1 = tl_timeline_frame_time(tl, frame + 1);
        tl_render_frame_scene(tl, t0, &cfg->settings, &prev);
        tl_render_frame_scene(tl, t1, &cfg->settings, &next);
        info.prev = tl_timeline_has_cut_between(tl, t0, scene->time) ? NULL : &prev;
        info.next = tl_timeline_has_cut_between(tl, scene->time, t1) ? NULL : &next;
    }
    return tl_passes_write_frame(path, f, &info, &opt, err);
}

/* A frame's files: on any writer thread, several frames at once. */
static int write_files(void *ctx, long n, const tl_scene *scene, const tl_frame *f,
                       const char *path, tl_error *err)
{
    const run_state *s = ctx;
    if (!s->cfg->pattern)
        return TL_OK;
    int rc = write_frame_files(s, n, scene, f, path, err);
    const int single = s->cfg->frames->count == 1;
    for (int k = 0; !rc && k < s->cfg->more_count; k++) {
        char more[4096];
        rc = tl_pattern_format(s->cfg->more_patterns[k], n, single, more, sizeof more, err);
        if (!rc)
            rc = write_frame_files(s, n, scene, f, more, err);
    }
    return rc;
}

/* The planes a frame file at `path` is made from. */
static unsigned planes_for(const char *path, unsigned passes)
{
    return tl_image_format_from_path(path) == TL_IMAGE_EXR
               ? TL_PLANE_COLOR | TL_PLANE_DEPTH | (tl_passes_need_aov(passes) ? TL_PLANE_AOV : 0u)
               : TL_PLANE_DISPLAY;
}

/* Whether frame n is complete in every pattern (--skip-existing). */
static int frame_complete(const tl_run_config *cfg, long n, const char *path, int width, int height,
                          const char *passes)
{
    const char *space = tl_color_working_name(cfg->space);
    if (!tl_job_frame_complete(path, width, height, passes, space))
        return 0;
    for (int k = 0; k < cfg->more_count; k++) {
        char more[4096];
        tl_error err;
        if (tl_pattern_format(cfg->more_patterns[k], n, cfg->frames->count == 1, more, sizeof more,
                              &err) ||
            !tl_job_frame_complete(more, width, height, passes, space))
            return 0;
    }
    return 1;
}

/* A frame of the movie: one at a time, in frame order, dithered as 8-bit
 * PNGs are. */
static int write_movie(void *ctx, long n, const tl_scene *scene, const tl_frame *f,
                       const char *path, tl_error *err)
{
    (void)n;
    (void)scene;
    (void)path;
    const run_state *s = ctx;
    for (int y = 0; y < f->height; y++)
        tl_frame_display_row8(f, y, !s->cfg->image.no_dither,
                              s->rgb + (size_t)y * (size_t)f->width * 3);
    return tl_movie_write(s->cfg->movie, s->rgb, err);
}

/* Counts a frame the writer finished. */
static void frame_written(run_state *s, long n, const char *path)
{
    if (n < 0)
        return;
    s->result->written++;
    s->done++;
    report(s, TL_RUN_WRITTEN, n, path, 0, 0);
}

/* The frame drawn last, whose planes are still on their way to the CPU
 * (tl_render_timeline_frame_queue): collected once the next one is drawn. */
typedef struct pending_frame {
    int queued;
    long n;
    tl_scene scene;
    char path[4096];
} pending_frame;

/* Collects the pending frame into `frame` and hands it to the writers. */
static int submit_pending(run_state *s, tl_render *render, tl_writer *writer, pending_frame *p,
                          tl_frame *frame, tl_error *err)
{
    if (!p->queued)
        return TL_OK;
    p->queued = 0;
    int rc = tl_render_collect(render, frame, err);
    if (!rc) {
        long done;
        rc = tl_writer_submit(writer, frame, p->n, &p->scene, p->path, &done, err);
        frame_written(s, done, tl_writer_path(writer));
        s->result->drawn += !rc;
    }
    return rc;
}

static int stopped(const tl_run_config *cfg)
{
    return cfg->stop && *cfg->stop;
}

int tl_run_frames(tl_render *render, const tl_run_config *cfg, tl_run_result *out, tl_error *err)
{
    memset(out, 0, sizeof *out);
    run_state s = {cfg, out, 0, NULL};
    const tl_frame_list *frames = cfg->frames;
    tl_render_settings settings = cfg->settings;
    /* Consecutive frames share auto exposure's meters. */
    tl_meter_cache meters;
    tl_meter_cache_reset(&meters);
    if (!settings.meter)
        settings.meter = &meters;
    tl_scene first;
    tl_render_frame_scene(cfg->timeline, 0.0, &settings, &first);
    const int width = first.width, height = first.height;
    /* Read back only what the outputs use: EXR holds colour and depth,
     * PNG and movies the display image. */
    settings.planes = 0;
    char path[4096] = "";
    int rc = TL_OK;
    if (cfg->pattern && frames->count > 0) {
        rc = tl_pattern_format(cfg->pattern, frames->frames[0], frames->count == 1, path,
                               sizeof path, err);
        int exr = tl_image_format_from_path(path) == TL_IMAGE_EXR;
        settings.planes |= planes_for(path, cfg->passes);
        for (int k = 0; !rc && k < cfg->more_count; k++) {
            char more[4096];
            rc = tl_pattern_format(cfg->more_patterns[k], frames->frames[0], frames->count == 1,
                                   more, sizeof more, err);
            settings.planes |= planes_for(more, cfg->passes);
            exr |= tl_image_format_from_path(more) == TL_IMAGE_EXR;
        }
        settings.layers = exr ? tl_passes_light_layers(cfg->passes) : 0u;
    }
    if (cfg->movie) {
        settings.planes |= TL_PLANE_DISPLAY;
        s.rgb = malloc((size_t)width * (size_t)height * 3);
        if (!s.rgb)
            rc = tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    }
    if (rc) {
        free(s.rgb);
        return rc;
    }

    /* The passes a complete frame holds (--skip-existing). */
    char passes[TL_PASSES_NAMES_SIZE] = "";
    if (cfg->passes)
        tl_passes_format(cfg->passes | TL_PASSES_COMBINED, passes, sizeof passes);
    tl_frame frame = {0};
    tl_writer writer;
    /* A frame with the passes' data holds 24 more floats a pixel, and its
     * writer as many again while it encodes: fewer writers by default. */
    int writers = cfg->writers ? cfg->writers : tl_writer_default_count();
    if (!cfg->writers && (tl_passes_need_aov(cfg->passes) || tl_passes_light_layers(cfg->passes)) &&
        writers > TL_RUN_PASSES_WRITERS)
        writers = TL_RUN_PASSES_WRITERS;
    tl_writer_init(&writer, write_files, cfg->movie ? write_movie : NULL, &s, writers);
    report(&s, TL_RUN_STARTED, -1, "", 0, writer.count);
    unsigned last_features = 0;
    long done_frame;
    pending_frame pending = {0};
    for (size_t i = 0; !rc && i < frames->count && !stopped(cfg); i++) {
        long n = frames->frames[i];
        if (cfg->pattern)
            rc = tl_pattern_format(cfg->pattern, n, frames->count == 1, path, sizeof path, err);
        if (rc)
            break;
        if (cfg->skip_existing && cfg->pattern &&
            frame_complete(cfg, n, path, width, height, passes)) {
            /* The frames in flight are reported first: progress stays in order. */
            rc = submit_pending(&s, render, &writer, &pending, &frame, err);
            for (int k = 0; !rc && k < writer.count; k++) {
                rc = tl_writer_wait(&writer, &done_frame, err);
                frame_written(&s, done_frame, tl_writer_path(&writer));
            }
            if (rc)
                break;
            out->skipped++;
            s.done++;
            report(&s, TL_RUN_SKIPPED, n, path, 0, 0);
            continue;
        }
        double t0 = tl_clock_seconds();
        tl_scene scene;
        if (settings.layers) {
            /* Light layers redraw the frame: it is read back at once,
             * not queued (tl_render_timeline_frame_queue). */
            rc = tl_render_timeline_frame(render, cfg->timeline, n, &settings, &frame, &scene, err);
            if (rc)
                break;
            if (i == 0 || tl_render_last_features(render) != last_features) {
                last_features = tl_render_last_features(render);
                report(&s, TL_RUN_FEATURES, n, path, last_features, 0);
            }
            long done;
            rc = tl_writer_submit(&writer, &frame, n, &scene, cfg->pattern ? path : "", &done, err);
            frame_written(&s, done, tl_writer_path(&writer));
            s.result->drawn += !rc;
            out->busy_seconds += tl_clock_seconds() - t0;
            continue;
        }
        rc = tl_render_timeline_frame_queue(render, cfg->timeline, n, &settings, &scene, err);
        if (rc)
            break;
        if (i == 0 || tl_render_last_features(render) != last_features) {
            last_features = tl_render_last_features(render);
            report(&s, TL_RUN_FEATURES, n, path, last_features, 0);
        }
        if (stopped(cfg))
            break; /* the frame just drawn is discarded: never collected */
        rc = submit_pending(&s, render, &writer, &pending, &frame, err);
        pending = (pending_frame){1, n, scene, ""};
        snprintf(pending.path, sizeof pending.path, "%s", cfg->pattern ? path : "");
        out->busy_seconds += tl_clock_seconds() - t0;
    }
    /* The frame drawn before an interruption or an error is complete too. */
    if (pending.queued) {
        int prc = submit_pending(&s, render, &writer, &pending, &frame, rc ? &(tl_error){0} : err);
        if (!rc)
            rc = prc;
    }
    /* The frames submitted are complete: they are always written, even
     * when interrupted (what was rendered is kept, atomically). */
    double t_last = tl_clock_seconds();
    for (int i = 0; i < writer.count; i++) { /* each wait takes the oldest */
        int wrc = tl_writer_wait(&writer, &done_frame, rc ? &(tl_error){0} : err);
        if (!rc && wrc)
            rc = wrc;
        else if (!wrc)
            frame_written(&s, done_frame, tl_writer_path(&writer));
    }
    out->busy_seconds += tl_clock_seconds() - t_last;
    tl_writer_free(&writer);
    out->interrupted = stopped(cfg) && !rc;
    tl_frame_free(&frame);
    free(s.rgb);
    return rc;
}
