#include "tl_timeline.h"

#include <math.h>
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
    tl_path_init(&tl->boat_path.path);
    tl_path_init(&tl->camera_path.path);
    return TL_OK;
}

void tl_timeline_free(tl_timeline *tl)
{
    if (tl->tracks) {
        for (int i = 0; i < tl_channel_count(); i++)
            for (int c = 0; c < 3; c++)
                tl_curve_free(&tl->tracks[i].curve[c]);
        free(tl->tracks);
    }
    tl_path_free(&tl->boat_path.path);
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

static const tl_track *track_of(const tl_timeline *tl, const char *name)
{
    const tl_channel *ch = tl_channel_find(name);
    return ch ? &tl->tracks[tl_channel_index(ch)] : NULL;
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
    double then[3] = {s->boat.position[0], 0.0, s->boat.position[2]};
    if (tl->boat_path.present)
        tl_path_eval(&tl->boat_path.path, s->giant.arrival, then, NULL);
    double dir[2] = {sin(s->giant.angle), cos(s->giant.angle)};
    double now[2] = {s->boat.position[0] + off[0], s->boat.position[2] + off[2]};
    double at[2] = {then[0] + off[0], then[2] + off[2]};
    double along = dir[0] * at[0] + dir[1] * at[1];
    double across = dir[1] * now[0] - dir[0] * now[1];
    s->giant.center[0] = along * dir[0] + across * dir[1];
    s->giant.center[1] = along * dir[1] - across * dir[0];
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

    for (int i = 0; i < tl_channel_count(); i++) {
        const tl_channel *ch = tl_channel_at(i);
        const tl_track *tr = &tl->tracks[i];
        if (tr->state == TL_TRACK_DEFAULT)
            continue;
        double v[3] = {0, 0, 0};
        for (int c = 0; c < ch->components; c++) {
            double x = tr->state == TL_TRACK_SET ? tr->value[c] : tl_curve_eval(&tr->curve[c], t);
            /* Clamp: overshooting eases (back, elastic) and Bezier handles
             * may leave the range the keys respect. */
            v[c] = clampd(x, ch->min, ch->max);
        }
        tl_channel_set(ch, s, v);
    }

    /* The hull's size: the model's bounds (the built-in boat's until a
     * loader says otherwise), in metres. */
    tl_boat *b = &s->boat;
    if (tl->boat_bounds_known)
        for (int i = 0; i < 3; i++) {
            b->model_min[i] = tl->boat_model_min[i];
            b->model_max[i] = tl->boat_model_max[i];
        }
    b->scale = tl->boat_model[0] ? b->model_scale : b->size;
    double ex = b->model_max[0] - b->model_min[0], ez = b->model_max[2] - b->model_min[2];
    double c = fabs(cos(b->model_yaw)), sn = fabs(sin(b->model_yaw));
    b->length = (c * ez + sn * ex) * b->scale; /* model_yaw turns the model */
    b->beam = (c * ex + sn * ez) * b->scale;

    /* The boat rides the path; the giant wave may follow it. */
    bool heading_from_path = track_of(tl, "boat.heading")->state == TL_TRACK_DEFAULT;
    if (tl->boat_path.present) {
        double p[3], tangent[3];
        tl_path_eval(&tl->boat_path.path, t, p, tangent);
        s->boat.enabled = true;
        s->boat.position[0] = p[0];
        s->boat.position[2] = p[2];
        if (heading_from_path && (tangent[0] != 0.0 || tangent[2] != 0.0))
            s->boat.heading = atan2(tangent[0], tangent[2]);
    }

    if (tl->camera_path.present)
        tl_path_eval(&tl->camera_path.path, t, s->camera.position, NULL);
    if (tl->giant_follow.target == TL_TARGET_BOAT)
        aim_giant(tl, s);
    /* Where it was, for its wake: twice the fade time back. */
    if (s->boat.enabled)
        boat_wake(&tl->boat_path.path, t, &s->boat);
    /* ... and floats on the waves, the giant one included. How fast the
     * water rises against its bow (its spray) is the change of the bow's
     * gap to the water over TL_BOW_IMPACT_DT: the pose a moment before,
     * floated alike (the pose depends on the time alone, so this does). */
    if (s->boat.enabled && float_boat) {
        tl_timeline_float_boat(tl, t, heading_from_path, s);
        if (impact) {
            tl_scene before;
            eval_scene(tl, t - TL_BOW_IMPACT_DT, &before, true, false);
            s->boat.impact =
                (tl_timeline_bow_gap(s) - tl_timeline_bow_gap(&before)) / TL_BOW_IMPACT_DT;
        }
    }
    if (tl->camera_follow.target == TL_TARGET_BOAT)
        add3(s->camera.position, s->boat.position, tl->camera_follow.offset);
    /* Paths (a Catmull-Rom curve may overshoot its points) and links (boat +
     * offset) can leave a channel's range: hold every channel inside it. */
    for (int i = 0; i < tl_channel_count(); i++) {
        const tl_channel *ch = tl_channel_at(i);
        if (ch->kind != TL_CH_REAL)
            continue;
        double v[3];
        tl_channel_get(ch, s, v);
        for (int c = 0; c < ch->components; c++)
            v[c] = clampd(v[c], ch->min, ch->max);
        tl_channel_set(ch, s, v);
    }
    if (tl->camera_look.target != TL_TARGET_NONE) {
        double target[3];
        if (tl->camera_look.target == TL_TARGET_BOAT)
            add3(target, s->boat.position, tl->camera_look.offset);
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
        const tl_track *tr = &tl->tracks[i];
        if (tr->state != TL_TRACK_KEYED)
            continue;
        for (int c = 0; c < tl_channel_at(i)->components; c++)
            if (tl_curve_has_cut_between(&tr->curve[c], t0, t1))
                return true;
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
        f->boat |= s.boat.enabled;
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
