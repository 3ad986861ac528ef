#include "tl_timeline.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tl_timeline_init(tl_timeline *tl, tl_error *err)
{
    memset(tl, 0, sizeof *tl);
    tl->version = 1;
    tl->fps = 24.0;
    tl->duration = 10.0;
    tl->width = 1280;
    tl->height = 720;
    tl->quality = tl_quality_default();
    tl->tracks = calloc((size_t)tl_channel_count(), sizeof *tl->tracks);
    if (!tl->tracks)
        return tl_error_set(err, TL_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < tl_channel_count(); i++)
        for (int c = 0; c < 3; c++)
            tl_curve_init(&tl->tracks[i].curve[c]);
    tl_path_init(&tl->camera_path.path);
    snprintf(tl->objects[0].name, sizeof tl->objects[0].name, "boat");
    tl_path_init(&tl->objects[0].path.path);
    tl->object_count = 1;
    return TL_OK;
}

static tl_track *new_tracks(void)
{
    tl_track *tracks = calloc((size_t)tl_channel_count(), sizeof *tracks);
    if (tracks)
        for (int i = 0; i < tl_channel_count(); i++)
            for (int c = 0; c < 3; c++)
                tl_curve_init(&tracks[i].curve[c]);
    return tracks;
}

static void free_tracks(tl_track *tracks)
{
    if (!tracks)
        return;
    for (int i = 0; i < tl_channel_count(); i++)
        for (int c = 0; c < 3; c++)
            tl_curve_free(&tracks[i].curve[c]);
    free(tracks);
}

int tl_timeline_add_object(tl_timeline *tl, const char *name, int line, int column)
{
    if (tl->object_count >= TL_OBJECT_MAX)
        return -1;
    tl_object *o = &tl->objects[tl->object_count];
    memset(o, 0, sizeof *o);
    o->tracks = new_tracks();
    if (!o->tracks)
        return -1;
    snprintf(o->name, sizeof o->name, "%s", name);
    o->line = line;
    o->column = column;
    tl_path_init(&o->path.path);
    return tl->object_count++;
}

int tl_timeline_object(const tl_timeline *tl, const char *name)
{
    for (int k = 0; k < tl->object_count; k++)
        if (strcmp(tl->objects[k].name, name) == 0)
            return k;
    return -1;
}

tl_track *tl_timeline_track(const tl_timeline *tl, int channel, int object)
{
    if (object > 0 && tl_channel_is_object(tl_channel_at(channel)))
        return &tl->objects[object].tracks[channel];
    return &tl->tracks[channel];
}

void tl_timeline_free(tl_timeline *tl)
{
    free_tracks(tl->tracks);
    for (int k = 0; k < tl->object_count; k++) {
        free_tracks(tl->objects[k].tracks);
        tl_path_free(&tl->objects[k].path.path);
    }
    tl_path_free(&tl->camera_path.path);
    memset(tl, 0, sizeof *tl);
}

long tl_timeline_frame_count(const tl_timeline *tl)
{
    double n = floor(tl->duration * tl->fps + 0.5);
    return n < 1.0 ? 1 : (long)n;
}

double tl_timeline_frame_time(const tl_timeline *tl, long frame)
{
    return (double)frame / tl->fps;
}

