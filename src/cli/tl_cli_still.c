/* tideline still: render one frame of the default ocean (or, with flags,
 * any camera, sun, time and quality) to EXR and/or PNG files. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "core/tl_clock.h"
#include "image/tl_image_io.h"
#include "passes/tl_passes.h"
#include "prepare/tl_prepare.h"
#include "render/tl_render.h"
#include "run/tl_run.h"
#include "scene/tl_scene.h"
#include "shader/tl_shader_lib.h"
#include "timeline/tl_parse.h"

#define MAX_OUTPUTS 8

/* The progress line of a long frame (a `reference` still takes minutes on
 * a CPU renderer): on a terminal only, from its first second on, at most
 * two updates a second (`delay`: tl_cli_progress_delay, 1 s). */
typedef struct still_progress {
    double start, last, delay;
    int shown;
} still_progress;

static void still_progress_update(void *ctx, double fraction)
{
    still_progress *p = ctx;
    double now = tl_clock_seconds(), spent = now - p->start;
    if (spent < p->delay || (now - p->last < 0.5 * p->delay && fraction < 1.0) || fraction <= 0.0)
        return;
    p->last = now;
    p->shown = 1;
    char eta[32];
    tl_cli_format_duration(spent * (1.0 - fraction) / fraction, eta, sizeof eta);
    fprintf(stderr, "\rtideline still: %3.0f%% drawn, ETA %s   ", fraction * 100.0, eta);
    fflush(stderr);
}

static const char usage[] =
    "Usage: tideline still [TIMELINE.tl] [options] -o FILE [-o FILE...]\n"
    "\n"
    "Render one frame headless: the default ocean, or the scene a timeline gives\n"
    "at --time / --frame. Flags below override what the timeline says.\n"
    "The extension of each -o picks the format:\n"
    "  .exr  linear scene-referred half RGBA + float Z (distance along the view\n"
    "        ray, metres; sky = 1e10), ZIP compressed; with --passes, layers\n"
    "        named as Blender names them\n"
    "  .png  tonemapped (exposure, ACES fit, sRGB; or an OpenColorIO view)\n"
    "        8-bit RGB, dithered\n"
    "Files are written atomically: a failed run never leaves a partial file.\n"
    "On a terminal a frame that takes over a second shows how much of it is\n"
    "drawn (a `reference` frame takes minutes on a CPU renderer).\n"
    "\n"
    "Options:\n"
    "  -o, --output FILE      output file (repeat for several formats)\n"
    "  --time T               time since the start: 2.5, 2.5s, 1500ms, 60f (default 0)\n"
    "  --frame N              the timeline's frame N (time N / fps); outside the\n"
    "                         timeline it renders the keys' ends, with a warning\n"
    "  --size WxH             image size, each side 1..16384 (default 1280x720)\n"
    "  --camera X,Y,Z         camera position in metres (default 0,1.5,0;\n"
    "                         +Y up, +Z north, +X east, water at y = 0)\n"
    "  --yaw DEG              heading: 0 looks along +Z, 90 along +X (default 0)\n"
    "  --pitch DEG            up/down, positive looks up (default -6)\n"
    "  --roll DEG             roll about the view direction (default 0)\n"
    "  --look-at X,Y,Z        aim the camera at a point (overrides yaw/pitch)\n"
    "  --fov DEG              vertical field of view, 0 < DEG < 180 (default 67.38)\n"
    "  --sun-elevation DEG    sun above the horizon (default 10)\n"
    "  --sun-azimuth DEG      sun compass direction (default -7.6)\n"
    "  --exposure E|auto      linear exposure before tonemapping (default 2; replaces\n"
    "                         render.exposure and turns the meter off), or auto: the\n"
    "                         metered exposure (render.exposure auto)\n"
    "  --ev STOPS             exposure compensation, -20..20: +1 halves the light\n"
    "                         (replaces render.ev); the display multiplies the light\n"
    "                         by exposure x 2^-ev before the tonemap (EXR: untouched)\n"
    "  --quality PRESET       draft, preview, final (default), reference, seed\n"
    "  --spp N                stratified samples per pixel (1..1024; default: the preset's)\n"
    "  --shader-dir DIR       load shaders from DIR instead of the built-in copies\n"
    "  --dither on|off        8-bit PNG: dither to the code below or above so smooth\n"
    "                         skies do not band (default on; off rounds)\n" TL_CLI_COLOR_USAGE
    "  --passes LIST          .exr: compositing passes as layers named as Blender\n"
    "                         names them (combined, depth, normal, position, mask_water,\n"
    "                         mask_foam, mask_giant, mask_boat, mask_sky, mask_underwater,\n"
    "                         cryptomatte, vector, light_sky, light_reflection,\n"
    "                         light_body, light_glitter, light_foam, light_spray,\n"
    "                         light_boat, light_glare, cryptomatte_material; masks,\n"
    "                         lights, all; none); each light layer but the glare\n"
    "                         draws the frame again; overrides the timeline's\n"
    "                         `passes` line (docs/compositing.md)\n"
    "  -v, --verbose          log the GL platform, renderer and timings\n"
    "  -h, --help             show this help\n"
    "Angles accept a 'rad' suffix for radians.\n";

