/* Floating: the boat's height, pitch and roll on the water.
 *
 * The hull samples the surface at five points (centre, bow and stern at
 * ±0.4 length, both beams at ±0.5 beam): their mean is the height, their
 * differences pitch and roll. Pitch and roll, and the ocean's part of the
 * height, go through a critically damped spring (response time
 * boat.float_time), so chop does not shake the boat and a sharp crest
 * passing under it turns it smoothly. The giant wave's part of the height,
 * hundreds of times longer than the hull, is followed directly, as a hull
 * follows a long swell: a spring would lag metres behind its face and sink
 * the boat into it.
 *
 * The spring is a closed form: its output is the target convolved with
 * the impulse response w² τ e^(−wτ), integrated by Simpson's rule over
 * wτ in [0, 12] at the boat's past positions. It depends on t alone, so
 * frame N rendered by itself equals frame N of a whole run. */
#include <math.h>
#include <string.h>

#include "timeline/tl_timeline.h"
#include "waves/tl_giant.h"
#include "waves/tl_waves.h"

#define FLOAT_NODES 36   /* Simpson intervals (even) */
#define FLOAT_SPAN  12.0 /* in units of the response time */

typedef struct hull_pose {
    double height, pitch, roll;
} hull_pose;

/* The surface under the five hull points of a boat at (x, z) heading h. */
static hull_pose sample_hull(const tl_boat *b, double x, double z, double heading,
                             double (*height)(const void *, double, double), const void *ctx)
{
    double fx = sin(heading), fz = cos(heading); /* toward the bow */
    double rx = fz, rz = -fx;                    /* toward starboard */
    double a = 0.4 * b->length, c = 0.5 * b->beam;
    double centre = height(ctx, x, z);
    double bow = height(ctx, x + fx * a, z + fz * a), stern = height(ctx, x - fx * a, z - fz * a);
    double star = height(ctx, x + rx * c, z + rz * c), port = height(ctx, x - rx * c, z - rz * c);
    hull_pose p;
    p.height = (centre + bow + stern + star + port) / 5.0;
    p.pitch = atan2(bow - stern, 2.0 * a);
    p.roll = atan2(port - star, 2.0 * c);
    return p;
}

typedef struct ocean_ctx {
    const tl_waves *waves;
    double t;
    int octaves;
    const tl_giant *giant; /* the small waves ride its water (NULL: none) */
    int iterations;
} ocean_ctx;

static double ocean_height(const void *ctx, double x, double z)
{
    const ocean_ctx *o = ctx;
    if (o->giant && o->giant->active) {
        tl_giant_sample smp;
        tl_giant_sample_at(o->giant, x, z, o->iterations, &smp);
        double q[2];
        tl_giant_ride_point(o->giant, &smp, x, z, q);
        x = q[0];
        z = q[1];
    }
    return tl_waves_height(o->waves, x, z, o->t, o->octaves);
}

typedef struct giant_ctx {
    const tl_giant *giant;
    int iterations;
    double base; /* the ocean's mean level, where the lip's heights are measured from */
} giant_ctx;

/* The giant wave's part of the height: its height field's, or the top of
 * its lip where the lip overhangs the point (the hull rides on it rather
 * than sinking through it to the face below). */
static double giant_height(const void *ctx, double x, double z)
{
    const giant_ctx *g = ctx;
    double h = tl_giant_height(g->giant, x, z, g->iterations), lips[4];
    int n = tl_giant_lip_heights(g->giant, x, z, g->base + h, g->base, lips, 4);
    return n > 0 ? fmax(h, lips[n - 1] - g->base) : h;
}

/* The boat's position and heading at time t (the heading channel, when it
 * is set or keyed, is taken at the frame's time). */
static void boat_at(const tl_timeline *tl, int object, double t, const tl_boat *b,
                    int heading_from_path, double *x, double *z, double *heading)
{
    double p[3], tangent[3];
    tl_path_eval(&tl->objects[object].path.path, t, p, tangent);
    *x = p[0];
    *z = p[2];
    *heading = b->heading;
    if (heading_from_path && (tangent[0] != 0.0 || tangent[2] != 0.0))
        *heading = atan2(tangent[0], tangent[2]);
}

/* The giant wave of moment `past` as the boat at (px, pz) then met it:
 * this one moved back along its travel, and across with the object its
 * centre follows, if any (`leader`, `lead`). Its break and envelope are
 * this moment's: they change over seconds, the springs' past is short. */
static void giant_then(const tl_giant *giant, const tl_timeline *tl, int object, int leader,
                       const tl_boat *lead, double t, double past, double px, double pz,
                       tl_giant *then)
{
    *then = *giant;
    if (!giant->active)
        return;
    double back = giant->speed * (t - past);
    then->origin[0] -= giant->dir[0] * back;
    then->origin[1] -= giant->dir[1] * back;
    if (lead) { /* the centre line follows its object across */
        double lx = px, lz = pz, lh;
        if (leader != object)
            boat_at(tl, leader, past, lead, 0, &lx, &lz, &lh);
        double across = giant->across[0] * (lx - lead->position[0]) +
                        giant->across[1] * (lz - lead->position[2]);
        then->origin[0] += giant->across[0] * across;
        then->origin[1] += giant->across[1] * across;
    }
}

/* TL_FLOAT_MAX_TILT's soft limit: the angle itself up to the knee, then a
 * tanh toward the limit with the same slope there. */
