/* tideline still: render one frame of the default ocean (or, with flags,
 * any camera, sun, time and quality) to EXR and/or PNG files. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "cli/tl_args.h"
#include "cli/tl_cli.h"
#include "image/tl_image_io.h"
#include "render/tl_render.h"
#include "scene/tl_scene.h"

#define MAX_OUTPUTS 8

static const char usage[] =
    "Usage: tideline still [options] -o FILE [-o FILE...]\n"
    "\n"
    "Render one frame headless. The extension of each -o picks the format:\n"
    "  .exr  linear scene-referred half RGBA + float Z (distance along the view\n"
    "        ray, metres; sky = 1e10), ZIP compressed\n"
    "  .png  tonemapped (exposure, ACES, sRGB) 8-bit RGB\n"
    "Files are written atomically: a failed run never leaves a partial file.\n"
    "\n"
    "Options:\n"
    "  -o, --output FILE      output file (repeat for several formats)\n"
    "  --time T               seconds since the start (default 0)\n"
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
    "  --exposure E           linear exposure before tonemapping (default 2)\n"
    "  --quality PRESET       draft, preview, final (default), reference, seed\n"
    "  --shader-dir DIR       load shaders from DIR instead of the built-in copies\n"
    "  -v, --verbose          log the GL platform, renderer and timings\n"
    "  -h, --help             show this help\n"
    "Angles accept a 'rad' suffix for radians.\n";

typedef struct still_options {
    tl_scene scene;
    const char *outputs[MAX_OUTPUTS];
    int output_count;
    double look_at[3];
    int has_look_at;
    const char *shader_dir;
    int verbose;
} still_options;

static int parse(int argc, char **argv, still_options *o, int *help, tl_error *err)
{
    tl_args a;
    tl_args_init(&a, argc, argv);
    a.index = 1;
    tl_scene *s = &o->scene;
    while (!tl_args_done(&a)) {
        int rc = TL_OK;
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
            rc = a.value ? tl_args_double(a.flag, a.value, &s->time, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--size", NULL, true, err)) {
            rc = a.value ? tl_args_size(a.flag, a.value, &s->width, &s->height, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--camera", NULL, true, err)) {
            rc = a.value ? tl_args_vec3(a.flag, a.value, s->camera.position, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--look-at", NULL, true, err)) {
            rc = a.value ? tl_args_vec3(a.flag, a.value, o->look_at, err) : TL_ERR_USAGE;
            o->has_look_at = 1;
        } else if (tl_args_match(&a, "--yaw", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.yaw, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--pitch", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.pitch, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--roll", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.roll, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--fov", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->camera.vfov, err) : TL_ERR_USAGE;
            if (!rc && !(s->camera.vfov > 0.0 && s->camera.vfov < M_PI))
                rc = tl_error_set(err, TL_ERR_USAGE, "--fov: '%s' is outside (0, 180) degrees",
                                  a.value);
        } else if (tl_args_match(&a, "--sun-elevation", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->sun.elevation, err) : TL_ERR_USAGE;
            if (!rc && fabs(s->sun.elevation) > M_PI / 2)
                rc = tl_error_set(err, TL_ERR_USAGE,
                                  "--sun-elevation: '%s' is outside -90..90 degrees", a.value);
        } else if (tl_args_match(&a, "--sun-azimuth", NULL, true, err)) {
            rc = a.value ? tl_args_angle(a.flag, a.value, &s->sun.azimuth, err) : TL_ERR_USAGE;
        } else if (tl_args_match(&a, "--exposure", NULL, true, err)) {
            rc = a.value ? tl_args_double(a.flag, a.value, &s->exposure, err) : TL_ERR_USAGE;
            if (!rc && s->exposure < 0.0)
                rc = tl_error_set(err, TL_ERR_USAGE, "--exposure: '%s' is negative", a.value);
        } else if (tl_args_match(&a, "--quality", NULL, true, err)) {
            rc = a.value ? tl_quality_preset(a.value, &s->quality, err) : TL_ERR_USAGE;
            if (rc)
                tl_error_prefix(err, "--quality");
        } else if (tl_args_match(&a, "--shader-dir", NULL, true, err)) {
            o->shader_dir = a.value;
            rc = a.value ? TL_OK : TL_ERR_USAGE;
        } else {
            return tl_args_unknown(&a, "still", err);
        }
        if (rc)
            return rc;
    }
    if (o->output_count == 0)
        return tl_error_set(err, TL_ERR_USAGE, "no output file: give -o FILE.exr or -o FILE.png");
    return TL_OK;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

int tl_cli_still(int argc, char **argv)
{
    tl_error err;
    tl_error_clear(&err);
    still_options o = {0};
    tl_scene_defaults(&o.scene);
    int help = 0;
    int rc = parse(argc, argv, &o, &help, &err);
    if (help) {
        fputs(usage, stdout);
        return 0;
    }
    if (!rc && o.has_look_at)
        rc = tl_scene_camera_look_at(&o.scene.camera, o.look_at, &err);
    if (!rc)
        rc = tl_scene_validate(&o.scene, &err);
    /* Check every output before rendering: a bad path costs nothing. */
    for (int i = 0; !rc && i < o.output_count; i++)
        if (tl_image_check_writable(o.outputs[i], &err))
            rc = TL_ERR_USAGE;
    tl_shader_lib lib;
    tl_shader_lib_embedded(&lib);
    if (!rc && o.shader_dir)
        rc = tl_shader_lib_from_dir(&lib, o.shader_dir, &err);
    if (rc) {
        tl_cli_print_error("still", &err);
        return rc == TL_ERR_RUNTIME ? 1 : 2;
    }

    double t0 = now_seconds();
    tl_render *render = NULL;
    tl_frame frame = {0};
    rc = tl_render_open(&render, &lib, &err);
    if (!rc && o.verbose)
        fprintf(stderr, "tideline still: %s\n", tl_render_describe(render));
    double t1 = now_seconds();
    if (!rc)
        rc = tl_render_frame(render, &o.scene, &frame, &err);
    double t2 = now_seconds();
    if (!rc && o.verbose)
        fprintf(stderr, "tideline still: %dx%d in %.1f ms (context and shaders %.1f ms)\n",
                o.scene.width, o.scene.height, (t2 - t1) * 1e3, (t1 - t0) * 1e3);

    const tl_camera *cam = &o.scene.camera;
    char camera_text[256];
    snprintf(camera_text, sizeof camera_text,
             "position %.17g %.17g %.17g yaw %.17g pitch %.17g roll %.17g vfov %.17g (radians)",
             cam->position[0], cam->position[1], cam->position[2], cam->yaw, cam->pitch, cam->roll,
             cam->vfov);
    const tl_meta meta[] = {
        {"tideline/version", TL_META_STRING, TL_VERSION, 0, 0},
        {"tideline/time", TL_META_DOUBLE, NULL, o.scene.time, 0},
        {"tideline/camera", TL_META_STRING, camera_text, 0, 0},
        {"tideline/quality", TL_META_STRING, o.scene.quality.name, 0, 0},
    };
    tl_image_options opt = {0, meta, (int)(sizeof meta / sizeof meta[0])};
    for (int i = 0; !rc && i < o.output_count; i++) {
        rc = tl_image_write(o.outputs[i], &frame, &opt, &err);
        if (!rc && o.verbose)
            fprintf(stderr, "tideline still: wrote %s\n", o.outputs[i]);
    }
    tl_frame_free(&frame);
    tl_render_close(render);
    if (rc) {
        tl_cli_print_error("still", &err);
        return rc == TL_ERR_USAGE ? 2 : 1;
    }
    return 0;
}