/* What the flags say; each has_ flag marks a value that overrides the
 * timeline (or the defaults). */
typedef struct still_options {
    const char *timeline;
    const char *time_text;
    long frame;
    int has_frame;
    tl_scene values; /* holds the flag values; only fields with has_ set count */
    int has_size, has_camera, has_yaw, has_pitch, has_roll, has_fov, has_sun_elevation,
        has_sun_azimuth, has_exposure, has_ev, has_quality;
    const char *outputs[MAX_OUTPUTS];
    int output_count;
    double look_at[3];
    int has_look_at;
    const char *shader_dir;
    int verbose;
    int spp;         /* 0: the preset's */
    int dither;      /* 8-bit PNGs dithered (default) */
    unsigned passes; /* --passes, or the timeline's `passes` line (TL_PASSES_*) */
    int has_passes;
    /* Kept from the timeline for the EXR: its objects' names and fps. */
    char object_names[TL_OBJECT_MAX][TL_OBJECT_NAME_MAX];
    /* their materials (tl_crypto_material_name), as long as a model's path */
    char object_models[TL_OBJECT_MAX][sizeof(((tl_object *)0)->model)];
    int objects;
    double fps;
    /* The Vector pass: the scenes a frame before and after. */
    tl_scene prev, next;
    int has_prev, has_next;
    tl_cli_color color; /* --working-space, --ocio, --display, --view */
    int timeline_space; /* the timeline's `working_space` */
    int exposure_auto;  /* --exposure auto */
    /* The timeline (or the defaults' when none is given), kept for the
     * auto exposure's meters; freed by tl_cli_still. */
    tl_timeline tl;
    int have_tl;
    double time;
} still_options;