static double limit_tilt(double a)
{
    double over = fabs(a) - TL_FLOAT_TILT_KNEE, room = TL_FLOAT_MAX_TILT - TL_FLOAT_TILT_KNEE;
    if (over <= 0.0)
        return a;
    return copysign(TL_FLOAT_TILT_KNEE + room * tanh(over / room), a);
}

void tl_timeline_float_boat(const tl_timeline *tl, int object, double t, int heading_from_path,
                            tl_scene *s)
{
    tl_boat *b = tl_scene_object(s, object);
    tl_waves waves;
    tl_waves_init(&waves, &s->ocean);
    tl_giant giant;
    tl_giant_prepare(&giant, &s->giant, t);
    ocean_ctx oc = {&waves, t, s->quality.march_octaves, NULL, s->quality.giant_iterations};
    /* The object the giant wave's centre follows, if any (this one or another). */
    const int leader = tl->giant_follow.target == TL_TARGET_BOAT ? tl->giant_follow.object : -1;
    const tl_boat *lead = leader >= 0 ? tl_scene_object(s, leader) : NULL;

    /* The springs, at the boat's past poses (giant_then: the giant wave
     * as it was met then). The giant wave's slope goes through a quicker
     * one (TL_FLOAT_GIANT_TIME). */
    const double w = 1.0 / b->float_time, h = FLOAT_SPAN / FLOAT_NODES;
    const double w_giant = 1.0 / fmin(b->float_time, TL_FLOAT_GIANT_TIME);
    hull_pose sum = {0.0, 0.0, 0.0};
    double weights = 0.0;
    for (int i = 0; i <= FLOAT_NODES; i++) {
        double x = i * h; /* w·τ */
        double simpson = (i == 0 || i == FLOAT_NODES) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        double weight = simpson * x * exp(-x);
        if (weight == 0.0)
            continue;
        double past = t - x / w, px, pz, heading;
        boat_at(tl, object, past, b, heading_from_path, &px, &pz, &heading);
        tl_giant then;
        giant_then(&giant, tl, object, leader, lead, t, past, px, pz, &then);
        oc.t = past;
        oc.giant = &then;
        hull_pose p = sample_hull(b, px, pz, heading, ocean_height, &oc);
        if (giant.active) {
            /* The giant wave's slope through its own, quicker spring. */
            double past_g = t - x / w_giant, gx, gz, gh;
            boat_at(tl, object, past_g, b, heading_from_path, &gx, &gz, &gh);
            tl_giant then_g;
            giant_then(&giant, tl, object, leader, lead, t, past_g, gx, gz, &then_g);
            giant_ctx gc = {&then_g, s->quality.giant_iterations, -0.5 * s->ocean.depth};
            hull_pose g = sample_hull(b, gx, gz, gh, giant_height, &gc);
            p.pitch += g.pitch;
            p.roll += g.roll;
        }
        sum.height += weight * p.height;
        sum.pitch += weight * p.pitch;
        sum.roll += weight * p.roll;
        weights += weight;
    }
    /* Normalised: a still target comes out exactly (the tail beyond 12
     * response times holds 8e-5 of the weight). */
    b->position[1] = sum.height / weights;
    b->pitch = limit_tilt(sum.pitch / weights);
    b->roll = limit_tilt(sum.roll / weights);

    /* The giant wave's height, followed directly. */
    oc.t = t;
    oc.giant = &giant;
    double centre = ocean_height(&oc, b->position[0], b->position[2]);
    if (giant.active) {
        giant_ctx gc = {&giant, s->quality.giant_iterations, -0.5 * s->ocean.depth};
        hull_pose g = sample_hull(b, b->position[0], b->position[2], b->heading, giant_height, &gc);
        b->position[1] += g.height;
        centre += giant_height(&gc, b->position[0], b->position[2]);
    }
    /* Clamp: a hull bridging a sharp crest would sink its middle under the
     * water by the crest's curvature; the waterline stays at most 5% of the
     * hull's length below the water at its centre, so the deck stays dry. */
    double lowest = centre - TL_FLOAT_MAX_SINK * b->length;
    if (b->position[1] < lowest)
        b->position[1] = lowest;
}

double tl_timeline_bow_gap(const tl_scene *s, int object)
{
    const tl_boat *b = tl_scene_object_const(s, object);
    tl_waves waves;
    tl_waves_init(&waves, &s->ocean);
    tl_giant giant;
    tl_giant_prepare(&giant, &s->giant, s->time);
    ocean_ctx oc = {&waves, s->time, s->quality.march_octaves, &giant, s->quality.giant_iterations};
    const double a = 0.5 * b->length;
    const double x = b->position[0] + sin(b->heading) * a, z = b->position[2] + cos(b->heading) * a;
    double water = ocean_height(&oc, x, z);
    if (giant.active) {
        giant_ctx gc = {&giant, s->quality.giant_iterations, -0.5 * s->ocean.depth};
        water += giant_height(&gc, x, z);
    }
    return water - (b->position[1] + sin(b->pitch) * a);
}

void tl_timeline_set_object_model(tl_timeline *tl, int object, int mesh, const float bounds_min[3],
                                  const float bounds_max[3])
{
    tl_object *o = &tl->objects[object];
    for (int i = 0; i < 3; i++) {
        o->model_min[i] = bounds_min[i];
        o->model_max[i] = bounds_max[i];
    }
    o->mesh = mesh;
    o->bounds_known = true;
}
