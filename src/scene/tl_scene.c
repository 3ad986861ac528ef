#include "tl_scene.h"

#include <math.h>

#include "core/tl_math.h"

void tl_scene_defaults(tl_scene *s)
{
    *s = (tl_scene){0};
    s->time = 0.0;
    s->width = 1280;
    s->height = 720;
    s->exposure = 2.0;
    s->adapt_time = 1.0;
    s->ev = 0.0;
    s->bloom = 0.02;
    s->white_point[0] = s->white_point[1] = s->white_point[2] = 1.0;
    s->white_depth = 0.0;

    s->camera.position[0] = 0.0;
    s->camera.position[1] = 1.5;
    s->camera.position[2] = 0.0;
    s->camera.yaw = 0.0;
    s->camera.pitch = -6.0 * TL_DEG;
    s->camera.roll = 0.0;
    /* The reference shader's projection: image plane at 1.5, half height 1. */
    s->camera.vfov = 2.0 * atan(1.0 / 1.5);
    /* Blender's defaults: no rotation, axis +Y, a 36 x 24 mm sensor. */
    s->rig = (tl_camera_rig){.rotation_mode = TL_ROTATION_YAW_PITCH_ROLL,
                             .quat_w = 1.0,
                             .axis = {0.0, 1.0, 0.0},
                             .sensor_width = 36.0,
                             .sensor_height = 24.0,
                             .sensor_fit = TL_SENSOR_AUTO};

    s->sun.elevation = 10.0 * TL_DEG;
    s->sun.azimuth = -7.6 * TL_DEG;
    s->sun.intensity = 210.0;
    s->sun.sharpness = 720.0;
    s->sun.angular_diameter = 0.53 * TL_DEG;

    s->ocean.depth = 1.0;
    s->ocean.drag = 0.38;
    s->ocean.frequency = 1.0;
    s->ocean.frequency_growth = 1.18;
    s->ocean.speed = 2.0;
    s->ocean.speed_growth = 1.07;
    s->ocean.weight_ratio = 0.8;
    s->ocean.direction_step = 1232.399963;
    s->ocean.radial_phase = 0.1;

    s->water.fresnel_f0 = 0.04;
    s->water.scatter_color[0] = 0.0293;
    s->water.scatter_color[1] = 0.0698;
    s->water.scatter_color[2] = 0.1717;
    s->water.scatter_strength = 0.1;
    s->water.scatter_base = 0.2;
    s->water.normal_smooth_max = 0.8;
    s->water.normal_smooth_rate = 0.01;
    s->water.normal_smooth_gain = 1.1;

    s->water.absorption[0] = 0.34; /* Pope & Fry 1997: 650, 550, 450 nm */
    s->water.absorption[1] = 0.057;
    s->water.absorption[2] = 0.009;
    s->water.scattering = 0.03;
    /* Cox and Munk's sun glitter: a slick, which damps the capillary
     * ripples, takes about half the mean square slope off a clean sea in a
     * light breeze; the waves' octaves stop at a few centimetres, so about
     * half as much again as theirs is left to the ripples. */
    s->water.capillaries = 0.5;
    s->water.color_at_distance[0] = 0.3;
    s->water.color_at_distance[1] = 0.7;
    s->water.color_at_distance[2] = 0.8;
    s->water.color_distance = 0.0; /* off: absorption + scattering */
    s->water.ior = 1.333;
    s->water.foam = 1.0; /* scales every foam term (today: the giant wave's) */

    s->sky.model = TL_SKY_PHYSICAL;
    s->sky.brightness = 0.5;
    s->sky.sun_illuminance = 8.0;
    s->sky.turbidity = 1.0;
    s->sky.ozone = 1.0;
    s->sky.ground_albedo = 0.1;
    s->sky.planet_radius = 6360.0;
    s->sky.atmosphere_height = 100.0;

    s->fog.density = 0.0;
    s->fog.color[0] = 0.55;
    s->fog.color[1] = 0.65;
    s->fog.color[2] = 0.75;
    s->fog.height = 100.0;
    s->underwater.mode = TL_UNDERWATER_AUTO;
    s->underwater.caustics = 1.0;
    s->underwater.shafts = 1.0;
    s->underwater.particles = 0.0;
    s->ocean.floor_depth = 0.0;

    s->giant.enabled = false;
    s->giant.height = 12.0;
    s->giant.width = 120.0;
    s->giant.wavelength = 80.0;
    s->giant.angle = 0.0;
    s->giant.falloff = 30.0;
    s->giant.phase = 0.0;
    s->giant.arrival = 0.0;
    s->giant.speed = 1.0;
    s->giant.steepness = 0.6;
    s->giant.curve_strength = 0.3;
    s->giant.fade = 1.0;
    s->giant.peak = 0.0;
    s->giant.taper = 0.45;
    s->giant.bow = 10.0;
    s->giant.variation = 0.12;
    s->giant.seed = 1;
    s->giant.breaking = false;
    s->giant.break_time = 0.0;
    s->giant.peel_speed = 8.0;
    s->giant.break_drop = 0.3;
    s->giant.spray = 1.0;
    s->giant.spray_wind = 8.0;
    s->giant.ride = 1.0;
    s->giant.foam_compression = 0.35;
    s->giant.foam_trail = 40.0;
    s->giant.scatter = 1.0;
    s->giant.scatter_forward = 0.6;
    s->giant.scatter_back = 0.3;
    s->giant.caustics = 0.4;
    s->giant.scatter_color[0] = 0.1; /* sea green: red is absorbed in the crest */
    s->giant.scatter_color[1] = 0.5;
    s->giant.scatter_color[2] = 0.45;

    s->boat.enabled = false;
    s->boat.visible = true;
    s->boat.size = 8.0;
    s->boat.model_yaw = 0.0;
    s->boat.model_scale = 1.0;
    s->boat.float_time = 0.3;
    s->boat.wake = 1.0;
    s->boat.wake_time = 6.0;
    s->boat.lights = 0.0;
    s->boat.spray = 1.0;
    s->boat.shadows = true;
    s->boat.scale = 8.0;
    const double lo[3] = TL_BOAT_BUILTIN_MIN, hi[3] = TL_BOAT_BUILTIN_MAX;
    for (int i = 0; i < 3; i++) {
        s->boat.model_min[i] = lo[i];
        s->boat.model_max[i] = hi[i];
    }
    s->boat.length = 8.0;
    s->boat.beam = 8.0 * TL_BOAT_BEAM_RATIO;
    const double paint[3] = TL_BOAT_PAINT, cabin[3] = TL_BOAT_CABIN_PAINT;
    for (int i = 0; i < 3; i++) {
        s->boat.paint[i] = paint[i];
        s->boat.cabin_paint[i] = cabin[i];
    }
    for (int k = 0; k < TL_OBJECT_MAX - 1; k++)
        s->fleet[k] = s->boat;
    s->objects = 1;
    s->quality = tl_quality_default();
}