static int parse(int argc, char **argv, still_options *o, int *help, tl_error *err)
{
    tl_args a;
    tl_args_init(&a, argc, argv);
    a.index = 1;
    tl_scene *s = &o->values;
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
        } else if (tl_args_match(&a, "--verbose", "-v", false, err)) {
            o->verbose = 1;
        } else if (tl_args_match(&a, "--output", "-o", true, err)) {
            if (!a.value)
                return TL_ERR_USAGE;
            if (o->output_count == MAX_OUTPUTS)
                return tl_error_set(err, TL_ERR_USAGE, "at most %d outputs", MAX_OUTPUTS);
            o->outputs[o->output_count++] = a.value;
        } else if (tl_args_match(&a, "--time", NULL, true, err)) {
            o->time_text = a.value;
            rc = a.value ? TL_OK : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--frame", NULL, true, err)) {
            double f = 0.0;
            rc = a.value ? tl_args_double(a.flag, a.value, &f, err) : TL_ERR_USAGE;
            if (!rc && (f < 0.0 || f != floor(f) || f > 1e12))
                rc =
                    tl_error_set(err, TL_ERR_USAGE, "--frame: '%s' is not a frame number", a.value);
            o->frame = (long)f;
            o->has_frame = 1;
        } else if (tl_args_match(&a, "--size", NULL, true, err)) {
            rc = a.value ? tl_args_size(a.flag, a.value, &s->width, &s->height, err) : TL_ERR_USAGE;
            o->has_size = 1;
        } else if (tl_args_match(&a, "--camera", NULL, true, err)) {
            rc = a.value ? tl_args_vec3(a.flag, a.value, s->camera.position, err) : TL_ERR_USAGE;
            o->has_camera = 1;
        } else if (tl_args_match(&a, "--look-at", NULL, true, err)) {
            rc = a.value ? tl_args_vec3(a.flag, a.value, o->look_at, err) : TL_ERR_USAGE;
            o->has_look_at = 1;
        } else if (tl_args_match(&a, "--yaw", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.yaw, err) : TL_ERR_USAGE;
            o->has_yaw = 1;
        } else if (tl_args_match(&a, "--pitch", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.pitch, err) : TL_ERR_USAGE;
            o->has_pitch = 1;
        } else if (tl_args_match(&a, "--roll", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.roll, err) : TL_ERR_USAGE;
            o->has_roll = 1;
        } else if (tl_args_match(&a, "--fov", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.vfov, err) : TL_ERR_USAGE;
            if (!rc && !(s->camera.vfov > 0.0 && s->camera.vfov < M_PI))
                rc = tl_error_set(err, TL_ERR_USAGE, "--fov: '%s' is outside (0, 180) degrees",
                                  a.value);
            o->has_fov = 1;
        } else if (tl_args_match(&a, "--sun-elevation", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->sun.elevation, err) : TL_ERR_USAGE;
            if (!rc && fabs(s->sun.elevation) > M_PI / 2)
                rc = tl_error_set(err, TL_ERR_USAGE,
                                  "--sun-elevation: '%s' is outside -90..90 degrees", a.value);
            o->has_sun_elevation = 1;
        } else if (tl_args_match(&a, "--sun-azimuth", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->sun.azimuth, err) : TL_ERR_USAGE;
            o->has_sun_azimuth = 1;
        } else if (tl_args_match(&a, "--exposure", NULL, true, err)) {
            /* The last one counts: a number, or `auto` (the meter's). */
            o->exposure_auto = a.value && strcmp(a.value, "auto") == 0;
            o->has_exposure = !o->exposure_auto;
            if (!o->exposure_auto) {
                rc = a.value ? tl_args_double(a.flag, a.value, &s->exposure, err) : TL_ERR_USAGE;
                if (!rc && s->exposure < 0.0)
                    rc = tl_error_set(err, TL_ERR_USAGE, "--exposure: '%s' is negative", a.value);
            }
        } else if (tl_args_match(&a, "--ev", NULL, true, err)) {
            rc = a.value ? tl_args_double(a.flag, a.value, &s->ev, err) : TL_ERR_USAGE;
            if (!rc && !(fabs(s->ev) <= 20.0))
                rc =
                    tl_error_set(err, TL_ERR_USAGE, "--ev: '%s' is outside -20..20 stops", a.value);
            o->has_ev = 1;
        } else if (tl_args_match(&a, "--quality", NULL, true, err)) {
            rc = a.value ? tl_quality_preset(a.value, &s->quality, err) : TL_ERR_USAGE;
            if (rc && a.value)
                tl_error_prefix(err, "--quality");
            o->has_quality = 1;
        } else if (tl_args_match(&a, "--spp", NULL, true, err)) {
            rc = a.value ? tl_args_int_range(a.flag, a.value, 1, TL_MAX_SPP, &o->spp, err)
                         : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--shader-dir", NULL, true, err)) {
            o->shader_dir = a.value;
            rc = a.value ? TL_OK : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--dither", NULL, true, err)) {
            rc = a.value ? tl_args_on_off(a.flag, a.value, &o->dither, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--passes", NULL, true, err)) {
            rc = a.value ? tl_cli_passes(a.flag, a.value, &o->passes, err) : TL_ERR_USAGE;
            o->has_passes = 1;
        } else if (!o->timeline && tl_args_positional(&a, &pos)) {
            o->timeline = pos;
        } else {
            return tl_args_unknown(&a, "still", err);
        }
        if (rc)
            return rc;
    }
    if (o->output_count == 0)
        return tl_error_set(err, TL_ERR_USAGE, "no output file: give -o FILE.exr or -o FILE.png");
    if (o->time_text && o->has_frame)
        return tl_error_set(err, TL_ERR_USAGE, "give --time or --frame, not both");
    int exr = 0;
    for (int i = 0; i < o->output_count; i++)
        exr |= tl_image_format_from_path(o->outputs[i]) == TL_IMAGE_EXR;
    if (o->has_passes && o->passes && !exr)
        return tl_error_set(err, TL_ERR_USAGE,
                            "--passes: the passes are layers of an EXR; give -o FILE.exr");
    if (o->has_frame && !o->timeline)
        return tl_error_set(err, TL_ERR_USAGE, "--frame needs a timeline file");
    return TL_OK;
}