static double clampd(double v, double lo, double hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static const tl_track *track_of(const tl_timeline *tl, const char *name, int object)
{
    const tl_channel *ch = tl_channel_find(name);
    return ch ? tl_timeline_track(tl, tl_channel_index(ch), object) : NULL;
}

static void add3(double out[3], const double a[3], const double b[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = a[i] + b[i];
}

/* Where the boat was over the last 2 x wake_time, for its wake: x z and
 * the distance along its path at each of TL_WAKE_POINTS times back from t.
 * A path that starts with the timeline (its first point at or before 0 s)
 * continues back along its first velocity: a boat under way in the first
 * frame was under way before it, and its wake is already there (it grew
 * from nothing over the first seconds of every bundled cutscene). A path
 * that starts later holds still before its start, as the boat on screen
 * does, and so does its wake. */
static void boat_wake(const tl_path *path, double t, tl_boat *b)
{
    b->wake_step = 2.0 * b->wake_time / (TL_WAKE_POINTS - 1);
    const double t0 = path->count ? path->points[0].t : 0.0;
    const bool extrapolate = path->count >= 2 && t0 <= 0.0;
    double start[3] = {0.0, 0.0, 0.0}, vx = 0.0, vz = 0.0;
    if (extrapolate && t - (TL_WAKE_POINTS - 1) * b->wake_step < t0) {
        double h = 1e-3 * (path->points[1].t - t0), q[3];
        tl_path_eval(path, t0, start, NULL);
        tl_path_eval(path, t0 + h, q, NULL);
        vx = (q[0] - start[0]) / h;
        vz = (q[2] - start[2]) / h;
    }
    for (int k = 0; k < TL_WAKE_POINTS; k++) {
        double tk = t - k * b->wake_step, p[3];
        if (extrapolate && tk < t0) {
            double dt = tk - t0; /* < 0 */
            b->wake_path[k][0] = start[0] + vx * dt;
            b->wake_path[k][1] = start[2] + vz * dt;
            b->wake_along[k] = hypot(vx, vz) * dt; /* negative: before the first point */
            continue;
        }
        tl_path_eval(path, tk, p, NULL);
        b->wake_path[k][0] = p[0];
        b->wake_path[k][1] = p[2];
        b->wake_along[k] = tl_path_distance(path, tk);
    }
}

/* `follow giant.center boat` aims the wave; it does not carry it. Along
 * its travel the centre is where the boat (plus the link's offset) is at
 * giant.arrival, so the crest moves over the water at its own speed and
 * meets the boat then; across, the centre line is where the boat is now,
 * so the boat stays within the crest's width (a crest sliding along its
 * own line does not change its speed over the water). */
static void aim_giant(const tl_timeline *tl, tl_scene *s)
{
    const double *off = tl->giant_follow.offset;
    const int k = tl->giant_follow.object;
    const tl_boat *b = tl_scene_object(s, k);
    double then[3] = {b->position[0], 0.0, b->position[2]};
    if (tl->objects[k].path.present)
        tl_path_eval(&tl->objects[k].path.path, s->giant.arrival, then, NULL);
    double dir[2] = {sin(s->giant.angle), cos(s->giant.angle)};
    double now[2] = {b->position[0] + off[0], b->position[2] + off[2]};
    double at[2] = {then[0] + off[0], then[2] + off[2]};
    double along = dir[0] * at[0] + dir[1] * at[1];
    double across = dir[1] * now[0] - dir[0] * now[1];
    s->giant.center[0] = along * dir[0] + across * dir[1];
    s->giant.center[1] = along * dir[1] - across * dir[0];
}

/* Object k's size from its model's bounds (the built-in boat's until a
 * loader says otherwise), in metres. */
static void object_size(const tl_object *o, tl_boat *b)
{
    if (o->bounds_known)
        for (int i = 0; i < 3; i++) {
            b->model_min[i] = o->model_min[i];
            b->model_max[i] = o->model_max[i];
        }
    b->model = o->mesh;
    b->scale = o->model[0] ? b->model_scale : b->size;
    double ex = b->model_max[0] - b->model_min[0], ez = b->model_max[2] - b->model_min[2];
    double c = fabs(cos(b->model_yaw)), sn = fabs(sin(b->model_yaw));
    b->length = (c * ez + sn * ex) * b->scale; /* model_yaw turns the model */
    b->beam = (c * ex + sn * ez) * b->scale;
}

static bool heading_from_path(const tl_timeline *tl, int k)
{
    return track_of(tl, "boat.heading", k)->state == TL_TRACK_DEFAULT;
}

/* The scene at t; floating (the costly part) only when asked, and the
 * bow's impact (floating twice) only with it. */
static void eval_scene(const tl_timeline *tl, double t, tl_scene *s, bool float_boat, bool impact)
{
    tl_scene_defaults(s);
    s->time = t;
    s->width = tl->width;
    s->height = tl->height;
    s->quality = tl->quality;
    s->objects = tl->object_count;

    for (int i = 0; i < tl_channel_count(); i++) {
        const tl_channel *ch = tl_channel_at(i);
        int objects = tl_channel_is_object(ch) ? tl->object_count : 1;
        for (int k = 0; k < objects; k++) {
            const tl_track *tr = tl_timeline_track(tl, i, k);
            if (tr->state == TL_TRACK_DEFAULT)
                continue;
            double v[3] = {0, 0, 0};
            for (int c = 0; c < ch->components; c++) {
                double x =
                    tr->state == TL_TRACK_SET ? tr->value[c] : tl_curve_eval(&tr->curve[c], t);
                /* Clamp: overshooting eases (back, elastic) and Bezier
                 * handles may leave the range the keys respect. */
                v[c] = clampd(x, ch->min, ch->max);
            }
            tl_channel_set_object(ch, s, k, v);
        }
    }
    /* A camera given as Blender gives it: its rotation and lens. */
    tl_scene_apply_rig(&s->rig, s->width, s->height, &s->camera);

    /* Each object rides its path; the giant wave may follow one. */
    for (int k = 0; k < tl->object_count; k++) {
        const tl_object *o = &tl->objects[k];
        tl_boat *b = tl_scene_object(s, k);
        object_size(o, b);
        if (!o->path.present)
            continue;
        double p[3], tangent[3];
        tl_path_eval(&o->path.path, t, p, tangent);
        b->enabled = true;
        b->position[0] = p[0];
        b->position[2] = p[2];
        if (heading_from_path(tl, k) && (tangent[0] != 0.0 || tangent[2] != 0.0))
            b->heading = atan2(tangent[0], tangent[2]);
    }

    if (tl->camera_path.present)
        tl_path_eval(&tl->camera_path.path, t, s->camera.position, NULL);
    if (tl->giant_follow.target == TL_TARGET_BOAT)
        aim_giant(tl, s);
    for (int k = 0; k < tl->object_count; k++) {
        tl_boat *b = tl_scene_object(s, k);
        if (!b->enabled)
            continue;
        /* Where it was, for its wake: twice the fade time back. */
        boat_wake(&tl->objects[k].path.path, t, b);
        /* ... and floats on the waves, the giant one included. */
        if (float_boat)
            tl_timeline_float_boat(tl, k, t, heading_from_path(tl, k), s);
    }
    /* How fast the water rises against each bow (its spray) is the change
     * of the bow's gap to the water over TL_BOW_IMPACT_DT: the poses a
     * moment before, floated alike (a pose depends on the time alone, so
     * this does). */
    bool any = false;
    for (int k = 0; k < tl->object_count; k++)
        any |= tl_scene_object(s, k)->enabled;
    if (float_boat && impact && any) {
        tl_scene before;
        eval_scene(tl, t - TL_BOW_IMPACT_DT, &before, true, false);
        for (int k = 0; k < tl->object_count; k++)
            if (tl_scene_object(s, k)->enabled)
                tl_scene_object(s, k)->impact =
                    (tl_timeline_bow_gap(s, k) - tl_timeline_bow_gap(&before, k)) /
                    TL_BOW_IMPACT_DT;
    }
    if (tl->camera_follow.target == TL_TARGET_BOAT)
        add3(s->camera.position, tl_scene_object(s, tl->camera_follow.object)->position,
             tl->camera_follow.offset);
    /* Paths (a Catmull-Rom curve may overshoot its points) and links (boat +
     * offset) can leave a channel's range: hold every channel inside it. */
    for (int i = 0; i < tl_channel_count(); i++) {
        const tl_channel *ch = tl_channel_at(i);
        if (ch->kind != TL_CH_REAL)
            continue;
        int objects = tl_channel_is_object(ch) ? tl->object_count : 1;
        for (int k = 0; k < objects; k++) {
            double v[3];
            tl_channel_get_object(ch, s, k, v);
            for (int c = 0; c < ch->components; c++)
                v[c] = clampd(v[c], ch->min, ch->max);
            tl_channel_set_object(ch, s, k, v);
        }
    }
    if (tl->camera_look.target != TL_TARGET_NONE) {
        double target[3];
        if (tl->camera_look.target == TL_TARGET_BOAT)
            add3(target, tl_scene_object(s, tl->camera_look.object)->position,
                 tl->camera_look.offset);
        else
            memcpy(target, tl->camera_look.point, sizeof target);
        /* A target on the camera keeps the previous orientation (no flip). */
        tl_scene_camera_look_at(&s->camera, target, NULL);
    }
}

void tl_timeline_eval(const tl_timeline *tl, double t, tl_scene *s)
{
    eval_scene(tl, t, s, true, true);
}

bool tl_timeline_has_cut_between(const tl_timeline *tl, double t0, double t1)
{
    for (int i = 0; i < tl_channel_count(); i++) {
        int objects = tl_channel_is_object(tl_channel_at(i)) ? tl->object_count : 1;
        for (int k = 0; k < objects; k++) {
            const tl_track *tr = tl_timeline_track(tl, i, k);
            if (tr->state != TL_TRACK_KEYED)
                continue;
            for (int c = 0; c < tl_channel_at(i)->components; c++)
                if (tl_curve_has_cut_between(&tr->curve[c], t0, t1))
                    return true;
        }
    }
    return false;
}

/* Samples the evaluated scene: at every frame for ordinary timelines, and at
 * most TL_FEATURE_SAMPLES evenly spaced times for enormous ones. */
#define TL_FEATURE_SAMPLES 20000

void tl_timeline_features_of(const tl_timeline *tl, tl_timeline_features *f)
{
    memset(f, 0, sizeof *f);
    long frames = tl_timeline_frame_count(tl);
    long samples = frames < TL_FEATURE_SAMPLES ? frames : TL_FEATURE_SAMPLES;
    for (long i = 0; i < samples; i++) {
        double t = samples == frames ? tl_timeline_frame_time(tl, i)
                                     : tl->duration * (double)i / (double)(samples - 1);
        tl_scene s;
        eval_scene(tl, t, &s, false, false); /* the features do not depend on the boat's pose */
        int objects = 0;
        for (int k = 0; k < s.objects; k++)
            objects += tl_scene_object(&s, k)->enabled;
        f->boat |= objects > 0;
        f->objects = objects > f->objects ? objects : f->objects;
        f->giant_wave |= s.giant.enabled && s.giant.fade > 0.0 && s.giant.height > 0.0;
        f->fog |= s.fog.density > 0.0;
        /* Auto: the camera may be under water once it is below the highest
         * crest (the ocean's plane at 0, or the giant wave's top); each
         * frame decides exactly from the surface. */
        bool giant = s.giant.enabled && s.giant.fade > 0.0 && s.giant.height > 0.0;
        double crests = giant ? s.giant.fade * (1.0 + s.giant.variation) * s.giant.height : 0.0;
        f->underwater |=
            s.underwater.mode == TL_UNDERWATER_ON ||
            (s.underwater.mode == TL_UNDERWATER_AUTO && s.camera.position[1] < crests + 0.5);
    }
}
