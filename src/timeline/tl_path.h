/* tl_path: a 3-D path through timed points (a camera or boat track).
 *
 * Centripetal Catmull-Rom (alpha 0.5): no cusps or self-loops within a
 * segment. The end tangents come from mirrored phantom points
 * (P[-1] = 2 P[0] - P[1], P[n] = 2 P[n-1] - P[n-2]), so the path leaves its
 * first point heading straight at the second. By default point i is reached
 * at its time t_i, the knot parameter of segment i mapping linearly from
 * [t_i, t_i+1]. With constant_speed the same shape is traversed at constant
 * speed from the first point's time to the last point's time (intermediate
 * points are then passed when the arc length gets there, not at their
 * times). Before the first / after the last time the position clamps to the
 * end point and the heading to the end tangent. */
#ifndef TL_PATH_H
#define TL_PATH_H

#include <stdbool.h>
#include <stddef.h>

#include "core/tl_error.h"

typedef struct tl_path_point {
    double t;      /* seconds, strictly increasing */
    double p[3];   /* position */
} tl_path_point;

typedef struct tl_path {
    tl_path_point *points; /* owned */
    size_t count, capacity;
    bool constant_speed;   /* takes effect at tl_path_prepare; until then by point times */
    /* Built by tl_path_prepare when constant_speed is set: cumulative arc
     * length at arc_samples + 1 evenly spaced values of the global segment
     * parameter g in [0, count - 1] (integer part: segment). */
    double *arc;
    size_t arc_samples;
    double *point_arc;     /* arc length at each point (tl_path_distance) */
    double length;         /* total arc length (always computed) */
    bool prepared;
} tl_path;

void tl_path_init(tl_path *path);
void tl_path_free(tl_path *path);

int tl_path_add_point(tl_path *path, double t, const double pos[3], tl_error *err);

/* Finite times and positions, times strictly increasing. On failure
 * *bad_point (may be NULL) is the 0-based index and the message starts
 * with "point N: ". */
int tl_path_validate(const tl_path *path, size_t *bad_point, tl_error *err);

/* Measures the path (the arc length at each point) and, with
 * constant_speed, builds the arc-length table. Call after the points are
 * added and validated. */
int tl_path_prepare(tl_path *path, tl_error *err);

/* Position and unit tangent (heading) at time t; either output may be
 * NULL. The tangent is the zero vector only when all points coincide.
 * An empty path gives the origin. */
void tl_path_eval(const tl_path *path, double t, double pos[3], double tangent[3]);

/* Arc length along the path from its first point to where it is at time t
 * (0 before the first time, the whole length after the last): a place on
 * the path keeps its distance whenever it is passed (the wake's foam
 * texture is anchored by it). 0 for fewer than two points. */
double tl_path_distance(const tl_path *path, double t);

#endif