/* The flags' values over a scene (all but --look-at, which can fail). */
static void apply_flags(const still_options *o, tl_scene *scene)
{
    const tl_scene *v = &o->values;
    if (o->has_size) {
        scene->width = v->width;
        scene->height = v->height;
    }
    if (o->has_camera)
        memcpy(scene->camera.position, v->camera.position, sizeof v->camera.position);
    if (o->has_yaw)
        scene->camera.yaw = v->camera.yaw;
    if (o->has_pitch)
        scene->camera.pitch = v->camera.pitch;
    if (o->has_roll)
        scene->camera.roll = v->camera.roll;
    if (o->has_fov)
        scene->camera.vfov = v->camera.vfov;
    if (o->has_sun_elevation)
        scene->sun.elevation = v->sun.elevation;
    if (o->has_sun_azimuth)
        scene->sun.azimuth = v->sun.azimuth;
    if (o->has_exposure) { /* a fixed exposure: the meter is off */
        scene->exposure = v->exposure;
        scene->auto_exposure = 0.0;
    }
    if (o->exposure_auto)
        scene->auto_exposure = 1.0;
    if (o->has_ev)
        scene->ev = v->ev;
    if (o->has_quality)
        scene->quality = v->quality;
    if (o->spp)
        scene->quality.spp = o->spp;
}

/* The scene to render: the timeline's at the requested time (or the
 * defaults), then every flag the user gave on top. */
static int build_scene(still_options *o, tl_scene *scene, tl_models *models, tl_error *err)
{
    double fps = 24.0, t = 0.0;
    tl_timeline tl;
    int have_timeline = 0;
    if (o->timeline) {
        if (tl_cli_load_timeline("still", o->timeline, &tl, models))
            return -1; /* diagnostics already printed */
        have_timeline = 1;
        o->have_tl = 1;
        fps = tl.fps;
        if (!o->has_passes)
            o->passes = tl.passes;
        o->timeline_space = tl.working_space;
        for (int k = 0; k < tl.object_count && k < TL_OBJECT_MAX; k++) {
            snprintf(o->object_names[k], sizeof o->object_names[k], "%s", tl.objects[k].name);
            snprintf(o->object_models[k], sizeof o->object_models[k], "%s",
                     tl_crypto_material_name(tl.objects[k].model));
        }
        o->objects = tl.object_count;
    } else {
        snprintf(o->object_names[0], sizeof o->object_names[0], "boat");
        snprintf(o->object_models[0], sizeof o->object_models[0], "%s",
                 tl_crypto_material_name(""));
        o->objects = 1;
    }
    o->fps = have_timeline ? fps : 0.0;
    int rc = TL_OK;
    if (o->time_text && tl_parse_time_text(o->time_text, fps, &t, err)) {
        tl_error_prefix(err, "--time");
        rc = TL_ERR_USAGE;
    }
    if (!rc && o->has_frame)
        t = tl_timeline_frame_time(&tl, o->frame);
    char frame[32];
    snprintf(frame, sizeof frame, "%ld", o->frame);
    if (!rc && have_timeline && (o->has_frame || o->time_text))
        tl_cli_warn_outside("still", o->has_frame ? "--frame" : "--time",
                            o->has_frame ? frame : o->time_text, &tl, t);
    if (!rc) {
        if (have_timeline)
            tl_timeline_eval(&tl, t, scene);
        else
            tl_scene_defaults(scene);
        scene->time = t;
    }
    if (rc) {
        if (have_timeline)
            tl_timeline_free(&tl);
        o->have_tl = 0;
        return rc;
    }

    apply_flags(o, scene);
    if (!rc && o->has_look_at)
        rc = tl_scene_camera_look_at(&scene->camera, o->look_at, err);
    /* The Vector pass: the scenes a frame before and after (none across a
     * cut), with the same flags. */
    o->has_prev = o->has_next = 0;
    if (!rc && (o->passes & TL_PASSES_VECTOR)) {
        for (int k = 0; k < 2; k++) {
            double tk = t + (k ? 1.0 : -1.0) / fps;
            tl_scene *to = k ? &o->next : &o->prev;
            if (have_timeline && tl_timeline_has_cut_between(&tl, k ? t : tk, k ? tk : t))
                continue;
            if (have_timeline)
                tl_timeline_eval(&tl, tk, to);
            else
                tl_scene_defaults(to);
            to->time = tk;
            apply_flags(o, to);
            if (o->has_look_at && tl_scene_camera_look_at(&to->camera, o->look_at, err))
                continue;
            *(k ? &o->has_next : &o->has_prev) = 1;
        }
    }
    o->time = t;
    if (have_timeline)
        o->tl = tl;                             /* the meters' (tl_cli_still frees it) */
    else if (!rc && scene->auto_exposure > 0.0) /* --exposure auto over the defaults */
        o->have_tl = (rc = tl_timeline_init(&o->tl, err)) == TL_OK;
    return rc ? rc : tl_scene_validate(scene, err);
}