void tl_scene_sun_direction(const tl_sun *sun, double out[3])
{
    double ce = cos(sun->elevation);
    out[0] = ce * sin(sun->azimuth);
    out[1] = sin(sun->elevation);
    out[2] = ce * cos(sun->azimuth);
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void tl_scene_camera_basis(const tl_camera *cam, double right[3], double up[3], double forward[3])
{
    double cp = cos(cam->pitch);
    forward[0] = cp * sin(cam->yaw);
    forward[1] = sin(cam->pitch);
    forward[2] = cp * cos(cam->yaw);
    /* Right is horizontal and never degenerate, even looking straight down:
     * it depends on yaw alone. */
    double r0[3] = {cos(cam->yaw), 0.0, -sin(cam->yaw)};
    double u0[3];
    cross3(forward, r0, u0);
    double cr = cos(cam->roll), sr = sin(cam->roll);
    for (int i = 0; i < 3; i++) {
        right[i] = cr * r0[i] + sr * u0[i];
        up[i] = cr * u0[i] - sr * r0[i];
    }
}

int tl_scene_camera_look_at(tl_camera *cam, const double target[3], tl_error *err)
{
    double d[3] = {target[0] - cam->position[0], target[1] - cam->position[1],
                   target[2] - cam->position[2]};
    double horiz = hypot(d[0], d[2]);
    double len = hypot(horiz, d[1]);
    if (!(len > 1e-9))
        return tl_error_set(err, TL_ERR_USAGE, "look-at target coincides with the camera");
    /* Straight up or down: keep the current yaw so the image does not spin. */
    if (horiz > 1e-12 * len)
        cam->yaw = atan2(d[0], d[2]);
    cam->pitch = atan2(d[1], horiz);
    return TL_OK;
}

static int finite_all(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

int tl_scene_validate(const tl_scene *s, tl_error *err)
{
    if (s->width < 1 || s->height < 1 || s->width > 16384 || s->height > 16384)
        return tl_error_set(err, TL_ERR_USAGE, "size %dx%d is outside 1..16384", s->width,
                            s->height);
    if (!isfinite(s->time))
        return tl_error_set(err, TL_ERR_USAGE, "time is not finite");
    if (!finite_all(s->camera.position, 3) || !isfinite(s->camera.yaw) ||
        !isfinite(s->camera.pitch) || !isfinite(s->camera.roll))
        return tl_error_set(err, TL_ERR_USAGE, "camera position/orientation is not finite");
    if (!(s->camera.vfov > 0.0 && s->camera.vfov < M_PI))
        return tl_error_set(err, TL_ERR_USAGE, "camera field of view %.6g deg is outside (0, 180)",
                            s->camera.vfov / TL_DEG);
    if (!(s->ocean.depth > 0.0) || !isfinite(s->ocean.depth))
        return tl_error_set(err, TL_ERR_USAGE, "ocean depth must be a positive number");
    if (!(s->exposure >= 0.0) || !isfinite(s->exposure))
        return tl_error_set(err, TL_ERR_USAGE, "exposure must be finite and >= 0");
    const tl_quality *q = &s->quality;
    if (q->march_octaves < 1 || q->march_octaves > TL_MAX_OCTAVES || q->normal_octaves < 1 ||
        q->normal_octaves > TL_MAX_OCTAVES)
        return tl_error_set(err, TL_ERR_USAGE, "octave counts must be in 1..%d", TL_MAX_OCTAVES);
    return TL_OK;
}