int tl_cli_still(int argc, char **argv)
{
    tl_error err;
    tl_error_clear(&err);
    still_options o = {0};
    o.dither = 1;
    tl_scene_defaults(&o.values);
    int help = 0;
    int rc = parse(argc, argv, &o, &help, &err);
    if (help) {
        fputs(usage, stdout);
        return 0;
    }
    tl_scene scene;
    tl_models models = {0};
    if (!rc) {
        rc = build_scene(&o, &scene, &models, &err);
        if (rc < 0)
            return 1; /* the timeline's diagnostics were printed */
    }
    /* Check every output before rendering: a bad path costs nothing. Every
     * name's format first, then the folders are made (as render does). */
    for (int i = 0; !rc && i < o.output_count; i++)
        if (tl_image_format_from_path(o.outputs[i]) == TL_IMAGE_UNKNOWN &&
            tl_image_check_writable(o.outputs[i], &err))
            rc = TL_ERR_USAGE;
    for (int i = 0; !rc && i < o.output_count; i++)
        if (tl_cli_make_parent_dirs(o.outputs[i], &err) ||
            tl_image_check_writable(o.outputs[i], &err))
            rc = TL_ERR_USAGE;
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    if (!rc && o.shader_dir && (rc = tl_shader_lib_from_dir(&lib, o.shader_dir, &err)))
        tl_error_prefix(&err, "--shader-dir");
    int shows = 0; /* a PNG among the outputs */
    for (int i = 0; i < o.output_count; i++)
        shows |= tl_image_format_from_path(o.outputs[i]) == TL_IMAGE_PNG;
    if (!rc)
        rc = tl_cli_color_prepare(&o.color, o.timeline_space, shows, &err);
    if (rc) {
        tl_cli_color_free(&o.color);
        tl_cli_print_error("still", &err);
        tl_models_free(&models);
        if (o.have_tl)
            tl_timeline_free(&o.tl);
        return rc == TL_ERR_RUNTIME ? 1 : 2;
    }

    double t0 = tl_clock_seconds();
    tl_render *render = NULL;
    tl_frame frame = {0};
    rc = tl_render_open(&render, &lib, &err);
    if (!rc && models.count)
        rc = tl_render_set_models(render, &models, &err);
    tl_models_free(&models);
    if (!rc)
        rc = tl_cli_color_use(&o.color, render, &err);
    if (!rc && o.verbose)
        fprintf(stderr, "tideline still: %s\n", tl_render_describe(render));
    double t1 = tl_clock_seconds();
    still_progress progress = {t1, 0.0, tl_cli_progress_delay(), 0};
    if (!rc && isatty(STDERR_FILENO))
        tl_render_set_progress(render, still_progress_update, &progress);
    const unsigned planes = TL_PLANES_ALL | (tl_passes_need_aov(o.passes) ? TL_PLANE_AOV : 0u);
    /* Auto exposure meters the timeline's scene; from a camera the flags
     * moved, with that camera. */
    const int moved =
        o.has_camera || o.has_yaw || o.has_pitch || o.has_roll || o.has_fov || o.has_look_at;
    if (!rc && o.have_tl)
        rc = tl_render_meter_exposure(render, &o.tl, o.time, moved ? &scene.camera : NULL, NULL,
                                      &scene, &err);
    if (!rc)
        rc = tl_render_frame_layers(render, &scene, planes, tl_passes_light_layers(o.passes),
                                    &frame, &err);
    if (progress.shown)
        fputc('\n', stderr);
    double t2 = tl_clock_seconds();
    if (!rc && o.verbose) {
        char features[256];
        tl_feature_describe(tl_render_last_features(render), features, sizeof features);
        fprintf(stderr, "tideline still: %dx%d in %.1f ms (context and shaders %.1f ms)\n",
                scene.width, scene.height, (t2 - t1) * 1e3, (t1 - t0) * 1e3);
        fprintf(stderr, "tideline still: features: %s\n", features);
        fprintf(stderr, "tideline still: display: %s\n", tl_cli_color_describe(&o.color));
    }

    const tl_camera *cam = &scene.camera;
    char camera_text[256];
    snprintf(camera_text, sizeof camera_text,
             "position %.17g %.17g %.17g yaw %.17g pitch %.17g roll %.17g vfov %.17g (radians)",
             cam->position[0], cam->position[1], cam->position[2], cam->yaw, cam->pitch, cam->roll,
             cam->vfov);
    tl_meta meta[4 + TL_RUN_QUALITY_META] = {
        {"tideline/version", TL_META_STRING, TL_VERSION, 0, 0, NULL},
        {"tideline/time", TL_META_DOUBLE, NULL, scene.time, 0, NULL},
        {"tideline/timeline", TL_META_STRING, o.timeline ? o.timeline : "", 0, 0, NULL},
        {"tideline/camera", TL_META_STRING, camera_text, 0, 0, NULL},
    };
    tl_image_options opt = {.no_dither = !o.dither,
                            .meta = meta,
                            .meta_count = 4 + tl_run_quality_meta(&scene.quality, meta + 4)};
    const char *object[TL_OBJECT_MAX], *model[TL_OBJECT_MAX];
    for (int k = 0; k < o.objects; k++) {
        object[k] = o.object_names[k];
        model[k] = o.object_models[k];
    }
    const tl_passes_frame info = {o.passes,
                                  &scene.camera,
                                  object,
                                  o.objects,
                                  o.fps,
                                  &scene,
                                  o.has_prev ? &o.prev : NULL,
                                  o.has_next ? &o.next : NULL,
                                  o.color.space,
                                  o.color.convert ? o.color.matrix : NULL,
                                  model};
    for (int i = 0; !rc && i < o.output_count; i++) {
        rc = tl_image_format_from_path(o.outputs[i]) == TL_IMAGE_EXR
                 ? tl_passes_write_frame(o.outputs[i], &frame, &info, &opt, &err)
                 : tl_image_write(o.outputs[i], &frame, &opt, &err);
        if (!rc && o.verbose)
            fprintf(stderr, "tideline still: wrote %s\n", o.outputs[i]);
    }
    tl_frame_free(&frame);
    tl_render_close(render);
    tl_cli_color_free(&o.color);
    if (o.have_tl)
        tl_timeline_free(&o.tl);
    if (rc) {
        tl_cli_print_error("still", &err);
        return rc == TL_ERR_USAGE ? 2 : 1;
    }
    return 0;
}
